// filter_irregular: the leftover aggregation of the automatic reduction (automatic_reduction.h),
// an opt-in stage after the sweeps and meetings (ReductionOptions::aggregateLeftovers).
//
// Why: what the sweeps leave is mostly what the surface's curvature needs (caps and saddles,
// leftover_reasons.h) or what a thin part keeps. That curvature must stay, but it can sit in
// fewer vertices: type aggregation (sec. 6.3, type_change.h) merges two v5 into one v4 and two
// v7 into one v8, the same total of 6 - valence (eq. 2) in one vertex instead of two. The
// paper's results keep v5 and v7 only (sec. 3: "the most fundamental"), and so does the
// reduction by default; a user who wants the fewest irregular vertices, whatever their
// valence, asks for this stage. Counted on the default run's results from the peer's outputs
// at 20K (0.9.28): pairs in an aggregation's configuration are few (bunny00, knot1: none; the
// elephant 4 v5 pairs and 2 v7 pairs among 100 leftovers; the man 116 v5 pairs and 87 v7 pairs,
// at most 84 and 65 of them disjoint, among 1001 leftovers), and on the man the guard refuses
// most merges for an angle.
//
// The configurations (type_change.h): two v5 two edges apart on a regular common neighbour t,
// one vertex between them on t's ring (t splits into the v4); two v7 facing each other across
// an edge (x, y) of two regular vertices (the edge collapses into the v8). Adjacent v5 cannot
// become a v4 (sec. 3) and are not tried.
//
// Gathering (0.9.31, ReductionOptions::gatherRadius): most leftovers have a partner of their
// type a few edges away, not in a configuration (the elephant at 20K: of 83 v5 and v7 left,
// the nearest of the same type 3 or 4 edges away for 22, within 12 for most). Such a leftover
// walks toward a partner (PairTransport::WalkToward: each hop a move with 5-7 pair generation,
// sec. 6.2, the pair carried off to a cancellation, sec. 7.2), landing two edges from it only in
// the configuration, and the two merge. The elephant: 90 left with aggregation alone, 60 with
// gathering (radius 16; native bench, 0.9.31).
//
// An aggregation is kept only if it passes the edit guard (edit_guard.h: Hausdorff, crease,
// angle, protected selection, after local relaxation of its 2-ring and a few more relaxations
// around the corners left under the minimum angle) and turns no triangle over (where its region
// had none turned over before: slivers on thin parts, as in angle_flip.h).
//
// Preconditions: as EditGuard (the guard's mesh with FF/VF adjacency, journaled editor, inside
// the reduction's snapshot, the running count started). Postconditions: every kept aggregation
// lowered the interior irregular count by one and passed the above; a refused one is rolled back
// exactly; a kept gathering lowered it by one in all (its walk's pairs all cancelled). Cost: one
// scan of the vertices, then O(1) per irregular vertex (a dry run and at most one guarded edit
// per candidate pair); a gathering pass scans again (at most kGatherRounds), and each walk costs
// O(radius) hops, each a transport of at most the travel, bounded per region by the refusals
// (ReductionState::TurnExhausted) and in all by the walks' bound of effort (GatherOpen).
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "edit_guard.h"
#include "pair_transport.h"
#include "reduction_options.h"
#include "type_change.h"

namespace vcg_ext {
namespace irregular {

/// Rounds of relaxation around the sharp corners an aggregation leaves under the minimum angle
/// (at most; AggregateLeftovers stops them earlier as a transport's repair stops). The man at 20K
/// (native bench, 0.9.28): 86 of 298 pairs kept with none, 91 of 305 with 3, 103 of 281 with 8
/// and 105 of 281 with 16 rounds that never stop early, most refused ones 3-8 degrees short;
/// with the early stops 94 of 313 at 8 rounds, for half the stage's instructions (callgrind:
/// 1.08 G against 2.35 G, of a 30.05 G run without the stage).
constexpr int kAggregationRepairRounds = 8;

/// Passes of gathering over the leftovers, at most (AggregateLeftovers; a pass that gathers
/// nothing ends them).
constexpr int kGatherRounds = 3;
/// Partners a gathering tries per leftover, nearest first (Gather).
constexpr int kGatherPartners = 3;

/// How the aggregation went: v4s and v8s made (kept), candidate pairs tried under the guard.
struct AggregationReport {
  int v4 = 0, v8 = 0, tried = 0;
  int gathered = 0, gathersTried = 0;  ///< of v4 + v8, those made by a gathering; gatherings tried
  bool gatherBoundReached = false;     ///< the gathering stopped at its bound of effort (GatherOpen)
  int Kept() const { return v4 + v8; }
};

/// May one more gathering walk be tried? While walks pay their way: fewer tried than
/// o.gatherTries plus o.gatherTriesPerGathered per kept one (the near meetings' rule,
/// automatic_reduction.h), counted over all rounds. Why: a walk that fails mostly fails after
/// some hops, each a transport of its generated pair, all undone; and the share of walks that
/// get there differs by model: at 20K (native bench, 0.9.32) the elephant kept 30 of 55, the
/// bull 32 of 177, the femur 31 of 503 and the man 28 of 807, and the failed ones were most of
/// the stage's time (the femur: 2.1 of its 2.5 s). Deterministic: attempts are counted, not
/// time. A closed bound is recorded in r (gatherBoundReached), for the report.
inline bool GatherOpen(const ReductionOptions& o, AggregationReport& r) {
  const bool open = o.gatherTries <= 0 || r.gathersTried < o.gatherTries + o.gatherTriesPerGathered * r.gathered;
  r.gatherBoundReached = r.gatherBoundReached || !open;
  return open;
}

/// The partners an interior v5 or v7 `a` can aggregate with (type_change.h's configurations),
/// as (partner, aggregate vertex): for two v5 the common neighbour t that would become the v4
/// (two v5 on either side of a lattice step of two edges that is not straight have two such
/// t), for two v7 -1 (either end of the edge between them). Sorted. Reads the mesh only.
/// Partners are free (not protected), interior and of a's valence; the vertices between them
/// are regular, interior and free.
template <class MeshType>
std::vector<std::pair<int, int>> AggregationPartners(MeshEditor<MeshType>& ed, const ReductionState<MeshType>& state,
                                                     int a) {
  std::vector<std::pair<int, int>> out;
  auto free = [&](int v, int valence) {
    return ed.IsLive(v) && !state.Frozen(v) && !ed.IsBoundary(v) && ed.Valence(v) == valence;
  };
  const VertexStar<MeshType> s = ed.Star(a);
  const int d = s.Valence();
  if (s.boundary || (d != 5 && d != 7)) return out;
  for (int k = 0; k < d; ++k) {
    const int t = ed.Index(s.neighbors[size_t(k)]);
    if (!free(t, 6)) continue;
    if (d == 5) {
      // t's ring, a and the partner one vertex apart on it: (i +- 2) mod 6
      const VertexStar<MeshType> st = ed.Star(t);
      const int i = st.IndexOf(ed.V(a));
      if (i < 0) continue;
      for (int step : {2, 4}) {
        const int b = ed.Index(st.neighbors[size_t((i + step) % 6)]);
        if (b != a && free(b, 5) && !ed.Adjacent(a, b)) out.push_back({b, t});
      }
    } else {
      // the edge (t, next) of a's star; the vertex across it from a
      const int x = ed.Index(s.neighbors[size_t((k + 1) % d)]);
      int o[2];
      if (!free(x, 6) || !ed.Opposites(t, x, o)) continue;
      const int b = o[0] == a ? o[1] : o[1] == a ? o[0] : -1;
      if (b >= 0 && b != a && free(b, 7)) out.push_back({b, -1});
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

/// One aggregation of a with one of its partners (AggregationPartners: (b, aggregate vertex))
/// under its own guarded edit, nested in a gathering's when there is one. Kept if the guard
/// passes it (after its angle repair, then the allowance), it turns no triangle over where
/// none was, and it lowers the count; otherwise rolled back. *touchedOut gets what it touched
/// (kept only). Counts the try in out.tried; with `count` (not nested) the aggregate in out.v4 /
/// out.v8, after checking that the count went down (a gathering checks and counts its whole).
template <class MeshType>
bool TryAggregation(MeshType& m, EditGuard<MeshType>& guard, TypeChange<MeshType>& tc, ReductionReport& rep, int a,
                    const std::pair<int, int>& partner, AggregationReport& out, bool count,
                    std::vector<int>* touchedOut = nullptr) {
  MeshEditor<MeshType>& ed = guard.ed();
  ReductionState<MeshType>& state = guard.state();
  const int b = partner.first;
  const int valence = ed.Valence(a);
  AggregationRequest req;
  req.group = {a, b};
  req.at = partner.second;
  if (!tc.PredictAggregation(req)) return false;
  const std::vector<int> around = KRing(m, {a, b}, 1);
  // a region that already had a turned-over triangle (slivers on thin parts, as in
  // angle_flip.h) is judged by the rest: refused only for turning one over itself
  const bool foldedBefore = guard.FoldsAround(around);
  ++out.tried;
  const std::vector<int> none;  // no subject: a refusal is no leftover's reason
  GuardedEdit<MeshType> g(guard, rep, around, &none);
  const TypeChangeOutcome o = tc.Aggregate(req);
  if (!o) {
    g.Undo();
    return false;
  }
  std::vector<int> touched;
  for (const auto& kv : o.valences) touched.push_back(kv.first);
  touched.insert(touched.end(), o.created.begin(), o.created.end());
  guard.RelaxAround(touched);
  GuardVerdict verdict = g.Verdict(touched, false);
  // a triangle left under the minimum angle: relax around the sharp corners again, as a
  // transport's route is (GuardedEdit::RepairAngles), judged against the guard's own bound;
  // the angle allowance (edit_guard.h) only for what the repair could not lift
  if (verdict == GuardVerdict::Angle)
    verdict = g.RepairAngles(touched, kAggregationRepairRounds, std::min(guard.options().minAngleDeg, g.AngleBefore()),
                             guard.options().angleRepairSlackDeg, false);
  if (verdict == GuardVerdict::Angle) verdict = g.VerdictWithinAllowance(touched);
  // nested (a gathering's, !count): the running count is that of before the walk, so the
  // aggregation's own change cannot be read here; the gathering checks the whole
  if ((foldedBefore || !guard.FoldsAround(touched)) && (!count || state.CountChange(touched) < 0) &&
      verdict == GuardVerdict::Kept) {
    g.Keep(touched);
    if (count) ++(valence == 5 ? out.v4 : out.v8);
    if (touchedOut) *touchedOut = touched;
    return true;
  }
  g.Undo();
  return false;
}

/// The partner entry of b among a's aggregation partners, or (-1, -1).
template <class MeshType>
std::pair<int, int> PartnerEntry(MeshEditor<MeshType>& ed, const ReductionState<MeshType>& state, int a, int b) {
  for (const std::pair<int, int>& p : AggregationPartners(ed, state, a))
    if (p.first == b) return p;
  return {-1, -1};
}

/// How far a gathering's generated pairs are transported toward the nearest irregular vertices
/// before they glide, in units of the run's travel (maxTravel, scaled to the mesh). The leftovers
/// are sparse: the elephant at 20K kept 63 with no transport toward a target (the pairs only
/// glided), 61 with 1 travel, 60 with 2, 3 or 4 (native bench, 0.9.31).
constexpr int kGatherTravelScale = 2;

template <class MeshType>
int GatherTravel(EditGuard<MeshType>& guard) {
  return kGatherTravelScale * std::max(1, guard.options().maxTravel);
}

/// Gathering (ReductionOptions::gatherRadius): a leftover v5 / v7 `a` with no partner in an
/// aggregation's configuration walks toward b, a vertex of its type within `radius` edges (PairTransport::WalkToward: each step a move with 5-7 pair generation, sec. 6.2, the
/// generated pair transported away to a cancellation, sec. 7.2), until b is its partner; then
/// the two aggregate (TryAggregation). Why the walk costs no irregular vertex on the way: in
/// the lattice picture a v5 or v7 is a disclination, and moving one by a lattice step leaves a
/// dislocation (the 5-7 pair) behind; the transport carries it to a removal (against another
/// pair, or a lone vertex it moves by a step), so each step is count-neutral or better, and
/// the aggregation at the end removes one. One guarded edit for the whole: kept only if the
/// count went down and every part passed the guard; otherwise everything is rolled back (the
/// report as before, the refusals counted). If a stops short, b walks the rest toward it.
/// Runs inside the caller's turn (Gather).
template <class MeshType>
bool GatherPair(MeshType& m, EditGuard<MeshType>& guard, PairTransport<MeshType>& transport, TypeChange<MeshType>& tc,
                ReductionReport& rep, int a, int b, int radius, AggregationReport& out) {
  MeshEditor<MeshType>& ed = guard.ed();
  ReductionState<MeshType>& state = guard.state();
  const int valence = ed.Valence(a);
  ++out.gathersTried;
  const ReductionReport saved = rep;
  bool kept = false;
  {
    GuardedEdit<MeshType> g(guard, rep, {a, b});
    std::vector<int> touched{a, b}, unjudged{a, b};
    // x walks toward y until the two are partners; two edges apart, a hop must land in the configuration: one step more would make
    // the two adjacent, and adjacent v5 never aggregate (sec. 3)
    typename PairTransport<MeshType>::WalkRules rules;
    rules.arrived = [&](int c, int y) { return PartnerEntry(ed, state, c, y).first >= 0; };
    rules.accept = [&](int c, int y) {
      if (rules.arrived(c, y)) return true;
      if (ed.Adjacent(c, y)) return false;
      for (auto* nb : ed.Star(c).neighbors)
        if (ed.Adjacent(ed.Index(nb), y)) return false;
      return true;
    };
    auto partnerOf = [&](int x, int y) {
      return ed.IsLive(x) && ed.IsLive(y) && ed.Valence(x) == valence && ed.Valence(y) == valence
                 ? PartnerEntry(ed, state, x, y)
                 : std::pair<int, int>(-1, -1);
    };
    int other = b;
    int cur = transport.WalkToward(rep, a, other, radius, GatherTravel(guard), touched, unjudged, rules);
    std::pair<int, int> partner = partnerOf(cur, other);
    // a stopped short (no hop closer it could keep): the partner walks the rest toward a
    if (partner.first < 0 && ed.IsLive(cur) && ed.IsLive(other) && ed.Valence(cur) == valence &&
        ed.Valence(other) == valence && !ed.Adjacent(cur, other) && !state.TurnExhausted()) {
      std::swap(cur, other);
      cur = transport.WalkToward(rep, cur, other, radius, GatherTravel(guard), touched, unjudged, rules);
      partner = partnerOf(cur, other);
    }
    const bool walked = touched.size() > 2;
    std::vector<int> aggregated;
    if (walked && partner.first >= 0 && !state.TurnExhausted() &&
        TryAggregation(m, guard, tc, rep, cur, partner, out, false, &aggregated)) {
      touched.insert(touched.end(), aggregated.begin(), aggregated.end());
      if (state.CountChange(touched) < 0 && g.Judge(unjudged)) {
        g.Keep(touched);
        kept = true;
      }
    }
    if (!kept) {
      rep.RestoreKeepingRefusals(saved);
      g.Undo();
    }
  }
  if (kept) {
    ++(valence == 5 ? out.v4 : out.v8);
    ++out.gathered;
  }
  return kept;
}

/// Gathering for a: GatherPair with the nearest vertices of its type within `radius` edges,
/// up to kGatherPartners of them, nearest first, until one is kept. One turn (the effort bound
/// of a region, ReductionState::BeginTurn) for all of them.
template <class MeshType>
bool Gather(MeshType& m, EditGuard<MeshType>& guard, PairTransport<MeshType>& transport, TypeChange<MeshType>& tc,
            ReductionReport& rep, int a, int radius, AggregationReport& out) {
  MeshEditor<MeshType>& ed = guard.ed();
  ReductionState<MeshType>& state = guard.state();
  const int valence = ed.Valence(a);
  if (!GatherOpen(guard.options(), out)) return false;  // before the search for partners
  const std::vector<int> near = transport.NearestIrregular({a}, radius, kGatherPartners, valence);
  bool kept = false;
  state.BeginTurn(a);
  for (int b : near) {
    if (state.TurnExhausted() || !GatherOpen(guard.options(), out)) break;
    // adjacent v5 never make a v4 (sec. 3); the others were changed by nothing (a refused
    // gathering is rolled back whole)
    if (!ed.Adjacent(a, b) && ed.Valence(a) == valence && GatherPair(m, guard, transport, tc, rep, a, b, radius, out)) {
      kept = true;
      break;
    }
  }
  state.EndTurn();
  return kept;
}

/// Merges pairs of interior v5 (into a v4) and of v7 (into a v8) where the configuration of
/// sec. 6.3 holds and the guard passes the result (header comment); then, with a transport and
/// gatherRadius > 0, gathers the leftovers that had no partner (Gather). Vertices in ascending
/// index, each with its partners (and aggregate vertices) in ascending index: deterministic.
template <class MeshType>
AggregationReport AggregateLeftovers(MeshType& m, EditGuard<MeshType>& guard, ReductionReport& rep,
                                     PairTransport<MeshType>* transport = nullptr, int gatherRadius = 0) {
  MeshEditor<MeshType>& ed = guard.ed();
  ReductionState<MeshType>& state = guard.state();
  TypeChange<MeshType> tc(ed);
  AggregationReport out;
  std::vector<int> irregular;  // gathered first: a kept aggregation adds a vertex (the v4's split)
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (state.IsInteriorIrregular(int(i)) && !state.Frozen(int(i))) irregular.push_back(int(i));
  for (int a : irregular) {
    if (!ed.IsLive(a)) continue;
    for (const std::pair<int, int>& partner : AggregationPartners(ed, state, a)) {
      const int b = partner.first;
      if (!ed.IsLive(a) || !ed.IsLive(b)) break;  // an earlier aggregation changed them
      const int valence = ed.Valence(a);
      if ((valence != 5 && valence != 7) || ed.Valence(b) != valence) break;
      if (TryAggregation(m, guard, tc, rep, a, partner, out, true)) break;  // a is aggregated
    }
  }
  if (!transport || gatherRadius <= 0) return out;
  // rounds while they gather: a walk moves other leftovers (its pairs' removals), which can
  // bring a partner within reach or into a configuration
  for (int round = 0; round < kGatherRounds; ++round) {
    const int before = out.gathered;
    irregular.clear();
    for (size_t i = 0; i < m.vert.size(); ++i)
      if (state.IsInteriorIrregular(int(i)) && !state.Frozen(int(i))) irregular.push_back(int(i));
    for (int a : irregular) {
      if (!ed.IsLive(a) || !state.IsInteriorIrregular(a) || state.Frozen(a)) continue;
      const int valence = ed.Valence(a);
      if (valence != 5 && valence != 7) continue;
      // a refused aggregation is rolled back whole, so the partners stay those found here
      const std::vector<std::pair<int, int>> partners = AggregationPartners(ed, state, a);
      bool done = false;
      for (const std::pair<int, int>& partner : partners)
        if (TryAggregation(m, guard, tc, rep, a, partner, out, true)) {
          done = true;
          break;
        }
      if (!done && partners.empty()) Gather(m, guard, *transport, tc, rep, a, gatherRadius, out);
    }
    if (out.gathered == before) break;
  }
  return out;
}

}  // namespace irregular
}  // namespace vcg_ext
