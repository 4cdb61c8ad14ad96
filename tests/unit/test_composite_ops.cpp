// Unit tests of vcg_ext/irregular/composite_ops.h (paper sec. 6.3, 7): exact outcomes on
// constructed meshes; refusals leave the mesh identical.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

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
/// Vertex adjacency from the face list alone, independent of the stars and FF/VF adjacency
/// the code under test maintains.
std::vector<std::set<int>> FaceAdjacency(TMesh& m) {
  std::vector<std::set<int>> adj(m.vert.size());
  for (auto& f : m.face)
    if (!f.IsD())
      for (int z = 0; z < 3; ++z) {
        const int a = int(vcg::tri::Index(m, f.V(z))), b = int(vcg::tri::Index(m, f.V((z + 1) % 3)));
        adj[size_t(a)].insert(b);
        adj[size_t(b)].insert(a);
      }
  return adj;
}
/// vertex -> valence of the irregular vertices (closed meshes), from the face list.
std::map<int, int> FaceValenceIrregular(TMesh& m) {
  std::map<int, int> r;
  std::vector<std::set<int>> adj = FaceAdjacency(m);
  for (size_t i = 0; i < adj.size(); ++i)
    if (!m.vert[i].IsD() && !adj[i].empty() && adj[i].size() != 6) r[int(i)] = int(adj[i].size());
  return r;
}
/// Graph distance (BFS over the face edges) between two vertex sets; -1 if not connected.
int GraphDistance(TMesh& m, const std::vector<int>& from, const std::vector<int>& to) {
  std::vector<std::set<int>> adj = FaceAdjacency(m);
  std::vector<int> d(adj.size(), -1), queue;
  for (int v : from) d[size_t(v)] = 0, queue.push_back(v);
  for (size_t q = 0; q < queue.size(); ++q)
    for (int w : adj[size_t(queue[q])])
      if (d[size_t(w)] < 0) d[size_t(w)] = d[size_t(queue[q])] + 1, queue.push_back(w);
  int best = -1;
  for (int v : to)
    if (d[size_t(v)] >= 0 && (best < 0 || d[size_t(v)] < best)) best = d[size_t(v)];
  return best;
}
int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
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

TEST(Composite, QuadrupleCancellationFollowsTheSeparatrixPathAroundATurn) {
  // One pair of a generated quadruple is moved 6 steps in direction d1, then 6 in d2 (an
  // L-shaped offset for most combinations); cancelling the quadruple then transports it back
  // along the connecting path of two separatrix segments (sec. 7.1.1).
  TMesh m;
  test::RegularTorus(m, 48, 48);
  SurfaceProjector original(m);
  MeshEditor<TMesh> ed(m);
  CompositeOptions opt;
  opt.relax = false;
  CompositeOperations<TMesh> co(ed, &original, opt);
  AtomicOutcome g = co.atomic().GenerateQuadruple(24 * 48 + 24, 0, false);
  ASSERT_TRUE(g);
  const int a5 = g.irregular[0], a7 = g.irregular[2], b5 = g.irregular[1], b7 = g.irregular[3];
  int cases = 0, turns = 0;
  for (int d1 = 0; d1 < 6; ++d1)
    for (int d2 = 0; d2 < 6; ++d2) {
      auto cp = ed.Mark();
      CompositeOutcome o1 = co.MoveAdjacentPair57(a5, a7, d1, 6);
      CompositeOutcome o2 = o1 ? co.MoveAdjacentPair57(o1.irregular[0], o1.irregular[1], d2, 6) : o1;
      if (o2) {
        ++cases;
        const int dist = GraphDistance(m, o2.irregular, {b5, b7});

        CompositeOutcome c = co.CancelQuadruple({o2.irregular[0], o2.irregular[1], b5, b7});
        ASSERT_TRUE(c) << d1 << " " << d2 << ": " << c.result.reason << "\n" << c.log;
        EXPECT_TRUE(FaceValenceIrregular(m).empty());
        ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
        // one atomic step per edge of the way, plus at most two alignment steps beside the
        // partner pair where the path ends (taken greedily), plus the removal
        EXPECT_LE(c.atomicSteps, dist + 3) << c.log;
        EXPECT_LE(Count(c.log, "greedy"), 2) << c.log;
        turns += Count(c.log, "turn point") > 0;
      }
      ed.RollbackTo(cp);
    }
  EXPECT_GE(cases, 20);
  EXPECT_GE(turns, 10);
}
