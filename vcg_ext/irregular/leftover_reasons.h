// filter_irregular: why each irregular vertex left after a reduction is still there.
//
// For every leftover irregular vertex one primary reason, the first that applies in this order:
//   boundary   it lies on the boundary or next to it (the reduction does not edit there);
//   protected  it or a neighbour is frozen (the user's protected selection);
//   cap        a v5 (any valence < 6) where the surface is convex: the discrete Gaussian
//              curvature (angle defect, 2 pi - sum of the angles at a vertex) summed over the
//              k-ring around it is at least `curvatureShare` of the pi / 3 a v5 stands for
//              (eq. 1). k is half the distance to the nearest other irregular vertex (the
//              vertex's own share of the surface, as eq. 2 hands curvature out), clamped to
//              [curvatureRings, maxCurvatureRings]: on a finer mesh the same curvature spreads
//              over more rings. The curvature needs it there;
//   saddle     likewise a v7 (valence > 6) where that sum is at most -curvatureShare * pi / 3;
//   thin       the part is thinner than `thinEdges` mean edge lengths (see below): a thin tube
//              or plate needs irregular vertices that the angle bound does not let go;
//   no partner no irregular vertex it could cancel with lies within `reach` edges (a v5 needs
//              a v7 or a 5-7 pair, a v7 a v5 or a pair, a 5-7 pair anything; its own cluster of
//              adjacent irregular vertices does not count);
//   budget     a partner is within reach, and edits around it (the vertex and its
//              `undoneRings`-ring) were tried and undone by the edit guard at least `minUndone`
//              times: the driver passes its per-vertex count of undone edits;
//   no route   a partner is within reach, nothing there was undone, and the driver's strategies
//              were tried from this vertex since its last change (`tried`) and found no
//              cancellation: no transport or split-and-absorb within the travel bound ends in a
//              removal (e.g. two 5-7 pairs whose Burgers vectors are not opposite, dislocation.h);
//   untried    none of the above: a partner is within reach, nothing there was undone, and the
//              strategies were not tried from it in its present state (the sweeps ended first:
//              the target count, the sweep limit, the time limit; or no `tried` is known).
// The reasons partition the leftovers: the counts add up to the leftover count. The flags of
// every test that holds are kept too (a cap on a thin ear is a cap and on a thin part).
//
// Thin parts: the local thickness at v is the distance from v to the nearest vertex u of the
// surface that faces the other way (normals n_u . n_v < -0.5) and lies behind v (inside:
// (u - v) . n_v < 0), i.e. the distance to the opposite side of a tube or a plate, divided by
// the mean edge length around v. Found with a hash grid of the vertices (built once, O(V),
// only when a leftover needs it) and a ball query of radius thinEdges * h: O(ball) per vertex.
// It also finds two parts that nearly touch (a small gap is a small local feature size too).
//
// Cost: O(leftovers * (rings + reach)^2) star queries, plus one O(V) pass to find the
// leftovers when the caller does not give them, plus the grid. Never O(mesh) per vertex.
// An analysis reads the mesh once per vertex and remembers it (the thickness grid, which
// vertices are irregular, cluster charges): the mesh must not change while one is in use.
// Preconditions: FF and VF adjacency up to date on a manifold, consistently oriented mesh with
// outward normals (the thin test's "behind"). Postconditions: the mesh is not modified.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "dislocation.h"
#include "topology.h"

namespace vcg_ext {
namespace irregular {

enum class LeftoverReason { Boundary = 0, Protected, Cap, Saddle, Thin, NoPartner, Budget, NoRoute, Untried };
constexpr int kLeftoverReasons = 9;

inline const char* LeftoverReasonName(LeftoverReason r) {
  static const char* n[kLeftoverReasons] = {"boundary", "protected", "cap",    "saddle",
                                            "thin",     "no partner", "budget", "no route",
                                            "untried"};
  return n[int(r)];
}

struct LeftoverOptions {
  int curvatureRings = 3;        ///< rings summed for the curvature test, at least ...
  int maxCurvatureRings = 6;     ///< ... and up to halfway to the nearest other irregular vertex, at most this
  double curvatureShare = 0.5;   ///< share of pi / 3 the summed angle defect must reach (sign of the valence's)
  double thinEdges = 4;          ///< thinner than this many mean edge lengths: a thin part
  int reach = 12;                ///< travel bound (edges) within which a partner counts
  int minUndone = 1;             ///< undone edits around a vertex that make it "budget"
  int undoneRings = 1;           ///< rings around the vertex whose undone edits count
  const std::vector<int>* undone = nullptr;   ///< per vertex index: edits tried there and undone by the
                                              ///< guard (the driver's count); null: none known
  const std::vector<char>* frozen = nullptr;  ///< per vertex index, 1: protected (may be null)
  const std::vector<char>* tried = nullptr;   ///< per vertex index, 1: the driver's strategies were tried
                                              ///< from it and nothing changed it since ("no route"
                                              ///< rather than "untried"); null: not known
};

/// One leftover irregular vertex and why it stays.
struct LeftoverVertex {
  int vertex = -1;
  int valence = 0;
  bool boundary = false;          ///< on the boundary (not merely next to it)
  LeftoverReason reason = LeftoverReason::Untried;
  unsigned flags = 0;             ///< bit (1 << reason) for every test that holds
  double curvature = 0;           ///< angle defect summed over the rings (radians)
  int curvatureRings = 0;         ///< the rings summed
  int nearestIrregular = -1;      ///< edges to the nearest other irregular vertex outside its cluster (-1: none within reach)
  double thickness = std::numeric_limits<double>::infinity();  ///< in mean edge lengths; inf: not
                                  ///< thinner than thinEdges
  int partner = -1;               ///< nearest irregular vertex it could cancel with, within reach (-1: none)
  int partnerDistance = -1;       ///< edges to it
  int undoneNearby = 0;           ///< undone edits counted around it
  bool Has(LeftoverReason r) const { return (flags >> int(r)) & 1u; }
};

/// Leftovers by reason; `vertices` in increasing vertex index.
struct LeftoverReport {
  std::vector<LeftoverVertex> vertices;
  int total = 0;
  int counts[kLeftoverReasons] = {0, 0, 0, 0, 0, 0, 0, 0, 0};  ///< by primary reason: they add up to total
  int onThinPart = 0;  ///< leftovers on a thin part whatever their primary reason
  int boundary = 0, protectedCount = 0, caps = 0, saddles = 0, thin = 0, noPartner = 0, budget = 0, noRoute = 0,
      untried = 0;
  int Count(LeftoverReason r) const { return counts[int(r)]; }
  /// "62 left: 20 cap, 5 saddle, 30 no partner, 7 budget (thin parts: 3)"; zero counts omitted.
  std::string Summary() const {
    std::ostringstream o;
    o << total << " irregular vertices left";
    const char* sep = ": ";
    for (int r = 0; r < kLeftoverReasons; ++r)
      if (counts[r]) o << sep << counts[r] << ' ' << LeftoverReasonName(LeftoverReason(r)), sep = ", ";
    if (onThinPart) o << " (on thin parts: " << onThinPart << ")";
    return o.str();
  }
};

template <class MeshType>
class LeftoverAnalysis {
 public:
  typedef typename MeshType::VertexType VertexType;
  typedef typename MeshType::CoordType CoordType;

  LeftoverAnalysis(MeshType& m, const LeftoverOptions& opt) : m_(m), opt_(opt) {}

  /// Explains the given irregular vertices (every irregular vertex of the mesh, found in one
  /// O(V) pass, when `leftovers` is empty).
  LeftoverReport Explain(std::vector<int> leftovers = {}) {
    if (leftovers.empty()) {
      ValenceField<MeshType> vf = ComputeValences(m_);
      for (size_t i = 0; i < m_.vert.size(); ++i)
        if (!m_.vert[i].IsD() && vf.IsIrregular(i)) leftovers.push_back(int(i));
    }
    std::sort(leftovers.begin(), leftovers.end());
    leftovers.erase(std::unique(leftovers.begin(), leftovers.end()), leftovers.end());
    LeftoverReport rep;
    for (int v : leftovers) {
      if (!Live(v)) continue;
      LeftoverVertex lv = ExplainVertex(v);
      rep.vertices.push_back(lv);
      ++rep.total;
      ++rep.counts[int(lv.reason)];
      rep.onThinPart += lv.Has(LeftoverReason::Thin);
    }
    rep.boundary = rep.counts[int(LeftoverReason::Boundary)];
    rep.protectedCount = rep.counts[int(LeftoverReason::Protected)];
    rep.caps = rep.counts[int(LeftoverReason::Cap)];
    rep.saddles = rep.counts[int(LeftoverReason::Saddle)];
    rep.thin = rep.counts[int(LeftoverReason::Thin)];
    rep.noPartner = rep.counts[int(LeftoverReason::NoPartner)];
    rep.budget = rep.counts[int(LeftoverReason::Budget)];
    rep.noRoute = rep.counts[int(LeftoverReason::NoRoute)];
    rep.untried = rep.counts[int(LeftoverReason::Untried)];
    return rep;
  }

  /// The reason for one vertex (see the header comment).
  LeftoverVertex ExplainVertex(int v) {
    LeftoverVertex lv = ShapeOf(v);  // star, partner, cap, saddle, thin
    auto set = [&](LeftoverReason r) { lv.flags |= 1u << int(r); };
    bool nearBoundary = lv.boundary;
    bool prot = Frozen(v);
    for (VertexType* n : StarOf<MeshType>(V(v)).neighbors) {
      nearBoundary = nearBoundary || StarOf<MeshType>(n).boundary;
      prot = prot || Frozen(Index(n));
    }
    if (nearBoundary) set(LeftoverReason::Boundary);
    if (prot) set(LeftoverReason::Protected);
    if (!lv.boundary && lv.partner < 0) set(LeftoverReason::NoPartner);
    if (opt_.undone) {
      std::unordered_map<int, int> ring = Rings(v, opt_.undoneRings);
      for (auto& kv : ring)
        if (size_t(kv.first) < opt_.undone->size()) lv.undoneNearby += (*opt_.undone)[size_t(kv.first)];
    }
    if (lv.partner >= 0 && lv.undoneNearby >= std::max(1, opt_.minUndone)) set(LeftoverReason::Budget);
    if (lv.partner >= 0 && lv.undoneNearby < std::max(1, opt_.minUndone))
      set(Tried(v) ? LeftoverReason::NoRoute : LeftoverReason::Untried);
    for (int r = 0; r < kLeftoverReasons; ++r)
      if (lv.Has(LeftoverReason(r))) {
        lv.reason = LeftoverReason(r);
        break;
      }
    return lv;
  }

  /// Only the tests of the shape (cap, saddle, thin: flags, curvature, thickness) and the
  /// nearest partner, for an interior vertex: whether the surface needs v where it is, without
  /// the driver's records (undone edits, tries). For choosing which vertices deserve more
  /// effort (AutomaticReduction::FarMeetings).
  LeftoverVertex ShapeOf(int v) {
    LeftoverVertex lv;
    lv.vertex = v;
    VertexStar<MeshType> s = StarOf<MeshType>(V(v));
    lv.valence = s.Valence();
    lv.boundary = s.boundary;
    if (!s.boundary) NearestPartner(v, &lv.partner, &lv.partnerDistance, &lv.nearestIrregular);
    ShapeTests(v, s, RegularValenceOf(s), lv);
    return lv;
  }

  /// Sum of the angle defects (2 pi - angle sum) of the interior vertices within `rings`
  /// edges of v (radians): the discrete Gaussian curvature integrated there.
  double AngleDefectAround(int v, int rings) {
    double sum = 0;
    for (auto& kv : Rings(v, rings)) {
      VertexStar<MeshType> s = StarOf<MeshType>(V(kv.first));
      if (s.boundary || s.corners.empty()) continue;
      sum += 2 * M_PI - CornerAngleDeg(s) * M_PI / 180.0;
    }
    return sum;
  }

  /// The nearest interior irregular vertex within opt.reach edges that could cancel with v
  /// (as for the "no partner" reason, NearestPartner), or -1; *distance: its distance in edges.
  int PartnerOf(int v, int* distance = nullptr) {
    int partner = -1, d = -1, nearest = -1;
    NearestPartner(v, &partner, &d, &nearest);
    if (distance) *distance = d;
    return partner;
  }

  /// The local thickness at v in mean edge lengths (see the header comment); infinity when
  /// nothing facing the other way lies within thinEdges edge lengths.
  double Thickness(int v, const VertexStar<MeshType>& s) {
    if (s.corners.empty()) return std::numeric_limits<double>::infinity();
    double h = 0;
    for (VertexType* n : s.neighbors) h += double((n->cP() - V(v)->cP()).Norm());
    h /= double(s.neighbors.size());
    if (!(h > 0)) return std::numeric_limits<double>::infinity();
    return ThicknessAt(V(v)->cP(), Normal(s), h);
  }

  /// The local thickness behind point pv of a surface whose outward unit normal there is nv,
  /// in units of h: the distance to the nearest vertex of the mesh behind it (against nv) whose
  /// normal faces the other way (dot < -0.5), over h; infinity when none lies within
  /// thinEdges * h. pv need not be a vertex of the mesh (thin_creases.h probes another mesh's
  /// edges with it).
  double ThicknessAt(const CoordType& pv, const CoordType& nv, double h) {
    if (!(h > 0)) return std::numeric_limits<double>::infinity();
    const double radius = opt_.thinEdges * h;
    BuildGrid();
    double best = std::numeric_limits<double>::infinity();
    const int64_t r = int64_t(std::ceil(radius / cell_));
    const int64_t cx = Cell(pv[0]), cy = Cell(pv[1]), cz = Cell(pv[2]);
    for (int64_t x = cx - r; x <= cx + r; ++x)
      for (int64_t y = cy - r; y <= cy + r; ++y)
        for (int64_t z = cz - r; z <= cz + r; ++z) {
          auto it = grid_.find(Key(x, y, z));
          if (it == grid_.end()) continue;
          for (int u : it->second) {
            const CoordType d = V(u)->cP() - pv;
            const double dist = double(d.Norm());
            if (dist >= radius || dist >= best || !(double(d.dot(nv)) < 0)) continue;
            const VertexStar<MeshType> su = StarOf<MeshType>(V(u));
            if (su.corners.empty() || double(Normal(su).dot(nv)) >= -0.5) continue;
            best = dist;
          }
        }
    return best / h;
  }

  /// The mesh's mean edge length (over the faces' edges; built with the grid, once).
  double MeanEdgeLength() {
    BuildGrid();
    return meanEdge_;
  }

 private:
  VertexType* V(int i) { return &m_.vert[size_t(i)]; }
  int Index(const VertexType* v) const { return int(vcg::tri::Index(m_, v)); }
  bool Live(int v) const { return v >= 0 && size_t(v) < m_.vert.size() && !m_.vert[size_t(v)].IsD() && m_.vert[size_t(v)].cVFp(); }
  bool Frozen(int v) const { return opt_.frozen && size_t(v) < opt_.frozen->size() && (*opt_.frozen)[size_t(v)]; }
  bool Tried(int v) const { return opt_.tried && size_t(v) < opt_.tried->size() && (*opt_.tried)[size_t(v)]; }

  /// The cap, saddle and thin tests of ExplainVertex on lv (its valence, boundary and
  /// nearestIrregular set): curvature over the vertex's share of the surface, and thickness.
  void ShapeTests(int v, const VertexStar<MeshType>& s, int regular, LeftoverVertex& lv) {
    auto set = [&](LeftoverReason r) { lv.flags |= 1u << int(r); };
    const int far = lv.nearestIrregular < 0 ? opt_.maxCurvatureRings : lv.nearestIrregular / 2;
    lv.curvatureRings = std::max(opt_.curvatureRings, std::min(opt_.maxCurvatureRings, far));
    lv.curvature = AngleDefectAround(v, lv.curvatureRings);
    const double need = opt_.curvatureShare * M_PI / 3;
    const int excess = lv.valence - regular;  // < 0: a v5-like vertex, > 0: v7-like
    if (!s.boundary && excess < 0 && lv.curvature >= need) set(LeftoverReason::Cap);
    if (!s.boundary && excess > 0 && lv.curvature <= -need) set(LeftoverReason::Saddle);
    lv.thickness = Thickness(v, s);
    if (lv.thickness < opt_.thinEdges) set(LeftoverReason::Thin);
  }

  /// Area-weighted unit normal of a star.
  static CoordType Normal(const VertexStar<MeshType>& s) {
    CoordType n(0, 0, 0);
    for (auto& c : s.corners) n += (c.f->cP(1) - c.f->cP(0)) ^ (c.f->cP(2) - c.f->cP(0));
    const auto l = n.Norm();
    return l > 0 ? n / l : n;
  }

  /// Vertices within k edges of v with their distance.
  std::unordered_map<int, int> Rings(int v, int k) { return DislocationAnalysis<MeshType>(m_).Distances({v}, k); }

  /// As DislocationAnalysis::InteriorIrregular, memoised per vertex (kind_): the partner
  /// searches of one analysis visit the same vertices many times (the man at 20K, 2041
  /// leftovers each searched 18 rings deep: the searches were a tenth of the whole run).
  bool InteriorIrregular(int x) {
    if (x < 0 || size_t(x) >= m_.vert.size()) return false;
    if (kind_.empty()) kind_.assign(m_.vert.size(), 0);
    signed char& k = kind_[size_t(x)];
    if (k == 0) k = DislocationAnalysis<MeshType>(m_).InteriorIrregular(x) ? 2 : 1;
    return k == 2;
  }
  /// The summed charge (6 - valence) of x's cluster (ClusterOf), memoised per vertex.
  int ClusterCharge(int x) {
    auto it = clusterCharge_.find(x);
    if (it != clusterCharge_.end()) return it->second;
    const int q = DislocationAnalysis<MeshType>(m_).ChargeOf(ClusterOf(x));
    clusterCharge_.emplace(x, q);
    return q;
  }

  /// The nearest interior irregular vertex within opt.reach edges outside v's cluster (its
  /// adjacent irregular vertices, transitively) that could cancel with it: any, if the cluster
  /// has net charge 0 (a 5-7 pair); else one whose own cluster has charge 0 or the other sign.
  /// *nearest: edges to the nearest interior irregular vertex outside the cluster, whatever
  /// its type (-1: none within reach).
  void NearestPartner(int v, int* partner, int* distance, int* nearest) {
    std::vector<int> cluster = ClusterOf(v);
    std::unordered_set<int> own(cluster.begin(), cluster.end());
    const int q = DislocationAnalysis<MeshType>(m_).ChargeOf(cluster);
    std::unordered_map<int, int> d;
    std::vector<int> queue;
    for (int x : cluster) d.emplace(x, 0), queue.push_back(x);
    for (size_t i = 0; i < queue.size(); ++i) {
      const int x = queue[i], dx = d[x];
      if (!own.count(x) && InteriorIrregular(x)) {
        if (*nearest < 0) *nearest = dx;
        const int qx = ClusterCharge(x);
        if (q == 0 || qx == 0 || (qx > 0) != (q > 0)) {
          *partner = x;
          *distance = dx;
          return;
        }
      }
      if (dx >= opt_.reach) continue;
      VertexStar<MeshType> s = StarOf<MeshType>(V(x));
      if (s.boundary) continue;
      std::vector<int> next;
      for (VertexType* n : s.neighbors) next.push_back(Index(n));
      std::sort(next.begin(), next.end());  // deterministic: the lowest index among equals
      for (int w : next)
        if (d.emplace(w, dx + 1).second) queue.push_back(w);
    }
  }

  /// As DislocationAnalysis::ClusterOf, with the memoised InteriorIrregular.
  std::vector<int> ClusterOf(int v) {
    return DislocationAnalysis<MeshType>(m_).ClusterOf(v, 64, [this](int w) { return InteriorIrregular(w); });
  }

  // ---- hash grid of the vertices for the thickness query (built once)
  static uint64_t Key(int64_t x, int64_t y, int64_t z) {
    return (uint64_t(x & 0x1FFFFF) << 42) | (uint64_t(y & 0x1FFFFF) << 21) | uint64_t(z & 0x1FFFFF);
  }
  int64_t Cell(double x) const { return int64_t(std::floor(x / cell_)); }
  void BuildGrid() {
    if (built_) return;
    built_ = true;
    double sum = 0;
    long n = 0;
    for (auto& f : m_.face)
      if (!f.IsD())
        for (int z = 0; z < 3; ++z, ++n) sum += double((f.cP(z) - f.cP((z + 1) % 3)).Norm());
    meanEdge_ = n ? sum / double(n) : 0;
    cell_ = n ? std::max(1e-12, opt_.thinEdges * sum / double(n)) : 1.0;
    for (size_t i = 0; i < m_.vert.size(); ++i)
      if (Live(int(i))) {
        const CoordType& p = m_.vert[i].cP();
        grid_[Key(Cell(p[0]), Cell(p[1]), Cell(p[2]))].push_back(int(i));
      }
  }

  MeshType& m_;
  LeftoverOptions opt_;
  bool built_ = false;
  double cell_ = 1;
  double meanEdge_ = 0;
  std::unordered_map<uint64_t, std::vector<int>> grid_;
  std::vector<signed char> kind_;                ///< per vertex: 0 not known yet, 1 not, 2 interior irregular
  std::unordered_map<int, int> clusterCharge_;   ///< ClusterCharge's memo
};

/// Convenience: the reasons for every irregular vertex of m (or the given ones).
template <class MeshType>
LeftoverReport ExplainLeftovers(MeshType& m, const LeftoverOptions& opt = LeftoverOptions(),
                                const std::vector<int>& leftovers = {}) {
  LeftoverAnalysis<MeshType> a(m, opt);
  return a.Explain(leftovers);
}

}  // namespace irregular
}  // namespace vcg_ext
