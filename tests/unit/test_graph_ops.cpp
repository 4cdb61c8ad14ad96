// Unit tests of vcg_ext/irregular/graph_ops.h: exact valence effects of flip, collapse and split
// (paper sec. 6.1), refusals leave the mesh bit-identical, local adjacency equals a rebuild,
// and random sequences keep every invariant.
#include <gtest/gtest.h>

#include <random>

#include <vcg_ext/irregular/graph_ops.h>
#include <vcg_ext/irregular/mesh_checks.h>

#include "test_mesh.h"
#include "test_util.h"

using namespace vcg_ext::irregular;
using test::TMesh;

TEST(GraphOps, FlipChangesFourValences) {
  TMesh m;
  test::HexPatch(m, 4);
  MeshEditor<TMesh> ed(m);
  VertexStar<TMesh> s = ed.Star(0);
  int x = 0, y = ed.Index(s.neighbors[0]);
  int o[2];
  ASSERT_TRUE(ed.Opposites(x, y, o));
  auto before = test::Valences(m);
  ASSERT_TRUE(ed.Flip(x, y).ok);
  auto after = test::Valences(m);
  EXPECT_EQ(after[x], 5);
  EXPECT_EQ(after[y], 5);
  EXPECT_EQ(after[o[0]], 7);
  EXPECT_EQ(after[o[1]], 7);
  EXPECT_EQ(test::CountChanged(before, after), 4);
  EXPECT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
  EXPECT_TRUE(test::AdjacencyEqualsRebuild(m));
  // flipping back restores the valences
  ASSERT_TRUE(ed.Flip(o[0], o[1]).ok);
  EXPECT_EQ(test::Valences(m), before);
}

TEST(GraphOps, CollapseValences) {
  TMesh m;
  test::HexPatch(m, 4);
  MeshEditor<TMesh> ed(m);
  int u = 0, v = ed.Index(ed.Star(0).neighbors[2]);
  int o[2];
  ed.Opposites(u, v, o);
  auto before = test::Valences(m);
  const int fn = m.fn, vn = m.vn;
  ASSERT_TRUE(ed.Collapse(u, v).ok);
  auto after = test::Valences(m);
  EXPECT_TRUE(m.vert[u].IsD());
  EXPECT_EQ(after[v], 6 + 6 - 4);
  EXPECT_EQ(after[o[0]], 5);
  EXPECT_EQ(after[o[1]], 5);
  EXPECT_EQ(m.fn, fn - 2);
  EXPECT_EQ(m.vn, vn - 1);
  EXPECT_EQ(test::CountChanged(before, after), 4);
  EXPECT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
  EXPECT_TRUE(test::AdjacencyEqualsRebuild(m));
}

TEST(GraphOps, SplitValences) {
  TMesh m;
  test::HexPatch(m, 4);
  MeshEditor<TMesh> ed(m);
  VertexStar<TMesh> s = ed.Star(0);
  // d1 = 2 (neighbours 1, 2 between a = n0 and b = n3), d2 = 2
  int a = ed.Index(s.neighbors[0]), b = ed.Index(s.neighbors[3]);
  const int w = ed.Index(s.neighbors[1]);  // indices: a split may move the vertex vector
  auto before = test::Valences(m);
  int x = -1;
  ASSERT_TRUE(ed.Split(0, a, b, &x).ok);
  auto after = test::Valences(m);
  EXPECT_EQ(after[0], 2 + 3);
  EXPECT_EQ(after[x], 2 + 3);
  EXPECT_EQ(after[a], before[a] + 1);
  EXPECT_EQ(after[b], before[b] + 1);
  EXPECT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
  EXPECT_TRUE(test::AdjacencyEqualsRebuild(m));
  // asymmetric split: d1 = 1, d2 = 3
  VertexStar<TMesh> s2 = ed.Star(w);
  int a2 = ed.Index(s2.neighbors[0]), b2 = ed.Index(s2.neighbors[2]);
  const int dw = ed.Valence(w);
  ASSERT_TRUE(ed.Split(w, a2, b2, &x).ok);
  EXPECT_EQ(ed.Valence(w), 1 + 3);
  EXPECT_EQ(ed.Valence(x), dw - 2 - 1 + 3);
  EXPECT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
}

TEST(GraphOps, RefusalsLeaveMeshIdentical) {
  TMesh m;
  test::HexPatch(m, 3);
  MeshEditor<TMesh> ed(m);
  auto snap = test::Snapshot(m);
  int boundary = -1;
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (ed.IsBoundary(int(i))) { boundary = int(i); break; }
  ASSERT_GE(boundary, 0);
  int nb = ed.Index(ed.Star(boundary).neighbors[0]);
  Result r = ed.Flip(boundary, nb);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.reason.find("boundary"), std::string::npos) << r.reason;
  // a boundary vertex into an interior neighbour: refused (the boundary vertex must survive)
  const int inner = ed.Index(ed.Star(boundary).neighbors[1]);
  ASSERT_FALSE(ed.IsBoundary(inner));
  Result rc = ed.Collapse(boundary, inner);
  EXPECT_FALSE(rc.ok);
  EXPECT_NE(rc.reason.find("instead"), std::string::npos) << rc.reason;
  EXPECT_FALSE(ed.Split(boundary, nb, nb).ok);
  EXPECT_FALSE(ed.Flip(0, 0).ok);
  // not adjacent
  EXPECT_FALSE(ed.Flip(0, boundary).ok);
  // duplicate edge: on a tetrahedron-like valence 3 vertex every flip is refused
  EXPECT_EQ(test::Snapshot(m), snap);
}

TEST(GraphOps, FoldRefusedAndRolledBack) {
  TMesh m;
  test::HexPatch(m, 3);
  MeshEditor<TMesh> ed(m);
  // Make the quad around edge (0, n0) non-convex: pull n0 across the centre, so the flip
  // would turn a triangle over.
  VertexStar<TMesh> s = ed.Star(0);
  int y = ed.Index(s.neighbors[0]);
  int o[2];
  ed.Opposites(0, y, o);
  // move vertex 0 far beyond y so the quad (0, o0, y, o1) is not convex
  m.vert[0].P() = m.vert[y].P() * 1.6f;
  test::UpdateTopology(m);
  auto snap = test::Snapshot(m);
  Result r = ed.Flip(0, y);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.reason.find("fold"), std::string::npos) << r.reason;
  EXPECT_EQ(test::Snapshot(m), snap);
}

TEST(GraphOps, CollapseLinkConditionOnIcosahedron) {
  TMesh m;
  test::Icosahedron(m);
  MeshEditor<TMesh> ed(m);
  int v = ed.Index(ed.Star(0).neighbors[0]);
  // 5 + 5 - 4 = 6: allowed; the opposite vertices go to 4
  ASSERT_TRUE(ed.Collapse(0, v).ok);
  EXPECT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
}

// Thousands of random flips, collapses and splits on a real mesh: after each one the
// invariants hold; every refused operation leaves the mesh bit-identical; at the end the
// local adjacency equals a full rebuild.
TEST(GraphOps, RandomSequencesKeepInvariants) {
  TMesh m;
  if (!test::LoadCorpus(m, "bunny00.off")) {
    test::Icosphere(m, 4);
  }
  MeshEditor<TMesh> ed(m);
  std::mt19937 rng(7);
  int done = 0, refused = 0;
  const int steps = 3000;
  for (int it = 0; it < steps; ++it) {
    int v = int(rng() % m.vert.size());
    if (!ed.IsLive(v)) continue;
    VertexStar<TMesh> s = ed.Star(v);
    int k = int(rng() % s.neighbors.size());
    int y = ed.Index(s.neighbors[size_t(k)]);
    int kind = int(rng() % 3);
    bool check = it % 25 == 0;
    test::MeshSnapshot snap;
    if (check) snap = test::Snapshot(m);
    Result r;
    if (kind == 0) r = ed.Flip(v, y);
    else if (kind == 1) r = ed.Collapse(v, y);
    else r = ed.Split(v, y, ed.Index(s.neighbors[size_t((k + 3) % s.neighbors.size())]));
    if (r.ok) {
      ++done;
      if (check) ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason << " at step " << it;
    } else {
      ++refused;
      EXPECT_FALSE(r.reason.empty());
      if (check) ASSERT_EQ(test::Snapshot(m), snap) << "refused op changed the mesh: " << r.reason;
    }
    ed.Commit();
  }
  EXPECT_GT(done, steps / 2);
  ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
  EXPECT_TRUE(test::AdjacencyEqualsRebuild(m));
  RecordProperty("applied", done);
  RecordProperty("refused", refused);
}

// A long sequence rolled back through the journal restores the mesh exactly.
TEST(GraphOps, JournalRollbackRestoresEverything) {
  TMesh m;
  test::Icosphere(m, 3);
  auto snap = test::Snapshot(m);
  MeshEditor<TMesh> ed(m);
  auto cp = ed.Mark();
  std::mt19937 rng(3);
  int applied = 0;
  for (int it = 0; it < 500; ++it) {
    int v = int(rng() % m.vert.size());
    if (!ed.IsLive(v)) continue;
    VertexStar<TMesh> s = ed.Star(v);
    int k = int(rng() % s.neighbors.size());
    int y = ed.Index(s.neighbors[size_t(k)]);
    Result r = (it % 3 == 0) ? ed.Flip(v, y) : (it % 3 == 1) ? ed.Collapse(v, y)
                                                               : ed.Split(v, y, ed.Index(s.neighbors[size_t((k + 2) % s.neighbors.size())]));
    applied += r.ok;
  }
  EXPECT_GT(applied, 100);
  ed.RollbackTo(cp);
  EXPECT_EQ(test::Snapshot(m), snap);
}

// PredictSplitPlaces (used by the reduction's StepCloser to skip applying every split) gives
// the places Split then gives, to the bit: interior vertices of the bunny and boundary
// vertices of a jittered patch, every pair of edges; and it declines with the fold check on,
// where a split refused at share 1/3 retries at smaller shares.
TEST(GraphOps, PredictSplitPlacesAreTheSplitsToTheBit) {
  for (int which = 0; which < 2; ++which) {
    TMesh m;
    if (which == 0 && !test::LoadCorpus(m, "bunny00.off")) test::Icosphere(m, 3);
    if (which == 1) test::HexPatch(m, 4);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> jitter(-0.05, 0.05);
    if (which == 1)  // a flat lattice is too symmetric: every centroid would be a lattice point
      for (auto& v : m.vert) v.P() += TMesh::CoordType(jitter(rng), jitter(rng), 0);
    MeshEditor<TMesh> ed(m);
    EXPECT_TRUE(ed.geometry().checkFolds);
    {
      TMesh::CoordType pw, px;
      const VertexStar<TMesh> s = ed.Star(0);
      EXPECT_FALSE(ed.PredictSplitPlaces(0, ed.Index(s.neighbors[0]), ed.Index(s.neighbors[2]), pw, px));
    }
    ed.geometry().checkFolds = false;
    int compared = 0, boundary = 0;
    for (int v = 0; v < int(m.vert.size()) && compared < 400; v += which == 0 ? 37 : 1) {
      if (!ed.IsLive(v)) continue;
      const VertexStar<TMesh> s = ed.Star(v);
      const int d = s.Valence();
      for (int i = 0; i < d; ++i)
        for (int j = 0; j < d; ++j) {
          const int a = ed.Index(s.neighbors[size_t(i)]), b = ed.Index(s.neighbors[size_t(j)]);
          if (i == j || !ed.CanSplit(v, a, b)) continue;
          TMesh::CoordType pw, px;
          ASSERT_TRUE(ed.PredictSplitPlaces(v, a, b, pw, px));
          auto cp = ed.Mark();
          int created = -1;
          ASSERT_TRUE(ed.Split(v, a, b, &created).ok);
          for (int k = 0; k < 3; ++k) {
            ASSERT_EQ(m.vert[size_t(v)].P()[k], pw[k]) << "vertex " << v << " split along " << a << ", " << b;
            ASSERT_EQ(m.vert[size_t(created)].P()[k], px[k]) << "vertex " << v << " split along " << a << ", " << b;
          }
          ed.RollbackTo(cp);
          ++compared;
          boundary += s.boundary;
        }
    }
    EXPECT_GT(compared, 100);
    if (which == 1) EXPECT_GT(boundary, 10);  // the boundary rule (one half stays) is covered
  }
}
