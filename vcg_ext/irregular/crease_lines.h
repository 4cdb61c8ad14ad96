// filter_irregular: crease lines, the sharp features the automatic reduction keeps (issue 14:
// "creases stay sharp").
//
// An edge is sharp when the dihedral angle between its two faces exceeds a threshold (60
// degrees: fandisk's creases). A single sharp edge, or two or three together, is usually no
// feature of the design but a spot where the triangles are coarse for the curvature (the tip
// of an ear, a folded triangle of a remesher); protecting those blocks the edits around them
// and costs the reduction a third more work on an organic model. A crease line is therefore a
// connected set (edges sharing vertices) of at least `minEdges` sharp edges.
//
// Cost: O(E alpha(V)) time and O(V) memory for the union-find over the vertices; once per run.
#pragma once

#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace vcg_ext {
namespace irregular {

/// keep[i] = 1 when sharp edge i (a pair of vertex indices below nVerts) belongs to a connected
/// set of at least minEdges sharp edges.
inline std::vector<char> CreaseLineEdges(const std::vector<std::pair<uint32_t, uint32_t>>& edges, size_t nVerts,
                                         int minEdges) {
  std::vector<uint32_t> parent(nVerts);
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& e : edges) {
    const uint32_t a = find(e.first), b = find(e.second);
    if (a != b) parent[a] = b;
  }
  std::vector<int> count(nVerts, 0);
  for (const auto& e : edges) ++count[find(e.first)];
  std::vector<char> keep(edges.size(), 0);
  for (size_t i = 0; i < edges.size(); ++i) keep[i] = count[find(edges[i].first)] >= minEdges;
  return keep;
}

}  // namespace irregular
}  // namespace vcg_ext
