// Unit tests of vcg_ext/irregular/circle_pattern.h (paper sec. 10, Fig. 14): no circle on a
// regular lattice, the exact rings around one irregular vertex, and more circles after
// generating irregular vertices (composite_ops.h), each an annulus counted independently.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <vector>

#include <vcg_ext/irregular/circle_pattern.h>
#include <vcg_ext/irregular/composite_ops.h>
#include <vcg_ext/irregular/mesh_checks.h>

#include "test_mesh.h"
#include "test_pattern_mesh.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {
/// Euler characteristic and number of boundary loops of a set of faces, from the face list
/// alone (edges as vertex pairs), independent of region_outline.h.
struct FaceSetTopology {
  int chi = 0;
  int boundaryEdges = 0;
  int boundaryLoops = 0;
};
FaceSetTopology Topology(TMesh& m, const std::vector<int>& faces) {
  std::set<int> verts;
  std::map<std::pair<int, int>, int> edges;
  for (int f : faces)
    for (int z = 0; z < 3; ++z) {
      const int a = int(vcg::tri::Index(m, m.face[size_t(f)].V(z))), b = int(vcg::tri::Index(m, m.face[size_t(f)].V((z + 1) % 3)));
      verts.insert(a);
      edges[{std::min(a, b), std::max(a, b)}]++;
    }
  FaceSetTopology t;
  t.chi = int(verts.size()) - int(edges.size()) + int(faces.size());
  // boundary loops: components of the graph of boundary edges (each boundary vertex has 2)
  std::map<int, std::vector<int>> adj;
  for (auto& e : edges)
    if (e.second == 1) {
      adj[e.first.first].push_back(e.first.second);
      adj[e.first.second].push_back(e.first.first);
      t.boundaryEdges++;
    }
  std::set<int> seen;
  for (auto& kv : adj) {
    if (seen.count(kv.first)) continue;
    t.boundaryLoops++;
    std::vector<int> st{kv.first};
    seen.insert(kv.first);
    while (!st.empty()) {
      int v = st.back();
      st.pop_back();
      for (int w : adj[v])
        if (seen.insert(w).second) st.push_back(w);
    }
  }
  return t;
}
std::vector<std::vector<int>> RegionFaces(const PatternLabels& P) {
  std::vector<std::vector<int>> r(P.regionKind.size());
  for (size_t i = 0; i < P.faceRegion.size(); ++i)
    if (P.faceRegion[i] >= 0) r[size_t(P.faceRegion[i])].push_back(int(i));
  return r;
}
/// Every Circle region is an annulus by the independent count.
void ExpectCirclesAreAnnuli(TMesh& m, const PatternLabels& P) {
  auto rf = RegionFaces(P);
  int circles = 0;
  for (size_t r = 0; r < rf.size(); ++r) {
    if (P.regionKind[r] != RegionKind::Circle) continue;
    ++circles;
    FaceSetTopology t = Topology(m, rf[r]);
    EXPECT_EQ(t.chi, 0) << "circle " << r;
    EXPECT_EQ(t.boundaryLoops, 2) << "circle " << r;
  }
  EXPECT_EQ(circles, P.measures.circles);
}
}  // namespace

TEST(CirclePattern, RegularLatticeHasNoCircle) {
  TMesh m;
  test::RegularTorus(m, 20, 20);
  PatternLabels P = ComputeCircles(m, CircleOptions());
  ASSERT_TRUE(P.ok) << P.reason;
  EXPECT_EQ(P.measures.circles, 0);
  EXPECT_EQ(P.regionKind, std::vector<RegionKind>{RegionKind::Background});
  TMesh h;
  test::NGonPatch(h, 6, 6);
  EXPECT_EQ(ComputeCircles(h, CircleOptions()).measures.circles, 0);
}

// One v5 in a flat patch of radius 6: vertex ring k is at graph distance k, so face ring d
// holds the faces whose outer vertices lie on ring d. Width 1: rings 2, 4, 6 are circles
// (ring 6 runs along the boundary, still a closed annulus); width 2: rings 3-4 only (5-6 is a
// gap).
TEST(CirclePattern, ExactRingsAroundOneV5) {
  TMesh m;
  test::NGonPatch(m, 5, 6);
  auto ringOf = [&](int f) {
    int d = 0;
    for (int z = 0; z < 3; ++z) d = std::max(d, int(std::lround(m.face[size_t(f)].V(z)->P().Norm())));
    return d;
  };
  for (int width : {1, 2}) {
    CircleOptions o;
    o.ringWidth = width;
    PatternLabels P = ComputeCircles(m, o);
    ASSERT_TRUE(P.ok) << P.reason;
    const std::set<int> circleRings = width == 1 ? std::set<int>{2, 4, 6} : std::set<int>{3, 4};
    EXPECT_EQ(P.measures.circles, width == 1 ? 3 : 1);
    std::map<int, std::set<int>> regionsOfRing;
    for (size_t f = 0; f < m.face.size(); ++f) {
      const RegionKind k = P.regionKind[size_t(P.faceRegion[f])];
      EXPECT_EQ(k == RegionKind::Circle, circleRings.count(ringOf(int(f))) == 1) << "face " << f << " ring " << ringOf(int(f));
      if (k == RegionKind::Circle) regionsOfRing[(ringOf(int(f)) - 1) / width].insert(P.faceRegion[f]);
    }
    for (auto& kv : regionsOfRing) EXPECT_EQ(kv.second.size(), 1u) << "one region per band";
    ExpectCirclesAreAnnuli(m, P);
  }
}

// Generate, then pattern: a regular torus has no circle; each generated, spaced quadruple
// (two 5-7 pairs moved apart) makes rings close around its pairs.
TEST(CirclePattern, GeneratingIrregularVerticesMakesCirclesClose) {
  TMesh m;
  test::RegularTorus(m, 40, 40);
  EXPECT_EQ(ComputeCircles(m, CircleOptions()).measures.circles, 0);
  SurfaceProjector original(m);
  MeshEditor<TMesh> ed(m);
  CompositeOperations<TMesh> co(ed, &original);
  CompositeOutcome g = co.GenerateQuadruple(10 * 40 + 10, 0, 8);
  ASSERT_TRUE(g) << g.result.reason;
  ASSERT_TRUE(CheckInvariants(m).ok);
  PatternLabels P1 = ComputeCircles(m, CircleOptions());
  ASSERT_TRUE(P1.ok) << P1.reason;
  // two clusters (the 5-7 pairs) 8 steps apart: rings 2 and 4 close around each, ring 6 is cut
  EXPECT_EQ(P1.measures.circles, 4);
  ExpectCirclesAreAnnuli(m, P1);
  CompositeOutcome g2 = co.GenerateQuadruple(30 * 40 + 30, 0, 8);
  ASSERT_TRUE(g2) << g2.result.reason;
  PatternLabels P2 = ComputeCircles(m, CircleOptions());
  EXPECT_EQ(P2.measures.circles, 8);
  ExpectCirclesAreAnnuli(m, P2);
  // no circle face lies in two regions, no circle contains an irregular vertex's faces
  for (size_t f = 0; f < m.face.size(); ++f) {
    if (m.face[f].IsD() || P2.regionKind[size_t(P2.faceRegion[f])] != RegionKind::Circle) continue;
    for (int z = 0; z < 3; ++z) EXPECT_EQ(Valence<TMesh>(m.face[f].V(z)), 6);
  }
}
