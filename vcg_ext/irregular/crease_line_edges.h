// filter_irregular: the edges of a mesh's crease lines (crease_lines.h's rule: interior edges
// sharper than a dihedral angle, in connected sets of at least minEdges that run as lines), each
// with its midpoint and its two faces' unit normals, for the automatic reduction (which keeps
// them sharp, relaxation.h CreaseLineVertices) and for the thin-rim test (thin_creases.h).
//
// Two finders, one rule: CreaseLineEdgesOf walks FF adjacency (the mesh being edited);
// CreaseLineEdgesOfSoup sorts half-edges (the edit guard's copy of the input, which has none).
// Cost: O(F + E log E) and O(F log F), once per call.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>

#include "crease_lines.h"

namespace vcg_ext {
namespace irregular {

/// An edge of a crease line: its ends (vertex indices of its mesh), its midpoint and the unit
/// normals of its two faces.
struct CreaseLineEdge {
  uint32_t a, b;
  vcg::Point3d mid, nA, nB;
};

namespace crease_detail {

template <class FaceType>
vcg::Point3d UnitNormal(const FaceType& f) {
  vcg::Point3d n = vcg::Point3d::Construct(vcg::TriangleNormal(f));
  const double l = n.Norm();
  return l > 0 ? n / l : n;
}

/// The candidates (interior edges sharper than angleDeg) with their faces, kept when their set
/// is a crease line (CreaseLineEdges).
template <class MeshType>
std::vector<CreaseLineEdge> KeepLines(const MeshType& m, std::vector<CreaseLineEdge> sharp, int minEdges,
                                      double minStraightShare) {
  std::vector<std::pair<uint32_t, uint32_t>> ends;
  ends.reserve(sharp.size());
  for (const CreaseLineEdge& e : sharp) ends.push_back({e.a, e.b});
  const std::vector<char> keep = CreaseLineEdges(
      ends, m.vert.size(), minEdges, [&m](uint32_t i) { return m.vert[i].cP(); }, minStraightShare);
  std::vector<CreaseLineEdge> lines;
  for (size_t i = 0; i < sharp.size(); ++i)
    if (keep[i]) lines.push_back(sharp[i]);
  return lines;
}

}  // namespace crease_detail

/// The crease-line edges of a mesh with FF adjacency: edges sharper than angleDeg (none if 0) in
/// sets of minEdges that run as lines (CreaseLineEdges). O(F + E log E).
template <class MeshType>
std::vector<CreaseLineEdge> CreaseLineEdgesOf(MeshType& m, double angleDeg, int minEdges, double minStraightShare) {
  std::vector<CreaseLineEdge> sharp;
  if (angleDeg <= 0) return sharp;
  const double c = std::cos(angleDeg * M_PI / 180.0);
  for (auto& f : m.face) {
    if (f.IsD()) continue;
    for (int z = 0; z < 3; ++z) {
      auto* g = f.FFp(z);
      if (g == &f || g < &f) continue;  // each interior edge once
      if (!(double(vcg::TriangleNormal(f).Normalize().dot(vcg::TriangleNormal(*g).Normalize())) < c)) continue;
      const vcg::Point3d nf = crease_detail::UnitNormal(f), ng = crease_detail::UnitNormal(*g);
      const uint32_t a = uint32_t(vcg::tri::Index(m, f.V(z))), b = uint32_t(vcg::tri::Index(m, f.V((z + 1) % 3)));
      sharp.push_back({a, b, (vcg::Point3d::Construct(f.cP(z)) + vcg::Point3d::Construct(f.cP((z + 1) % 3))) / 2, nf, ng});
    }
  }
  return crease_detail::KeepLines(m, std::move(sharp), minEdges, minStraightShare);
}

/// The same for a mesh without adjacency but with unit face normals (the edit guard's copy of
/// the input, SurfaceProjector::Mesh): its half-edges sorted by their ends; sharpness from the
/// stored normals, as the guard's SharpEdgeSamples computes it. Vertex indices are the mesh's.
/// O(F log F).
template <class MeshType>
std::vector<CreaseLineEdge> CreaseLineEdgesOfSoup(const MeshType& m, double angleDeg, int minEdges,
                                                  double minStraightShare) {
  std::vector<CreaseLineEdge> sharp;
  if (angleDeg <= 0) return sharp;
  struct HalfEdge {
    uint32_t a, b, f;
  };
  std::vector<HalfEdge> he;
  he.reserve(3 * m.face.size());
  for (size_t i = 0; i < m.face.size(); ++i) {
    if (m.face[i].IsD()) continue;
    for (int z = 0; z < 3; ++z) {
      uint32_t a = uint32_t(vcg::tri::Index(m, m.face[i].cV(z))), b = uint32_t(vcg::tri::Index(m, m.face[i].cV((z + 1) % 3)));
      if (a > b) std::swap(a, b);
      he.push_back({a, b, uint32_t(i)});
    }
  }
  std::sort(he.begin(), he.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.f < y.f;
  });
  const double c = std::cos(angleDeg * M_PI / 180.0);
  for (size_t i = 0, j = 0; i < he.size(); i = j) {
    for (j = i + 1; j < he.size() && he[j].a == he[i].a && he[j].b == he[i].b; ++j) {
    }
    if (j - i != 2) continue;  // boundary or non-manifold
    if (!(double(m.face[he[i].f].cN().dot(m.face[he[i + 1].f].cN())) < c)) continue;
    const vcg::Point3d nf = crease_detail::UnitNormal(m.face[he[i].f]), ng = crease_detail::UnitNormal(m.face[he[i + 1].f]);
    const vcg::Point3d mid = (vcg::Point3d::Construct(m.vert[he[i].a].cP()) + vcg::Point3d::Construct(m.vert[he[i].b].cP())) / 2;
    sharp.push_back({he[i].a, he[i].b, mid, nf, ng});
  }
  return crease_detail::KeepLines(m, std::move(sharp), minEdges, minStraightShare);
}

/// Per vertex of a mesh of nVerts vertices, 1 on one of the lines.
inline std::vector<char> LineVertices(const std::vector<CreaseLineEdge>& lines, size_t nVerts) {
  std::vector<char> flags(nVerts, 0);
  for (const CreaseLineEdge& e : lines) flags[e.a] = flags[e.b] = 1;
  return flags;
}

}  // namespace irregular
}  // namespace vcg_ext
