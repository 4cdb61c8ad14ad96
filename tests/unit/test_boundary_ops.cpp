// Boundary operations (boundary_ops.h): an interior v5 or v7 next to the boundary absorbed
// into it, a 5-7 pair generated from the boundary and absorbed again, a boundary v3 moved
// along the boundary; refusals leave the mesh unchanged; Predict* agrees with the operation
// on random requests near boundaries. Vertices are named by lattice coordinates or by the
// ids the outcome names; every touched valence and the untouched rest are checked.
#include <gtest/gtest.h>

#include <random>

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
      // seed irregularity: a boundary split or a boundary-edge collapse
      if (!s.boundary) continue;
      const int a = ed.Index(s.neighbors[size_t(rng() % s.neighbors.size())]);
      Result r = rng() % 2 ? ed.SplitBoundary(v, a) : ed.Collapse(v, a);
      if (r) ExpectValid(m);
      ed.Commit();
      continue;
    }
    int p7 = -1;
    for (auto* n : s.neighbors)
      if (ed.Valence(ed.Index(n)) == 7) p7 = ed.Index(n);
    switch (kind) {
      case 1: pred = bo.PredictAbsorb(v); break;
      case 2: pred = bo.PredictAbsorbPair(v, p7); break;
      case 3: pred = bo.PredictMoveAlongBoundary(v, side); break;
      default: pred = bo.PredictGeneratePair(v, side); break;
    }
    ASSERT_EQ(test::Snapshot(m), snap) << "a prediction changed the mesh";
    switch (kind) {
      case 1: real = bo.Absorb(v); break;
      case 2: real = bo.AbsorbPair(v, p7); break;
      case 3: real = bo.MoveAlongBoundary(v, side); break;
      default: real = bo.GeneratePair(v, side); break;
    }
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
