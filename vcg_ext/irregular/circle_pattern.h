// filter_irregular: the circle pattern (paper sec. 10, Fig. 14: on the U-shaped model "many
// irregular vertices are generated intentionally to create circles with the triangulation").
//
// Definition. The centres are the interior irregular vertices (valence != 6; a ring around a
// boundary vertex cannot close), or the given vertices; adjacent centres form one cluster (a 5-7
// pair is one centre). Every vertex belongs to its nearest cluster by graph distance (a
// multi-source breadth-first search; a vertex as near to two clusters, or reached only
// through such vertices, belongs to none). A face belongs to a cluster when its three
// vertices do, and lies on ring d = the largest graph distance of its vertices (ring 1: the
// faces around the cluster). Rings are grouped in bands of `ringWidth` rings, band
// j = (d - 1) / ringWidth; odd bands are circle candidates, even bands (the centre's own
// faces among them) are gaps. A candidate is a circle when it closes: its faces form a simple
// closed cycle of faces (an annulus: one edge-connected component, no pinched vertex, two
// boundary loops, Euler characteristic 0; region_outline.h). A candidate cut by another
// cluster's cell or by the mesh boundary is an arc, not a circle, and joins the background.
//
// So a circle exists only around irregular vertices, and it closes only while its cluster's
// cell (the faces nearer to it than to any other cluster) holds the whole ring: a regular
// lattice has none, and generating well separated irregular vertices (composite_ops.h's
// generation, then spacing) makes circles close around each of them: more generated and
// spaced irregular vertices, more circles. Regions: one Circle region per closed band (in
// cluster order, then band order), then one Background region for every other face.
//
// Preconditions: FF and VF adjacency up to date on a manifold, consistently oriented mesh.
// Postconditions: the mesh is not modified. Cost O(V + F).
#pragma once

#include <deque>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "pattern_result.h"
#include "region_outline.h"
#include "topology.h"

namespace vcg_ext {
namespace irregular {

struct CircleOptions {
  int ringWidth = 1;         ///< rings of faces per circle band (and per gap between circles)
  std::vector<int> centres;  ///< centre vertices; empty: the irregular vertices (default)
};

/// Circles. Reports `circles` (closed rings). Reads the mesh only.
template <class MeshType>
PatternLabels ComputeCircles(const MeshType& cm, const CircleOptions& opt) {
  MeshType& m = const_cast<MeshType&>(cm);  // read only: vcg's accessors are not const
  if (m.fn == 0) return PatternLabels::Fail("circle pattern: the mesh has no faces");
  if (opt.ringWidth < 1) return PatternLabels::Fail("circle pattern: the ring width must be at least 1");
  const size_t nv = m.vert.size();
  auto live = [&](int v) { return v >= 0 && size_t(v) < nv && !m.vert[size_t(v)].IsD() && m.vert[size_t(v)].VFp() != nullptr; };
  std::vector<char> centre(nv, 0);
  if (opt.centres.empty()) {
    for (size_t v = 0; v < nv; ++v)
      if (live(int(v))) {
        VertexStar<MeshType> s = StarOf<MeshType>(&m.vert[v]);
        centre[v] = !s.boundary && s.Valence() != 6;
      }
  } else {
    for (int v : opt.centres) {
      if (!live(v)) return PatternLabels::Fail("circle pattern: centre " + std::to_string(v) + " is not a vertex of the mesh");
      centre[size_t(v)] = 1;
    }
  }
  auto neighbours = [&](int v) {
    std::vector<int> r;
    VertexStar<MeshType> s = StarOf<MeshType>(&m.vert[size_t(v)]);
    for (auto* n : s.neighbors) r.push_back(int(vcg::tri::Index(m, n)));
    return r;
  };
  // clusters of adjacent centres, then the multi-source breadth-first search
  const int kNone = -1, kTie = -2;
  std::vector<int> owner(nv, kNone), dist(nv, -1);
  std::deque<int> q;
  int clusters = 0;
  for (size_t v0 = 0; v0 < nv; ++v0) {
    if (!centre[v0] || owner[v0] != kNone) continue;
    std::vector<int> stack{int(v0)};
    owner[v0] = clusters;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      dist[size_t(v)] = 0;
      q.push_back(v);
      for (int w : neighbours(v))
        if (centre[size_t(w)] && owner[size_t(w)] == kNone) {
          owner[size_t(w)] = clusters;
          stack.push_back(w);
        }
    }
    ++clusters;
  }
  while (!q.empty()) {
    const int v = q.front();
    q.pop_front();
    for (int w : neighbours(v)) {
      if (dist[size_t(w)] < 0) {
        dist[size_t(w)] = dist[size_t(v)] + 1;
        owner[size_t(w)] = owner[size_t(v)];
        q.push_back(w);
      } else if (dist[size_t(w)] == dist[size_t(v)] + 1 && owner[size_t(w)] != owner[size_t(v)]) {
        owner[size_t(w)] = kTie;
      }
    }
  }
  // circle candidates: (cluster, odd band) -> faces
  std::map<std::pair<int, int>, std::vector<int>> candidates;
  for (size_t i = 0; i < m.face.size(); ++i) {
    auto& f = m.face[i];
    if (f.IsD()) continue;
    const int c = owner[vcg::tri::Index(m, f.V(0))];
    int d = 0;
    bool same = c >= 0;
    for (int z = 0; z < 3 && same; ++z) {
      const size_t v = vcg::tri::Index(m, f.V(z));
      same = owner[v] == c;
      d = std::max(d, dist[v]);
    }
    if (!same || d < 1) continue;
    const int band = (d - 1) / opt.ringWidth;
    if (band % 2 == 1) candidates[{c, band}].push_back(int(i));
  }
  PatternLabels P;
  P.faceRegion.assign(m.face.size(), -1);
  for (auto& kv : candidates) {
    if (!BuildRegionOutline(m, kv.second).IsAnnulus()) continue;
    const int id = int(P.regionKind.size());
    P.regionKind.push_back(RegionKind::Circle);
    for (int f : kv.second) P.faceRegion[size_t(f)] = id;
    P.measures.circles++;
  }
  AssignBackgroundRegion(m, P);
  return P;
}

}  // namespace irregular
}  // namespace vcg_ext
