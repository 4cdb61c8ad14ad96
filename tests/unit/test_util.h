// Helpers for vcg_ext unit tests: valences by index, exact mesh snapshots, adjacency vs rebuild.
#pragma once

#include <cstring>
#include <algorithm>
#include <array>
#include <tuple>
#include <vector>

#include <vcg_ext/irregular/topology.h>

#include "test_mesh.h"

namespace test {

inline std::vector<int> Valences(TMesh& m) {
  auto vf = vcg_ext::irregular::ComputeValences(m);
  return vf.valence;
}

inline int CountChanged(const std::vector<int>& a, const std::vector<int>& b) {
  int n = 0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) n += a[i] != b[i];
  return n;
}

/// Everything an edit may touch, by index: positions, flags, vertex refs, FF, VF, sizes.
struct MeshSnapshot {
  std::vector<std::tuple<float, float, float, int, long, int>> verts;
  std::vector<std::vector<long>> faces;
  int fn = 0, vn = 0;
  bool operator==(const MeshSnapshot& o) const { return verts == o.verts && faces == o.faces && fn == o.fn && vn == o.vn; }
};

inline MeshSnapshot Snapshot(TMesh& m) {
  MeshSnapshot s;
  s.fn = m.fn;
  s.vn = m.vn;
  auto fidx = [&](const TFace* f) -> long { return f ? long(vcg::tri::Index(m, f)) : -1; };
  for (auto& v : m.vert)
    s.verts.emplace_back(v.P()[0], v.P()[1], v.P()[2], v.Flags(), fidx(v.cVFp()), v.cVFi());
  for (auto& f : m.face) {
    std::vector<long> r{long(f.Flags())};
    for (int z = 0; z < 3; ++z) {
      r.push_back(f.cV(z) ? long(vcg::tri::Index(m, f.cV(z))) : -1);
      r.push_back(fidx(f.cFFp(z)));
      r.push_back(f.cFFi(z));
      r.push_back(fidx(f.cVFp(z)));
      r.push_back(f.cVFi(z));
    }
    s.faces.push_back(r);
  }
  return s;
}

/// Every face normal's bytes, by face index: an undo gives them back bit for bit.
inline std::vector<unsigned char> FaceNormalBits(const TMesh& m) {
  std::vector<unsigned char> bits(m.face.size() * sizeof(TMesh::FaceType::NormalType));
  for (size_t i = 0; i < m.face.size(); ++i) {
    const TMesh::FaceType::NormalType n = m.face[i].cN();
    std::memcpy(&bits[i * sizeof(n)], &n, sizeof(n));
  }
  return bits;
}

/// FF adjacency maintained locally equals vcg's full rebuild (FF is unique on a manifold mesh).
inline bool AdjacencyEqualsRebuild(TMesh& m) {
  std::vector<std::pair<long, int>> ff;
  for (auto& f : m.face)
    for (int z = 0; z < 3; ++z)
      ff.push_back({f.IsD() ? -1 : long(vcg::tri::Index(m, f.cFFp(z))), f.IsD() ? 0 : f.cFFi(z)});
  vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
  size_t k = 0;
  bool same = true;
  for (auto& f : m.face)
    for (int z = 0; z < 3; ++z, ++k)
      if (!f.IsD() && (ff[k].first != long(vcg::tri::Index(m, f.cFFp(z))) || ff[k].second != f.cFFi(z))) same = false;
  return same;
}

}  // namespace test

namespace test {
/// Live faces as vertex-index triples rotated to start at the smallest index, sorted: equal
/// for two meshes with the same connectivity whatever the face order or rotation.
inline std::vector<std::array<int, 3>> CanonicalFaces(TMesh& m) {
  std::vector<std::array<int, 3>> out;
  for (auto& f : m.face) {
    if (f.IsD()) continue;
    std::array<int, 3> t{int(vcg::tri::Index(m, f.cV(0))), int(vcg::tri::Index(m, f.cV(1))), int(vcg::tri::Index(m, f.cV(2)))};
    while (t[0] > t[1] || t[0] > t[2]) std::rotate(t.begin(), t.begin() + 1, t.end());
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Indices of live vertices whose valence is not regular.
inline std::vector<int> IrregularVertices(TMesh& m) {
  auto vf = vcg_ext::irregular::ComputeValences(m);
  std::vector<int> r;
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD() && vf.IsIrregular(i)) r.push_back(int(i));
  return r;
}
}  // namespace test
