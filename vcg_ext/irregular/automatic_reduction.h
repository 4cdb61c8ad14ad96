// filter_irregular: automatic reduction of the number of irregular vertices, built only from
// the paper's operations (Li et al., sec. 6.2, 6.3, 7): the driver.
//
// What a designer of the paper does by hand, as a deterministic greedy loop:
//   1. type change (sec. 6.3): every vertex of valence <= 4 or >= 8 is split into v5 / v7
//      (local_cancellation.h);
//   2. local cancellation: wherever a single flip or collapse removes irregular vertices (the
//      atomic removals of sec. 6.2), it is applied (local_cancellation.h);
//   3. transport (sec. 7.1, 7.2): an adjacent 5-7 pair is moved by pair steps toward the
//      nearest other irregular vertices, within a travel bound, until a removal applies there;
//      stretched dislocations are split and absorbed (pair_transport.h);
//   4. steps 2-3 repeat with a growing travel distance;
//   5. far meetings: a vertex left with no partner within the travel, but one a little
//      farther, gets one more turn with a longer travel (FarMeetings); so does one with a
//      partner within the travel that the shape does not need, while such near meetings pay
//      off; in rounds, while a round removes something (Meetings);
//   6. a final relaxation (sec. 8) evens out the triangles.
// Every edit is relaxed locally and passes the edit guard (edit_guard.h: angle bound,
// Hausdorff budget, frozen region) or is undone. Settings: reduction_options.h; the run's
// state (running count, stamps, the input snapshot): reduction_state.h.
//
// Cost: each edit costs O(what it touches) (the guard, the count, the journal, which is
// committed after every kept edit); a sweep scans the vertices once; the input is copied once
// (as journal records) for the whole-run undo.
//
// Preconditions: a manifold, consistently oriented triangle mesh with FF and VF adjacency up to
// date (see mesh_checks.h). Boundary vertices are edited only by the boundary stage (boundary_reduction.h), which never
// raises their irregular count above the input's. Postconditions: the mesh is a
// valid 2-manifold with the same topology, compacted; on interruption (progress callback
// returns false) the mesh is exactly as it was.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include "angle_flip.h"
#include "angle_polish.h"
#include "composite_ops.h"
#include "edit_guard.h"
#include "leftover_aggregation.h"
#include "local_cancellation.h"
#include "pair_transport.h"
#include "quality.h"
#include "reduction_options.h"
#include "reduction_state.h"
#include "sweep_undo.h"
#include "thin_creases.h"

namespace vcg_ext {
namespace irregular {

template <class MeshType>
class AutomaticReduction {
 public:
  typedef MeshEditor<MeshType> Editor;
  typedef typename MeshType::CoordType CoordType;

  /// original: the input surface (edits are projected on it and measured against it).
  AutomaticReduction(MeshType& m, const SurfaceProjector& original, ReductionOptions opt = ReductionOptions())
      : m_(m),
        original_(original),
        opt_(ScaleToResolution(std::move(opt), m.vn)),
        ed_(m),
        crease_(ProtectedCreases(m, opt_, &original, &inputCrease_, &thinRimLines_)),
        inputBoundary_(m),
        comp_(ed_, &original, Quiet(&crease_)),
        state_(m, ed_, opt_),
        guard_(m, original, opt_, ed_, state_, &crease_, &inputCrease_),
        cancel_(m, ed_, comp_, guard_, state_),
        transport_(m, opt_, ed_, comp_.atomic(), guard_, state_, cancel_) {
    // The run reports counts and reasons of its own, never an atomic operation's text.
    comp_.atomic().SetDescribing(false);
    // A crease or frozen vertex keeps its index-keyed flag through a whole-run restore
    // (RestoreSnapshot), so its slot is never reused; a reused slot's run state is forgotten.
    ed_.slotPool().Enable(opt_.reuseDeadSlots, [this](int v) {
      if (state_.Frozen(v) || (size_t(v) < crease_.size() && crease_[size_t(v)])) return false;
      state_.ForgetVertex(v);
      return true;
    });
  }

  /// Runs the reduction. Postcondition on success: the symmetric Hausdorff distance of the
  /// result to the input, as measured by HausdorffPercent (quality.h), is within the budget
  /// (the per-edit checks sample; a final measurement verifies, and a run that overshoots is
  /// redone with a tighter per-edit budget, at worst undone whole).
  ReductionReport Run() {
    ReductionReport rep;
    t0_ = std::chrono::steady_clock::now();
    state_.TakeSnapshot();
    Histogram(rep.histogramBefore, rep.irregularBefore);
    rep.boundaryIrregularBefore = CountIrregularByPlace(m_).boundary;
    for (int attempt = 0;; ++attempt) {
      ReductionReport r;
      r.histogramBefore = rep.histogramBefore;
      r.irregularBefore = rep.irregularBefore;
      r.boundaryIrregularBefore = rep.boundaryIrregularBefore;
      r.budgetRetries = attempt;
      r.travel = opt_.maxTravel;
      r.hausdorffPercent = -1;
      Edit(r);  // sets r.hausdorffPercent when the final relaxation measured the result
      if (r.interrupted) {
        state_.RestoreSnapshot();
        r.result = Result::Fail("interrupted: the mesh is unchanged");
        return r;
      }
      if (r.hausdorffPercent < 0) r.hausdorffPercent = HausdorffPercent(m_, original_);
      // the independent check of the tests samples more densely than HausdorffPercent: keep
      // a small margin below the budget
      const bool within = r.hausdorffPercent <= kVerifyMargin * opt_.hausdorffBudgetPercent;
      if (within || attempt == kMaxBudgetRetries) {
        rep = r;
        if (!within) {
          // even the tightest retry overshoots: give the input back unchanged
          state_.RestoreSnapshot();
          rep.allUndone = true;
          rep.hausdorffPercent = HausdorffPercent(m_, original_);
        }
        break;
      }
      // Over the budget: start again with the per-edit check stricter: the input sampled all
      // over (not only on sharp edges), and the per-edit budget lowered in proportion to the
      // overshoot (gently: where the input is curved, the mesh before the edits may already
      // use most of the budget, and a much lower one would forbid every edit there).
      state_.RestoreSnapshot();
      state_.TakeSnapshot();
      guard_.Tighten(std::max(0.5, std::min(0.95, kVerifyMargin * opt_.hausdorffBudgetPercent / r.hausdorffPercent)));
      state_.Reset();
      globalKept_ = sweepsKept_ = true;
      sweepsRestored_ = 0;
    }
    ed_.Commit();
    state_.DropSnapshot();
    if (!rep.allUndone) Explain(rep);
    rep.undoneAt = CompactedIndices(state_.UndoneAt());
    CompactKeepingAdjacency(m_);
    ed_.slotPool().Clear();  // the pooled slots are gone
    Histogram(rep.histogramAfter, rep.irregularAfter);
    rep.boundaryIrregularAfter = CountIrregularByPlace(m_).boundary;
    rep.globalRelaxUndone = !globalKept_;
    rep.finalSweepsUndone = !sweepsKept_;
    rep.finalSweepsRestored = sweepsRestored_;
    rep.seconds = Elapsed();
    rep.thinRimLines = thinRimLines_;
    rep.result = Result::Ok();
    return rep;
  }

 private:
  static constexpr double kVerifyMargin = 0.97;  ///< final distance must be under this share of the budget
  static constexpr int kMaxBudgetRetries = 2;     ///< reruns with a tighter per-edit budget

  /// One pass of the whole pipeline (type change, sweeps, final relaxation) into rep.
  void Edit(ReductionReport& rep) {
    state_.StartCount();
    RecountAngleAllowance();
    bool go = Stage(rep, 0, "Splitting high and low valences");
    if (go) cancel_.ReduceTypes(rep);
    // The boundary stage (boundary_reduction.h): its edits pass the same guard; a kept one is
    // committed only once the stage has re-counted it (BoundaryEditGuard::end).
    std::unique_ptr<GuardedEdit<MeshType>> boundaryEdit;
    std::vector<int> boundaryRelaxed;  // seeds relaxed between the steps of the current edit
    BoundaryEditGuard bg;
    bg.begin = [&](const std::vector<int>& around) {
      boundaryEdit.reset(new GuardedEdit<MeshType>(guard_, rep, around));
      boundaryRelaxed.clear();
    };
    // the stage's edits split and collapse boundary edges: their relaxation lets the boundary
    // vertices around slide along the input's boundary, or the triangles there stay squeezed
    // and the angle check refuses the edit (ReductionOptions::boundarySlide)
    const BoundaryCurve* slide = opt_.boundarySlide ? &inputBoundary_ : nullptr;
    bg.relax = [&](const std::vector<int>& seeds) {
      guard_.RelaxAround(seeds, slide);
      boundaryRelaxed.insert(boundaryRelaxed.end(), seeds.begin(), seeds.end());
    };
    bg.accept = [&](const std::vector<int>& touched) {
      guard_.RelaxAround(touched, slide);
      // judged where anything moved: the touched vertices and every seed relaxed on the way
      std::vector<int> judged(touched);
      judged.insert(judged.end(), boundaryRelaxed.begin(), boundaryRelaxed.end());
      return boundaryEdit && boundaryEdit->Judge(judged);
    };
    bg.end = [&](bool kept, const std::vector<int>& touched) {
      if (boundaryEdit && kept) boundaryEdit->Keep(touched);
      boundaryEdit.reset();
    };
    BoundaryReductionOptions bo = opt_.boundary;
    bo.boundaryLimit = rep.boundaryIrregularBefore;  // the input's count, also on a budget retry
    BoundaryReduction<MeshType> boundary(ed_, &original_, bg, opt_.frozen.empty() ? nullptr : &opt_.frozen, bo,
                                         &inputBoundary_);
    // Growing travel: cheap local cancellations everywhere first, so the long transports only
    // run for what is left. Sweeps: local removals only until they stop paying, then with
    // transports, until a sweep removes nothing (or a small share) more.
    for (int sweep = 0, travel = 0; go && sweep < opt_.maxSweeps; ++sweep) {
      const int before = state_.Irregular();
      // the angle allowance's count, exact again once per sweep (EditGuard::Recount)
      RecountAngleAllowance();
      go = Stage(rep, 10 + 70 * sweep / opt_.maxSweeps, "Cancelling triples and quadruples") && Sweep(rep, travel);
      // Once per sweep, after the per-vertex strategies: the boundary stage.
      RecountAngleAllowance();
      if (go && opt_.boundaryStage && !state_.Done()) rep.boundaryStage.Add(boundary.Run());
      if (!go || state_.Done()) break;
      const int removed = before - state_.Irregular();
      if (removed * 100 <= before * opt_.minSweepGainPercent) {
        if (travel > 0) break;
        travel = opt_.maxTravel;
      }
    }
    RecountAngleAllowance();
    if (go && !state_.Done()) go = Meetings(rep);
    if (rep.interrupted) return;
    // Opt-in: what curvature or a thin part keeps, in fewer vertices (leftover_aggregation.h).
    // Before the polish and flips, which then work on the aggregates' triangles too.
    if (go && opt_.aggregateLeftovers && !state_.Done()) {
      RecountAngleAllowance();
      const AggregationReport ag = AggregateLeftovers(m_, guard_, rep, &transport_, opt_.gatherRadius);
      rep.aggregatedV4 = ag.v4;
      rep.aggregatedV8 = ag.v8;
      rep.aggregationsTried = ag.tried;
      rep.gathered = ag.gathered;
      rep.gathersTried = ag.gathersTried;
      rep.gatherBoundReached = ag.gatherBoundReached;
    }
    // A stage after the sweeps (e.g. on the boundary) goes here: it runs even when the time
    // limit stopped the editing only if it is cheap; the final relaxation always does.
    if (opt_.progress && !opt_.progress(90, "Relaxing")) {
      rep.interrupted = true;
      return;
    }
    if (opt_.anglePolishDeg > 0) {
      const AnglePolishReport ap = PolishAngles(m_, guard_, rep, opt_.anglePolishDeg, opt_.anglePolishRounds);
      rep.anglePolished = ap.kept;
      rep.anglePolishBelow = ap.below;
    }
    if (opt_.anglePolishDeg > 0 && opt_.angleFlips) {
      const AngleFlipReport af = FlipSqueezedEdges(m_, guard_, rep, opt_.anglePolishDeg);
      rep.angleFlips = af.kept;
      rep.angleFlipsTried = af.tried;
    }
    // the sweeps' stamps and the strategies' per-vertex scratch are not read past this point:
    // give them back before the final relaxation allocates its arrays and the measurement its
    // grid (the run's memory peak)
    state_.ReleaseSweepState();
    comp_.atomic().ReleaseScratch();
    transport_.ReleaseScratch();
    rep.hausdorffPercent = FinalRelax();
  }

  /// The angle allowance's count made exact again (EditGuard::Recount, O(F)): at the start and
  /// between the stages, never per edit; nothing without an allowance.
  void RecountAngleAllowance() {
    if (opt_.angleAllowancePercent > 0) guard_.Recount();
  }

  /// One pass over the irregular vertices: local cancellations; with travel > 0 also pair
  /// transports of up to `travel` steps. False if interrupted or out of time.
  bool Sweep(ReductionReport& rep, int travel) {
    const size_t n = m_.vert.size();
    for (size_t i = 0; i < n && i < m_.vert.size(); ++i) {
      const int v = int(i);
      if ((i & 1023) == 0 && !Stage(rep, int(10 + 70 * i / n / std::max(1, opt_.maxTravel) * std::max(1, travel)),
                                    travel == 0 ? "Cancelling adjacent triples and quadruples"
                                                : "Moving pairs to cancel them"))
        return false;
      if ((i & 255) == 0 && state_.Done()) return true;
      if (!state_.IsInteriorIrregular(v) || state_.Frozen(v)) continue;
      bool kept = false;
      if (!state_.GivenUp(v)) {
        state_.BeginTurn(v);
        kept = Turn(rep, v, travel);
        state_.EndTurn();
      }
      // a turn with the travel strategies that kept nothing, or skipped as given up: v was
      // tried as it is (for the leftover reasons only; "no route" rather than "untried")
      if (!kept && travel > 0) state_.Tried(v);
    }
    return true;
  }

  /// Far and near meetings, after the sweeps, in up to opt.farMeetingRounds rounds: a round
  /// that removes nothing ends them (a later round tries only what changed, FarMeetings).
  /// False if interrupted or out of time.
  bool Meetings(ReductionReport& rep) {
    MeetingEffort near;
    for (int round = 0; round < std::max(1, opt_.farMeetingRounds) && !state_.Done(); ++round) {
      const int before = state_.Irregular();
      ++rep.meetingRounds;
      if (!FarMeetings(rep, round, near)) return false;
      if (state_.Irregular() >= before) break;
    }
    return true;
  }

  /// The near meetings' bound of effort over all rounds (ReductionOptions::nearMeetingTries).
  struct MeetingEffort {
    int tried = 0, kept = 0;
    bool Open(const ReductionOptions& o) const {
      return o.nearMeetingTries > 0 && tried < o.nearMeetingTries + o.nearMeetingTriesPerKept * kept;
    }
  };

  /// One round of far meetings: an interior irregular vertex left with no partner within the
  /// travel (leftover_reasons.h: no irregular vertex it could cancel with within maxTravel
  /// edges) but one within opt.farMeetingReach x maxTravel gets one more turn, whose
  /// transports and split-and-absorb (sec. 7.1, 7.2) walk and carry the pairs they generate
  /// opt.farMeetingTravel x maxTravel edges. The sweeps cannot do it: a stretched dislocation
  /// whose v5 and v7 lie farther apart than the travel is never walked, and giving every turn
  /// of every sweep the longer travel costs what the thorough setting costs (knot1 at 20K:
  /// 3.4x the peer's time). Near meetings: a vertex with a partner within the travel that the
  /// sweeps left gets the same turn, unless the shape needs it (a cap or saddle by curvature,
  /// a thin part), while they pay their way (MeetingEffort). A later round (round > 0) tries
  /// only a vertex whose turn did not fail before, or with an edit kept within maxTravel
  /// edges since (the search is deterministic: unchanged, it would fail again). The candidates
  /// are found in one pass over the vertices, each with a search of the reach's rings; each
  /// turn costs what a sweep's turn with the longer travel costs. False if interrupted or out
  /// of time.
  bool FarMeetings(ReductionReport& rep, int round, MeetingEffort& near) {
    const int reach = FarReach();
    if (reach <= opt_.maxTravel || opt_.farMeetingTravel <= 0) return true;
    const int far = std::max(reach, int(std::lround(opt_.farMeetingTravel * opt_.maxTravel)));
    std::vector<std::pair<int, bool>> candidates;  // (vertex, near meeting)
    {
      LeftoverOptions lo;
      lo.reach = reach;
      LeftoverAnalysis<MeshType> within(m_, lo);
      for (size_t i = 0; i < m_.vert.size(); ++i) {
        const int v = int(i);
        if (!state_.IsInteriorIrregular(v) || state_.Frozen(v) || state_.GivenUp(v)) continue;
        if (round > 0 && state_.UnchangedSinceFailure(v, opt_.maxTravel)) continue;
        // the nearest partner (a breadth-first search): within the reach, beyond the travel
        int distance = -1;
        if (within.PartnerOf(v, &distance) < 0) continue;
        if (distance > opt_.maxTravel) {
          candidates.emplace_back(v, false);
        } else if (near.Open(opt_)) {
          const LeftoverVertex shape = within.ShapeOf(v);
          if (!shape.Has(LeftoverReason::Cap) && !shape.Has(LeftoverReason::Saddle) &&
              !shape.Has(LeftoverReason::Thin))
            candidates.emplace_back(v, true);
        }
      }
    }
    for (size_t i = 0; i < candidates.size(); ++i) {
      const int v = candidates[i].first;
      const bool isNear = candidates[i].second;
      if (!Stage(rep, int(80 + 10 * i / candidates.size()), "Meeting far partners")) return false;
      if (state_.Done()) return true;
      // an earlier meeting may have cancelled or moved it
      if (!state_.IsInteriorIrregular(v) || state_.Frozen(v)) continue;
      if (isNear && !near.Open(opt_)) continue;
      ++(isNear ? rep.nearMeetings : rep.farMeetings);
      if (isNear) ++near.tried;
      state_.BeginTurn(v);
      // a turn without the repeated-failure check (every candidate failed at the shorter travel)
      const bool kept =
          cancel_.CancelAround(rep, v) || (!state_.TurnExhausted() && TravelStrategies(rep, v, far, far, far));
      state_.EndTurn();
      if (kept) {
        ++(isNear ? rep.nearMeetingsKept : rep.farMeetingsKept);
        if (isNear) ++near.kept;
      } else {
        state_.Tried(v);   // a leftover reason of "no route" (or budget), not "untried"
        state_.Failed(v);  // for the next round
      }
    }
    return true;
  }

  /// The partner reach of the far meetings (0: they do not run).
  int FarReach() const {
    return opt_.farMeetingReach > 1 ? int(std::lround(opt_.farMeetingReach * opt_.maxTravel)) : 0;
  }

  /// v's turn: the per-vertex strategies, cheapest first; the first that edits ends it, and
  /// so does the region's bound of refused edits (ReductionState::TurnExhausted; the
  /// strategies check it between attempts). A new strategy is one more line here. True if an
  /// edit was kept.
  bool Turn(ReductionReport& rep, int v, int travel) {
    if (cancel_.CancelAround(rep, v)) return true;
    // What a failed turn read reaches 2 x travel edges from v: the partner of a
    // split-and-absorb lies within travel, and the pairs its walk generates are transported up
    // to travel from the walk. An edit kept within that reach can change the outcome; one
    // farther cannot. (With travel as the radius, the triceratops kept 186 instead of 180;
    // undone edits leave no stamp, ReductionState::Kept.)
    if (travel == 0 || state_.UnchangedSinceFailure(v, 2 * travel) || state_.TurnExhausted()) return false;
    if (TravelStrategies(rep, v, travel, std::max(2, travel), 0)) return true;
    state_.Failed(v);
    return false;
  }

  /// The travel strategies of a turn at v: a 5-7 pair's transport (up to `travel` toward its
  /// targets), then an isolated v5 / v7's split-and-absorb (a partner within `radius`, its
  /// generated pairs transported innerTravel; 0: maxTravel). True if an edit was kept.
  bool TravelStrategies(ReductionReport& rep, int v, int travel, int radius, int innerTravel) {
    if (ed_.Valence(v) == 5 && transport_.Transport(rep, v, travel)) return true;
    if (state_.TurnExhausted()) return false;
    return transport_.Isolated(v) && transport_.SplitAndAbsorb(rep, v, radius, innerTravel);
  }

  /// The vertices of the crease lines of m that stay sharp: its crease lines (the rule of
  /// CreaseLineVertices) but a thin part's rims (thin_creases.h; opt.creaseThinEdges 0: none
  /// dropped). With original, *inputCrease gets the same for the input the guard measures
  /// against (per vertex of its copy), judged against m too, so the two agree even when m is a
  /// remeshing of it; *dropped: the number of m's lines dropped. Once per run (and once more for
  /// the final relaxation).
  static std::vector<char> ProtectedCreases(MeshType& m, const ReductionOptions& o,
                                            const SurfaceProjector* original = nullptr,
                                            std::vector<char>* inputCrease = nullptr, int* dropped = nullptr) {
    std::vector<CreaseLineEdge> lines = CreaseLineEdgesOf(m, o.creaseDeg, o.creaseMinEdges, o.creaseStraightShare);
    std::vector<CreaseLineEdge> inputLines;
    if (original && inputCrease)
      inputLines = CreaseLineEdgesOfSoup(original->Mesh(), o.creaseDeg, o.creaseMinEdges, o.creaseStraightShare);
    int n = 0;
    if (o.creaseThinEdges > 0 && (!lines.empty() || !inputLines.empty())) {
      ThinRimProbe<MeshType> probe(m, o.creaseThinEdges);
      n = DropThinLines(lines, m.vert.size(), probe);
      if (original && inputCrease) DropThinLines(inputLines, original->Mesh().vert.size(), probe);
    }
    if (original && inputCrease) *inputCrease = LineVertices(inputLines, original->Mesh().vert.size());
    if (dropped) *dropped = n;
    return LineVertices(lines, m.vert.size());
  }

  static CompositeOptions Quiet(const std::vector<char>* crease) {
    CompositeOptions o;
    o.relax = true;
    o.crease = crease;
    return o;
  }

  double Elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }

  /// Reports progress; false (and rep.interrupted) if the caller asked to stop.
  bool Stage(ReductionReport& rep, int pct, const char* what) {
    if (opt_.progress && !opt_.progress(std::min(99, pct), what)) {
      rep.interrupted = true;
      return false;
    }
    if (Elapsed() > opt_.timeLimitSeconds) {
      rep.timeLimitReached = true;
      return false;
    }
    return true;
  }

  void Histogram(std::map<int, int>& h, int& irregular) {
    h.clear();
    irregular = 0;
    for (size_t i = 0; i < m_.vert.size(); ++i) {
      if (!ed_.IsLive(int(i)) || ed_.IsBoundary(int(i))) continue;
      const int d = ed_.Valence(int(i));
      ++h[d];
      irregular += d != 6;
    }
  }

  /// Why each irregular vertex left stays (leftover_reasons.h). Runs before compaction, so
  /// the guard's refusals per vertex (ReductionState::UndoneAt) and the protected mask use the
  /// run's indices; the report's vertex indices are then mapped to the compacted mesh's. One
  /// pass, once per run.
  void Explain(ReductionReport& rep) {
    std::vector<int> undone(m_.vert.size(), 0);
    for (auto& kv : state_.UndoneAt())
      if (kv.first >= 0 && size_t(kv.first) < undone.size()) undone[size_t(kv.first)] = kv.second;
    // a region given up for the guard's refusals is "budget" even where the edits it refused
    // were aimed at vertices farther than the reasons' ring (its split-and-absorbs that found
    // no cancellation are not the guard's: those make it "no route")
    for (const GaveUpRegion& g : state_.GaveUpRegions())
      if (g.vertex >= 0 && size_t(g.vertex) < undone.size())
        undone[size_t(g.vertex)] += g.refused - g.byReason[int(Refusal::NoCancellation)];
    LeftoverOptions lo;
    // a partner within the far meetings' reach was tried: "no partner" means none within it
    lo.reach = std::max(opt_.maxTravel, FarReach());
    lo.undone = &undone;
    lo.tried = &state_.TriedUnchanged();
    if (!opt_.frozen.empty()) lo.frozen = &opt_.frozen;
    rep.leftovers = ExplainLeftovers(m_, lo);
    const std::vector<int> rank = CompactionRank();
    auto remap = [&](int& v) { v = v >= 0 && size_t(v) < rank.size() ? rank[size_t(v)] : -1; };
    for (LeftoverVertex& x : rep.leftovers.vertices) remap(x.vertex), remap(x.partner);
    ExplainGaveUp(rep, lo);
    for (GaveUpRegion& g : rep.gaveUp) remap(g.vertex);
  }

  /// The regions given up that still hold an interior irregular vertex (their own: a region
  /// whose vertex an edit nearby cancelled is no longer given up), with the irregular
  /// vertices around and the local thickness; rep.gaveUpVertices counts the distinct interior
  /// irregular vertices in them. O(regions) plus one grid of the mesh for the thickness.
  void ExplainGaveUp(ReductionReport& rep, const LeftoverOptions& lo) {
    rep.gaveUp.clear();
    LeftoverAnalysis<MeshType> thin(m_, lo);
    std::vector<int> irregularIn;
    for (GaveUpRegion g : state_.GaveUpRegions()) {
      if (!state_.IsInteriorIrregular(g.vertex)) continue;
      g.irregularAround = 0;
      for (int x : KRing(m_, {g.vertex}, kRegionRings))
        if (state_.IsInteriorIrregular(x)) ++g.irregularAround, irregularIn.push_back(x);
      const double t = thin.Thickness(g.vertex, ed_.Star(g.vertex));
      if (t < lo.thinEdges) g.thickness = t;
      rep.gaveUp.push_back(g);
    }
    std::sort(irregularIn.begin(), irregularIn.end());
    rep.gaveUpVertices = int(std::unique(irregularIn.begin(), irregularIn.end()) - irregularIn.begin());
  }

  /// Per run-time vertex index, its index after CompactEveryVector (which keeps the order of
  /// the live vertices); -1 for deleted vertices. O(V), once per run.
  std::vector<int> CompactionRank() const {
    std::vector<int> rank(m_.vert.size(), -1);
    int next = 0;
    for (size_t i = 0; i < m_.vert.size(); ++i)
      if (!m_.vert[i].IsD()) rank[i] = next++;
    return rank;
  }

  /// Run-time vertex indices -> indices after CompactEveryVector (which keeps the order of
  /// the live vertices); deleted vertices are dropped.
  std::map<int, int> CompactedIndices(const std::map<int, int>& byIndex) {
    std::map<int, int> out;
    const std::vector<int> rank = CompactionRank();
    for (auto& kv : byIndex)
      if (kv.first >= 0 && size_t(kv.first) < rank.size() && rank[size_t(kv.first)] >= 0)
        out[rank[size_t(kv.first)]] += kv.second;
    return out;
  }

  /// The final relaxation of everything not frozen: global (eq. 5) if asked, kept only if it
  /// does not lower the smallest angle (the global solve equalizes lengths and angles on
  /// average and can squeeze a few triangles next to the remaining irregular vertices), then
  /// local sweeps, kept only if they keep the budget (with Run's margin) and the smallest angle
  /// (above the bound, or as it was). Not journaled: the whole-run undo restores the snapshot.
  /// Returns the final positions' HausdorffPercent when it measured them (the sweeps kept),
  /// -1 otherwise: Run measures only then, as each measurement costs a grid over the mesh.
  double FinalRelax() {
    std::vector<int> all;
    all.reserve(size_t(std::max(0, m_.vn)));
    for (size_t i = 0; i < m_.vert.size(); ++i)
      if (ed_.IsLive(int(i)) && !state_.Frozen(int(i))) all.push_back(int(i));
    // relaxing the vertices of crease lines would round them (issue 14: creases within 0.1%):
    // they stay, the input's and those of the lines now (vertices edits created on them)
    std::vector<char> crease = ProtectedCreases(m_, opt_);
    for (size_t i = 0; i < crease_.size() && i < crease.size(); ++i) crease[i] |= crease_[i];
    if (opt_.finalRelax == RelaxMode::Global) {
      const double before = MeasureShape(m_).minAngleDeg;
      std::vector<CoordType> saved;
      for (int v : all) saved.push_back(ed_.V(v)->P());
      RelaxOptions go;
      go.mode = RelaxMode::Global;
      go.iterations = opt_.globalRelaxRounds;
      irregular::Relax(m_, all, &original_, go, &crease);
      if (MeasureShape(m_).minAngleDeg < before) {
        for (size_t i = 0; i < all.size(); ++i) ed_.V(all[i])->P() = saved[i];
        globalKept_ = false;
      }
    }
    std::vector<CoordType> beforeSweeps;
    beforeSweeps.reserve(all.size());
    for (int v : all) beforeSweeps.push_back(ed_.V(v)->P());
    const double angleBeforeSweeps = MeasureShape(m_).minAngleDeg;
    RelaxOptions lo;
    lo.iterations = opt_.finalLocalSweeps;
    LocalRelax(m_, all, &original_, lo, &crease);
    std::vector<char>().swap(crease);
    ReleaseFreedMemory();  // what the relaxation freed, before the measurement's grid
    for (auto& f : m_.face)
      if (!f.IsD()) f.N() = vcg::TriangleNormal(f).Normalize();
    // The sweeps are not checked vertex by vertex against the Hausdorff budget (sharp creases
    // get rounded a little): measure once and keep the edited positions if they overshoot.
    // Nor are they checked against the angle bound (local relaxation refuses only moves that
    // halve an angle): keep the positions before them if the smallest angle fell under the
    // bound (or under what it was, if it was under the bound already).
    // Where they did either, the vertices around are put back first (SweepUndo, sweep_undo.h):
    // the corners they moved of each triangle they pushed under the bound, and those around
    // each sample of the measure past the margin; the rest of the sweeps stay.
    const double angleFloor = std::min(opt_.minAngleDeg, angleBeforeSweeps) - 1e-9;
    if (opt_.finalLocalSweeps <= 0) return -1;
    // kept only under the margin Run verifies against: sweeps that end between the margin and
    // the budget made Run redo the whole reduction with a stricter guard, when the positions
    // before them were within it (native bench, the peer's armadillo at 20K: sweeps to 0.494%,
    // two retries, 32 s; without the sweeps 0.452% in 10.5 s)
    const double margin = kVerifyMargin * opt_.hausdorffBudgetPercent;
    SweepUndo<MeshType> undo(m_, all, beforeSweeps);
    if (opt_.partialSweepUndo) undo.UnderAngle(opt_.minAngleDeg, kSweepUndoRounds);
    bool angleDropped = MeasureShape(m_).minAngleDeg < angleFloor;
    double measured = angleDropped ? -1 : HausdorffPercent(m_, original_);
    const float bound = float(margin / 100 * double(original_.Diagonal()));
    for (int round = 0; opt_.partialSweepUndo && measured > margin && round < kSweepDistanceRounds; ++round) {
      if (undo.BeyondDistance(original_, bound) == 0) break;  // past the margin, but not the sweeps' doing
      undo.UnderAngle(opt_.minAngleDeg, kSweepUndoRounds);
      angleDropped = MeasureShape(m_).minAngleDeg < angleFloor;
      measured = angleDropped ? -1 : HausdorffPercent(m_, original_);
    }
    sweepsRestored_ = undo.PutBack();
    if (measured >= 0 && measured <= margin) return measured;
    for (size_t i = 0; i < all.size(); ++i) ed_.V(all[i])->P() = beforeSweeps[i];
    for (auto& f : m_.face)
      if (!f.IsD()) f.N() = vcg::TriangleNormal(f).Normalize();
    sweepsKept_ = false;
    sweepsRestored_ = 0;
    return -1;
  }

  MeshType& m_;
  const SurfaceProjector& original_;
  ReductionOptions opt_;
  Editor ed_;
  /// Per vertex of the input's copy (original_.Mesh()), 1 on a crease line the run keeps sharp
  /// (ProtectedCreases): the edit guard's crease samples are those lines'. thinRimLines_: the
  /// mesh's crease lines left unprotected as a thin part's rims (thin_creases.h).
  std::vector<char> inputCrease_;
  int thinRimLines_ = 0;
  /// Per vertex index of the input, 1 on a crease line (opt.creaseDeg, opt.creaseMinEdges; not
  /// a thin part's rim, ProtectedCreases): no relaxation moves these, so creases stay sharp (issue 14). Vertices created later are free
  /// (the guard's crease check undoes an edit that cuts a crease); indices are stable during a
  /// run (nothing is compacted until its end).
  std::vector<char> crease_;
  /// The input's boundary polyline (empty on a closed mesh), along which the boundary stage's
  /// relaxations slide boundary vertices (opt.boundarySlide); the stage reads this one rather
  /// than building its own. O(boundary edges).
  BoundaryCurve inputBoundary_;
  CompositeOperations<MeshType> comp_;
  ReductionState<MeshType> state_;
  EditGuard<MeshType> guard_;
  LocalCancellation<MeshType> cancel_;
  PairTransport<MeshType> transport_;
  bool globalKept_ = true;
  bool sweepsKept_ = true;
  int sweepsRestored_ = 0;  ///< vertices SweepUndo put back (the sweeps kept elsewhere)
  /// SweepUndo's bounds on its rounds, for the angles and for the distance (each of the latter
  /// measures the distance twice; one sufficed on each of the full set's 5 inputs at 20K whose
  /// sweeps overshot the margin); past them every sweep is undone, as before 0.9.25.
  static constexpr int kSweepUndoRounds = 8;
  static constexpr int kSweepDistanceRounds = 2;
  std::chrono::steady_clock::time_point t0_;
};

}  // namespace irregular
}  // namespace vcg_ext
