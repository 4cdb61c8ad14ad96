// filter_irregular: the star pattern seeded at v5 vertices (paper sec. 10, Fig. 12: on the
// duck, "several v5 vertices do not have other irregular vertices nearby so that a star
// pattern can be seeded from these vertices").
//
// The star of a seed s with radius R:
//   * its arms follow s's separatrices (sec. 5, separatrix.h): the straight path from s along
//     each of its edges, traced until R edges, an irregular or a boundary vertex, or a loop;
//     a v5 seed has 5 arms, a v7 seed 7;
//   * its faces are the body (the faces around s) and, for each arm s = a0, a1, ..., aL, the
//     faces around a1 ... a(L-1) (regular vertices strictly inside the arm) and the faces along
//     its last edge (a(L-1), aL). So an arm is a band two triangles wide centred on the edge
//     line, and on a flat lattice a 5-armed star of radius R >= 2 whose arms all reach R
//     holds 20R - 20 faces (5 for R = 1).
// Body and arms form one Star region per seed (the body is not a region of its own, so a
// panel is one star-shaped polygon). A face that two stars claim becomes Conflict (one region
// per edge-connected set of such faces), and a star left without faces has no region. All
// other faces form one Background region. Region ids: stars in seed order, then conflicts,
// then the background.
//
// A seed is isolated when no other irregular vertex (interior: valence != 6; boundary: the
// boundary valence rule, topology.h) lies within R edges of it: the star's arms then all
// reach their full length unless they meet the boundary.
//
// Preconditions: FF and VF adjacency up to date on a manifold, consistently oriented mesh.
// Postconditions: the mesh is not modified. Cost: O(V) to find the default seeds, O(F) for
// the face-region vector, and per seed O(R) for the star and O(R^2) for the isolation test
// (the disk of radius R).
#pragma once

#include <algorithm>
#include <deque>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "pattern_result.h"
#include "region_outline.h"
#include "separatrix.h"
#include "topology.h"

namespace vcg_ext {
namespace irregular {

struct StarOptions {
  std::vector<int> seeds;  ///< seed vertex indices; empty: every interior v5
  int radius = 3;          ///< star radius in rings (edges) around the seed
};

/// Is v irregular: interior valence != 6, boundary by the boundary valence rule. O(valence).
template <class MeshType>
bool IsIrregularVertex(MeshType& m, int v) {
  VertexStar<MeshType> s = StarOf<MeshType>(&m.vert[size_t(v)]);
  return s.Valence() != RegularValenceOf(s);
}

/// The faces of the star of `seed` (see the header), each once. O(R * valence).
template <class MeshType>
std::vector<int> StarFaces(MeshType& m, int seed, int radius) {
  std::unordered_set<int> faces;
  auto addFan = [&](int v) {
    VertexStar<MeshType> s = StarOf<MeshType>(&m.vert[size_t(v)]);
    for (auto& c : s.corners) faces.insert(int(vcg::tri::Index(m, c.f)));
  };
  addFan(seed);
  SeparatrixTracer<MeshType> tr(m);
  for (const Separatrix& arm : tr.TraceAll(seed, std::max(1, radius))) {
    const int L = arm.Length();
    for (int k = 1; k < L; ++k) addFan(arm.vertices[size_t(k)]);
    if (L >= 1) {  // faces along the last edge
      const int a = arm.vertices[size_t(L - 1)], b = arm.vertices[size_t(L)];
      VertexStar<MeshType> s = StarOf<MeshType>(&m.vert[size_t(a)]);
      for (auto& c : s.corners)
        for (int z = 0; z < 3; ++z)
          if (int(vcg::tri::Index(m, c.f->V(z))) == b) faces.insert(int(vcg::tri::Index(m, c.f)));
    }
  }
  std::vector<int> r(faces.begin(), faces.end());
  std::sort(r.begin(), r.end());
  return r;
}

/// Does an irregular vertex other than `seed` lie within `radius` edges of it? Breadth-first
/// over the disk of that radius.
template <class MeshType>
bool HasIrregularWithin(MeshType& m, int seed, int radius) {
  std::unordered_map<int, int> dist{{seed, 0}};
  std::deque<int> q{seed};
  while (!q.empty()) {
    const int v = q.front();
    q.pop_front();
    if (v != seed && IsIrregularVertex(m, v)) return true;
    const int d = dist[v];
    if (d >= radius) continue;
    VertexStar<MeshType> s = StarOf<MeshType>(&m.vert[size_t(v)]);
    for (auto* n : s.neighbors) {
      const int w = int(vcg::tri::Index(m, n));
      if (dist.emplace(w, d + 1).second) q.push_back(w);
    }
  }
  return false;
}

/// Stars around the seeds. Reports starSeeds and isolatedStarSeeds (no other irregular vertex
/// within `radius` rings), conflictRegions and conflictFaces. Reads the mesh only.
template <class MeshType>
PatternLabels ComputeStars(const MeshType& cm, const StarOptions& opt) {
  MeshType& m = const_cast<MeshType&>(cm);  // read only: vcg's accessors are not const
  if (m.fn == 0) return PatternLabels::Fail("star pattern: the mesh has no faces");
  if (opt.radius < 1) return PatternLabels::Fail("star pattern: the radius must be at least 1 ring");
  std::vector<int> seeds;
  std::unordered_set<int> seen;
  if (opt.seeds.empty()) {
    for (size_t i = 0; i < m.vert.size(); ++i) {
      if (m.vert[i].IsD() || m.vert[i].VFp() == nullptr) continue;
      VertexStar<MeshType> s = StarOf<MeshType>(&m.vert[i]);
      if (!s.boundary && s.manifold && s.Valence() == 5) seeds.push_back(int(i));
    }
    if (seeds.empty()) return PatternLabels::Fail("star pattern: the mesh has no interior v5 to seed a star; select seed vertices");
  } else {
    for (int v : opt.seeds) {
      if (v < 0 || v >= int(m.vert.size()) || m.vert[size_t(v)].IsD() || m.vert[size_t(v)].VFp() == nullptr)
        return PatternLabels::Fail("star pattern: seed " + std::to_string(v) + " is not a vertex of the mesh");
      if (seen.insert(v).second) seeds.push_back(v);
    }
  }
  PatternLabels P;
  P.faceRegion.assign(m.face.size(), -1);
  std::vector<int> claim(m.face.size(), -1);  // star index, or -2: claimed by two stars
  std::vector<std::vector<int>> starFaces;
  for (size_t k = 0; k < seeds.size(); ++k) {
    starFaces.push_back(StarFaces(m, seeds[k], opt.radius));
    for (int f : starFaces.back()) claim[size_t(f)] = claim[size_t(f)] == -1 ? int(k) : -2;
    P.measures.starSeeds++;
    if (!HasIrregularWithin(m, seeds[k], opt.radius)) P.measures.isolatedStarSeeds++;
  }
  for (size_t k = 0; k < seeds.size(); ++k) {
    int id = -1;
    for (int f : starFaces[k])
      if (claim[size_t(f)] == int(k)) {
        if (id < 0) {
          id = int(P.regionKind.size());
          P.regionKind.push_back(RegionKind::Star);
        }
        P.faceRegion[size_t(f)] = id;
      }
  }
  // conflicts: edge-connected components of faces claimed twice
  for (size_t k = 0; k < seeds.size(); ++k)
    for (int f0 : starFaces[k]) {
      if (claim[size_t(f0)] != -2 || P.faceRegion[size_t(f0)] >= 0) continue;
      const int id = int(P.regionKind.size());
      P.regionKind.push_back(RegionKind::Conflict);
      P.measures.conflictRegions++;
      std::vector<int> stack{f0};
      P.faceRegion[size_t(f0)] = id;
      while (!stack.empty()) {
        auto& f = m.face[size_t(stack.back())];
        stack.pop_back();
        P.measures.conflictFaces++;
        for (int z = 0; z < 3; ++z) {
          const int g = int(vcg::tri::Index(m, f.FFp(z)));
          if (claim[size_t(g)] == -2 && P.faceRegion[size_t(g)] < 0) {
            P.faceRegion[size_t(g)] = id;
            stack.push_back(g);
          }
        }
      }
    }
  AssignBackgroundRegion(m, P);
  return P;
}

}  // namespace irregular
}  // namespace vcg_ext
