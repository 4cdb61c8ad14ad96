// Test meshes for the pattern tests (star_pattern.h, circle_pattern.h, pattern_panels.h):
// a flat patch with one vertex of any valence in the middle.
#pragma once

#include <cmath>
#include <vector>

#include "test_mesh.h"

namespace test {

/// Index of the vertex of ring k (1..R), sector s (0..n-1), position i (0..k-1) in NGonPatch.
inline int NGonIndex(int n, int k, int s, int i) {
  if (k == 0) return 0;
  const int first = 1 + n * (k - 1) * k / 2;  // rings 1..k-1 hold n * (1 + ... + (k-1)) vertices
  return first + (s * k + i) % (n * k);
}

/// A patch of the triangular lattice made of n sectors of 60 degrees (n = 6: the flat hexagon
/// of HexPatch) glued around vertex 0, which has valence n; every other interior vertex has
/// valence 6. Ring k holds n * k vertices on a circle of radius k, sector corners (i = 0) on
/// the sector axes, which are the separatrices of vertex 0. Flat (z = 0).
inline void NGonPatch(TMesh& m, int n, int R) {
  m.Clear();
  vcg::tri::Allocator<TMesh>::AddVertices(m, size_t(1 + n * R * (R + 1) / 2));
  m.vert[0].P() = vcg::Point3f(0, 0, 0);
  for (int k = 1; k <= R; ++k)
    for (int t = 0; t < n * k; ++t) {
      const float a = 2 * float(M_PI) * float(t) / float(n * k);
      m.vert[size_t(NGonIndex(n, k, 0, t))].P() = vcg::Point3f(k * std::cos(a), k * std::sin(a), 0);
    }
  auto add = [&](int a, int b, int c) { vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[size_t(a)], &m.vert[size_t(b)], &m.vert[size_t(c)]); };
  for (int s = 0; s < n; ++s) add(0, NGonIndex(n, 1, s, 0), NGonIndex(n, 1, s + 1, 0));
  for (int k = 1; k < R; ++k)
    for (int s = 0; s < n; ++s) {
      // inner ring k positions s*k .. s*k+k, outer ring k+1 positions s*(k+1) .. s*(k+1)+k+1
      auto in = [&](int i) { return NGonIndex(n, k, 0, s * k + i); };
      auto out = [&](int i) { return NGonIndex(n, k + 1, 0, s * (k + 1) + i); };
      for (int i = 0; i <= k; ++i) add(in(i), out(i), out(i + 1));
      for (int i = 0; i < k; ++i) add(in(i), out(i + 1), in(i + 1));
    }
  UpdateTopology(m);
}

}  // namespace test
