// SampleGrid (vcg_ext/irregular/sample_grid.h): a box query returns exactly the points inside
// the box, each once, for boxes of every size against blocks of cells, on both sides of the
// origin (the block of a negative cell index is a floor division).
#include <algorithm>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <vcg_ext/irregular/sample_grid.h>

using vcg_ext::irregular::SampleGrid;

namespace {

std::vector<int> BruteForce(const std::vector<vcg::Point3f>& pts, const vcg::Box3<float>& box) {
  std::vector<int> in;
  for (size_t i = 0; i < pts.size(); ++i)
    if (box.IsIn(pts[i])) in.push_back(int(i));
  return in;
}

TEST(SampleGrid, BoxQueryFindsExactlyThePointsInside) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> coord(-5.f, 5.f), size(0.f, 4.f);
  std::vector<vcg::Point3f> pts, nrm;
  // clustered like sharp-edge samples: along a few lines, so most blocks are empty
  for (int line = 0; line < 6; ++line) {
    const vcg::Point3f a(coord(rng), coord(rng), coord(rng)), b(coord(rng), coord(rng), coord(rng));
    for (int k = 0; k <= 200; ++k) pts.push_back(a + (b - a) * (float(k) / 200.f));
  }
  pts.push_back(vcg::Point3f(0, 0, 0));  // on cell and block borders
  pts.push_back(vcg::Point3f(-0.25f, 0.25f, -2.f));
  nrm.assign(pts.size(), vcg::Point3f(0, 0, 1));
  SampleGrid grid;
  grid.Build(pts, nrm, 0.25);  // blocks of 8 cells: 2 units
  ASSERT_EQ(grid.Size(), pts.size());
  int nonEmpty = 0;
  for (int q = 0; q < 400; ++q) {
    // half of the boxes start next to a point, so that they find some
    vcg::Point3f c(coord(rng), coord(rng), coord(rng));
    if (q % 2) c = pts[size_t(rng() % pts.size())] - vcg::Point3f(0.3f, 0.3f, 0.3f);
    vcg::Box3<float> box(c, c);
    box.Add(c + vcg::Point3f(size(rng), size(rng), size(rng)) * (q % 4 == 0 ? 1.f : 0.1f));
    std::vector<int> got = grid.InBox(box);
    std::sort(got.begin(), got.end());
    EXPECT_EQ(std::adjacent_find(got.begin(), got.end()), got.end()) << "a point twice, query " << q;
    const std::vector<int> want = BruteForce(pts, box);
    EXPECT_EQ(got, want) << "query " << q;
    nonEmpty += !want.empty();
  }
  EXPECT_GT(nonEmpty, 40);  // the queries do hit points
  // a box whose corners sit exactly on points, across the origin
  vcg::Box3<float> exact(vcg::Point3f(-0.25f, 0.f, -2.f), vcg::Point3f(0.f, 0.25f, 0.f));
  std::vector<int> got = grid.InBox(exact);
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, BruteForce(pts, exact));
  EXPECT_GE(got.size(), 2u);
  EXPECT_TRUE(grid.InBox(vcg::Box3<float>()).empty());  // a null box
  SampleGrid empty;
  empty.Build({}, {}, 1.0);
  EXPECT_TRUE(empty.InBox(exact).empty());
}

TEST(SampleGrid, SamplesAtOnePointWithOneTagAreOnePointWithTheirDistinctNormals) {
  const vcg::Point3f a(0.5f, 0.5f, 0.5f), b(1.5f, 0.5f, -0.f), b0(1.5f, 0.5f, 0.f);
  const vcg::Point3f up(0, 0, 1), down(0, 0, -1), side(1, 0, 0);
  // a three times (two normals, one of them twice), b twice with tag 0 (as -0 and 0) and once
  // with tag 1 (a crease sample stays apart: its bound differs)
  const std::vector<vcg::Point3f> pts{a, b, a, b0, a, b};
  const std::vector<vcg::Point3f> nrm{up, up, down, side, up, down};
  const std::vector<char> tags{0, 0, 0, 0, 0, 1};
  SampleGrid grid;
  std::vector<int> merged;
  grid.Build(pts, nrm, 0.25, tags, &merged);
  ASSERT_EQ(grid.Size(), 3u);
  // which merged point each sample became (the guard seeds its witnesses through it)
  EXPECT_EQ(merged, (std::vector<int>{0, 1, 0, 1, 0, 2}));
  // merged in the order first seen
  EXPECT_EQ(grid.Point(0), a);
  EXPECT_EQ(grid.Point(1), b);
  EXPECT_EQ(grid.Point(2), b);
  EXPECT_EQ(grid.Tag(0), 0);
  EXPECT_EQ(grid.Tag(1), 0);
  EXPECT_EQ(grid.Tag(2), 1);
  EXPECT_EQ(std::vector<vcg::Point3f>(grid.NormalsBegin(0), grid.NormalsEnd(0)), (std::vector<vcg::Point3f>{up, down}));
  EXPECT_EQ(std::vector<vcg::Point3f>(grid.NormalsBegin(1), grid.NormalsEnd(1)), (std::vector<vcg::Point3f>{up, side}));
  EXPECT_EQ(std::vector<vcg::Point3f>(grid.NormalsBegin(2), grid.NormalsEnd(2)), (std::vector<vcg::Point3f>{down}));
  // "does any of its normals ..." answers as over the separate samples
  auto facesX = [](const vcg::Point3f& n) { return n[0] > 0; };
  EXPECT_FALSE(grid.AnyNormal(0, facesX));
  EXPECT_TRUE(grid.AnyNormal(1, facesX));
  EXPECT_FALSE(grid.AnyNormal(2, facesX));
  // a box around b finds both of b's points once each; without tags everything at b is one
  std::vector<int> got = grid.InBox(vcg::Box3<float>(b - vcg::Point3f(0.1f, 0.1f, 0.1f), b + vcg::Point3f(0.1f, 0.1f, 0.1f)));
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, (std::vector<int>{1, 2}));
  SampleGrid untagged;
  untagged.Build(pts, nrm, 0.25);
  ASSERT_EQ(untagged.Size(), 2u);
  EXPECT_EQ(untagged.NormalsEnd(1) - untagged.NormalsBegin(1), 3);
}

}  // namespace
