// Patches with boundaries for the boundary tests: the hexagonal lattice patch of test_mesh.h,
// optionally with a hole, and lookup of a vertex by its lattice (axial) coordinates.
#pragma once

#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <vcg/complex/complex.h>
#include <vcg_ext/irregular/mesh_checks.h>

#include "test_mesh.h"

namespace test {

/// Position of the lattice point with axial coordinates (q, r), as HexPatch places it.
inline vcg::Point3f LatticePoint(int q, int r) {
  return vcg::Point3f(float(q) + 0.5f * float(r), float(r) * std::sqrt(3.f) / 2.f, 0.f);
}

/// Index of the live vertex at lattice point (q, r), or -1.
inline int At(TMesh& m, int q, int r) {
  const vcg::Point3f p = LatticePoint(q, r);
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD() && (m.vert[i].P() - p).Norm() < 1e-4f) return int(i);
  return -1;
}

/// Deletes the given faces and the vertices no face uses any more, compacts, rebuilds adjacency.
inline void RemoveFaces(TMesh& m, const std::vector<int>& faces) {
  for (int f : faces) vcg::tri::Allocator<TMesh>::DeleteFace(m, m.face[size_t(f)]);
  vcg::tri::Clean<TMesh>::RemoveUnreferencedVertex(m);
  vcg::tri::Allocator<TMesh>::CompactEveryVector(m);
  UpdateTopology(m);
}

/// HexPatch of `radius` with the faces within `holeRadius` rings of the centre removed: an
/// annulus whose inner boundary is a hexagon of 6 * holeRadius edges (corners of 240 degrees,
/// regular at valence 5 by the boundary valence rule).
inline void HexPatchWithHole(TMesh& m, int radius, int holeRadius = 1) {
  HexPatch(m, radius);
  std::vector<int> del;
  for (size_t i = 0; i < m.face.size(); ++i) {
    vcg::Point3f c = (m.face[i].P(0) + m.face[i].P(1) + m.face[i].P(2)) / 3.f;
    // inside the hexagon of the hole: |axial q|, |r|, |q + r| of the centroid within holeRadius
    const float r = c[1] / (std::sqrt(3.f) / 2.f), q = c[0] - 0.5f * r;
    if (std::abs(q) < holeRadius && std::abs(r) < holeRadius && std::abs(q + r) < holeRadius) del.push_back(int(i));
  }
  RemoveFaces(m, del);
}

/// Invariants (with the boundary consistency checks) and eq. 2.
inline void ExpectValid(TMesh& m) {
  vcg_ext::irregular::Result r = vcg_ext::irregular::CheckInvariants(m);
  EXPECT_TRUE(r.ok) << r.reason;
  EXPECT_TRUE(vcg_ext::irregular::Summarize(m).GaussBonnetHolds());
}

/// Index of the live face with these three vertices (any order), or -1.
inline int FaceWith(TMesh& m, int a, int b, int c) {
  for (size_t i = 0; i < m.face.size(); ++i) {
    auto& f = m.face[i];
    if (f.IsD()) continue;
    int n = 0;
    for (int z = 0; z < 3; ++z) {
      int v = int(vcg::tri::Index(m, f.V(z)));
      n += v == a || v == b || v == c;
    }
    if (n == 3) return int(i);
  }
  return -1;
}

}  // namespace test
