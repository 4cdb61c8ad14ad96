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
#include <vcg_ext/irregular/composite_ops.h>
#include <vcg_ext/irregular/legend.h>
#include <vcg_ext/irregular/mesh_checks.h>
#include <vcg_ext/irregular/quality.h>
#include <vcg_ext/irregular/relaxation.h>
#include <vcg_ext/irregular/topology.h>

namespace irr = vcg_ext::irregular;

FilterIrregularPlugin::FilterIrregularPlugin() {
  typeList << FP_ANALYZE << FP_ATOMIC << FP_RELAX << FP_REDUCE << FP_AGGREGATE << FP_MOVE_PAIR << FP_CANCEL_TRIPLE
           << FP_CANCEL_QUADRUPLE << FP_GENERATE << FP_AUTO_REDUCE;
  for (FilterIDType t : types()) actionList << new QAction(filterName(t), this);
}

QString FilterIrregularPlugin::pluginName() const { return "FilterIrregular"; }

QString FilterIrregularPlugin::filterName(FilterIDType id) const {
  switch (id) {
    case FP_ANALYZE: return "Irregular Vertices: Analyze";
    case FP_ATOMIC: return "Irregular Vertices: Atomic Operation";
    case FP_RELAX: return "Irregular Vertices: Relax";
    case FP_REDUCE: return "Irregular Vertices: Reduce to Valence 5 and 7";
    case FP_AGGREGATE: return "Irregular Vertices: Aggregate";
    case FP_MOVE_PAIR: return "Irregular Vertices: Move Pair";
    case FP_CANCEL_TRIPLE: return "Irregular Vertices: Cancel Triple";
    case FP_CANCEL_QUADRUPLE: return "Irregular Vertices: Cancel Quadruple";
    case FP_GENERATE: return "Irregular Vertices: Generate";
    case FP_AUTO_REDUCE: return "Irregular Vertices: Automatic Reduction";
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
             "tangent plane, with Eigen's conjugate gradient solver. Moved vertices are projected back onto the mesh as "
             "it was before the filter. Vertices on sharp creases stay fixed. Logs triangle quality and the "
             "Hausdorff distance to the input before and after.";
    case FP_REDUCE:
      return "Type splitting (Li et al., sec. 6.3): every irregular vertex of valence k > 7 becomes k-6 v7 "
             "(vertex splits), every v4 (v3) two (three) v5 (an edge collapse), so the other operations, "
             "which work on v5 and v7, apply. Vertices that cannot be reduced (e.g. no suitable neighbour) "
             "are kept and listed in the log. The resulting irregular vertices are selected.";
    case FP_AGGREGATE:
      return "Type aggregation (sec. 6.3), the inverse of type splitting: the selected v7s merge into one "
             "v8, v9, ... and the selected v5s into one v4 (two) or v3 (three). They must be as close as "
             "type splitting leaves them (one graph operation apart).";
    case FP_MOVE_PAIR:
      return "Moves the selected pair of irregular vertices (sec. 7.1). An adjacent 5-7 pair translates "
             "'steps' steps: the first in 'direction' (0..5 counter-clockwise around the v5 from the v7), the "
             "next ones straight on; or, with 'toward point', toward the picked point until it gets no "
             "closer. A non-adjacent 5-7 pair, or a 5-5 or 7-7 pair, moves by the pipeline of sec. 7.1.1: the "
             "lead vertex moves one step toward its neighbour 'direction' (counted counter-clockwise from "
             "its neighbour of smallest index) and generates a 5-7 pair, which travels to the partner and "
             "cancels there, moving the partner: 5-5 and 7-7 pairs move symmetrically (sec. 7.1.2). "
             "A single irregular vertex cannot move alone (Theorem 5.1).";
    case FP_CANCEL_TRIPLE:
      return "Triple cancellation (sec. 7.2): the selected 5-5-7 triple becomes one v5, a 5-7-7 triple one v7. "
             "An adjacent 5-7 pair of the triple is moved to the third vertex, then the atomic removal "
             "applies. A 5-7 pair alone cannot be cancelled (Theorem 5.5).";
    case FP_CANCEL_QUADRUPLE:
      return "Quadruple cancellation (sec. 7.3): the selected 5-5-7-7 quadruple, two adjacent 5-7 pairs, "
             "disappears: one pair is moved to the other until they annihilate. Refused when the two pairs "
             "cannot annihilate (they must be mirror images, sec. 7.3).";
    case FP_GENERATE:
      return "Generation (sec. 7.3), the inverse of cancellation: the selected v5 (v7) becomes a 5-5-7 (5-7-7) "
             "triple, or the selected regular vertex a 5-5-7-7 quadruple; the generated 5-7 pair is then "
             "moved 'spacing' steps away.";
    case FP_AUTO_REDUCE:
      return "Removes as many irregular vertices as the quality limits allow, with the paper's operations only "
             "(what its designers did by hand): type splitting into v5/v7 (sec. 6.3), triple and quadruple "
             "removals where they apply (sec. 6.2), 5-7 pairs moved to the nearest irregular vertex or gliding "
             "straight on until they cancel (sec. 7.1-7.2), and stretched 5-7 pairs split into two adjacent "
             "pairs that are cancelled in turn. Every edit is relaxed locally and undone if it leaves a triangle "
             "under the minimum angle or the input surface by more than the Hausdorff budget; the whole mesh is "
             "relaxed at the end. The budget bounds the result: it is measured at the end, and a run that "
             "overshoots is redone with stricter checks (at worst every edit is undone). Optionally remeshes "
             "isotropically first. Deterministic. Logs counts by valence, triangle quality, Hausdorff distance "
             "and time.";
  }
  return "";
}

MeshFilterInterface::FilterClass FilterIrregularPlugin::getClass(QAction* a) {
  switch (ID(a)) {
    case FP_ANALYZE: return FilterClass(Quality | Measure | Selection);
    case FP_ATOMIC: return FilterClass(Remeshing | Selection);
    case FP_RELAX: return FilterClass(Smoothing | Remeshing);
    default: return FilterClass(Remeshing | Selection);
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

void FilterIrregularPlugin::initParameterSet(QAction* a, MeshModel& m, RichParameterList& par) {
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
    case FP_REDUCE:
      par.addParam(RichEnum("scope", 0, QStringList() << "All irregular vertices" << "Selected vertices", "Vertices",
                            "Reduce every irregular vertex of valence other than 5 and 7, or only the selected ones."));
      break;
    case FP_MOVE_PAIR:
      par.addParam(RichEnum("lead", 0, QStringList() << "Lower valence" << "Higher valence" << "Lower index" << "Higher index",
                            "Leading vertex", "Non-adjacent pairs: which selected vertex moves first (its partner follows)."));
      par.addParam(RichInt("direction", 0, "Direction", "Adjacent 5-7 pair: 0..5 counter-clockwise around the v5 "
                                                        "from the v7. Otherwise: neighbour index of the lead vertex, "
                                                        "counted counter-clockwise from its neighbour of smallest index."));
      par.addParam(RichInt("steps", 1, "Steps", "How many steps the pair moves."));
      par.addParam(RichBool("towardPoint", false, "Toward point",
                            "Adjacent 5-7 pair: move toward 'point' until it gets no closer (steps and direction are ignored)."));
      par.addParam(RichPoint3f("point", Point3m(0, 0, 0), "Point",
                               "Where the pair should go: in the dialog, use Get / Surf. Pos. and double-click the mesh."));
      break;
    case FP_AUTO_REDUCE: initAutomaticReductionParameters(m, par); break;
    case FP_GENERATE:
      par.addParam(RichEnum("kind", 0, QStringList() << "Triple from a v5 or v7" << "Quadruple from a regular vertex",
                            "Generate", "What the selected vertex becomes."));
      par.addParam(RichInt("direction", 0, "Direction",
                           "Neighbour index, counted counter-clockwise from the neighbour of smallest index."));
      par.addParam(RichInt("spacing", 2, "Spacing", "Steps the generated 5-7 pair moves away."));
      break;
    default: break;
  }
  switch (ID(a)) {
    case FP_REDUCE:
    case FP_AGGREGATE:
    case FP_MOVE_PAIR:
    case FP_CANCEL_TRIPLE:
    case FP_CANCEL_QUADRUPLE:
    case FP_GENERATE:
      par.addParam(RichBool("relax", true, "Relax after editing",
                            "Local relaxation of the 2-ring around each step, projected onto the surface as it "
                            "was before the filter (paper sec. 8)."));
      break;
    default: break;
  }
  // Every editing filter, last: the legend, or the user's own colours and quality kept.
  if (ID(a) != FP_ANALYZE && ID(a) != FP_RELAX)
    par.addParam(RichBool("colorize", true, "Colour by valence",
                          "Paint the valence legend (v5 blue, v7 orange, v8 red, ...) and write the valence into "
                          "vertex quality. Off: the vertex colours and quality you had are kept (a vertex an "
                          "edit creates takes those of the vertex it was split from)."));
}

bool FilterIrregularPlugin::refuse(const QString& why) {
  errorMessage = why;
  Log(GLLogStream::WARNING, "Irregular Vertices: refused: %s", qUtf8Printable(why));
  return false;
}

void FilterIrregularPlugin::paintAndLog(MeshModel& mm, bool colorize, int selectMode, int selectValence,
                                        bool logSummary, bool writeQuality) {
  CMeshO& m = mm.cm;
  irr::ValenceField<CMeshO> vf = irr::ComputeValences(m);
  mm.updateDataMask((writeQuality ? MeshModel::MM_VERTQUALITY : 0) | (colorize ? MeshModel::MM_VERTCOLOR : 0));
  irr::PaintValences(m, vf, colorize, writeQuality);
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
  paintAndLog(mm, par.getBool("colorize"), 0, 0, true, par.getBool("colorize"));
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

bool FilterIrregularPlugin::composite(QAction* a, MeshModel& mm, const RichParameterList& par, vcg::CallBackPos* cb) {
  CMeshO& m = mm.cm;
  irr::Result input = irr::DiagnoseInput(m).Verdict();
  if (!input) return refuse(QString::fromStdString(input.reason));
  std::vector<int> sel = SelectedVertices(m);
  const bool relax = par.getBool("relax");
  std::unique_ptr<irr::SurfaceProjector> projector;
  if (relax) projector.reset(new irr::SurfaceProjector(m));
  irr::MeshEditor<CMeshO> ed(m);
  irr::CompositeOptions co;
  co.relax = relax;
  if (cb) co.progress = [cb](int pct, const char* what) { cb(pct, what); };
  irr::CompositeOperations<CMeshO> ops(ed, projector.get(), co);
  auto valences = [&](const std::vector<int>& vs) {
    std::vector<int> d;
    for (int v : vs) d.push_back(ed.Valence(v));
    std::sort(d.begin(), d.end());
    return d;
  };
  auto count = [&](size_t n, const QString& what) -> bool {
    if (sel.size() == n) return true;
    refuse(QString("%1 needs exactly %2 selected vertices; %3 are selected.").arg(what).arg(n).arg(sel.size()));
    return false;
  };
  irr::CompositeOutcome out;
  QString what = filterName(ID(a));
  switch (ID(a)) {
    case FP_REDUCE: {
      std::vector<int> todo;
      irr::ValenceField<CMeshO> vf = irr::ComputeValences(m);
      const bool selectedOnly = par.getEnum("scope") == 1;
      for (size_t i = 0; i < m.vert.size(); ++i) {
        if (m.vert[i].IsD() || !vf.referenced[i] || vf.boundary[i]) continue;
        if (vf.valence[i] >= 5 && vf.valence[i] <= 7) continue;
        if (selectedOnly && !m.vert[i].IsS()) continue;
        todo.push_back(int(i));
      }
      if (todo.empty()) return refuse("There is no interior vertex of valence other than 5, 6 and 7 to reduce.");
      int reduced = 0;
      QStringList failed;
      const size_t initial = todo.size();
      for (size_t t = 0; t < todo.size(); ++t) {
        if (cb && t % 64 == 0) cb(int(100 * std::min(t, initial) / initial), "Reducing to valence 5 and 7");
        if (!ed.IsLive(todo[t])) continue;
        const int d = ed.Valence(todo[t]);
        if (d >= 5 && d <= 7) continue;
        irr::CompositeOutcome r = ops.ReduceTo57(todo[t]);
        // a split end of valence 7 becomes a v8: reduce it too (bounded: each pass lowers valences)
        if (r && !selectedOnly && todo.size() < 4 * initial)
          for (int x : r.irregular)
            if (ed.IsLive(x) && (ed.Valence(x) > 7 || ed.Valence(x) < 5)) todo.push_back(x);
        if (r) {
          ++reduced;
          out.atomicSteps += r.atomicSteps;
          out.irregular.insert(out.irregular.end(), r.irregular.begin(), r.irregular.end());
        } else if (failed.size() < 10) {
          failed << QString("%1: %2").arg(todo[t]).arg(QString::fromStdString(r.result.reason));
        } else {
          failed << "...";
        }
        ed.Commit();
      }
      if (reduced == 0) return refuse("No vertex could be reduced. " + failed.join("; "));
      Log("Reduced %d vertices to valence 5 and 7 (%d asked)", reduced, int(initial));
      if (!failed.isEmpty()) Log(GLLogStream::WARNING, "Not reduced (kept as they were): %s", qUtf8Printable(failed.join("; ")));
      out.result = irr::Result::Ok();
      break;
    }
    case FP_AGGREGATE:
      out = ops.Aggregate(sel);
      break;
    case FP_MOVE_PAIR: {
      if (sel.size() == 1) return refuse(QString::fromStdString(irr::ImpossibleRequest::MoveSingleVertex()));
      if (!count(2, "Moving a pair")) return false;
      int lead = sel[0], partner = sel[1];
      const int how = par.getEnum("lead");
      const bool swap = (how == 0 && ed.Valence(lead) > ed.Valence(partner)) ||
                        (how == 1 && ed.Valence(lead) < ed.Valence(partner)) || how == 3;
      if (swap) std::swap(lead, partner);
      if (par.getBool("towardPoint")) {
        const int v5 = ed.Valence(lead) == 5 ? lead : partner, v7 = v5 == lead ? partner : lead;
        out = ops.MovePair57Toward(v5, v7, par.getPoint3m("point"));
      } else {
        out = ops.MovePair(lead, partner, par.getInt("direction"), std::max(1, par.getInt("steps")));
      }
      break;
    }
    case FP_CANCEL_TRIPLE:
      if (sel.size() == 2 && valences(sel) == std::vector<int>{5, 7})
        return refuse(QString::fromStdString(irr::ImpossibleRequest::CancelPair57()));
      if (!count(3, "A triple cancellation")) return false;
      out = ops.CancelTriple(sel);
      break;
    case FP_CANCEL_QUADRUPLE:
      if (sel.size() == 2 && valences(sel) == std::vector<int>{5, 7})
        return refuse(QString::fromStdString(irr::ImpossibleRequest::CancelPair57()));
      if (!count(4, "A quadruple cancellation")) return false;
      out = ops.CancelQuadruple(sel);
      break;
    case FP_GENERATE:
      if (!count(1, "Generation")) return false;
      out = par.getEnum("kind") == 0 ? ops.GenerateTriple(sel[0], par.getInt("direction"), std::max(0, par.getInt("spacing")))
                                     : ops.GenerateQuadruple(sel[0], par.getInt("direction"), std::max(0, par.getInt("spacing")));
      break;
  }
  if (!out.result) return refuse(QString::fromStdString(out.result.reason));
  for (auto& v : m.vert) v.ClearS();
  for (int v : out.irregular)
    if (ed.IsLive(v)) m.vert[size_t(v)].SetS();
  FinishEdit(m);
  Log("%s: %d atomic steps", qUtf8Printable(what), out.atomicSteps);
  if (!out.log.empty() && out.atomicSteps <= 50) Log("Steps:\n%s", out.log.c_str());
  paintAndLog(mm, par.getBool("colorize"), 0, 0, true, par.getBool("colorize"));
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
    case FP_AUTO_REDUCE: return automaticReduction(*mm, par, cb);
    default: return composite(a, *mm, par, cb);
  }
  return refuse("Unknown filter.");
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterIrregularPlugin)
