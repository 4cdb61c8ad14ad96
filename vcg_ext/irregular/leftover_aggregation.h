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
// An aggregation is kept only if it passes the edit guard (edit_guard.h: Hausdorff, crease,
// angle, protected selection, after local relaxation of its 2-ring and a few more relaxations
// around the corners left under the minimum angle) and turns no triangle over (where its region
// had none turned over before: slivers on thin parts, as in angle_flip.h).
//
// Preconditions: as EditGuard (the guard's mesh with FF/VF adjacency, journaled editor, inside
// the reduction's snapshot, the running count started). Postconditions: every kept aggregation
// lowered the interior irregular count by one and passed the above; a refused one is rolled back
// exactly. Cost: one scan of the vertices, then O(1) per irregular vertex (a dry run and at most
// one guarded edit per candidate pair).
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "edit_guard.h"
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

/// How the aggregation went: v4s and v8s made (kept), candidate pairs tried under the guard.
struct AggregationReport {
  int v4 = 0, v8 = 0, tried = 0;
  int Kept() const { return v4 + v8; }
};

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

/// Merges pairs of interior v5 (into a v4) and of v7 (into a v8) where the configuration of
/// sec. 6.3 holds and the guard passes the result (header comment). Vertices in ascending
/// index, each with its partners (and aggregate vertices) in ascending index: deterministic.
template <class MeshType>
AggregationReport AggregateLeftovers(MeshType& m, EditGuard<MeshType>& guard, ReductionReport& rep) {
  MeshEditor<MeshType>& ed = guard.ed();
  ReductionState<MeshType>& state = guard.state();
  TypeChange<MeshType> tc(ed);
  AggregationReport out;
  std::vector<int> irregular;  // gathered first: a kept aggregation adds a vertex (the v4's split)
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (state.IsInteriorIrregular(int(i)) && !state.Frozen(int(i))) irregular.push_back(int(i));
  const std::vector<int> none;  // no subject: a refusal is no leftover's reason
  for (int a : irregular) {
    if (!ed.IsLive(a)) continue;
    for (const std::pair<int, int>& partner : AggregationPartners(ed, state, a)) {
      const int b = partner.first;
      if (!ed.IsLive(a) || !ed.IsLive(b)) break;  // an earlier aggregation changed them
      const int valence = ed.Valence(a);
      if ((valence != 5 && valence != 7) || ed.Valence(b) != valence) break;
      AggregationRequest req;
      req.group = {a, b};
      req.at = partner.second;
      if (!tc.PredictAggregation(req)) continue;
      const std::vector<int> around = KRing(m, {a, b}, 1);
      // a region that already had a turned-over triangle (slivers on thin parts, as in
      // angle_flip.h) is judged by the rest: refused only for turning one over itself
      const bool foldedBefore = guard.FoldsAround(around);
      ++out.tried;
      GuardedEdit<MeshType> g(guard, rep, around, &none);
      const TypeChangeOutcome o = tc.Aggregate(req);
      if (!o) {
        g.Undo();
        continue;
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
      if ((foldedBefore || !guard.FoldsAround(touched)) && state.CountChange(touched) < 0 &&
          verdict == GuardVerdict::Kept) {
        g.Keep(touched);
        ++(valence == 5 ? out.v4 : out.v8);
        break;  // a is aggregated
      }
      g.Undo();
    }
  }
  return out;
}

}  // namespace irregular
}  // namespace vcg_ext
