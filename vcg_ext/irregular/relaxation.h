// filter_irregular: geometric relaxation after connectivity edits (paper sec. 8).
//
// Connectivity edits leave badly shaped triangles. Two relaxations move vertices along the
// surface, never changing connectivity:
//  * LocalRelax (Turk 1992 style, the paper's "local relaxation"): vertices move one at a time
//    in their tangent plane toward the centroid of their neighbours, then are projected back
//    onto the original surface. Cheap enough to run on the k-ring of an edit after every step.
//  * GlobalRelax (eq. 5): minimizes sum_i sum_{j in N_i} |p_j - (p_i + d u_ij)|^2, where d is
//    the mean edge length of v_i's 1-ring (the paper's global mean fights the size gradation of
//    adaptive meshes; see README) and u_ij splits the tangent plane of v_i into equal angles
//    (alpha_ij = alpha_0 + k_j 2 pi / valence, alpha_0 the best rotation). Each vertex is
//    constrained to its current tangent plane (two unknowns per vertex), the quadratic
//    problem is solved with Eigen's conjugate gradients (sparse LDLT optional), and vertices are projected back onto the
//    original surface. Iterated.
// Both refuse a vertex move that would turn an incident triangle over (fold), and keep
// vertices on sharp creases fixed when a feature angle is given.
//
// Boundary vertices stay fixed unless RelaxOptions::boundaryCurve is given (a BoundaryCurve
// made from the original mesh). Then LocalRelax moves each boundary vertex along the boundary:
// towards the midpoint of its two boundary neighbours, projected onto the original boundary
// polyline, so the holes keep their shape; a corner (corner angle, the sum of its face angles,
// differing from 180 degrees by at least RelaxOptions::cornerAngleDeg, default 30: the
// vertices the boundary valence rule of topology.h gives a regular valence other than 4, and
// those at exactly 150 degrees) stays fixed. GlobalRelax keeps boundary vertices fixed (they are its boundary conditions).
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

#include "surface_projector.h"
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
  const BoundaryCurve* boundaryCurve = nullptr;  ///< local: if set, boundary vertices slide along it (header)
  double cornerAngleDeg = 30;     ///< local, with boundaryCurve: |corner angle - 180| >= this stays fixed
};

struct RelaxReport {
  int vertices = 0;   ///< vertices in the region that were free to move
  int moved = 0;      ///< accepted vertex moves over all sweeps
  int rejected = 0;   ///< moves refused because they would fold a triangle
  double seconds = 0;
  double solveSeconds = 0;  ///< global: time in the sparse factorization and solve
};

/// Vertices within k edges of the seeds (k = 0: the seeds). O(size of the ring).
template <class MeshType>
std::vector<int> KRing(MeshType& m, const std::vector<int>& seeds, int k) {
  std::unordered_set<int> seen(seeds.begin(), seeds.end());
  std::vector<int> frontier(seen.begin(), seen.end());
  for (int r = 0; r < k; ++r) {
    std::vector<int> next;
    for (int v : frontier)
      for (auto n : StarOf<MeshType>(&m.vert[size_t(v)]).neighbors) {
        const int ni = int(vcg::tri::Index(m, n));
        if (seen.insert(ni).second) next.push_back(ni);
      }
    frontier.swap(next);
  }
  std::vector<int> out(seen.begin(), seen.end());
  std::sort(out.begin(), out.end());
  return out;
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

namespace relax_detail {

/// Would moving v to p turn one of its faces by more than acos(minCos)?
template <class MeshType>
bool MoveFolds(const VertexStar<MeshType>& st, typename MeshType::VertexType* v, const typename MeshType::CoordType& p,
               double minCos) {
  for (auto& c : st.corners) {
    auto* f = c.f;
    auto before = vcg::TriangleNormal(*f);
    auto old = v->P();
    v->P() = p;
    auto after = vcg::TriangleNormal(*f);
    v->P() = old;
    double lb = before.Norm(), la = after.Norm();
    if (la <= 1e-12 * (lb + 1e-30)) return true;
    if (lb > 0 && double(before.dot(after)) / (lb * la) < minCos) return true;
  }
  return false;
}

/// Smallest angle (radians) of the faces around v.
template <class MeshType>
double MinAngleAround(const VertexStar<MeshType>& st) {
  double mn = M_PI;
  for (auto& c : st.corners)
    for (int z = 0; z < 3; ++z) {
      auto a = c.f->P((z + 1) % 3) - c.f->P(z), b = c.f->P((z + 2) % 3) - c.f->P(z);
      double la = a.Norm(), lb = b.Norm();
      if (la <= 0 || lb <= 0) return 0;
      mn = std::min(mn, std::acos(std::max(-1.0, std::min(1.0, double(a.dot(b)) / (la * lb)))));
    }
  return mn;
}

/// A move is kept if it folds nothing and does not halve the smallest angle around the vertex
/// (the simultaneous global solve can otherwise squeeze a single triangle).
template <class MeshType>
bool MoveHurts(const VertexStar<MeshType>& st, typename MeshType::VertexType* v, const typename MeshType::CoordType& p,
               double minCos) {
  if (MoveFolds<MeshType>(st, v, p, minCos)) return true;
  const double before = MinAngleAround<MeshType>(st);
  auto old = v->P();
  v->P() = p;
  const double after = MinAngleAround<MeshType>(st);
  v->P() = old;
  return after < 0.5 * before;
}

template <class MeshType>
typename MeshType::CoordType VertexNormal(const VertexStar<MeshType>& st) {
  typename MeshType::CoordType n(0, 0, 0);
  for (auto& c : st.corners) n += vcg::TriangleNormal(*c.f);
  return n.Normalize();
}

/// Live and not on a crease (crease: per-vertex flags, or null for none).
template <class MeshType>
bool Movable(MeshType& m, int v, const std::vector<char>* crease) {
  return !m.vert[size_t(v)].IsD() && !(crease && size_t(v) < crease->size() && (*crease)[size_t(v)]);
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
  for (int it = 0; it < opt.iterations; ++it) {
    for (int v : region) {
      if (!relax_detail::Movable(m, v, creaseIn)) continue;
      auto* vp = &m.vert[size_t(v)];
      VertexStar<MeshType> st = StarOf<MeshType>(vp);
      if (st.neighbors.empty()) continue;
      if (st.boundary) {
        if (!opt.boundaryCurve || opt.boundaryCurve->Empty() ||
            std::abs(CornerAngleDeg(st) - 180.0) >= opt.cornerAngleDeg)
          continue;  // fixed: no curve to slide on, or a corner
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
      const CoordType n = relax_detail::VertexNormal<MeshType>(st);
      CoordType d = c - vp->P();
      d -= n * (d.dot(n));  // tangential part only (the surface is kept by projection)
      CoordType p = vp->P() + d * ScalarType(opt.step);
      // a degenerate star (zero-area faces) has no normal: leave the vertex where it is
      if (!std::isfinite(double(p[0])) || !std::isfinite(double(p[1])) || !std::isfinite(double(p[2]))) {
        ++rep.rejected;
        continue;
      }
      if (opt.reproject && original) p = CoordType::Construct(original->Closest(vcg::Point3f::Construct(p)));
      if (relax_detail::MoveHurts<MeshType>(st, vp, p, opt.minFaceTurnCos)) {
        ++rep.rejected;
        continue;
      }
      vp->P() = p;
      ++rep.moved;
    }
  }
  for (int v : region)
    for (auto& c : StarOf<MeshType>(&m.vert[size_t(v)]).corners) c.f->N() = vcg::TriangleNormal(*c.f).Normalize();
  rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return rep;
}

/// Global relaxation (eq. 5) of the given vertices; the others are fixed boundary conditions.
template <class MeshType>
RelaxReport GlobalRelax(MeshType& m, const std::vector<int>& region, const SurfaceProjector* original,
                        const RelaxOptions& opt, const std::vector<char>* creaseIn = nullptr) {
  typedef typename MeshType::CoordType CoordType;
  typedef Eigen::Triplet<double> T;
  auto t0 = std::chrono::steady_clock::now();
  RelaxReport rep;

  // Unknowns: (a, b) per free vertex, p = c + a t1 + b t2 in its tangent plane.
  std::vector<int> unknown(m.vert.size(), -1);
  std::vector<int> freeV;
  for (int v : region) {
    if (!relax_detail::Movable(m, v, creaseIn)) continue;
    VertexStar<MeshType> st = StarOf<MeshType>(&m.vert[size_t(v)]);
    if (st.boundary || st.neighbors.empty()) continue;
    unknown[size_t(v)] = int(freeV.size());
    freeV.push_back(v);
  }
  rep.vertices = int(freeV.size());
  if (freeV.empty()) return rep;
  const int n = int(freeV.size());

  for (int it = 0; it < opt.iterations; ++it) {
    // Tangent frames and the target directions u_ij.
    std::vector<Eigen::Vector3d> c(static_cast<size_t>(n)), t1(static_cast<size_t>(n)), t2(static_cast<size_t>(n));
    double lsum = 0;
    long lcount = 0;
    std::vector<VertexStar<MeshType>> stars(static_cast<size_t>(n));
    std::vector<double> scale(static_cast<size_t>(n), 0.0);  // mean 1-ring edge length
    for (int i = 0; i < n; ++i) {
      auto* vp = &m.vert[size_t(freeV[size_t(i)])];
      stars[size_t(i)] = StarOf<MeshType>(vp);
      CoordType nn = relax_detail::VertexNormal<MeshType>(stars[size_t(i)]);
      Eigen::Vector3d N(nn[0], nn[1], nn[2]);
      Eigen::Vector3d a = std::abs(N.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
      t1[size_t(i)] = (a - N * N.dot(a)).normalized();
      t2[size_t(i)] = N.cross(t1[size_t(i)]);
      c[size_t(i)] = Eigen::Vector3d(vp->P()[0], vp->P()[1], vp->P()[2]);
      for (auto nb : stars[size_t(i)].neighbors) {
        const double l = double((nb->P() - vp->P()).Norm());
        lsum += l;
        scale[size_t(i)] += l;
        ++lcount;
      }
      scale[size_t(i)] /= double(stars[size_t(i)].neighbors.size());
    }
    // The paper's d is the mean edge length of the mesh; on adaptive meshes (edge lengths that
    // vary over the surface) that fights the size gradation, so d_i is the mean edge length of
    // the 1-ring of v_i, optionally blended with the global mean.
    const double dGlobal = lsum / double(std::max(1L, lcount));
    std::vector<T> trip;
    std::vector<double> rhs;
    int row = 0;
    auto pos = [&](int v) {
      return Eigen::Vector3d(m.vert[size_t(v)].P()[0], m.vert[size_t(v)].P()[1], m.vert[size_t(v)].P()[2]);
    };
    for (int i = 0; i < n; ++i) {
      const auto& st = stars[size_t(i)];
      const int l = int(st.neighbors.size());
      // alpha0 = circular mean of (alpha0_ij - beta_ij), beta_ij = k_j 2 pi / l (sec. 8)
      double sx = 0, sy = 0;
      std::vector<int> nbIdx(static_cast<size_t>(l));
      for (int k = 0; k < l; ++k) {
        nbIdx[size_t(k)] = int(vcg::tri::Index(m, st.neighbors[size_t(k)]));
        Eigen::Vector3d e = pos(nbIdx[size_t(k)]) - c[size_t(i)];
        double a0 = std::atan2(e.dot(t2[size_t(i)]), e.dot(t1[size_t(i)]));
        double beta = 2 * M_PI * k / l;
        sx += std::cos(a0 - beta);
        sy += std::sin(a0 - beta);
      }
      const double alpha0 = std::atan2(sy, sx);
      for (int k = 0; k < l; ++k) {
        const double alpha = alpha0 + 2 * M_PI * k / l;
        Eigen::Vector3d u = std::cos(alpha) * t1[size_t(i)] + std::sin(alpha) * t2[size_t(i)];
        const int j = nbIdx[size_t(k)];
        const int uj = unknown[size_t(j)];
        // residual r = p_j - p_i - d u ; p_i = c_i + T_i x_i ; p_j = c_j + T_j x_j (or fixed)
        const double d = opt.uniformEdgeLength ? dGlobal : scale[size_t(i)];
        Eigen::Vector3d r0 = pos(j) - c[size_t(i)] - d * u;
        for (int q = 0; q < 3; ++q) {
          trip.emplace_back(row + q, 2 * i, -t1[size_t(i)][q]);
          trip.emplace_back(row + q, 2 * i + 1, -t2[size_t(i)][q]);
          if (uj >= 0) {
            trip.emplace_back(row + q, 2 * uj, t1[size_t(uj)][q]);
            trip.emplace_back(row + q, 2 * uj + 1, t2[size_t(uj)][q]);
          }
          rhs.push_back(-r0[q]);
        }
        row += 3;
      }
    }
    Eigen::SparseMatrix<double> A(row, 2 * n);
    A.setFromTriplets(trip.begin(), trip.end());
    Eigen::VectorXd b = Eigen::Map<Eigen::VectorXd>(rhs.data(), long(rhs.size()));
    auto ts = std::chrono::steady_clock::now();
    Eigen::SparseMatrix<double> AtA = A.transpose() * A;
    for (int k = 0; k < 2 * n; ++k) AtA.coeffRef(k, k) += opt.regularization;
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
    if (info != Eigen::Success) break;
    for (int i = 0; i < n; ++i) {
      auto* vp = &m.vert[size_t(freeV[size_t(i)])];
      Eigen::Vector3d p = c[size_t(i)] + opt.damping * (x[2 * i] * t1[size_t(i)] + x[2 * i + 1] * t2[size_t(i)]);
      CoordType q(typename CoordType::ScalarType(p.x()), typename CoordType::ScalarType(p.y()),
                  typename CoordType::ScalarType(p.z()));
      if (opt.reproject && original) q = CoordType::Construct(original->Closest(vcg::Point3f::Construct(q)));
      if (relax_detail::MoveHurts<MeshType>(stars[size_t(i)], vp, q, opt.minFaceTurnCos)) {
        ++rep.rejected;
        continue;
      }
      vp->P() = q;
      ++rep.moved;
    }
  }
  for (int v : freeV)
    for (auto& cc : StarOf<MeshType>(&m.vert[size_t(v)]).corners) cc.f->N() = vcg::TriangleNormal(*cc.f).Normalize();
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
