// filter_irregular: the transport strategies of the automatic reduction (automatic_reduction.h),
// sec. 7.1, 7.2:
//   * Transport: an adjacent 5-7 pair is moved by pair steps toward the nearest other irregular
//     vertices, within a travel bound, then glides straight on, until a removal
//     (local_cancellation.h) applies next to it; a transport that meets nothing to cancel is
//     undone;
//   * SplitAndAbsorb: an isolated v5 / v7 and an isolated vertex of the other type a few edges
//     away (a stretched dislocation) are brought together by moves with 5-7 pair generation,
//     each generated pair transported away to a cancellation, then cancelled as a pair.
// A failed transport is the common case: a topology-only probe (no relaxation, no fold check)
// first finds whether and after how many steps a removal happens, and each step's direction is
// chosen with the dry runs (StepCloser); a route that reaches a removal is relaxed as a whole.
// Every kept edit passes the edit guard.
#pragma once

#include <algorithm>
#include <functional>
#include <vector>

#include "atomic_ops.h"
#include "edit_guard.h"
#include "local_cancellation.h"
#include "reduction_options.h"
#include "reduction_state.h"
#include "stamp_set.h"

namespace vcg_ext {
namespace irregular {

template <class MeshType>
class PairTransport {
 public:
  typedef MeshEditor<MeshType> Editor;
  /// Hops a walk with an accept test may take sideways (WalkToward), at most.
  static constexpr int kMaxSidewaysHops = 2;
  typedef typename MeshType::CoordType CoordType;
  typedef std::function<AtomicOutcome(int, int)> PairStep;

  PairTransport(MeshType& m, const ReductionOptions& opt, Editor& ed, AtomicOperations<MeshType>& ops,
                EditGuard<MeshType>& guard, ReductionState<MeshType>& state, LocalCancellation<MeshType>& cancel)
      : m_(m), opt_(opt), ed_(ed), ops_(ops), guard_(guard), state_(state), cancel_(cancel) {}

  /// Transports a 5-7 pair containing v5 toward the nearest irregular vertices (graph
  /// distance <= travel), one pair step at a time, until a removal applies next to it.
  bool Transport(ReductionReport& rep, int v5, int travel) {
    for (auto* nb : ed_.Star(v5).neighbors) {
      const int w = ed_.Index(nb);
      if (ed_.Valence(w) == 7 && !state_.Frozen(w)) return Transport(rep, v5, w, travel);
    }
    return false;
  }

  /// Transports the adjacent 5-7 pair (v5, v7) to a cancellation: toward the nearest
  /// irregular vertices first, then gliding straight on. True if a removal happened; the
  /// vertices it changed are added to *touchedOut.
  bool Transport(ReductionReport& rep, int v5, int v7, int travel, std::vector<int>* touchedOut = nullptr) {
    refused_.clear();  // the routes of another call started from another mesh
    std::vector<int> targets = NearestIrregular({v5, v7}, travel, opt_.targetsPerPair);
    for (int t : targets) {
      if (state_.TurnExhausted()) return false;
      const CoordType goal = ed_.V(t)->P();
      if (TryMove(rep, v5, v7, [&](int a, int b) { return StepCloser(a, b, goal); }, travel + 2, rep.transports,
                  touchedOut))
        return true;
    }
    // No irregular vertex nearby takes the pair: let it glide straight on (repeating the same
    // pair move parallel-transports it, sec. 6.2) until it meets one that does. This is what
    // empties the walls of 5-7 pairs between differently oriented regular patches.
    for (int dir : {1, 4, 0, 5, 2, 3})
      if (!state_.TurnExhausted() && TryMove(rep, v5, v7, [&](int a, int b) { return ops_.MovePair57(a, b, dir); }, opt_.glideTravel,
                  rep.glides, touchedOut))
        return true;
    return false;
  }

  /// Gives back NearestIrregular's per-vertex scratch (a later call grows it again).
  void ReleaseScratch() { seen_.Release(); }

  bool Isolated(int v) {
    for (auto* nb : ed_.Star(v).neighbors)
      if (ed_.Valence(ed_.Index(nb)) != 6) return false;
    return true;
  }

  /// An isolated v5 / v7 and an isolated vertex w of the other type a few edges away form a
  /// stretched dislocation that no single pair move can carry. v steps toward w with 5-7
  /// pair generation (sec. 6.2), and each generated pair is transported away until it cancels
  /// elsewhere (sec. 7.2); once v is next to w the two form an adjacent 5-7 pair, which is
  /// transported to a cancellation in turn. Kept if that last cancellation happens (net: two
  /// irregular vertices fewer), or, with opt.partialAbsorption, if the steps taken already
  /// lowered the count; otherwise undone. innerTravel: how far the generated pairs and the
  /// closing pair are transported (0: opt.maxTravel; the far meetings of automatic_reduction.h
  /// pass a longer one, as the partner they walk to lies beyond the travel).
  bool SplitAndAbsorb(ReductionReport& rep, int v, int radius, int innerTravel = 0) {
    if (innerTravel <= 0) innerTravel = opt_.maxTravel;
    const int dv = ed_.Valence(v);
    std::vector<int> near = NearestIrregular({v}, radius, 1, dv == 5 ? 7 : 5);
    if (near.empty()) return false;
    const int w = near[0];
    const ReductionReport saved = rep;
    GuardedEdit<MeshType> g(guard_, rep, {v, w});
    std::vector<int> touched{v, w};
    // What no inner guard judged: the moves with pair generation and their relaxation. Each
    // transport inside judged, on kept, the 2-ring of what it touched, which holds every vertex
    // its steps and relaxations moved; a face changed later is changed by a later edit, judged
    // in turn. So the closing check needs only these (it was a second pass over everything, a
    // tenth of the reduction's time on the bunny).
    std::vector<int> unjudged{v, w};
    WalkRules rules;
    rules.arrived = [&](int c, int target) { return ed_.Adjacent(c, target); };
    const int cur = WalkToward(rep, v, w, radius, innerTravel, touched, unjudged, rules);
    if (!state_.TurnExhausted() && ed_.IsLive(cur) && ed_.IsLive(w) && ed_.Adjacent(cur, w) &&
        ed_.Valence(cur) + ed_.Valence(w) == 12) {
      const int a5 = ed_.Valence(cur) == 5 ? cur : w, a7 = a5 == cur ? w : cur;
      if (Transport(rep, a5, a7, innerTravel, &touched) && g.Judge(unjudged)) {
        g.Keep(touched);
        ++rep.splitAbsorptions;
        return true;
      }
    }
    // The walk stopped short of w (or the last pair found no cancellation), but the pairs it
    // generated on the way met more irregular vertices than they made: what it did is a
    // reduction by itself, and v stands closer to w for a later turn.
    if (opt_.partialAbsorption && cur != v && !state_.TurnExhausted() && state_.CountChange(touched) < 0 &&
        g.Judge(unjudged)) {
      g.Keep(touched);
      ++rep.partialAbsorptions;
      return true;
    }
    rep.RestoreKeepingRefusals(saved);
    // an attempt that edited and is undone whole counts against the region's bound (unless the
    // bound is what stopped it: then the refusal that reached it was counted already)
    if (touched.size() > 2 && !state_.TurnExhausted()) state_.Refused(Refusal::NoCancellation);
    g.Undo();
    return false;
  }

  /// One hop of a walk: cur moves to a neighbour (direction k, as MoveWithPairGeneration) by a
  /// move with 5-7 pair generation (sec. 6.2), relaxed around. False (nothing changed) where
  /// the move is not possible or would cut a crease. What it changed is appended to `touched`
  /// and `unjudged`; gen gets the outcome (irregular: the moved vertex, then the pair).
  bool Hop(int cur, int k, std::vector<int>& touched, std::vector<int>& unjudged, AtomicOutcome& gen) {
    auto cp = ed_.Mark();
    const size_t mark = touched.size();
    gen = ops_.MoveWithPairGeneration(cur, k);
    if (!gen) return false;
    const std::vector<int> changed = state_.Record(gen, touched);
    bool cuts = false;
    {
      const typename EditGuard<MeshType>::SameTopology sameTopology(guard_);  // one gathering for both
      cuts = guard_.CutsCrease(changed);
      if (!cuts) guard_.RelaxAround(changed);
    }
    if (cuts) {
      touched.resize(mark);
      ed_.RollbackTo(cp);
      return false;
    }
    unjudged.insert(unjudged.end(), changed.begin(), changed.end());
    return true;
  }

  /// The directions (k, as Hop) in which cur's hop lands at `distance` from the vertex of the
  /// last Distances call, in increasing k; `avoid` excluded.
  std::vector<int> HopsTo(int cur, int distance, int avoid = -1) {
    std::vector<int> ks;
    const int d = ed_.Valence(cur);
    for (int k = 0; k < d; ++k) {
      const int to = ops_.NeighbourFrom(cur, -1, d == 5 ? k : k + 1);
      if (to >= 0 && to != avoid && DistanceTo(to) == distance) ks.push_back(k);
    }
    return ks;
  }

  /// How a walk ends and what it may do (WalkToward).
  struct WalkRules {
    std::function<bool(int, int)> arrived;  ///< (where v is, where w is): stop there
    std::function<bool(int, int)> accept;   ///< a hop is kept only where this holds (null: any);
                                            ///< with it, up to kMaxSidewaysHops hops may keep the distance
  };

  /// v walks toward w (sec. 6.2, 7.2): each hop moves v to a neighbour closer to w (graph
  /// distance, within radius + 1) by a move with 5-7 pair generation (Hop), and transports the
  /// generated pair away (innerTravel) until it cancels against neither v nor w; a hop whose
  /// pair finds no cancellation is rolled back and the next direction tried.
  /// Stops when
  /// rules.arrived holds, after radius + 1 hops, when no direction is kept, or when the turn's
  /// effort is spent. Returns where v ended (its index after the moves). What the hops changed is appended to `touched`; what no inner guard judged
  /// (the moves and their relaxation) to `unjudged`. No guard of its own: the caller's
  /// GuardedEdit keeps or undoes the walk as a whole.
  int WalkToward(ReductionReport& rep, int v, int w, int radius, int innerTravel, std::vector<int>& touched,
                 std::vector<int>& unjudged, const WalkRules& rules) {
    int cur = v, last = -1, sideways = 0;
    for (int hop = 0; hop <= radius && !rules.arrived(cur, w) && !state_.TurnExhausted(); ++hop) {
      // the BFS from w stops at cur's layer: only the neighbours closer than cur matter
      Distances(w, radius + 1, cur);
      const int here = DistanceTo(cur) >= 0 ? DistanceTo(cur) : radius + 2;
      // with an accept test, a hop that stays as far from w may follow when no closer one is
      // accepted (a gathering two or three edges from its partner, on the wrong side of it)
      std::vector<int> closer = HopsTo(cur, here - 1), aside;
      if (rules.accept && sideways < kMaxSidewaysHops) aside = HopsTo(cur, here, last);
      const size_t nCloser = closer.size();
      closer.insert(closer.end(), aside.begin(), aside.end());
      int next = -1;
      for (size_t i = 0; i < closer.size() && next < 0 && !state_.TurnExhausted(); ++i) {
        const int k = closer[i];
        auto cp = ed_.Mark();
        const size_t mark = touched.size(), unjudgedMark = unjudged.size();
        AtomicOutcome gen;
        if (!Hop(cur, k, touched, unjudged, gen)) continue;
        const int moved = gen.irregular[0];
        int p5 = gen.irregular[1], p7 = gen.irregular[2];
        if (ed_.Valence(p5) != 5) std::swap(p5, p7);
        ReductionReport beforeTransport;  // only a walk with an accept test may give a kept hop back
        if (rules.accept) beforeTransport = rep;
        // a removal of the generated pair against the moved vertex would only undo the step
        cancel_.exclude = {moved, w};
        bool away = Transport(rep, p5, p7, innerTravel, &touched);
        cancel_.exclude.clear();
        if (away && rules.accept && !rules.accept(moved, w)) {
          // where the hop led is no place for the caller (a gathering's overshoot): as if the
          // hop had not been tried, but for the refusals counted on the way
          rep.RestoreKeepingRefusals(beforeTransport);
          away = false;
        }
        if (away) {
          next = moved;
          if (i >= nCloser) ++sideways;
        } else {
          touched.resize(mark);
          unjudged.resize(unjudgedMark);
          ed_.RollbackTo(cp);
        }
      }
      if (next < 0) break;
      last = cur;
      cur = next;
    }
    return cur;
  }

  /// The pair step (one of the six of sec. 6.2) after which the pair's midpoint is closest to
  /// `goal`, if it gets closer; refused steps (blocked, folds, frozen) are skipped; ties go
  /// to the lowest direction. The dry runs (PredictMovePair57) rule out blocked and frozen
  /// steps and bound each step's distance from below without editing: a flip moves no
  /// vertex, a collapse leaves its survivor at one of three known places (graph_ops.h
  /// Collapse); only a split's new positions need the step applied. A step is applied (and
  /// rolled back) only if its bound can still beat the best so far, so the choice is the
  /// one trying all six would make, at usually two or three applications instead of seven (the
  /// last trial, when it is the choice, is kept rather than undone and applied again).
  AtomicOutcome StepCloser(int v5, int v7, CoordType goal) {
    auto mid = [&](int a, int b) { return (ed_.V(a)->P() + ed_.V(b)->P()) / 2; };
    auto dist = [&](const CoordType& p) { return double((p - goal).Norm()); };
    double best = dist(mid(v5, v7));
    int bestDir = -1;
    struct Bound {
      double d;
      int dir;
      bool operator<(const Bound& o) const { return d < o.d || (d == o.d && dir < o.dir); }
    };
    Bound bounds[6];  // at most one per direction: no heap allocation per step
    size_t count = 0;
    AtomicPrediction all[6];
    ops_.PredictMovePair57All(v5, v7, all);
    for (int dir = 0; dir < 6; ++dir) {
      const AtomicPrediction& pr = all[dir];
      bool ok = bool(pr);
      for (auto& kv : pr.changes) ok = ok && !state_.Frozen(kv.first);
      if (!ok) continue;
      // A lower bound on the distance after the step, exact where the editor can say where
      // the step puts the pair: then only the best direction is applied (0.9.19; before, every
      // split was applied and rolled back to measure it, a third of this function's time).
      double lb = 0;
      const bool oneStep = pr.steps.size() == 1;
      if (oneStep && pr.steps[0].kind == GraphStep::kFlip) {
        lb = dist(mid(pr.pair5, pr.pair7));
      } else if (oneStep && pr.steps[0].kind == GraphStep::kCollapse) {
        // collapse x into the survivor (pair7): it ends at the midpoint, or (with the fold check
        // on, if the midpoint folds) at its own or x's place
        const CoordType px = ed_.V(pr.steps[0].x)->P(), ps = ed_.V(pr.steps[0].y)->P(), p5 = ed_.V(pr.pair5)->P();
        lb = ed_.geometry().checkFolds ? std::min({dist((p5 + (px + ps) / 2) / 2), dist((p5 + ps) / 2), dist((p5 + px) / 2)})
                                       : dist((p5 + (px + ps) / 2) / 2);
      } else if (oneStep && pr.steps[0].kind == GraphStep::kSplit && pr.steps[0].x == pr.pair5) {
        // split pair5 (the old v7): it moves to its place, the new vertex is not in the pair
        CoordType pw, pnew;
        if (ed_.PredictSplitPlaces(pr.steps[0].x, pr.steps[0].y, pr.steps[0].z, pw, pnew))
          lb = dist((pw + ed_.V(pr.pair7)->P()) / 2);
      }
      // a margin for rounding: the bound must never exceed the distance after the real step
      bounds[count++] = {lb * (1 - 1e-9) - 1e-12, dir};
    }
    std::sort(bounds, bounds + count);
    // past the best so far, a bound that cannot beat it ends the trials
    auto hopeless = [&](const Bound& b) { return b.d > best || (bestDir >= 0 && b.d == best && b.dir > bestDir); };
    for (size_t i = 0; i < count && !hopeless(bounds[i]); ++i) {
      const Bound& b = bounds[i];
      auto cp = ed_.Mark();
      AtomicOutcome o = ops_.MovePair57(v5, v7, b.dir);
      if (o) {
        const double d = dist(mid(o.irregular[0], o.irregular[1]));
        if (d < best || (d == best && bestDir >= 0 && b.dir < bestDir)) {
          best = d, bestDir = b.dir;
          // the best and the last trial: kept as it is instead of undone and applied again
          if (i + 1 == count || hopeless(bounds[i + 1])) return o;
        }
      }
      ed_.RollbackTo(cp);
    }
    if (bestDir < 0) return AtomicOutcome();
    return ops_.MovePair57(v5, v7, bestDir);
  }

  /// Irregular vertices (not in `from`) within `radius` edges of `from`, nearest first (a
  /// breadth-first search, each vertex's neighbours by index). Layer by layer over reused
  /// buffers, with a stamp set for "seen": no allocation per call but the result.
  std::vector<int> NearestIrregular(const std::vector<int>& from, int radius, int count, int valence = 0) {
    std::vector<int> found;
    seen_.Begin(m_.vert.size());
    layer_.assign(from.begin(), from.end());
    for (int v : from) seen_.Insert(size_t(v));
    for (int r = 0; r < radius && !layer_.empty() && int(found.size()) < count; ++r) {
      nextLayer_.clear();
      for (size_t i = 0; i < layer_.size() && int(found.size()) < count; ++i) {
        VertexStar<MeshType> s = ed_.Star(layer_[i]);
        ring_.clear();
        for (auto* nb : s.neighbors) ring_.push_back(ed_.Index(nb));
        std::sort(ring_.begin(), ring_.end());  // deterministic order
        for (int w : ring_) {
          if (!seen_.Insert(size_t(w))) continue;
          nextLayer_.push_back(w);
          if (state_.IsInteriorIrregular(w) && !state_.Frozen(w) && (valence == 0 || ed_.Valence(w) == valence) &&
              int(found.size()) < count)
            found.push_back(w);
        }
      }
      layer_.swap(nextLayer_);
    }
    return found;
  }

 private:
  /// Moves the pair with `step` until a removal applies next to it, and keeps the result if
  /// it is good enough (the guard). A failed transport is the common case, so a topology-only
  /// probe (no relaxation, no fold check) first finds whether and after how many steps a
  /// removal happens. A route that reaches one is relaxed as a whole and kept if no triangle
  /// turned over and the guard passes it, after one more relaxation if needed (on bunny00,
  /// 3965 of 4367 routes); otherwise it is undone, and the guard's refusal counts against the
  /// region. Skipping that second relaxation where it rarely pays (a route refused for its
  /// distance: saved 4 times in 1980 on fandisk; for its angles, beyond the repair slack: 11
  /// times in 4300) made fandisk 11% and the bull 8% faster but bunny00 15% slower, with 60
  /// left instead of 58 (0.9.7, tried and dropped: bunny's 1.5x is met only without the
  /// skip). A route that turned a triangle over counts too (Refusal::Fold, 0.9.5): on thin
  /// parts most undone routes fold, and without counting them a region there was never given
  /// up for them (the man: 16% less CPU time with them counted, 2045 left instead of 2041; the
  /// quick set's counts and the femur's the same). Redoing a refused route step by step, with a
  /// relaxation and the fold check after every step, rescued 41 of 402 on bunny00 at a tenth
  /// of the whole reduction's time, and left about as many irregular vertices in the end
  /// (bunny00 / knot1 / mushroom / elephant: 68 / 52 / 61 / 127 with it, 0.9.3; 72 / 54 / 59 / 128
  /// without, 0.9.4, with the region bound raised from 12 to 20 to match).
  bool TryMove(ReductionReport& rep, int v5, int v7, const PairStep& step, int maxSteps, int& successes,
               std::vector<int>* touchedOut) {
    GuardedEdit<MeshType> g(guard_, rep, {v5, v7});
    std::vector<int> touched{v5, v7};
    int reach = -1;
    {
      const bool folds = ed_.geometry().checkFolds;
      ed_.geometry().checkFolds = false;
      reach = MoveUntilRemoval(v5, v7, step, maxSteps, touched);
      ed_.geometry().checkFolds = folds;
    }
    if (reach < 0) {
      g.Undo();
      return false;
    }
    // Every try of one Transport call starts from the same mesh (each refused one is undone),
    // and the rest of a try depends only on that mesh and the probe's result: a probe that
    // ends where a refused one of the same call ended is refused the same way. Many do: the
    // goals of nearby targets and the glide directions often lead to the same first removal
    // (a third of the angle repairs on the bull, 0.9.14). Refused again without the
    // relaxation and the guard, with the same bookkeeping, so the run stays the same to the bit.
    std::vector<double> probe;
    if (opt_.refusedRouteMemo) {
      probe = ProbeResult(touched, reach);
      for (const RefusedRoute& r : refused_)
        if (r.probe == probe) {
          RefuseAgain(g, rep, r.how);
          ++rep.routesRefusedAgain;
          return false;
        }
    }
    auto refuse = [&](int how) {
      RefuseAgain(g, rep, how);
      if (opt_.refusedRouteMemo) refused_.push_back({std::move(probe), how});
      return false;
    };
    GuardVerdict verdict = GuardVerdict::Kept;
    bool repaired = false;
    int refusal = 0;  // kCutsCrease, kFolds, a GuardVerdict, or 0 (kept)
    {
      // from here to the verdict only positions change: the route's 2-ring is gathered once
      const typename EditGuard<MeshType>::SameTopology sameTopology(guard_);
      if (guard_.CutsCrease(touched)) {
        refusal = kCutsCrease;
      } else {
        // The probe's route, relaxed as a whole: usually as good as the same route relaxed
        // step by step, at a fraction of the cost (the steps' 2-rings overlap).
        guard_.RelaxAround(touched);
        if (guard_.FoldsAround(touched)) {
          refusal = kFolds;
        } else {
          // by the angle bound alone first, then the angle repair; the angle allowance
          // (edit_guard.h) only for what the repair could not lift
          verdict = g.Verdict(touched, false);
          if (verdict != GuardVerdict::Kept) {
            guard_.RelaxAround(touched);
            verdict = g.Verdict(touched, false);
          }
          if (verdict == GuardVerdict::Angle) repaired = (verdict = RepairAngles(g, touched)) == GuardVerdict::Kept;
          if (verdict == GuardVerdict::Angle) verdict = g.VerdictWithinAllowance(touched);
          if (verdict != GuardVerdict::Kept) refusal = int(verdict);
        }
      }
    }
    if (refusal != 0) return refuse(refusal);
    rep.angleRepairs += repaired;
    g.Keep(touched);
    if (touchedOut) touchedOut->insert(touchedOut->end(), touched.begin(), touched.end());
    ++successes;
    rep.pairSteps += reach;
    return true;
  }

  /// How TryMove refused a route: a GuardVerdict other than Kept, or one of these.
  static constexpr int kCutsCrease = -1, kFolds = -2;
  struct RefusedRoute {
    std::vector<double> probe;  ///< ProbeResult of its probe
    int how;                    ///< the refusal (above)
  };
  /// What a probe did, to compare with another from the same mesh: its steps, the vertices it
  /// changed in order, and their valences and places after it (a deleted one: -1).
  std::vector<double> ProbeResult(const std::vector<int>& touched, int reach) {
    std::vector<double> r;
    r.reserve(1 + 5 * touched.size());
    r.push_back(reach);
    for (int t : touched) {
      r.push_back(t);
      if (!ed_.IsLive(t)) {
        r.push_back(-1);
        continue;
      }
      r.push_back(ed_.Valence(t));
      for (int k = 0; k < 3; ++k) r.push_back(double(ed_.V(t)->P()[k]));
    }
    return r;
  }
  /// Undoes the try and records its refusal as TryMove records it: the report's counts, the
  /// subjects' undone count and the region's effort bound.
  void RefuseAgain(GuardedEdit<MeshType>& g, ReductionReport& rep, int how) {
    ++rep.undone;
    if (how == kFolds) {
      g.Undo();
      state_.Refused(Refusal::Fold);
    } else {
      // a crease cut is refused as a Hausdorff one (as LocalCancellation::CancelAround does)
      g.Refuse(how == kCutsCrease ? GuardVerdict::Hausdorff : GuardVerdict(how));
    }
  }

  /// A route refused for triangles under the minimum angle: a long route relaxed as a whole
  /// often leaves a few just under it, where one more relaxation around them (their 2-ring)
  /// lifts them. Up to opt.angleRepairRounds rounds, each only while the smallest angle is at
  /// most opt.angleRepairSlackDeg under the minimum. The relaxed vertices join `touched` (the
  /// guard judges their rings, and a kept edit stamps them). A repaired route must clear the
  /// minimum angle itself, not the guard's "no worse than before" (its angle before was
  /// measured at the pair's start, not where the repair reaches); crease faces keep their
  /// slack. The rounds also stop once two in a row have not raised the smallest angle: a
  /// repair that works lifts it round after round, one that does not often lowers it (the
  /// relaxation pulls one corner open by closing another). Of fandisk's 1388 repairs, 103
  /// succeeded; the stop saves 37% of their rounds and would have lost one of the 103 (the
  /// bull: 14% of 6926 rounds, one of 294; 0.9.14, traced without the refused-route memo).
  /// Stopping at the first round that does not raise it saved half the rounds but lost 13 of
  /// the 103, and left fandisk 186 irregular vertices instead of 175.
  /// Returns the last verdict (Angle if no round was tried).
  GuardVerdict RepairAngles(GuardedEdit<MeshType>& g, std::vector<int>& touched) {
    return g.RepairAngles(touched, opt_.angleRepairRounds, opt_.minAngleDeg, opt_.angleRepairSlackDeg, true);
  }

  /// Steps the pair (a, b) with `step` until a removal (sec. 6.2) applies next to it; when no
  /// step is possible, one more step in any direction may set the removal up. Topology only:
  /// nothing is relaxed (TryMove relaxes the route). Returns the number of pair steps taken,
  /// or -1 if no removal happened (the caller undoes).
  int MoveUntilRemoval(int a, int b, const PairStep& step, int maxSteps, std::vector<int>& touched) {
    for (int s = 0; s < maxSteps; ++s) {
      auto cp = ed_.Mark();
      AtomicOutcome o = step(a, b);
      bool ok = bool(o);
      for (auto& kv : o.changes) ok = ok && !state_.Frozen(kv.first);
      if (!ok) {
        ed_.RollbackTo(cp);
        return StepAndCancel(a, b, touched) ? s + 1 : -1;
      }
      a = o.irregular[0];
      b = o.irregular[1];
      state_.Record(o, touched);
      if (cancel_.RemovalAt({a, b}, touched)) return s + 1;
    }
    return -1;
  }

  /// One pair step, in the first of the six directions after which a removal applies. A step
  /// its dry run refuses (blocked, or touching a frozen vertex) is not tried.
  bool StepAndCancel(int v5, int v7, std::vector<int>& touched) {
    AtomicPrediction all[6];
    ops_.PredictMovePair57All(v5, v7, all);
    for (int dir = 0; dir < 6; ++dir) {
      const AtomicPrediction& pr = all[dir];
      bool ok = bool(pr);
      for (auto& kv : pr.changes) ok = ok && !state_.Frozen(kv.first);
      if (!ok) continue;
      auto cp = ed_.Mark();
      const size_t mark = touched.size();
      AtomicOutcome o = ops_.Apply(pr);
      if (o) {
        state_.Record(o, touched);
        if (cancel_.RemovalAt({o.irregular[0], o.irregular[1]}, touched)) return true;
      }
      touched.resize(mark);
      ed_.RollbackTo(cp);
    }
    return false;
  }

 public:
  /// Graph distances from v, up to radius, read with DistanceTo until the next call; with
  /// stopAt >= 0, only up to stopAt's layer (every vertex closer to v than stopAt is in, and
  /// stopAt itself). A stamp per vertex instead of a hash map (0.9.19: its inserts were 1.6% of
  /// the reduction's instructions on bunny00); vertices created later are not in.
  void Distances(int v, int radius, int stopAt = -1) {
    distSeen_.Begin(m_.vert.size());
    if (distOf_.size() < m_.vert.size()) distOf_.resize(m_.vert.size());
    auto reach = [&](int y, int r) {
      if (!distSeen_.Insert(size_t(y))) return false;
      distOf_[size_t(y)] = r;
      return true;
    };
    reach(v, 0);
    distLayer_.assign(1, v);
    for (int r = 1; r <= radius && !(stopAt >= 0 && DistanceTo(stopAt) >= 0); ++r) {
      distNext_.clear();
      for (int x : distLayer_)
        for (auto* nb : ed_.Star(x).neighbors) {
          const int y = ed_.Index(nb);
          if (reach(y, r)) distNext_.push_back(y);
        }
      distLayer_.swap(distNext_);
    }
  }
 public:
  /// The last Distances call's distance to x; -1 if x was not reached.
  int DistanceTo(int x) const {
    return x >= 0 && size_t(x) < distOf_.size() && distSeen_.Contains(size_t(x)) ? distOf_[size_t(x)] : -1;
  }

 private:
  MeshType& m_;
  const ReductionOptions& opt_;
  Editor& ed_;
  AtomicOperations<MeshType>& ops_;
  EditGuard<MeshType>& guard_;
  ReductionState<MeshType>& state_;
  LocalCancellation<MeshType>& cancel_;
  StampSet seen_;                          ///< NearestIrregular's visited vertices
  std::vector<int> layer_, nextLayer_, ring_;  ///< ... and its buffers
  std::vector<RefusedRoute> refused_;      ///< the routes the current Transport call refused (TryMove)
  StampSet distSeen_;                      ///< Distances: the vertices reached
  std::vector<int> distOf_;                ///< ... their distances (valid where reached)
  std::vector<int> distLayer_, distNext_;  ///< ... and its layers
};

}  // namespace irregular
}  // namespace vcg_ext
