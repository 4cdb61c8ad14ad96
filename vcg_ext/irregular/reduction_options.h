// filter_irregular: the user settings of the automatic reduction (automatic_reduction.h) and
// what a run reports. Settings only: the run's own state lives in reduction_state.h.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "boundary_reduction.h"
#include "leftover_reasons.h"
#include "relaxation.h"
#include "result.h"

namespace vcg_ext {
namespace irregular {

/// Why an edit tried in a region was undone: the edit guard's refusals (edit_guard.h), or a
/// split-and-absorb (pair_transport.h) whose closing cancellation never happened.
enum class Refusal { Angle = 0, Hausdorff, Frozen, Boundary, NoCancellation, Fold };
constexpr int kRefusalKinds = 6;
/// A region of the bounded effort: the vertices within this many edges of an irregular vertex
/// (the edit guard relaxes and judges the 2-ring of what an edit touches).
constexpr int kRegionRings = 2;
inline const char* RefusalName(Refusal r) {
  static const char* n[kRefusalKinds] = {"angle", "Hausdorff budget", "protected selection", "boundary count",
                                         "no cancellation", "triangle turned over"};
  return n[int(r)];
}

/// A region the run gave up on (bounded effort, issue 14 "thin parts make it grind"): the
/// irregular vertex whose turns there had maxRefusalsPerRegion edits refused, and why.
struct GaveUpRegion {
  int vertex = -1;           ///< the irregular vertex the region is around (index of the returned mesh)
  int irregularAround = 0;   ///< interior irregular vertices within kRegionRings edges of it, itself included
  int refused = 0;           ///< edits refused there (= the bound when it was given up)
  int byReason[kRefusalKinds] = {};  ///< those refusals by Refusal
  double thickness = std::numeric_limits<double>::infinity();  ///< local thickness in mean edge lengths
                             ///< (leftover_reasons.h); inf: not a thin part
  bool Thin() const { return thickness < std::numeric_limits<double>::infinity(); }
  /// "gave up around vertex 812 (3 irregular vertices) after 12 refused edits: thin part (1.9
  /// edge lengths across); Hausdorff budget 9, angle 3"
  std::string Describe() const {
    std::ostringstream o;
    o << "gave up around vertex " << vertex << " (" << irregularAround << " irregular vertices) after " << refused
      << " refused edits: ";
    if (Thin()) o << "thin part (" << (std::round(thickness * 10) / 10) << " edge lengths across); ";
    const char* sep = "";
    for (int k = 0; k < kRefusalKinds; ++k)
      if (byReason[k]) o << sep << RefusalName(Refusal(k)) << ' ' << byReason[k], sep = ", ";
    return o.str();
  }
};

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
  double angleAllowancePercent = 0.8;   ///< default 0.8: this share of the mesh's triangles may be left with an angle
                                        ///< under minAngleDeg by edits, counted over the whole mesh, the input's own
                                        ///< included (EditGuard::UnderBound; issue 14 bounds the share under 30
                                        ///< degrees at 1%); such an edit must still keep every angle at or above
                                        ///< angleFloorDeg (or what was there before; a triangle at a crease line
                                        ///< keeps minAngleDeg - creaseAngleSlackDeg). The peer's remeshing at 20K:
                                        ///< lion 107 -> 79 interior irregular vertices, bull 284 -> 248, femur
                                        ///< 494 -> 442, holes 83 -> 53, fandisk 175 -> 148 (0.9.30); 0: every edit
                                        ///< keeps minAngleDeg
  double angleFloorDeg = 20;            ///< default 20: the smallest angle an edit may leave under the allowance
                                        ///< (at most minAngleDeg)
  std::vector<char> frozen;             ///< default empty: per vertex index, 1 = never touched by an edit (protected
                                        ///< selection); vertices created later are free
  double sharpEdgeDeg = 25;             ///< default 25: input edges sharper than this are sampled for the Hausdorff
                                        ///< check
  double creaseDeg = 60;                ///< default 60 (not a filter parameter): the input's crease lines, connected
                                        ///< sets of at least creaseMinEdges edges sharper than this (crease_lines.h),
                                        ///< stay sharp: no relaxation moves their vertices (after an edit, in a
                                        ///< transport, at the end); 0: none. Lower catches more of a crease that a
                                        ///< remeshing splits over two edges (fandisk at 20K has a stretch of a
                                        ///< 61-degree crease at 57-58 degrees), but also ridges of organic models:
                                        ///< at 55 the triceratops kept 220 irregular vertices instead of 174, at 45
                                        ///< the elephant 185 instead of 130
  double creaseThinEdges = 4;           ///< default 4 (not a filter parameter): a crease line that is the rim of a
                                        ///< part thinner than this many mean edge lengths (thin_creases.h) is not
                                        ///< kept sharp; 0: every crease line is (before 0.9.29)
  int creaseMinEdges = 8;               ///< default 8 (not a filter parameter): fewer sharp edges together are a
                                        ///< coarse spot (an ear tip), not a crease
  double creaseStraightShare = 0.9;     ///< default 0.9 (not a filter parameter): ... and a set is a crease line
                                        ///< only if it passes this share of its vertices (or all but two, an
                                        ///< open line's ends) straight through: two of its edges, turning by
                                        ///< under 30 degrees (crease_lines.h). fandisk's creases 98%; the frayed
                                        ///< sharp edges of an organic model remeshed from a coarse input 78% at
                                        ///< most (femur, bull at 20K: 987 -> 494, 543 -> 284 irregular vertices
                                        ///< left); 0: any set, as before 0.9.27
  double creaseAngleSlackDeg = 4;       ///< default 4 (not a filter parameter): a triangle with a vertex on a crease
                                        ///< line may fall this far under minAngleDeg after an edit. Crease vertices
                                        ///< are never relaxed, so an edit next to a crease cannot even out the
                                        ///< triangles it squeezes there (fandisk at 20K: 234 irregular vertices left
                                        ///< with no slack, 172 with 4 degrees, 0.32% of triangles under 30)
  double creaseBudgetPercent = 0.05;    ///< default 0.05 (not a filter parameter): an edit that leaves a sample of
                                        ///< those creases farther than this (percent of the diagonal) from the
                                        ///< edited surface is undone (a flip across a crease, a collapse of a
                                        ///< crease vertex); the Hausdorff budget still holds elsewhere
  double hausdorffSamplesPerEdge = 0;   ///< default 0 (sharp edges only): input samples per edited edge length for
                                        ///< the Hausdorff check besides its sharp edges; 2 is stricter and ~3x slower
  int localRelaxIterations = 3;         ///< default 3: sweeps of local relaxation of the 2-ring after each step
  int angleRepairRounds = 6;            ///< default 6 (not a filter parameter): a transport's route that the guard
                                        ///< refuses for triangles under the minimum angle is relaxed again around
                                        ///< those triangles, up to this many times, and kept if then none is left
                                        ///< (0: never). bunny00 / knot1 / elephant at 20K: 72 / 54 / 128 left
                                        ///< without, 62 / 46 / 126 with (3 rounds: 60 / 56 / 126); at maxTravel 24
                                        ///< bunny00 / knot1: 46 / 34 without, 38 / 22 with; about the same time.
                                        ///< On a mesh finer than travelReferenceVertices it grows as the travel
                                        ///< does (ScaleToResolution)
  double angleRepairSlackDeg = 8;       ///< default 8 (not a filter parameter): ... only when the smallest angle
                                        ///< there is at most this far under the minimum (farther, as on thin
                                        ///< parts, the rounds cost a quarter more time and save nothing)
  // --- transport (pair_transport.h)
  int maxTravel = 12;                   ///< default 12: most pair steps a 5-7 pair is transported to meet a partner
  int glideTravel = 30;                 ///< default 30 (the filter: 4 x maxTravel): most steps a pair glides
                                        ///< straight on looking for a partner
  int travelReferenceVertices = 20000;  ///< default 20000: maxTravel and glideTravel are steps on a mesh of this
                                        ///< many vertices; on a finer one the same distance on the surface is more
                                        ///< steps, and both grow by sqrt(V / this), as does nearMeetingTries
                                        ///< (ScaleToResolution; never shrink; 0: fixed).
                                        ///< bunny00 remeshed by the peer to 80K (72K vertices): 194 left at 12
                                        ///< steps (0.9.4), 90 at the scaled 24 (0.9.5)
  double maxTravelScale = 2;            ///< default 2 (not a filter parameter): ... by at most this factor (80K
                                        ///< vertices at the default reference), so that a finer mesh's time
                                        ///< grows with its size only (0: no bound)
  bool partialAbsorption = true;        ///< default true (not a filter parameter): a split-and-absorb whose walk
                                        ///< stops short is kept when the pairs it generated already met more
                                        ///< irregular vertices than they made (pair_transport.h). The full set's
                                        ///< 18 models at 20K (native bench): 6216 left without, 6159 with (10
                                        ///< fewer, 3 more, 5 the same; bunny00 62 -> 58, knot1 46 -> 48); bunny00
                                        ///< at maxTravel 24: 38 -> 36
  int targetsPerPair = 4;               ///< default 4: nearest irregular vertices a pair tries to reach, per round
  // --- the driver (automatic_reduction.h)
  int maxSweeps = 12;                   ///< default 12: passes over the irregular vertices
  int maxRefusalsPerRegion = 20;        ///< default 20: once this many edits tried around an irregular vertex
                                        ///< (in its turns) were refused, the region is given up, and retried only
                                        ///< after an edit nearby was kept (0: no bound). Counts attempts, not
                                        ///< seconds, so runs stay deterministic. Every route the guard refuses
                                        ///< counts (0.9.4): at 12, bunny00 gave up 6 regions and knot1 / mushroom /
                                        ///< elephant kept 54 / 65 / 136 irregular vertices, against 54 / 59 / 128
  double minSweepGainPercent = 1;       ///< default 1: stop when a pass removes no more than this share
  double farMeetingReach = 1.5;         ///< default 1.5 (not a filter parameter): after the sweeps, an interior
                                        ///< irregular vertex with no partner within maxTravel edges but one within
                                        ///< this x maxTravel gets one more turn, a far meeting (AutomaticReduction::
                                        ///< FarMeetings); 0: none. bunny00 / knot1 / elephant at 20K (native bench):
                                        ///< the partners of the far meetings kept lay 13-19 edges away (one at 21)
  double farMeetingTravel = 3;          ///< default 3: ... whose split-and-absorb walks up to this x maxTravel
                                        ///< edges and transports the pairs it generates as far: with the pairs
                                        ///< transported only maxTravel, no far meeting was kept (knot1: 0 of 33);
                                        ///< at 1.5 x, 4 / 4 / 3 instead of 6 / 6 / 5 (bunny00 / knot1 / elephant)
                                        ///< at 2 x; with the rounds and near meetings (0.9.20) knot1 at 20K kept 26
                                        ///< at 2 x and 20 at 3 x, bunny00 / mushroom / the elephant the same
  int farMeetingRounds = 3;             ///< default 3 (not a filter parameter): rounds of far meetings; a round
                                        ///< after the first gives a turn only to a vertex it did not try before, or
                                        ///< one with an edit kept within maxTravel edges since its turn failed, and
                                        ///< the rounds stop after one that removes nothing (1: one round)
  int nearMeetingTries = 8;             ///< default 8 (not a filter parameter): the far meetings also give a turn
                                        ///< to vertices with a partner within maxTravel that the sweeps could not
                                        ///< cancel (near meetings: the longer walk finds routes the travel did
                                        ///< not), except a cap or saddle whose curvature needs it and a thin part
                                        ///< (leftover_reasons.h; bunny00 / knot1 / the bull at 20K: none of 6 / 1 /
                                        ///< 105 such turns kept); they must pay their way: the stage stops them
                                        ///< once this many plus nearMeetingTriesPerKept per kept one were tried
                                        ///< (the bull: 2 of 185 kept, a tenth of its time); on a mesh finer
                                        ///< than travelReferenceVertices it grows as the travel does
                                        ///< (ScaleToResolution). 0: none
  int nearMeetingTriesPerKept = 4;      ///< default 4 (not a filter parameter): see nearMeetingTries
  RelaxMode finalRelax = RelaxMode::Local;  ///< default Local: final relaxation of the whole mesh: local sweeps,
                                            ///< or a global solve (eq. 5) followed by local sweeps
  int globalRelaxRounds = 3;            ///< default 3: solve-and-project rounds of the final global relaxation
  int finalLocalSweeps = 5;             ///< default 5: local sweeps over the whole mesh at the end (0: none)
  bool partialSweepUndo = true;         ///< default true (not a filter parameter): when those sweeps push a
                                        ///< triangle under the angle bound or the surface past the verified
                                        ///< margin of the Hausdorff budget, only the vertices there are put
                                        ///< back (sweep_undo.h); false: every vertex is
  double anglePolishDeg = 30;           ///< default 30 (not a filter parameter): before the final relaxation, each
                                        ///< triangle with an angle under this is relaxed locally under the guard,
                                        ///< kept if fewer such triangles are left around it (angle_polish.h;
                                        ///< issue 14's bound on the share under 30 degrees; 0: none)
  int anglePolishRounds = 1;            ///< default 1 (not a filter parameter): passes of that polish (the cow at
                                        ///< 20K: 57 of 449 kept in one, 61 in two, 62 in four; 0.76% / 0.75% / 0.74%)
  bool angleFlips = true;               ///< default true (not a filter parameter): after that polish, the longest
                                        ///< edge of each triangle still under anglePolishDeg is flipped where that
                                        ///< does not raise the irregular count and the guard passes it (angle_flip.h)
  bool aggregateLeftovers = false;      ///< default false (the filter's "aggregate"): after the sweeps and
                                        ///< meetings, two leftover v5 two edges apart become one v4 and two v7
                                        ///< across an edge one v8 (type aggregation, sec. 6.3), where the guard
                                        ///< passes it (leftover_aggregation.h): fewer irregular vertices, of higher
                                        ///< charge; false keeps v5 and v7 only, as the paper's results do
  int gatherRadius = 16;                ///< default 16 (not a filter parameter; with aggregateLeftovers only): a
                                        ///< leftover v5 / v7 with no partner in that configuration walks toward
                                        ///< one of its type within this many edges (the 3 nearest in turn), each
                                        ///< step's generated 5-7 pair transported away (leftover_aggregation.h),
                                        ///< and the two aggregate if they get there; 0: no gathering. Native
                                        ///< bench, 8 models at 20K (the pairs' travel kGatherTravelScale): 12 and
                                        ///< 16 edges leave 1418 and 1409 in all (the elephant 63 and 60; without
                                        ///< gathering 90)
  int gatherTries = 16;                 ///< default 16 (not a filter parameter): the gathering's bound of effort,
                                        ///< as the near meetings' (nearMeetingTries): walks are tried while fewer
                                        ///< than this many plus gatherTriesPerGathered per kept gathering were
                                        ///< (leftover_aggregation.h); 0: no bound
  int gatherTriesPerGathered = 3;       ///< default 3 (not a filter parameter): see gatherTries. The full set at
                                        ///< 20K with aggregate (native bench, 0.9.33; unbounded 2514 left in all):
                                        ///< 8 stops the femur and the man only; 4 also the bull (179 -> 185 left,
                                        ///< 42.5 G -> 37.7 G instructions, still 3.10x the peer) and the cow; 3
                                        ///< the bull at 205 (31.8 G), 2620 in all; 2: 209 (30.5 G), 2651 in all.
                                        ///< The elephant keeps its 60 at each
  bool reuseDeadSlots = true;           ///< default true: a split takes the slot of a vertex or face a kept edit
                                        ///< deleted before it appends one (slot_pool.h), so the vectors grow by
                                        ///< what the run adds, not by what it adds and deletes (bunny00 subdivided
                                        ///< once: 150,818 -> 212,417 vertex slots without; issue 14's memory target)
  bool boundaryStage = true;            ///< default true: once per sweep, interior irregular vertices near a
                                        ///< boundary are moved into it or cancelled there (boundary_reduction.h)
  bool boundarySlide = true;            ///< default true (not a filter parameter): the guard's relaxation of a
                                        ///< boundary-stage edit slides the boundary vertices around it along the
                                        ///< input's boundary (as the stage's own relaxation does), corners excepted;
                                        ///< false: they stay, and a split or collapse on the boundary leaves its
                                        ///< triangles squeezed against them. holes at 20K: 110 -> 83 interior
                                        ///< irregular vertices (0.44%), 444 -> 437 in all, smallest angle 20.3 ->
                                        ///< 22.9; the lion 337 -> 320 in all (0.9.13)
  bool refusedRouteMemo = true;         ///< default true (not a filter parameter): a pair transport's try whose
                                        ///< probe ends where a refused try of the same transport ended is refused
                                        ///< again without its relaxation and guard (PairTransport::TryMove); false:
                                        ///< every try is judged. The same result to the bit either way (fandisk at
                                        ///< 20K: 6% fewer instructions, 0.9.14); false is for tests and benchmarks
  BoundaryReductionOptions boundary;    ///< the boundary stage's settings (its boundaryLimit is set by the run:
                                        ///< the input's boundary irregular count)
  double timeLimitSeconds = std::numeric_limits<double>::infinity();  ///< default: no limit (results then do
                                        ///< not depend on the machine's speed); else stop editing (keeping what was
                                        ///< done) after this long
  std::function<bool(int, const char*)> progress;  ///< default none: (percent, stage); returning false interrupts
                                                   ///< and rolls back
};

/// The filter's reading of its maxTravel parameter (filter_automatic_reduction.cpp), in one
/// place so that the native bench (bench/bench_reduction.cpp) runs what the filter runs (it
/// kept the struct's glide default of 30 instead, and its counts differed from pymeshlab's:
/// fandisk 163 instead of 171, knot1 50 instead of 42): pairs glide 4 x maxTravel steps, and
/// a longer travel, a request for a more thorough run, raises the refusals a region may take
/// to maxTravel (the default 20 at the default travel 12). bunny00 at 20K vertices: maxTravel
/// 24 leaves 38 irregular vertices against 62 at 12, at 2.33x the peer's time against 1.31x
/// (0.9.5, the pymeshlab bench; 0.9.4: 46 against 72); with the bound held lower a longer
/// travel gives up more regions (0.6.0: 52 against 48 at 12 and 24), which are retried after
/// every nearby edit. On a mesh above 20K vertices the run scales both travels
/// (travelReferenceVertices), not this bound.
inline void SetFilterTravel(ReductionOptions& opt, int maxTravel) {
  opt.maxTravel = maxTravel;
  opt.glideTravel = 4 * maxTravel;
  opt.maxRefusalsPerRegion = std::max(ReductionOptions().maxRefusalsPerRegion, maxTravel);
}

/// opt scaled to a mesh of `vertices` vertices: a mesh finer than travelReferenceVertices needs
/// s = sqrt(V / reference) times more steps for the same distance on the surface, so maxTravel
/// and glideTravel grow by s (most of what bunny00 at 80K vertices kept at 12 steps had no
/// partner within them: 76 of 194), up to maxTravelScale times: a transport's cost grows with
/// its travel, so an unbounded scale makes the run superlinear in the mesh size. The near
/// meetings' bound (nearMeetingTries) grows by s too: a finer mesh leaves more candidates for
/// them (bunny00, the peer's outputs: 29 at 80K, 4 at 20K), and at 80K the unscaled 8 tries
/// stopped them before the first kept one (80 left, 0 of 8 kept; with 16, 70 left, 5 of 29
/// kept, every candidate tried; the same time). So do the angle repair rounds (angleRepairRounds):
/// a route of twice the steps leaves twice the stretch of squeezed triangles to lift, and at
/// 80K the repairs' 6 rounds left most of what stayed refused for its angles ("budget" in the
/// leftover reasons: bunny00 28 of 70). The peer's outputs at 80K vertices, native bench, 6
/// rounds -> 12: bunny00 70 -> 60, knot1 58 -> 58, the elephant 162 -> 161, bear 95 -> 79,
/// homer 125 -> 117 (475 left instead of 510); bunny00 at 80K with 10 / 11 / 14 / 16 rounds:
/// 70 / 64 / 68 / 60, a trend under the noise of which routes happen to pass. Never shrinks: a
/// coarser mesh keeps opt (at 20K, 12 rounds left bunny00 48 instead of 42).
inline ReductionOptions ScaleToResolution(ReductionOptions opt, int vertices) {
  if (opt.travelReferenceVertices > 0 && vertices > opt.travelReferenceVertices) {
    double s = std::sqrt(double(vertices) / double(opt.travelReferenceVertices));
    if (opt.maxTravelScale > 0) s = std::min(s, opt.maxTravelScale);
    opt.maxTravel = int(std::lround(opt.maxTravel * s));
    opt.glideTravel = int(std::lround(opt.glideTravel * s));
    opt.nearMeetingTries = int(std::lround(opt.nearMeetingTries * s));
    opt.angleRepairRounds = int(std::lround(opt.angleRepairRounds * s));
  }
  return opt;
}

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
  int partialAbsorptions = 0; ///< split-and-absorbs kept part way, for what they had already removed
                              ///< (partialAbsorption)
  int farMeetings = 0;        ///< far meetings tried (ReductionOptions::farMeetingReach)
  int farMeetingsKept = 0;    ///< ... and kept (each a transport or split-and-absorb that cancelled)
  int nearMeetings = 0;       ///< near meetings tried (ReductionOptions::nearMeetingTries)
  int nearMeetingsKept = 0;   ///< ... and kept
  int meetingRounds = 0;      ///< rounds of far and near meetings run (ReductionOptions::farMeetingRounds)
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
  int finalSweepsRestored = 0;     ///< vertices the final sweeps moved that were put back where they were,
                                   ///< around triangles the sweeps pushed under the angle bound and samples
                                   ///< of the distance measure past the margin (the sweeps kept elsewhere:
                                   ///< ReductionOptions::partialSweepUndo, sweep_undo.h)
  bool timeLimitReached = false;
  bool interrupted = false;
  double hausdorffPercent = 0;  ///< symmetric distance of the result to the input (HausdorffPercent)
  int angleRepairs = 0;       ///< transport routes kept after angle repair rounds (angleRepairRounds)
  int routesRefusedAgain = 0; ///< transport tries refused again from the refused-route memo (refusedRouteMemo)
  int anglePolished = 0;      ///< triangles under anglePolishDeg relaxed by the angle polish and kept
  int anglePolishBelow = 0;   ///< triangles under anglePolishDeg when the polish began
  int angleFlips = 0;         ///< longest edges of triangles under anglePolishDeg flipped and kept (angleFlips)
  int angleFlipsTried = 0;    ///< ... flips tried (count-neutral, opening the triangle before relaxation)
  int aggregatedV4 = 0;       ///< leftover v5 pairs merged into a v4 (aggregateLeftovers)
  int aggregatedV8 = 0;       ///< leftover v7 pairs merged into a v8 (aggregateLeftovers)
  int aggregationsTried = 0;  ///< ... pairs tried under the guard
  int gathered = 0;           ///< ... of the aggregations, those whose pair first walked together (gatherRadius)
  int gathersTried = 0;       ///< ... walks tried
  bool gatherBoundReached = false;  ///< ... and stopped at their bound of effort (gatherTries)
  int thinRimLines = 0;       ///< crease lines left unprotected as a thin part's rims (creaseThinEdges)
  int travel = 0;               ///< the pair travel used: maxTravel, scaled to the mesh (travelReferenceVertices)
  int budgetRetries = 0;        ///< reruns with a tighter per-edit budget after overshooting
  bool allUndone = false;       ///< even the retries overshot: the mesh was given back unchanged
  double seconds = 0;
  int boundaryIrregularBefore = 0, boundaryIrregularAfter = 0;  ///< boundary irregular vertices (corner rule,
                                                                ///< topology.h); irregularBefore/After: interior
  BoundaryReductionReport boundaryStage;  ///< what the boundary stage did, summed over the sweeps
  /// Regions given up (maxRefusalsPerRegion) that still hold an irregular vertex at the end,
  /// in increasing vertex order; gaveUpVertices: the distinct interior irregular vertices in them.
  std::vector<GaveUpRegion> gaveUp;
  int gaveUpVertices = 0;
  LeftoverReport leftovers;  ///< why each irregular vertex left stays (leftover_reasons.h; boundary ones: "boundary");
                             ///< its vertex indices are those of the returned (compacted) mesh
  explicit operator bool() const { return result.ok; }
  /// An attempt made of several guarded edits is undone whole: the report goes back to
  /// `before` it, but keeps what the guard refused in it (the refusals by reason).
  void RestoreKeepingRefusals(const ReductionReport& before) {
    const int angle = undoneAngle, hausdorff = undoneHausdorff, frozen = undoneFrozen, boundary = undoneBoundary;
    *this = before;
    undoneAngle = angle, undoneHausdorff = hausdorff, undoneFrozen = frozen, undoneBoundary = boundary;
  }
};

}  // namespace irregular
}  // namespace vcg_ext
