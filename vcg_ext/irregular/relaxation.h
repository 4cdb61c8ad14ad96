// filter_irregular: geometric relaxation after connectivity edits (paper sec. 8).
//
// Connectivity edits leave badly shaped triangles. Two relaxations move vertices along the
// surface, never changing connectivity:
//  * LocalRelax (Turk 1992 style, the paper's "local relaxation"): vertices move one at a time
//    in their tangent plane toward the centroid of their neighbours, then are projected back
//    onto the original surface. Cheap enough to run on the k-ring of an edit after every step.
//  * GlobalRelax (eq. 5): minimizes sum_i sum_{j in N_i} |p_j - (p_i + d u_ij)|^2, where d is
//    the mean edge length of v_i's 1-ring (a documented deviation: the paper's global mean
//    fights the size gradation of adaptive meshes; see README) and u_ij splits the tangent
//    plane of v_i into equal angles (alpha_ij = alpha_0 + k_j 2 pi / valence, alpha_0 the best
//    rotation). Each vertex is constrained to its current tangent plane (two unknowns per
//    vertex), the quadratic problem is solved with Eigen's conjugate gradients (sparse LDLT
//    optional), and vertices are projected back onto the original surface. Iterated. Each
//    round's step is guarded (see GlobalRelax): it never lowers the smallest angle nor raises
//    the share of triangles under 30 degrees, and lowers eq. 5's energy strictly or is not taken.
// Both refuse a vertex move that would turn an incident triangle over (fold), and keep
// vertices on sharp creases fixed when a feature angle is given. Both cost O(region) per
// sweep or round (plus the global solve): nothing is sized by the mesh.
//
// Boundary vertices stay fixed unless RelaxOptions::boundaryCurve is given (a BoundaryCurve
// made from the original mesh). Then both relaxations move boundary vertices along the
// boundary, projected onto the original boundary polyline, so the holes keep their shape:
// LocalRelax towards the midpoint of the two boundary neighbours, GlobalRelax with one unknown
// (along the boundary) per boundary vertex in eq. 5. A corner (corner angle, the sum of its
// face angles, differing from 180 degrees by at least RelaxOptions::cornerAngleDeg, default
// 30: the vertices the boundary valence rule of topology.h gives a regular valence other than
// 4, and those at exactly 150 degrees) stays fixed.
#pragma once

#include <algorithm>
#include <chrono>
#include <limits>
#include <cmath>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <Eigen/Sparse>
#include <vcg/complex/complex.h>

#include "crease_line_edges.h"
#include "crease_lines.h"
#include "surface_projector.h"
#include "stamp_set.h"
#include "topology.h"

namespace vcg_ext {
namespace irregular {

/// The boundary polyline of a mesh as it was (its boundary edges), with closest-point queries
/// through a uniform hash grid of cell size about two boundary edges. O(B) to build; a query
/// looks at the few cells around the point.
class BoundaryCurve {
 public:
  typedef vcg::Point3d P;

  template <class MeshType>
  explicit BoundaryCurve(const MeshType& m) {
    double len = 0;
    for (auto& f : m.face) {
      if (f.IsD()) continue;
      for (int z = 0; z < 3; ++z)
        if (f.cFFp(z) == &f) {
          seg_.push_back({P::Construct(f.cP(z)), P::Construct(f.cP((z + 1) % 3))});
          len += (seg_.back().b - seg_.back().a).Norm();
        }
    }
    cell_ = seg_.empty() ? 1.0 : std::max(1e-12, 2.0 * len / double(seg_.size()));
    for (size_t i = 0; i < seg_.size(); ++i) {
      const Key lo = KeyOf(seg_[i].a), hi = KeyOf(seg_[i].b);
      for (long x = std::min(lo.x, hi.x); x <= std::max(lo.x, hi.x); ++x)
        for (long y = std::min(lo.y, hi.y); y <= std::max(lo.y, hi.y); ++y)
          for (long z = std::min(lo.z, hi.z); z <= std::max(lo.z, hi.z); ++z) grid_[Hash(Key{x, y, z})].push_back(i);
    }
  }

  bool Empty() const { return seg_.empty(); }
  size_t Segments() const { return seg_.size(); }

  /// Closest point of the original boundary polyline to p (p itself if the mesh had none).
  template <class Coord>
  Coord Closest(const Coord& p, double* dist = nullptr) const {
    const P q = P::Construct(p);
    double best = std::numeric_limits<double>::max();
    P bestP = q;
    const Key k = KeyOf(q);
    for (long r = 1; r <= 64 && best == std::numeric_limits<double>::max(); r *= 2) {
      for (long x = k.x - r; x <= k.x + r; ++x)
        for (long y = k.y - r; y <= k.y + r; ++y)
          for (long z = k.z - r; z <= k.z + r; ++z) {
            auto it = grid_.find(Hash(Key{x, y, z}));
            if (it == grid_.end()) continue;
            for (size_t i : it->second) {
              const P c = OnSegment(seg_[i], q);
              const double d = (c - q).SquaredNorm();
              if (d < best) best = d, bestP = c;
            }
          }
    }
    if (best == std::numeric_limits<double>::max())  // far from every cell: look at all
      for (auto& s : seg_) {
        const P c = OnSegment(s, q);
        const double d = (c - q).SquaredNorm();
        if (d < best) best = d, bestP = c;
      }
    if (dist) *dist = seg_.empty() ? 0 : std::sqrt(best);
    return Coord::Construct(bestP);
  }

 private:
  struct Seg {
    P a, b;
  };
  struct Key {
    long x, y, z;
  };
  Key KeyOf(const P& p) const {
    return Key{long(std::floor(p[0] / cell_)), long(std::floor(p[1] / cell_)), long(std::floor(p[2] / cell_))};
  }
  static size_t Hash(const Key& k) {
    return size_t(k.x) * 73856093u ^ size_t(k.y) * 19349663u ^ size_t(k.z) * 83492791u;
  }
  static P OnSegment(const Seg& s, const P& q) {
    const P d = s.b - s.a;
    const double l2 = d.SquaredNorm();
    double t = l2 > 0 ? (q - s.a).dot(d) / l2 : 0;
    t = std::max(0.0, std::min(1.0, t));
    return s.a + d * t;
  }
  std::vector<Seg> seg_;
  std::unordered_map<size_t, std::vector<size_t>> grid_;  // hash collisions only add candidates
  double cell_ = 1;
};

enum class RelaxMode { Local = 0, Global = 1 };
enum class RelaxSolver { ConjugateGradient = 0, SparseLDLT = 1 };

struct RelaxOptions {
  RelaxMode mode = RelaxMode::Local;
  int iterations = 10;            ///< sweeps (local) or solve-and-project rounds (global)
  double step = 0.5;              ///< local: share of the way to the target per sweep
  bool reproject = true;          ///< project moved vertices onto the original surface
  double featureAngleDeg = 0;     ///< > 0: vertices on edges whose dihedral angle exceeds this stay fixed
  double regularization = 0.1;    ///< global: weight that keeps each vertex near its current position
  double minFaceTurnCos = 0.2;    ///< a move is refused if an incident face normal turns beyond acos(this)
  bool uniformEdgeLength = false; ///< global: target the mesh's mean edge length everywhere (the paper's d)
                                  ///< instead of each vertex's 1-ring mean (keeps adaptive sizing)
  RelaxSolver solver = RelaxSolver::ConjugateGradient;  ///< global: sparse solver
  double solverTolerance = 1e-6;  ///< global, conjugate gradients: relative residual
  int solverMaxIterations = 300;  ///< global, conjugate gradients
  double damping = 1.0;           ///< global: share of the solved displacement applied per round
  const BoundaryCurve* boundaryCurve = nullptr;  ///< if set, boundary vertices slide along it (header)
  double cornerAngleDeg = 30;     ///< with boundaryCurve: |corner angle - 180| >= this stays fixed
  size_t cachedStarsUpTo = 8192;  ///< local: a region of up to this many vertices has its stars walked once
                                  ///< per call and kept (speed: every edit's relaxation); a larger one walks
                                  ///< each when it needs it (memory: a whole mesh's would be ~350 bytes a
                                  ///< vertex). The same positions either way.
};

struct RelaxReport {
  int vertices = 0;   ///< vertices in the region that were free to move
  int moved = 0;      ///< accepted vertex moves over all sweeps
  int rejected = 0;   ///< moves refused because they would fold a triangle
  double seconds = 0;
  double solveSeconds = 0;  ///< global: time in the sparse factorization and solve
  // Global only (see GlobalRelax), over the faces around the free vertices and the terms of
  // eq. 5 they reach (MeasureRelaxRegion measures the same for either mode):
  double energyBefore = 0, energyAfter = 0;          ///< eq. 5, 1-ring d_i (Eq5Targets)
  double minAngleBeforeDeg = 180, minAngleAfterDeg = 180;
  double shareBelow30Before = 0, shareBelow30After = 0;
  int rounds = 0;      ///< global: rounds whose guarded step was taken
  int backtracks = 0;  ///< global: step lengths tried and refused (energy not lower)
};

namespace relax_detail {
/// The scratch of WalkRings, one per thread, shared by every instantiation.
struct RingWalkScratch {
  StampSet seen;
  std::vector<int> frontier, next;
};
inline RingWalkScratch& RingWalk() {
  static thread_local RingWalkScratch s;
  return s;
}
}  // namespace relax_detail

/// Breadth-first walk over the vertices within k edges of the seeds [first, last): visit(x)
/// once on each, the seeds first, then ring by ring in the order the stars give them; the walk
/// stops as soon as visit returns true. True if it stopped so. O(size of the ring walked).
/// visit must not start another walk (KRing, AnyWithin): the scratch is shared.
template <class MeshType, class Visit>
bool WalkRings(MeshType& m, const int* first, const int* last, int k, Visit visit) {
  relax_detail::RingWalkScratch& w = relax_detail::RingWalk();
  w.seen.Begin(m.vert.size());
  w.frontier.clear();
  for (const int* v = first; v != last; ++v) {
    if (!w.seen.Insert(size_t(*v))) continue;
    if (visit(*v)) return true;
    w.frontier.push_back(*v);
  }
  for (int r = 0; r < k && !w.frontier.empty(); ++r) {
    w.next.clear();
    for (int x : w.frontier)
      for (auto n : StarOf<MeshType>(&m.vert[size_t(x)]).neighbors) {
        const int ni = int(vcg::tri::Index(m, n));
        if (!w.seen.Insert(size_t(ni))) continue;
        if (visit(ni)) return true;
        w.next.push_back(ni);
      }
    w.frontier.swap(w.next);
  }
  return false;
}

/// Vertices within k edges of the seeds (k = 0: the seeds), sorted. O(size of the ring).
template <class MeshType>
std::vector<int> KRing(MeshType& m, const std::vector<int>& seeds, int k) {
  std::vector<int> out;
  WalkRings(m, seeds.data(), seeds.data() + seeds.size(), k, [&](int x) {
    out.push_back(x);
    return false;
  });
  std::sort(out.begin(), out.end());
  return out;
}

/// True if pred(x) holds for a vertex x within k edges of v: the walk stops at the first such
/// x and builds no list of the ring (the driver's "unchanged since" checks walk 24 rings,
/// about 1800 vertices, per turn).
template <class MeshType, class Pred>
bool AnyWithin(MeshType& m, int v, int k, Pred pred) {
  return WalkRings(m, &v, &v + 1, k, pred);
}

/// 1 for vertices touching an edge whose dihedral angle exceeds angleDeg (a sharp crease).
template <class MeshType>
std::vector<char> CreaseVertices(MeshType& m, double angleDeg) {
  std::vector<char> crease(m.vert.size(), 0);
  if (angleDeg <= 0) return crease;
  const double c = std::cos(angleDeg * M_PI / 180.0);
  for (auto& f : m.face) {
    if (f.IsD()) continue;
    auto n0 = vcg::TriangleNormal(f).Normalize();
    for (int z = 0; z < 3; ++z) {
      auto g = f.FFp(z);
      if (g == &f) continue;
      auto n1 = vcg::TriangleNormal(*g).Normalize();
      if (double(n0.dot(n1)) < c) {
        crease[vcg::tri::Index(m, f.V(z))] = 1;
        crease[vcg::tri::Index(m, f.V((z + 1) % 3))] = 1;
      }
    }
  }
  return crease;
}

/// 1 for the vertices of crease lines (crease_lines.h): connected sets of at least minEdges
/// interior edges whose dihedral angle exceeds angleDeg that run as lines (all of a set's
/// vertices but two, or but 1 - minStraightShare of them, passed straight through; 0: any
/// set). Needs FF adjacency. O(F + V + E log E) for the E sharp edges, once.
template <class MeshType>
std::vector<char> CreaseLineVertices(MeshType& m, double angleDeg, int minEdges, double minStraightShare = 0.9) {
  return LineVertices(CreaseLineEdgesOf(m, angleDeg, minEdges, minStraightShare), m.vert.size());
}

namespace relax_detail {

/// Largest cosine of f's three corner angles (1 with a zero-length edge: a zero angle). Each
/// edge and length once: p_j - p_i is exactly -(p_i - p_j), and a negated vector has the same
/// norm and negates a dot product exactly, so this is the value corner by corner would give.
/// The largest cosine is the smallest angle's, which faces the shortest edge: only that
/// corner is computed (two square roots and one division instead of three each; the
/// relaxation's move check asks this for every face of every star it moves). When the two
/// shortest edges are within a millionth of each other the rounding of the two cosines could
/// order them either way, so all three are computed and the largest kept. The value is the
/// largest of the three as before, to the bit, but on a needle with two angles near zero
/// (both cosines within an ulp of 1, either may round higher).
template <class FaceType>
double MaxCornerCos(const FaceType* f) {
  const auto e01 = f->cP(1) - f->cP(0), e12 = f->cP(2) - f->cP(1), e20 = f->cP(0) - f->cP(2);
  // squared lengths in the mesh's scalar type: a length is its square root there, the value
  // Norm() gives (float meshes take a float square root)
  const auto s01 = e01.SquaredNorm(), s12 = e12.SquaredNorm(), s20 = e20.SquaredNorm();
  if (s01 <= 0 || s12 <= 0 || s20 <= 0) return 1;
  auto len = [](decltype(s01) sq) { return double(std::sqrt(sq)); };
  // the corner at P(z) between the edges to P(z+1) and P(z+2), facing edge (z+1, z+2)
  auto at0 = [&] { return double(-e01.dot(e20)) / (len(s01) * len(s20)); };  // faces e12
  auto at1 = [&] { return double(-e12.dot(e01)) / (len(s12) * len(s01)); };  // faces e20
  auto at2 = [&] { return double(-e20.dot(e12)) / (len(s20) * len(s12)); };  // faces e01
  const double lo = double(std::min({s01, s12, s20}));
  const double mid = double(std::max(std::min(s01, s12), std::min(std::max(s01, s12), s20)));
  if (mid - lo <= 1e-6 * mid) return std::max({at0(), at1(), at2()});
  return lo == s12 ? at0() : lo == s20 ? at1() : at2();
}

/// A move is kept if it folds nothing (no face of v turns by more than acos(minCos)) and does
/// not halve the smallest angle around the vertex (the simultaneous global solve can otherwise
/// squeeze a single triangle). One pass over the star at v's place, one with v at p: this runs
/// for every vertex of every relaxation sweep. The smallest angle before is measured only when
/// the one after is under 30 degrees: no triangle's smallest angle exceeds 60, so an angle after
/// of 30 or more halves nothing (its corner cosines were 7% of Automatic Reduction's
/// instructions on fandisk, half of them for the angle before).
/// before: the star's face normals (vcg::TriangleNormal) at v's place, if the caller has them.
template <class MeshType>
bool MoveHurts(const VertexStar<MeshType>& st, typename MeshType::VertexType* v, const typename MeshType::CoordType& p,
               double minCos, const typename MeshType::CoordType* before = nullptr) {
  typedef typename MeshType::CoordType CoordType;
  // the normals before the move: on the stack up to valence 16 (no allocation per vertex)
  const size_t n = st.corners.size();
  CoordType onStack[16];
  std::vector<CoordType> onHeap(n > 16 && !before ? n : 0);
  const CoordType* normalBefore = before;
  if (!before) {
    CoordType* computed = n > 16 ? onHeap.data() : onStack;
    for (size_t i = 0; i < n; ++i) computed[i] = vcg::TriangleNormal(*st.corners[i].f);
    normalBefore = computed;
  }
  double maxCosAfter = -1.0;
  const CoordType old = v->P();
  v->P() = p;
  bool folds = false;
  for (size_t i = 0; i < n && !folds; ++i) {
    const auto* f = st.corners[i].f;
    const CoordType after = vcg::TriangleNormal(*f);
    const double lb = normalBefore[i].Norm(), la = after.Norm();
    folds = la <= 1e-12 * (lb + 1e-30) || (lb > 0 && double(normalBefore[i].dot(after)) / (lb * la) < minCos);
    maxCosAfter = std::max(maxCosAfter, MaxCornerCos(f));
  }
  v->P() = old;
  if (folds) return true;
  // the smallest angles after and before: acos is decreasing and correctly rounded (so
  // monotone), so each is the acos of the largest cosine, one acos per side. Before: a largest
  // corner cosine of a triangle is at least 0.5 (its smallest angle at most 60 degrees; 1 for
  // a degenerate one), up to rounding, so half the angle before is under kHalfOfAtMost.
  static const double kHalfOfAtMost = 0.5 * std::acos(0.5 - 1e-9);
  const double after = std::acos(std::max(-1.0, std::min(1.0, maxCosAfter)));
  if (after >= kHalfOfAtMost) return false;
  double maxCosBefore = -1.0;
  for (size_t i = 0; i < n; ++i) maxCosBefore = std::max(maxCosBefore, MaxCornerCos(st.corners[i].f));
  return after < 0.5 * std::acos(std::max(-1.0, std::min(1.0, maxCosBefore)));
}

template <class MeshType>
typename MeshType::CoordType VertexNormal(const VertexStar<MeshType>& st) {
  typename MeshType::CoordType n(0, 0, 0);
  for (auto& c : st.corners) n += vcg::TriangleNormal(*c.f);
  return n.Normalize();
}

/// VertexNormal from the star's face normals, already computed (the same sum, so the same bits).
template <class CoordType>
CoordType VertexNormalOf(const CoordType* faceNormals, size_t n) {
  CoordType s(0, 0, 0);
  for (size_t i = 0; i < n; ++i) s += faceNormals[i];
  return s.Normalize();
}

/// Live and not on a crease (crease: per-vertex flags, or null for none).
template <class MeshType>
bool Movable(MeshType& m, int v, const std::vector<char>* crease) {
  return !m.vert[size_t(v)].IsD() && !(crease && size_t(v) < crease->size() && (*crease)[size_t(v)]);
}

/// A boundary vertex slides along opt.boundaryCurve unless there is none or it is a corner
/// (its corner angle differs from 180 degrees by opt.cornerAngleDeg or more).
template <class MeshType>
bool SlidesOnBoundary(const VertexStar<MeshType>& st, const RelaxOptions& opt) {
  return opt.boundaryCurve && !opt.boundaryCurve->Empty() && std::abs(CornerAngleDeg(st) - 180.0) < opt.cornerAngleDeg;
}

}  // namespace relax_detail

/// Local relaxation of the given vertices (interior, non-crease ones move). O(region x sweeps).
template <class MeshType>
RelaxReport LocalRelax(MeshType& m, const std::vector<int>& region, const SurfaceProjector* original,
                       const RelaxOptions& opt, const std::vector<char>* creaseIn = nullptr) {
  typedef typename MeshType::CoordType CoordType;
  typedef typename MeshType::ScalarType ScalarType;
  auto t0 = std::chrono::steady_clock::now();
  RelaxReport rep;
  // O(region x sweeps): called after every edit, so nothing here may be sized by the mesh.
  // Only positions change here, never the connectivity: a local edit's region (up to
  // opt.cachedStarsUpTo vertices) has each star walked once per call instead of once per sweep
  // and once more for the normals (the walks were an eighth of Automatic Reduction's time), in
  // a buffer reused from call to call (LocalRelax does not call itself). A larger region (the
  // final relaxation of a whole mesh) walks each star when it needs it instead: cached, a
  // million-face mesh's stars took ~350 bytes a vertex, 200 MB from the final relaxation on,
  // kept by the thread's buffer after the run (issue 14's memory target). The same stars
  // either way, so the same positions to the bit.
  const bool cached = region.size() <= opt.cachedStarsUpTo;
  static thread_local std::vector<VertexStar<MeshType>> stars;
  stars.clear();
  if (cached)
    for (int v : region) stars.push_back(StarOf<MeshType>(&m.vert[size_t(v)]));
  VertexStar<MeshType> walked;
  static thread_local std::vector<CoordType> faceNormals;  // the star's, at the vertex's place
  auto starAt = [&](size_t k) -> const VertexStar<MeshType>& {
    if (cached) return stars[k];
    walked = StarOf<MeshType>(&m.vert[size_t(region[k])]);
    return walked;
  };
  for (int it = 0; it < opt.iterations; ++it) {
    for (size_t k = 0; k < region.size(); ++k) {
      const int v = region[k];
      if (!relax_detail::Movable(m, v, creaseIn)) continue;
      auto* vp = &m.vert[size_t(v)];
      const VertexStar<MeshType>& st = starAt(k);
      if (st.neighbors.empty()) continue;
      if (st.boundary) {
        if (!relax_detail::SlidesOnBoundary(st, opt)) continue;  // fixed: no curve to slide on, or a corner
        if (it == 0) ++rep.vertices;
        // Along the boundary: towards the midpoint of the two boundary neighbours, onto the
        // original boundary polyline.
        const CoordType mid = (st.neighbors.front()->P() + st.neighbors.back()->P()) / ScalarType(2);
        CoordType p = vp->P() + (mid - vp->P()) * ScalarType(opt.step);
        p = opt.boundaryCurve->Closest(p);
        if (relax_detail::MoveHurts<MeshType>(st, vp, p, opt.minFaceTurnCos)) {
          ++rep.rejected;
          continue;
        }
        vp->P() = p;
        ++rep.moved;
        continue;
      }
      if (it == 0) ++rep.vertices;
      CoordType c(0, 0, 0);
      for (auto n : st.neighbors) c += n->P();
      c /= ScalarType(st.neighbors.size());
      // the face normals once, for the vertex normal and the move check (0.9.19: computed
      // twice before, 1.5% of Automatic Reduction's instructions)
      const size_t nf = st.corners.size();
      if (faceNormals.size() < nf) faceNormals.resize(nf);
      for (size_t i = 0; i < nf; ++i) faceNormals[i] = vcg::TriangleNormal(*st.corners[i].f);
      const CoordType n = relax_detail::VertexNormalOf(faceNormals.data(), nf);
      CoordType d = c - vp->P();
      d -= n * (d.dot(n));  // tangential part only (the surface is kept by projection)
      CoordType p = vp->P() + d * ScalarType(opt.step);
      // a degenerate star (zero-area faces) has no normal: leave the vertex where it is
      if (!std::isfinite(double(p[0])) || !std::isfinite(double(p[1])) || !std::isfinite(double(p[2]))) {
        ++rep.rejected;
        continue;
      }
      if (opt.reproject && original)
        p = CoordType::Construct(original->ClosestForVertex(size_t(v), vcg::Point3f::Construct(p)));
      if (relax_detail::MoveHurts<MeshType>(st, vp, p, opt.minFaceTurnCos, faceNormals.data())) {
        ++rep.rejected;
        continue;
      }
      vp->P() = p;
      ++rep.moved;
    }
  }
  for (size_t k = 0; k < region.size(); ++k)
    for (auto& c : starAt(k).corners) c.f->N() = vcg::TriangleNormal(*c.f).Normalize();
  rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return rep;
}

namespace relax_detail {

/// The smallest angle in degrees of the triangle p0, p1, p2 (FaceMinAngleDeg of a face there).
template <class CoordType>
double MinAngleDegOf(const CoordType& p0, const CoordType& p1, const CoordType& p2) {
  const CoordType* p[3] = {&p0, &p1, &p2};
  double mn = 180;
  for (int z = 0; z < 3; ++z) {
    auto a = *p[(z + 1) % 3] - *p[z], b = *p[(z + 2) % 3] - *p[z];
    double la = a.Norm(), lb = b.Norm();
    double ang =
        (la > 0 && lb > 0) ? std::acos(std::max(-1.0, std::min(1.0, double(a.dot(b)) / (la * lb)))) * 180 / M_PI : 0;
    mn = std::min(mn, ang);
  }
  return mn;
}

/// Smallest angle of a face in degrees, computed exactly as MeasureShape (quality.h) computes
/// it, so that the guard of GlobalRelax and the measures a caller takes agree to the last bit.
template <class FaceType>
double FaceMinAngleDeg(const FaceType* f) {
  return MinAngleDegOf(f->cP(0), f->cP(1), f->cP(2));
}

template <class CoordType>
Eigen::Vector3d ToEigen(const CoordType& p) {
  return Eigen::Vector3d(double(p[0]), double(p[1]), double(p[2]));
}
template <class CoordType>
CoordType FromEigen(const Eigen::Vector3d& p) {
  typedef typename CoordType::ScalarType S;
  return CoordType(S(p.x()), S(p.y()), S(p.z()));
}

/// What a relaxation of `region` can change, found in O(region) (never sized by the mesh):
///  * free: the region's vertices that may move (sorted), each with its degrees of freedom:
///    two inside (its tangent plane), one on the boundary (along the boundary curve; only with
///    RelaxOptions::boundaryCurve, never at a corner). Deleted, crease and non-manifold
///    vertices stay fixed.
///  * centers: the free vertices and their neighbours (sorted): the vertices i whose terms of
///    eq. 5 change when a free vertex moves (p_i, p_j, d_i and u_ij all depend on positions).
///  * faces: the faces around the free vertices, the only ones whose shape changes, with the
///    free vertices of each (faceFree) and the faces of each free vertex (vertFaces).
template <class MeshType>
struct RelaxRegion {
  typedef typename MeshType::FaceType FaceType;
  std::vector<int> free;
  std::vector<char> onBoundary;
  std::unordered_map<int, int> slot;  ///< vertex index -> position in free
  std::vector<int> centers;
  std::vector<FaceType*> faces;
  std::vector<std::vector<int>> faceFree;   ///< per face: positions in free of its free vertices
  std::vector<std::vector<int>> vertFaces;  ///< per free vertex: positions in faces
  int Slot(int v) const {
    auto it = slot.find(v);
    return it == slot.end() ? -1 : it->second;
  }
};

template <class MeshType>
RelaxRegion<MeshType> MakeRelaxRegion(MeshType& m, const std::vector<int>& regionIn, const RelaxOptions& opt,
                                      const std::vector<char>* crease) {
  typedef typename MeshType::FaceType FaceType;
  RelaxRegion<MeshType> R;
  std::vector<int> region(regionIn);
  std::sort(region.begin(), region.end());
  region.erase(std::unique(region.begin(), region.end()), region.end());
  for (int v : region) {
    if (v < 0 || size_t(v) >= m.vert.size() || !Movable(m, v, crease)) continue;
    VertexStar<MeshType> st = StarOf<MeshType>(&m.vert[size_t(v)]);
    if (st.neighbors.empty() || !st.manifold) continue;
    if (st.boundary && !SlidesOnBoundary(st, opt)) continue;
    R.slot[v] = int(R.free.size());
    R.free.push_back(v);
    R.onBoundary.push_back(st.boundary);
  }
  std::unordered_map<const FaceType*, int> faceSlot;
  R.vertFaces.resize(R.free.size());
  for (size_t i = 0; i < R.free.size(); ++i) {
    VertexStar<MeshType> st = StarOf<MeshType>(&m.vert[size_t(R.free[i])]);
    R.centers.push_back(R.free[i]);
    for (auto n : st.neighbors) R.centers.push_back(int(vcg::tri::Index(m, n)));
    for (auto& c : st.corners) {
      auto ins = faceSlot.emplace(c.f, int(R.faces.size()));
      if (ins.second) {
        R.faces.push_back(c.f);
        R.faceFree.emplace_back();
      }
      R.faceFree[size_t(ins.first->second)].push_back(int(i));
      R.vertFaces[i].push_back(ins.first->second);
    }
  }
  std::sort(R.centers.begin(), R.centers.end());
  R.centers.erase(std::unique(R.centers.begin(), R.centers.end()), R.centers.end());
  return R;
}

/// The target offsets d_i u_ij of eq. 5 from v_i (at pi) to its neighbours, in StarOf order.
/// Inside (sec. 8): u_ij split the tangent plane of v_i into equal angles, alpha_ij = alpha_0 +
/// k_j 2 pi / l, alpha_0 the circular mean of alpha0_ij - beta_ij. On the boundary (our
/// extension; the paper's meshes are closed) the l neighbours split the corner angle theta
/// (sum of the face angles) instead: beta = k theta / (l - 1). d_i is the mean edge length of
/// the 1-ring of v_i (the documented deviation from the paper's one global d, which fights the
/// size gradation of adaptive meshes), or dUniform when that is > 0. A star without a normal
/// (zero-area faces) targets each neighbour along its own direction at distance d_i.
template <class MeshType>
void Eq5Targets(const VertexStar<MeshType>& st, const Eigen::Vector3d& pi, double dUniform,
                std::vector<Eigen::Vector3d>& du) {
  const int l = int(st.neighbors.size());
  du.assign(size_t(l), Eigen::Vector3d::Zero());
  if (l == 0) return;
  double d = 0;
  for (auto nb : st.neighbors) d += (ToEigen(nb->cP()) - pi).norm();
  d = dUniform > 0 ? dUniform : d / l;
  Eigen::Vector3d N = ToEigen(VertexNormal<MeshType>(st));
  if (!N.allFinite() || N.norm() < 0.5) {
    for (int k = 0; k < l; ++k) {
      Eigen::Vector3d e = ToEigen(st.neighbors[size_t(k)]->cP()) - pi;
      du[size_t(k)] = e.norm() > 0 ? Eigen::Vector3d(d * e.normalized()) : Eigen::Vector3d::Zero();
    }
    return;
  }
  const Eigen::Vector3d a = std::abs(N.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d t1 = (a - N * N.dot(a)).normalized(), t2 = N.cross(t1);
  const double spacing = st.boundary ? (l > 1 ? CornerAngleDeg(st) * M_PI / 180.0 / (l - 1) : 0) : 2 * M_PI / l;
  double sx = 0, sy = 0;
  for (int k = 0; k < l; ++k) {
    const Eigen::Vector3d e = ToEigen(st.neighbors[size_t(k)]->cP()) - pi;
    const double a0 = std::atan2(e.dot(t2), e.dot(t1));
    sx += std::cos(a0 - k * spacing);
    sy += std::sin(a0 - k * spacing);
  }
  const double alpha0 = std::atan2(sy, sx);
  for (int k = 0; k < l; ++k) {
    const double alpha = alpha0 + k * spacing;
    du[size_t(k)] = d * (std::cos(alpha) * t1 + std::sin(alpha) * t2);
  }
}

/// Eq. 5 restricted to the terms of `centers`: sum_i sum_{j in N_i} |p_j - (p_i + d_i u_ij)|^2.
/// Over RelaxRegion::centers this differs from the whole mesh's eq. 5 by a constant (the terms
/// no free vertex reaches), so it goes down exactly when the whole mesh's does. O(centers).
/// scale, if given, receives the sum of the squared lengths of the same terms' edges (the
/// energy's natural unit).
template <class MeshType>
double Eq5Energy(MeshType& m, const std::vector<int>& centers, double dUniform, double* scale = nullptr) {
  double e = 0;
  if (scale) *scale = 0;
  std::vector<Eigen::Vector3d> du;
  for (int v : centers) {
    if (m.vert[size_t(v)].IsD()) continue;
    VertexStar<MeshType> st = StarOf<MeshType>(&m.vert[size_t(v)]);
    if (st.neighbors.empty() || !st.manifold) continue;
    const Eigen::Vector3d pi = ToEigen(m.vert[size_t(v)].cP());
    Eq5Targets<MeshType>(st, pi, dUniform, du);
    for (size_t k = 0; k < st.neighbors.size(); ++k) {
      e += (ToEigen(st.neighbors[k]->cP()) - pi - du[k]).squaredNorm();
      if (scale) *scale += (ToEigen(st.neighbors[k]->cP()) - pi).squaredNorm();
    }
  }
  return e;
}

/// Mean length of the edges around the centers (the paper's d, taken over the region).
template <class MeshType>
double MeanEdgeLength(MeshType& m, const std::vector<int>& centers) {
  double sum = 0;
  long count = 0;
  for (int v : centers) {
    if (m.vert[size_t(v)].IsD()) continue;
    for (auto nb : StarOf<MeshType>(&m.vert[size_t(v)]).neighbors) {
      sum += (ToEigen(nb->cP()) - ToEigen(m.vert[size_t(v)].cP())).norm();
      ++count;
    }
  }
  return count ? sum / double(count) : 0;
}

}  // namespace relax_detail

/// Eq. 5's energy and the triangle shape over what a relaxation of `region` can change (see
/// relax_detail::RelaxRegion; the same free vertices GlobalRelax would move with these options).
/// O(region).
struct RelaxMeasures {
  double energy = 0;         ///< eq. 5 over the terms the free vertices reach (1-ring d_i; see Eq5Targets)
  double minAngleDeg = 180;  ///< smallest angle of the faces around the free vertices
  double shareBelow30 = 0;   ///< share of those faces whose smallest angle is under 30 degrees
  int faces = 0;
};

template <class MeshType>
RelaxMeasures MeasureRelaxRegion(MeshType& m, const std::vector<int>& region, const RelaxOptions& opt,
                                 const std::vector<char>* crease = nullptr) {
  const relax_detail::RelaxRegion<MeshType> R = relax_detail::MakeRelaxRegion(m, region, opt, crease);
  RelaxMeasures r;
  const double dUniform = opt.uniformEdgeLength ? relax_detail::MeanEdgeLength(m, R.centers) : 0;
  r.energy = relax_detail::Eq5Energy(m, R.centers, dUniform);
  long below = 0;
  for (auto* f : R.faces) {
    const double a = relax_detail::FaceMinAngleDeg(f);
    r.minAngleDeg = std::min(r.minAngleDeg, a);
    below += a < 30;
  }
  r.faces = int(R.faces.size());
  r.shareBelow30 = R.faces.empty() ? 0 : double(below) / double(R.faces.size());
  return r;
}

/// Global relaxation (eq. 5) of the given vertices; the others are fixed boundary conditions.
///
/// Each round solves the quadratic problem of sec. 8 (targets d_i u_ij frozen at the round's
/// start, each free vertex on its tangent plane, or on the boundary's tangent line when it
/// slides along opt.boundaryCurve), then takes a guarded step: the positions
/// p(t) = project(old + t (solved - old)), t = 1, 1/2, ..., 1/64, projected onto the original
/// surface (onto the original boundary polyline for boundary vertices). At each t, a face that
/// folds, or whose smallest angle falls below its floor, sends its free vertices back to their
/// old positions, and so on until no face around a moved vertex is bad. The floor of a face
/// is the round's smallest angle m0 if the face was under 30 degrees, else max(30, m0) (and
/// at least half its own old angle). The step is taken at the first t where something moved
/// and eq. 5's energy is lower by more than rounding noise (1e-9 of the sum of the squared
/// edge lengths of its terms); if no t qualifies, the round restores every position
/// and the relaxation stops. Postconditions (over the faces around the free vertices, hence
/// over the whole mesh): the smallest angle is no lower and the share of triangles under 30
/// degrees no higher than before the call; eq. 5's energy is strictly lower whenever
/// rep.moved > 0; moved vertices lie on the original surface (boundary ones on the original
/// boundary) when `original` is given and opt.reproject. O(region x rounds), plus the solver.
template <class MeshType>
RelaxReport GlobalRelax(MeshType& m, const std::vector<int>& region, const SurfaceProjector* original,
                        const RelaxOptions& opt, const std::vector<char>* creaseIn = nullptr) {
  typedef typename MeshType::CoordType CoordType;
  typedef typename MeshType::FaceType FaceType;
  typedef Eigen::Triplet<double> T;
  using relax_detail::FromEigen;
  using relax_detail::ToEigen;
  auto t0 = std::chrono::steady_clock::now();
  RelaxReport rep;
  const relax_detail::RelaxRegion<MeshType> R = relax_detail::MakeRelaxRegion(m, region, opt, creaseIn);
  const int n = int(R.free.size()), nf = int(R.faces.size());
  rep.vertices = n;
  // The paper's d, if asked for, is taken once per call over the region (never the whole mesh).
  const double dUniform = opt.uniformEdgeLength ? relax_detail::MeanEdgeLength(m, R.centers) : 0;
  double scale = 0;
  double energy = relax_detail::Eq5Energy(m, R.centers, dUniform, &scale);
  // A step must lower eq. 5 by more than rounding noise (float positions) to count as progress.
  const double noise = 1e-9 * scale;
  auto shape = [&](double& minAngle, double& share) {
    long below = 0;
    minAngle = 180;
    for (auto* f : R.faces) {
      const double a = relax_detail::FaceMinAngleDeg(f);
      minAngle = std::min(minAngle, a);
      below += a < 30;
    }
    share = nf ? double(below) / nf : 0;
  };
  rep.energyBefore = energy;
  shape(rep.minAngleBeforeDeg, rep.shareBelow30Before);

  // Columns: two per interior free vertex (tangent plane), one per sliding boundary vertex.
  std::vector<int> col(size_t(n), 0);
  int cols = 0;
  for (int i = 0; i < n; ++i) {
    col[size_t(i)] = cols;
    cols += R.onBoundary[size_t(i)] ? 1 : 2;
  }
  std::vector<CoordType> old(static_cast<size_t>(n));
  std::vector<Eigen::Vector3d> solved(static_cast<size_t>(n)), b1(static_cast<size_t>(n)), b2(static_cast<size_t>(n));
  std::vector<double> angleBefore(static_cast<size_t>(nf)), floorAngle(static_cast<size_t>(nf));
  std::vector<CoordType> normalBefore(static_cast<size_t>(nf));
  std::vector<char> queued(static_cast<size_t>(nf), 0), sentBack(static_cast<size_t>(n), 0);
  std::vector<Eigen::Vector3d> du;
  auto restore = [&]() {
    for (int i = 0; i < n; ++i) m.vert[size_t(R.free[size_t(i)])].P() = old[size_t(i)];
  };
  auto isMoved = [&](int i) { return m.vert[size_t(R.free[size_t(i)])].cP() != old[size_t(i)]; };
  auto faceBad = [&](int fi) {
    const FaceType* f = R.faces[size_t(fi)];
    bool changed = false;
    for (int i : R.faceFree[size_t(fi)]) changed = changed || isMoved(i);
    if (!changed) return false;  // as at the round's start: fine by definition
    const CoordType nb = normalBefore[size_t(fi)], na = vcg::TriangleNormal(*f);
    const double lb = nb.Norm(), la = na.Norm();
    if (la <= 1e-12 * (lb + 1e-30)) return true;
    if (lb > 0 && double(nb.dot(na)) / (lb * la) < opt.minFaceTurnCos) return true;
    return relax_detail::FaceMinAngleDeg(f) < floorAngle[size_t(fi)];
  };

  for (int it = 0; it < opt.iterations && n > 0; ++it) {
    // The round's start: positions, face shapes and floors, frames.
    double m0 = 180;
    for (int fi = 0; fi < nf; ++fi) {
      angleBefore[size_t(fi)] = relax_detail::FaceMinAngleDeg(R.faces[size_t(fi)]);
      normalBefore[size_t(fi)] = vcg::TriangleNormal(*R.faces[size_t(fi)]);
      m0 = std::min(m0, angleBefore[size_t(fi)]);
    }
    for (int fi = 0; fi < nf; ++fi) {
      const double a = angleBefore[size_t(fi)];
      floorAngle[size_t(fi)] = a < 30 ? std::max(m0, 0.5 * a) : std::max(30.0, m0);
    }
    for (int i = 0; i < n; ++i) {
      auto* vp = &m.vert[size_t(R.free[size_t(i)])];
      old[size_t(i)] = vp->P();
      VertexStar<MeshType> st = StarOf<MeshType>(vp);
      if (R.onBoundary[size_t(i)]) {
        // the boundary's direction at v: from its first to its last boundary neighbour
        Eigen::Vector3d t = ToEigen(st.neighbors.back()->cP()) - ToEigen(st.neighbors.front()->cP());
        b1[size_t(i)] = t.norm() > 0 ? Eigen::Vector3d(t.normalized()) : Eigen::Vector3d::Zero();
        b2[size_t(i)] = Eigen::Vector3d::Zero();
        continue;
      }
      Eigen::Vector3d N = ToEigen(relax_detail::VertexNormal<MeshType>(st));
      if (!N.allFinite() || N.norm() < 0.5) {  // no tangent plane: this vertex stays
        b1[size_t(i)] = b2[size_t(i)] = Eigen::Vector3d::Zero();
        continue;
      }
      Eigen::Vector3d a = std::abs(N.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
      b1[size_t(i)] = (a - N * N.dot(a)).normalized();
      b2[size_t(i)] = N.cross(b1[size_t(i)]);
    }
    // Rows: one 3-vector residual p_j - p_i - d_i u_ij per term of eq. 5 that a free vertex
    // reaches; p = old + B x for free vertices, fixed otherwise.
    std::vector<T> trip;
    std::vector<double> rhs;
    int row = 0;
    auto addColumns = [&](int r, int i, double sign) {
      if (i < 0) return;
      for (int q = 0; q < 3; ++q) {
        trip.emplace_back(r + q, col[size_t(i)], sign * b1[size_t(i)][q]);
        if (!R.onBoundary[size_t(i)]) trip.emplace_back(r + q, col[size_t(i)] + 1, sign * b2[size_t(i)][q]);
      }
    };
    for (int v : R.centers) {
      if (m.vert[size_t(v)].IsD()) continue;
      VertexStar<MeshType> st = StarOf<MeshType>(&m.vert[size_t(v)]);
      if (st.neighbors.empty() || !st.manifold) continue;
      const Eigen::Vector3d pi = ToEigen(m.vert[size_t(v)].cP());
      relax_detail::Eq5Targets<MeshType>(st, pi, dUniform, du);
      const int si = R.Slot(v);
      for (size_t k = 0; k < st.neighbors.size(); ++k) {
        const int j = int(vcg::tri::Index(m, st.neighbors[k]));
        const int sj = R.Slot(j);
        if (si < 0 && sj < 0) continue;  // a constant term
        const Eigen::Vector3d r0 = ToEigen(st.neighbors[k]->cP()) - pi - du[k];
        addColumns(row, si, -1.0);
        addColumns(row, sj, 1.0);
        for (int q = 0; q < 3; ++q) rhs.push_back(-r0[q]);
        row += 3;
      }
    }
    Eigen::SparseMatrix<double> A(row, cols);
    A.setFromTriplets(trip.begin(), trip.end());
    Eigen::VectorXd b = Eigen::Map<Eigen::VectorXd>(rhs.data(), long(rhs.size()));
    auto ts = std::chrono::steady_clock::now();
    Eigen::SparseMatrix<double> AtA = A.transpose() * A;
    for (int k = 0; k < cols; ++k) AtA.coeffRef(k, k) += opt.regularization;
    Eigen::VectorXd x;
    Eigen::ComputationInfo info;
    Eigen::VectorXd atb = A.transpose() * b;
    if (opt.solver == RelaxSolver::SparseLDLT) {
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(AtA);
      x = solver.solve(atb);
      info = solver.info();
    } else {
      // The regularized normal matrix is symmetric positive definite and well conditioned:
      // conjugate gradients (Jacobi preconditioner) scale to millions of unknowns where the
      // LDLT factorization fills in.
      Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> solver;
      solver.setTolerance(opt.solverTolerance);
      solver.setMaxIterations(opt.solverMaxIterations);
      solver.compute(AtA);
      x = solver.solve(atb);
      info = solver.info() == Eigen::NoConvergence ? Eigen::Success : solver.info();  // best effort is fine
    }
    rep.solveSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - ts).count();
    if (info != Eigen::Success || !x.allFinite()) break;
    for (int i = 0; i < n; ++i) {
      Eigen::Vector3d dx = x[col[size_t(i)]] * b1[size_t(i)];
      if (!R.onBoundary[size_t(i)]) dx += x[col[size_t(i)] + 1] * b2[size_t(i)];
      solved[size_t(i)] = ToEigen(old[size_t(i)]) + opt.damping * dx;
    }
    // The guarded step.
    bool taken = false;
    for (double t = 1; t >= 1.0 / 64 && !taken; t *= 0.5) {
      for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d o = ToEigen(old[size_t(i)]);
        CoordType q = FromEigen<CoordType>(o + t * (solved[size_t(i)] - o));
        if (R.onBoundary[size_t(i)])
          q = opt.boundaryCurve->Closest(q);
        else if (opt.reproject && original)
          q = CoordType::Construct(original->ClosestForVertex(size_t(R.free[size_t(i)]), vcg::Point3f::Construct(q)));
        const bool finite = std::isfinite(double(q[0])) && std::isfinite(double(q[1])) && std::isfinite(double(q[2]));
        m.vert[size_t(R.free[size_t(i)])].P() = finite ? q : old[size_t(i)];
        sentBack[size_t(i)] = 0;
      }
      // Send the vertices of bad faces back, until no face around a moved vertex is bad
      // (terminates: every pass sends a vertex back for good; all back is the round's start).
      std::vector<int> queue;
      for (int fi = 0; fi < nf; ++fi) queue.push_back(fi), queued[size_t(fi)] = 1;
      int sent = 0;
      while (!queue.empty()) {
        const int fi = queue.back();
        queue.pop_back();
        queued[size_t(fi)] = 0;
        if (!faceBad(fi)) continue;
        for (int i : R.faceFree[size_t(fi)]) {
          if (!isMoved(i)) continue;
          m.vert[size_t(R.free[size_t(i)])].P() = old[size_t(i)];
          sentBack[size_t(i)] = 1;
          ++sent;
          for (int g : R.vertFaces[size_t(i)])
            if (!queued[size_t(g)]) queue.push_back(g), queued[size_t(g)] = 1;
        }
      }
      int moved = 0;
      for (int i = 0; i < n; ++i) moved += isMoved(i);
      if (moved == 0) continue;
      const double e = relax_detail::Eq5Energy(m, R.centers, dUniform);
      if (e < energy - noise) {
        energy = e;
        rep.moved += moved;
        rep.rejected += sent;
        taken = true;
      } else {
        restore();
        ++rep.backtracks;
      }
    }
    if (!taken) {
      restore();
      break;  // no step lowers eq. 5 without hurting a triangle: converged as far as the guard allows
    }
    ++rep.rounds;
  }
  for (auto* f : R.faces) f->N() = vcg::TriangleNormal(*f).Normalize();
  rep.energyAfter = energy;
  shape(rep.minAngleAfterDeg, rep.shareBelow30After);
  rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return rep;
}

/// Dispatch on opt.mode.
template <class MeshType>
RelaxReport Relax(MeshType& m, const std::vector<int>& region, const SurfaceProjector* original, const RelaxOptions& opt,
                  const std::vector<char>* crease = nullptr) {
  return opt.mode == RelaxMode::Global ? GlobalRelax(m, region, original, opt, crease)
                                       : LocalRelax(m, region, original, opt, crease);
}

}  // namespace irregular
}  // namespace vcg_ext
