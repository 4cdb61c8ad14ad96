// Unit tests of vcg_ext/irregular/star_pattern.h (paper sec. 10, Fig. 12): stars on flat
// lattices with one vertex of valence n in the middle and on the subdivided icosahedron,
// where the arms, the faces and the isolation of each seed are known exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include <vcg_ext/irregular/mesh_checks.h>
#include <vcg_ext/irregular/star_pattern.h>

#include "test_mesh.h"
#include "test_pattern_mesh.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {
std::set<int> FacesOfRegion(const PatternLabels& P, int r) {
  std::set<int> s;
  for (size_t i = 0; i < P.faceRegion.size(); ++i)
    if (P.faceRegion[i] == r) s.insert(int(i));
  return s;
}
/// Faces incident to any of the vertices, from the face list alone.
std::set<int> FacesAround(TMesh& m, const std::set<int>& verts) {
  std::set<int> s;
  for (size_t i = 0; i < m.face.size(); ++i)
    for (int z = 0; z < 3; ++z)
      if (verts.count(int(vcg::tri::Index(m, m.face[i].V(z))))) s.insert(int(i));
  return s;
}
/// Faces in both stars.
std::set<int> Intersection(const std::vector<int>& sa, const std::vector<int>& sb) {
  std::set<int> both;
  for (int f : sa)
    if (std::find(sb.begin(), sb.end(), f) != sb.end()) both.insert(f);
  return both;
}
}  // namespace

// A flat patch with one v5 in the middle: the star has 5 arms along the sector axes, each of
// exactly R edges; its faces are those around the centre and around the axis vertices of
// rings 1 .. R-1 (the last edge's faces lie around ring R-1's axis vertex): 20R - 20 faces.
TEST(StarPattern, OneV5HasFiveArmsOfExactLengthAndIsIsolated) {
  TMesh m;
  test::NGonPatch(m, 5, 7);
  ASSERT_TRUE(CheckInvariants(m).ok);
  for (int R = 1; R <= 5; ++R) {
    StarOptions o;  // default seeds: every interior v5, here only the centre
    o.radius = R;
    PatternLabels P = ComputeStars(m, o);
    ASSERT_TRUE(P.ok) << P.reason;
    ASSERT_EQ(P.regionKind, (std::vector<RegionKind>{RegionKind::Star, RegionKind::Background}));
    std::set<int> centres{0};
    for (int k = 1; k < R; ++k)
      for (int s = 0; s < 5; ++s) centres.insert(test::NGonIndex(5, k, s, 0));
    const std::set<int> star = FacesOfRegion(P, 0);
    EXPECT_EQ(star, FacesAround(m, centres)) << "R = " << R;
    EXPECT_EQ(int(star.size()), R == 1 ? 5 : 20 * R - 20);
    // each arm's tip (axis vertex of ring R) is on the star, the axis vertex of ring R+1 is not
    for (int s = 0; s < 5; ++s) {
      EXPECT_FALSE(FacesAround(m, {test::NGonIndex(5, R, s, 0)}).empty());
      std::set<int> tip = FacesAround(m, {test::NGonIndex(5, R, s, 0)}), beyond = FacesAround(m, {test::NGonIndex(5, R + 1, s, 0)});
      int onStar = 0, beyondOnStar = 0;
      for (int f : tip) onStar += star.count(f) ? 1 : 0;
      for (int f : beyond) beyondOnStar += star.count(f) ? 1 : 0;
      EXPECT_EQ(onStar, R == 1 ? 2 : 2) << "the last edge's two faces";
      EXPECT_EQ(beyondOnStar, 0);
    }
    EXPECT_EQ(P.measures.starSeeds, 1);
    EXPECT_EQ(P.measures.isolatedStarSeeds, 1);
    EXPECT_EQ(P.measures.conflictRegions, 0);
    EXPECT_EQ(P.measures.conflictFaces, 0);
  }
}

// A v7 seed given explicitly has 7 arms: 28R - 28 faces.
TEST(StarPattern, SelectedV7SeedHasSevenArms) {
  TMesh m;
  test::NGonPatch(m, 7, 6);
  StarOptions o;
  o.seeds = {0};
  o.radius = 3;
  PatternLabels P = ComputeStars(m, o);
  ASSERT_TRUE(P.ok) << P.reason;
  EXPECT_EQ(int(FacesOfRegion(P, 0).size()), 28 * 3 - 28);
  EXPECT_EQ(P.measures.isolatedStarSeeds, 1);
  // a regular patch has no v5 to seed from: refused with a reason
  TMesh h;
  test::NGonPatch(h, 6, 4);
  PatternLabels Q = ComputeStars(h, StarOptions());
  EXPECT_FALSE(Q.ok);
  EXPECT_NE(Q.reason.find("no interior v5"), std::string::npos);
  o.seeds = {100000};
  EXPECT_FALSE(ComputeStars(h, o).ok);
}

// Two v5 two edges apart, made by a flip (their two common neighbours become v7): neither is
// isolated. Their arms through the v7 stop there and the others point away from each other,
// so the stars share no face: no conflict.
TEST(StarPattern, TwoCloseV5AreNotIsolated) {
  TMesh m;
  test::NGonPatch(m, 6, 8);
  const int a = test::NGonIndex(6, 3, 0, 1), b = test::NGonIndex(6, 3, 0, 2);
  bool flipped = false;
  for (auto& f : m.face)
    for (int z = 0; z < 3 && !flipped; ++z)
      if ((vcg::tri::Index(m, f.V(z)) == size_t(a) && vcg::tri::Index(m, f.V((z + 1) % 3)) == size_t(b)) ||
          (vcg::tri::Index(m, f.V(z)) == size_t(b) && vcg::tri::Index(m, f.V((z + 1) % 3)) == size_t(a))) {
        ASSERT_TRUE(vcg::face::CheckFlipEdge(f, z));
        vcg::face::FlipEdge(f, z);
        flipped = true;
      }
  ASSERT_TRUE(flipped);
  test::UpdateTopology(m);
  ASSERT_TRUE(CheckInvariants(m).ok);
  ASSERT_EQ(Valence<TMesh>(&m.vert[size_t(a)]), 5);
  ASSERT_EQ(Valence<TMesh>(&m.vert[size_t(b)]), 5);
  StarOptions o;
  o.radius = 3;
  PatternLabels P = ComputeStars(m, o);
  ASSERT_TRUE(P.ok) << P.reason;
  EXPECT_EQ(P.measures.starSeeds, 2);
  EXPECT_EQ(P.measures.isolatedStarSeeds, 0);
  const std::vector<int> sa = StarFaces(m, a, 3), sb = StarFaces(m, b, 3);
  const std::set<int> both = Intersection(sa, sb);
  EXPECT_TRUE(both.empty());
  std::set<int> conflict;
  for (size_t i = 0; i < P.faceRegion.size(); ++i)
    if (P.regionKind[size_t(P.faceRegion[i])] == RegionKind::Conflict) conflict.insert(int(i));
  EXPECT_EQ(conflict, both);
  EXPECT_EQ(P.measures.conflictFaces, int(both.size()));
  EXPECT_EQ(P.measures.conflictRegions, 0);
  EXPECT_EQ(P.regionKind, (std::vector<RegionKind>{RegionKind::Star, RegionKind::Star, RegionKind::Background}));
  // every face has a region, ids dense
  for (int r : P.faceRegion) EXPECT_TRUE(r >= 0 && r < int(P.regionKind.size()));
}

// Two selected seeds two edges apart on one axis of a regular patch: the faces both stars
// claim, exactly the intersection of the two stars, are one Conflict region; no irregular
// vertex anywhere, so both seeds are isolated.
TEST(StarPattern, OverlappingSelectedStarsConflict) {
  TMesh m;
  test::NGonPatch(m, 6, 8);
  const int a = 0, b = test::NGonIndex(6, 2, 0, 0);
  StarOptions o;
  o.seeds = {a, b};
  o.radius = 2;
  PatternLabels P = ComputeStars(m, o);
  ASSERT_TRUE(P.ok) << P.reason;
  EXPECT_EQ(P.measures.isolatedStarSeeds, 2);
  const std::vector<int> sa = StarFaces(m, a, 2), sb = StarFaces(m, b, 2);
  EXPECT_EQ(sa.size(), 24u);
  EXPECT_EQ(sb.size(), 24u);
  const std::set<int> both = Intersection(sa, sb);
  std::set<int> conflict, onlyA, onlyB;
  for (size_t i = 0; i < P.faceRegion.size(); ++i) {
    const RegionKind k = P.regionKind[size_t(P.faceRegion[i])];
    if (k == RegionKind::Conflict) conflict.insert(int(i));
    if (P.faceRegion[i] == 0) onlyA.insert(int(i));
    if (P.faceRegion[i] == 1) onlyB.insert(int(i));
  }
  EXPECT_FALSE(both.empty());
  EXPECT_EQ(conflict, both);
  EXPECT_EQ(P.measures.conflictFaces, int(both.size()));
  EXPECT_EQ(P.measures.conflictRegions, 1);
  EXPECT_EQ(onlyA.size() + both.size(), 24u);
  EXPECT_EQ(onlyB.size() + both.size(), 24u);
}

// The subdivided icosahedron: 12 v5 at distance 4 along the icosahedron's edges. Radius 3:
// every seed is isolated, and along each of the 30 edges the two stars meet on the fan of the
// edge's middle vertex (6 faces): 30 conflict regions, 180 faces. Radius 4: none isolated.
TEST(StarPattern, IcosphereStarsMeetOnEveryEdge) {
  TMesh m;
  test::Icosphere(m, 2);
  StarOptions o;
  o.radius = 3;
  PatternLabels P = ComputeStars(m, o);
  ASSERT_TRUE(P.ok) << P.reason;
  EXPECT_EQ(P.measures.starSeeds, 12);
  EXPECT_EQ(P.measures.isolatedStarSeeds, 12);
  EXPECT_EQ(P.measures.conflictRegions, 30);
  EXPECT_EQ(P.measures.conflictFaces, 180);
  o.radius = 4;
  P = ComputeStars(m, o);
  EXPECT_EQ(P.measures.isolatedStarSeeds, 0);
  o.radius = 1;
  P = ComputeStars(m, o);
  EXPECT_EQ(P.measures.conflictFaces, 0);
  EXPECT_EQ(P.regionKind.size(), 13u);
}
