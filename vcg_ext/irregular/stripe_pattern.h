// filter_irregular: stripe and zebra patterns (paper sec. 10, Figs. 1 and 13), and the
// hexagonal lattice cells measured with them.
//
// Definitions (all combinatorial; positions are never read):
//  * Lattice direction of a face f: one of its three edges, d(f) ("the direction edge"); the
//    opposite vertex is f's apex. It is carried from the seed face (d = StripeOptions::direction)
//    by breadth-first flooding over face adjacency with the straight-continuation rule
//    (CarryDirection): crossing f's direction edge, the neighbour's direction edge is that same
//    edge; crossing a non-direction edge (q, r) of f (q on the direction edge, r the apex), the
//    neighbour g's direction edge is g's other edge through r. On a regular lattice this is the
//    parallel family of edges; around a vertex of valence 6 +- 1 it comes back turned by 60
//    degrees, so the flood finds *inconsistent* edges: the two faces' directions disagree with
//    the rule. They form seams that start at irregular vertices (or close around a handle).
//  * Line edge: the direction edge of a face on either side. Edge line: line edges joined
//    through interior vertices of valence 6 by the opposite edge (3 edges further round, as
//    sec. 5's separatrices go straight). A line is *complete* unless one of its ends is an
//    interior irregular vertex (ends on the boundary, closed loops and ends at a seam are
//    complete). Complete lines separate strips; an incomplete line (it stops at a v5/v7, e.g. the
//    extra half-line of a 5-7 pair) does not, so the two rows on its sides merge.
//  * Strip: a connected set of faces joined across consistent edges that are not on a complete
//    line. Width of a strip = 1 + the number of distinct incomplete lines with an edge inside the
//    strip (both sides in it): 1 for a row between two consecutive complete lines, 2 where one
//    line stops at an irregular vertex (Fig. 1 top), and so on.
//  * Stripes (ComputeStripes): every face of an inconsistent edge is a Conflict face (the design
//    cannot keep one direction family there); conflict regions are their connected components.
//  * Zebra (ComputeZebra, Fig. 13): the seams are placed at the irregular vertices and
//    accepted. A cut tree joins every interior irregular vertex to the boundary (closed mesh: to
//    the first irregular vertex) along breadth-first paths in the vertex graph (MarkCutTree); the
//    flood crosses a tree edge only where nothing else reaches, so the direction's 60-degree
//    turns show up on the tree, i.e. between singularities (a 5-7 pair: on its own edge, since
//    its two turns cancel). The strips on both sides of a seam follow the lattice, turned by 60
//    degrees; the seam only separates them. No face is in conflict.
//  * Alternation: strips adjacent across a complete line form the strip graph; breadth-first
//    levels from the seed's strip (then from each unreached strip) give StripeA where
//    level % period == 0, StripeB otherwise (period 2: A B A B; an odd cycle of strips shows as
//    two adjacent strips of one kind).
//  * Cells (measures only, not regions): the hexagonal cells of the lattice. The vertices get a
//    3-colouring carried from the seed face (the seed's apex is colour 0; every face's third
//    vertex takes the colour its two others leave; a vertex reached with two colours is
//    inconsistent). A cell is the one-ring of an interior colour-0 vertex, consistently coloured,
//    with no neighbour coloured 0; its polygon has as many sides as the centre's valence. On a
//    regular torus whose sides are multiples of 3 the cells tile the faces and are all hexagons;
//    a v5 of colour 0 gives a pentagon (the 3-colouring's defect around it swaps colours 1 and 2
//    and keeps 0, so its cell survives); a v5 or v7 of colour 1 or 2 breaks the cells near it.
//
// Preconditions: a 2-manifold triangle mesh with FF adjacency (boundaries allowed); deleted
// faces are skipped. Postconditions: the mesh is not modified; faceRegion[f] is a dense region
// id (-1 for deleted faces); strips come first (region 0 is the seed's strip), then conflict
// regions, then at most one Background region (faces of other components than the seed's).
// O(F) time and memory (union-find with path halving).
#pragma once

#include <algorithm>
#include <deque>
#include <string>
#include <utility>
#include <vector>

#include "pattern_result.h"

namespace vcg_ext {
namespace irregular {

struct StripeOptions {
  int seedFace = -1;      ///< face where the direction is picked; -1: from seedVertex, else face 0
  int seedVertex = -1;    ///< alternative seed: a selected vertex (its first incident face)
  int direction = 0;      ///< which of the seed face's three edges gives the lattice direction (0..2)
  int period = 2;         ///< stripes alternate every `period` strips (2: A B A B ...)
};

/// Per-face lattice directions and what the strips are made of (the intermediate result of
/// ComputeStripes / ComputeZebra, exposed for tests and for the panels).
struct StripeField {
  std::vector<int> direction;      ///< per face: its direction edge 0..2, -1 if not reached
  std::vector<char> inconsistent;  ///< per face edge (3f + i): the two sides disagree
  std::vector<int> lineOf;         ///< per face edge: edge line id (root), -1 if not a line edge
  std::vector<char> lineComplete;  ///< per line id (indexed like face edges): complete line
  std::vector<int> stripWidth;     ///< per region id (strips only): width
  std::vector<char> cutTree;       ///< per face edge: on the zebra's cut tree (empty for stripes)
};

namespace stripe_detail {

/// Union-find over 0..n-1 with path halving.
struct UnionFind {
  std::vector<int> p;
  explicit UnionFind(size_t n) : p(n) {
    for (size_t i = 0; i < n; ++i) p[i] = int(i);
  }
  int Find(int x) {
    while (p[size_t(x)] != x) x = p[size_t(x)] = p[size_t(p[size_t(x)])];
    return x;
  }
  void Union(int a, int b) {
    a = Find(a), b = Find(b);
    if (a != b) p[size_t(std::max(a, b))] = std::min(a, b);
  }
};

template <class MeshType>
struct Indexer {
  const MeshType& m;
  int F(const typename MeshType::FaceType* f) const { return int(f - &m.face[0]); }
  int V(const typename MeshType::VertexType* v) const { return int(v - &m.vert[0]); }
  int FF(int f, int i) const { return F(m.face[size_t(f)].cFFp(i)); }
  int FFi(int f, int i) const { return m.face[size_t(f)].cFFi(i); }
  int Vx(int f, int z) const { return V(m.face[size_t(f)].cV(z)); }
};

}  // namespace stripe_detail

/// The straight-continuation rule: the direction edge, in the face across edge i of face f,
/// when f's direction edge is d. Returns -1 across a boundary edge. O(1).
template <class MeshType>
int CarryDirection(const MeshType& m, int f, int d, int i) {
  stripe_detail::Indexer<MeshType> ix{m};
  const int g = ix.FF(f, i);
  if (g == f) return -1;
  const int j = ix.FFi(f, i);
  if (i == d) return j;
  const int r = ix.Vx(f, (d + 2) % 3);  // f's apex
  return ix.Vx(g, j) == r ? (j + 2) % 3 : (j + 1) % 3;
}

/// Resolves the seed face of `opt`: seedFace, else the first live face of seedVertex, else the
/// first live face. -1 and a reason when the requested seed does not exist.
template <class MeshType>
int StripeSeedFace(const MeshType& m, const StripeOptions& opt, std::string* why) {
  const int nf = int(m.face.size());
  if (opt.seedFace >= 0) {
    if (opt.seedFace >= nf || m.face[size_t(opt.seedFace)].IsD()) {
      *why = "the seed face " + std::to_string(opt.seedFace) + " does not exist";
      return -1;
    }
    return opt.seedFace;
  }
  if (opt.seedVertex >= 0) {
    if (opt.seedVertex >= int(m.vert.size()) || m.vert[size_t(opt.seedVertex)].IsD()) {
      *why = "the seed vertex " + std::to_string(opt.seedVertex) + " does not exist";
      return -1;
    }
    const auto* v = &m.vert[size_t(opt.seedVertex)];
    for (int f = 0; f < nf; ++f) {  // O(F) once; VF adjacency is not required
      if (m.face[size_t(f)].IsD()) continue;
      for (int z = 0; z < 3; ++z)
        if (m.face[size_t(f)].cV(z) == v) return f;
    }
    *why = "the seed vertex " + std::to_string(opt.seedVertex) + " has no face";
    return -1;
  }
  for (int f = 0; f < nf; ++f)
    if (!m.face[size_t(f)].IsD()) return f;
  *why = "the mesh has no faces";
  return -1;
}

namespace stripe_detail {

/// Interior valence and boundary flag per vertex (FF only). O(F).
template <class MeshType>
void Valences(const MeshType& m, std::vector<int>& valence, std::vector<char>& boundary) {
  Indexer<MeshType> ix{m};
  valence.assign(m.vert.size(), 0);
  boundary.assign(m.vert.size(), 0);
  for (int f = 0; f < int(m.face.size()); ++f) {
    if (m.face[size_t(f)].IsD()) continue;
    for (int z = 0; z < 3; ++z) {
      valence[size_t(ix.Vx(f, z))] += 1;
      if (ix.FF(f, z) == f) boundary[size_t(ix.Vx(f, z))] = boundary[size_t(ix.Vx(f, (z + 1) % 3))] = 1;
    }
  }
  // a boundary vertex has one edge more than faces; it only matters that it is on the boundary
}

/// The corner of f at vertex V(z), stepped counter-clockwise around that vertex (to the face
/// across edge (z+2)%3): its outgoing edge gz turns one edge further. False on a boundary.
template <class MeshType>
bool StepCCW(const Indexer<MeshType>& ix, int& f, int& z) {
  const int e = (z + 2) % 3;
  const int g = ix.FF(f, e);
  if (g == f) return false;
  const int v = ix.Vx(f, z);
  const int j = ix.FFi(f, e);
  z = ix.Vx(g, j) == v ? j : (j + 1) % 3;
  f = g;
  return true;
}

/// The zebra's cut tree: breadth-first over the vertex graph from the boundary (or, on a closed
/// mesh, from the first interior irregular vertex), then every interior irregular vertex joined
/// to the tree along its parents. Marks both sides (3f + i) of the tree's edges. O(F).
template <class MeshType>
void MarkCutTree(const MeshType& m, const std::vector<int>& valence, const std::vector<char>& boundary,
                 std::vector<char>& cut) {
  Indexer<MeshType> ix{m};
  const int nv = int(m.vert.size()), nf = int(m.face.size());
  std::vector<int> start(size_t(nv) + 1, 0), to, key;  // adjacency (CSR) with the face edge
  for (int f = 0; f < nf; ++f)
    if (!m.face[size_t(f)].IsD())
      for (int i = 0; i < 3; ++i) start[size_t(ix.Vx(f, i)) + 1] += 1, start[size_t(ix.Vx(f, (i + 1) % 3)) + 1] += 1;
  for (int v = 0; v < nv; ++v) start[size_t(v) + 1] += start[size_t(v)];
  to.resize(size_t(start[size_t(nv)]));
  key.resize(to.size());
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int f = 0; f < nf; ++f) {
    if (m.face[size_t(f)].IsD()) continue;
    for (int i = 0; i < 3; ++i) {
      const int a = ix.Vx(f, i), b = ix.Vx(f, (i + 1) % 3);
      to[size_t(fill[size_t(a)])] = b, key[size_t(fill[size_t(a)]++)] = 3 * f + i;
      to[size_t(fill[size_t(b)])] = a, key[size_t(fill[size_t(b)]++)] = 3 * f + i;
    }
  }
  auto irregular = [&](int v) { return !boundary[size_t(v)] && valence[size_t(v)] > 0 && valence[size_t(v)] != 6; };
  std::vector<int> parent(size_t(nv), -1), parentKey(size_t(nv), -1), order;
  std::vector<char> inTree(size_t(nv), 0);
  for (int v = 0; v < nv; ++v)
    if (boundary[size_t(v)]) inTree[size_t(v)] = 1, order.push_back(v);
  for (int v = 0; v < nv && order.empty(); ++v)
    if (irregular(v)) inTree[size_t(v)] = 1, order.push_back(v);
  std::vector<char> seen(inTree);
  for (size_t h = 0; h < order.size(); ++h)
    for (int k = start[size_t(order[h])]; k < start[size_t(order[h]) + 1]; ++k)
      if (!seen[size_t(to[size_t(k)])]) {
        seen[size_t(to[size_t(k)])] = 1;
        parent[size_t(to[size_t(k)])] = order[h], parentKey[size_t(to[size_t(k)])] = key[size_t(k)];
        order.push_back(to[size_t(k)]);
      }
  for (int v = 0; v < nv; ++v) {
    if (!irregular(v) || !seen[size_t(v)]) continue;
    for (int w = v; !inTree[size_t(w)]; w = parent[size_t(w)]) {
      inTree[size_t(w)] = 1;
      const int e = parentKey[size_t(w)], f = e / 3, i = e % 3;
      cut[size_t(e)] = 1;
      if (ix.FF(f, i) != f) cut[size_t(3 * ix.FF(f, i) + ix.FFi(f, i))] = 1;
    }
  }
}

/// The lattice 3-colouring from the seed and the cells it gives (see the header comment).
template <class MeshType>
void MeasureCells(const MeshType& m, int seed, int seedApex, const std::vector<int>& valence,
                  const std::vector<char>& boundary, PatternMeasures& out) {
  Indexer<MeshType> ix{m};
  const size_t nv = m.vert.size();
  std::vector<int> colour(nv, -1);
  std::vector<char> bad(nv, 0), seen(m.face.size(), 0);
  colour[size_t(ix.Vx(seed, seedApex))] = 0;
  colour[size_t(ix.Vx(seed, (seedApex + 1) % 3))] = 1;
  colour[size_t(ix.Vx(seed, (seedApex + 2) % 3))] = 2;
  std::deque<int> q{seed};
  seen[size_t(seed)] = 1;
  while (!q.empty()) {
    const int f = q.front();
    q.pop_front();
    for (int z = 0; z < 3; ++z) {  // the vertex whose colour the two others decide
      const int a = colour[size_t(ix.Vx(f, (z + 1) % 3))], b = colour[size_t(ix.Vx(f, (z + 2) % 3))];
      if (a < 0 || b < 0) continue;
      const size_t v = size_t(ix.Vx(f, z));
      const int want = a == b ? -2 : 3 - a - b;
      if (want == -2) {
        bad[size_t(ix.Vx(f, (z + 1) % 3))] = bad[size_t(ix.Vx(f, (z + 2) % 3))] = 1;
      } else if (colour[v] < 0) {
        colour[v] = want;
      } else if (colour[v] != want) {
        bad[v] = 1;
      }
    }
    for (int i = 0; i < 3; ++i) {
      const int g = ix.FF(f, i);
      if (g != f && !seen[size_t(g)]) seen[size_t(g)] = 1, q.push_back(g);
    }
  }
  // a cell: interior colour-0 vertex, consistently coloured, no neighbour coloured 0
  std::vector<char> blocked(nv, 0);
  for (int f = 0; f < int(m.face.size()); ++f) {
    if (m.face[size_t(f)].IsD()) continue;
    int zeros = 0;
    for (int z = 0; z < 3; ++z) zeros += colour[size_t(ix.Vx(f, z))] == 0;
    for (int z = 0; z < 3; ++z)
      if (zeros > 1 || colour[size_t(ix.Vx(f, z))] < 0) blocked[size_t(ix.Vx(f, z))] = 1;
  }
  for (size_t v = 0; v < nv; ++v) {
    if (colour[v] != 0 || bad[v] || blocked[v] || boundary[v] || valence[v] == 0) continue;
    out.cells += 1;
    const int sides = valence[v];
    if (sides != 6) out.nonHexagonalCells += 1;
    if (int(out.cellSidesHistogram.size()) <= sides) out.cellSidesHistogram.resize(size_t(sides) + 1, 0);
    out.cellSidesHistogram[size_t(sides)] += 1;
  }
}

/// Stripes (zebra = false) or zebra (zebra = true). See the header comment.
template <class MeshType>
PatternLabels ComputeStripeLike(const MeshType& m, const StripeOptions& opt, bool zebra, StripeField* fieldOut) {
  if (opt.direction < 0 || opt.direction > 2) return PatternLabels::Fail("the direction must be 0, 1 or 2");
  if (opt.period < 1) return PatternLabels::Fail("the period must be at least 1");
  std::string why;
  const int seed = StripeSeedFace(m, opt, &why);
  if (seed < 0) return PatternLabels::Fail(why);
  Indexer<MeshType> ix{m};
  const int nf = int(m.face.size());
  const size_t ne = size_t(nf) * 3;
  StripeField fd;
  fd.direction.assign(size_t(nf), -1);
  fd.inconsistent.assign(ne, 0);

  std::vector<int> valence;
  std::vector<char> boundary;
  Valences(m, valence, boundary);
  // zebra: the flood crosses the cut tree (edges joining the irregular vertices) last, so the
  // seams lie on it, starting at the singularities
  std::vector<char> cut(ne, 0);
  if (zebra) MarkCutTree(m, valence, boundary, cut);

  // 1. the direction flood
  fd.direction[size_t(seed)] = opt.direction;
  std::deque<int> q{seed};
  std::vector<std::pair<int, int>> deferred;  // (face, edge) across the cut tree
  for (size_t next = 0;;) {
    if (q.empty()) {  // cross the cut tree only where nothing else reaches
      while (next < deferred.size() && q.empty()) {
        const int f = deferred[next].first, i = deferred[next].second;
        ++next;
        const int g = ix.FF(f, i);
        if (fd.direction[size_t(g)] >= 0) continue;
        fd.direction[size_t(g)] = CarryDirection(m, f, fd.direction[size_t(f)], i);
        q.push_back(g);
      }
      if (q.empty()) break;
    }
    const int f = q.front();
    q.pop_front();
    for (int i = 0; i < 3; ++i) {
      const int dg = CarryDirection(m, f, fd.direction[size_t(f)], i);
      if (dg < 0) continue;
      const int g = ix.FF(f, i);
      if (fd.direction[size_t(g)] < 0) {
        if (cut[size_t(3 * f + i)]) {
          deferred.push_back({f, i});
          continue;
        }
        fd.direction[size_t(g)] = dg;
        q.push_back(g);
      } else if (fd.direction[size_t(g)] != dg) {
        fd.inconsistent[size_t(3 * f + i)] = fd.inconsistent[size_t(3 * g + ix.FFi(f, i))] = 1;
      }
    }
  }
  std::vector<char> conflict(size_t(nf), 0);
  if (!zebra)
    for (int f = 0; f < nf; ++f)
      for (int i = 0; i < 3; ++i)
        if (fd.inconsistent[size_t(3 * f + i)]) conflict[size_t(f)] = 1;
  auto inStrip = [&](int f) { return fd.direction[size_t(f)] >= 0 && !conflict[size_t(f)]; };

  // 2. line edges and edge lines
  auto key = [&](int f, int i) {  // one key per undirected edge
    const int g = ix.FF(f, i);
    return g == f ? 3 * f + i : std::min(3 * f + i, 3 * g + ix.FFi(f, i));
  };
  std::vector<char> isLine(ne, 0);
  for (int f = 0; f < nf; ++f)
    if (inStrip(f)) isLine[size_t(key(f, fd.direction[size_t(f)]))] = 1;
  UnionFind lines(ne);
  std::vector<char> endsAtIrregular(ne, 0);
  for (int f = 0; f < nf; ++f) {
    if (!inStrip(f)) continue;
    const int i = fd.direction[size_t(f)];
    const int k = key(f, i);
    // at V(i) the line edge is the corner's outgoing edge: the opposite one is 3 steps round;
    // at V(i+1) the corner's outgoing edge is one step before the line edge: 4 steps
    for (int end = 0; end < 2; ++end) {
      int g = f, z = end == 0 ? i : (i + 1) % 3;
      const int v = ix.Vx(f, z);
      if (boundary[size_t(v)]) continue;
      if (valence[size_t(v)] != 6) {
        endsAtIrregular[size_t(k)] = 1;
        continue;
      }
      bool ok = true;
      for (int s = 0; s < (end == 0 ? 3 : 4) && ok; ++s) ok = StepCCW(ix, g, z);
      if (ok && isLine[size_t(key(g, z))]) lines.Union(k, key(g, z));
    }
  }
  std::vector<char> complete(ne, 1);
  for (size_t e = 0; e < ne; ++e)
    if (isLine[e] && endsAtIrregular[e]) complete[size_t(lines.Find(int(e)))] = 0;
  auto lineRoot = [&](int f, int i) { return isLine[size_t(key(f, i))] ? lines.Find(key(f, i)) : -1; };

  // 3. strips
  UnionFind strips(size_t(nf) + 0);
  for (int f = 0; f < nf; ++f) {
    if (!inStrip(f)) continue;
    for (int i = 0; i < 3; ++i) {
      const int g = ix.FF(f, i);
      if (g == f || !inStrip(g) || fd.inconsistent[size_t(3 * f + i)]) continue;
      const int l = lineRoot(f, i);
      if (l < 0 || !complete[size_t(l)]) strips.Union(f, g);
    }
  }
  // strip graph (across complete lines), BFS levels from the seed's strip
  std::vector<int> stripId(size_t(nf), -1);
  std::vector<int> roots;  // strip roots in discovery order
  std::vector<std::vector<int>> adj;
  std::vector<int> rootIndex(size_t(nf), -1);
  auto indexOf = [&](int f) {
    const int r = strips.Find(f);
    if (rootIndex[size_t(r)] < 0) {
      rootIndex[size_t(r)] = int(roots.size());
      roots.push_back(r);
      adj.emplace_back();
    }
    return rootIndex[size_t(r)];
  };
  if (inStrip(seed)) indexOf(seed);
  for (int f = 0; f < nf; ++f)
    if (inStrip(f)) stripId[size_t(f)] = indexOf(f);
  for (int f = 0; f < nf; ++f) {
    if (!inStrip(f)) continue;
    for (int i = 0; i < 3; ++i) {
      const int g = ix.FF(f, i);
      if (g == f || !inStrip(g) || fd.inconsistent[size_t(3 * f + i)]) continue;
      const int a = stripId[size_t(f)], b = stripId[size_t(g)];
      if (a != b) adj[size_t(a)].push_back(b);
    }
  }
  const int ns = int(roots.size());
  std::vector<int> level(size_t(ns), -1), order;
  for (int s0 = 0; s0 < ns; ++s0) {
    if (level[size_t(s0)] >= 0) continue;
    level[size_t(s0)] = 0;
    order.push_back(s0);
    for (size_t h = order.size() - 1; h < order.size(); ++h)
      for (int t : adj[size_t(order[h])])
        if (level[size_t(t)] < 0) level[size_t(t)] = level[size_t(order[h])] + 1, order.push_back(t);
  }
  // region ids: strips in BFS order (the seed's strip is 0)
  std::vector<int> regionOfStrip(size_t(ns), -1);
  PatternLabels out;
  for (int s : order) {
    regionOfStrip[size_t(s)] = int(out.regionKind.size());
    out.regionKind.push_back(level[size_t(s)] % opt.period == 0 ? RegionKind::StripeA : RegionKind::StripeB);
  }
  out.faceRegion.assign(size_t(nf), -1);
  for (int f = 0; f < nf; ++f)
    if (stripId[size_t(f)] >= 0) out.faceRegion[size_t(f)] = regionOfStrip[size_t(stripId[size_t(f)])];

  // widths: distinct incomplete lines inside each strip
  std::vector<std::pair<int, int>> inner;
  for (int f = 0; f < nf; ++f) {
    if (!inStrip(f)) continue;
    for (int i = 0; i < 3; ++i) {
      const int g = ix.FF(f, i);
      if (g == f || g < f || out.faceRegion[size_t(g)] != out.faceRegion[size_t(f)]) continue;
      const int l = lineRoot(f, i);
      if (l >= 0 && !complete[size_t(l)]) inner.push_back({out.faceRegion[size_t(f)], l});
    }
  }
  std::sort(inner.begin(), inner.end());
  inner.erase(std::unique(inner.begin(), inner.end()), inner.end());
  fd.stripWidth.assign(size_t(ns), 1);
  for (auto& p : inner) fd.stripWidth[size_t(p.first)] += 1;
  PatternMeasures& ms = out.measures;
  ms.strips = ns;
  for (int w : fd.stripWidth) {
    if (int(ms.stripWidthHistogram.size()) <= w) ms.stripWidthHistogram.resize(size_t(w) + 1, 0);
    ms.stripWidthHistogram[size_t(w)] += 1;
  }

  // conflict regions: components of conflict faces
  for (int f = 0; f < nf; ++f) {
    if (!conflict[size_t(f)] || out.faceRegion[size_t(f)] >= 0) continue;
    const int id = int(out.regionKind.size());
    out.regionKind.push_back(RegionKind::Conflict);
    ms.conflictRegions += 1;
    std::vector<int> stack{f};
    out.faceRegion[size_t(f)] = id;
    while (!stack.empty()) {
      const int h = stack.back();
      stack.pop_back();
      ms.conflictFaces += 1;
      for (int i = 0; i < 3; ++i) {
        const int g = ix.FF(h, i);
        if (conflict[size_t(g)] && out.faceRegion[size_t(g)] < 0) out.faceRegion[size_t(g)] = id, stack.push_back(g);
      }
    }
  }
  // faces the flood did not reach (other components)
  for (int f = 0; f < nf; ++f) {
    if (m.face[size_t(f)].IsD() || out.faceRegion[size_t(f)] >= 0) continue;
    if (out.regionKind.empty() || out.regionKind.back() != RegionKind::Background)
      out.regionKind.push_back(RegionKind::Background);
    out.faceRegion[size_t(f)] = int(out.regionKind.size()) - 1;
  }

  MeasureCells(m, seed, (opt.direction + 2) % 3, valence, boundary, ms);
  if (fieldOut) {
    fd.lineOf.assign(ne, -1);
    fd.lineComplete.assign(ne, 0);
    for (int f = 0; f < nf; ++f)
      for (int i = 0; i < 3; ++i) fd.lineOf[size_t(3 * f + i)] = m.face[size_t(f)].IsD() ? -1 : lineRoot(f, i);
    for (size_t e = 0; e < ne; ++e) fd.lineComplete[e] = complete[e];
    if (zebra) fd.cutTree = cut;
    *fieldOut = std::move(fd);
  }
  return out;
}

}  // namespace stripe_detail

/// Stripes: triangle strips between consecutive complete edge lines of one lattice direction,
/// carried from the seed; faces on inconsistent edges are Conflict. Fills faceRegion,
/// regionKind (StripeA/StripeB/Conflict/Background) and the measures (strips, width histogram,
/// cells, conflict regions and faces). Reads the mesh only. O(F).
template <class MeshType>
PatternLabels ComputeStripes(const MeshType& m, const StripeOptions& opt, StripeField* field = nullptr) {
  return stripe_detail::ComputeStripeLike(m, opt, false, field);
}

/// Zebra (Fig. 13): the same strips, but the direction follows the lattice through the
/// singularities: the seams where the carried direction comes back turned by 60 degrees only
/// separate strips (no Conflict faces). Reads the mesh only. O(F).
template <class MeshType>
PatternLabels ComputeZebra(const MeshType& m, const StripeOptions& opt, StripeField* field = nullptr) {
  return stripe_detail::ComputeStripeLike(m, opt, true, field);
}

}  // namespace irregular
}  // namespace vcg_ext
