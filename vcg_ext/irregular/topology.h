// filter_irregular: topology queries on vcg triangle meshes.
//
// Valence, the star of a vertex, irregular-vertex classification, Euler characteristic,
// boundary loops, genus and the discrete Gauss-Bonnet identity of the paper (Li et al.,
// "Editing Operations for Irregular Vertices in Triangle Meshes", eq. 2):
//
//     sum_{interior v} (6 - valence(v)) + sum_{boundary v} (4 - valence(v)) = 6 * chi
//
// eq. 2 is the invariant every edit keeps; it counts every boundary vertex against 4.
// Which vertices are *irregular* on a boundary follows the boundary valence rule
// (RegularBoundaryValence below): regular valence round(corner angle / 60) + 1, so 4 on a
// smooth stretch and 3 at a 120 degree corner. The two agree on a smooth boundary; at a corner
// eq. 2 sees a defect that the corner's shape, not an irregular vertex, accounts for.
//
// Preconditions: the mesh is a vcg triangle mesh with FF adjacency up to date. Functions that
// start from a single vertex (VertexStar, Valence) also need VF adjacency.
// Orientation: vcg faces are counter-clockwise (CCW) seen from outside; "CCW around v" below
// means counter-clockwise seen from outside the surface.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/simplex/face/pos.h>

#include "result.h"
#include "small_vector.h"

namespace vcg_ext {
namespace irregular {

/// A corner of a face: vertex f->V(z).
template <class FaceType>
struct Corner {
  FaceType* f = nullptr;
  int z = 0;
};

/// (z + 1) % 3 and (z + 2) % 3 for a corner index z in {0, 1, 2}: a compare instead of a
/// division by 3 (the star walks below take these at every step, and StarOf is a tenth of
/// Automatic Reduction's instructions).
inline int Succ3(int z) { return z == 2 ? 0 : z + 1; }
inline int Pred3(int z) { return z == 0 ? 2 : z - 1; }

/// Next corner counter-clockwise around the vertex f->V(z): the face across edge (z+2)%3
/// (the edge from V(z+2) to V(z)). Returns {nullptr,0} on a boundary edge.
template <class FaceType>
inline Corner<FaceType> NextCornerCCW(const Corner<FaceType>& c) {
  const int e = Pred3(c.z);
  FaceType* g = c.f->FFp(e);
  if (g == c.f) return Corner<FaceType>();
  // Consistent orientation: g runs the shared edge from V(z) to V(z+2), so V(z) = g->V(j).
  return Corner<FaceType>{g, c.f->FFi(e)};
}

/// Next corner clockwise around f->V(z): the face across edge z. {nullptr,0} on a boundary.
template <class FaceType>
inline Corner<FaceType> NextCornerCW(const Corner<FaceType>& c) {
  FaceType* g = c.f->FFp(c.z);
  if (g == c.f) return Corner<FaceType>();
  return Corner<FaceType>{g, Succ3(c.f->FFi(c.z))};
}

/// The star (1-ring) of a vertex, in CCW order.
/// corners[k] is the k-th incident face; for an interior vertex neighbors[k] = corners[k].f->V(z+1)
/// and the ring closes; for a boundary vertex the fan starts at the boundary edge whose other
/// end is neighbors[0] and ends at neighbors.back(), so neighbors.size() == corners.size() + 1.
template <class MeshType>
struct VertexStar {
  typedef typename MeshType::FaceType FaceType;
  typedef typename MeshType::VertexType VertexType;
  // Inline storage (small_vector.h): building a star allocates nothing up to valence 12.
  SmallVector<Corner<FaceType>, 12> corners;
  SmallVector<VertexType*, 13> neighbors;
  bool boundary = false;
  bool manifold = true;  ///< false if the walk did not close or exceeded the bound
  int Valence() const { return int(neighbors.size()); }
  /// Index of w in neighbors, or -1.
  int IndexOf(const VertexType* w) const {
    for (size_t i = 0; i < neighbors.size(); ++i)
      if (neighbors[i] == w) return int(i);
    return -1;
  }
};

/// Builds the CCW star of v from its VF entry and FF adjacency. O(valence).
/// Precondition: v is not deleted and is referenced by a face through v->VFp().
template <class MeshType>
VertexStar<MeshType> StarOf(typename MeshType::VertexType* v, int maxValence = 4096) {
  typedef typename MeshType::FaceType FaceType;
  VertexStar<MeshType> s;
  if (v->cVFp() == nullptr) {
    s.manifold = false;
    return s;
  }
  Corner<FaceType> start{v->VFp(), v->VFi()};
  // Most vertices are interior: walk counter-clockwise from the VF entry first; if the fan
  // closes, that is the star (the rewind below would have come back to `start` after a whole
  // turn, so the result is the same at half the walking). Only a fan that meets a border, or
  // runs past the bound, is redone from its clockwise end.
  {
    Corner<FaceType> c = start;
    for (int guard = 0; guard <= maxValence; ++guard) {
      s.corners.push_back(c);
      s.neighbors.push_back(c.f->V(Succ3(c.z)));
      c = NextCornerCCW(c);
      if (c.f == nullptr) break;
      if (c.f == start.f && c.z == start.z) return s;
    }
    s.corners.clear();
    s.neighbors.clear();
  }
  // Rewind clockwise to the boundary, if there is one.
  Corner<FaceType> c = start;
  int guard = 0;
  for (;;) {
    Corner<FaceType> p = NextCornerCW(c);
    if (p.f == nullptr) {
      s.boundary = true;
      break;
    }
    c = p;
    if (c.f == start.f && c.z == start.z) break;
    if (++guard > maxValence) {
      s.manifold = false;
      return s;
    }
  }
  Corner<FaceType> first = c;
  guard = 0;
  for (;;) {
    s.corners.push_back(c);
    s.neighbors.push_back(c.f->V(Succ3(c.z)));
    Corner<FaceType> n = NextCornerCCW(c);
    if (n.f == nullptr) {
      if (!s.boundary) s.manifold = false;  // FF says border only one way: broken adjacency
      s.neighbors.push_back(c.f->V(Pred3(c.z)));
      break;
    }
    c = n;
    if (c.f == first.f && c.z == first.z) {
      if (s.boundary) s.manifold = false;
      break;
    }
    if (++guard > maxValence) {
      s.manifold = false;
      break;
    }
  }
  return s;
}

/// Valence (number of incident edges) of v. O(valence). Needs VF and FF.
template <class MeshType>
int Valence(typename MeshType::VertexType* v, int maxValence = 4096) {
  // StarOf's walk, counting instead of storing: the same value, no allocation.
  typedef typename MeshType::FaceType FaceType;
  if (v->cVFp() == nullptr) return 0;
  const Corner<FaceType> start{v->VFp(), v->VFi()};
  // As in StarOf: an interior fan closes counter-clockwise from the VF entry in one turn, and
  // the rewind below would come back to `start` after a whole turn (the same count at half
  // the walking); only a fan that meets a border, or runs past the bound, is redone.
  {
    Corner<FaceType> c = start;
    for (int n = 1; n <= maxValence + 1; ++n) {
      c = NextCornerCCW(c);
      if (c.f == nullptr) break;
      if (c.f == start.f && c.z == start.z) return n;
    }
  }
  Corner<FaceType> c = start;
  int guard = 0;
  for (;;) {  // rewind clockwise to the boundary, if there is one
    Corner<FaceType> p = NextCornerCW(c);
    if (p.f == nullptr) break;
    c = p;
    if (c.f == start.f && c.z == start.z) break;
    if (++guard > maxValence) return 0;
  }
  const Corner<FaceType> first = c;
  int n = 0;
  guard = 0;
  for (;;) {
    ++n;
    Corner<FaceType> next = NextCornerCCW(c);
    if (next.f == nullptr) return n + 1;  // the fan's last neighbour
    c = next;
    if (c.f == first.f && c.z == first.z) return n;
    if (++guard > maxValence) return n;
  }
}

/// Is v on the boundary (its fan meets a border edge)? StarOf's rewind alone, no allocation.
template <class MeshType>
bool OnBoundary(typename MeshType::VertexType* v, int maxValence = 4096) {
  typedef typename MeshType::FaceType FaceType;
  if (v->cVFp() == nullptr) return false;
  const Corner<FaceType> start{v->VFp(), v->VFi()};
  Corner<FaceType> c = start;
  for (int guard = 0; guard <= maxValence; ++guard) {
    Corner<FaceType> p = NextCornerCW(c);
    if (p.f == nullptr) return true;
    c = p;
    if (c.f == start.f && c.z == start.z) return false;
  }
  return false;  // StarOf gives up too (a non-manifold walk), with boundary still false
}

/// Valence of v if it is an interior vertex, -1 if it lies on the boundary: OnBoundary and
/// Valence in one walk (an interior fan closes counter-clockwise from the VF entry, a boundary
/// fan meets a border edge on the way). The reduction asks "interior and of valence d?" of
/// every vertex near an edit; the two walks were 3.5% of its time on the bull (0.9.22).
template <class MeshType>
int InteriorValence(typename MeshType::VertexType* v, int maxValence = 4096) {
  typedef typename MeshType::FaceType FaceType;
  if (v->cVFp() != nullptr) {
    const Corner<FaceType> start{v->VFp(), v->VFi()};
    Corner<FaceType> c = start;
    for (int n = 1; n <= maxValence + 1; ++n) {
      c = NextCornerCCW(c);
      if (c.f == nullptr) return -1;
      if (c.f == start.f && c.z == start.z) return n;
    }
  }
  // no face, or a walk past the bound (not a manifold fan): what the two queries say
  return OnBoundary<MeshType>(v, maxValence) ? -1 : Valence<MeshType>(v, maxValence);
}

/// The valence eq. 2 counts a vertex against: 6 inside, 4 on the boundary (paper sec. 4).
/// This is the Gauss-Bonnet bookkeeping valence; for "is this boundary vertex irregular" use
/// the boundary valence rule (RegularBoundaryValence), which also looks at the corner angle.
inline int RegularValence(bool boundary) { return boundary ? 4 : 6; }

/// The boundary valence rule. A boundary vertex whose incident faces span the corner angle
/// `cornerAngleDeg` (the sum of its face angles, degrees) is regular when its faces are
/// equilateral-like, i.e. when it has angle / 60 faces: valence round(angle / 60) + 1, at
/// least 2 (one face). So: 4 on a smooth stretch (angle in [150, 210)), 3 at a 120 degree
/// corner, 2 at 60, 5 at 240. Rounding is half away from zero (std::lround), so a boundary
/// vertex is a *corner* (IsBoundaryCorner) exactly when its angle is below 150 or at least 210
/// degrees, i.e. |angle - 180| >= 30 but for an angle of exactly 150.
inline int RegularBoundaryValence(double cornerAngleDeg) {
  if (!(cornerAngleDeg > 0)) return 4;  // no faces / not a number: treat as a smooth stretch
  return std::max(2, int(std::lround(cornerAngleDeg / 60.0)) + 1);
}

/// A boundary vertex whose regular valence differs from the smooth-stretch 4 (see above).
inline bool IsBoundaryCorner(double cornerAngleDeg) { return RegularBoundaryValence(cornerAngleDeg) != 4; }

/// Angle (degrees) of face f at its corner z, computed in double.
template <class FaceType>
double FaceAngleDeg(const FaceType* f, int z) {
  const auto& p = f->cP(z);
  const auto& q = f->cP((z + 1) % 3);
  const auto& r = f->cP((z + 2) % 3);
  const double a[3] = {double(q[0]) - double(p[0]), double(q[1]) - double(p[1]), double(q[2]) - double(p[2])};
  const double b[3] = {double(r[0]) - double(p[0]), double(r[1]) - double(p[1]), double(r[2]) - double(p[2])};
  const double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double sn = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  const double cs = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return std::atan2(sn, cs) * 180.0 / M_PI;
}

/// Corner angle of a vertex: the sum of the angles of its incident faces at it (degrees).
template <class MeshType>
double CornerAngleDeg(const VertexStar<MeshType>& s) {
  double sum = 0;
  for (auto& c : s.corners) sum += FaceAngleDeg(c.f, c.z);
  return sum;
}

/// The regular valence of a vertex: 6 inside; on the boundary, the boundary valence rule.
template <class MeshType>
int RegularValenceOf(const VertexStar<MeshType>& s) {
  return s.boundary ? RegularBoundaryValence(CornerAngleDeg(s)) : 6;
}

/// Valence of the interior vertex with the same irregularity: valence + 6 - regular valence,
/// so a boundary vertex of valence 3 on a smooth stretch counts as a v5 and one of valence 3
/// at a 120 degree corner as a v6. The colour legend and "select valence N" use it.
inline int EquivalentValence(int valence, int regularValence) { return valence + 6 - regularValence; }

/// Old form: a boundary vertex counted as if on a smooth stretch (valence + 2).
inline int EquivalentValence(int valence, bool boundary) { return boundary ? valence + 2 : valence; }

/// Per-vertex valence and boundary flag for the whole mesh, from FF only. O(F).
template <class MeshType>
struct ValenceField {
  std::vector<int> valence;       ///< indexed like m.vert; 0 for deleted or unreferenced vertices
  std::vector<char> boundary;     ///< 1 if the vertex lies on a boundary edge
  std::vector<char> referenced;   ///< 1 if some live face references the vertex
  std::vector<int> regular;       ///< regular valence: 6 inside, the boundary valence rule on the boundary

  /// Irregular by the boundary valence rule (interior: valence != 6).
  bool IsIrregular(size_t i) const { return referenced[i] && valence[i] != regular[i]; }
  /// A boundary vertex at a corner (regular valence != 4).
  bool IsCorner(size_t i) const { return referenced[i] && boundary[i] && regular[i] != 4; }
  int Equivalent(size_t i) const { return EquivalentValence(valence[i], regular[i]); }
};

template <class MeshType>
ValenceField<MeshType> ComputeValences(MeshType& m) {
  ValenceField<MeshType> vf;
  const size_t n = m.vert.size();
  vf.valence.assign(n, 0);
  vf.boundary.assign(n, 0);
  vf.referenced.assign(n, 0);
  std::vector<int> borderEdges(n, 0);
  for (auto fi = m.face.begin(); fi != m.face.end(); ++fi) {
    if (fi->IsD()) continue;
    for (int z = 0; z < 3; ++z) {
      size_t i = vcg::tri::Index(m, fi->V(z));
      vf.valence[i] += 1;  // one face per corner; each interior edge is seen by two faces
      vf.referenced[i] = 1;
      if (fi->FFp(z) == &*fi) {
        borderEdges[vcg::tri::Index(m, fi->V(z))] += 1;
        borderEdges[vcg::tri::Index(m, fi->V((z + 1) % 3))] += 1;
      }
    }
  }
  // For a manifold vertex: edges = (2 * faces + border edges) / 2.
  for (size_t i = 0; i < n; ++i) {
    vf.boundary[i] = borderEdges[i] > 0;
    vf.valence[i] += borderEdges[i] / 2;
  }
  // The boundary valence rule needs the corner angle of the boundary vertices.
  std::vector<double> angle(n, 0.0);
  for (auto fi = m.face.begin(); fi != m.face.end(); ++fi) {
    if (fi->IsD()) continue;
    for (int z = 0; z < 3; ++z) {
      size_t i = vcg::tri::Index(m, fi->V(z));
      if (vf.boundary[i]) angle[i] += FaceAngleDeg(&*fi, z);
    }
  }
  vf.regular.assign(n, 6);
  for (size_t i = 0; i < n; ++i)
    if (vf.boundary[i]) vf.regular[i] = RegularBoundaryValence(angle[i]);
  return vf;
}

/// Counts of the mesh's elements and its topological invariants.
struct TopologySummary {
  int vertices = 0;       ///< referenced, live vertices
  int edges = 0;
  int faces = 0;
  int boundaryEdges = 0;
  int boundaryLoops = 0;
  int components = 0;
  int eulerCharacteristic = 0;
  int genus = 0;          ///< total genus over components (orientable surfaces)
  int irregular = 0;          ///< interior valence != 6, boundary by the boundary valence rule
  int boundaryIrregular = 0;  ///< the boundary vertices among `irregular`
  int boundaryCorners = 0;    ///< boundary vertices at a corner (regular valence != 4)
  int gaussBonnetSum = 0;  ///< eq. 2: sum of (6 - valence) inside and (4 - valence) on the boundary
  std::map<int, int> histogram;          ///< valence -> count, interior vertices
  std::map<int, int> boundaryHistogram;  ///< valence -> count, boundary vertices
  std::map<int, int> equivalentHistogram;  ///< equivalent valence (EquivalentValence) -> count, all vertices
  bool GaussBonnetHolds() const { return gaussBonnetSum == 6 * eulerCharacteristic; }
};

/// Number of connected components through FF adjacency. O(F).
template <class MeshType>
int CountComponents(MeshType& m) {
  std::vector<char> seen(m.face.size(), 0);
  std::vector<typename MeshType::FacePointer> stack;
  int comps = 0;
  for (size_t i = 0; i < m.face.size(); ++i) {
    if (m.face[i].IsD() || seen[i]) continue;
    ++comps;
    seen[i] = 1;
    stack.push_back(&m.face[i]);
    while (!stack.empty()) {
      auto f = stack.back();
      stack.pop_back();
      for (int z = 0; z < 3; ++z) {
        auto g = f->FFp(z);
        size_t gi = vcg::tri::Index(m, g);
        if (!seen[gi]) {
          seen[gi] = 1;
          stack.push_back(g);
        }
      }
    }
  }
  return comps;
}

/// Number of boundary loops, walking boundary edges with vcg::face::Pos. O(F).
template <class MeshType>
int CountBoundaryLoops(MeshType& m) {
  typedef typename MeshType::FaceType FaceType;
  std::vector<char> seen(3 * m.face.size(), 0);
  int loops = 0;
  for (size_t i = 0; i < m.face.size(); ++i) {
    FaceType* f = &m.face[i];
    if (f->IsD()) continue;
    for (int z = 0; z < 3; ++z) {
      if (f->FFp(z) != f || seen[3 * i + z]) continue;
      ++loops;
      vcg::face::Pos<FaceType> p(f, z);
      const vcg::face::Pos<FaceType> start = p;
      size_t guard = 0;
      do {
        seen[3 * vcg::tri::Index(m, p.F()) + p.E()] = 1;
        p.NextB();
      } while (p != start && ++guard <= 3 * m.face.size());
    }
  }
  return loops;
}

/// Histogram, Euler characteristic, boundary loops, genus and the Gauss-Bonnet check (eq. 2).
/// Precondition: a manifold triangle mesh with FF adjacency.
template <class MeshType>
TopologySummary Summarize(MeshType& m) {
  TopologySummary s;
  ValenceField<MeshType> vf = ComputeValences(m);
  for (size_t i = 0; i < m.vert.size(); ++i) {
    if (!vf.referenced[i]) continue;
    ++s.vertices;
    if (vf.boundary[i])
      s.boundaryHistogram[vf.valence[i]]++;
    else
      s.histogram[vf.valence[i]]++;
    s.equivalentHistogram[vf.Equivalent(i)]++;
    if (vf.IsIrregular(i)) {
      ++s.irregular;
      if (vf.boundary[i]) ++s.boundaryIrregular;
    }
    if (vf.IsCorner(i)) ++s.boundaryCorners;
    s.gaussBonnetSum += RegularValence(vf.boundary[i]) - vf.valence[i];
  }
  for (auto fi = m.face.begin(); fi != m.face.end(); ++fi) {
    if (fi->IsD()) continue;
    ++s.faces;
    for (int z = 0; z < 3; ++z)
      if (fi->FFp(z) == &*fi) ++s.boundaryEdges;
  }
  s.edges = (3 * s.faces + s.boundaryEdges) / 2;
  s.eulerCharacteristic = s.vertices - s.edges + s.faces;
  s.boundaryLoops = CountBoundaryLoops(m);
  s.components = CountComponents(m);
  // chi = sum over components of (2 - 2 g_i - b_i)
  s.genus = (2 * s.components - s.eulerCharacteristic - s.boundaryLoops) / 2;
  return s;
}

}  // namespace irregular
}  // namespace vcg_ext
