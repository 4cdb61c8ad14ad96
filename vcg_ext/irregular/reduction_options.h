// filter_irregular: the user settings of the automatic reduction (automatic_reduction.h) and
// what a run reports. Settings only: the run's own state lives in reduction_state.h.
#pragma once

#include <functional>
#include <limits>
#include <map>
#include <vector>

#include "boundary_reduction.h"
#include "leftover_reasons.h"
#include "relaxation.h"
#include "result.h"

namespace vcg_ext {
namespace irregular {

/// User settings of AutomaticReduction. Every field is read by the run; defaults in comments
/// are the filter's defaults unless the filter sets the field itself (filter_automatic_reduction.cpp).
struct ReductionOptions {
  // --- what to reach
  int targetCount = 0;                  ///< default 0: as few as possible; > 0: stop once this many interior
                                        ///< irregular vertices remain
  // --- the edit guard (edit_guard.h): an edit that breaks one of these is undone
  double hausdorffBudgetPercent = 0.5;  ///< default 0.5: an edit whose faces leave the input surface by more
                                        ///< (percent of its bounding-box diagonal) is undone
  double minAngleDeg = 30;              ///< default 30: an edit is undone if, after local relaxation, a triangle
                                        ///< around it has a smaller angle (unless one already had before the edit)
  std::vector<char> frozen;             ///< default empty: per vertex index, 1 = never touched by an edit (protected
                                        ///< selection); vertices created later are free
  double sharpEdgeDeg = 25;             ///< default 25: input edges sharper than this are sampled for the Hausdorff
                                        ///< check
  double hausdorffSamplesPerEdge = 0;   ///< default 0 (sharp edges only): input samples per edited edge length for
                                        ///< the Hausdorff check besides its sharp edges; 2 is stricter and ~3x slower
  int localRelaxIterations = 3;         ///< default 3: sweeps of local relaxation of the 2-ring after each step
  // --- transport (pair_transport.h)
  int maxTravel = 12;                   ///< default 12: most pair steps a 5-7 pair is transported to meet a partner
  int glideTravel = 30;                 ///< default 30 (the filter: 4 x maxTravel): most steps a pair glides
                                        ///< straight on looking for a partner
  int targetsPerPair = 4;               ///< default 4: nearest irregular vertices a pair tries to reach, per round
  // --- the driver (automatic_reduction.h)
  int maxSweeps = 12;                   ///< default 12: passes over the irregular vertices
  double minSweepGainPercent = 1;       ///< default 1: stop when a pass removes no more than this share
  RelaxMode finalRelax = RelaxMode::Local;  ///< default Local: final relaxation of the whole mesh: local sweeps,
                                            ///< or a global solve (eq. 5) followed by local sweeps
  int globalRelaxRounds = 3;            ///< default 3: solve-and-project rounds of the final global relaxation
  int finalLocalSweeps = 5;             ///< default 5: local sweeps over the whole mesh at the end (0: none)
  bool boundaryStage = true;            ///< default true: once per sweep, interior irregular vertices near a
                                        ///< boundary are moved into it or cancelled there (boundary_reduction.h)
  BoundaryReductionOptions boundary;    ///< the boundary stage's settings (its boundaryLimit is set by the run:
                                        ///< the input's boundary irregular count)
  double timeLimitSeconds = std::numeric_limits<double>::infinity();  ///< default: no limit (results then do
                                        ///< not depend on the machine's speed); else stop editing (keeping what was
                                        ///< done) after this long
  std::function<bool(int, const char*)> progress;  ///< default none: (percent, stage); returning false interrupts
                                                   ///< and rolls back
};

struct ReductionReport {
  Result result = Result::Fail("not run");
  std::map<int, int> histogramBefore, histogramAfter;  ///< interior valence -> count
  int irregularBefore = 0, irregularAfter = 0;
  int typeSplits = 0;         ///< vertices of valence <= 4 or >= 8 reduced to 5/7
  int localCancellations = 0; ///< atomic removals applied where they were
  int transports = 0;         ///< pair transports that ended in a cancellation
  int glides = 0;             ///< pairs that glided straight on into a cancellation
  int pairSteps = 0;          ///< pair steps of those transports
  int splitAbsorptions = 0;   ///< stretched dislocations split into two pairs that were both cancelled
  int undone = 0;             ///< edits undone (angle, Hausdorff or fold), not counting those inside a
                              ///< split-and-absorb that was undone as a whole
  // The guard's refusals by reason count every refusal, those inside an undone
  // split-and-absorb included (so their sum can exceed `undone`):
  int undoneAngle = 0;        ///< edits the guard undid for a triangle under the angle bound
  int undoneHausdorff = 0;    ///< ... for leaving the input surface by more than the budget
  int undoneFrozen = 0;       ///< ... for touching the protected region
  int undoneBoundary = 0;     ///< ... for raising the boundary irregular count above the input's
  /// Edits the guard undid (angle, Hausdorff, frozen), by the irregular vertex each tried to
  /// cancel, move or split: vertex index in the returned mesh -> count (vertices since deleted
  /// are left out). For the classification of the leftovers.
  std::map<int, int> undoneAt;
  bool globalRelaxUndone = false;  ///< the final global solve lowered the smallest angle and was undone
  bool finalSweepsUndone = false;  ///< the final local sweeps overshot the Hausdorff budget, or lowered the
                                   ///< smallest angle under the bound, and were undone
  bool timeLimitReached = false;
  bool interrupted = false;
  double hausdorffPercent = 0;  ///< symmetric distance of the result to the input (HausdorffPercent)
  int budgetRetries = 0;        ///< reruns with a tighter per-edit budget after overshooting
  bool allUndone = false;       ///< even the retries overshot: the mesh was given back unchanged
  double seconds = 0;
  int boundaryIrregularBefore = 0, boundaryIrregularAfter = 0;  ///< boundary irregular vertices (corner rule,
                                                                ///< topology.h); irregularBefore/After: interior
  BoundaryReductionReport boundaryStage;  ///< what the boundary stage did, summed over the sweeps
  LeftoverReport leftovers;  ///< why each irregular vertex left stays (leftover_reasons.h; boundary ones: "boundary");
                             ///< its vertex indices are those of the returned (compacted) mesh
  explicit operator bool() const { return result.ok; }
};

}  // namespace irregular
}  // namespace vcg_ext
