// filter_irregular: a pattern region (a set of faces) as a surface of its own: its vertices
// split into fans, its outline (boundary loops), its Euler characteristic and the corners of
// its outline. The circle pattern (circle_pattern.h) asks whether a ring of faces closes as an
// annulus; the panels (pattern_panels.h) copy, inset and extrude a region.
//
// Fans: a source vertex whose region faces form k > 1 separate fans (the region touches
// itself at the vertex only) becomes k region vertices, one per fan, so the copy is always a
// manifold surface with boundary, whatever faces the region holds (the source mesh being
// manifold and consistently oriented).
//
// Outline corners (the panel's "sides"): an outline vertex is straight when the region holds
// exactly 3 faces at it, as a straight line through a regular vertex leaves 3 triangles on
// each side (sec. 5's separatrices); any other count is a corner. So the fan of a v6 (a
// hexagonal cell: 2 faces at each outline vertex) has 6 corners, the fan of a v5 has 5, a
// strip of width one between two straight edge lines has none.
//
// Preconditions: FF adjacency up to date on a manifold, consistently oriented triangle mesh;
// the face indices are live faces, each listed once. Postconditions: the mesh is not
// modified. Cost O(region faces), with hash maps keyed by the region's faces.
#pragma once

#include <array>
#include <numeric>
#include <unordered_map>
#include <vector>

#include <vcg/complex/complex.h>

#include "pattern_result.h"

namespace vcg_ext {
namespace irregular {

struct RegionOutline {
  /// One region vertex per fan: the source vertex index and the number of region faces in the fan.
  std::vector<int> source;
  std::vector<int> fanFaces;
  std::vector<char> onOutline;  ///< 1 if the region vertex lies on a boundary loop
  /// The region's faces (source face index) and their corners as region vertices, in the
  /// source face's orientation.
  std::vector<int> faces;
  std::vector<std::array<int, 3>> corners;
  /// Boundary loops, region vertex indices in order; the region lies on the left of each edge
  /// loop[i] -> loop[i+1] (the source faces' orientation).
  std::vector<std::vector<int>> loops;
  int edges = 0;
  int components = 0;  ///< edge-connected components
  bool splitVertices = false;  ///< some source vertex became several region vertices

  int Vertices() const { return int(source.size()); }
  int EulerCharacteristic() const { return Vertices() - edges + int(faces.size()); }
  bool IsCorner(int rv) const { return onOutline[size_t(rv)] && fanFaces[size_t(rv)] != 3; }
  /// Corners over all loops (see the header's definition).
  int Corners() const {
    int c = 0;
    for (auto& l : loops)
      for (int v : l) c += IsCorner(v) ? 1 : 0;
    return c;
  }
  /// A simple closed cycle of faces: one component, no pinched vertex, two boundary loops,
  /// Euler characteristic 0 (an annulus).
  bool IsAnnulus() const { return components == 1 && !splitVertices && loops.size() == 2 && EulerCharacteristic() == 0; }
};

namespace detail {
inline int UfFind(std::vector<int>& p, int x) {
  while (p[size_t(x)] != x) x = p[size_t(x)] = p[size_t(p[size_t(x)])];
  return x;
}
}  // namespace detail

/// The region of `faceIdx` (source face indices) of m, as described above. O(region size).
template <class MeshType>
RegionOutline BuildRegionOutline(const MeshType& cm, const std::vector<int>& faceIdx) {
  MeshType& m = const_cast<MeshType&>(cm);  // read only: vcg's accessors are not const
  RegionOutline R;
  R.faces = faceIdx;
  const int nf = int(faceIdx.size());
  std::unordered_map<int, int> local;
  local.reserve(size_t(nf) * 2);
  for (int i = 0; i < nf; ++i) local[faceIdx[size_t(i)]] = i;
  auto localOf = [&](const typename MeshType::FaceType* g) -> int {
    auto it = local.find(int(vcg::tri::Index(m, g)));
    return it == local.end() ? -1 : it->second;
  };
  // corners 3*i+z; union the corners of one vertex across region edges (fans)
  std::vector<int> uf(3 * size_t(nf));
  std::iota(uf.begin(), uf.end(), 0);
  std::vector<int> faceUf((size_t(nf)));
  std::iota(faceUf.begin(), faceUf.end(), 0);
  std::vector<std::array<int, 3>> nb((size_t(nf)));  // region neighbour across edge z, or -1
  for (int i = 0; i < nf; ++i) {
    auto& f = m.face[size_t(faceIdx[size_t(i)])];
    for (int z = 0; z < 3; ++z) {
      auto* g = f.FFp(z);
      const int j = (g == &f) ? -1 : localOf(g);
      nb[size_t(i)][size_t(z)] = j;
      if (j < 0) continue;
      const int e = f.FFi(z);  // g->V(e) == f.V(z+1), g->V(e+1) == f.V(z)
      auto unite = [&](int a, int b) { uf[size_t(detail::UfFind(uf, a))] = detail::UfFind(uf, b); };
      unite(3 * i + z, 3 * j + (e + 1) % 3);
      unite(3 * i + (z + 1) % 3, 3 * j + e);
      faceUf[size_t(detail::UfFind(faceUf, i))] = detail::UfFind(faceUf, j);
      if (i < j) ++R.edges;
    }
  }
  for (int i = 0; i < nf; ++i)
    if (detail::UfFind(faceUf, i) == i) ++R.components;
  std::unordered_map<int, int> rvOfRoot;
  std::unordered_map<int, int> fansOfSource;
  R.corners.resize(size_t(nf));
  for (int i = 0; i < nf; ++i) {
    auto& f = m.face[size_t(faceIdx[size_t(i)])];
    for (int z = 0; z < 3; ++z) {
      const int root = detail::UfFind(uf, 3 * i + z);
      auto it = rvOfRoot.find(root);
      int rv;
      if (it == rvOfRoot.end()) {
        rv = int(R.source.size());
        rvOfRoot[root] = rv;
        const int s = int(vcg::tri::Index(m, f.V(z)));
        R.source.push_back(s);
        R.fanFaces.push_back(0);
        R.onOutline.push_back(0);
        if (++fansOfSource[s] > 1) R.splitVertices = true;
      } else {
        rv = it->second;
      }
      R.corners[size_t(i)][size_t(z)] = rv;
      R.fanFaces[size_t(rv)]++;
    }
  }
  // boundary edges: one leaving each outline vertex (each fan is a manifold disk sector)
  std::unordered_map<int, int> nextOnOutline;
  for (int i = 0; i < nf; ++i)
    for (int z = 0; z < 3; ++z)
      if (nb[size_t(i)][size_t(z)] < 0) {
        const int a = R.corners[size_t(i)][size_t(z)], b = R.corners[size_t(i)][size_t((z + 1) % 3)];
        nextOnOutline[a] = b;
        R.onOutline[size_t(a)] = R.onOutline[size_t(b)] = 1;
        ++R.edges;
      }
  std::vector<char> done(R.source.size(), 0);
  for (size_t v = 0; v < R.source.size(); ++v) {
    if (!R.onOutline[v] || done[v]) continue;
    std::vector<int> loop;
    int c = int(v);
    while (!done[size_t(c)]) {
      done[size_t(c)] = 1;
      loop.push_back(c);
      auto it = nextOnOutline.find(c);
      if (it == nextOnOutline.end()) break;  // cannot happen on a manifold source
      c = it->second;
    }
    R.loops.push_back(std::move(loop));
  }
  return R;
}

/// Puts every live face of m that has no region yet (faceRegion -1) into one new Background
/// region, created only if some face needs it. O(F).
template <class MeshType>
void AssignBackgroundRegion(const MeshType& m, PatternLabels& P) {
  int background = -1;
  for (size_t i = 0; i < m.face.size(); ++i) {
    if (m.face[i].IsD() || P.faceRegion[i] >= 0) continue;
    if (background < 0) {
      background = int(P.regionKind.size());
      P.regionKind.push_back(RegionKind::Background);
    }
    P.faceRegion[i] = background;
  }
}

}  // namespace irregular
}  // namespace vcg_ext
