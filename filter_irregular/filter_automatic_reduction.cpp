// filter_irregular: MeshLab adapter of "Irregular Vertices: Automatic Reduction"
// (vcg_ext/irregular/automatic_reduction.h): parameters, optional remeshing, protection of the
// selection, progress, logging.
#include "filter_irregular.h"

#include <chrono>
#include <memory>

#include <QString>
#include <QStringList>

#include <vcg/complex/append.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <vcg_ext/irregular/automatic_reduction.h>
#include <vcg_ext/irregular/mesh_checks.h>
#include <vcg_ext/irregular/quality.h>
#include <vcg_ext/irregular/remeshing.h>

namespace irr = vcg_ext::irregular;

void FilterIrregularPlugin::initAutomaticReductionParameters(MeshModel& mm, RichParameterList& par) {
  const float diag = mm.cm.bbox.Diag();
  par.addParam(RichAbsPerc("remeshEdgeLength", 0.f, 0.f, diag, "Remesh first: target edge length",
                           "If > 0, the mesh is first remeshed isotropically to this edge length (vcglib's "
                           "IsotropicRemeshing, as 'Remeshing: Isotropic Explicit Remeshing'), so one run goes "
                           "from a scan to a clean result. 0 keeps the mesh as it is."));
  par.addParam(RichInt("targetCount", 0, "Target irregular count",
                       "Stop once this many irregular vertices remain; 0 removes as many as the limits below "
                       "allow. A closed surface of genus g keeps at least |12 - 12g| (Gauss-Bonnet, eq. 2)."));
  par.addParam(RichFloat("hausdorffBudget", 0.5f, "Hausdorff budget (% of diagonal)",
                         "An edit whose triangles would leave the input surface by more than this (percent of "
                         "the bounding-box diagonal) is undone."));
  par.addParam(RichFloat("minAngle", 30.f, "Minimum angle (degrees)",
                         "An edit is undone if, after local relaxation, a triangle around it has a smaller "
                         "angle than this (unless one already had before). This keeps the irregular vertices "
                         "the surface needs (v5 on tips, v7 in saddles)."));
  par.addParam(RichInt("maxTravel", 12, "Pair travel (steps)",
                       "How far a 5-7 pair moves toward another irregular vertex to cancel with it "
                       "(straight glides go up to four times farther)."));
  par.addParam(RichEnum("protect", 0,
                        QStringList() << "Nothing" << "Selected region untouched" << "Selected irregular vertices kept",
                        "Protect the selection",
                        "Selected region untouched: no edit changes a selected vertex or a face around one. "
                        "Selected irregular vertices kept: they stay where they are with their valence."));
  par.addParam(RichEnum("relaxation", 0, QStringList() << "Local" << "Global", "Final relaxation",
                        "After the edits the whole mesh is relaxed: local sweeps, or the global solve of eq. 5 "
                        "followed by local sweeps (the global result is kept only if it does not lower the "
                        "smallest angle). Every edit is relaxed locally as it is made."));
  par.addParam(RichFloat("timeLimit", 60.f, "Time limit (seconds)",
                         "Editing stops after this long; what was done is kept, relaxed and checked against the "
                         "Hausdorff budget. 0: no limit (the result then does not depend on the machine's speed)."));
}

namespace {
/// Per-vertex frozen flags from the selection (empty: nothing protected).
std::vector<char> FrozenFromSelection(CMeshO& m, int protect) {
  std::vector<char> frozen;
  if (protect == 0) return frozen;
  frozen.assign(m.vert.size(), 0);
  irr::ValenceField<CMeshO> vf = irr::ComputeValences(m);
  std::vector<int> seeds;
  for (size_t i = 0; i < m.vert.size(); ++i) {
    if (m.vert[i].IsD() || !m.vert[i].IsS()) continue;
    if (protect == 2 && !vf.IsIrregular(i)) continue;
    seeds.push_back(int(i));
  }
  // Region untouched: an edit changes the faces around every vertex it touches, so the
  // selection's 1-ring is frozen too; then no face with a selected corner changes.
  for (int v : protect == 1 ? irr::KRing(m, seeds, 1) : seeds) frozen[size_t(v)] = 1;
  return frozen;
}
}  // namespace

bool FilterIrregularPlugin::automaticReduction(MeshModel& mm, const RichParameterList& par, vcg::CallBackPos* cb) {
  CMeshO& m = mm.cm;
  irr::Result input = irr::DiagnoseInput(m).Verdict();
  if (!input) return refuse(QString::fromStdString(input.reason));
  const int protect = par.getEnum("protect");
  const float remeshLength = par.getAbsPerc("remeshEdgeLength");
  if (protect != 0 && remeshLength > 0)
    return refuse("Remeshing first replaces every vertex, so a selection cannot be protected: set 'Remesh first' to 0 "
                  "or 'Protect the selection' to Nothing.");
  if (protect != 0) {
    bool any = false;
    for (auto& v : m.vert) any = any || (!v.IsD() && v.IsS());
    if (!any) return refuse("'Protect the selection' is set but no vertex is selected.");
  }
  const auto t0 = std::chrono::steady_clock::now();
  irr::SurfaceProjector original(m);
  irr::TopologySummary before = irr::Summarize(m);
  logShape("Before", m);

  // Remeshing replaces the mesh: keep a copy to give back if the run is refused or interrupted.
  std::unique_ptr<CMeshO> saved;
  auto restore = [&] {
    if (!saved) return;
    m.Clear();
    vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(m, *saved, false, true);
    vcg::tri::UpdateTopology<CMeshO>::FaceFace(m);
    vcg::tri::UpdateTopology<CMeshO>::VertexFace(m);
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
  };
  if (remeshLength > 0) {
    saved.reset(new CMeshO);
    vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(*saved, m, false, true);
    if (cb) cb(1, "Isotropic remeshing");
    mm.updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTMARK | MeshModel::MM_FACEMARK |
                      MeshModel::MM_FACEFLAG);
    irr::RemeshOptions ro;
    ro.targetEdgeLength = remeshLength;
    irr::RemeshIsotropic(m, ro);
    const double remeshDistance = irr::HausdorffPercent(m, original);
    Log("Isotropic remeshing to edge length %.5g: %d vertices, %d irregular, %.4f%% of the diagonal from the input",
        remeshLength, m.VN(), irr::Summarize(m).irregular, remeshDistance);
    // The budget bounds the result's distance to the filter's input: remeshing counts.
    if (remeshDistance > par.getFloat("hausdorffBudget")) {
      restore();
      return refuse(QString("Remeshing to edge length %1 alone leaves the input by %2% of the diagonal, more than the "
                            "Hausdorff budget (%3%): use a shorter edge length or a larger budget.")
                        .arg(remeshLength)
                        .arg(remeshDistance, 0, 'f', 3)
                        .arg(par.getFloat("hausdorffBudget")));
    }
  }

  irr::ReductionOptions opt;
  opt.targetCount = std::max(0, par.getInt("targetCount"));
  opt.hausdorffBudgetPercent = std::max(0.f, par.getFloat("hausdorffBudget"));
  opt.minAngleDeg = par.getFloat("minAngle");
  opt.maxTravel = std::max(1, par.getInt("maxTravel"));
  opt.glideTravel = 4 * opt.maxTravel;
  opt.finalRelax = par.getEnum("relaxation") == 1 ? irr::RelaxMode::Global : irr::RelaxMode::Local;
  if (par.getFloat("timeLimit") > 0) opt.timeLimitSeconds = par.getFloat("timeLimit");  // 0: no limit
  opt.frozen = FrozenFromSelection(m, protect);
  if (cb) opt.progress = [cb](int pct, const char* what) { return cb(pct, what); };
  irr::AutomaticReduction<CMeshO> reduction(m, original, opt);
  irr::ReductionReport rep = reduction.Run();
  if (!rep) {
    restore();
    return refuse(QString::fromStdString(rep.result.reason));
  }
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
  vcg::tri::UpdateBounding<CMeshO>::Box(m);

  auto hist = [](const std::map<int, int>& h) {
    QString s;
    for (auto& kv : h) s += QString(" v%1:%2").arg(kv.first).arg(kv.second);
    return s;
  };
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Log("Automatic reduction: %d -> %d irregular vertices (%d before any remeshing)", rep.irregularBefore,
      rep.irregularAfter, before.irregular);
  Log("Valences before:%s", qUtf8Printable(hist(rep.histogramBefore)));
  Log("Valences after:%s", qUtf8Printable(hist(rep.histogramAfter)));
  Log("Edits: %d type splits, %d local cancellations, %d pair transports and %d glides (%d pair steps), "
      "%d stretched 5-7 pairs split and cancelled, %d edits undone (angle or Hausdorff limit)",
      rep.typeSplits, rep.localCancellations, rep.transports, rep.glides, rep.pairSteps, rep.splitAbsorptions,
      rep.undone);
  if (rep.timeLimitReached) Log(GLLogStream::WARNING, "Time limit reached: editing stopped early");
  if (rep.globalRelaxUndone) Log("The final global relaxation lowered the smallest angle and was undone");
  if (rep.finalSweepsUndone) Log("The final local relaxation sweeps overshot the Hausdorff budget and were undone");
  logShape("After", m);
  Log("Hausdorff distance to the input: %.4f%% of the bounding box diagonal (budget %.3f%%)", rep.hausdorffPercent,
      opt.hausdorffBudgetPercent);
  if (rep.budgetRetries > 0)
    Log(GLLogStream::WARNING,
        "The first run overshot the Hausdorff budget (the per-edit checks sample the surface): redone %d time(s) "
        "with a tighter per-edit budget",
        rep.budgetRetries);
  if (rep.allUndone)
    Log(GLLogStream::WARNING,
        "Every run overshot the Hausdorff budget: all reduction edits were undone. Raise the budget or remesh "
        "finer first.");
  Log("Time: %.2f s (reduction %.2f s)", seconds, rep.seconds);
  // Keep a protected selection; otherwise select what remains irregular.
  paintAndLog(mm, par.getBool("colorize"), protect == 0 ? 1 : 0, 0, true, par.getBool("colorize"));
  return true;
}
