// filter_irregular: "Irregular Vertices: Automatic Reduction"
// (vcg_ext/irregular/automatic_reduction.h): optional remeshing, protection of the selection,
// progress, log and output values.
#include <algorithm>
#include <chrono>
#include <memory>

#include "filter_common.h"
#include "filters.h"

#include <vcg/complex/append.h>
#include <vcg/complex/algorithms/stat.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <vcg_ext/irregular/automatic_reduction.h>
#include <vcg_ext/irregular/quality.h>
#include <vcg_ext/irregular/remeshing.h>

namespace irr = vcg_ext::irregular;

namespace filter_irregular {

/// Why a reduction stopped where it did: the output value `stop_reason` (documented in the
/// README; pymeshlab drops strings, so the words are in the log).
enum ReductionStop {
  kStopNoMoreEdits = 0,   ///< no further edit passes the limits (the usual end)
  kStopTargetReached = 1, ///< targetCount irregular vertices or fewer remain
  kStopTimeLimit = 2,     ///< timeLimit reached: what was done is kept
  kStopAllUndone = 3,     ///< every run overshot the Hausdorff budget: all edits undone
};  // An interrupted run (GUI progress cancelled) is a refusal: the mesh is given back unchanged.

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

FilterOutcome ApplyAutomaticReduction(FilterContext& ctx, const ParamValues& par) {
  CMeshO& m = ctx.Mesh();
  const std::string defect = InputDefect(m);
  if (!defect.empty()) return FilterOutcome::Refuse(defect);
  const int protect = par.Enum("protect");
  const double remeshLength = par.Float("remeshEdgeLength");
  const double budget = par.Float("hausdorffBudget");
  if (protect != 0 && remeshLength > 0)
    return FilterOutcome::Refuse(
        "Remeshing first replaces every vertex, so a selection cannot be protected: set 'Remesh first' to 0 or "
        "'Protect the selection' to Nothing.");
  if (remeshLength > 0) {
    // A tiny edge length on a large surface would remesh toward billions of triangles: refuse
    // with the estimate instead of running for hours.
    const double area = vcg::tri::Stat<CMeshO>::ComputeMeshArea(m);
    const double estimate = irr::VertexCountForEdgeLength(area, remeshLength);
    if (estimate > irr::kMaxRemeshVertices)
      return FilterOutcome::Refuse(
          Format("Remeshing to edge length %g would make about %.3g vertices, more than this filter accepts (%.0f): "
                 "use an edge length of at least %.4g (about %.0f vertices), or %.4g for about 20,000.",
                 remeshLength, estimate, irr::kMaxRemeshVertices,
                 irr::EdgeLengthForVertexCount(area, int(irr::kMaxRemeshVertices)), irr::kMaxRemeshVertices,
                 irr::EdgeLengthForVertexCount(area, 20000)));
  }
  if (protect != 0 && SelectedVertices(m).empty())
    return FilterOutcome::Refuse("'Protect the selection' is set but no vertex is selected.");
  const auto t0 = std::chrono::steady_clock::now();
  irr::SurfaceProjector original(m);
  irr::TopologySummary before = irr::Summarize(m);
  LogShape(ctx, "Before", m);
  FilterOutcome out;
  AddSummaryValues(out, before, "_input");

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
  auto cb = ctx.Progress();
  double remeshDistance = 0;
  if (remeshLength > 0) {
    saved.reset(new CMeshO);
    vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(*saved, m, false, true);
    if (cb) cb(1, "Isotropic remeshing");
    ctx.Require(kVertQuality | kVertMark | kFaceMark | kFaceFlag);
    irr::RemeshOptions ro;
    ro.targetEdgeLength = float(remeshLength);
    irr::RemeshIsotropic(m, ro);
    remeshDistance = irr::HausdorffPercent(m, original);
    ctx.Logf("Isotropic remeshing to edge length %.5g: %d vertices, %d irregular, %.4f%% of the diagonal from the input",
             remeshLength, m.VN(), irr::Summarize(m).irregular, remeshDistance);
    // The budget bounds the result's distance to the filter's input: remeshing counts.
    if (remeshDistance > budget) {
      restore();
      return FilterOutcome::Refuse(
          Format("Remeshing to edge length %g alone leaves the input by %.3f%% of the diagonal, more than the "
                 "Hausdorff budget (%g%%): use a shorter edge length or a larger budget.",
                 remeshLength, remeshDistance, budget));
    }
  }

  // What the reduction starts from (after any remeshing), counted as Analyze counts.
  const irr::TopologySummary start = remeshLength > 0 ? irr::Summarize(m) : before;
  irr::ReductionOptions opt;
  opt.targetCount = par.Int("targetCount");
  opt.hausdorffBudgetPercent = budget;
  opt.minAngleDeg = par.Float("minAngle");
  opt.angleAllowancePercent = par.Float("angleAllowance");
  opt.angleFloorDeg = par.Float("angleFloor");
  irr::SetFilterTravel(opt, par.Int("maxTravel"));  // glides 4x; a longer travel: more refusals per region
  opt.finalRelax = par.Enum("relaxation") == 1 ? irr::RelaxMode::Global : irr::RelaxMode::Local;
  if (par.Float("timeLimit") > 0) opt.timeLimitSeconds = par.Float("timeLimit");  // 0: no limit
  opt.frozen = FrozenFromSelection(m, protect);
  opt.aggregateLeftovers = par.Bool("aggregate");
  if (cb) opt.progress = [cb](int pct, const char* what) { return cb(pct, what); };
  irr::AutomaticReduction<CMeshO> reduction(m, original, opt);
  irr::ReductionReport rep = reduction.Run();
  if (!rep) {
    restore();
    return FilterOutcome::Refuse(rep.result.reason);
  }
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
  vcg::tri::UpdateBounding<CMeshO>::Box(m);

  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ctx.Logf("Automatic reduction: %d -> %d irregular vertices (%d before any remeshing)", rep.irregularBefore,
           rep.irregularAfter, before.irregular);
  ctx.Logf("Valences before:%s", HistogramText(rep.histogramBefore).c_str());
  ctx.Logf("Valences after:%s", HistogramText(rep.histogramAfter).c_str());
  ctx.Logf("Edits: %d type splits, %d local cancellations, %d pair transports and %d glides (%d pair steps), "
           "%d stretched 5-7 pairs split and cancelled (and %d walked part way, for what their steps removed), "
           "%d edits undone (angle or Hausdorff limit)",
           rep.typeSplits, rep.localCancellations, rep.transports, rep.glides, rep.pairSteps, rep.splitAbsorptions,
           rep.partialAbsorptions, rep.undone);
  ctx.Logf("Far meetings: %d of %d irregular vertices with no partner within the travel but one within %.1fx it "
           "cancelled by a longer walk; near meetings: %d of %d with a partner within the travel that the sweeps "
           "left (%d rounds)",
           rep.farMeetingsKept, rep.farMeetings, opt.farMeetingReach, rep.nearMeetingsKept, rep.nearMeetings,
           rep.meetingRounds);
  ctx.Logf("Pair travel: %d steps (maxTravel %d%s); %d routes kept after their sharpest triangles were relaxed again",
           rep.travel, opt.maxTravel,
           rep.travel != opt.maxTravel ? ", grown with the square root of the vertex count above 20000" : "",
           rep.angleRepairs);
  ctx.Logf("Undone by the edit guard: %d for a triangle under the minimum angle, %d for leaving the Hausdorff budget, "
           "%d for touching the protected selection, %d for adding boundary irregular vertices; %d vertices had an "
           "edit undone",
           rep.undoneAngle, rep.undoneHausdorff, rep.undoneFrozen, rep.undoneBoundary, int(rep.undoneAt.size()));
  const irr::BoundaryReductionReport& bs = rep.boundaryStage;
  ctx.Logf("Boundary: %d -> %d boundary irregular vertices (corner rule; never more than the input's); the boundary "
           "stage absorbed %d v5, %d v7 and %d 5-7 pairs (%d moved there first), %d hops, cancelling %d boundary "
           "irregular vertices",
           rep.boundaryIrregularBefore, rep.boundaryIrregularAfter, bs.absorbedV5, bs.absorbedV7, bs.absorbedPairs,
           bs.pairsMoved, bs.hops, bs.cancelled);
  ctx.Logf("Why the irregular vertices left stay: %s", rep.leftovers.Summary().c_str());
  // Bounded effort: one line per region given up (the first kMaxGaveUpLines; all are counted).
  const size_t kMaxGaveUpLines = 200;
  if (!rep.gaveUp.empty())
    ctx.Logf("Gave up on %d regions (%d irregular vertices in them) after %d refused edits each",
             int(rep.gaveUp.size()), rep.gaveUpVertices, opt.maxRefusalsPerRegion);
  for (size_t i = 0; i < rep.gaveUp.size() && i < kMaxGaveUpLines; ++i)
    ctx.Logf("%s", rep.gaveUp[i].Describe().c_str());
  if (rep.gaveUp.size() > kMaxGaveUpLines)
    ctx.Logf("... and %d more regions given up", int(rep.gaveUp.size() - kMaxGaveUpLines));
  ctx.Logf("Angle polish: %d of the %d triangles with an angle under %.0f degrees relaxed locally within the budget",
           rep.anglePolished, rep.anglePolishBelow, opt.anglePolishDeg);
  ctx.Logf("Angle flips: %d of %d longest edges of triangles still under %.0f degrees flipped without raising the "
           "irregular count",
           rep.angleFlips, rep.angleFlipsTried, opt.anglePolishDeg);
  if (opt.aggregateLeftovers)
    ctx.Logf("Aggregation: %d pairs of leftover v5 merged into a v4 and %d pairs of v7 into a v8 (%d pairs tried); "
             "%d of them first walked together (%d walks tried)",
             rep.aggregatedV4, rep.aggregatedV8, rep.aggregationsTried, rep.gathered, rep.gathersTried);
  if (opt.aggregateLeftovers && rep.gatherBoundReached)
    ctx.Logf("Aggregation: the walks stopped at their bound of effort (%d tried, %d plus %d per kept one): most of "
             "them did not get there",
             rep.gathersTried, opt.gatherTries, opt.gatherTriesPerGathered);
  if (rep.thinRimLines > 0)
    ctx.Logf("Crease lines: %d rims of parts thinner than %.0f edge lengths were not kept sharp (the thin part keeps "
             "its shape within the Hausdorff budget)",
             rep.thinRimLines, opt.creaseThinEdges);
  if (rep.timeLimitReached) ctx.Warnf("Time limit reached: editing stopped early");
  if (rep.globalRelaxUndone) ctx.Logf("The final global relaxation lowered the smallest angle and was undone");
  if (rep.finalSweepsUndone) ctx.Logf("The final local relaxation sweeps overshot the Hausdorff budget or lowered the smallest angle under "
                                      "the bound, and were undone");
  else if (rep.finalSweepsRestored > 0)
    ctx.Logf("The final local relaxation sweeps were kept but for %d vertices, put back where they were before them: "
             "there the sweeps pushed a triangle under the %.0f degree bound or the surface past 97%% of the Hausdorff "
             "budget",
             rep.finalSweepsRestored, opt.minAngleDeg);
  const irr::ShapeMeasures shape = irr::MeasureShape(m);
  LogShape(ctx, "After", m);
  ctx.Logf("Hausdorff distance to the input: %.4f%% of the bounding box diagonal (budget %.3f%%)", rep.hausdorffPercent,
           opt.hausdorffBudgetPercent);
  if (rep.budgetRetries > 0)
    ctx.Warnf("The first run overshot the Hausdorff budget (the per-edit checks sample the surface): redone %d time(s) "
              "with a tighter per-edit budget",
              rep.budgetRetries);
  if (rep.allUndone)
    ctx.Warnf("Every run overshot the Hausdorff budget: all reduction edits were undone. Raise the budget or remesh "
              "finer first.");
  ctx.Logf("Time: %.2f s (reduction %.2f s)", seconds, rep.seconds);
  // Keep a protected selection; otherwise select what remains irregular.
  const bool colorize = par.Bool("colorize");
  const irr::TopologySummary after = PaintAndLog(ctx, colorize, protect == 0 ? 1 : 0, 0, colorize);

  int stop = kStopNoMoreEdits;
  if (rep.allUndone) stop = kStopAllUndone;
  else if (rep.timeLimitReached) stop = kStopTimeLimit;
  else if (opt.targetCount > 0 && rep.irregularAfter <= opt.targetCount) stop = kStopTargetReached;
  out.SetBool("remeshed", remeshLength > 0);
  out.SetInt("remeshed_vertices", remeshLength > 0 ? m.VN() : 0);
  out.SetFloat("remesh_hausdorff_percent", remeshDistance);
  AddSummaryValues(out, start, "_before");
  AddSummaryValues(out, after, "_after");
  // The reduction edits interior vertices only: targetCount and stop_reason count those.
  out.SetInt("interior_irregular_before", rep.irregularBefore);
  out.SetInt("interior_irregular_after", rep.irregularAfter);
  out.SetInt("vertices_after", after.vertices);
  out.SetInt("faces_after", after.faces);
  out.SetInt("type_splits", rep.typeSplits);
  out.SetInt("local_cancellations", rep.localCancellations);
  out.SetInt("transports", rep.transports);
  out.SetInt("glides", rep.glides);
  out.SetInt("pair_steps", rep.pairSteps);
  out.SetInt("split_absorptions", rep.splitAbsorptions);
  out.SetInt("partial_absorptions", rep.partialAbsorptions);
  out.SetInt("far_meetings", rep.farMeetings);
  out.SetInt("far_meetings_kept", rep.farMeetingsKept);
  out.SetInt("near_meetings", rep.nearMeetings);
  out.SetInt("near_meetings_kept", rep.nearMeetingsKept);
  out.SetInt("meeting_rounds", rep.meetingRounds);
  out.SetInt("angle_repairs", rep.angleRepairs);
  out.SetInt("angle_polished", rep.anglePolished);
  out.SetInt("angle_polish_below", rep.anglePolishBelow);
  out.SetInt("angle_flips", rep.angleFlips);
  out.SetInt("angle_flips_tried", rep.angleFlipsTried);
  out.SetInt("aggregated_v4", rep.aggregatedV4);
  out.SetInt("aggregated_v8", rep.aggregatedV8);
  out.SetInt("aggregations_tried", rep.aggregationsTried);
  out.SetInt("aggregations_gathered", rep.gathered);
  out.SetInt("gatherings_tried", rep.gathersTried);
  out.SetBool("gathering_bound_reached", rep.gatherBoundReached);
  out.SetInt("thin_rim_lines", rep.thinRimLines);
  out.SetInt("travel", rep.travel);
  out.SetInt("undone", rep.undone);
  out.SetInt("undone_angle", rep.undoneAngle);
  out.SetInt("undone_hausdorff", rep.undoneHausdorff);
  out.SetInt("undone_frozen", rep.undoneFrozen);
  out.SetInt("undone_boundary", rep.undoneBoundary);
  out.SetInt("boundary_irregular_before", rep.boundaryIrregularBefore);
  out.SetInt("boundary_irregular_after", rep.boundaryIrregularAfter);
  out.SetInt("boundary_absorbed", bs.absorbedV5 + bs.absorbedV7 + 2 * bs.absorbedPairs);
  out.SetInt("boundary_cancelled", bs.cancelled);
  out.SetInt("leftover_caps", rep.leftovers.caps);
  out.SetInt("leftover_saddles", rep.leftovers.saddles);
  out.SetInt("leftover_thin", rep.leftovers.thin);
  out.SetInt("leftover_no_partner", rep.leftovers.noPartner);
  out.SetInt("leftover_budget", rep.leftovers.budget);
  out.SetInt("leftover_no_route", rep.leftovers.noRoute);
  out.SetInt("leftover_untried", rep.leftovers.untried);
  out.SetInt("leftover_boundary", rep.leftovers.boundary);
  out.SetInt("leftover_protected", rep.leftovers.protectedCount);
  out.SetInt("leftover_on_thin_parts", rep.leftovers.onThinPart);
  out.SetInt("gave_up_regions", int(rep.gaveUp.size()));
  out.SetInt("gave_up_vertices", rep.gaveUpVertices);
  out.SetInt("budget_retries", rep.budgetRetries);
  out.SetFloat("hausdorff_percent", rep.hausdorffPercent);
  out.SetFloat("min_angle_after", shape.minAngleDeg);
  out.SetFloat("percent_below_30_after", 100.0 * shape.shareBelow30);
  out.SetFloat("seconds", seconds);
  out.SetFloat("reduction_seconds", rep.seconds);
  out.SetInt("stop_reason", stop);
  return out;
}

}  // namespace filter_irregular
