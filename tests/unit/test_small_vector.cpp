// SmallVector (small_vector.h): the vector of vertex stars. Checked against std::vector on the
// same operations, across the inline room's bound (N) in both directions, and the copies and
// moves between an inline and a heap-backed vector that the stars go through.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include <vcg_ext/irregular/small_vector.h>
#include <vcg_ext/irregular/topology.h>

#include "test_mesh.h"

using vcg_ext::irregular::Corner;
using vcg_ext::irregular::SmallVector;

namespace {

template <size_t N>
void ExpectSame(const SmallVector<int, N>& s, const std::vector<int>& v) {
  ASSERT_EQ(s.size(), v.size());
  EXPECT_EQ(s.empty(), v.empty());
  EXPECT_TRUE(std::equal(v.begin(), v.end(), s.begin()));
  EXPECT_EQ(s.end() - s.begin(), std::ptrdiff_t(v.size()));
  if (!v.empty()) {
    EXPECT_EQ(s.front(), v.front());
    EXPECT_EQ(s.back(), v.back());
  }
  EXPECT_GE(s.capacity(), s.size());
}

}  // namespace

TEST(SmallVector, RandomOperationsMatchStdVectorAcrossTheInlineBound) {
  std::mt19937 rng(7);
  for (int round = 0; round < 200; ++round) {
    SmallVector<int, 4> s;
    std::vector<int> v;
    for (int op = 0; op < 60; ++op) {
      const int kind = int(rng() % 10);
      if (kind < 5) {
        const int x = int(rng() % 1000);
        s.push_back(x), v.push_back(x);
      } else if (kind == 5 && !v.empty()) {
        // push_back of one of its own elements while it grows (the copy before reserve)
        s.push_back(s[0]), v.push_back(v[0]);
      } else if (kind == 6 && !v.empty()) {
        const size_t a = rng() % v.size(), b = a + rng() % (v.size() - a + 1);
        s.erase(s.begin() + a, s.begin() + b), v.erase(v.begin() + long(a), v.begin() + long(b));
      } else if (kind == 7) {
        const size_t n = rng() % 12;
        const int x = int(rng() % 1000);
        s.resize(n, x), v.resize(n, x);
      } else if (kind == 8) {
        SmallVector<int, 4> copy(s);  // copy construction, then the original is changed
        ExpectSame(copy, v);
        s.push_back(-1);
        ExpectSame(copy, v);
        v.push_back(-1);
      } else {
        if (rng() % 4 == 0) s.clear(), v.clear();
      }
      ExpectSame(s, v);
      if (::testing::Test::HasFailure()) return;
    }
  }
}

TEST(SmallVector, MovesAndCopiesBetweenInlineAndHeapKeepTheElements) {
  for (size_t a : {0u, 3u, 4u, 5u, 40u})
    for (size_t b : {0u, 3u, 4u, 5u, 40u}) {
      SmallVector<int, 4> x, y;
      std::vector<int> vx, vy;
      for (size_t i = 0; i < a; ++i) x.push_back(int(i)), vx.push_back(int(i));
      for (size_t i = 0; i < b; ++i) y.push_back(int(100 + i)), vy.push_back(int(100 + i));
      SmallVector<int, 4> moved(std::move(x));  // x is left empty and usable
      ExpectSame(moved, vx);
      ExpectSame(x, {});
      x.push_back(9);
      ExpectSame(x, {9});
      moved = y;  // copy assignment over an inline or heap-backed vector
      ExpectSame(moved, vy);
      ExpectSame(y, vy);
      y = std::move(moved);  // move assignment
      ExpectSame(y, vy);
      ExpectSame(moved, {});
      const SmallVector<int, 4>& self = y;
      y = self;  // self-assignment keeps everything
      ExpectSame(y, vy);
      // a moved-from heap-backed vector grows again from its inline room
      for (int i = 0; i < 10; ++i) moved.push_back(i);
      ExpectSame(moved, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
    }
}

TEST(SmallVector, HoldsStarCornersWithTheirValues) {
  // Corner has default member initializers (a null face): the inline room is raw bytes, and
  // what is read back is what was pushed, never a default.
  test::TMesh m;
  vcg::tri::Allocator<test::TMesh>::AddFaces(m, 3);
  SmallVector<Corner<test::TFace>, 2> s;
  for (int i = 0; i < 7; ++i) s.push_back(Corner<test::TFace>{&m.face[size_t(i % 3)], i % 3});
  ASSERT_EQ(s.size(), 7u);
  for (int i = 0; i < 7; ++i) {
    EXPECT_EQ(s[size_t(i)].f, &m.face[size_t(i % 3)]);
    EXPECT_EQ(s[size_t(i)].z, i % 3);
  }
  s.resize(9);  // new elements take T's default: a null face
  EXPECT_EQ(s[8].f, nullptr);
  EXPECT_EQ(s[8].z, 0);
}
