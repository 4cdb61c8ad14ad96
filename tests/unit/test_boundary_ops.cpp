// Boundary operations (boundary_ops.h): an interior v5 or v7 next to the boundary absorbed
// into it, a 5-7 pair generated from the boundary and absorbed again, a boundary v3 moved
// along the boundary; refusals leave the mesh unchanged; Predict* agrees with the operation
// on random requests near boundaries. Vertices are named by lattice coordinates or by the
// ids the outcome names; every touched valence and the untouched rest are checked.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include <vcg_ext/irregular/atomic_ops.h>
#include <vcg_ext/irregular/boundary_ops.h>
#include <vcg_ext/irregular/mesh_checks.h>

#include "test_boundary_mesh.h"
#include "test_mesh.h"
#include "test_util.h"

using namespace vcg_ext::irregular;
using test::At;
using test::ExpectValid;
using test::TMesh;

namespace {


/// Live vertices irregular by the boundary valence rule, split by where they are.
struct Irregular {
  std::vector<int> interior, boundary;
};
Irregular IrregularOf(TMesh& m) {
  Irregular r;
  ValenceField<TMesh> vf = ComputeValences(m);
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD() && vf.IsIrregular(i)) (vf.boundary[i] ? r.boundary : r.interior).push_back(int(i));
  return r;
}

/// Every live vertex outside `touched` kept its valence.
void ExpectOthersUnchanged(TMesh& m, const std::vector<int>& before, const std::map<int, int>& touched) {
  const std::vector<int> after = test::Valences(m);
  for (size_t i = 0; i < before.size(); ++i) {
    auto it = touched.find(int(i));
    EXPECT_EQ(after[i], it == touched.end() ? before[i] : it->second) << "vertex " << i;
  }
}

/// HexPatch(4) whose corner (4, 0) is pulled in to a corner angle of about 167 degrees: a
/// boundary v3 on a smooth stretch (a boundary "v5"), the only irregular vertex.
int FlattenedCorner(TMesh& m) {
  test::HexPatch(m, 4);
  const int c = At(m, 4, 0);
  VertexStar<TMesh> cs = StarOf<TMesh>(&m.vert[size_t(c)]);
  const vcg::Point3f mid = (cs.neighbors.front()->P() + cs.neighbors.back()->P()) * 0.5f;
  m.vert[size_t(c)].P() = mid + (m.vert[size_t(c)].P() - mid) * 0.2f;
  test::UpdateTopology(m);
  return c;
}

/// Random boundary requests: makes the boundary at v irregular by a boundary split or a
/// boundary-edge collapse to a random neighbour (nothing if v is interior), then commits.
void SeedBoundaryIrregularity(TMesh& m, MeshEditor<TMesh>& ed, std::mt19937& rng, int v) {
  VertexStar<TMesh> s = ed.Star(v);
  if (!s.boundary) return;
  const int a = ed.Index(s.neighbors[size_t(rng() % s.neighbors.size())]);
  Result r = rng() % 2 ? ed.SplitBoundary(v, a) : ed.Collapse(v, a);
  if (r) ExpectValid(m);
  ed.Commit();
}
/// A neighbour of valence 7 in the star s (the last one), or -1.
int Neighbour7(MeshEditor<TMesh>& ed, const VertexStar<TMesh>& s) {
  int p7 = -1;
  for (auto* n : s.neighbors)
    if (ed.Valence(ed.Index(n)) == 7) p7 = ed.Index(n);
  return p7;
}
/// Request `kind` (1 Absorb, 2 AbsorbPair, 3 MoveAlongBoundary, else GeneratePair), its dry
/// run (predict) or the operation.
BoundaryOutcome BoundaryOp(BoundaryOperations<TMesh>& bo, bool predict, int kind, int v, int p7, int side) {
  switch (kind) {
    case 1: return predict ? bo.PredictAbsorb(v) : bo.Absorb(v);
    case 2: return predict ? bo.PredictAbsorbPair(v, p7) : bo.AbsorbPair(v, p7);
    case 3: return predict ? bo.PredictMoveAlongBoundary(v, side) : bo.MoveAlongBoundary(v, side);
    default: return predict ? bo.PredictGeneratePair(v, side) : bo.GeneratePair(v, side);
  }
}

}  // namespace

TEST(BoundaryOps, FlattenedCornerIsTheOnlyIrregularVertex) {
  TMesh m;
  const int c = FlattenedCorner(m);
  Irregular ir = IrregularOf(m);
  EXPECT_TRUE(ir.interior.empty());
  EXPECT_EQ(ir.boundary, std::vector<int>{c});
}

// The boundary v3 emitted into the inside by a boundary-edge collapse, then absorbed again.
TEST(BoundaryOps, AbsorbV5) {
  TMesh m;
  const int c = FlattenedCorner(m);
  MeshEditor<TMesh> ed(m);
  BoundaryOperations<TMesh> bo(ed);
  const int s1 = At(m, 3, 1), in = At(m, 3, 0);
  ASSERT_TRUE(ed.Collapse(c, s1).ok);  // (A): s1 3 + 4 - 3 = 4, in: 6 -> 5
  ed.Commit();
  ASSERT_EQ(ed.Valence(in), 5);
  Irregular ir = IrregularOf(m);
  ASSERT_EQ(ir.interior, std::vector<int>{in});
  ASSERT_TRUE(ir.boundary.empty());
  const auto before = test::Valences(m);
  auto snap = test::Snapshot(m);
  BoundaryOutcome pred = bo.PredictAbsorb(in);
  EXPECT_EQ(test::Snapshot(m), snap);
  BoundaryOutcome o = bo.Absorb(in);
  ASSERT_TRUE(o) << o.result.reason;
  EXPECT_TRUE(pred.result.ok);
  EXPECT_EQ(pred.changes, o.changes);
  EXPECT_EQ(pred.boundaryVertex, o.boundaryVertex);
  EXPECT_EQ(o.absorbed, in);
  EXPECT_EQ(ed.Valence(in), 6);
  ASSERT_GE(o.created, 0);
  ASSERT_GE(o.boundaryVertex, 0);
  EXPECT_TRUE(ed.IsBoundary(o.boundaryVertex));
  EXPECT_EQ(ed.Valence(o.boundaryVertex), 3);
  // touched: in (5 -> 6) and the new half of the split boundary vertex (3); the split vertex
  // keeps valence 4 (its fan had `in` at index 2 of 3 corners: halves 4 and 3)
  EXPECT_EQ(o.changes, (std::map<int, int>{{in, 6}, {o.created, 3}}));
  EXPECT_EQ(o.boundaryVertex, o.created);
  ExpectOthersUnchanged(m, before, o.changes);
  ir = IrregularOf(m);
  EXPECT_TRUE(ir.interior.empty());
  EXPECT_EQ(ir.boundary, std::vector<int>{o.boundaryVertex});
  ExpectValid(m);
}

// SplitBoundary of a regular side vertex makes a v7 and a boundary v3; absorbing the v7 by a
// boundary-edge collapse removes the v3 end and leaves no irregular vertex.
TEST(BoundaryOps, AbsorbV7CancelsABoundaryV3) {
  TMesh m;
  test::HexPatch(m, 4);
  MeshEditor<TMesh> ed(m);
  BoundaryOperations<TMesh> bo(ed);
  const int w = At(m, 2, 2);
  VertexStar<TMesh> st = ed.Star(w);
  ASSERT_EQ(st.Valence(), 4);
  const int c = ed.Index(st.neighbors[1]);
  int x = -1;
  ASSERT_TRUE(ed.SplitBoundary(w, c, &x).ok);
  EXPECT_EQ(ed.Valence(w), 3);  // i + 2, i = 1
  EXPECT_EQ(ed.Valence(x), 4);  // n - i + 2, n = 3
  EXPECT_EQ(ed.Valence(c), 7);
  ExpectValid(m);
  ed.Commit();
  Irregular ir = IrregularOf(m);
  ASSERT_EQ(ir.interior, std::vector<int>{c});
  ASSERT_EQ(ir.boundary, std::vector<int>{w});
  const auto before = test::Valences(m);
  BoundaryOutcome pred = bo.PredictAbsorb(c);
  BoundaryOutcome o = bo.Absorb(c);
  ASSERT_TRUE(o) << o.result.reason;
  EXPECT_EQ(pred.changes, o.changes);
  EXPECT_EQ(o.absorbed, c);
  EXPECT_EQ(o.deleted, w);  // the boundary v3 end is the one removed
  EXPECT_EQ(o.boundaryVertex, -1);
  EXPECT_EQ(ed.Valence(c), 6);
  ExpectOthersUnchanged(m, before, o.changes);
  ir = IrregularOf(m);
  EXPECT_TRUE(ir.interior.empty());
  EXPECT_TRUE(ir.boundary.empty());
  ExpectValid(m);
}

// A 5-7 pair generated from a regular boundary vertex (leaving a boundary 5-7 pair), then
// absorbed again: the defects cancel and nothing irregular is left.
TEST(BoundaryOps, GeneratePairThenAbsorbPair) {
  TMesh m;
  test::HexPatch(m, 4);
  MeshEditor<TMesh> ed(m);
  BoundaryOperations<TMesh> bo(ed);
  const int b = At(m, 2, 2);
  VertexStar<TMesh> st = ed.Star(b);
  const int apex = ed.Index(st.neighbors[1]), oi = ed.Index(st.neighbors[2]), ob = ed.Index(st.neighbors[0]);
  const auto before = test::Valences(m);
  BoundaryOutcome pred = bo.PredictGeneratePair(b, 0);
  BoundaryOutcome g = bo.GeneratePair(b, 0);
  ASSERT_TRUE(g) << g.result.reason;
  EXPECT_EQ(pred.changes, g.changes);
  EXPECT_EQ(pred.v5, g.v5);
  EXPECT_EQ(pred.v7, g.v7);
  EXPECT_EQ(g.v5, apex);
  EXPECT_EQ(g.v7, oi);
  EXPECT_EQ(ed.Valence(g.v5), 5);
  EXPECT_EQ(ed.Valence(g.v7), 7);
  EXPECT_TRUE(ed.Adjacent(g.v5, g.v7));
  EXPECT_FALSE(ed.IsBoundary(g.v5) || ed.IsBoundary(g.v7));
  EXPECT_EQ(g.changes, (std::map<int, int>{{b, 3}, {apex, 5}, {oi, 7}, {ob, 5}}));
  ExpectOthersUnchanged(m, before, g.changes);
  Irregular ir = IrregularOf(m);
  std::vector<int> pair{g.v5, g.v7}, bpair{b, ob};
  std::sort(pair.begin(), pair.end());
  std::sort(bpair.begin(), bpair.end());
  EXPECT_EQ(ir.interior, pair);
  EXPECT_EQ(ir.boundary, bpair);
  EXPECT_EQ(g.boundaryIrregular.size(), 2u);
  ExpectValid(m);
  ed.Commit();

  const auto mid = test::Valences(m);
  BoundaryOutcome pa = bo.PredictAbsorbPair(g.v5, g.v7);
  BoundaryOutcome a = bo.AbsorbPair(g.v5, g.v7);
  ASSERT_TRUE(a) << a.result.reason;
  EXPECT_EQ(pa.changes, a.changes);
  EXPECT_EQ(ed.Valence(g.v5), 6);
  EXPECT_EQ(ed.Valence(g.v7), 6);
  EXPECT_EQ(a.boundaryVertex, -1);
  ExpectOthersUnchanged(m, mid, a.changes);
  ir = IrregularOf(m);
  EXPECT_TRUE(ir.interior.empty());
  EXPECT_TRUE(ir.boundary.empty());
  ExpectValid(m);
}

// The flattened corner's v3 steps along the boundary towards its neighbour (4, -1).
TEST(BoundaryOps, MoveBoundaryV3AlongTheBoundary) {
  TMesh m;
  const int c = FlattenedCorner(m);
  MeshEditor<TMesh> ed(m);
  BoundaryOperations<TMesh> bo(ed);
  VertexStar<TMesh> st = ed.Star(c);
  const int first = ed.Index(st.neighbors.front()), last = ed.Index(st.neighbors.back());
  const vcg::Point3f pFirst = m.vert[size_t(first)].P(), pC = m.vert[size_t(c)].P();
  const auto before = test::Valences(m);
  BoundaryOutcome pred = bo.PredictMoveAlongBoundary(c, 0);
  BoundaryOutcome o = bo.MoveAlongBoundary(c, 0);
  ASSERT_TRUE(o) << o.result.reason;
  EXPECT_EQ(pred.changes, o.changes);
  EXPECT_EQ(pred.boundaryVertex, o.boundaryVertex);
  EXPECT_EQ(o.deleted, c);
  EXPECT_EQ(ed.Valence(last), 4);
  ASSERT_GE(o.boundaryVertex, 0);
  EXPECT_EQ(ed.Valence(o.boundaryVertex), 3);
  EXPECT_TRUE(ed.IsBoundary(o.boundaryVertex));
  // it lies between the old corner and the neighbour it moved towards
  const vcg::Point3f q = m.vert[size_t(o.boundaryVertex)].P();
  EXPECT_LT((q - pFirst).Norm(), (pC - pFirst).Norm());
  ExpectOthersUnchanged(m, before, o.changes);
  Irregular ir = IrregularOf(m);
  EXPECT_TRUE(ir.interior.empty());
  EXPECT_EQ(ir.boundary, std::vector<int>{o.boundaryVertex});
  EXPECT_EQ(Summarize(m).vertices, 61);  // 3 r (r + 1) + 1: the vertex count is kept
  ExpectValid(m);
}

TEST(BoundaryOps, RefusalsLeaveTheMeshUnchanged) {
  TMesh m;
  test::HexPatch(m, 4);
  MeshEditor<TMesh> ed(m);
  BoundaryOperations<TMesh> bo(ed);
  auto snap = test::Snapshot(m);
  BoundaryOutcome r1 = bo.Absorb(At(m, 2, 1));  // an interior v6
  EXPECT_FALSE(r1);
  EXPECT_NE(r1.result.reason.find("v5 or v7"), std::string::npos) << r1.result.reason;
  BoundaryOutcome r2 = bo.GeneratePair(At(m, 4, 0), 0);  // a corner
  EXPECT_FALSE(r2);
  BoundaryOutcome r3 = bo.MoveAlongBoundary(At(m, 3, 1), 0);  // a regular side vertex
  EXPECT_FALSE(r3);
  BoundaryOutcome r4 = bo.AbsorbPair(At(m, 0, 0), At(m, 1, 0));
  EXPECT_FALSE(r4);
  EXPECT_EQ(test::Snapshot(m), snap);
  // an interior v5 away from the boundary
  TMesh t;
  test::Icosahedron(t);
  MeshEditor<TMesh> et(t);
  BoundaryOperations<TMesh> bt(et);
  auto st = test::Snapshot(t);
  BoundaryOutcome r5 = bt.Absorb(0);
  EXPECT_FALSE(r5);
  EXPECT_NE(r5.result.reason.find("not next to the boundary"), std::string::npos) << r5.result.reason;
  EXPECT_EQ(test::Snapshot(t), st);
}

// Random boundary operations on an annulus whose outer corners were made irregular by random
// boundary splits (fixed seed): Predict* says exactly what the operation then does, refusals
// change nothing, successes keep every invariant.
TEST(BoundaryOps, PredictionsAgreeOnRandomRequests) {
  TMesh m;
  test::HexPatchWithHole(m, 6, 2);
  MeshEditor<TMesh> ed(m);
  BoundaryOperations<TMesh> bo(ed);
  std::mt19937 rng(11);
  int applied = 0, refused = 0;
  for (int it = 0; it < 600; ++it) {
    int v = int(rng() % m.vert.size());
    if (!ed.IsLive(v)) continue;
    VertexStar<TMesh> s = ed.Star(v);
    const int kind = int(rng() % 6);
    const int side = int(rng() % 2);
    BoundaryOutcome pred, real;
    auto snap = test::Snapshot(m);
    if (kind == 0) {
      SeedBoundaryIrregularity(m, ed, rng, v);
      continue;
    }
    const int p7 = Neighbour7(ed, s);
    pred = BoundaryOp(bo, true, kind, v, p7, side);
    ASSERT_EQ(test::Snapshot(m), snap) << "a prediction changed the mesh";
    ASSERT_EQ(ed.journal().LoggedFaces() + ed.journal().LoggedVertices(), 0u) << "a prediction wrote the mesh";
    real = BoundaryOp(bo, false, kind, v, p7, side);
    ASSERT_EQ(pred.result.ok, real.result.ok) << "kind " << kind << ": " << pred.result.reason << " / "
                                              << real.result.reason;
    EXPECT_EQ(pred.result.reason, real.result.reason);
    EXPECT_EQ(pred.changes, real.changes);
    EXPECT_EQ(pred.boundaryVertex, real.boundaryVertex);
    if (real) {
      ++applied;
      Result inv = CheckInvariants(m);
      ASSERT_TRUE(inv.ok) << inv.reason << " after kind " << kind;
    } else {
      ++refused;
      EXPECT_FALSE(real.result.reason.empty());
      ASSERT_EQ(test::Snapshot(m), snap) << real.result.reason;
    }
    ed.Commit();
  }
  EXPECT_GT(applied, 5);
  std::printf("random boundary operations: applied %d, refused %d\n", applied, refused);
}

// ---------------------------------------------------------------- boundary 5-7 pairs
// (boundary_ops.h: MoveBoundaryPair, GenerateBoundaryPairs, EarSplit; docs/boundary_pair_move.svg)
namespace {

/// Lattice (axial) coordinates of every vertex of a fresh HexPatch, by id.
std::map<int, std::pair<int, int>> LatticeIds(TMesh& m, int radius) {
  std::map<int, std::pair<int, int>> r;
  for (int q = -radius; q <= radius; ++q)
    for (int s = -radius; s <= radius; ++s) {
      const int v = At(m, q, s);
      if (v >= 0) r[v] = {q, s};
    }
  return r;
}

bool AtLattice(TMesh& m, int v, int q, int r) {
  return v >= 0 && (m.vert[size_t(v)].P() - test::LatticePoint(q, r)).Norm() < 1e-4f;
}

/// The boundary vertex after `v` going away from `prev`.
int NextAlong(MeshEditor<TMesh>& ed, int v, int prev) {
  VertexStar<TMesh> st = ed.Star(v);
  const int f = ed.Index(st.neighbors.front()), l = ed.Index(st.neighbors.back());
  return f == prev ? l : f;
}

/// All live vertices irregular (by the boundary valence rule), with their valences.
std::map<int, int> IrregularMap(TMesh& m) {
  std::map<int, int> r;
  ValenceField<TMesh> vf = ComputeValences(m);
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD() && vf.IsIrregular(i)) r[int(i)] = vf.valence[i];
  return r;
}

}  // namespace

// A regular boundary vertex of a straight side becomes two boundary pairs of opposite sign
// (a one-row bump): n0 5, e 3, e' 3, nn 5; the vertex itself goes inside with valence 6.
TEST(BoundaryPairs, GenerateBoundaryPairsMakesABump) {
  TMesh m;
  test::HexPatch(m, 8);
  MeshEditor<TMesh> ed(m);
  BoundaryOperations<TMesh> bo(ed);
  const int b = At(m, 4, 4);  // on the side q + r = 8
  VertexStar<TMesh> st = ed.Star(b);
  const int n0 = ed.Index(st.neighbors.front()), nn = ed.Index(st.neighbors.back());
  const auto before = test::Valences(m);
  const auto snap = test::Snapshot(m);
  BoundaryPairOutcome pred = bo.PredictGenerateBoundaryPairs(b);
  EXPECT_EQ(test::Snapshot(m), snap);
  BoundaryPairOutcome g = bo.GenerateBoundaryPairs(b);
  ASSERT_TRUE(g) << g.result.reason;
  EXPECT_EQ(pred.changes, g.changes);
  EXPECT_EQ(pred.v3, g.v3);
  EXPECT_EQ(pred.other3, g.other3);
  ASSERT_EQ(g.created.size(), 2u);
  EXPECT_EQ(g.v5, nn);
  EXPECT_EQ(g.other5, n0);
  // the changes, vertex by vertex: b inside (6), the new vertices 3 and 3, n0 and nn 5
  EXPECT_EQ(g.changes, (std::map<int, int>{{b, 6}, {g.v3, 3}, {g.other3, 3}, {n0, 5}, {nn, 5}}));
  EXPECT_FALSE(ed.IsBoundary(b));
  EXPECT_TRUE(ed.IsBoundaryEdge(n0, g.other3));
  EXPECT_TRUE(ed.IsBoundaryEdge(g.other3, g.v3));
  EXPECT_TRUE(ed.IsBoundaryEdge(g.v3, nn));
  // n0 and nn keep their lattice points
  EXPECT_TRUE(AtLattice(m, n0, 3, 5) || AtLattice(m, n0, 5, 3));
  EXPECT_TRUE(AtLattice(m, nn, 3, 5) || AtLattice(m, nn, 5, 3));
  ExpectOthersUnchanged(m, before, g.changes);
  EXPECT_EQ(IrregularMap(m), (std::map<int, int>{{g.v3, 3}, {g.other3, 3}, {n0, 5}, {nn, 5}}));
  EXPECT_EQ(Summarize(m).vertices, 3 * 8 * 9 + 1 + 2);
  ExpectValid(m);
}

// The pair (e' 3, nn 5) walks k steps towards its 5 along the straight side and back: each
// step is one ear split (E) forwards, one collapse (C) backwards. The boundary vertices stay
// on lattice points: after k steps the 3 sits at the lattice point of the k-th side vertex
// beyond nn's start (a new vertex), the 5 is the (k+1)-th side vertex itself; the side
// vertices passed over are inside with valence 6. Back again, the pair is where it started.
TEST(BoundaryPairs, PairMovesAlongTheBoundaryTowardsItsFiveAndBack) {
  for (int k : {1, 2, 3}) {
    SCOPED_TRACE(testing::Message() << "k = " << k);
    TMesh m;
    test::HexPatch(m, 10);
    const auto lattice = LatticeIds(m, 10);
    MeshEditor<TMesh> ed(m);
    BoundaryOperations<TMesh> bo(ed);
    const int b = At(m, 5, 5);
    BoundaryPairOutcome g = bo.GenerateBoundaryPairs(b);
    ASSERT_TRUE(g) << g.result.reason;
    ed.Commit();
    // the side beyond nn: s[0] = nn, s[1], ... (original vertices, lattice points)
    std::vector<int> side{g.v5};
    for (int prev = g.v3; side.size() < size_t(k) + 2;) {
      const int nx = NextAlong(ed, side.back(), prev);
      prev = side.back();
      side.push_back(nx);
    }
    const auto irr0 = IrregularMap(m);
    const auto before = test::Valences(m);
    const auto snap = test::Snapshot(m);
    BoundaryPairOutcome pred = bo.PredictMoveBoundaryPair(g.v3, g.v5, BoundaryPairDirection::TowardFive, k);
    EXPECT_EQ(test::Snapshot(m), snap);
    BoundaryPairOutcome o = bo.MoveBoundaryPair(g.v3, g.v5, BoundaryPairDirection::TowardFive, k);
    ASSERT_TRUE(o) << o.result.reason;
    EXPECT_EQ(pred.changes, o.changes);
    EXPECT_EQ(pred.v3, o.v3);
    EXPECT_EQ(pred.v5, o.v5);
    EXPECT_EQ(o.steps, k);
    EXPECT_FALSE(o.cancelled);
    ASSERT_EQ(o.created.size(), size_t(k));
    // where the pair is: the 3 at the lattice point of side[k - 1], the 5 is side[k]
    const auto pk = lattice.at(side[size_t(k) - 1]);
    EXPECT_TRUE(AtLattice(m, o.v3, pk.first, pk.second));
    EXPECT_EQ(o.v3, o.created.back());
    EXPECT_EQ(o.v5, side[size_t(k)]);
    // every touched vertex: the old 3 back to 4, side[0..k-1] inside with 6, the new
    // vertices on their lattice points with 4 (the last: 3), side[k] 5
    std::map<int, int> expect{{g.v3, 4}};
    for (int i = 0; i < k; ++i) {
      expect[side[size_t(i)]] = 6;
      expect[o.created[size_t(i)]] = i + 1 == k ? 3 : 4;
      const auto pi = lattice.at(side[size_t(i)]);
      EXPECT_TRUE(AtLattice(m, o.created[size_t(i)], pi.first, pi.second)) << "created vertex " << i;
      EXPECT_FALSE(ed.IsBoundary(side[size_t(i)]));
    }
    expect[side[size_t(k)]] = 5;
    EXPECT_EQ(o.changes, expect);
    ExpectOthersUnchanged(m, before, o.changes);
    std::map<int, int> irr = irr0;
    irr.erase(g.v3);
    irr.erase(g.v5);
    irr[o.v3] = 3;
    irr[o.v5] = 5;
    EXPECT_EQ(IrregularMap(m), irr);
    ExpectValid(m);
    ed.Commit();

    // back: k collapses (C); the pair ends on (created[0]'s predecessor = g.v3, created[0])
    BoundaryPairOutcome back = bo.MoveBoundaryPair(o.v3, o.v5, BoundaryPairDirection::TowardThree, k);
    ASSERT_TRUE(back) << back.result.reason;
    EXPECT_EQ(back.v3, g.v3);
    EXPECT_EQ(back.v5, o.created[0]);
    const auto p0 = lattice.at(side[0]);
    EXPECT_TRUE(AtLattice(m, back.v5, p0.first, p0.second));
    std::vector<int> deleted(side.begin(), side.begin() + k);
    std::reverse(deleted.begin(), deleted.end());
    EXPECT_EQ(back.deleted, deleted);  // the vertices that went inside are collapsed again
    irr = irr0;
    irr.erase(g.v5);
    irr[back.v5] = 5;
    EXPECT_EQ(IrregularMap(m), irr);
    EXPECT_EQ(Summarize(m).vertices, 3 * 10 * 11 + 1 + 2);
    ExpectValid(m);
  }
}

// Bump: the pair (e' 3, nn 5) steps once towards its 5 and then twice towards its 3: the
// second step meets the opposite pair (n0 5, e 3) and both cancel: nothing irregular is left.
TEST(BoundaryPairs, OppositePairsCancelInABump) {
  TMesh m;
  test::HexPatch(m, 8);
  MeshEditor<TMesh> ed(m);
  BoundaryOperations<TMesh> bo(ed);
  BoundaryPairOutcome g = bo.GenerateBoundaryPairs(At(m, 4, 4));
  ASSERT_TRUE(g) << g.result.reason;
  BoundaryPairOutcome f = bo.MoveBoundaryPair(g.v3, g.v5, BoundaryPairDirection::TowardFive, 1);
  ASSERT_TRUE(f) << f.result.reason;
  ed.Commit();
  const auto before = test::Valences(m);
  BoundaryPairOutcome pred = bo.PredictMoveBoundaryPair(f.v3, f.v5, BoundaryPairDirection::TowardThree, 5);
  BoundaryPairOutcome o = bo.MoveBoundaryPair(f.v3, f.v5, BoundaryPairDirection::TowardThree, 5);
  ASSERT_TRUE(o) << o.result.reason;
  EXPECT_EQ(pred.changes, o.changes);
  EXPECT_TRUE(o.cancelled);
  EXPECT_EQ(o.steps, 2);  // one step, then the cancellation
  EXPECT_EQ(o.survivor, -1);
  EXPECT_EQ(o.v3, -1);
  EXPECT_TRUE(o.boundaryIrregular.empty());
  ExpectOthersUnchanged(m, before, o.changes);
  EXPECT_TRUE(IrregularMap(m).empty());
  EXPECT_EQ(Summarize(m).vertices, 3 * 8 * 9 + 1);  // the bump's vertices are gone again
  ExpectValid(m);
}

// Notch: two bumps three side vertices apart; the inner pairs face each other (3 5 .. 5 3).
// The left one moves towards its 5 until it meets the right one: two ear splits and a
// boundary-edge collapse cancel both; the outer pairs stay where they were.
TEST(BoundaryPairs, OppositePairsCancelInANotch) {
  TMesh m;
  test::HexPatch(m, 10);
  MeshEditor<TMesh> ed(m);
  BoundaryOperations<TMesh> bo(ed);
  // side q + r = 10; bumps at (7, 3) and (3, 7)
  BoundaryPairOutcome g1 = bo.GenerateBoundaryPairs(At(m, 7, 3));
  ASSERT_TRUE(g1) << g1.result.reason;
  BoundaryPairOutcome g2 = bo.GenerateBoundaryPairs(At(m, 3, 7));
  ASSERT_TRUE(g2) << g2.result.reason;
  ed.Commit();
  // the inner pairs: the one of g1 and the one of g2 whose 5s are closest
  auto dist = [&](int a, int b) { return (m.vert[size_t(a)].P() - m.vert[size_t(b)].P()).Norm(); };
  int l3 = g1.v3, l5 = g1.v5, o3 = g1.other3, o5 = g1.other5;
  if (dist(g1.other5, g2.v5) + dist(g1.other5, g2.other5) < dist(g1.v5, g2.v5) + dist(g1.v5, g2.other5))
    std::swap(l3, o3), std::swap(l5, o5);
  int r3 = g2.v3, r5 = g2.v5, s3 = g2.other3, s5 = g2.other5;
  if (dist(g2.other5, l5) < dist(g2.v5, l5)) std::swap(r3, s3), std::swap(r5, s5);
  const auto before = test::Valences(m);
  BoundaryPairOutcome pred = bo.PredictMoveBoundaryPair(l3, l5, BoundaryPairDirection::TowardFive, 10);
  BoundaryPairOutcome o = bo.MoveBoundaryPair(l3, l5, BoundaryPairDirection::TowardFive, 10);
  ASSERT_TRUE(o) << o.result.reason;
  EXPECT_EQ(pred.changes, o.changes);
  EXPECT_TRUE(o.cancelled);
  EXPECT_EQ(o.survivor, -1);
  EXPECT_EQ(o.steps, 2);  // (7,3)-bump's 5 at (6,4), the other's 5 at (4,6): one step, then the notch
  ExpectOthersUnchanged(m, before, o.changes);
  // the outer pairs are all that is left
  EXPECT_EQ(IrregularMap(m), (std::map<int, int>{{o3, 3}, {o5, 5}, {s3, 3}, {s5, 5}}));
  ExpectValid(m);
}

// A pair meeting a single boundary irregular vertex of opposite sign cancels against it: the
// flattened corner's 3 absorbs the pair's 5 step, one boundary 3 is left (one step closer).
TEST(BoundaryPairs, PairCancelsAgainstASingleBoundaryThree) {
  TMesh m;
  const int c = FlattenedCorner(m);  // HexPatch(4), (4, 0) a boundary 3 on a smooth stretch
  MeshEditor<TMesh> ed(m);
  BoundaryOperations<TMesh> bo(ed);
  // a bump two side vertices from the corner, on the side towards (4, -4)... or (0, 4)
  const int b = At(m, 4, -2);
  ASSERT_GE(b, 0);
  BoundaryPairOutcome g = bo.GenerateBoundaryPairs(b);
  ASSERT_TRUE(g) << g.result.reason;
  ed.Commit();
  // the pair whose 5 lies towards the corner
  auto dist = [&](int a, int e) { return (m.vert[size_t(a)].P() - m.vert[size_t(e)].P()).Norm(); };
  const bool firstNearer = dist(g.other5, c) < dist(g.v5, c);
  const int p3 = firstNearer ? g.other3 : g.v3, p5 = firstNearer ? g.other5 : g.v5;
  const int k3 = firstNearer ? g.v3 : g.other3, k5 = firstNearer ? g.v5 : g.other5;
  ASSERT_EQ(NextAlong(ed, p5, p3), c);
  const auto before = test::Valences(m);
  BoundaryPairOutcome o = bo.MoveBoundaryPair(p3, p5, BoundaryPairDirection::TowardFive, 3);
  ASSERT_TRUE(o) << o.result.reason;
  EXPECT_TRUE(o.cancelled);
  EXPECT_EQ(o.steps, 1);
  ASSERT_EQ(o.created.size(), 1u);
  EXPECT_EQ(o.survivor, o.created[0]);
  EXPECT_EQ(o.changes, (std::map<int, int>{{p3, 4}, {p5, 6}, {o.survivor, 3}, {c, 4}}));
  ExpectOthersUnchanged(m, before, o.changes);
  EXPECT_EQ(IrregularMap(m), (std::map<int, int>{{k3, 3}, {k5, 5}, {o.survivor, 3}}));
  ExpectValid(m);
}

TEST(BoundaryPairs, RefusalsSayWhyAndChangeNothing) {
  TMesh m;
  test::HexPatch(m, 6);
  MeshEditor<TMesh> ed(m);
  BoundaryOperations<TMesh> bo(ed);
  const auto snap = test::Snapshot(m);
  BoundaryPairOutcome r1 = bo.MoveBoundaryPair(At(m, 3, 3), At(m, 2, 4), BoundaryPairDirection::TowardThree, 1);
  EXPECT_FALSE(r1);
  EXPECT_NE(r1.result.reason.find("valence 3 and 5"), std::string::npos) << r1.result.reason;
  BoundaryPairOutcome r2 = bo.GenerateBoundaryPairs(At(m, 6, 0));  // a corner
  EXPECT_FALSE(r2);
  EXPECT_NE(r2.result.reason.find("corner"), std::string::npos) << r2.result.reason;
  BoundaryPairOutcome r3 = bo.GenerateBoundaryPairs(At(m, 1, 1));  // interior
  EXPECT_FALSE(r3);
  EXPECT_EQ(test::Snapshot(m), snap);
  // a pair walking into a corner: (4, 2)'s bump, the pair on the side of (6, 0)
  BoundaryPairOutcome g = bo.GenerateBoundaryPairs(At(m, 4, 2));
  ASSERT_TRUE(g) << g.result.reason;
  ed.Commit();
  const int corner = At(m, 6, 0);
  const bool firstNearer = (m.vert[size_t(g.other5)].P() - m.vert[size_t(corner)].P()).Norm() <
                           (m.vert[size_t(g.v5)].P() - m.vert[size_t(corner)].P()).Norm();
  const int p3 = firstNearer ? g.other3 : g.v3, p5 = firstNearer ? g.other5 : g.v5;
  ASSERT_EQ(NextAlong(ed, p5, p3), corner);
  const auto snap2 = test::Snapshot(m);
  BoundaryPairOutcome o = bo.MoveBoundaryPair(p3, p5, BoundaryPairDirection::TowardFive, 1);
  EXPECT_FALSE(o);
  EXPECT_NE(o.result.reason.find("corner"), std::string::npos) << o.result.reason;
  EXPECT_EQ(test::Snapshot(m), snap2);
}

// Random boundary pair requests on an annulus with bumps (fixed seed): the dry run says
// exactly what the operation then does; refusals change nothing; successes keep invariants.
TEST(BoundaryPairs, PredictionsAgreeOnRandomRequests) {
  TMesh m;
  test::HexPatchWithHole(m, 7, 2);
  MeshEditor<TMesh> ed(m);
  BoundaryOperations<TMesh> bo(ed);
  std::mt19937 rng(5);
  int applied = 0, refused = 0, cancelled = 0;
  for (int it = 0; it < 400; ++it) {
    const int v = int(rng() % m.vert.size());
    if (!ed.IsLive(v) || !ed.IsBoundary(v)) continue;
    const auto snap = test::Snapshot(m);
    BoundaryPairOutcome pred, real;
    if (rng() % 3 == 0) {
      pred = bo.PredictGenerateBoundaryPairs(v);
      ASSERT_EQ(test::Snapshot(m), snap);
      ASSERT_EQ(ed.journal().LoggedFaces() + ed.journal().LoggedVertices(), 0u);
      real = bo.GenerateBoundaryPairs(v);
    } else {
      // a pair through v: v and a boundary neighbour
      VertexStar<TMesh> st = ed.Star(v);
      const int w = ed.Index(rng() % 2 ? st.neighbors.front() : st.neighbors.back());
      const auto dir = rng() % 2 ? BoundaryPairDirection::TowardThree : BoundaryPairDirection::TowardFive;
      const int steps = 1 + int(rng() % 4);
      pred = bo.PredictMoveBoundaryPair(v, w, dir, steps);
      ASSERT_EQ(test::Snapshot(m), snap);
      ASSERT_EQ(ed.journal().LoggedFaces() + ed.journal().LoggedVertices(), 0u);
      real = bo.MoveBoundaryPair(v, w, dir, steps);
    }
    ASSERT_EQ(pred.result.ok, real.result.ok) << pred.result.reason << " / " << real.result.reason;
    EXPECT_EQ(pred.result.reason, real.result.reason);
    EXPECT_EQ(pred.changes, real.changes);
    EXPECT_EQ(pred.v3, real.v3);
    EXPECT_EQ(pred.v5, real.v5);
    EXPECT_EQ(pred.cancelled, real.cancelled);
    EXPECT_EQ(pred.survivor, real.survivor);
    EXPECT_EQ(pred.created, real.created);
    EXPECT_EQ(pred.deleted, real.deleted);
    EXPECT_EQ(pred.steps, real.steps);
    if (real) {
      ++applied;
      cancelled += real.cancelled;
      Result inv = CheckInvariants(m);
      ASSERT_TRUE(inv.ok) << inv.reason;
      ASSERT_TRUE(Summarize(m).GaussBonnetHolds());
    } else {
      ++refused;
      EXPECT_FALSE(real.result.reason.empty());
      ASSERT_EQ(test::Snapshot(m), snap) << real.result.reason;
    }
    ed.Commit();
  }
  EXPECT_GT(applied, 10);
  std::printf("random boundary pair requests: applied %d (cancelled %d), refused %d\n", applied, cancelled, refused);
}

// What MoveAlongBoundary is, by connectivity: its collapse (A) and split (B) give back the
// same triangulation with the v3 renamed (the new vertex takes the deleted one's place, or
// the neighbour it moved towards takes it and the new vertex the neighbour's). Only the
// positions change: the v3 slides along the boundary polyline. A single boundary irregular
// vertex cannot move through the lattice alone (as a single v5 cannot inside, sec. 5); a
// boundary pair can (MoveBoundaryPair).
TEST(BoundaryOps, MoveAlongBoundaryIsARenamingOfTheConnectivity) {
  TMesh m;
  const int c = FlattenedCorner(m);
  MeshEditor<TMesh> ed(m);
  BoundaryOperations<TMesh> bo(ed);
  VertexStar<TMesh> st = ed.Star(c);
  const int p = ed.Index(st.neighbors.front());
  auto faces = [&](std::map<int, int> rename) {
    std::set<std::vector<int>> fs;
    for (auto& f : m.face) {
      if (f.IsD()) continue;
      std::vector<int> v;
      for (int z = 0; z < 3; ++z) {
        const int i = int(vcg::tri::Index(m, f.V(z)));
        v.push_back(rename.count(i) ? rename[i] : i);
      }
      std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
      fs.insert(v);
    }
    return fs;
  };
  const auto f0 = faces({});
  BoundaryOutcome o = bo.MoveAlongBoundary(c, 0);
  ASSERT_TRUE(o) << o.result.reason;
  const int x = o.created;
  EXPECT_TRUE(faces({{x, c}}) == f0 || faces({{p, c}, {x, p}}) == f0);
}

// An interior 5-7 pair next to the boundary moves parallel to it with the atomic pair move
// (fig. 6, atomic_ops.h): the pair GeneratePair leaves in the first row (q + r = 7 of
// HexPatch(8); 5 at (3, 4), 7 at (4, 3), its edge along the row) moves one lattice step along
// the row by a vertex split of the 7: the 7 lands exactly on (5, 2), the 5 is the split vertex
// (moved a share of the way, relaxation off: within half an edge of (4, 3)); the old
// 5 is regular again, the boundary pair it came from and every other valence stay. (The step
// the other way along the row, and the flips there, are refused by atomic_ops.h: "the
// operation would touch boundary vertex ..."; FI_DEBUG_B13=1 prints every direction.)
TEST(BoundaryPairs, InteriorPairNextToTheBoundaryMovesParallelToIt) {
  TMesh m;
  test::HexPatch(m, 8);
  MeshEditor<TMesh> ed(m);
  BoundaryOperations<TMesh> bo(ed);
  AtomicOperations<TMesh> ops(ed);
  BoundaryOutcome g = bo.GeneratePair(At(m, 4, 4), 0);
  ASSERT_TRUE(g) << g.result.reason;
  ed.Commit();
  const auto lattice = LatticeIds(m, 8);
  ASSERT_TRUE(AtLattice(m, g.v5, 3, 4));
  ASSERT_TRUE(AtLattice(m, g.v7, 4, 3));
  const auto irr0 = IrregularMap(m);
  int along = 0;
  for (int dir = 0; dir < 6; ++dir) {
    auto cp = ed.Mark();
    AtomicOutcome o = ops.MovePair57(g.v5, g.v7, dir);
    if (getenv("FI_DEBUG_B13"))
      std::printf("dir %d: %s\n", dir, o ? o.description.c_str() : o.result.reason.c_str());
    if (o && AtLattice(m, o.pair7, 5, 2)) {
      ++along;
      EXPECT_EQ(ed.Valence(o.pair7), 7);
      EXPECT_EQ(ed.Valence(o.pair5), 5);
      EXPECT_TRUE(ed.Adjacent(o.pair5, o.pair7));
      ASSERT_EQ(o.created.size(), 1u);  // the split's other half: regular
      EXPECT_EQ(ed.Valence(o.created[0]), 6);
      EXPECT_EQ(o.pair5, g.v7);  // the split vertex keeps the 5's half
      EXPECT_LT((m.vert[size_t(o.pair5)].P() - test::LatticePoint(4, 3)).Norm(), 0.5f);
      EXPECT_FALSE(ed.IsBoundary(o.pair5) || ed.IsBoundary(o.pair7));
      EXPECT_EQ(ed.Valence(g.v5), 6);
      std::map<int, int> expect = irr0;
      expect.erase(g.v5);
      expect.erase(g.v7);
      expect[o.pair5] = 5;
      expect[o.pair7] = 7;
      EXPECT_EQ(IrregularMap(m), expect);
      ExpectValid(m);
    }
    ed.RollbackTo(cp);
  }
  EXPECT_EQ(along, 1) << "no atomic move takes the pair one step along the row";
}

// ---------------------------------------------------------------- dry runs on a scratch copy
// (boundary_ops.h "Dry runs", scratch_region.h; issue 13, item 3)
namespace {

/// Every named field of two outcomes, description and exact verdict text included.
void ExpectSameOutcome(const BoundaryOutcome& p, const BoundaryOutcome& r, const std::string& what) {
  EXPECT_EQ(p.result.ok, r.result.ok) << what;
  EXPECT_EQ(p.result.reason, r.result.reason) << what;
  EXPECT_EQ(p.description, r.description) << what;
  EXPECT_EQ(p.absorbed, r.absorbed) << what;
  EXPECT_EQ(p.boundaryVertex, r.boundaryVertex) << what;
  EXPECT_EQ(p.boundaryIrregular, r.boundaryIrregular) << what;
  EXPECT_EQ(p.v5, r.v5) << what;
  EXPECT_EQ(p.v7, r.v7) << what;
  EXPECT_EQ(p.created, r.created) << what;
  EXPECT_EQ(p.deleted, r.deleted) << what;
  EXPECT_EQ(p.changes, r.changes) << what;
}
void ExpectSameOutcome(const BoundaryPairOutcome& p, const BoundaryPairOutcome& r, const std::string& what) {
  EXPECT_EQ(p.result.ok, r.result.ok) << what;
  EXPECT_EQ(p.result.reason, r.result.reason) << what;
  EXPECT_EQ(p.description, r.description) << what;
  EXPECT_EQ(p.v3, r.v3) << what;
  EXPECT_EQ(p.v5, r.v5) << what;
  EXPECT_EQ(p.other3, r.other3) << what;
  EXPECT_EQ(p.other5, r.other5) << what;
  EXPECT_EQ(p.survivor, r.survivor) << what;
  EXPECT_EQ(p.cancelled, r.cancelled) << what;
  EXPECT_EQ(p.steps, r.steps) << what;
  EXPECT_EQ(p.created, r.created) << what;
  EXPECT_EQ(p.deleted, r.deleted) << what;
  EXPECT_EQ(p.changes, r.changes) << what;
  EXPECT_EQ(p.boundaryIrregular, r.boundaryIrregular) << what;
}

}  // namespace

// A prediction only reads the user's mesh: after a fresh Commit the editor's journal logs
// nothing and the mesh is bit-identical (positions, flags, FF, VF); and what it says is, field
// by field (reason and description texts too, in the user's ids), what the operation then
// does. Random requests of all six boundary operations on an annulus whose boundary is made
// irregular as it goes (fixed seed).
TEST(BoundaryPredictions, ReadTheMeshOnlyAndAgreeFieldByField) {
  TMesh m;
  test::HexPatchWithHole(m, 7, 2);
  MeshEditor<TMesh> ed(m);
  BoundaryOperations<TMesh> bo(ed);
  std::mt19937 rng(23);
  int applied = 0, refused = 0, exact = 0, predicted = 0;
  for (int it = 0; it < 700; ++it) {
    const int v = int(rng() % m.vert.size());
    if (!ed.IsLive(v)) continue;
    VertexStar<TMesh> s = ed.Star(v);
    const int kind = int(rng() % 8);
    const int side = int(rng() % 2);
    if (kind == 0) {
      SeedBoundaryIrregularity(m, ed, rng, v);
      continue;
    }
    const int p7 = Neighbour7(ed, s);
    const int w = s.boundary ? ed.Index(side ? s.neighbors.front() : s.neighbors.back()) : -1;
    const auto dir = rng() % 2 ? BoundaryPairDirection::TowardThree : BoundaryPairDirection::TowardFive;
    const int steps = int(rng() % 5);  // 0 is refused
    ed.Commit();
    const auto snap = test::Snapshot(m);
    const std::string what = "request " + std::to_string(it) + " kind " + std::to_string(kind) + " at " +
                             std::to_string(v);
    bool ok = false, ex = false;
    auto noWrite = [&] {
      ASSERT_EQ(ed.journal().LoggedFaces(), 0u) << what;
      ASSERT_EQ(ed.journal().LoggedVertices(), 0u) << what;
      ASSERT_EQ(test::Snapshot(m), snap) << what;
    };
    if (kind <= 4) {
      const BoundaryOutcome pred = BoundaryOp(bo, true, kind, v, p7, side);
      noWrite();
      const BoundaryOutcome real = BoundaryOp(bo, false, kind, v, p7, side);
      ExpectSameOutcome(pred, real, what);
      ok = bool(real), ex = pred.exact;
    } else {
      BoundaryPairOutcome pred, real;
      if (kind == 5) {
        pred = bo.PredictGenerateBoundaryPairs(v);
        noWrite();
        real = bo.GenerateBoundaryPairs(v);
      } else {
        pred = bo.PredictMoveBoundaryPair(v, w, dir, steps);
        noWrite();
        real = bo.MoveBoundaryPair(v, w, dir, steps);
      }
      ExpectSameOutcome(pred, real, what);
      ok = bool(real), ex = pred.exact;
    }
    ++predicted;
    exact += ex;
    if (ok) {
      ++applied;
      Result inv = CheckInvariants(m);
      ASSERT_TRUE(inv.ok) << inv.reason << " after " << what;
    } else {
      ++refused;
      ASSERT_EQ(test::Snapshot(m), snap) << what;
    }
    ed.Commit();
  }
  EXPECT_GT(applied, 20);
  EXPECT_GT(refused, 20);
  // every request here stays far from the cut border: each prediction is exact
  EXPECT_EQ(exact, predicted);
  std::printf("scratch predictions: %d (exact %d), applied %d, refused %d\n", predicted, exact, applied, refused);
}

// ScratchRegion (scratch_region.h) on its own: ids map both ways, created vertices map after
// the user's last vertex, placeholders keep every live scratch id >= pad, and BackText renames
// exactly the numbers that are scratch vertex ids.
TEST(BoundaryPredictions, ScratchRegionMapsIdsBothWays) {
  TMesh m;
  test::HexPatch(m, 6);
  const int c = At(m, 3, 3);
  ScratchRegion<TMesh> r;
  r.Extract(m, {c}, 1, 1, 1000);
  EXPECT_EQ(r.pad, 1000);
  EXPECT_EQ(r.userSize, int(m.vert.size()));
  // the 1-ring's faces: its 2-ring's vertices, in the user's order
  const std::vector<int> ring2 = KRing(m, std::vector<int>{c}, 2);
  EXPECT_EQ(r.orig, ring2);
  EXPECT_EQ(r.n0, 1000 + int(ring2.size()));
  for (int u : ring2) {
    const int sx = r.ToScratch(u);
    ASSERT_GE(sx, 1000);
    EXPECT_EQ(r.Back(sx), u);
    EXPECT_FALSE(r.mesh.vert[size_t(sx)].IsD());
    EXPECT_EQ(r.mesh.vert[size_t(sx)].P(), m.vert[size_t(u)].P());
  }
  for (int i = 0; i < 1000; ++i) ASSERT_TRUE(r.mesh.vert[size_t(i)].IsD());
  EXPECT_EQ(r.ToScratch(At(m, 0, 0)), -1);
  EXPECT_EQ(r.Back(r.n0 + 2), int(m.vert.size()) + 2);
  // the 1-ring's whole stars were copied: same valence, same side, same star order
  for (int u : KRing(m, std::vector<int>{c}, 1)) {
    VertexStar<TMesh> us = StarOf<TMesh>(&m.vert[size_t(u)]);
    VertexStar<TMesh> ss = StarOf<TMesh>(&r.mesh.vert[size_t(r.ToScratch(u))]);
    EXPECT_EQ(ss.Valence(), us.Valence()) << u;
    EXPECT_EQ(ss.boundary, us.boundary) << u;
    for (size_t k = 0; k < us.neighbors.size() && k < ss.neighbors.size(); ++k)
      EXPECT_EQ(r.Back(int(vcg::tri::Index(r.mesh, ss.neighbors[k]))), int(vcg::tri::Index(m, us.neighbors[k])));
  }
  EXPECT_FALSE(r.guard.empty());  // the cut border (2-ring) and its margin
  vcg::tri::Allocator<TMesh>::AddVertices(r.mesh, 1);  // a vertex a run would create
  const int sc = r.ToScratch(c);
  EXPECT_EQ(r.BackText("vertex " + std::to_string(sc) + " has valence 6, step 3 of 999"),
            "vertex " + std::to_string(c) + " has valence 6, step 3 of 999");
  EXPECT_EQ(r.BackText("edge (" + std::to_string(sc) + ", " + std::to_string(r.n0) + ")"),
            "edge (" + std::to_string(c) + ", " + std::to_string(m.vert.size()) + ")");
}

// With no spare rings (scratchRings 0, a margin of 1) the first scratch often cuts through
// what the operation reads: the runs must grow until two radii agree, and a prediction that
// says exact must then agree with the operation field by field (one that is not exact may
// differ; it is counted). Pair moves of several steps on the annulus (fixed seed).
TEST(BoundaryPredictions, TightRegionGrowsAndStaysHonest) {
  TMesh m;
  test::HexPatchWithHole(m, 7, 2);
  MeshEditor<TMesh> ed(m);
  BoundaryOperations<TMesh> bo(ed);
  bo.scratchRings = 0;
  bo.scratchMargin = 1;
  std::mt19937 rng(31);
  int exact = 0, inexact = 0, applied = 0;
  for (int it = 0; it < 400; ++it) {
    const int v = int(rng() % m.vert.size());
    if (!ed.IsLive(v) || !ed.IsBoundary(v)) continue;
    VertexStar<TMesh> st = ed.Star(v);
    BoundaryPairOutcome pred, real;
    const auto snap = test::Snapshot(m);
    if (rng() % 3 == 0) {
      pred = bo.PredictGenerateBoundaryPairs(v);
      ASSERT_EQ(test::Snapshot(m), snap);
      real = bo.GenerateBoundaryPairs(v);
    } else {
      const int w = ed.Index(rng() % 2 ? st.neighbors.front() : st.neighbors.back());
      const auto dir = rng() % 2 ? BoundaryPairDirection::TowardThree : BoundaryPairDirection::TowardFive;
      const int steps = 1 + int(rng() % 6);
      pred = bo.PredictMoveBoundaryPair(v, w, dir, steps);
      ASSERT_EQ(test::Snapshot(m), snap);
      real = bo.MoveBoundaryPair(v, w, dir, steps);
    }
    ASSERT_EQ(ed.journal().LoggedFaces() + ed.journal().LoggedVertices() > 0, bool(real));
    if (pred.exact) {
      ++exact;
      ExpectSameOutcome(pred, real, "request " + std::to_string(it));
    } else {
      ++inexact;
    }
    applied += bool(real);
    if (!real) ASSERT_EQ(test::Snapshot(m), snap);
    ed.Commit();
  }
  EXPECT_GT(applied, 10);
  EXPECT_GT(exact, 50);
  std::printf("tight scratch: %d exact, %d inexact, %d applied\n", exact, inexact, applied);
}
