// Unit tests of vcg_ext/irregular/composite_ops.h (paper sec. 6.3, 7): exact outcomes on
// constructed meshes; refusals leave the mesh identical.
#include <gtest/gtest.h>

#include <vcg_ext/irregular/composite_ops.h>
#include <vcg_ext/irregular/mesh_checks.h>

#include "test_mesh.h"
#include "test_util.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {
std::multiset<int> IrregularValences(TMesh& m) {
  std::multiset<int> r;
  auto vf = ComputeValences(m);
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD() && vf.IsIrregular(i)) r.insert(vf.valence[i]);
  return r;
}
int FirstWithValence(TMesh& m, int d) {
  auto vf = ComputeValences(m);
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD() && vf.valence[i] == d) return int(i);
  return -1;
}
}  // namespace

TEST(Composite, TypeSplitV8IntoTwoV7AndAggregateBack) {
  TMesh m;
  test::RegularTorus(m, 30, 30);
  SurfaceProjector original(m);
  MeshEditor<TMesh> ed(m);
  CompositeOperations<TMesh> co(ed, &original);
  const int c = 15 * 30 + 15;
  const int x = ed.Index(ed.Star(c).neighbors[0]);
  ASSERT_TRUE(ed.Collapse(x, c).ok);  // c: 6 + 6 - 4 = 8, two v5 beside it
  ASSERT_EQ(IrregularValences(m), (std::multiset<int>{5, 5, 8}));
  CompositeOutcome r = co.ReduceTo57(c);
  ASSERT_TRUE(r) << r.result.reason;
  EXPECT_EQ(IrregularValences(m), (std::multiset<int>{5, 5, 7, 7}));
  ASSERT_EQ(r.irregular.size(), 2u);
  for (int v : r.irregular) EXPECT_EQ(ed.Valence(v), 7);
  ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
  CompositeOutcome a = co.Aggregate(r.irregular);
  ASSERT_TRUE(a) << a.result.reason;
  EXPECT_EQ(IrregularValences(m), (std::multiset<int>{5, 5, 8}));
  ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
}

TEST(Composite, TypeSplitV9IntoThreeV7) {
  TMesh m;
  test::RegularTorus(m, 30, 30);
  SurfaceProjector original(m);
  MeshEditor<TMesh> ed(m);
  CompositeOperations<TMesh> co(ed, &original);
  const int c = 15 * 30 + 15;
  int x = ed.Index(ed.Star(c).neighbors[0]);
  ASSERT_TRUE(ed.Collapse(x, c).ok);  // v8
  VertexStar<TMesh> s = ed.Star(c);
  // raise to 9 with a flip of a link edge whose ends are regular
  bool raised = false;
  for (size_t i = 0; i < s.neighbors.size() && !raised; ++i) {
    int a = ed.Index(s.neighbors[i]), b = ed.Index(s.neighbors[(i + 1) % s.neighbors.size()]);
    if (ed.Valence(a) == 6 && ed.Valence(b) == 6) raised = ed.Flip(a, b).ok;
  }
  ASSERT_TRUE(raised);
  ASSERT_EQ(ed.Valence(c), 9);
  const auto before = IrregularValences(m);
  CompositeOutcome r = co.ReduceTo57(c);
  ASSERT_TRUE(r) << r.result.reason;
  int n9 = int(before.count(9)), n7before = int(before.count(7));
  EXPECT_EQ(n9, 1);
  auto after = IrregularValences(m);
  EXPECT_EQ(after.count(9), 0u);
  EXPECT_EQ(int(after.count(7)), n7before + 3);
  ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
}

TEST(Composite, MoveAdjacentPairTenSteps) {
  TMesh m;
  test::RegularTorus(m, 48, 48);
  SurfaceProjector original(m);
  MeshEditor<TMesh> ed(m);
  CompositeOperations<TMesh> co(ed, &original);
  AtomicOutcome g = co.atomic().GenerateQuadruple(24 * 48 + 24, 0, false);
  ASSERT_TRUE(g);
  const int v5 = g.irregular[0], v7 = g.irregular[2];
  const vcg::Point3f start = m.vert[size_t(v5)].P();
  // find a first direction that moves away from the partner pair
  CompositeOutcome best;
  float bestDist = -1;
  for (int dir = 0; dir < 6; ++dir) {
    auto cp = ed.Mark();
    CompositeOutcome o = co.MoveAdjacentPair57(v5, v7, dir, 10);
    if (o) {
      float d = (m.vert[size_t(o.irregular[0])].P() - start).Norm();
      if (d > bestDist) bestDist = d;
      EXPECT_EQ(o.atomicSteps, 10);
      EXPECT_EQ(IrregularValences(m), (std::multiset<int>{5, 5, 7, 7}));
      EXPECT_TRUE(ed.Adjacent(o.irregular[0], o.irregular[1]));
      EXPECT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
    }
    ed.RollbackTo(cp);
  }
  // ten steps on a lattice of unit-ish edges take the pair well away (on a torus of radius 3
  // with 48 segments an edge is about 0.4 long)
  EXPECT_GT(bestDist, 2.0f);
}

TEST(Composite, TripleGenerationAndCancellationAtADistance) {
  TMesh m;
  test::Icosphere(m, 3);
  SurfaceProjector original(m);
  MeshEditor<TMesh> ed(m);
  CompositeOperations<TMesh> co(ed, &original);
  const int p = FirstWithValence(m, 5);
  CompositeOutcome g = co.GenerateTriple(p, 0, 2);
  ASSERT_TRUE(g) << g.result.reason;
  EXPECT_EQ(IrregularValences(m).size(), 14u);
  ASSERT_EQ(g.irregular.size(), 3u);
  ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
  CompositeOutcome c = co.CancelTriple(g.irregular);
  ASSERT_TRUE(c) << c.result.reason << "\n" << c.log;
  EXPECT_EQ(IrregularValences(m), (std::multiset<int>{5, 5, 5, 5, 5, 5, 5, 5, 5, 5, 5, 5}));
  ASSERT_EQ(c.irregular.size(), 1u);
  EXPECT_EQ(ed.Valence(c.irregular[0]), 5);
  ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
}

TEST(Composite, QuadrupleGenerationApartAndCancellation) {
  TMesh m;
  test::RegularTorus(m, 40, 40);
  SurfaceProjector original(m);
  MeshEditor<TMesh> ed(m);
  CompositeOperations<TMesh> co(ed, &original);
  CompositeOutcome g = co.GenerateQuadruple(20 * 40 + 20, 0, 3);
  ASSERT_TRUE(g) << g.result.reason;
  EXPECT_EQ(IrregularValences(m), (std::multiset<int>{5, 5, 7, 7}));
  CompositeOutcome c = co.CancelQuadruple(g.irregular);
  ASSERT_TRUE(c) << c.result.reason << "\n" << c.log;
  EXPECT_TRUE(IrregularValences(m).empty());
  ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
}

TEST(Composite, NonAdjacentPairMovesByThePipeline) {
  TMesh m;
  test::Icosphere(m, 3);
  SurfaceProjector original(m);
  MeshEditor<TMesh> ed(m);
  CompositeOperations<TMesh> co(ed, &original);
  // two v5 of the icosphere: eight edges apart
  const int a = FirstWithValence(m, 5);
  int b = -1;
  float bd = 1e9f;
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (int(i) != a && ed.Valence(int(i)) == 5) {
      float d = (m.vert[i].P() - m.vert[size_t(a)].P()).Norm();
      if (d < bd) bd = d, b = int(i);
    }
  CompositeOutcome o = co.MovePair(a, b, 0, 1);
  ASSERT_TRUE(o) << o.result.reason << "\n" << o.log;
  EXPECT_EQ(IrregularValences(m).size(), 12u);
  EXPECT_EQ(ed.Valence(a), 6);  // the lead left its place
  ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
}

TEST(Composite, RefusalsLeaveMeshUnchanged) {
  TMesh m;
  test::Icosphere(m, 2);
  SurfaceProjector original(m);
  MeshEditor<TMesh> ed(m);
  CompositeOperations<TMesh> co(ed, &original);
  auto snap = test::Snapshot(m);
  const int p = FirstWithValence(m, 5);
  EXPECT_FALSE(co.CancelTriple({p, p, p}));
  EXPECT_FALSE(co.Aggregate({p}));
  EXPECT_FALSE(co.CancelQuadruple({0, 1, 2, 3}));
  int r = FirstWithValence(m, 6);
  EXPECT_FALSE(co.MovePair(p, r, 0, 3));
  EXPECT_EQ(test::Snapshot(m), snap);
}
