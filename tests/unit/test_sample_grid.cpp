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

}  // namespace
