// Unit tests of vcg_ext/irregular/stripe_pattern.h: stripes, zebra and lattice cells on
// constructed lattices where the strips and cells are known exactly (issue 15).
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <vector>

#include <vcg_ext/irregular/composite_ops.h>
#include <vcg_ext/irregular/stripe_pattern.h>

#include "composite_test_util.h"
#include "test_mesh.h"
#include "test_util.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {
int Vi(TMesh& m, int f, int z) { return int(vcg::tri::Index(m, m.face[size_t(f)].V(z))); }

/// Faces that share an edge and lie in different regions: (region a, region b) pairs.
std::set<std::pair<int, int>> RegionContacts(TMesh& m, const PatternLabels& p) {
  std::set<std::pair<int, int>> r;
  for (size_t f = 0; f < m.face.size(); ++f)
    for (int i = 0; i < 3; ++i) {
      const size_t g = vcg::tri::Index(m, m.face[f].FFp(i));
      if (g != f && p.faceRegion[f] != p.faceRegion[g]) r.insert({p.faceRegion[f], p.faceRegion[g]});
    }
  return r;
}

/// Vertices within `rings` edges of the irregular vertices.
std::set<int> NearIrregular(TMesh& m, int rings) {
  std::set<int> near;
  for (auto& kv : test::Irregular(m)) near.insert(kv.first);
  for (int r = 0; r < rings; ++r) {
    std::set<int> next = near;
    for (auto& f : m.face) {
      bool touches = false;
      for (int z = 0; z < 3; ++z) touches |= near.count(int(vcg::tri::Index(m, f.V(z)))) > 0;
      if (touches)
        for (int z = 0; z < 3; ++z) next.insert(int(vcg::tri::Index(m, f.V(z))));
    }
    near.swap(next);
  }
  return near;
}
}  // namespace

// On test::RegularTorus(n, k), vertex (i, j) has index i * k + j and face 0 is
// ((0,0), (1,0), (1,1)): its edge 0 runs along i (lines j = const: k loops, k strips), edge 1
// along j (n strips), edge 2 along the diagonal (gcd(n, k) loops). Each strip is one row of
// triangles between two consecutive loops; n, k multiples of 3 make the 3-colouring (i + j) % 3
// consistent, so the one-rings of its colour-0 vertices tile the torus with n k / 3 hexagons.
TEST(StripePattern, RegularTorusEveryStripWidthOneEveryCellAHexagon) {
  const int n = 12, k = 6;
  TMesh m;
  test::RegularTorus(m, n, k);
  const int expectedStrips[3] = {k, n, 6};
  for (int d = 0; d < 3; ++d) {
    SCOPED_TRACE(d);
    StripeOptions o;
    o.direction = d;
    StripeField fd;
    PatternLabels p = ComputeStripes(m, o, &fd);
    ASSERT_TRUE(p.ok) << p.reason;
    EXPECT_EQ(p.measures.strips, expectedStrips[d]);
    EXPECT_EQ(p.measures.stripWidthHistogram, (std::vector<int>{0, expectedStrips[d]}));
    EXPECT_EQ(p.measures.conflictFaces, 0);
    EXPECT_EQ(p.measures.conflictRegions, 0);
    EXPECT_EQ(p.measures.cells, n * k / 3);
    EXPECT_EQ(p.measures.nonHexagonalCells, 0);
    ASSERT_GE(p.measures.cellSidesHistogram.size(), 7u);
    EXPECT_EQ(p.measures.cellSidesHistogram[6], n * k / 3);
    ASSERT_EQ(int(p.regionKind.size()), expectedStrips[d]);
    // every face's direction edge is parallel to the seed's (d = 0: same j; 1: same i; 2: diagonal),
    // and a strip is exactly the row of faces between two consecutive lines
    std::map<int, std::set<int>> rowsOfRegion;
    std::vector<int> facesOfRegion(p.regionKind.size(), 0);
    for (int f = 0; f < int(m.face.size()); ++f) {
      const int e = fd.direction[size_t(f)];
      ASSERT_GE(e, 0);
      const int a = Vi(m, f, e), b = Vi(m, f, (e + 1) % 3);
      const int di = ((b / k - a / k) % n + n) % n, dj = ((b % k - a % k) % k + k) % k;
      if (d == 0) EXPECT_TRUE(dj == 0 && (di == 1 || di == n - 1));
      if (d == 1) EXPECT_TRUE(di == 0 && (dj == 1 || dj == k - 1));
      if (d == 2) EXPECT_TRUE((di == 1 && dj == 1) || (di == n - 1 && dj == k - 1));
      // the row: the line coordinate of the direction edge and of the apex
      const int c = Vi(m, f, (e + 2) % 3);
      auto lineOf = [&](int v) { return d == 0 ? v % k : d == 1 ? v / k : ((v / k - v % k) % 6 + 6) % 6; };
      EXPECT_NE(lineOf(a), lineOf(c));
      rowsOfRegion[p.faceRegion[size_t(f)]].insert(std::min(lineOf(a), lineOf(c)) * 100 + std::max(lineOf(a), lineOf(c)));
      facesOfRegion[size_t(p.faceRegion[size_t(f)])] += 1;
      EXPECT_TRUE(p.regionKind[size_t(p.faceRegion[size_t(f)])] == RegionKind::StripeA ||
                  p.regionKind[size_t(p.faceRegion[size_t(f)])] == RegionKind::StripeB);
    }
    std::set<int> rows;
    for (auto& kv : rowsOfRegion) {
      EXPECT_EQ(kv.second.size(), 1u) << "strip " << kv.first << " spans several rows";
      rows.insert(*kv.second.begin());
    }
    EXPECT_EQ(int(rows.size()), expectedStrips[d]);  // different strips, different rows
    for (int c : facesOfRegion) EXPECT_EQ(c, 2 * n * k / expectedStrips[d]);
    // alternation: neighbouring strips differ (even number of strips, period 2)
    for (auto& ab : RegionContacts(m, p))
      EXPECT_NE(p.regionKind[size_t(ab.first)], p.regionKind[size_t(ab.second)]) << ab.first << " " << ab.second;
    // the seed's strip is region 0, kind A
    EXPECT_EQ(p.faceRegion[0], 0);
    EXPECT_EQ(p.regionKind[0], RegionKind::StripeA);
    // the zebra of a regular torus is the same pattern
    PatternLabels z = ComputeZebra(m, o);
    EXPECT_EQ(z.faceRegion, p.faceRegion);
  }
}

TEST(StripePattern, PeriodThreeAlternatesABB) {
  TMesh m;
  test::RegularTorus(m, 12, 6);
  StripeOptions o;
  o.direction = 1;  // 12 strips, a cycle of 12: levels 0..6 from the seed's strip
  o.period = 3;
  PatternLabels p = ComputeStripes(m, o);
  ASSERT_TRUE(p.ok);
  int a = 0;
  for (RegionKind k : p.regionKind) a += k == RegionKind::StripeA;
  EXPECT_EQ(a, 4);  // levels 0, 3, 6 (6 is one strip: the far side of the cycle), 3 twice
  for (auto& ab : RegionContacts(m, p))  // never two A strips side by side
    EXPECT_FALSE(p.regionKind[size_t(ab.first)] == RegionKind::StripeA &&
                 p.regionKind[size_t(ab.second)] == RegionKind::StripeA);
}

// Two 5-7 pairs (a quadruple generated on a 40 x 40 torus, one pair moved 6 steps away): the
// lines that stop at the four irregular vertices no longer separate strips, so the strips
// along them have width two or more; every other strip keeps width one; the direction's
// holonomy around each pair is zero (60 degrees at the 5, -60 at the 7), so the stripes'
// conflicts stay next to the pairs; the zebra has none.
TEST(StripePattern, FiveSevenPairsMakeWideStripsOnlyAlongTheirLines) {
  const int N = 40;
  TMesh m;
  test::RegularTorus(m, N, N);
  {
    MeshEditor<TMesh> ed(m);
    CompositeOptions copt;
    copt.relax = false;
    CompositeOperations<TMesh> co(ed, nullptr, copt);
    CompositeOutcome g = co.GenerateQuadrupleShape(20 * N + 20, 0, 4, 6, 4, 0);
    ASSERT_TRUE(g) << g.result.reason;
    ed.Commit();
  }
  const auto irregular = test::Irregular(m);
  ASSERT_EQ(irregular.size(), 4u);
  const std::set<int> near2 = NearIrregular(m, 2);
  const test::MeshSnapshot before = test::Snapshot(m);
  for (int d = 0; d < 3; ++d) {
    SCOPED_TRACE(d);
    StripeOptions o;
    o.direction = d;
    StripeField fd;
    PatternLabels p = ComputeStripes(m, o, &fd);
    ASSERT_TRUE(p.ok);
    int wide = 0;
    for (int w = 2; w < int(p.measures.stripWidthHistogram.size()); ++w) wide += p.measures.stripWidthHistogram[size_t(w)];
    EXPECT_GE(wide, 1) << "a line stops at the pairs: some strip is wider than one";
    EXPECT_LE(wide, 4);
    EXPECT_GT(p.measures.conflictFaces, 0);
    // wide strips touch an irregular vertex (the end of the line inside them); strips that do
    // not touch one are single rows
    std::vector<char> touches(p.regionKind.size(), 0);
    for (size_t f = 0; f < m.face.size(); ++f)
      for (int z = 0; z < 3; ++z)
        if (irregular.count(Vi(m, int(f), z))) touches[size_t(p.faceRegion[f])] = 1;
    for (int r = 0; r < p.measures.strips; ++r)
      if (fd.stripWidth[size_t(r)] > 1) EXPECT_TRUE(touches[size_t(r)]) << "strip " << r;
    // incomplete lines end at the irregular vertices: every line edge at an irregular vertex is
    // on an incomplete line, and every incomplete line has such an edge
    std::set<int> incomplete, incompleteAtIrregular;
    for (size_t f = 0; f < m.face.size(); ++f)
      for (int i = 0; i < 3; ++i) {
        const int l = fd.lineOf[3 * f + size_t(i)];
        if (l < 0) continue;
        const bool atIrr = irregular.count(Vi(m, int(f), i)) || irregular.count(Vi(m, int(f), (i + 1) % 3));
        if (!fd.lineComplete[size_t(l)]) incomplete.insert(l);
        if (!fd.lineComplete[size_t(l)] && atIrr) incompleteAtIrregular.insert(l);
        if (atIrr && p.regionKind[size_t(p.faceRegion[f])] != RegionKind::Conflict) EXPECT_FALSE(fd.lineComplete[size_t(l)]);
      }
    EXPECT_EQ(incomplete, incompleteAtIrregular);
    // conflicts only next to the pairs
    for (size_t f = 0; f < m.face.size(); ++f)
      if (p.regionKind[size_t(p.faceRegion[f])] == RegionKind::Conflict) {
        bool close = false;
        for (int z = 0; z < 3; ++z) close |= near2.count(Vi(m, int(f), z)) > 0;
        EXPECT_TRUE(close) << "conflict face " << f << " far from the pairs";
      }
    StripeField fz;
    PatternLabels z = ComputeZebra(m, o, &fz);
    EXPECT_EQ(z.measures.conflictFaces, 0);
    for (size_t f = 0; f < m.face.size(); ++f) EXPECT_LT(z.faceRegion[f], z.measures.strips);
    // the zebra's seams are on its cut tree and touch the pairs: the turns of a 5-7 pair cancel,
    // so no seam runs between the two pairs
    int seams = 0;
    for (size_t e = 0; e < fz.inconsistent.size(); ++e)
      if (fz.inconsistent[e]) {
        ++seams;
        EXPECT_TRUE(fz.cutTree[e]);
        const int f = int(e / 3), i = int(e % 3);
        EXPECT_TRUE(irregular.count(Vi(m, f, i)) || irregular.count(Vi(m, f, (i + 1) % 3))) << "seam edge " << e;
      }
    EXPECT_GT(seams, 0);
  }
  EXPECT_TRUE(test::Snapshot(m) == before) << "the patterns must not change the mesh";
}

// The icosphere's twelve v5: a cell centred at a v5 is a pentagon; around a v5 the carried
// direction comes back turned, so the stripes have conflicts and the zebra has seams (edges
// whose two faces' directions disagree) but no conflict face: every face is in a strip. The mesh is bit-identical after.
TEST(StripePattern, FiveValentCentreGivesAPentagonAndSeams) {
  TMesh m;
  test::Icosphere(m, 2);
  const test::MeshSnapshot before = test::Snapshot(m);
  int seed = -1, z5 = -1;
  const auto irregular = test::Irregular(m);
  ASSERT_EQ(irregular.size(), 12u);
  for (size_t f = 0; f < m.face.size() && seed < 0; ++f)
    for (int z = 0; z < 3; ++z)
      if (irregular.count(Vi(m, int(f), z))) seed = int(f), z5 = z;
  StripeOptions o;
  o.seedFace = seed;
  o.direction = (z5 + 1) % 3;  // the apex V((d + 2) % 3) is the v5: a cell centre
  PatternLabels p = ComputeStripes(m, o);
  ASSERT_TRUE(p.ok);
  ASSERT_GE(p.measures.cellSidesHistogram.size(), 6u);
  EXPECT_GE(p.measures.cellSidesHistogram[5], 1);
  EXPECT_GE(p.measures.cellSidesHistogram[6], 1);
  EXPECT_EQ(p.measures.nonHexagonalCells, p.measures.cells - p.measures.cellSidesHistogram[6]);
  EXPECT_GT(p.measures.conflictFaces, 0);
  EXPECT_GT(p.measures.conflictRegions, 0);
  StripeField fz;
  PatternLabels z = ComputeZebra(m, o, &fz);
  ASSERT_TRUE(z.ok);
  EXPECT_EQ(z.measures.conflictFaces, 0);
  int seams = 0;
  for (size_t e = 0; e < fz.inconsistent.size(); ++e) {
    seams += fz.inconsistent[e];
    if (fz.inconsistent[e]) EXPECT_TRUE(fz.cutTree[e]) << "the zebra's seams lie on the cut tree";
  }
  EXPECT_GT(seams, 0);
  // every face is in a strip; across a seam the direction is turned (the carried direction
  // differs from the neighbour's own), everywhere else it agrees
  for (size_t f = 0; f < m.face.size(); ++f) {
    EXPECT_LT(z.faceRegion[f], z.measures.strips);
    for (int i = 0; i < 3; ++i) {
      const size_t g = vcg::tri::Index(m, m.face[f].FFp(i));
      const bool agrees = CarryDirection(m, int(f), fz.direction[f], i) == fz.direction[g];
      EXPECT_EQ(agrees, !fz.inconsistent[3 * f + size_t(i)]);
    }
  }
  EXPECT_TRUE(test::Snapshot(m) == before);
}

TEST(StripePattern, CarryDirectionIsSymmetric) {
  TMesh m;
  test::Icosphere(m, 2);
  for (int f = 0; f < int(m.face.size()); ++f)
    for (int d = 0; d < 3; ++d)
      for (int i = 0; i < 3; ++i) {
        const int g = int(vcg::tri::Index(m, m.face[size_t(f)].FFp(i)));
        const int dg = CarryDirection(m, f, d, i);
        ASSERT_GE(dg, 0);
        EXPECT_EQ(CarryDirection(m, g, dg, m.face[size_t(f)].FFi(i)), d);
      }
}

TEST(StripePattern, RefusesBadRequests) {
  TMesh m;
  test::HexPatch(m, 3);
  StripeOptions o;
  o.direction = 3;
  EXPECT_FALSE(ComputeStripes(m, o).ok);
  o.direction = 0;
  o.seedFace = int(m.face.size());
  EXPECT_FALSE(ComputeStripes(m, o).ok);
  o.seedFace = -1;
  o.seedVertex = int(m.vert.size()) + 5;
  EXPECT_FALSE(ComputeZebra(m, o).ok);
  o.seedVertex = 0;
  o.period = 0;
  EXPECT_FALSE(ComputeStripes(m, o).ok);
  o.period = 2;
  PatternLabels p = ComputeStripes(m, o);  // a flat patch: lines end on the boundary, width one
  ASSERT_TRUE(p.ok);
  EXPECT_EQ(p.measures.conflictFaces, 0);
  EXPECT_EQ(p.measures.stripWidthHistogram, (std::vector<int>{0, 6}));
}
