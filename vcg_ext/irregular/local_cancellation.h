// filter_irregular: the local strategies of the automatic reduction (automatic_reduction.h):
//   * type change (sec. 6.3): a vertex of valence <= 4 or >= 8 is split into v5 / v7;
//   * local cancellation: wherever a single flip or collapse removes irregular vertices (an
//     adjacent 5-5-7 / 5-7-7 triple becomes one v5 / v7, an adjacent 5-5-7-7 quadruple
//     disappears: the atomic removals of sec. 6.2), it is applied.
// Every edit goes through the edit guard (edit_guard.h). Preconditions as AutomaticReduction.
#pragma once

#include <algorithm>
#include <map>
#include <vector>

#include "atomic_ops.h"
#include "composite_ops.h"
#include "edit_guard.h"
#include "reduction_options.h"
#include "reduction_state.h"

namespace vcg_ext {
namespace irregular {

template <class MeshType>
class LocalCancellation {
 public:
  typedef MeshEditor<MeshType> Editor;

  LocalCancellation(MeshType& m, Editor& ed, CompositeOperations<MeshType>& comp, EditGuard<MeshType>& guard,
                    ReductionState<MeshType>& state)
      : m_(m), ed_(ed), comp_(comp), ops_(comp.atomic()), guard_(guard), state_(state) {}

  /// Type change (sec. 6.3) of every free vertex of valence <= 4 or >= 8, each guarded.
  /// O(V) scan, O(1) per split.
  void ReduceTypes(ReductionReport& rep) {
    for (size_t i = 0; i < m_.vert.size(); ++i) {
      const int v = int(i);
      if (!state_.IsInteriorIrregular(v) || state_.Frozen(v)) continue;
      const int d = ed_.Valence(v);
      if (d == 5 || d == 7) continue;
      // the split relaxes the 2-ring of the vertices it touches, all within v's 2-ring
      std::vector<int> around = KRing(m_, {v}, 2);
      const std::vector<int> subject{v};
      GuardedEdit<MeshType> g(guard_, rep, around, &subject);
      CompositeOutcome o = comp_.ReduceTo57(v);
      if (o) around.insert(around.end(), o.irregular.begin(), o.irregular.end());
      if (o && g.Accept(around)) ++rep.typeSplits;
      else ++rep.undone;
    }
  }

  /// Applies a removal around v if one exists and keeps it if the guard passes it.
  /// The dry run first: most turns find no removal, and then the guard's measure of the
  /// angles before (GuardedEdit) is not taken (the same edits as FindAndApply under the guard).
  bool CancelAround(ReductionReport& rep, int v) {
    const std::vector<AtomicPrediction> removals = ops_.Candidates(
        {v}, [&](const ValenceChanges& b, const ValenceChanges& a) { return Reduces(b, a); }, "cancellation", false,
        kIrregularForARemoval);
    if (removals.empty()) return false;
    GuardedEdit<MeshType> g(guard_, rep, {v});
    AtomicOutcome o = ops_.ApplyFirst(removals);
    if (!o) return false;
    std::vector<int> touched = state_.Changed(o);
    bool cuts = false;
    GuardVerdict verdict = GuardVerdict::Kept;
    {
      // only positions change until the verdict: the 2-ring is gathered once
      const typename EditGuard<MeshType>::SameTopology sameTopology(guard_);
      // an edit that cuts a crease line is refused before any relaxation: it nearly always
      // fails the guard after relaxation too (fandisk at 20K: 3910 of 3916 routes), and
      // refusing it first saves its relaxation and judging (a third of fandisk's reduction)
      cuts = guard_.CutsCrease(touched);
      if (!cuts) {
        guard_.RelaxAround(touched);
        verdict = g.Verdict(touched);
      }
    }
    if (cuts || verdict != GuardVerdict::Kept) {
      g.Refuse(cuts ? GuardVerdict::Hausdorff : verdict);  // a crease cut counts as the distance's
      ++rep.undone;
      return false;
    }
    g.Keep(touched);
    ++rep.localCancellations;
    return true;
  }

  /// Applies a removal (sec. 6.2) involving one of the vertices, if one exists, and adds what
  /// it changed to touched. Topology only: the caller relaxes and guards (the pair transport
  /// relaxes its whole route once).
  bool RemovalAt(const std::vector<int>& vs, std::vector<int>& touched) {
    if (vs.size() == 2 && LonePair(vs[0], vs[1])) return false;
    for (int x : vs) {
      if (!ed_.IsLive(x)) continue;
      AtomicOutcome c = ops_.FindAndApply(
          {x}, [&](const ValenceChanges& bf, const ValenceChanges& af) { return Reduces(bf, af); },
          "cancellation", false, kIrregularForARemoval);
      if (!c) continue;
      state_.Record(c, touched);
      return true;
    }
    return false;
  }

  /// Count-reducing test for FindAndApply: the operation removes 2 or 4 irregular vertices
  /// among those it touches, leaves only valences 5-7, and touches no frozen vertex nor an
  /// excluded irregular vertex. These are exactly the atomic removals of sec. 6.2 (triple
  /// into one vertex, quadruple).
  bool Reduces(const ValenceChanges& before, const ValenceChanges& after) const {
    int irrBefore = 0, irrAfter = 0;
    for (auto& kv : before) {
      if (state_.Frozen(kv.first)) return false;
      if (kv.second != 6 && std::find(exclude.begin(), exclude.end(), kv.first) != exclude.end()) return false;
      irrBefore += kv.second != 6;
    }
    for (auto& kv : after) {
      if (kv.second == 0) continue;
      if (kv.second < 5 || kv.second > 7) return false;
      irrAfter += kv.second != 6;
    }
    return irrAfter <= irrBefore - 2;
  }

  std::vector<int> exclude;  ///< irregular vertices a removal must not involve (set by a transport)
  /// Reduces passes only a step that removes at least two irregular vertices, so one whose
  /// vertices hold fewer than two is not asked (AtomicOperations::Candidates' minIrregularBefore).
  static constexpr int kIrregularForARemoval = 2;

  /// True if (a, b) is an adjacent 5-7 pair with no other irregular vertex (nor a boundary
  /// vertex) within 2 edges of either: then no removal of RemovalAt({a, b}) exists, so the
  /// search (FindAndApply over the flips and collapses around a and b) can be skipped with the
  /// same answer. Why: those operations change valences only within 2 edges of a or b; a flip
  /// lowers its two ends and raises its two opposite vertices by one, a collapse of w into v
  /// makes v of valence v + w - 4, lowers the two opposite vertices and removes w. With the
  /// pair as the only irregular vertices touched, making both regular would need the 7 lowered
  /// and the 5 raised by a flip (its other end then becomes a v5) or a collapse whose survivor
  /// ends at 6 (from 5 + 7 - 4 = 8, or 6 + d - 4 = d + 2, or 4 + 6 - 4: none is 6 from a 5, 6 or
  /// 7). A lone 5-7 pair is a dislocation: it cannot vanish by itself. An excluded irregular
  /// vertex (`exclude`) does not stop a pair from being lone: Reduces refuses every operation
  /// that touches it, so the operations left touch no irregular vertex but the pair (a
  /// generated pair starts next to the vertex that generated it: this skips the searches of
  /// its first steps, 48,000 of 77,000 on bunny00). Allocation-free walk (the pair step probes
  /// call this after every step), O(2-ring).
  bool LonePair(int a, int b) {
    if (!ed_.IsLive(a) || !ed_.IsLive(b)) return false;
    int va = 0, vb = 0;
    ring_.clear();
    if (!Walk(a, va, &ring_) || !Walk(b, vb, &ring_)) return false;
    if (!((va == 5 && vb == 7) || (va == 7 && vb == 5))) return false;
    const size_t first = ring_.size();
    for (size_t i = 0; i < first; ++i) {
      int d = 0;
      if (ring_[i] == a || ring_[i] == b) continue;
      if (!Walk(ring_[i], d, &ring_) || (d != 6 && !Excluded(ring_[i]))) return false;
    }
    for (size_t i = first; i < ring_.size(); ++i) {
      int d = 0;
      const int y = ring_[i];
      if (y == a || y == b) continue;
      bool seen = false;  // rings of a few dozen vertices: a linear scan beats a set
      for (size_t j = 0; j < i && !seen; ++j) seen = ring_[j] == y;
      if (!seen && (!Walk(y, d, nullptr) || (d != 6 && !Excluded(y)))) return false;
    }
    return true;
  }

 private:
  MeshType& m_;
  Editor& ed_;
  CompositeOperations<MeshType>& comp_;
  AtomicOperations<MeshType>& ops_;
  EditGuard<MeshType>& guard_;
  ReductionState<MeshType>& state_;
  std::vector<int> ring_;  ///< LonePair's buffer, reused across calls

  bool Excluded(int v) const { return std::find(exclude.begin(), exclude.end(), v) != exclude.end(); }

  /// Valence of interior vertex v by walking its faces counter-clockwise (no allocation);
  /// appends its neighbours to *out if given. False on a boundary or broken fan.
  bool Walk(int v, int& valence, std::vector<int>* out) {
    typedef typename MeshType::FaceType FaceType;
    auto* vp = ed_.V(v);
    if (vp->cVFp() == nullptr) return false;
    const Corner<FaceType> start{vp->VFp(), vp->VFi()};
    Corner<FaceType> c = start;
    valence = 0;
    do {
      if (out) out->push_back(ed_.Index(c.f->V((c.z + 1) % 3)));
      c = NextCornerCCW(c);
      if (c.f == nullptr || ++valence > 64) return false;
    } while (c.f != start.f || c.z != start.z);
    return true;
  }
};

}  // namespace irregular
}  // namespace vcg_ext
