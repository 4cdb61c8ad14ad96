// Graph operations on and next to a boundary (graph_ops.h, "Boundaries"): flips of interior
// edges with boundary ends, collapses into a boundary vertex and of boundary edges, splits of
// boundary vertices, and the refusals (boundary edge flip, pinch, link condition). Each test
// names the vertices by lattice coordinates and checks the valence of every vertex (touched
// ones to their predicted value, all others unchanged), where the survivors are, the
// invariants with the boundary consistency checks, and eq. 2.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include <vcg_ext/irregular/graph_ops.h>
#include <vcg_ext/irregular/mesh_checks.h>

#include "test_boundary_mesh.h"
#include "test_mesh.h"
#include "test_util.h"

using namespace vcg_ext::irregular;
using test::At;
using test::ExpectValid;
using test::TMesh;

namespace {


/// Every vertex has its old valence except those in `changed` (0: deleted).
void ExpectValences(TMesh& m, const std::vector<int>& before, const std::map<int, int>& changed) {
  const std::vector<int> after = test::Valences(m);
  for (size_t i = 0; i < before.size(); ++i) {
    auto it = changed.find(int(i));
    EXPECT_EQ(after[i], it == changed.end() ? before[i] : it->second) << "vertex " << i;
  }
}

/// Every live vertex not in `moved` kept its position.
void ExpectUnmoved(TMesh& m, const std::vector<vcg::Point3f>& before, std::vector<int> moved) {
  for (size_t i = 0; i < before.size(); ++i) {
    if (m.vert[i].IsD() || std::find(moved.begin(), moved.end(), int(i)) != moved.end()) continue;
    EXPECT_EQ(m.vert[i].P(), before[i]) << "vertex " << i;
  }
}

std::vector<vcg::Point3f> Positions(TMesh& m) {
  std::vector<vcg::Point3f> p;
  for (auto& v : m.vert) p.push_back(v.P());
  return p;
}

}  // namespace

// Hexagon of radius 3; the side q + r = 3 runs (3,0) corner, (2,1), (1,2), (0,3) corner.
TEST(BoundaryGraphOps, FlipInteriorEdgeAtSideVertex) {
  TMesh m;
  test::HexPatch(m, 3);
  MeshEditor<TMesh> ed(m);
  const int x = At(m, 2, 1), y = At(m, 1, 1), o1 = At(m, 1, 2), o2 = At(m, 2, 0);
  ASSERT_TRUE(ed.IsBoundary(x));
  ASSERT_FALSE(ed.IsBoundary(y));
  int o[2];
  ASSERT_TRUE(ed.Opposites(x, y, o));
  EXPECT_EQ(std::set<int>({o[0], o[1]}), std::set<int>({o1, o2}));
  auto before = test::Valences(m);
  auto pos = Positions(m);
  ASSERT_TRUE(ed.CanFlip(x, y).ok);
  ASSERT_TRUE(ed.Flip(x, y).ok);
  ExpectValences(m, before, {{x, 3}, {y, 5}, {o1, 5}, {o2, 7}});
  ExpectUnmoved(m, pos, {});
  EXPECT_TRUE(ed.Adjacent(o1, o2));
  EXPECT_FALSE(ed.Adjacent(x, y));
  EXPECT_TRUE(ed.IsBoundary(x) && ed.IsBoundary(o1));
  ExpectValid(m);
  // x is a boundary v3 on a smooth stretch (a v5), o1 a boundary v5 (a v7)
  TopologySummary s = Summarize(m);
  EXPECT_EQ(s.irregular, 4);
  EXPECT_EQ(s.boundaryIrregular, 2);
  EXPECT_EQ(test::IrregularVertices(m), ([&] {
              std::vector<int> v{x, y, o1, o2};
              std::sort(v.begin(), v.end());
              return v;
            }()));
}

// Flipping the interior edge of a 120 degree corner makes it an ear (valence 2) and joins its
// two boundary neighbours by an interior edge; collapsing that edge would pinch the surface.
TEST(BoundaryGraphOps, EarFlipPinchRefusalAndEarRemoval) {
  TMesh m;
  test::HexPatch(m, 3);
  MeshEditor<TMesh> ed(m);
  const int c = At(m, 3, 0), in = At(m, 2, 0), s1 = At(m, 2, 1), s2 = At(m, 3, -1);
  ASSERT_EQ(ed.Valence(c), 3);
  const auto faces0 = test::CanonicalFaces(m);
  auto before = test::Valences(m);
  ASSERT_TRUE(ed.Flip(c, in).ok);
  ExpectValences(m, before, {{c, 2}, {in, 5}, {s1, 5}, {s2, 5}});
  ExpectValid(m);
  ASSERT_TRUE(ed.Adjacent(s1, s2));
  EXPECT_FALSE(ed.IsBoundaryEdge(s1, s2));
  ed.Commit();
  // the ear's edges are both boundary edges: no flip
  Result rf = ed.CanFlip(c, s1);
  EXPECT_FALSE(rf.ok);
  EXPECT_NE(rf.reason.find("boundary edge"), std::string::npos) << rf.reason;
  // pinch: an interior edge between two boundary vertices
  auto snap = test::Snapshot(m);
  Result can = ed.CanCollapse(s1, s2);
  Result r = ed.Collapse(s1, s2);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.reason, can.reason);
  EXPECT_NE(r.reason.find("pinch"), std::string::npos) << r.reason;
  EXPECT_EQ(test::Snapshot(m), snap);
  // flipping it back restores the patch
  ASSERT_TRUE(ed.Flip(s1, s2).ok);
  EXPECT_EQ(test::CanonicalFaces(m), faces0);
  ASSERT_TRUE(ed.Flip(c, in).ok);
  ed.Commit();
  // removing the ear: boundary edge (c, s1) with apex s2; c is a corner (one face of 120
  // degrees), s1 is not, so the survivor s1 takes the corner's place
  before = test::Valences(m);
  auto pos = Positions(m);
  ASSERT_TRUE(ed.CanCollapse(c, s1).ok);
  ASSERT_TRUE(ed.Collapse(c, s1).ok);
  ExpectValences(m, before, {{c, 0}, {s1, 4}, {s2, 4}});
  EXPECT_TRUE(m.vert[size_t(c)].IsD());
  EXPECT_EQ(m.vert[size_t(s1)].P(), pos[size_t(c)]);
  ExpectUnmoved(m, pos, {s1});
  ExpectValid(m);
}

// An interior vertex collapsed into a boundary vertex: the boundary vertex survives in place.
TEST(BoundaryGraphOps, CollapseInteriorIntoBoundaryVertex) {
  TMesh m;
  test::HexPatch(m, 3);
  MeshEditor<TMesh> ed(m);
  const int v = At(m, 2, 1), u = At(m, 1, 1), a = At(m, 1, 2), b = At(m, 2, 0);
  auto before = test::Valences(m);
  auto pos = Positions(m);
  auto snap = test::Snapshot(m);
  Result wrong = ed.Collapse(v, u);  // boundary into interior: refused, names the other way
  EXPECT_FALSE(wrong.ok);
  EXPECT_NE(wrong.reason.find("instead"), std::string::npos) << wrong.reason;
  EXPECT_EQ(test::Snapshot(m), snap);
  ASSERT_TRUE(ed.CanCollapse(u, v).ok);
  ASSERT_TRUE(ed.Collapse(u, v).ok);
  ExpectValences(m, before, {{u, 0}, {v, 6}, {a, 3}, {b, 5}});
  EXPECT_EQ(m.vert[size_t(v)].P(), pos[size_t(v)]);  // stays on the boundary, where it was
  EXPECT_TRUE(ed.IsBoundary(v));
  ExpectUnmoved(m, pos, {});
  ExpectValid(m);
  TopologySummary s = Summarize(m);
  EXPECT_EQ(s.boundaryIrregular, 2);  // v (6 on a smooth stretch) and a (3)
  EXPECT_EQ(s.irregular, 3);          // and b (5)
}

// A boundary edge between two smooth boundary vertices: the survivor sits at the midpoint.
// A boundary edge at a corner: the survivor takes the corner's place.
TEST(BoundaryGraphOps, CollapseBoundaryEdge) {
  TMesh m;
  test::HexPatch(m, 3);
  MeshEditor<TMesh> ed(m);
  const int v = At(m, 2, 1), u = At(m, 1, 2), apex = At(m, 1, 1);
  ASSERT_TRUE(ed.IsBoundaryEdge(u, v));
  auto before = test::Valences(m);
  auto pos = Positions(m);
  const int edges0 = Summarize(m).boundaryEdges;
  ASSERT_TRUE(ed.CanCollapse(u, v).ok);
  ASSERT_TRUE(ed.Collapse(u, v).ok);
  ExpectValences(m, before, {{u, 0}, {v, 5}, {apex, 5}});
  EXPECT_EQ(m.vert[size_t(v)].P(), (pos[size_t(u)] + pos[size_t(v)]) / 2.f);
  ExpectUnmoved(m, pos, {v});
  EXPECT_TRUE(ed.IsBoundary(v));
  EXPECT_EQ(Summarize(m).boundaryEdges, edges0 - 1);
  EXPECT_EQ(Summarize(m).boundaryLoops, 1);
  ExpectValid(m);

  TMesh m2;
  test::HexPatch(m2, 3);
  MeshEditor<TMesh> ed2(m2);
  const int corner = At(m2, 3, 0), side = At(m2, 2, 1), apex2 = At(m2, 2, 0);
  before = test::Valences(m2);
  pos = Positions(m2);
  ASSERT_TRUE(ed2.Collapse(side, corner).ok);
  ExpectValences(m2, before, {{side, 0}, {corner, 4}, {apex2, 5}});
  EXPECT_EQ(m2.vert[size_t(corner)].P(), pos[size_t(corner)]);
  ExpectUnmoved(m2, pos, {});
  ExpectValid(m2);
}

// A triangular hole: its edges' ends share the far corner of the hole and the apex, so the
// link condition for boundary edges refuses (the hole would become a two-edge loop).
TEST(BoundaryGraphOps, BoundaryEdgeLinkConditionRefused) {
  TMesh m;
  test::HexPatch(m, 2);
  const int a0 = At(m, 0, 0), a1 = At(m, 1, 0), a2 = At(m, 0, 1);
  test::RemoveFaces(m, {test::FaceWith(m, a0, a1, a2)});
  const int p = At(m, 0, 0), q = At(m, 1, 0);
  MeshEditor<TMesh> ed(m);
  ASSERT_TRUE(ed.IsBoundaryEdge(p, q));
  ExpectValid(m);
  auto snap = test::Snapshot(m);
  Result can = ed.CanCollapse(p, q);
  Result r = ed.Collapse(p, q);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.reason, can.reason);
  EXPECT_NE(r.reason.find("link condition"), std::string::npos) << r.reason;
  EXPECT_EQ(test::Snapshot(m), snap);
}

// Splitting a boundary vertex along two interior edges: the half with the boundary stays at
// the vertex's position; the other half becomes an interior vertex.
TEST(BoundaryGraphOps, SplitBoundaryVertex) {
  for (int keep = 0; keep < 2; ++keep) {
    TMesh m;
    test::HexPatch(m, 3);
    MeshEditor<TMesh> ed(m);
    const int w = At(m, 2, 1);
    VertexStar<TMesh> st = ed.Star(w);
    ASSERT_EQ(st.Valence(), 4);
    const int n0 = ed.Index(st.neighbors[0]), n1 = ed.Index(st.neighbors[1]), n2 = ed.Index(st.neighbors[2]),
              n3 = ed.Index(st.neighbors[3]);
    auto before = test::Valences(m);
    auto pos = Positions(m);
    auto snap = test::Snapshot(m);
    Result bad = ed.Split(w, n0, n2);  // (w, n0) is a boundary edge
    EXPECT_FALSE(bad.ok);
    EXPECT_NE(bad.reason.find("boundary"), std::string::npos) << bad.reason;
    EXPECT_EQ(test::Snapshot(m), snap);
    int x = -1;
    // keep == 1: w keeps the edges from n2 round the boundary to n1 (it stays on the boundary);
    // keep == 0: w keeps the single corner from n1 to n2 and the new vertex takes the boundary.
    const int a = keep ? n2 : n1, b = keep ? n1 : n2;
    ASSERT_TRUE(ed.CanSplit(w, a, b).ok);
    ASSERT_TRUE(ed.Split(w, a, b, &x).ok);
    const int onB = keep ? w : x, inner = keep ? x : w;
    ExpectValences(m, before, {{onB, 5}, {inner, 3}, {n1, before[size_t(n1)] + 1}, {n2, before[size_t(n2)] + 1},
                               {x, keep ? 3 : 5}});
    EXPECT_TRUE(ed.IsBoundary(onB));
    EXPECT_FALSE(ed.IsBoundary(inner));
    EXPECT_EQ(m.vert[size_t(onB)].P(), pos[size_t(w)]);
    EXPECT_TRUE(ed.Adjacent(onB, n0) && ed.Adjacent(onB, n3));
    ExpectUnmoved(m, pos, {w});
    ExpectValid(m);
  }
}

// The annulus: the six vertices round a hole of one ring span 240 degrees, regular at 5.
TEST(BoundaryGraphOps, HoleCountsByTheBoundaryRule) {
  TMesh m;
  test::HexPatchWithHole(m, 3, 1);
  TopologySummary s = Summarize(m);
  EXPECT_EQ(s.boundaryLoops, 2);
  EXPECT_EQ(s.eulerCharacteristic, 0);
  EXPECT_EQ(s.boundaryHistogram.at(5), 6);
  EXPECT_EQ(s.boundaryCorners, 12);
  EXPECT_EQ(s.irregular, 0);
  EXPECT_TRUE(s.GaussBonnetHolds());
  ExpectValid(m);
}

// Random flips, collapses and splits of vertices within two rings of a boundary (fixed seed):
// each Can* answers exactly as its operation does (a geometric refusal after a topological
// yes aside), every refusal leaves the mesh bit-identical, every success keeps the invariants.
TEST(BoundaryGraphOps, DryRunsAgreeNearBoundaries) {
  TMesh m;
  test::HexPatchWithHole(m, 6, 2);
  MeshEditor<TMesh> ed(m);
  std::mt19937 rng(2024);
  int applied = 0, refused = 0, geometric = 0, boundaryTouched = 0;
  for (int it = 0; it < 1500; ++it) {
    // a vertex on or next to a boundary
    int v = int(rng() % m.vert.size());
    if (!ed.IsLive(v)) continue;
    VertexStar<TMesh> s = ed.Star(v);
    bool near = s.boundary;
    for (auto* nb : s.neighbors) near = near || ed.IsBoundary(ed.Index(nb));
    if (!near) continue;
    const int k = int(rng() % s.neighbors.size());
    const int y = ed.Index(s.neighbors[size_t(k)]);
    const int z = ed.Index(s.neighbors[size_t((k + 1 + rng() % (s.neighbors.size() - 1)) % s.neighbors.size())]);
    const int kind = int(rng() % 3);
    auto snap = test::Snapshot(m);
    Result can = kind == 0 ? ed.CanFlip(v, y) : kind == 1 ? ed.CanCollapse(v, y) : ed.CanSplit(v, y, z);
    EXPECT_EQ(test::Snapshot(m), snap) << "a dry run changed the mesh";
    Result r = kind == 0 ? ed.Flip(v, y) : kind == 1 ? ed.Collapse(v, y) : ed.Split(v, y, z);
    if (!can.ok) {
      ASSERT_FALSE(r.ok) << "kind " << kind << " at step " << it;
      EXPECT_EQ(r.reason, can.reason);
    }
    if (r.ok) {
      ++applied;
      boundaryTouched += s.boundary;
      Result inv = CheckInvariants(m);
      ASSERT_TRUE(inv.ok) << inv.reason << " after kind " << kind << " at step " << it;
    } else {
      ++refused;
      if (can.ok) {
        ++geometric;
        EXPECT_TRUE(r.reason.find("fold") != std::string::npos || r.reason.find("degenerate") != std::string::npos)
            << r.reason;
      }
      ASSERT_EQ(test::Snapshot(m), snap) << "refused op changed the mesh: " << r.reason;
    }
    ed.Commit();
  }
  EXPECT_GT(applied, 200);
  EXPECT_GT(boundaryTouched, 50);
  EXPECT_TRUE(test::AdjacencyEqualsRebuild(m));
  RecordProperty("applied", applied);
  RecordProperty("refused", refused);
  RecordProperty("geometric", geometric);
  std::printf("near-boundary random ops: applied %d, refused %d (of which geometric %d), on a boundary vertex %d\n",
              applied, refused, geometric, boundaryTouched);
}
