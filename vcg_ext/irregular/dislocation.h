// filter_irregular: 5-7 pairs as lattice dislocations, and a global plan of which irregular
// vertices to bring together (paper sec. 5, 7.1, 7.2, 7.3).
//
// A regular triangulation is a piece of the triangular lattice. A v5 or v7 alone is a
// disclination: it rotates the lattice by +-60 degrees (eq. 1). An adjacent 5-7 pair carries no
// net rotation but a translation, its Burgers vector b: walk a closed circuit of regular
// vertices counter-clockwise around the pair, write each edge as one of the six lattice steps
// e0..e5 (carried along the circuit: straight on keeps the step, a turn by k triangles rotates
// it by k * 60 degrees, sec. 4's turn points), and add the steps up. Around regular vertices
// only, the steps close (sum 0); around a 5-7 pair they miss by one lattice step: b. Burgers
// vectors add, and are conserved by every pair move (fig. 6 moves the pair, not its b), so:
//   * two pairs annihilate (5-5-7-7 quadruple removal, fig. 8 inverse, sec. 7.3) only when
//     their vectors are opposite, b1 + b2 = 0 (fig. 11's "opposite sides match" is the same
//     condition); Theorem 5.5 is the case of a single pair, b != 0;
//   * any pair cancels into a lone v5 or v7 (a 5-5-7 / 5-7-7 triple, sec. 7.2), whatever its b:
//     the disclination absorbs the translation by moving one step;
//   * two pairs whose vectors are not opposite still give a triple (one pair with one vertex
//     of the other), leaving one pair with b1 + b2.
// The 60-degree rule: in lattice coordinates of the undistorted lattice (read from vertex
// indices on a flat torus, where flips keep indices), b is the step of the v5->v7 edge turned
// 60 degrees clockwise; the two flip moves of fig. 6 (directions 1 and 4 of atomic_ops.h, which
// keep the vertex count) glide the pair along b: direction 4 moves it by b, direction 1 by -b;
// the four collapse / split moves climb (tested for all six orientations).
//
// Comparing two pairs needs one frame: a lattice frame (a regular vertex and the neighbour
// that is its step e0) is carried from one pair's circuit to the other's through regular
// vertices (each step: the edge's direction, reversed, fixes the frame at the next vertex).
// The carried rotation does not depend on the route as long as two routes enclose only
// regular vertices and 5-7 pairs (zero net curvature); a route that passes a lone v5 on the
// other side rotates by 60 degrees (one lone v7: -60). The comparison therefore flags
// `ambiguous` when a disclination (a cluster of irregular vertices of non-zero net charge)
// lies where a route at most `slack` edges longer than the chosen one could pass: routes of
// about the same length then pass it on both sides and answer differently. Irregular vertices
// themselves are never crossed (no frame there).
//
// Preconditions: FF and VF adjacency up to date on a manifold, consistently oriented mesh.
// Postconditions: the mesh is not modified. Cost: a circuit O(cluster); a comparison O(R^2)
// for routes of at most R edges; a plan O(sites * R^2) plus O(2^n) per exactly matched
// component of n <= maxExact sites.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "result.h"
#include "separatrix.h"
#include "topology.h"

namespace vcg_ext {
namespace irregular {

/// A vector of the triangular lattice, a * e0 + b * e1, where e_k is the unit step at k * 60
/// degrees counter-clockwise from e0 (so e2 = e1 - e0, e3 = -e0, ...).
struct LatticeVector {
  int a = 0, b = 0;
  static LatticeVector Step(int k) {
    static const int t[6][2] = {{1, 0}, {0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}};
    k = ((k % 6) + 6) % 6;
    return LatticeVector{t[k][0], t[k][1]};
  }
  /// Rotated counter-clockwise by k * 60 degrees.
  LatticeVector Rotated(int k) const {
    LatticeVector v = *this;
    for (int i = 0; i < ((k % 6) + 6) % 6; ++i) v = LatticeVector{-v.b, v.a + v.b};
    return v;
  }
  /// Squared length in edge lengths: 1 for a step, 3 for e0 + e1, 4 for 2 e0.
  int Norm2() const { return a * a + a * b + b * b; }
  bool IsZero() const { return a == 0 && b == 0; }
  /// The step k with this vector, or -1 if it is not a single step.
  int StepIndex() const {
    for (int k = 0; k < 6; ++k)
      if (*this == Step(k)) return k;
    return -1;
  }
  LatticeVector operator+(const LatticeVector& o) const { return LatticeVector{a + o.a, b + o.b}; }
  LatticeVector operator-(const LatticeVector& o) const { return LatticeVector{a - o.a, b - o.b}; }
  LatticeVector operator-() const { return LatticeVector{-a, -b}; }
  bool operator==(const LatticeVector& o) const { return a == o.a && b == o.b; }
  bool operator!=(const LatticeVector& o) const { return !(*this == o); }
  std::string Str() const { return "(" + std::to_string(a) + ", " + std::to_string(b) + ")"; }
};

/// A lattice frame at a regular interior vertex: `ref` is the neighbour in direction e0.
struct LatticeFrame {
  int vertex = -1, ref = -1;
  bool Valid() const { return vertex >= 0 && ref >= 0; }
};

/// A Burgers circuit around a set of vertices (the core): the loop bounding the union of the
/// core's stars, counter-clockwise (the core on its left), and the sum of its lattice steps in
/// the frame of its first edge (frame = {loop[0], loop[1]}).
struct BurgersCircuit {
  Result result = Result::Fail("not traced");
  std::vector<int> core;        ///< the vertices enclosed (sorted)
  std::vector<int> loop;        ///< the circuit, loop[0] = its lowest vertex index
  std::vector<int> directions;  ///< directions[i]: the step of loop[i] -> loop[i+1] in `frame`
  LatticeFrame frame;           ///< {loop[0], loop[1]}
  int charge = 0;               ///< sum of (6 - valence) over the core: 0 for a 5-7 pair
  int holonomy = 0;             ///< rotation (in 60 degree steps) after one circuit: -charge mod 6
  LatticeVector burgers;        ///< sum of the steps; meaningful when holonomy == 0
  explicit operator bool() const { return result.ok; }
};

/// Two Burgers vectors expressed in one frame (the first circuit's).
struct BurgersComparison {
  Result result = Result::Fail("not compared");
  LatticeVector first;      ///< b of the first circuit, in its own frame
  LatticeVector second;     ///< b of the second circuit, carried into the first's frame
  int rotation = 0;         ///< 60-degree steps from the second frame to the first
  std::vector<int> route;   ///< regular vertices from the first loop to the second loop
  bool opposite = false;    ///< first + second == 0: the two can annihilate (a quadruple)
  bool ambiguous = false;   ///< a disclination lies near the route (see the header comment)
  int disclinationNearRoute = -1;  ///< one such vertex, or -1
  LatticeVector Sum() const { return first + second; }
  explicit operator bool() const { return result.ok; }
};

/// An isolated defect of the mesh: a cluster of adjacent interior irregular vertices.
struct DefectSite {
  enum class Kind {
    Pair,      ///< an adjacent v5 and v7 with no other irregular neighbour: a dislocation
    Lone,      ///< a single v5 or v7 with no irregular neighbour: a disclination
    Other      ///< any other cluster (other valences, 3+ adjacent irregular vertices, a pair whose
               ///< circuit meets the boundary): left out of the plan, reduce it first
  };
  Kind kind = Kind::Other;
  std::vector<int> vertices;  ///< sorted
  int v5 = -1, v7 = -1;       ///< Pair: its two vertices
  int vertex = -1;            ///< Lone: the vertex
  int valence = 0;            ///< Lone: 5 or 7
  int charge = 0;             ///< sum of (6 - valence): 0 for a pair, +1 for a v5, -1 for a v7
  BurgersCircuit circuit;     ///< Pair: its Burgers circuit
};

/// What a planned meeting is predicted to cancel into.
enum class MeetingKind {
  Quadruple,   ///< two pairs with opposite Burgers vectors: all four vanish (sec. 7.3)
  Triple,      ///< a pair and a lone v5 (v7): a 5-5-7 (5-7-7) triple, one v5 (v7) left (sec. 7.2)
  Merge,       ///< two pairs whose vectors are not opposite: the first pair and the second's
               ///< nearer vertex form a triple (sec. 7.2); one 5-7 pair is left, of vector `remaining`
  LoneTriple   ///< three lone vertices, 5-5-7 or 5-7-7, gathered by the triple cancellation (sec. 7.2)
};

inline const char* MeetingKindName(MeetingKind k) {
  switch (k) {
    case MeetingKind::Quadruple: return "quadruple";
    case MeetingKind::Triple: return "triple";
    case MeetingKind::Merge: return "merge";
    case MeetingKind::LoneTriple: return "lone triple";
  }
  return "?";
}

/// One meeting of the plan: which sites to bring together and what is predicted to happen.
struct PlannedMeeting {
  MeetingKind kind = MeetingKind::Triple;
  int first = -1, second = -1, third = -1;  ///< site indices (third: LoneTriple only); for a
                                            ///< Triple, `first` is the pair and `second` the lone vertex
  std::vector<int> vertices;  ///< what to pass to the composite operation: Quadruple {a5, a7, b5, b7}
                              ///< (CancelQuadruple); Triple / Merge / LoneTriple: three vertices (CancelTriple)
  int distance = 0;           ///< graph distance (edges) between the nearest vertices of first and second
                              ///< (LoneTriple: from the odd vertex to both others, summed)
  int routeLength = 0;        ///< the route's length: the separatrix path (two straight segments,
                              ///< separatrix.h) when one joins the nearest vertices, else `distance`
  bool alongSeparatrices = false;
  int removes = 0;            ///< irregular vertices the cancellation removes (4 or 2)
  int survivorValence = 0;    ///< Triple / LoneTriple: 5 or 7, the lone vertex left; Merge: 0 (a pair is left)
  LatticeVector remaining;    ///< Merge: the Burgers vector of the pair left (first's frame)
  bool ambiguous = false;     ///< the Burgers comparison deciding the kind was ambiguous, or impossible
                              ///< (no route of regular vertices: then planned as a merge)
  std::string Describe() const {
    std::ostringstream o;
    o << MeetingKindName(kind) << " of vertices";
    for (int v : vertices) o << ' ' << v;
    o << ", route " << routeLength << " edges" << (alongSeparatrices ? " along separatrices" : "") << ", removes "
      << removes;
    if (kind == MeetingKind::Merge) o << ", leaves a 5-7 pair of Burgers vector " << remaining.Str();
    if (ambiguous) o << " (Burgers comparison ambiguous: a lone irregular vertex near the route)";
    return o.str();
  }
};

struct MatchingOptions {
  int reach = 12;           ///< most edges between two sites that may meet (the travel bound)
  int maxExact = 16;        ///< components of at most this many sites (at most 20) are matched exactly (subset DP);
                            ///< larger ones greedily (most removed first, then the shortest route)
  bool loneTriples = true;  ///< also plan triples of three lone vertices
  int loneTripleFanout = 6; ///< lone vertices considered around each odd vertex for those triples
  int ambiguitySlack = 2;   ///< see DislocationAnalysis::Compare
};

/// The plan: every site, the meetings chosen, and the sites left unmatched.
struct MeetingPlan {
  std::vector<DefectSite> sites;
  std::vector<PlannedMeeting> meetings;  ///< shortest route first
  std::vector<int> unmatched;            ///< site indices no meeting uses
  int candidates = 0;                    ///< meetings considered
  int exactComponents = 0, greedyComponents = 0;
  int predictedRemoved = 0;              ///< sum of `removes` over the meetings
  int Count(MeetingKind k) const {
    int n = 0;
    for (auto& m : meetings) n += m.kind == k;
    return n;
  }
  std::string Summary() const {
    std::ostringstream o;
    o << sites.size() << " sites, " << meetings.size() << " meetings (" << Count(MeetingKind::Quadruple)
      << " quadruples, " << Count(MeetingKind::Triple) << " triples, " << Count(MeetingKind::Merge) << " merges, "
      << Count(MeetingKind::LoneTriple) << " lone triples), " << predictedRemoved << " irregular vertices to remove, "
      << unmatched.size() << " sites unmatched";
    return o.str();
  }
};

template <class MeshType>
class DislocationAnalysis {
 public:
  typedef typename MeshType::VertexType VertexType;
  typedef typename MeshType::FaceType FaceType;

  explicit DislocationAnalysis(MeshType& m) : m_(m) {}

  /// A regular interior vertex (valence 6, not on the boundary): where a frame can be.
  bool IsRegular(int v) {
    if (!Live(v)) return false;
    VertexStar<MeshType> s = StarOf<MeshType>(V(v));
    return s.manifold && !s.boundary && s.Valence() == 6;
  }

  /// The direction (0..5) of the edge f.vertex -> w in frame f; -1 if f.vertex is not regular
  /// or w is not its neighbour.
  int DirectionOf(const LatticeFrame& f, int w) {
    if (!f.Valid() || !Live(f.vertex)) return -1;
    VertexStar<MeshType> s = StarOf<MeshType>(V(f.vertex));
    if (!s.manifold || s.boundary || s.Valence() != 6) return -1;
    const int i = s.IndexOf(V(f.ref)), j = s.IndexOf(V(w));
    if (i < 0 || j < 0) return -1;
    return ((j - i) % 6 + 6) % 6;
  }

  /// The frame at regular vertex v whose direction `dir` is the edge v -> w.
  LatticeFrame FrameWith(int v, int w, int dir) {
    LatticeFrame f;
    if (!Live(v)) return f;
    VertexStar<MeshType> s = StarOf<MeshType>(V(v));
    if (!s.manifold || s.boundary || s.Valence() != 6) return f;
    const int j = s.IndexOf(V(w));
    if (j < 0) return f;
    f.vertex = v;
    f.ref = Index(s.neighbors[size_t(((j - dir) % 6 + 6) % 6)]);
    return f;
  }

  /// Carries frame f across the edge f.vertex -> w (parallel transport on the lattice: the
  /// edge keeps its direction, so w -> f.vertex points the opposite way). Invalid if w is
  /// not regular.
  LatticeFrame Carry(const LatticeFrame& f, int w) {
    const int d = DirectionOf(f, w);
    if (d < 0) return LatticeFrame();
    return FrameWith(w, f.vertex, d + 3);
  }

  /// The Burgers circuit around `core` (see BurgersCircuit). Fails, with the reason, when the
  /// core touches the boundary, its stars do not bound a single loop, or the loop passes an
  /// irregular vertex (the core is not isolated: take the larger cluster as the core).
  BurgersCircuit Circuit(std::vector<int> core) {
    BurgersCircuit c;
    std::sort(core.begin(), core.end());
    core.erase(std::unique(core.begin(), core.end()), core.end());
    c.core = core;
    std::unordered_set<const FaceType*> region;
    for (int v : core) {
      if (!Live(v)) return Fail(c, "vertex " + std::to_string(v) + " is not a live vertex");
      VertexStar<MeshType> s = StarOf<MeshType>(V(v));
      if (s.boundary || !s.manifold) return Fail(c, "vertex " + std::to_string(v) + " lies on the boundary");
      c.charge += 6 - s.Valence();
      for (auto& k : s.corners) region.insert(k.f);
    }
    // the region's border: half-edges V(z) -> V(z+1) of its faces whose neighbour is outside;
    // a CCW face has itself on the left, so these run counter-clockwise around the region
    std::unordered_map<int, int> next;
    for (const FaceType* f : region)
      for (int z = 0; z < 3; ++z) {
        const FaceType* g = f->cFFp(z);
        if (g == f) return Fail(c, "the circuit around the vertices meets the boundary");
        if (region.count(g)) continue;
        const int a = Index(f->cV(z)), b = Index(f->cV((z + 1) % 3));
        if (!next.emplace(a, b).second)
          return Fail(c, "the stars of the vertices do not bound a single loop (vertex " + std::to_string(a) +
                             " is on it twice)");
      }
    if (next.empty()) return Fail(c, "no circuit: the vertices' stars cover the whole mesh");
    int start = std::numeric_limits<int>::max();
    for (auto& kv : next) start = std::min(start, kv.first);
    c.loop.push_back(start);
    for (int v = next[start]; v != start; v = next[v]) {
      c.loop.push_back(v);
      if (c.loop.size() > next.size() || !next.count(v)) return Fail(c, "the circuit does not close");
    }
    if (c.loop.size() != next.size())
      return Fail(c, "the stars of the vertices bound more than one loop (a hole in the region)");
    for (int v : c.loop)
      if (!IsRegular(v))
        return Fail(c, "vertex " + std::to_string(v) + " on the circuit is irregular: the defect is not isolated");
    // walk: d_i = d_{i-1} + 3 - (triangles on the left at loop[i]) (sec. 4's turn)
    const size_t n = c.loop.size();
    c.frame = LatticeFrame{c.loop[0], c.loop[1]};
    int d = 0;
    c.directions.push_back(0);
    c.burgers = LatticeVector::Step(0);
    for (size_t i = 1; i <= n; ++i) {
      const int cur = c.loop[i % n], prev = c.loop[i - 1], nxt = c.loop[(i + 1) % n];
      VertexStar<MeshType> s = StarOf<MeshType>(V(cur));
      const int a = s.IndexOf(V(prev)), b = s.IndexOf(V(nxt));
      d = ((d + 3 + b - a) % 6 + 12) % 6;
      if (i == n) break;
      c.directions.push_back(d);
      c.burgers = c.burgers + LatticeVector::Step(d);
    }
    c.holonomy = d;
    if (c.holonomy != 0) c.burgers = LatticeVector();
    c.result = Result::Ok();
    return c;
  }

  /// The Burgers circuit of the adjacent 5-7 pair (v5, v7).
  BurgersCircuit PairCircuit(int v5, int v7) { return Circuit({v5, v7}); }

  /// The frame of circuit c at its loop vertex loop[i].
  LatticeFrame LoopFrame(const BurgersCircuit& c, size_t i) {
    return FrameWith(c.loop[i], c.loop[(i + 1) % c.loop.size()], c.directions[i]);
  }

  /// The Burgers vector of circuit `from` carried into frame `to` through regular vertices
  /// (at most maxDistance edges): in the result, `second` and `rotation`; on failure result says why.
  BurgersComparison CarryInto(const BurgersCircuit& from, const LatticeFrame& to, int maxDistance) {
    BurgersComparison r;
    // sources: the frame `to` (one vertex); goals: the loop of `from`
    std::vector<std::pair<int, LatticeFrame>> sources{{to.vertex, to}};
    int goalIndex = -1;
    LatticeFrame atGoal;
    if (!Route(sources, from.loop, maxDistance, &goalIndex, &atGoal, &r.route)) {
      r.result = Result::Fail("no route of regular vertices within " + std::to_string(maxDistance) + " edges");
      return r;
    }
    const int j = goalIndex;
    const int dirTo = DirectionOf(atGoal, from.loop[(size_t(j) + 1) % from.loop.size()]);
    r.rotation = ((dirTo - from.directions[size_t(j)]) % 6 + 6) % 6;
    r.second = from.burgers.Rotated(r.rotation);
    r.result = Result::Ok();
    return r;
  }

  /// The Burgers vector of circuit c in frame `to` (carried through regular vertices).
  LatticeVector BurgersIn(const BurgersCircuit& c, const LatticeFrame& to, int maxDistance, Result* why = nullptr) {
    BurgersComparison r = CarryInto(c, to, maxDistance);
    if (why) *why = r.result;
    return r.second;
  }

  /// Compares the Burgers vectors of two circuits (both of holonomy 0) in the first one's
  /// frame, carried along the shortest route of regular vertices between the two loops (at
  /// most maxDistance edges; ties: the order of the loops and of the stars). `ambiguous` when
  /// a disclination x lies where a route at most `slack` edges longer could pass, i.e.
  /// d(loop a, x) + d(x, loop b) <= route length + slack: routes of about that length pass it
  /// on both sides, and their rotations differ by 60 degrees.
  BurgersComparison Compare(const BurgersCircuit& a, const BurgersCircuit& b, int maxDistance, int slack = 2) {
    BurgersComparison r;
    if (!a || !b || a.holonomy != 0 || b.holonomy != 0) {
      r.result = Result::Fail("a Burgers vector is defined around a net charge of 0 only (a 5-7 pair)");
      return r;
    }
    r.first = a.burgers;
    std::vector<std::pair<int, LatticeFrame>> sources;
    for (size_t i = 0; i < a.loop.size(); ++i) sources.push_back({a.loop[i], LoopFrame(a, i)});
    int goalIndex = -1;
    LatticeFrame atGoal;
    if (!Route(sources, b.loop, maxDistance, &goalIndex, &atGoal, &r.route)) {
      r.result = Result::Fail("no route of regular vertices joins the two circuits within " +
                              std::to_string(maxDistance) + " edges");
      return r;
    }
    const int dirA = DirectionOf(atGoal, b.loop[(size_t(goalIndex) + 1) % b.loop.size()]);
    r.rotation = ((dirA - b.directions[size_t(goalIndex)]) % 6 + 6) % 6;
    r.second = b.burgers.Rotated(r.rotation);
    r.opposite = (r.first + r.second).IsZero();
    // ambiguity: a disclination (a cluster of non-zero charge, other than a and b) that a
    // route at most `slack` edges longer than this one could pass on either side
    const int L = int(r.route.size()) - 1;
    std::unordered_set<int> own(a.core.begin(), a.core.end());
    own.insert(b.core.begin(), b.core.end());
    std::unordered_map<int, int> da = Distances(a.loop, L + slack), db = Distances(b.loop, L + slack);
    std::vector<int> near;
    for (auto& kv : da) {
      auto it = db.find(kv.first);
      if (it != db.end() && kv.second + it->second <= L + slack && !own.count(kv.first) &&
          InteriorIrregular(kv.first))
        near.push_back(kv.first);
    }
    std::sort(near.begin(), near.end());
    for (int x : near)
      if (ClusterCharge(x) != 0) {
        r.ambiguous = true;
        r.disclinationNearRoute = x;
        break;
      }
    r.result = Result::Ok();
    return r;
  }

  /// Graph distances (at most `bound`) from the vertices `from`.
  std::unordered_map<int, int> Distances(const std::vector<int>& from, int bound) {
    std::unordered_map<int, int> d;
    std::vector<int> q;
    for (int v : from)
      if (d.emplace(v, 0).second) q.push_back(v);
    for (size_t i = 0; i < q.size(); ++i) {
      const int v = q[i], dv = d[v];
      if (dv >= bound) continue;
      for (VertexType* n : StarOf<MeshType>(V(v)).neighbors)
        if (d.emplace(Index(n), dv + 1).second) q.push_back(Index(n));
    }
    return d;
  }

  /// The connected cluster of interior irregular vertices containing v (adjacency), at most
  /// `bound` vertices; sorted.
  std::vector<int> ClusterOf(int v, int bound = 64) {
    return ClusterOf(v, bound, [this](int w) { return InteriorIrregular(w); });
  }
  /// The same, with `irregular(w)` telling whether w is an interior irregular vertex (e.g. a
  /// caller's memo of InteriorIrregular).
  template <class IsIrregular>
  std::vector<int> ClusterOf(int v, int bound, IsIrregular irregular) {
    std::vector<int> c{v};
    std::unordered_set<int> seen{v};
    for (size_t i = 0; i < c.size() && c.size() < size_t(bound); ++i)
      for (VertexType* n : StarOf<MeshType>(V(c[i])).neighbors) {
        const int w = Index(n);
        if (seen.insert(w).second && irregular(w)) c.push_back(w);
      }
    std::sort(c.begin(), c.end());
    return c;
  }

  int ClusterCharge(int v) { return ChargeOf(ClusterOf(v)); }
  /// The summed charge (6 - valence) of the given vertices.
  int ChargeOf(const std::vector<int>& vertices) {
    int q = 0;
    for (int x : vertices) q += 6 - StarOf<MeshType>(V(x)).Valence();
    return q;
  }

  bool InteriorIrregular(int v) {
    if (!Live(v)) return false;
    VertexStar<MeshType> s = StarOf<MeshType>(V(v));
    return !s.boundary && s.Valence() != 6;
  }

  /// The defect sites of the given interior irregular vertices (clusters by adjacency), in
  /// order of their lowest vertex; pairs get their Burgers circuit.
  std::vector<DefectSite> Sites(const std::vector<int>& irregular) {
    std::vector<DefectSite> sites;
    std::unordered_set<int> done;
    std::vector<int> sorted = irregular;
    std::sort(sorted.begin(), sorted.end());
    for (int v : sorted) {
      if (done.count(v) || !InteriorIrregular(v)) continue;
      DefectSite s;
      s.vertices = ClusterOf(v);
      for (int x : s.vertices) done.insert(x), s.charge += 6 - StarOf<MeshType>(V(x)).Valence();
      if (s.vertices.size() == 1) {
        s.valence = 6 - s.charge;
        if (s.valence == 5 || s.valence == 7) s.kind = DefectSite::Kind::Lone, s.vertex = v;
      } else if (s.vertices.size() == 2 && s.charge == 0) {
        const int d0 = StarOf<MeshType>(V(s.vertices[0])).Valence();
        if (d0 == 5 || d0 == 7) {
          s.v5 = d0 == 5 ? s.vertices[0] : s.vertices[1];
          s.v7 = d0 == 5 ? s.vertices[1] : s.vertices[0];
          s.circuit = PairCircuit(s.v5, s.v7);
          if (s.circuit && s.circuit.holonomy == 0) s.kind = DefectSite::Kind::Pair;
        }
      }
      sites.push_back(s);
    }
    return sites;
  }

  /// The global plan (see MeetingPlan) for the given interior irregular vertices (every one
  /// of the mesh if empty: one O(V) pass). Sites of kind Other are never planned. Candidate
  /// meetings: two sites whose nearest vertices are at most opt.reach edges apart along a
  /// path that passes no other irregular vertex (pair + pair: a quadruple if the Burgers
  /// vectors are opposite, else a merge; pair + lone: a triple), and, for each lone vertex,
  /// two lone vertices of the other valence within reach of it (a lone triple, its route the
  /// sum of the two distances). The route of a two-site meeting is the separatrix path
  /// (separatrix.h) between the nearest vertices when one exists within reach.
  MeetingPlan Plan(std::vector<int> irregular = {}, const MatchingOptions& opt = MatchingOptions()) {
    if (irregular.empty()) {
      ValenceField<MeshType> vf = ComputeValences(m_);
      for (size_t i = 0; i < m_.vert.size(); ++i)
        if (!m_.vert[i].IsD() && vf.referenced[i] && !vf.boundary[i] && vf.valence[i] != 6) irregular.push_back(int(i));
    }
    MeetingPlan plan;
    plan.sites = Sites(irregular);
    std::unordered_map<int, int> siteOf;
    for (size_t s = 0; s < plan.sites.size(); ++s)
      for (int v : plan.sites[s].vertices) siteOf[v] = int(s);
    // nearest other sites within reach, from each site (BFS from its vertices)
    struct Near {
      int dist, from, to;
    };
    std::vector<std::map<int, Near>> near(plan.sites.size());
    for (size_t s = 0; s < plan.sites.size(); ++s) {
      if (plan.sites[s].kind == DefectSite::Kind::Other) continue;
      std::unordered_map<int, std::pair<int, int>> dist;  // vertex -> (distance, source vertex)
      std::vector<int> q;
      for (int v : plan.sites[s].vertices) dist[v] = {0, v}, q.push_back(v);
      for (size_t i = 0; i < q.size(); ++i) {
        const int v = q[i];
        const auto dv = dist[v];
        if (dv.first >= opt.reach) continue;
        VertexStar<MeshType> st = StarOf<MeshType>(V(v));
        if (st.boundary && dv.first > 0) continue;
        for (VertexType* n : st.neighbors) {
          const int w = Index(n);
          if (!dist.emplace(w, std::make_pair(dv.first + 1, dv.second)).second) continue;
          auto it = siteOf.find(w);
          if (it != siteOf.end()) {
            const int t = it->second;
            if (t != int(s) && plan.sites[size_t(t)].kind != DefectSite::Kind::Other && !near[s].count(t))
              near[s][t] = Near{dv.first + 1, dv.second, w};
            continue;  // never route through another defect
          }
          q.push_back(w);
        }
      }
    }
    // candidate meetings
    std::vector<PlannedMeeting> cand;
    SeparatrixTracer<MeshType> tracer(m_);
    auto route = [&](PlannedMeeting& pm, const Near& nr) {
      pm.distance = nr.dist;
      pm.routeLength = nr.dist;
      ConnectingPath p = tracer.Connect(nr.from, nr.to, opt.reach);
      if (p) pm.alongSeparatrices = true, pm.routeLength = p.Length();
    };
    for (size_t s = 0; s < plan.sites.size(); ++s)
      for (auto& kv : near[s]) {
        const size_t t = size_t(kv.first);
        if (t < s && near[t].count(int(s))) continue;  // each unordered couple once, from its lower site
        const DefectSite &A = plan.sites[s], &B = plan.sites[t];
        PlannedMeeting pm;
        if (A.kind == DefectSite::Kind::Pair && B.kind == DefectSite::Kind::Pair) {
          BurgersComparison c = Compare(A.circuit, B.circuit, opt.reach + 4, opt.ambiguitySlack);
          pm.first = int(s), pm.second = int(t);
          pm.ambiguous = !c.result.ok || c.ambiguous;  // not comparable: a merge, flagged
          if (c && c.opposite) {
            pm.kind = MeetingKind::Quadruple, pm.removes = 4;
            pm.vertices = {A.v5, A.v7, B.v5, B.v7};
          } else {
            pm.kind = MeetingKind::Merge, pm.removes = 2;
            if (c) pm.remaining = c.Sum();
            // the first pair travels to the second's vertex nearest to it
            pm.vertices = {A.v5, A.v7, kv.second.to};
          }
        } else if (A.kind == DefectSite::Kind::Pair || B.kind == DefectSite::Kind::Pair) {
          const bool aPair = A.kind == DefectSite::Kind::Pair;
          const DefectSite& P = aPair ? A : B;
          const DefectSite& L = aPair ? B : A;
          pm.kind = MeetingKind::Triple, pm.removes = 2, pm.survivorValence = L.valence;
          pm.first = aPair ? int(s) : int(t), pm.second = aPair ? int(t) : int(s);
          pm.vertices = {P.v5, P.v7, L.vertex};
        } else {
          continue;  // two lone vertices: only as part of a lone triple
        }
        route(pm, kv.second);
        cand.push_back(pm);
      }
    if (opt.loneTriples) {
      for (size_t s = 0; s < plan.sites.size(); ++s) {
        const DefectSite& X = plan.sites[s];
        if (X.kind != DefectSite::Kind::Lone) continue;
        // X is the odd vertex: two lone vertices of the other valence around it
        std::vector<std::pair<int, int>> others;  // (distance, site)
        for (auto& kv : near[s]) {
          const DefectSite& Y = plan.sites[size_t(kv.first)];
          if (Y.kind == DefectSite::Kind::Lone && Y.valence != X.valence) others.push_back({kv.second.dist, kv.first});
        }
        std::sort(others.begin(), others.end());
        if (int(others.size()) > opt.loneTripleFanout) others.resize(size_t(opt.loneTripleFanout));
        for (size_t i = 0; i < others.size(); ++i)
          for (size_t j = i + 1; j < others.size(); ++j) {
            PlannedMeeting pm;
            pm.kind = MeetingKind::LoneTriple, pm.removes = 2, pm.survivorValence = 12 - X.valence;
            pm.first = int(s), pm.second = others[i].second, pm.third = others[j].second;
            pm.vertices = {X.vertex, plan.sites[size_t(pm.second)].vertex, plan.sites[size_t(pm.third)].vertex};
            pm.distance = pm.routeLength = others[i].first + others[j].first;
            cand.push_back(pm);
          }
      }
    }
    plan.candidates = int(cand.size());
    Match(plan, cand, opt);
    return plan;
  }

 private:
  VertexType* V(int i) { return &m_.vert[size_t(i)]; }
  int Index(const VertexType* v) const { return int(vcg::tri::Index(m_, v)); }
  bool Live(int v) const { return v >= 0 && size_t(v) < m_.vert.size() && !m_.vert[size_t(v)].IsD() && m_.vert[size_t(v)].cVFp(); }

  static BurgersCircuit& Fail(BurgersCircuit& c, const std::string& why) {
    c.result = Result::Fail(why);
    return c;
  }

  /// Breadth-first search through regular vertices from the sources (each with its frame),
  /// carrying the frame, until a vertex of `goals`. *goalIndex: its index in goals; *frame:
  /// the frame carried there; *path: the route, source to goal.
  bool Route(const std::vector<std::pair<int, LatticeFrame>>& sources, const std::vector<int>& goals, int maxDistance,
             int* goalIndex, LatticeFrame* frame, std::vector<int>* path) {
    std::unordered_map<int, int> goalAt;
    for (size_t i = 0; i < goals.size(); ++i) goalAt.emplace(goals[i], int(i));
    struct Node {
      LatticeFrame f;
      int parent, dist;
    };
    std::unordered_map<int, Node> seen;
    std::vector<int> q;
    for (auto& s : sources)
      if (s.second.Valid() && seen.emplace(s.first, Node{s.second, -1, 0}).second) q.push_back(s.first);
    for (size_t i = 0; i < q.size(); ++i) {
      const int v = q[i];
      const Node nv = seen[v];
      auto g = goalAt.find(v);
      if (g != goalAt.end()) {
        *goalIndex = g->second;
        *frame = nv.f;
        path->clear();
        for (int x = v; x >= 0; x = seen[x].parent) path->push_back(x);
        std::reverse(path->begin(), path->end());
        return true;
      }
      if (nv.dist >= maxDistance) continue;
      for (VertexType* n : StarOf<MeshType>(V(v)).neighbors) {
        const int w = Index(n);
        if (seen.count(w)) continue;
        LatticeFrame fw = Carry(nv.f, w);
        if (!fw.Valid()) continue;  // irregular or boundary: no frame through it
        seen.emplace(w, Node{fw, v, nv.dist + 1});
        q.push_back(w);
      }
    }
    return false;
  }

  /// Chooses meetings: per connected component of the candidate graph, exactly (most
  /// vertices removed, then the shortest total route; subset DP) when it has at most
  /// opt.maxExact sites, else greedily in that order.
  void Match(MeetingPlan& plan, const std::vector<PlannedMeeting>& cand, const MatchingOptions& opt) {
    const size_t n = plan.sites.size();
    std::vector<int> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    std::function<int(int)> find = [&](int x) { return parent[size_t(x)] == x ? x : parent[size_t(x)] = find(parent[size_t(x)]); };
    auto members = [](const PlannedMeeting& pm) {
      std::vector<int> s{pm.first, pm.second};
      if (pm.third >= 0) s.push_back(pm.third);
      return s;
    };
    for (auto& pm : cand) {
      auto s = members(pm);
      for (size_t i = 1; i < s.size(); ++i) parent[size_t(find(s[i]))] = find(s[0]);
    }
    std::map<int, std::vector<int>> comps;  // root -> sites (ascending)
    for (size_t s = 0; s < n; ++s) comps[find(int(s))].push_back(int(s));
    std::map<int, std::vector<int>> candOf;  // root -> candidate indices
    for (size_t c = 0; c < cand.size(); ++c) candOf[find(cand[c].first)].push_back(int(c));
    std::vector<char> used(n, 0);
    std::vector<int> chosen;
    for (auto& comp : comps) {
      const std::vector<int>& sites = comp.second;
      const std::vector<int>& cs = candOf[comp.first];
      if (cs.empty()) continue;
      if (int(sites.size()) <= std::min(opt.maxExact, 20)) {
        ++plan.exactComponents;
        std::unordered_map<int, int> local;
        for (size_t i = 0; i < sites.size(); ++i) local[sites[i]] = int(i);
        int64_t big = 1;
        for (int c : cs) big += cand[size_t(c)].routeLength;
        std::vector<std::vector<int>> byNode(sites.size());
        std::vector<uint32_t> maskOf(cs.size());
        std::vector<int64_t> weight(cs.size());
        for (size_t k = 0; k < cs.size(); ++k) {
          const PlannedMeeting& pm = cand[size_t(cs[k])];
          uint32_t mk = 0;
          for (int s : members(pm)) mk |= 1u << local[s];
          maskOf[k] = mk;
          weight[k] = int64_t(pm.removes) * big - pm.routeLength;
          for (int s : members(pm)) byNode[size_t(local[s])].push_back(int(k));
        }
        const uint32_t full = (sites.size() >= 32) ? 0xFFFFFFFFu : ((1u << sites.size()) - 1);
        std::vector<int64_t> f(size_t(full) + 1, 0);
        std::vector<int> choice(size_t(full) + 1, -1);
        for (uint32_t mask = 1; mask <= full; ++mask) {
          int i = 0;
          while (!(mask & (1u << i))) ++i;
          int64_t best = f[mask ^ (1u << i)];
          int ch = -1;
          for (int k : byNode[size_t(i)]) {
            const uint32_t mk = maskOf[size_t(k)];
            if ((mk & mask) != mk) continue;
            const int64_t v = weight[size_t(k)] + f[mask ^ mk];
            if (v > best) best = v, ch = k;
          }
          f[mask] = best;
          choice[mask] = ch;
          if (mask == full) break;
        }
        for (uint32_t mask = full; mask;) {
          int i = 0;
          while (!(mask & (1u << i))) ++i;
          const int k = choice[mask];
          if (k < 0) {
            mask ^= 1u << i;
          } else {
            chosen.push_back(cs[size_t(k)]);
            mask ^= maskOf[size_t(k)];
          }
        }
      } else {
        ++plan.greedyComponents;
        std::vector<int> order = cs;
        std::stable_sort(order.begin(), order.end(), [&](int x, int y) {
          const PlannedMeeting &a = cand[size_t(x)], &b = cand[size_t(y)];
          if (a.removes != b.removes) return a.removes > b.removes;
          return a.routeLength < b.routeLength;
        });
        for (int c : order) {
          bool free = true;
          for (int s : members(cand[size_t(c)])) free = free && !used[size_t(s)];
          if (!free) continue;
          for (int s : members(cand[size_t(c)])) used[size_t(s)] = 1;
          chosen.push_back(c);
        }
      }
    }
    std::fill(used.begin(), used.end(), 0);
    for (int c : chosen) {
      plan.meetings.push_back(cand[size_t(c)]);
      for (int s : members(cand[size_t(c)])) used[size_t(s)] = 1;
    }
    std::stable_sort(plan.meetings.begin(), plan.meetings.end(), [](const PlannedMeeting& a, const PlannedMeeting& b) {
      if (a.routeLength != b.routeLength) return a.routeLength < b.routeLength;
      return a.vertices < b.vertices;
    });
    for (auto& pm : plan.meetings) plan.predictedRemoved += pm.removes;
    for (size_t s = 0; s < n; ++s)
      if (!used[s]) plan.unmatched.push_back(int(s));
  }

  MeshType& m_;
};

}  // namespace irregular
}  // namespace vcg_ext
