// Unit tests of vcg_ext/irregular/separatrix.h (paper sec. 5, 7.1.1): straight paths,
// separatrices and connecting paths with a turn point, on constructed regular patches where
// the lattice coordinates of every vertex are known.
#include <gtest/gtest.h>

#include <set>

#include <vcg_ext/irregular/graph_ops.h>
#include <vcg_ext/irregular/separatrix.h>

#include "test_mesh.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {
// RegularTorus(m, n, k): vertex (i, j) has index i * k + j; its neighbours are (i +- 1, j),
// (i, j +- 1), (i + 1, j + 1), (i - 1, j - 1); the straight lines run along i, along j and
// along the diagonal.
struct TorusGrid {
  int n, k;
  int operator()(int i, int j) const { return ((i % n + n) % n) * k + ((j % k) + k) % k; }
};

void ExpectStraight(TMesh& m, const std::vector<int>& path) {
  SeparatrixTracer<TMesh> t(m);
  for (size_t i = 1; i + 1 < path.size(); ++i) EXPECT_EQ(t.StraightNext(path[i - 1], path[i]), path[i + 1]);
}

/// A 30 x 40 regular torus; flip(i, j) flips the edge (i, j)-(i + 1, j): (i, j), (i + 1, j) -> v5,
/// (i + 1, j + 1), (i, j - 1) -> v7.
class SeparatrixOnTorus : public ::testing::Test {
 protected:
  SeparatrixOnTorus() : ed(m), t(m) { test::RegularTorus(m, 30, 40); }
  void FlipI(int i, int j) { ASSERT_TRUE(ed.Flip(g(i, j), g(i + 1, j)).ok); }
  TMesh m;
  TorusGrid g{30, 40};
  MeshEditor<TMesh> ed;
  SeparatrixTracer<TMesh> t;
};
}  // namespace

TEST(Separatrix, StraightLineOnAHexPatchEndsAtTheBoundary) {
  TMesh m;
  test::HexPatch(m, 5);
  SeparatrixTracer<TMesh> t(m);
  // every line from the centre reaches the boundary after exactly `radius` edges, along a
  // straight lattice line: the k-th vertex lies at distance k from the centre (unit edges)
  std::vector<Separatrix> all = t.TraceAll(0, 100);
  ASSERT_EQ(all.size(), 6u);
  for (const Separatrix& s : all) {
    EXPECT_EQ(s.end, Separatrix::End::Boundary);
    ASSERT_EQ(s.Length(), 5);
    const vcg::Point3f dir = m.vert[size_t(s.vertices[1])].P() - m.vert[0].P();
    for (int k = 0; k <= 5; ++k)
      EXPECT_NEAR((m.vert[size_t(s.vertices[size_t(k)])].P() - (m.vert[0].P() + dir * float(k))).Norm(), 0.f, 1e-5f);
  }
  Separatrix shortened = t.Trace(0, all[0].vertices[1], 3);
  EXPECT_EQ(shortened.end, Separatrix::End::MaxLength);
  EXPECT_EQ(shortened.Length(), 3);
}

TEST_F(SeparatrixOnTorus, StopsAtTheFirstIrregularVertexOrClosesAroundTheTorus) {
  // a regular line around the tube closes after 40 edges
  Separatrix loop = t.Trace(g(5, 5), g(5, 6), 1000);
  EXPECT_EQ(loop.end, Separatrix::End::Loop);
  EXPECT_EQ(loop.Length(), 40);
  EXPECT_EQ(loop.vertices.back(), g(5, 5));
  // flip edge (10,20)-(11,20): (10,20), (11,20) -> v5, (11,21), (10,19) -> v7
  FlipI(10, 20);
  ASSERT_EQ(ed.Valence(g(10, 19)), 7);
  ASSERT_EQ(ed.Valence(g(10, 20)), 5);
  Separatrix s = t.Trace(g(10, 5), g(10, 6), 1000);  // along j toward the v7 at (10, 19)
  EXPECT_EQ(s.end, Separatrix::End::Irregular);
  ASSERT_EQ(s.Length(), 14);
  for (int k = 0; k <= 14; ++k) EXPECT_EQ(s.vertices[size_t(k)], g(10, 5 + k));
  // the diagonal from (0, 9) passes (10, 19) after 10 edges
  Separatrix d = t.Trace(g(0, 9), g(1, 10), 1000);
  EXPECT_EQ(d.end, Separatrix::End::Irregular);
  EXPECT_EQ(d.Length(), 10);
  EXPECT_EQ(d.vertices.back(), g(10, 19));
  // the separatrices of the v7: seven of them, each ends at an irregular vertex or closes
  std::vector<Separatrix> fromV7 = t.TraceAll(g(10, 19), 1000);
  EXPECT_EQ(fromV7.size(), 7u);
  for (const Separatrix& x : fromV7) ExpectStraight(m, x.vertices);
}

TEST_F(SeparatrixOnTorus, ConnectingPathTurnsAtTheLatticeCorner) {
  FlipI(10, 20);  // b = (10, 19) becomes a v7
  // a = (5, 5), b = (10, 19): lattice offset (5, 14); the graph distance is 14 (5 diagonal
  // steps and 9 along j). Two shortest two-segment paths: turn at (10, 10) (L1 = 5 along the
  // diagonal, L2 = 9) or at (5, 14) (L1 = 9, L2 = 5); ties go to the shorter first segment.
  ConnectingPath p = t.Connect(g(5, 5), g(10, 19), 100);
  ASSERT_TRUE(p) << p.result.reason;
  EXPECT_EQ(p.Length(), 14);
  EXPECT_EQ(p.L1(), 5);
  EXPECT_EQ(p.L2(), 9);
  EXPECT_EQ(p.turn, g(10, 10));
  for (int k = 0; k <= 5; ++k) EXPECT_EQ(p.first[size_t(k)], g(5 + k, 5 + k));
  for (int k = 0; k <= 9; ++k) EXPECT_EQ(p.second[size_t(k)], g(10, 10 + k));
  EXPECT_NE(p.turnTriangles, 3);
  EXPECT_NE(p.turnTriangles, 0);
  ExpectStraight(m, p.first);
  ExpectStraight(m, p.second);
  std::vector<int> all = p.Vertices();
  EXPECT_EQ(all.size(), 15u);
  EXPECT_EQ(std::set<int>(all.begin(), all.end()).size(), all.size());  // simple
  // from the other end: same length, the turn at (5, 14) (shorter first segment from b's side
  // is the j-line from (10, 19) to (10, 10) = 9 or the diagonal to (5, 14) = 5)
  ConnectingPath q = t.Connect(g(10, 19), g(5, 5), 100);
  ASSERT_TRUE(q) << q.result.reason;
  EXPECT_EQ(q.Length(), 14);
  EXPECT_EQ(q.L1(), 5);
  EXPECT_EQ(q.turn, g(5, 14));
}

TEST_F(SeparatrixOnTorus, ConnectingPathIsStraightOnASharedLineAndFailsWhenBlocked) {
  ConnectingPath p = t.Connect(g(5, 5), g(5, 12), 100);
  ASSERT_TRUE(p) << p.result.reason;
  EXPECT_EQ(p.turn, -1);
  EXPECT_EQ(p.Length(), 7);
  EXPECT_TRUE(p.second.empty());
  // too short a bound: no line gets there
  ConnectingPath none = t.Connect(g(5, 5), g(10, 19), 4);
  EXPECT_FALSE(none);
  EXPECT_NE(none.result.reason.find("no path of two straight segments"), std::string::npos);
}

TEST_F(SeparatrixOnTorus, IrregularVertexOnTheWayIsNotATurnPoint) {
  // make (10, 10), the preferred turn point of the previous test, irregular: flip the edge
  // (10,10)-(11,10) ((10,10), (11,10) -> v5; (11,11), (10,9) -> v7), and (10,19) irregular too
  FlipI(10, 20);
  FlipI(10, 10);
  ASSERT_EQ(ed.Valence(g(10, 10)), 5);
  ConnectingPath p = t.Connect(g(5, 5), g(10, 19), 100);
  ASSERT_TRUE(p) << p.result.reason;
  EXPECT_EQ(p.Length(), 14);
  EXPECT_EQ(p.turn, g(5, 14));
  for (int v : p.Vertices())
    if (v != g(5, 5) && v != g(10, 19)) EXPECT_EQ(ed.Valence(v), 6);
}

// Fig. 11's polygon (sec. 7.3): the quadruple a flip generates on the torus (fig. 8) is the
// smallest one: four sides of one edge, opposite sides matching, the four vertices in cyclic
// order. (Translated pairs: Generation.QuadrupleOfAGivenShapeAndItsCancellation.)
TEST_F(SeparatrixOnTorus, QuadruplePolygonOfAGeneratedQuadrupleHasFourUnitSides) {
  // flip (10, 20)-(11, 20): (10, 20), (11, 20) -> v5; (11, 21), (10, 19) -> v7
  FlipI(10, 20);
  const int a5 = g(10, 20), a7 = g(10, 19);
  const int b5 = g(11, 20), b7 = g(11, 21);
  ASSERT_EQ(ed.Valence(a5), 5);
  ASSERT_EQ(ed.Valence(a7), 7);
  QuadruplePolygon P0 = t.Polygon({a5, a7, b5, b7}, 50);
  ASSERT_TRUE(P0.result.ok) << P0.result.reason;
  EXPECT_TRUE(P0.OppositeSidesMatch()) << P0.Sides();
  std::set<int> order(P0.order, P0.order + 4);
  EXPECT_EQ(order, (std::set<int>{a5, a7, b5, b7}));
  for (int i = 0; i < 4; ++i) EXPECT_EQ(P0.x[i] + P0.y[i], 1) << P0.Sides();  // four edges of one
}
