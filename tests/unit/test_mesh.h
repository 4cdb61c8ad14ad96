// Test meshes for vcg_ext unit tests: a plain vcg mesh type with FF and VF adjacency, and
// procedural shapes with known valences.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/create/platonic.h>
#include <vcg/complex/algorithms/refine.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/clean.h>
#include <wrap/io_trimesh/import_off.h>

namespace test {

class TVertex;
class TFace;
struct TUsedTypes : public vcg::UsedTypes<vcg::Use<TVertex>::AsVertexType, vcg::Use<TFace>::AsFaceType> {};
// Single precision, as MeshLab 2020.09's CMeshO; FI_TEST_MESH_DOUBLE gives double, as MeshLab
// 2025.07's (pymeshlab's wheel is built with MESHLAB_SCALAR=double), so that a native benchmark
// reproduces the filter's run bit for bit.
#ifdef FI_TEST_MESH_DOUBLE
#define FI_TEST_SCALAR(component) component##d
#else
#define FI_TEST_SCALAR(component) component##f
#endif
class TVertex : public vcg::Vertex<TUsedTypes, vcg::vertex::FI_TEST_SCALAR(Coord3), vcg::vertex::FI_TEST_SCALAR(Normal3),
                                   vcg::vertex::VFAdj, vcg::vertex::Color4b, vcg::vertex::FI_TEST_SCALAR(Quality),
                                   vcg::vertex::BitFlags, vcg::vertex::Mark> {};
class TFace : public vcg::Face<TUsedTypes, vcg::face::VertexRef, vcg::face::FFAdj, vcg::face::VFAdj,
                               vcg::face::FI_TEST_SCALAR(Normal3), vcg::face::BitFlags, vcg::face::Mark> {};
#undef FI_TEST_SCALAR
class TMesh : public vcg::tri::TriMesh<std::vector<TVertex>, std::vector<TFace>> {};

inline void UpdateTopology(TMesh& m) {
  vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
  vcg::tri::UpdateTopology<TMesh>::VertexFace(m);
  vcg::tri::UpdateBounding<TMesh>::Box(m);
  vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(m);
}

inline void Icosahedron(TMesh& m) {
  vcg::tri::Icosahedron(m);
  UpdateTopology(m);
}

/// Icosahedron with every triangle split into 4 (`levels` times), projected on the unit sphere.
inline void Icosphere(TMesh& m, int levels) {
  vcg::tri::Icosahedron(m);
  for (int l = 0; l < levels; ++l) {
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    vcg::tri::Refine<TMesh, vcg::tri::MidPoint<TMesh>>(m, vcg::tri::MidPoint<TMesh>(&m), 0);
  }
  for (auto& v : m.vert) v.P().Normalize();
  UpdateTopology(m);
}

/// Regular triangulated torus: n x k grid of quads, each cut by the same diagonal, so every
/// vertex has valence 6.
inline void RegularTorus(TMesh& m, int n, int k, float R = 3.f, float r = 1.f) {
  m.Clear();
  vcg::tri::Allocator<TMesh>::AddVertices(m, n * k);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < k; ++j) {
      float a = 2 * float(M_PI) * i / n, b = 2 * float(M_PI) * j / k;
      m.vert[i * k + j].P() = TMesh::CoordType((R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a),
                                               r * std::sin(b));
    }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < k; ++j) {
      int a = i * k + j, b = ((i + 1) % n) * k + j, c = ((i + 1) % n) * k + (j + 1) % k, d = i * k + (j + 1) % k;
      vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[a], &m.vert[b], &m.vert[c]);
      vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[a], &m.vert[c], &m.vert[d]);
    }
  UpdateTopology(m);
}

/// ConePatch patch: k sectors of the regular triangular lattice of the given radius glued around
/// the centre (vertex 0, valence k). Lattice point (a, b) of sector s (a*e_s + b*e_{s+1}) at
/// distance d = a+b, offset j = b < d, has id 1 + k*d*(d-1)/2 + s*d + j; so the centre's
/// neighbours, counter-clockwise, are r_s = 1 + s. Every other interior vertex is regular.
/// Planar: sector s spans the angles [s, s+1) * 360/k degrees.
struct ConePatch {
  int k, radius;
  int Id(int s, int a, int b) const {
    s = ((s % k) + k) % k;
    if (a == 0 && b == 0) return 0;
    const int d = a + b;
    if (a == 0) return Id(s + 1, b, 0);
    return 1 + k * d * (d - 1) / 2 + s * d + b;
  }
  int Ring(int s) const { return Id(s, 1, 0); }
};

inline ConePatch BuildCone(TMesh& m, int k, int radius = 6) {
  ConePatch c{k, radius};
  m.Clear();
  const int n = 1 + k * radius * (radius + 1) / 2;
  vcg::tri::Allocator<TMesh>::AddVertices(m, size_t(n));
  m.vert[0].P() = TMesh::CoordType(0, 0, 0);
  for (int s = 0; s < k; ++s)
    for (int d = 1; d <= radius; ++d)
      for (int b = 0; b < d; ++b) {
        const int a = d - b;
        const float x = a + 0.5f * b, y = b * std::sqrt(3.f) / 2, rho = std::sqrt(x * x + y * y);
        const float phi = (float(s) + std::atan2(y, x) / float(M_PI / 3)) * 2 * float(M_PI) / float(k);
        m.vert[size_t(c.Id(s, a, b))].P() = TMesh::CoordType(rho * std::cos(phi), rho * std::sin(phi), 0);
      }
  for (int s = 0; s < k; ++s)
    for (int a = 0; a < radius; ++a)
      for (int b = 0; a + b < radius; ++b) {
        vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[size_t(c.Id(s, a, b))], &m.vert[size_t(c.Id(s, a + 1, b))],
                                            &m.vert[size_t(c.Id(s, a, b + 1))]);
        if (a + b < radius - 1)
          vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[size_t(c.Id(s, a + 1, b))],
                                              &m.vert[size_t(c.Id(s, a + 1, b + 1))], &m.vert[size_t(c.Id(s, a, b + 1))]);
      }
  test::UpdateTopology(m);
  return c;
}

/// Planar patch of a regular triangular lattice: a hexagon of the given radius (in edges)
/// around the origin. Interior vertices have valence 6; the centre is vertex 0.
inline void HexPatch(TMesh& m, int radius) {
  m.Clear();
  // axial coordinates (q, r) with |q|, |r|, |q + r| <= radius
  std::vector<std::pair<int, int>> cells;
  cells.push_back({0, 0});
  for (int q = -radius; q <= radius; ++q)
    for (int r = -radius; r <= radius; ++r)
      if (!(q == 0 && r == 0) && std::abs(q + r) <= radius) cells.push_back({q, r});
  auto idx = [&](int q, int r) -> int {
    for (size_t i = 0; i < cells.size(); ++i)
      if (cells[i].first == q && cells[i].second == r) return int(i);
    return -1;
  };
  vcg::tri::Allocator<TMesh>::AddVertices(m, cells.size());
  for (size_t i = 0; i < cells.size(); ++i) {
    float q = float(cells[i].first), r = float(cells[i].second);
    m.vert[i].P() = TMesh::CoordType(q + 0.5f * r, r * std::sqrt(3.f) / 2.f, 0.f);
  }
  for (auto c : cells) {
    int a = idx(c.first, c.second), b = idx(c.first + 1, c.second), d = idx(c.first, c.second + 1),
        e = idx(c.first - 1, c.second + 1);
    if (a >= 0 && b >= 0 && d >= 0) vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[a], &m.vert[b], &m.vert[d]);
    if (a >= 0 && d >= 0 && e >= 0) vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[a], &m.vert[d], &m.vert[e]);
  }
  UpdateTopology(m);
}

// ---------------------------------------------------------------- meshes with attributes
// For attribute_transfer.h: TAMesh has per-wedge texture coordinates, face colour and quality,
// vertex colour, quality and texture coordinate as static components; TOMesh has them as
// optional components, the way MeshLab's CMeshO does (enabled at run time).
class TAVertex;
class TAFace;
struct TAUsedTypes : public vcg::UsedTypes<vcg::Use<TAVertex>::AsVertexType, vcg::Use<TAFace>::AsFaceType> {};
class TAVertex : public vcg::Vertex<TAUsedTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::VFAdj,
                                    vcg::vertex::Color4b, vcg::vertex::Qualityf, vcg::vertex::TexCoord2f,
                                    vcg::vertex::BitFlags, vcg::vertex::Mark> {};
class TAFace : public vcg::Face<TAUsedTypes, vcg::face::VertexRef, vcg::face::FFAdj, vcg::face::VFAdj,
                                vcg::face::Normal3f, vcg::face::WedgeTexCoord2f, vcg::face::Color4b,
                                vcg::face::Qualityf, vcg::face::BitFlags, vcg::face::Mark> {};
class TAMesh : public vcg::tri::TriMesh<std::vector<TAVertex>, std::vector<TAFace>> {};

class TOVertex;
class TOFace;
struct TOUsedTypes : public vcg::UsedTypes<vcg::Use<TOVertex>::AsVertexType, vcg::Use<TOFace>::AsFaceType> {};
class TOVertex : public vcg::Vertex<TOUsedTypes, vcg::vertex::InfoOcf, vcg::vertex::Coord3f, vcg::vertex::BitFlags,
                                    vcg::vertex::Normal3f, vcg::vertex::Qualityf, vcg::vertex::Color4b,
                                    vcg::vertex::VFAdjOcf, vcg::vertex::MarkOcf, vcg::vertex::TexCoordfOcf> {};
class TOFace : public vcg::Face<TOUsedTypes, vcg::face::InfoOcf, vcg::face::VertexRef, vcg::face::BitFlags,
                                vcg::face::Normal3f, vcg::face::QualityfOcf, vcg::face::MarkOcf, vcg::face::Color4bOcf,
                                vcg::face::FFAdjOcf, vcg::face::VFAdjOcf, vcg::face::WedgeTexCoordfOcf> {};
class TOMesh : public vcg::tri::TriMesh<vcg::vertex::vector_ocf<TOVertex>, vcg::face::vector_ocf<TOFace>> {};

/// A copy of a TMesh (positions and faces) in a mesh type with attributes, adjacency rebuilt.
/// Optional components (TOMesh) must be enabled before: FF, VF adjacency at least.
template <class MeshT>
inline void CopyWithAttributes(TMesh& src, MeshT& m) {
  vcg::tri::Append<MeshT, TMesh>::MeshCopy(m, src);
  vcg::tri::UpdateTopology<MeshT>::FaceFace(m);
  vcg::tri::UpdateTopology<MeshT>::VertexFace(m);
  vcg::tri::UpdateBounding<MeshT>::Box(m);
  vcg::tri::UpdateNormal<MeshT>::PerFaceNormalized(m);
}

/// Copies `from` into `m` with the optional components MeshLab's CMeshO enables (VF, FF, marks,
/// wedge texture coordinates, face colour).
inline void CopyAsCMeshO(TMesh& from, TOMesh& m) {
  m.vert.EnableVFAdjacency();
  m.vert.EnableMark();
  m.face.EnableFFAdjacency();
  m.face.EnableVFAdjacency();
  m.face.EnableMark();
  m.face.EnableWedgeTexCoord();
  m.face.EnableColor();
  CopyWithAttributes(from, m);
}

/// Everything a bit-identical check of an optional-component mesh compares, by index: counts and
/// vector sizes, positions, flags, face vertices, FF, VF and wedge texture coordinates.
inline std::vector<double> OcfSnapshot(TOMesh& m) {
  std::vector<double> s{double(m.vn), double(m.fn), double(m.vert.size()), double(m.face.size())};
  auto fi = [&](const TOMesh::FaceType* f) { return f ? double(vcg::tri::Index(m, f)) : -1.0; };
  for (auto& v : m.vert) s.insert(s.end(), {v.P()[0], v.P()[1], v.P()[2], double(v.Flags()), fi(v.cVFp()), double(v.cVFi())});
  for (auto& f : m.face) {
    s.push_back(double(f.Flags()));
    for (int z = 0; z < 3; ++z)
      s.insert(s.end(), {double(vcg::tri::Index(m, f.cV(z))), fi(f.cFFp(z)), double(f.cFFi(z)), fi(f.cVFp(z)),
                         double(f.cVFi(z)), f.cWT(z).U(), f.cWT(z).V()});
  }
  return s;
}

inline std::string DataFile(const std::string& name) { return std::string(FI_DATA_DIR) + "/" + name; }

/// Loads a corpus mesh (OFF); returns false if the file is missing.
inline bool LoadCorpus(TMesh& m, const std::string& name) {
  int mask = 0;
  if (vcg::tri::io::ImporterOFF<TMesh>::Open(m, DataFile(name).c_str(), mask) != 0) return false;
  vcg::tri::Clean<TMesh>::RemoveUnreferencedVertex(m);
  vcg::tri::Allocator<TMesh>::CompactEveryVector(m);
  UpdateTopology(m);
  return true;
}

}  // namespace test
