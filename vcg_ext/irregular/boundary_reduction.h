// filter_irregular: the boundary stage of the automatic reduction (issue 14, item 3): interior
// irregular vertices near a boundary are moved into it or cancelled there, with the boundary
// operations of boundary_ops.h and the 5-7 pair movement of atomic_ops.h.
//
// Why it can work (paper eq. 2, sec. 6.1). Eq. 2 reads
//     sum_{interior v} (6 - d(v)) + sum_{boundary v} (4 - d(v)) = 6 chi,
// so on a mesh with boundaries the curvature of the inside can leave through the boundary: the
// interior floor is 0. The boundary operations of boundary_ops.h move one unit of defect between
// the inside and the boundary (its header derives them from the valence rules of sec. 6.1 on the
// surface closed by a cone vertex over each hole):
//   (A) boundary-edge collapse under an interior v7 (its apex): the v7 becomes regular and the
//       surviving end gains d(u) + d(w) - 3; if the removed end was a boundary v3 the two
//       defects cancel, else the boundary gets a v5 (a boundary "v7");
//   (B) boundary split next to an interior v5: the v5 becomes regular, the split vertex's two
//       halves have i + 2 and n - i + 2 edges; at a boundary v5 (n = 4, i = 2) the defects
//       cancel, else a boundary v3 (a boundary "v5") is left.
// Which boundary vertices count as irregular follows the corner rule (topology.h,
// RegularBoundaryValence: round(corner angle / 60) + 1), a geometric rule: it is measured after
// each edit (and after the driver's relaxation), never predicted.
//
// Strategy (one pass per call; the driver calls it once per sweep):
//   candidates: interior v5 / v7 within `rings` edges of a boundary, found by a breadth-first
//   walk from the boundary vertices (one O(V + F) pass per call), nearest to the boundary first.
//   For each candidate, these edits are tried (each all or nothing, under one journal mark):
//     absorb   Absorb(v) when v touches the boundary (v5: a boundary neighbour, v7: apex of a
//              boundary edge); Absorb itself picks the boundary vertex that cancels (a boundary
//              v5 for (B), a boundary v3 end for (A)) when there is one;
//     pair     an adjacent interior 5-7 pair (v and a neighbour of the other type) is moved by
//              pair steps (fig. 6; at most `maxTravel`) toward a target and absorbed whole by
//              AbsorbPair as soon as it touches the boundary near the target; one edit per
//              target: the nearest boundary irregular vertices (targetsPerPair) and the nearest
//              boundary vertex. A
//              pair is absorbed whole only where its edge runs along the boundary, so trying
//              several places along a curved hole finds one more often. A pair is a dislocation:
//              it carries no curvature (5 + 7 = 12), so moving it never needs a partner; at the
//              boundary it cancels a boundary 5-7 pair or leaves one (a step in the boundary).
//     hop      a v5 / v7 two rings in (no boundary neighbour) moves one step onto a neighbour
//              that touches the boundary, generating an adjacent 5-7 pair (fig. 7, flip form;
//              Theorem 5.1: a single irregular vertex cannot move alone); the generated pair is
//              absorbed as above, then the moved vertex: three defects reach the boundary.
//   Not used: MoveAlongBoundary (boundary_ops.h). It collapses the v3 b into one boundary
//   neighbour and splits the other along its edge to b's apex a, so the result is the same
//   configuration relabelled (the new v3 hangs from the same apex a, with the same neighbours up
//   to renaming): the v3 shifts geometrically but never comes under another interior vertex, so
//   it cannot meet an interior v7. A move that carries a boundary 5-7 pair (or a boundary v3)
//   past interior vertices along the boundary would let the stage (1) bring a boundary
//   irregular vertex under an interior v5 / v7 that has only regular boundary neighbours (a
//   cancellation instead of a neutral absorption) and (2) cancel the boundary 5-7 pairs that
//   neutral absorptions leave against other boundary irregular vertices, which frees budget.
//   Each edit is scored by what it changes: dI (interior irregular vertices) and dB (boundary
//   irregular vertices, corner rule), counted on the vertices around the edit. It is kept only if
//     dI < 0 (the inside gets cleaner),  dB <= 0 or B + dB <= boundaryLimit (never more
//     boundary irregular vertices than the input had; if other edits already went past the
//     limit, the stage only lowers B), and dI + dB < 0 in the first phase (a cancellation: the
//     total drops) or dI + dB <= 0 in the second phase (a neutral move into the boundary, paid
//     with the slack the cancellations of the first phase made).
//   Among the edits that pass, the one with the lowest dI + dB (then dI) is applied again under
//   the driver's guard: begin(around) before the edit, accept(touched) after it (the driver
//   relaxes and checks angle and Hausdorff there); if accept says no, or the relaxation moved a
//   boundary corner so that the rules above fail, the stage rolls back to its mark.
//
// Cost: the per-call pass is O(V + F); each edit costs O(touched): the probes, the counting
// (statusRing rings around the touched vertices) and the pair transport (O(travel) steps, each a
// dry run of six moves) are local. Effort is bounded by counting attempts (maxAttemptsPerCall),
// never by the clock, so results are deterministic.
//
// Preconditions: a manifold, consistently oriented mesh with FF and VF adjacency (mesh_checks.h),
// edited through the given MeshEditor (journaled). Postconditions: every kept edit keeps the
// mesh a valid manifold with a consistent boundary and eq. 2; interior irregular count never
// rises; the boundary irregular count never rises above boundaryLimit. Frozen vertices (and the
// faces around them) are never changed.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <queue>
#include <set>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "atomic_ops.h"
#include "boundary_ops.h"
#include "relaxation.h"
#include "surface_projector.h"
#include "topology.h"

namespace vcg_ext {
namespace irregular {

/// Irregular vertices split by where they are: interior (valence != 6) and boundary (the corner
/// rule of topology.h). The report of a reduction shows both.
struct IrregularByPlace {
  int interior = 0;
  int boundary = 0;
  int Total() const { return interior + boundary; }
};

/// The irregular vertices themselves (indices into m.vert, ascending), split the same way.
struct IrregularVertexLists {
  std::vector<int> interior, boundary;
};

/// Lists the interior and boundary irregular vertices of the whole mesh. O(V + F).
template <class MeshType>
IrregularVertexLists IrregularVerticesByPlace(MeshType& m) {
  IrregularVertexLists l;
  ValenceField<MeshType> vf = ComputeValences(m);
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD() && vf.IsIrregular(i)) (vf.boundary[i] ? l.boundary : l.interior).push_back(int(i));
  return l;
}

/// Counts interior and boundary irregular vertices of the whole mesh. O(V + F).
template <class MeshType>
IrregularByPlace CountIrregularByPlace(MeshType& m) {
  IrregularVertexLists l = IrregularVerticesByPlace(m);
  IrregularByPlace c;
  c.interior = int(l.interior.size());
  c.boundary = int(l.boundary.size());
  return c;
}

struct BoundaryReductionOptions {
  int rings = 3;           ///< interior v5 / v7 within this many edges of a boundary are candidates
  int maxTravel = 6;       ///< most pair steps a 5-7 pair makes toward the boundary before it is absorbed
  int targetsPerPair = 3;  ///< boundary irregular vertices (nearest first) a pair tries to reach, besides the
                           ///< nearest boundary vertex
  bool neutralMoves = true;  ///< second phase: also absorb where the boundary gains what the inside loses
                             ///< (dI + dB = 0), as long as the boundary stays within boundaryLimit
  int boundaryLimit = -1;  ///< most boundary irregular vertices allowed; -1: the count when the stage was
                           ///< constructed (the input's, when the driver builds it before editing)
  int statusRing = 3;      ///< the counts are re-read within this many rings of the touched vertices (the
                           ///< guard relaxes 2 rings; a corner angle also depends on the neighbours)
  int relaxIterations = 3; ///< sweeps of the default relaxation between pair steps (when the guard has none)
  long maxAttemptsPerCall = 20000;  ///< effort bound per call: edits tried (probes included)
};

/// What the driver supplies to guard each edit. Only accept is required.
struct BoundaryEditGuard {
  /// Called after the stage's Mark() and before the edit, with the live vertices the edit will
  /// touch (the driver records the smallest angle around them, as its Guard does).
  std::function<void(const std::vector<int>& around)> begin;
  /// Relaxes the edit's neighbourhood and checks it (angle, Hausdorff, ...). False: the edit must
  /// be undone; the stage then rolls back to its mark (the guard may already have done so).
  std::function<bool(const std::vector<int>& touched)> accept;
  /// Optional: relaxation between the pair steps of one transport (so the next step's fold
  /// check sees usable triangles). Empty: local relaxation of the 2-ring, projected on the input,
  /// boundary vertices sliding along the input's boundary.
  std::function<void(const std::vector<int>& seeds)> relax;
  /// Optional: called once after every begin, when the stage has decided: kept (the edit stays;
  /// the driver may now commit it) or not (the stage has rolled back to its mark). A driver
  /// that commits its journal must do so here, never in accept: the stage re-counts after
  /// accept and may still roll back.
  std::function<void(bool kept, const std::vector<int>& touched)> end;
};

/// What one call did. Counts are of kept edits unless named otherwise.
struct BoundaryReductionReport {
  int interiorBefore = 0, interiorAfter = 0;  ///< interior irregular vertices of the whole mesh
  int boundaryBefore = 0, boundaryAfter = 0;  ///< boundary irregular vertices (corner rule), whole mesh
  int boundaryLimit = 0;  ///< the most boundary irregular vertices allowed (the input's)
  int candidates = 0;     ///< interior v5 / v7 within `rings` of a boundary at the start of the call (summed by Add)
  int absorbedV5 = 0;     ///< single interior v5 absorbed (boundary split, (B))
  int absorbedV7 = 0;     ///< single interior v7 absorbed (boundary-edge collapse, (A))
  int absorbedPairs = 0;  ///< adjacent interior 5-7 pairs absorbed whole
  int pairsMoved = 0;     ///< of those, pairs first moved toward the boundary
  int pairSteps = 0;      ///< pair steps of those moves
  int hops = 0;           ///< v5 / v7 two rings in that moved one step to the boundary generating a 5-7 pair
                          ///< (fig. 7), then were absorbed with the pair (not counted in the three above)
  int cancelled = 0;      ///< boundary irregular vertices removed by kept edits (each cancelled an interior one)
  int boundaryAdded = 0;  ///< boundary irregular vertices added by kept neutral edits (paid by `cancelled`)
  int undone = 0;         ///< edits the guard refused, or whose relaxation broke the counting rules; rolled back
  int refused = 0;        ///< candidates no edit could take within the rules (topology, budget, frozen, no reach)
  long attempts = 0;      ///< edits tried, probes included (the effort bound counts these)
  bool effortExhausted = false;  ///< maxAttemptsPerCall was reached
  int calls = 0;          ///< calls of Run() this report covers (1, or the number summed by Add)
  int Kept() const { return absorbedV5 + absorbedV7 + absorbedPairs + hops; }
  /// Sums the counts of a later call into this one (the driver's total over its sweeps): the
  /// "before" values stay the first call's, the "after" values become the later call's.
  void Add(const BoundaryReductionReport& o) {
    if (calls == 0) interiorBefore = o.interiorBefore, boundaryBefore = o.boundaryBefore;
    calls += o.calls;
    interiorAfter = o.interiorAfter, boundaryAfter = o.boundaryAfter, boundaryLimit = o.boundaryLimit;
    candidates += o.candidates;
    absorbedV5 += o.absorbedV5, absorbedV7 += o.absorbedV7, absorbedPairs += o.absorbedPairs;
    pairsMoved += o.pairsMoved, pairSteps += o.pairSteps, hops += o.hops;
    cancelled += o.cancelled, boundaryAdded += o.boundaryAdded, undone += o.undone, refused += o.refused;
    attempts += o.attempts;
    effortExhausted = effortExhausted || o.effortExhausted;
  }
};

template <class MeshType>
class BoundaryReduction {
 public:
  typedef MeshEditor<MeshType> Editor;
  typedef typename MeshType::CoordType CoordType;

  /// ed: the driver's editor (journaled). original: the input surface (the default relaxation
  /// projects on it; may be null: no default relaxation). frozen: per vertex index, 1 = never
  /// touched (may be null; vertices created later are free). Counts the input's boundary
  /// irregular vertices (the limit) unless opt.boundaryLimit >= 0. inputBoundary: the
  /// boundary polyline the default relaxation slides along, if the caller has it (it must
  /// outlive the stage); null: the stage builds it from the mesh as it is now. O(V + F).
  BoundaryReduction(Editor& ed, const SurfaceProjector* original, BoundaryEditGuard guard,
                    const std::vector<char>* frozen = nullptr,
                    BoundaryReductionOptions opt = BoundaryReductionOptions(),
                    const BoundaryCurve* inputBoundary = nullptr)
      : ed_(ed), m_(ed.Mesh()), original_(original), guard_(std::move(guard)), frozen_(frozen), opt_(opt),
        bops_(ed), ops_(ed), ownCurve_(inputBoundary ? nullptr : new BoundaryCurve(ed.Mesh())),
        curve_(inputBoundary ? inputBoundary : ownCurve_.get()) {
    limit_ = opt_.boundaryLimit >= 0 ? opt_.boundaryLimit : CountIrregularByPlace(m_).boundary;
  }

  int BoundaryLimit() const { return limit_; }

  /// One pass over the interior irregular vertices near the boundaries (see the header).
  BoundaryReductionReport Run() {
    BoundaryReductionReport r;
    r.calls = 1;
    r.boundaryLimit = limit_;
    std::vector<int> cands = BuildStatus();
    vetoed_.clear();
    r.interiorBefore = interior_;
    r.boundaryBefore = boundary_;
    r.candidates = int(cands.size());
    for (int phase = 0; phase < (opt_.neutralMoves ? 2 : 1); ++phase)
      for (int v : cands) {
        if (r.attempts >= opt_.maxAttemptsPerCall) {
          r.effortExhausted = true;
          break;
        }
        if (!ed_.IsLive(v) || Status(v) != kInterior || Frozen(v)) continue;
        const int d = ed_.Valence(v);
        if (d != 5 && d != 7) continue;
        if (!TryCandidate(v, phase == 1, r) && phase + 1 == (opt_.neutralMoves ? 2 : 1)) ++r.refused;
      }
    r.interiorAfter = interior_;
    r.boundaryAfter = boundary_;
    return r;
  }

 private:
  static constexpr signed char kRegular = 0, kInterior = 1, kBoundary = 2;  ///< a vertex's status
  enum Kind { kAbsorb = 0, kPair = 1, kHop = 2 };

  /// An edit for a candidate v: absorb v, or move the pair (v, partner) toward the boundary
  /// vertex `target` and absorb it. Everything the edit does follows from these (the re-run
  /// under the guard repeats the probe exactly).
  struct Plan {
    int kind = kAbsorb;
    int partner = -1, target = -1;  ///< pair: the other vertex of the pair, the boundary vertex it heads for
    int k = -1;                     ///< hop: the neighbour index of MoveWithPairGeneration
    bool operator<(const Plan& o) const {
      return std::tie(kind, partner, target, k) < std::tie(o.kind, o.partner, o.target, o.k);
    }
  };

  /// One edit tried for a candidate: what it touched and what it changed.
  struct Attempt {
    Plan plan;
    std::vector<int> touched;  ///< every vertex whose valence changed, created or deleted
    int dInterior = 0, dBoundary = 0;
    int absorbedValence = 0;   ///< absorb: 5 or 7
    int steps = 0;             ///< pair: pair steps before the absorption
  };

  bool Frozen(int v) const {
    return frozen_ && v >= 0 && size_t(v) < frozen_->size() && (*frozen_)[size_t(v)];
  }
  signed char Status(int v) const { return v >= 0 && size_t(v) < status_.size() ? status_[size_t(v)] : kRegular; }

  /// The status of a vertex now (corner rule on the boundary). O(valence).
  signed char StatusNow(int v) {
    if (!ed_.IsLive(v)) return kRegular;
    VertexStar<MeshType> s = ed_.Star(v);
    if (s.Valence() == RegularValenceOf(s)) return kRegular;
    return s.boundary ? kBoundary : kInterior;
  }

  /// The per-call pass: every vertex's status, the counts, and the candidates (BFS from the
  /// boundary vertices up to `rings`), nearest first.
  std::vector<int> BuildStatus() {
    ValenceField<MeshType> vf = ComputeValences(m_);
    const size_t n = m_.vert.size();
    status_.assign(n, kRegular);
    interior_ = boundary_ = 0;
    std::vector<int> dist(n, -1), frontier;
    for (size_t i = 0; i < n; ++i) {
      if (m_.vert[i].IsD() || !vf.referenced[i]) continue;
      if (vf.IsIrregular(i)) {
        status_[i] = vf.boundary[i] ? kBoundary : kInterior;
        ++(vf.boundary[i] ? boundary_ : interior_);
      }
      if (vf.boundary[i]) dist[i] = 0, frontier.push_back(int(i));
    }
    std::vector<int> cands;
    for (int r = 1; r <= opt_.rings && !frontier.empty(); ++r) {
      std::vector<int> next;
      for (int v : frontier)
        for (auto* nb : ed_.Star(v).neighbors) {
          const int w = ed_.Index(nb);
          if (dist[size_t(w)] >= 0) continue;
          dist[size_t(w)] = r;
          next.push_back(w);
        }
      std::sort(next.begin(), next.end());  // deterministic
      for (int w : next)
        if (status_[size_t(w)] == kInterior && !Frozen(w)) cands.push_back(w);
      frontier.swap(next);
    }
    return cands;
  }

  /// The edits to try for v: absorb, and each adjacent 5-7 pair it forms toward each target.
  std::vector<Plan> Plans(int v) {
    std::vector<Plan> plans(1);
    const int d = ed_.Valence(v);
    for (auto* nb : ed_.Star(v).neighbors) {
      const int w = ed_.Index(nb);
      if (ed_.InteriorValence(w) != 12 - d || Frozen(w)) continue;
      for (int t : Targets(d == 5 ? v : w, d == 5 ? w : v)) {
        Plan p;
        p.kind = kPair, p.partner = w, p.target = t;
        plans.push_back(p);
      }
    }
    // hop: v one step toward the boundary, onto a neighbour that touches it
    if (!TouchesBoundary(v))
      for (int k = 0; k < d; ++k) {
        AtomicPrediction g = ops_.PredictMoveWithPairGeneration(v, k);
        if (!g || !TouchesBoundary(g.moved)) continue;
        Plan p;
        p.kind = kHop, p.k = k;
        plans.push_back(p);
      }
    return plans;
  }

  /// Tries the edits for v, applies the best that passes the rules, under the guard.
  bool TryCandidate(int v, bool neutral, BoundaryReductionReport& r) {
    Attempt best;
    bool found = false;
    for (const Plan& plan : Plans(v)) {
      // the guard refused it in the first phase: it would again
      if (vetoed_.count(std::make_pair(v, plan))) continue;
      auto cp = ed_.Mark();
      Attempt a;
      ++r.attempts;
      if (Perform(plan, v, a)) {
        Count(a);
        if (Allowed(a, neutral) &&
            (!found || Score(a) < Score(best) || (Score(a) == Score(best) && a.dInterior < best.dInterior)))
          best = a, found = true;
      }
      ed_.RollbackTo(cp);
    }
    if (!found) return false;
    auto cp = ed_.Mark();
    if (guard_.begin) {
      std::vector<int> around;
      for (int t : best.touched)
        if (ed_.IsLive(t)) around.push_back(t);
      guard_.begin(around);
    }
    Attempt a;
    auto drop = [&]() {
      ed_.RollbackTo(cp);
      if (guard_.end) guard_.end(false, a.touched);
      return false;
    };
    bool ok = Perform(best.plan, v, a);  // deterministic: the same edit as the probe
    if (ok) Count(a);
    if (!ok || !Allowed(a, neutral)) return drop();
    if (!guard_.accept || !guard_.accept(a.touched)) {
      vetoed_.insert(std::make_pair(v, best.plan));
      ++r.undone;
      return drop();
    }
    // the guard relaxed: corner angles may have moved; count again on the relaxed mesh
    Count(a);
    if (!Allowed(a, neutral)) {
      ++r.undone;
      return drop();
    }
    Keep(a);
    if (guard_.end) guard_.end(true, a.touched);
    if (a.plan.kind == kHop) {
      ++r.hops;
    } else if (a.plan.kind == kPair) {
      ++r.absorbedPairs;
      if (a.steps > 0) ++r.pairsMoved, r.pairSteps += a.steps;
    } else if (a.absorbedValence == 5) {
      ++r.absorbedV5;
    } else {
      ++r.absorbedV7;
    }
    if (a.dBoundary < 0) r.cancelled += -a.dBoundary;
    if (a.dBoundary > 0) r.boundaryAdded += a.dBoundary;
    return true;
  }

  static int Score(const Attempt& a) { return a.dInterior + a.dBoundary; }

  /// The counting rules of the header, and no frozen vertex touched or next to a touched one.
  bool Allowed(const Attempt& a, bool neutral) {
    // over the limit already (the driver's own edits can raise it), an edit may still lower it
    if (a.dInterior >= 0 || (a.dBoundary > 0 && boundary_ + a.dBoundary > limit_)) return false;
    if (Score(a) > 0 || (!neutral && Score(a) == 0)) return false;
    if (frozen_) {
      for (int t : a.touched)
        if (Frozen(t)) return false;
      for (int x : KRing(m_, Live(a.touched), 1))
        if (Frozen(x)) return false;
    }
    return true;
  }

  std::vector<int> Live(const std::vector<int>& vs) {
    std::vector<int> live;
    for (int v : vs)
      if (ed_.IsLive(v)) live.push_back(v);
    std::sort(live.begin(), live.end());
    live.erase(std::unique(live.begin(), live.end()), live.end());
    return live;
  }

  /// The vertices whose status may have changed: statusRing rings around the live touched
  /// vertices, and the touched ones that are gone.
  std::vector<int> Region(const std::vector<int>& touched) {
    std::vector<int> reg = KRing(m_, Live(touched), opt_.statusRing);
    for (int t : touched)
      if (!ed_.IsLive(t)) reg.push_back(t);
    std::sort(reg.begin(), reg.end());
    reg.erase(std::unique(reg.begin(), reg.end()), reg.end());
    return reg;
  }

  /// dInterior, dBoundary of the edit against the cached status. O(region).
  void Count(Attempt& a) {
    a.dInterior = a.dBoundary = 0;
    for (int v : Region(a.touched)) {
      const signed char before = Status(v), now = StatusNow(v);
      a.dInterior += (now == kInterior) - (before == kInterior);
      a.dBoundary += (now == kBoundary) - (before == kBoundary);
    }
  }

  /// Commits a kept edit to the cached status and counts.
  void Keep(const Attempt& a) {
    for (int v : Region(a.touched)) {
      if (size_t(v) >= status_.size()) status_.resize(size_t(v) + 1, kRegular);
      status_[size_t(v)] = StatusNow(v);
    }
    interior_ += a.dInterior;
    boundary_ += a.dBoundary;
  }

  // ------------------------------------------------------------ the edits
  bool Perform(const Plan& plan, int v, Attempt& a) {
    a.plan = plan;
    if (plan.kind == kAbsorb) {
      a.absorbedValence = ed_.Valence(v);
      BoundaryOutcome o = bops_.Absorb(v);
      if (!o) return false;
      Add(o, a.touched);
      return true;
    }
    if (plan.kind == kHop) return Hop(v, plan.k, a);
    const bool five = ed_.Valence(v) == 5;
    if (!ed_.IsLive(plan.partner) || !ed_.IsLive(plan.target)) return false;
    return MovePairAndAbsorb(five ? v : plan.partner, five ? plan.partner : v, ed_.V(plan.target)->P(), a);
  }

  static void Add(const BoundaryOutcome& o, std::vector<int>& touched) {
    for (auto& kv : o.changes) touched.push_back(kv.first);
    for (int x : {o.absorbed, o.created, o.deleted, o.v5, o.v7})
      if (x >= 0) touched.push_back(x);
  }
  static void Add(const AtomicOutcome& o, std::vector<int>& touched) {
    for (auto& kv : o.changes) touched.push_back(kv.first);
  }

  bool TouchesBoundary(int v) {
    for (auto* nb : ed_.Star(v).neighbors)
      if (ed_.IsBoundary(ed_.Index(nb))) return true;
    return false;
  }

  /// Where a pair may head: the nearest boundary irregular vertices within reach (BFS from the
  /// pair, at most targetsPerPair), and the nearest boundary vertex. Boundary vertices are not
  /// crossed (the pair stays on this side of the hole).
  std::vector<int> Targets(int v5, int v7) {
    const int reach = opt_.rings + opt_.maxTravel + 1;
    std::unordered_map<int, int> dist{{v5, 0}, {v7, 0}};
    std::vector<int> frontier{std::min(v5, v7), std::max(v5, v7)}, targets;
    int anyBoundary = -1;
    for (int r = 1; r <= reach && !frontier.empty() && int(targets.size()) < opt_.targetsPerPair; ++r) {
      std::vector<int> next;
      for (int x : frontier)
        for (auto* nb : ed_.Star(x).neighbors) {
          const int y = ed_.Index(nb);
          if (dist.emplace(y, r).second) next.push_back(y);
        }
      std::sort(next.begin(), next.end());
      for (int y : next) {
        if (Status(y) == kBoundary && int(targets.size()) < opt_.targetsPerPair) targets.push_back(y);
        if (anyBoundary < 0 && ed_.IsBoundary(y)) anyBoundary = y;
      }
      next.erase(std::remove_if(next.begin(), next.end(), [&](int y) { return ed_.IsBoundary(y); }), next.end());
      frontier.swap(next);
    }
    if (anyBoundary >= 0 && std::find(targets.begin(), targets.end(), anyBoundary) == targets.end())
      targets.push_back(anyBoundary);
    return targets;
  }

  /// hop: an interior v5 / v7 two rings from the boundary moves one step onto a neighbour that
  /// touches it, generating an adjacent 5-7 pair (fig. 7, flip form); the generated pair is
  /// carried to the boundary and absorbed whole (pair, first target that works), then the moved
  /// vertex is absorbed. Net: the interior loses the vertex; the boundary takes three defects
  /// (+1 -1 +1 for a v5), which cancel against boundary irregular vertices where they land.
  bool Hop(int v, int k, Attempt& a) {
    a.absorbedValence = ed_.Valence(v);
    AtomicOutcome g = ops_.MoveWithPairGeneration(v, k);
    if (!g) return false;
    for (auto& kv : g.changes)
      if (Frozen(kv.first)) return false;
    Add(g, a.touched);
    RelaxBetween({g.moved, g.pair5, g.pair7});
    const int moved = g.moved;
    bool absorbed = false;
    for (int t : Targets(g.pair5, g.pair7)) {
      auto cp = ed_.Mark();
      Attempt pa;
      if (MovePairAndAbsorb(g.pair5, g.pair7, ed_.V(t)->P(), pa)) {
        a.touched.insert(a.touched.end(), pa.touched.begin(), pa.touched.end());
        a.steps = pa.steps;
        absorbed = true;
        break;
      }
      ed_.RollbackTo(cp);
    }
    if (!absorbed || !ed_.IsLive(moved) || ed_.Valence(moved) != a.absorbedValence) return false;
    BoundaryOutcome o = bops_.Absorb(moved);
    if (!o) return false;
    Add(o, a.touched);
    return true;
  }

  /// pair: the adjacent 5-7 pair (v5, v7) moves by pair steps toward `goal` (dry runs choose
  /// the step: the landing vertices exist before the move) and is absorbed whole by AbsorbPair
  /// as soon as it touches the boundary near the goal.
  bool MovePairAndAbsorb(int v5, int v7, CoordType goal, Attempt& a) {
    auto mid = [&](int x, int y) { return (ed_.V(x)->P() + ed_.V(y)->P()) / 2; };
    a.touched.push_back(v5);
    a.touched.push_back(v7);
    for (int s = 0;; ++s) {
      // absorbed where it touches the boundary near the goal (two edge lengths), not on the way
      // past another stretch of boundary
      const double near = 2.0 * double((ed_.V(v5)->P() - ed_.V(v7)->P()).Norm());
      if ((TouchesBoundary(v5) || TouchesBoundary(v7)) && double((mid(v5, v7) - goal).Norm()) <= near) {
        auto cp = ed_.Mark();
        BoundaryOutcome o = bops_.AbsorbPair(v5, v7);
        if (o) {
          Add(o, a.touched);
          a.steps = s;
          return true;
        }
        ed_.RollbackTo(cp);
      }
      if (s == opt_.maxTravel) return false;
      // the six moves' dry runs: the landing vertices exist before the move, so the step that
      // takes the pair's midpoint closest to the goal is chosen without editing
      std::vector<std::pair<double, int>> order;
      const double here = double((mid(v5, v7) - goal).Norm());
      for (int dir = 0; dir < 6; ++dir) {
        AtomicPrediction p = ops_.PredictMovePair57(v5, v7, dir);
        if (!p) continue;
        bool free = true;
        for (auto& kv : p.changes) free = free && !Frozen(kv.first);
        if (!free) continue;
        const double dd = double((mid(p.pair5, p.pair7) - goal).Norm());
        if (dd < here) order.push_back({dd, dir});
      }
      std::sort(order.begin(), order.end());
      bool moved = false;
      for (auto& od : order) {
        AtomicOutcome o = ops_.MovePair57(v5, v7, od.second);
        if (!o) continue;
        Add(o, a.touched);
        v5 = o.pair5;
        v7 = o.pair7;
        RelaxBetween({v5, v7});
        moved = true;
        break;
      }
      if (!moved) return false;
    }
  }

  /// Relaxation between the steps of one edit: the guard's, or local relaxation of the 2-ring
  /// projected on the input with boundary vertices sliding along the input's boundary. Journaled.
  void RelaxBetween(const std::vector<int>& seeds) {
    if (guard_.relax) {
      guard_.relax(seeds);
      return;
    }
    if (!original_) return;
    std::vector<int> ring, live = Live(seeds);
    if (live.empty()) return;
    for (int x : KRing(m_, live, 2))
      if (!Frozen(x)) ring.push_back(x);
    for (int x : ring) {
      ed_.journal().SaveVertex(ed_.V(x));
      for (auto& c : ed_.Star(x).corners) ed_.journal().SaveFace(c.f);
    }
    RelaxOptions ro;
    ro.iterations = opt_.relaxIterations;
    ro.boundaryCurve = curve_;
    LocalRelax(m_, ring, original_, ro);
  }

  Editor& ed_;
  MeshType& m_;
  const SurfaceProjector* original_;
  BoundaryEditGuard guard_;
  const std::vector<char>* frozen_;
  BoundaryReductionOptions opt_;
  BoundaryOperations<MeshType> bops_;
  AtomicOperations<MeshType> ops_;
  std::unique_ptr<BoundaryCurve> ownCurve_;  ///< built only when the caller gave no boundary
  const BoundaryCurve* curve_;               ///< the input's boundary, for the default relaxation
  int limit_ = 0;
  std::vector<signed char> status_;  ///< per vertex: kRegular, kInterior or kBoundary (irregular)
  int interior_ = 0, boundary_ = 0;  ///< current counts, kept up to date edit by edit
  std::set<std::pair<int, Plan>> vetoed_;  ///< (candidate, edit) the guard refused in this call
};

}  // namespace irregular
}  // namespace vcg_ext
