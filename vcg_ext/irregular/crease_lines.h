// filter_irregular: crease lines, the sharp features the automatic reduction keeps (issue 14:
// "creases stay sharp").
//
// An edge is sharp when the dihedral angle between its two faces exceeds a threshold (60
// degrees: fandisk's creases). A single sharp edge, or two or three together, is usually no
// feature of the design but a spot where the triangles are coarse for the curvature (the tip
// of an ear, a folded triangle of a remesher); protecting those blocks the edits around them
// and costs the reduction a third more work on an organic model. A crease line is therefore a
// connected set (edges sharing vertices) of at least `minEdges` sharp edges that runs as a
// line: all of its vertices but two (an open line's ends) or but 1 - `minStraightShare` of them
// are passed straight through, with exactly two of its edges that turn by less than
// `maxTurnDeg`. A design crease does (fandisk at 20K: one set of 1266 edges, 98% of its
// vertices passed straight; the rest are its corners). The sharp edges of an organic model
// remeshed from a coarse input, or wrapped around a thin part, form sets as long but frayed,
// branching and zig-zagging: at 20K the femur has 1265 edges in sets of 8 or more, of which
// only one straight set of 8 passes (the others pass at most 78% of their vertices straight);
// the man none of 810. Protecting them kept the femur at 987 irregular vertices and a smallest
// angle of 1 degree (494 and 11.9 degrees with this rule).
//
// Cost: O(E log E) time for the sharp edges and O(V) memory for the union-find over the
// vertices; once per run.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace vcg_ext {
namespace irregular {

/// The connected sets of a graph over vertices 0..n-1 (union-find with path halving): the
/// lines of a set of edges. O(n) memory; near-constant time per call.
class VertexSets {
 public:
  explicit VertexSets(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
  uint32_t Find(uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void Join(uint32_t x, uint32_t y) {
    const uint32_t a = Find(x), b = Find(y);
    if (a != b) parent_[a] = b;
  }

 private:
  std::vector<uint32_t> parent_;
};

/// keep[i] = 1 when sharp edge i (a pair of vertex indices below nVerts) belongs to a crease
/// line: a connected set of at least minEdges sharp edges whose vertices, but for two (an open
/// line's ends) or 1 - minStraightShare of them, have exactly two edges of the set, turning by
/// less than maxTurnDeg (the angle between the directions in and out). pos(i) gives vertex
/// i's position (x, y, z by operator[]). minStraightShare 0 keeps every set of minEdges edges,
/// whatever its shape (the rule before 0.9.27).
template <class PosFn>
std::vector<char> CreaseLineEdges(const std::vector<std::pair<uint32_t, uint32_t>>& edges, size_t nVerts, int minEdges,
                                  PosFn pos, double minStraightShare = 0.9, double maxTurnDeg = 30) {
  VertexSets sets(nVerts);
  auto find = [&](uint32_t x) { return sets.Find(x); };
  for (const auto& e : edges) sets.Join(e.first, e.second);
  // per root: edges, vertices, vertices passed straight through
  std::vector<int> count(nVerts, 0), verts, straight;
  for (const auto& e : edges) ++count[find(e.first)];
  if (minStraightShare > 0) {
    verts.assign(nVerts, 0);
    straight.assign(nVerts, 0);
    // each vertex's edges of the sets, found by sorting their ends (2E entries) rather than
    // by a neighbour list per vertex of the mesh
    std::vector<std::pair<uint32_t, uint32_t>> ends;  // (vertex, other end)
    ends.reserve(2 * edges.size());
    for (const auto& e : edges) {
      ends.push_back({e.first, e.second});
      ends.push_back({e.second, e.first});
    }
    std::sort(ends.begin(), ends.end());
    const double cosTurn = std::cos(maxTurnDeg * M_PI / 180.0);
    for (size_t i = 0, j = 0; i < ends.size(); i = j) {
      for (j = i + 1; j < ends.size() && ends[j].first == ends[i].first; ++j) {
      }
      const uint32_t root = find(ends[i].first);
      ++verts[root];
      if (j - i != 2) continue;  // an end of the set, or where it branches
      const auto v = pos(ends[i].first), a = pos(ends[i].second), b = pos(ends[i + 1].second);
      double in[3], out[3], dot = 0, ni = 0, no = 0;
      for (int k = 0; k < 3; ++k) {
        in[k] = double(v[k]) - double(a[k]);
        out[k] = double(b[k]) - double(v[k]);
        dot += in[k] * out[k], ni += in[k] * in[k], no += out[k] * out[k];
      }
      if (ni > 0 && no > 0 && dot >= cosTurn * std::sqrt(ni * no)) ++straight[root];
    }
  }
  std::vector<char> keep(edges.size(), 0);
  for (size_t i = 0; i < edges.size(); ++i) {
    const uint32_t root = find(edges[i].first);
    // an open line's two ends are not passed through: a short straight line is one too
    keep[i] = count[root] >= minEdges &&
              (minStraightShare <= 0 || verts[root] - straight[root] <= std::max(2.0, (1 - minStraightShare) * verts[root]));
  }
  return keep;
}

}  // namespace irregular
}  // namespace vcg_ext
