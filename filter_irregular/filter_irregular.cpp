// filter_irregular: MeshLab adapter. Each filter translates parameters, calls vcg_ext, logs.
#include "filter_irregular.h"

#include <memory>

#include <QString>
#include <QStringList>

#include <vcg/complex/algorithms/update/flag.h>
#include <vcg/complex/algorithms/update/selection.h>

#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <vcg_ext/irregular/atomic_ops.h>
#include <vcg_ext/irregular/legend.h>
#include <vcg_ext/irregular/mesh_checks.h>
#include <vcg_ext/irregular/quality.h>
#include <vcg_ext/irregular/relaxation.h>
#include <vcg_ext/irregular/topology.h>

namespace irr = vcg_ext::irregular;

FilterIrregularPlugin::FilterIrregularPlugin() {
  typeList << FP_ANALYZE << FP_ATOMIC << FP_RELAX;
  for (FilterIDType t : types()) actionList << new QAction(filterName(t), this);
}

QString FilterIrregularPlugin::pluginName() const { return "FilterIrregular"; }

QString FilterIrregularPlugin::filterName(FilterIDType id) const {
  switch (id) {
    case FP_ANALYZE: return "Irregular Vertices: Analyze";
    case FP_ATOMIC: return "Irregular Vertices: Atomic Operation";
    case FP_RELAX: return "Irregular Vertices: Relax";
  }
  return "";
}

QString FilterIrregularPlugin::filterInfo(FilterIDType id) const {
  switch (id) {
    case FP_ANALYZE:
      return "Colours vertices by valence (v3- purple, v4 cyan, v5 blue, v6 grey, v7 orange, v8 red, "
             "v9+ dark red; boundary vertices by valence + 2, so regular boundary vertices of valence 4 "
             "are grey), writes the valence into vertex quality, optionally selects irregular vertices, "
             "and logs the valence histogram, the irregular count, Euler characteristic, genus, "
             "boundary loops and whether the discrete Gauss-Bonnet identity "
             "sum(6 - valence) + sum_boundary(4 - valence) = 6 chi holds "
             "(Li et al., Editing Operations for Irregular Vertices in Triangle Meshes, eq. 2). "
             "Refuses non-manifold or polygonal meshes without changing them.";
    case FP_ATOMIC:
      return "Applies one atomic operation of Li et al. (sec. 6.1-6.2) to the selected vertices "
             "(select them with the Analyze filter, by hand, or with 'Conditional Vertex Selection'):<br>"
             "<b>5-7 pair move</b>: select an adjacent v5 and v7; direction 0..5 turns counter-clockwise "
             "around the v5 starting at the v7 (1, 4: edge flips; 2, 3: collapses; 0, 5: splits).<br>"
             "<b>v5/v7 move with 5-7 pair generation</b>: select one v5 or v7; it moves toward its "
             "neighbour number 'direction' (counted counter-clockwise from its neighbour of smallest "
             "index) and leaves an adjacent 5-7 pair.<br>"
             "<b>v5/v7 move with 5-7 pair removal</b>: select an adjacent 5-5-7 or 5-7-7 triple; it "
             "becomes one v5 or v7 (triple cancellation).<br>"
             "<b>5-5-7-7 generation</b> (by flip or by split): select one regular vertex.<br>"
             "<b>5-5-7-7 removal</b>: select the four vertices of a quadruple in two triangles.<br>"
             "<b>Edge flip / collapse</b>: select the two ends of the edge (collapse keeps the lower "
             "index). <b>Vertex split</b>: select a vertex and two of its neighbours.<br>"
             "Impossible requests are refused with the reason (one irregular vertex cannot move alone, "
             "Theorem 5.1; a 5-7 pair cannot be cancelled, Theorem 5.5). A refused operation leaves the "
             "mesh unchanged. Afterwards vertices are recoloured and the resulting irregular vertices "
             "selected.";
    case FP_RELAX:
      return "Improves the shape of triangles without changing connectivity (Li et al., sec. 8). "
             "<b>Local</b>: vertices move one at a time in their tangent plane toward the centroid of "
             "their neighbours (Turk 1992). <b>Global</b>: solves the quadratic energy of eq. 5 "
             "(uniform edge lengths, equal angles around each vertex) with each vertex constrained to its "
             "tangent plane, with a sparse LDLT solver. Moved vertices are projected back onto the mesh as "
             "it was before the filter. Vertices on sharp creases stay fixed. Logs triangle quality and the "
             "Hausdorff distance to the input before and after.";
  }
  return "";
}

MeshFilterInterface::FilterClass FilterIrregularPlugin::getClass(QAction* a) {
  switch (ID(a)) {
    case FP_ANALYZE: return FilterClass(Quality | Measure | Selection);
    case FP_ATOMIC: return FilterClass(Remeshing | Selection);
    case FP_RELAX: return FilterClass(Smoothing | Remeshing);
  }
  return Generic;
}

int FilterIrregularPlugin::getRequirements(QAction*) {
  return MeshModel::MM_FACEFACETOPO | MeshModel::MM_VERTFACETOPO;
}

int FilterIrregularPlugin::getPreConditions(QAction*) const { return MeshModel::MM_FACENUMBER; }

int FilterIrregularPlugin::postCondition(QAction* a) const {
  switch (ID(a)) {
    case FP_ANALYZE:
      return MeshModel::MM_VERTCOLOR | MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTFLAGSELECT;
    default: return MeshModel::MM_ALL;
  }
}

void FilterIrregularPlugin::initParameterSet(QAction* a, MeshModel&, RichParameterList& par) {
  switch (ID(a)) {
    case FP_ANALYZE:
      par.addParam(RichEnum("select", 1, QStringList() << "None" << "All irregular" << "Only valence",
                            "Select vertices",
                            "Replace the vertex selection: None keeps it as it is; All irregular selects "
                            "every vertex of valence != 6 (boundary: != 4); Only valence selects the "
                            "vertices of the valence below (boundary vertices count as valence + 2)."));
      par.addParam(RichInt("valence", 5, "Valence to select",
                           "Used with 'Only valence': select the vertices of this (interior-equivalent) valence."));
      par.addParam(RichBool("colorize", true, "Colour by valence",
                            "Paint vertices with the plugin's valence legend (v5 blue, v7 orange, v8 red, ...)."));
      break;
    case FP_ATOMIC:
      par.addParam(RichEnum("operation", 0, QStringList() << "5-7 pair move"
                                                           << "v5/v7 move with 5-7 pair generation"
                                                           << "v5/v7 move with 5-7 pair removal (triple cancellation)"
                                                           << "5-5-7-7 generation by flip"
                                                           << "5-5-7-7 generation by split"
                                                           << "5-5-7-7 removal"
                                                           << "Edge flip" << "Edge collapse" << "Vertex split",
                            "Operation", "Which atomic operation to apply to the selected vertices."));
      par.addParam(RichInt("direction", 0, "Direction",
                           "5-7 pair move: 0..5 counter-clockwise around the v5 from the v7. Single-vertex "
                           "operations: index of the neighbour to move toward, counter-clockwise from the "
                           "neighbour with the smallest vertex index."));
      par.addParam(RichBool("relax", true, "Relax after editing",
                            "Local relaxation of the 2-ring around the changed vertices, projected onto the "
                            "surface as it was before the filter (paper sec. 8)."));
      break;
    case FP_RELAX:
      par.addParam(RichEnum("mode", 0, QStringList() << "Local" << "Global", "Mode",
                            "Local: one vertex at a time (fast). Global: sparse least-squares solve of eq. 5."));
      par.addParam(RichInt("iterations", 10, "Iterations", "Sweeps (local) or solve-and-project rounds (global)."));
      par.addParam(RichEnum("region", 0, QStringList() << "All" << "Selection" << "Around irregular vertices",
                            "Region", "Which vertices move. With nothing selected, Selection relaxes the whole mesh. "
                                      "Around irregular vertices: the 2-ring of every irregular vertex."));
      par.addParam(RichBool("reproject", true, "Project onto the original surface",
                            "Project moved vertices back onto the mesh as it was before the filter."));
      par.addParam(RichFloat("featureAngle", 60.f, "Feature angle (degrees)",
                             "Vertices on edges whose dihedral angle exceeds this stay fixed, so sharp creases "
                             "survive. 0 disables."));
      break;
  }
}

bool FilterIrregularPlugin::refuse(const QString& why) {
  errorMessage = why;
  Log(GLLogStream::WARNING, "Irregular Vertices: refused: %s", qUtf8Printable(why));
  return false;
}

void FilterIrregularPlugin::paintAndLog(MeshModel& mm, bool colorize, int selectMode, int selectValence,
                                        bool logSummary) {
  CMeshO& m = mm.cm;
  irr::ValenceField<CMeshO> vf = irr::ComputeValences(m);
  mm.updateDataMask(MeshModel::MM_VERTQUALITY | (colorize ? MeshModel::MM_VERTCOLOR : 0));
  irr::PaintValences(m, vf, colorize);
  const int selected = irr::SelectByValence(m, vf, irr::IrregularSelection(selectMode), selectValence);
  m.svn = selected;
  if (!logSummary) return;
  irr::TopologySummary s = irr::Summarize(m);
  QString hist;
  for (auto& kv : s.histogram) hist += QString(" v%1:%2").arg(kv.first).arg(kv.second);
  QString bhist;
  for (auto& kv : s.boundaryHistogram) bhist += QString(" v%1:%2").arg(kv.first).arg(kv.second);
  Log("Irregular vertices: %d of %d vertices (%.2f%%)", s.irregular, s.vertices,
      s.vertices ? 100.0 * s.irregular / s.vertices : 0.0);
  Log("Valence histogram (interior):%s", qUtf8Printable(hist));
  if (!s.boundaryHistogram.empty()) Log("Valence histogram (boundary, regular = 4):%s", qUtf8Printable(bhist));
  Log("Euler characteristic %d, genus %d, boundary loops %d, components %d (V %d, E %d, F %d)",
      s.eulerCharacteristic, s.genus, s.boundaryLoops, s.components, s.vertices, s.edges, s.faces);
  Log("Gauss-Bonnet (eq. 2): sum of valence defects %d, 6 x chi = %d: %s", s.gaussBonnetSum,
      6 * s.eulerCharacteristic, s.GaussBonnetHolds() ? "holds" : "FAILS");
  if (selectMode != 0) Log("Selected %d vertices", selected);
}

bool FilterIrregularPlugin::analyze(MeshModel& mm, const RichParameterList& par) {
  irr::InputReport rep = irr::DiagnoseInput(mm.cm);
  irr::Result ok = rep.Verdict();
  if (!ok) return refuse(QString::fromStdString(ok.reason));
  paintAndLog(mm, par.getBool("colorize"), par.getEnum("select"), par.getInt("valence"), true);
  return true;
}

namespace {
/// Indices of the selected live vertices, ascending.
std::vector<int> SelectedVertices(CMeshO& m) {
  std::vector<int> s;
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD() && m.vert[i].IsS()) s.push_back(int(i));
  return s;
}

/// After an edit: drop deleted elements, rebuild adjacency once, update normals and box.
void FinishEdit(CMeshO& m) {
  vcg::tri::Allocator<CMeshO>::CompactEveryVector(m);
  vcg::tri::UpdateTopology<CMeshO>::FaceFace(m);
  vcg::tri::UpdateTopology<CMeshO>::VertexFace(m);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
}
}  // namespace

bool FilterIrregularPlugin::atomic(MeshModel& mm, const RichParameterList& par) {
  CMeshO& m = mm.cm;
  irr::Result input = irr::DiagnoseInput(m).Verdict();
  if (!input) return refuse(QString::fromStdString(input.reason));
  const int op = par.getEnum("operation");
  const int dir = par.getInt("direction");
  std::vector<int> sel = SelectedVertices(m);
  std::unique_ptr<irr::SurfaceProjector> projector;
  if (par.getBool("relax")) projector.reset(new irr::SurfaceProjector(m));
  irr::MeshEditor<CMeshO> ed(m);
  irr::AtomicOperations<CMeshO> ops(ed);
  auto valences = [&](const std::vector<int>& vs) {
    std::vector<int> d;
    for (int v : vs) d.push_back(ed.Valence(v));
    std::sort(d.begin(), d.end());
    return d;
  };
  auto need = [&](size_t n, const char* what) -> bool {
    if (sel.size() == n) return true;
    refuse(QString("%1 needs exactly %2 selected vertices (%3); %4 are selected.")
               .arg(what).arg(n).arg(n == 1 ? "one" : n == 2 ? "two" : n == 3 ? "three" : "four")
               .arg(sel.size()));
    return false;
  };
  irr::AtomicOutcome out;
  switch (op) {
    case 0: {  // 5-7 pair move
      if (sel.size() == 1 && (ed.Valence(sel[0]) == 5 || ed.Valence(sel[0]) == 7))
        return refuse(QString::fromStdString(irr::ImpossibleRequest::MoveSingleVertex()));
      if (!need(2, "A 5-7 pair move")) return false;
      int a = sel[0], b = sel[1];
      if (ed.Valence(a) == 7) std::swap(a, b);
      out = ops.MovePair57(a, b, dir);
      break;
    }
    case 1:
      if (!need(1, "A move with 5-7 pair generation")) return false;
      out = ops.MoveWithPairGeneration(sel[0], dir);
      break;
    case 2:
      if (sel.size() == 2 && valences(sel) == std::vector<int>{5, 7})
        return refuse(QString::fromStdString(irr::ImpossibleRequest::CancelPair57()));
      if (!need(3, "A triple cancellation")) return false;
      out = ops.MoveWithPairRemoval(sel);
      break;
    case 3:
    case 4:
      if (!need(1, "A 5-5-7-7 generation")) return false;
      out = ops.GenerateQuadruple(sel[0], dir, op == 4);
      break;
    case 5:
      if (sel.size() == 2 && valences(sel) == std::vector<int>{5, 7})
        return refuse(QString::fromStdString(irr::ImpossibleRequest::CancelPair57()));
      if (!need(4, "A 5-5-7-7 removal")) return false;
      out = ops.RemoveQuadruple(sel);
      break;
    case 6:
      if (!need(2, "An edge flip")) return false;
      out.result = ed.Flip(sel[0], sel[1]);
      out.description = QString("flip edge (%1, %2)").arg(sel[0]).arg(sel[1]).toStdString();
      break;
    case 7:
      if (!need(2, "An edge collapse")) return false;
      out.result = ed.Collapse(sel[1], sel[0]);
      out.description = QString("collapse vertex %1 into %2").arg(sel[1]).arg(sel[0]).toStdString();
      break;
    case 8: {
      if (!need(3, "A vertex split")) return false;
      // the split vertex is the one adjacent to the other two
      std::vector<int> centre;
      for (int i = 0; i < 3; ++i)
        if (ed.Adjacent(sel[i], sel[(i + 1) % 3]) && ed.Adjacent(sel[i], sel[(i + 2) % 3])) centre.push_back(i);
      if (centre.size() != 1)
        return refuse(centre.empty() ? "A vertex split needs a vertex and two of its neighbours."
                                     : "Ambiguous vertex split: the three selected vertices form a triangle; select "
                                       "two neighbours of the split vertex that are not adjacent to each other.");
      const int c = centre[0];
      int created = -1;
      out.result = ed.Split(sel[c], sel[(c + 1) % 3], sel[(c + 2) % 3], &created);
      out.description = QString("split vertex %1 along edges to %2 and %3")
                            .arg(sel[c]).arg(sel[(c + 1) % 3]).arg(sel[(c + 2) % 3]).toStdString();
      break;
    }
    default: return refuse("Unknown operation.");
  }
  if (!out.result) return refuse(QString::fromStdString(out.result.reason));
  // Re-select what the operation produced (irregular vertices it reports, or the touched ones).
  std::vector<int> keep = out.irregular;
  if (keep.empty())
    for (int v : sel)
      if (ed.IsLive(v)) keep.push_back(v);
  for (auto& v : m.vert) v.ClearS();
  for (int v : keep)
    if (ed.IsLive(v)) m.vert[size_t(v)].SetS();
  if (par.getBool("relax")) {
    std::vector<int> seeds;
    for (auto& kv : out.changes)
      if (ed.IsLive(kv.first)) seeds.push_back(kv.first);
    irr::RelaxOptions ro;
    ro.iterations = 5;
    irr::LocalRelax(m, irr::KRing(m, seeds, 2), projector.get(), ro);
  }
  QString changes;
  for (auto& kv : out.changes) changes += QString(" %1:%2").arg(kv.first).arg(kv.second);
  FinishEdit(m);
  Log("Atomic operation: %s", out.description.c_str());
  if (!changes.isEmpty()) Log("Valence after, by vertex index before compaction:%s", qUtf8Printable(changes));
  paintAndLog(mm, true, 0, 0, true);
  return true;
}

void FilterIrregularPlugin::logShape(const char* when, CMeshO& m) {
  irr::ShapeMeasures s = irr::MeasureShape(m);
  Log("%s: min angle %.2f deg, mean min angle %.2f deg, %.2f%% of triangles under 30 deg, edge length spread %.3f",
      when, s.minAngleDeg, s.meanMinAngleDeg, 100.0 * s.shareBelow30, s.edgeLengthSpread);
}

bool FilterIrregularPlugin::relax(MeshModel& mm, const RichParameterList& par, vcg::CallBackPos* cb) {
  CMeshO& m = mm.cm;
  irr::Result input = irr::DiagnoseInput(m).Verdict();
  if (!input) return refuse(QString::fromStdString(input.reason));
  irr::RelaxOptions ro;
  ro.mode = irr::RelaxMode(par.getEnum("mode"));
  ro.iterations = std::max(0, par.getInt("iterations"));
  ro.reproject = par.getBool("reproject");
  ro.featureAngleDeg = par.getFloat("featureAngle");
  std::vector<int> region;
  const int which = par.getEnum("region");
  if (which == 1) region = SelectedVertices(m);
  if (which == 2) {
    irr::ValenceField<CMeshO> vf = irr::ComputeValences(m);
    std::vector<int> seeds;
    for (size_t i = 0; i < m.vert.size(); ++i)
      if (!m.vert[i].IsD() && vf.IsIrregular(i)) seeds.push_back(int(i));
    region = irr::KRing(m, seeds, 2);
  }
  if (which == 0 || (which == 1 && region.empty()))
    for (size_t i = 0; i < m.vert.size(); ++i)
      if (!m.vert[i].IsD()) region.push_back(int(i));
  irr::SurfaceProjector original(m);
  std::vector<char> crease = irr::CreaseVertices(m, ro.featureAngleDeg);
  logShape("Before", m);
  // Progress: one sweep at a time so the bar moves.
  irr::RelaxOptions one = ro;
  one.iterations = 1;
  irr::RelaxReport total;
  for (int it = 0; it < ro.iterations; ++it) {
    if (cb) cb(100 * it / std::max(1, ro.iterations), "Relaxing...");
    irr::RelaxReport r = irr::Relax(m, region, ro.reproject ? &original : nullptr, one, &crease);
    total.vertices = r.vertices;
    total.moved += r.moved;
    total.rejected += r.rejected;
    total.seconds += r.seconds;
    total.solveSeconds += r.solveSeconds;
  }
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  logShape("After", m);
  Log("Relaxed %d vertices (%s, %d iterations): %d moves, %d refused (would fold), %.3f s (solver %.3f s)",
      total.vertices, ro.mode == irr::RelaxMode::Global ? "global" : "local", ro.iterations, total.moved,
      total.rejected, total.seconds, total.solveSeconds);
  Log("Hausdorff distance to the input: %.4f%% of the bounding box diagonal", irr::HausdorffPercent(m, original));
  return true;
}

bool FilterIrregularPlugin::applyFilter(QAction* a, MeshDocument& md, const RichParameterList& par,
                                        vcg::CallBackPos* cb) {
  MeshModel* mm = md.mm();
  if (mm == nullptr) return refuse("There is no current mesh.");
  switch (ID(a)) {
    case FP_ANALYZE: return analyze(*mm, par);
    case FP_ATOMIC: return atomic(*mm, par);
    case FP_RELAX: return relax(*mm, par, cb);
  }
  return refuse("Unknown filter.");
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterIrregularPlugin)
