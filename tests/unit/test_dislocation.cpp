// Unit tests of vcg_ext/irregular/dislocation.h: Burgers vectors of 5-7 pairs in lattice
// coordinates, their comparison, and the global plan of meetings.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <vector>

#include <vcg_ext/irregular/composite_ops.h>
#include <vcg_ext/irregular/dislocation.h>
#include <vcg_ext/irregular/mesh_checks.h>

#include "composite_test_util.h"
#include "test_mesh.h"
#include "test_util.h"

using namespace vcg_ext::irregular;
using test::Irregular;
using test::TMesh;

namespace {
const int N = 40;
/// On test::RegularTorus(m, N, N) vertex (i, j) has index i * N + j and neighbours (i +- 1, j),
/// (i, j +- 1), (i + 1, j + 1), (i - 1, j - 1), counter-clockwise (1,0), (1,1), (0,1), ...: the
/// lattice steps e0, e1, e2. Lattice coordinates of a torus displacement (di, dj):
LatticeVector FromTorus(int di, int dj) {
  auto wrap = [](int x) { return ((x % N) + N + N / 2) % N - N / 2; };
  di = wrap(di), dj = wrap(dj);
  return LatticeVector{di - dj, dj};
}
int At(int i, int j) { return ((i % N + N) % N) * N + ((j % N + N) % N); }
LatticeVector Displacement(int from, int to) { return FromTorus(to / N - from / N, to % N - from % N); }
/// The global frame of the torus at (i, j): e0 toward (i + 1, j).
LatticeFrame Global(int i, int j) { return LatticeFrame{At(i, j), At(i + 1, j)}; }
/// Graph distance between two vertex sets (breadth-first over the stars).
int Hops(TMesh& m, const std::vector<int>& from, const std::vector<int>& to) {
  std::map<int, int> d;
  std::vector<int> q;
  for (int v : from) d[v] = 0, q.push_back(v);
  for (size_t i = 0; i < q.size(); ++i) {
    if (std::find(to.begin(), to.end(), q[i]) != to.end()) return d[q[i]];
    for (auto* n : StarOf<TMesh>(&m.vert[size_t(q[i])]).neighbors) {
      const int w = int(vcg::tri::Index(m, n));
      if (!d.count(w)) d[w] = d[q[i]] + 1, q.push_back(w);
    }
  }
  return -1;
}
}  // namespace


namespace {
/// A 5-5-7-7 quadruple generated at (20, 20) in orientation k (atomic_ops.h's GenerateQuadruple
/// neighbour k), its first pair then moved `x` flips in pair direction 4 (a glide): two 5-7
/// pairs x + 1 edges apart, relaxation off so flips keep every index (lattice positions).
struct TorusQuadruple {
  TMesh m;
  int a5 = -1, a7 = -1, b5 = -1, b7 = -1;
  void Build(int k, int x, int at = At(20, 20)) {
    test::RegularTorus(m, N, N);
    Add(k, x, at);
  }
  void Add(int k, int x, int at) {
    MeshEditor<TMesh> ed(m);
    CompositeOptions opt;
    opt.relax = false;
    CompositeOperations<TMesh> co(ed, nullptr, opt);
    CompositeOutcome g = co.GenerateQuadrupleShape(at, k, 4, x, 4, 0);
    ASSERT_TRUE(g) << g.result.reason;
    ed.Commit();
    a5 = g.pair5, a7 = g.pair7, b5 = g.other5, b7 = g.other7;
  }
};
/// The first v5 of the mesh (by index).
int FirstV5(MeshEditor<TMesh>& ed) {
  for (size_t i = 0; i < ed.Mesh().vert.size(); ++i)
    if (ed.Valence(int(i)) == 5) return int(i);
  return -1;
}
/// Moves the v5 `lone` one step with 5-7 pair generation (fig. 7, neighbour k) and parks the
/// generated pair 3 atomic steps away from `lone`'s new place and from `away`.
void SplitOffPair(MeshEditor<TMesh>& ed, AtomicOperations<TMesh>& ops, int& lone, int k, int& p5, int& p7,
                  std::vector<vcg::Point3f> away) {
  AtomicOutcome g = ops.MoveWithPairGeneration(lone, k);
  ASSERT_TRUE(g) << g.result.reason;
  lone = g.irregular[0], p5 = g.irregular[1], p7 = g.irregular[2];
  if (ed.Valence(p5) != 5) std::swap(p5, p7);
  away.push_back(ed.V(lone)->P());
  test::Park(ed, ops, p5, p7, away, 3);
}

}  // namespace

// The Burgers circuit of a 5-7 pair on the flat torus, in the torus's global lattice frame,
// for the six orientations of a generated quadruple: exact lattice vectors, unit steps; the
// other pair of the quadruple has the opposite vector; the vector is the v5->v7 edge's step
// turned 60 degrees clockwise (the 60-degree rule) and the displacement of the glide (pair
// direction 4, a flip); each of the six atomic pair moves (fig. 6) keeps it.
TEST(Dislocation, BurgersVectorsOfAQuadruplesPairsAreExactOppositeAndConserved) {
  const LatticeVector expected[6] = {{-1, 1}, {-1, 0}, {0, -1}, {1, -1}, {1, 0}, {0, 1}};
  for (int k = 0; k < 6; ++k) {
    SCOPED_TRACE(testing::Message() << "orientation " << k);
    TorusQuadruple q;
    q.Build(k, 4);
    if (HasFatalFailure()) return;
    TMesh& m = q.m;
    DislocationAnalysis<TMesh> da(m);
    BurgersCircuit A = da.PairCircuit(q.a5, q.a7), B = da.PairCircuit(q.b5, q.b7);
    ASSERT_TRUE(A) << A.result.reason;
    ASSERT_TRUE(B) << B.result.reason;
    EXPECT_EQ(A.charge, 0);
    EXPECT_EQ(A.holonomy, 0);
    EXPECT_EQ(A.loop.size(), 8u);  // the boundary of the two stars: 5 + 7 - 2 - 2 vertices
    EXPECT_EQ(A.burgers.Norm2(), 1);
    Result why;
    const LatticeVector a = da.BurgersIn(A, Global(5, 5), 60, &why);
    ASSERT_TRUE(why.ok) << why.reason;
    const LatticeVector b = da.BurgersIn(B, Global(5, 5), 60, &why);
    ASSERT_TRUE(why.ok) << why.reason;
    EXPECT_EQ(a, expected[k]) << a.Str();
    EXPECT_EQ(b, -expected[k]) << b.Str();
    // the 60-degree rule, in lattice coordinates read from the indices
    EXPECT_EQ(a, Displacement(q.a5, q.a7).Rotated(-1)) << Displacement(q.a5, q.a7).Str();
    BurgersComparison c = da.Compare(A, B, 20);
    ASSERT_TRUE(c) << c.result.reason;
    EXPECT_TRUE(c.opposite);
    EXPECT_FALSE(c.ambiguous);
    EXPECT_EQ(c.first, A.burgers);
    MeshEditor<TMesh> ed(m);
    AtomicOperations<TMesh> ops(ed);
    for (int dir = 0; dir < 6; ++dir) {
      auto cp = ed.Mark();
      AtomicOutcome o = ops.MovePair57(q.a5, q.a7, dir);
      ASSERT_TRUE(o) << o.result.reason;
      DislocationAnalysis<TMesh> after(m);
      BurgersCircuit A2 = after.PairCircuit(o.irregular[0], o.irregular[1]);
      ASSERT_TRUE(A2) << A2.result.reason;
      EXPECT_EQ(after.BurgersIn(A2, Global(5, 5), 60), expected[k]) << "after pair move " << dir;
      if (dir == 4) EXPECT_EQ(Displacement(q.a5, o.irregular[0]), expected[k]);   // glide along b
      if (dir == 1) EXPECT_EQ(Displacement(q.a5, o.irregular[0]), -expected[k]);  // and back
      ed.RollbackTo(cp);
    }
  }
}

// A Burgers vector does not depend on the circuit: the circuit around the pair's 1-ring (a
// larger loop, 2 rings out) gives the same vector in the same global frame. Around a lone v5
// (an icosphere's) the frame turns once: holonomy -1 (mod 6), charge +1, no Burgers vector.
TEST(Dislocation, CircuitIndependenceAndTheHolonomyOfADisclination) {
  TorusQuadruple q;
  q.Build(2, 7);
  if (HasFatalFailure()) return;
  DislocationAnalysis<TMesh> da(q.m);
  BurgersCircuit small = da.PairCircuit(q.a5, q.a7);
  std::vector<int> core{q.a5, q.a7};
  for (int v : {q.a5, q.a7})
    for (auto* n : StarOf<TMesh>(&q.m.vert[size_t(v)]).neighbors) core.push_back(int(vcg::tri::Index(q.m, n)));
  BurgersCircuit big = da.Circuit(core);
  ASSERT_TRUE(small) << small.result.reason;
  ASSERT_TRUE(big) << big.result.reason;
  EXPECT_GT(big.loop.size(), small.loop.size());
  EXPECT_EQ(da.BurgersIn(big, Global(3, 3), 60), da.BurgersIn(small, Global(3, 3), 60));
  EXPECT_EQ(da.BurgersIn(small, Global(3, 3), 60), (LatticeVector{0, -1}));

  TMesh s;
  test::Icosphere(s, 3);
  DislocationAnalysis<TMesh> ds(s);
  int v5 = -1;
  for (size_t i = 0; i < s.vert.size() && v5 < 0; ++i)
    if (StarOf<TMesh>(&s.vert[i]).Valence() == 5) v5 = int(i);
  BurgersCircuit lone = ds.Circuit({v5});
  ASSERT_TRUE(lone) << lone.result.reason;
  EXPECT_EQ(lone.charge, 1);
  EXPECT_EQ(lone.holonomy, 5);
  EXPECT_TRUE(lone.burgers.IsZero());
  BurgersComparison c = ds.Compare(lone, lone, 10);
  EXPECT_FALSE(c);  // a disclination has no Burgers vector to compare
}

// Two quadruples whose same-vector pairs are nearer to each other (6 edges) than to their
// opposite partners (8 edges): the plan (exact and greedy alike) meets each pair with its
// opposite, not with its nearest irregular vertex; moving the pairs together with the
// composite quadruple cancellation (sec. 7.3) then leaves the torus regular. The same-vector
// couple is compared as not opposite (b + b = 2b) and cannot annihilate.
TEST(Dislocation, PlanMeetsOppositePairsAndTheyCancel) {
  for (int maxExact : {16, 0}) {
    SCOPED_TRACE(testing::Message() << "maxExact " << maxExact);
    TorusQuadruple q;
    q.Build(0, 7, At(20, 20));
    if (HasFatalFailure()) return;
    const int a5 = q.a5, a7 = q.a7, b5 = q.b5, b7 = q.b7;
    q.Add(0, 7, At(26, 20));
    if (HasFatalFailure()) return;
    const int c5 = q.a5, c7 = q.a7, d5 = q.b5, d7 = q.b7;
    TMesh& m = q.m;
    ASSERT_EQ(Irregular(m).size(), 8u);
    // the nearest irregular vertices of the first pair are the other quadruple's same-vector pair
    EXPECT_LT(Hops(m, {a5, a7}, {c5, c7}), Hops(m, {a5, a7}, {b5, b7}));
    DislocationAnalysis<TMesh> da(m);
    BurgersCircuit A = da.PairCircuit(a5, a7), C = da.PairCircuit(c5, c7);
    BurgersComparison same = da.Compare(A, C, 20);
    ASSERT_TRUE(same) << same.result.reason;
    EXPECT_FALSE(same.opposite);
    EXPECT_EQ(same.Sum(), A.burgers + A.burgers);
    MatchingOptions mo;
    mo.maxExact = maxExact;
    MeetingPlan plan = da.Plan({}, mo);
    ASSERT_EQ(plan.sites.size(), 4u) << plan.Summary();
    for (auto& s : plan.sites) EXPECT_EQ(s.kind, DefectSite::Kind::Pair);
    ASSERT_EQ(plan.meetings.size(), 2u) << plan.Summary();
    EXPECT_EQ(plan.predictedRemoved, 8);
    EXPECT_TRUE(plan.unmatched.empty());
    EXPECT_EQ(maxExact > 0 ? plan.exactComponents : plan.greedyComponents, 1);
    std::set<std::vector<int>> got;
    for (auto& pm : plan.meetings) {
      EXPECT_EQ(pm.kind, MeetingKind::Quadruple) << pm.Describe();
      EXPECT_EQ(pm.removes, 4);
      EXPECT_FALSE(pm.ambiguous);
      EXPECT_GE(pm.routeLength, pm.distance);
      EXPECT_LE(pm.distance, 8);
      std::vector<int> v = pm.vertices;
      std::sort(v.begin(), v.end());
      got.insert(v);
    }
    std::vector<int> ab{a5, a7, b5, b7}, cd{c5, c7, d5, d7};
    std::sort(ab.begin(), ab.end());
    std::sort(cd.begin(), cd.end());
    EXPECT_EQ(got, (std::set<std::vector<int>>{ab, cd}));
    // end to end: the composite move brings each pair to its partner and they vanish
    MeshEditor<TMesh> ed(m);
    CompositeOptions opt;
    opt.relax = false;
    CompositeOperations<TMesh> co(ed, nullptr, opt);
    for (auto& pm : plan.meetings) {
      CompositeOutcome o = co.CancelQuadruple(pm.vertices);
      ASSERT_TRUE(o) << o.result.reason << "\n" << o.log;
      EXPECT_TRUE(CheckInvariants(m).ok);
    }
    EXPECT_TRUE(Irregular(m).empty());
  }
}

// A 5-7 pair next to a lone v5 on an icosphere (whose twelve v5 are 16 edges apart): the plan
// proposes the 5-5-7 triple (sec. 7.2) of the pair with that v5, and no meeting of two lone
// v5 (they cannot cancel); the composite triple cancellation does it, leaving twelve v5.
TEST(Dislocation, PlanProposesTheTripleOfAPairAndALoneV5) {
  TMesh m;
  test::Icosphere(m, 4);
  int lone = -1, p5 = -1, p7 = -1;
  {
    MeshEditor<TMesh> ed(m);
    AtomicOperations<TMesh> ops(ed);
    lone = FirstV5(ed);
    SplitOffPair(ed, ops, lone, 0, p5, p7, {});
    if (HasFatalFailure()) return;
    ed.Commit();
  }
  DislocationAnalysis<TMesh> da(m);
  MeetingPlan plan = da.Plan();
  EXPECT_EQ(plan.sites.size(), 13u) << plan.Summary();
  ASSERT_EQ(plan.meetings.size(), 1u) << plan.Summary();
  const PlannedMeeting& pm = plan.meetings[0];
  EXPECT_EQ(pm.kind, MeetingKind::Triple);
  EXPECT_EQ(pm.vertices, (std::vector<int>{p5, p7, lone}));
  EXPECT_EQ(pm.survivorValence, 5);
  EXPECT_EQ(pm.removes, 2);
  EXPECT_EQ(plan.unmatched.size(), 11u);
  EXPECT_EQ(plan.sites[size_t(pm.first)].kind, DefectSite::Kind::Pair);
  EXPECT_EQ(plan.sites[size_t(pm.second)].vertex, lone);
  MeshEditor<TMesh> ed(m);
  SurfaceProjector original(m);
  CompositeOperations<TMesh> co(ed, &original);
  CompositeOutcome o = co.CancelTriple(pm.vertices);
  ASSERT_TRUE(o) << o.result.reason << "\n" << o.log;
  EXPECT_TRUE(CheckInvariants(m).ok);
  std::map<int, int> irr = Irregular(m);
  EXPECT_EQ(irr.size(), 12u);
  for (auto& kv : irr) EXPECT_EQ(kv.second, 5);
}

// Two pairs split off a lone v5 of an icosphere and parked on its two sides: the shortest
// route between them passes by the v5, and a route on its other side, about as short, would
// carry the frame 60 degrees differently, so their comparison is flagged ambiguous.
TEST(Dislocation, ComparisonNearADisclinationIsFlaggedAmbiguous) {
  TMesh m;
  test::Icosphere(m, 4);
  MeshEditor<TMesh> ed(m);
  AtomicOperations<TMesh> ops(ed);
  // two pairs split off the same v5 one after the other: a lone v5 with two pairs around it
  int lone = FirstV5(ed), x5 = -1, x7 = -1, y5 = -1, y7 = -1;
  SplitOffPair(ed, ops, lone, 0, x5, x7, {});
  if (HasFatalFailure()) return;
  test::Park(ed, ops, x5, x7, {ed.V(lone)->P()}, 1);
  AtomicOutcome h = ops.MoveWithPairGeneration(lone, 3);
  ASSERT_TRUE(h) << h.result.reason;
  lone = h.irregular[0], y5 = h.irregular[1], y7 = h.irregular[2];
  if (ed.Valence(y5) != 5) std::swap(y5, y7);
  test::Park(ed, ops, y5, y7, {ed.V(x5)->P()}, 5);  // away from X: past the lone v5
  if (HasFatalFailure()) return;
  ed.Commit();
  DislocationAnalysis<TMesh> da(m);
  BurgersCircuit X = da.PairCircuit(x5, x7), Y = da.PairCircuit(y5, y7);
  ASSERT_TRUE(X) << X.result.reason;
  ASSERT_TRUE(Y) << Y.result.reason;
  BurgersComparison c = da.Compare(X, Y, 20);
  ASSERT_TRUE(c) << c.result.reason;
  EXPECT_LE(Hops(m, c.route, {lone}), 2);  // the shortest route passes right by the lone v5
  EXPECT_TRUE(c.ambiguous);
  EXPECT_GE(c.disclinationNearRoute, 0);
  EXPECT_EQ(StarOf<TMesh>(&m.vert[size_t(c.disclinationNearRoute)]).Valence(), 5);
}


// The prediction agrees with the operation: a pair of one quadruple and a pair of another
// (six relative orientations) annihilate by the composite quadruple cancellation (sec. 7.3)
// exactly when their Burgers vectors are opposite; otherwise the cancellation is refused and
// the mesh is unchanged.
TEST(Dislocation, QuadrupleCancellationSucceedsExactlyForOppositeVectors) {
  int opposite = 0;
  for (int k2 = 0; k2 < 6; ++k2) {
    SCOPED_TRACE(testing::Message() << "second orientation " << k2);
    TorusQuadruple q;
    q.Build(0, 6, At(14, 14));
    if (HasFatalFailure()) return;
    const int a5 = q.a5, a7 = q.a7;
    q.Add(k2, 6, At(24, 14));
    if (HasFatalFailure()) return;
    const int c5 = q.a5, c7 = q.a7;
    TMesh& m = q.m;
    DislocationAnalysis<TMesh> da(m);
    BurgersComparison c = da.Compare(da.PairCircuit(a5, a7), da.PairCircuit(c5, c7), 30);
    ASSERT_TRUE(c) << c.result.reason;
    EXPECT_EQ(c.opposite, k2 == 3) << c.first.Str() << " " << c.second.Str();
    opposite += c.opposite;
    MeshEditor<TMesh> ed(m);
    CompositeOptions opt;
    opt.relax = false;
    opt.maxTransportSteps = 40;
    CompositeOperations<TMesh> co(ed, nullptr, opt);
    const auto snap = test::Snapshot(m);
    CompositeOutcome o = co.CancelQuadruple({a5, a7, c5, c7});
    EXPECT_EQ(bool(o), c.opposite) << o.result.reason;
    if (o) {
      EXPECT_EQ(Irregular(m).size(), 4u);  // the two other pairs stay
      EXPECT_TRUE(CheckInvariants(m).ok);
    } else {
      EXPECT_EQ(test::Snapshot(m), snap);
    }
  }
  EXPECT_EQ(opposite, 1);
}
