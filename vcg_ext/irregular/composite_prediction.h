// filter_irregular: dry runs of the composite operations (composite_ops.h; issue 13, item 3).
//
// A composite operation (pair movement, triple / quadruple cancellation, generation) spans
// O(L) elements and its outcome depends on relaxation and fold checks along the way, which
// topology alone cannot tell. So the dry run copies the region the operation can touch - the
// k-ring around the vertices involved and around a shortest edge path between them - into a
// small scratch mesh of the same type, runs the real composite operation there with the same
// options, and maps the result back to the user's indices. The user's mesh is only read.
//
// The region copy is scratch_region.h's ScratchRegion (shared with boundary_ops.h's dry runs).
// Fidelity: the scratch keeps the original's vertex and face order (so "the neighbour of
// smallest index" and every tie-break are the same), its FF adjacency and, for every vertex
// whose whole star is copied, its VF chain. Where the scratch outcome could differ from the
// real one - the operation changed something within `margin` rings of the scratch's cut
// border, or it probed steps there and undid them, or a separatrix trace ran into it - the
// operation runs on the region of radius k and again with the radius doubled (at most twice):
//  * exact = true when two consecutive radii give the same outcome (verdict; on success the
//    same named results, steps, created and deleted vertices) and the larger run left its
//    border rings untouched; the larger run is reported;
//  * otherwise exact = false and the largest run is reported (a guess the caller may verify
//    by applying).
// The refusal text comes from the scratch run: vertex ids inside it are scratch ids; the named
// fields are always the user's ids.
// Cost: O(region) = O(L * k) per prediction, never a pass over the whole mesh.
#pragma once

#include <algorithm>
#include <deque>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "composite_ops.h"
#include "scratch_region.h"

namespace vcg_ext {
namespace irregular {

struct CompositePrediction {
  Result result = Result::Fail("not predicted");  ///< the verdict and, if refused, why
  bool exact = false;          ///< true when the scratch region provably held the whole edit (see header)
  std::vector<int> irregular;  ///< the irregular vertices the operation would leave (user's ids)
  int atomicSteps = 0;         ///< atomic operations it would apply
  int lead = -1, partner = -1;  ///< pair movement: where the lead / partner would end
  int survivor = -1;            ///< triple cancellation: the vertex left; triple generation: the v5/v7
  int pair5 = -1, pair7 = -1;   ///< generation: the generated (moved) 5-7 pair
  int other5 = -1, other7 = -1; ///< quadruple generation: the pair that stays
  std::vector<int> created;     ///< ids new vertices would get (appended after the last vertex)
  std::vector<int> deleted;     ///< existing vertices that would be deleted (collapses)
  int regionVertices = 0;       ///< size of the scratch region used (diagnostics)
  bool grown = false;           ///< the region had to be grown beyond the first doubling
  explicit operator bool() const { return result.ok; }
};

template <class MeshType>
class CompositePredictor {
 public:
  typedef typename MeshType::VertexType VertexType;
  typedef typename MeshType::FaceType FaceType;
  typedef typename MeshType::CoordType CoordType;

  /// m: the user's mesh (FF/VF up to date); only read. original / opt / geometry: exactly what
  /// the real CompositeOperations / MeshEditor would be given.
  CompositePredictor(MeshType& m, const SurfaceProjector* original, CompositeOptions opt = CompositeOptions(),
                     GeometryOptions geometry = GeometryOptions())
      : m_(m), original_(original), opt_(opt), geom_(geometry) {
    opt_.progress = nullptr;
  }

  int margin = 4;  ///< rings next to the cut border whose change makes a run inexact
  /// rings copied beyond the vertices, the paths and the steps requested. 12, not fewer: on the
  /// icosphere one quadruple cancellation gave the same wrong step count with 7 and 14 rings
  /// (a separatrix trace or an undone probe reached further), the right one from 12 rings on.
  int rings = 12;

  /// Dry run of CompositeOperations::MovePair.
  CompositePrediction PredictMovePair(int lead, int partner, int k, int steps) {
    return Run({lead, partner}, {lead, partner}, std::max(0, steps) + rings,
               [&](Ops& co, const Map& s) { return co.MovePair(s(lead), s(partner), k, steps); });
  }
  /// Dry run of CompositeOperations::MoveAdjacentPair57.
  CompositePrediction PredictMoveAdjacentPair57(int v5, int v7, int dir, int steps) {
    return Run({v5, v7}, {v5, v7}, std::max(0, steps) + rings,
               [&](Ops& co, const Map& s) { return co.MoveAdjacentPair57(s(v5), s(v7), dir, steps); });
  }
  /// Dry run of CompositeOperations::MovePair57Toward: the corridor is a greedy walk toward
  /// the target point.
  CompositePrediction PredictMovePair57Toward(int v5, int v7, CoordType target) {
    std::vector<int> seeds{v5, v7};
    if (Live(v5)) {
      int cur = v5;
      for (int s = 0; s < opt_.maxTransportSteps; ++s) {
        int best = -1;
        double bd = (m_.vert[size_t(cur)].P() - target).Norm();
        for (auto n : StarOf<MeshType>(&m_.vert[size_t(cur)]).neighbors) {
          const double d = (n->P() - target).Norm();
          if (d < bd) bd = d, best = int(vcg::tri::Index(m_, n));
        }
        if (best < 0) break;
        seeds.push_back(cur = best);
      }
    }
    return Run(seeds, {v5, v7}, rings, [&](Ops& co, const Map& s) { return co.MovePair57Toward(s(v5), s(v7), target); });
  }
  /// Dry run of CompositeOperations::CancelTriple.
  CompositePrediction PredictCancelTriple(const std::vector<int>& triple) {
    return Run(Corridor(triple), triple, rings, [&](Ops& co, const Map& s) { return co.CancelTriple(s(triple)); });
  }
  /// Dry run of CompositeOperations::CancelQuadruple.
  CompositePrediction PredictCancelQuadruple(const std::vector<int>& quad) {
    return Run(Corridor(quad), quad, rings, [&](Ops& co, const Map& s) { return co.CancelQuadruple(s(quad)); });
  }
  /// Dry run of CompositeOperations::GenerateTriple.
  CompositePrediction PredictGenerateTriple(int v, int k, int spacing) {
    return Run({v}, {v}, std::max(0, spacing) + rings + 1,
               [&](Ops& co, const Map& s) { return co.GenerateTriple(s(v), k, spacing); });
  }
  /// Dry run of CompositeOperations::GenerateQuadruple.
  CompositePrediction PredictGenerateQuadruple(int v, int k, int spacing) {
    return Run({v}, {v}, std::max(0, spacing) + rings + 1,
               [&](Ops& co, const Map& s) { return co.GenerateQuadruple(s(v), k, spacing); });
  }
  /// Dry run of CompositeOperations::GenerateQuadrupleShape.
  CompositePrediction PredictGenerateQuadrupleShape(int v, int k, int dirX, int x, int dirY, int y) {
    return Run({v}, {v}, std::max(0, x) + std::max(0, y) + rings + 1,
               [&](Ops& co, const Map& s) { return co.GenerateQuadrupleShape(s(v), k, dirX, x, dirY, y); });
  }

 private:
  typedef CompositeOperations<MeshType> Ops;

  /// original id -> scratch id (-1 if not in the scratch, which the operations refuse as dead)
  struct Map {
    const std::unordered_map<int, int>* toScratch;
    int operator()(int i) const {
      auto it = toScratch->find(i);
      return it == toScratch->end() ? -1 : it->second;
    }
    std::vector<int> operator()(const std::vector<int>& v) const {
      std::vector<int> r;
      for (int i : v) r.push_back((*this)(i));
      return r;
    }
  };

  typedef ScratchRegion<MeshType> Scratch;

  bool Live(int i) const {
    return i >= 0 && size_t(i) < m_.vert.size() && !m_.vert[size_t(i)].IsD() && m_.vert[size_t(i)].cVFp();
  }

  /// The seeds plus, for every two of them, a shortest edge path (BFS, bounded) and the
  /// connecting path of two separatrix segments (separatrix.h) the transport follows. O(L^2).
  std::vector<int> Corridor(const std::vector<int>& seeds) {
    std::vector<int> out(seeds);
    for (int s : seeds)
      if (!Live(s)) return out;
    for (size_t a = 0; a < seeds.size(); ++a)
      for (size_t b = a + 1; b < seeds.size(); ++b) {
        std::vector<int> p = Path(seeds[a], seeds[b], opt_.maxTransportSteps);
        out.insert(out.end(), p.begin(), p.end());
        // the connecting path of two separatrix segments (sec. 7.1.1) the transport follows
        SeparatrixTracer<MeshType> tracer(m_);
        ConnectingPath c = ConnectByDeepening(tracer, m_, seeds[a], seeds[b], opt_.maxTransportSteps);
        if (c) {
          std::vector<int> cv = c.Vertices();
          out.insert(out.end(), cv.begin(), cv.end());
        }
      }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  std::vector<int> Path(int from, int to, int maxHops) {
    std::unordered_map<int, int> parent{{from, from}}, depth{{from, 0}};
    std::deque<int> q{from};
    while (!q.empty()) {
      const int x = q.front();
      q.pop_front();
      if (x == to) break;
      if (depth[x] >= maxHops) continue;
      for (auto n : StarOf<MeshType>(&m_.vert[size_t(x)]).neighbors) {
        const int ni = int(vcg::tri::Index(m_, n));
        if (parent.emplace(ni, x).second) depth[ni] = depth[x] + 1, q.push_back(ni);
      }
    }
    std::vector<int> p;
    if (!parent.count(to)) return p;
    for (int x = to; x != from; x = parent[x]) p.push_back(x);
    return p;
  }

  /// The scratch copy of the k-ring of `core` (scratch_region.h).
  void Extract(const std::vector<int>& core, int k, Scratch& s) { s.Extract(m_, core, k, margin); }

  int Back(const Scratch& s, int i) const { return s.Back(i); }

  template <class Op>
  CompositePrediction RunOnce(const std::vector<int>& core, int k, Op& op, bool& touchedBorder) {
    Scratch s;
    Extract(core, k, s);
    MeshEditor<MeshType> ed(s.mesh, geom_);
    Ops co(ed, original_, opt_);
    const typename Scratch::GuardState before = s.Guard();
    std::vector<char> liveBefore(s.mesh.vert.size());
    for (size_t i = 0; i < s.mesh.vert.size(); ++i) liveBefore[i] = ed.IsLive(int(i));
    CompositeOutcome o = op(co, Map{&s.toScratch});
    touchedBorder = !(before == s.Guard());
    CompositePrediction p;
    p.result = o.result;
    p.regionVertices = s.n0;
    p.atomicSteps = o.atomicSteps;
    if (!o) return p;
    for (int v : o.irregular) p.irregular.push_back(Back(s, v));
    p.lead = Back(s, o.lead), p.partner = Back(s, o.partner), p.survivor = Back(s, o.survivor);
    p.pair5 = Back(s, o.pair5), p.pair7 = Back(s, o.pair7), p.other5 = Back(s, o.other5), p.other7 = Back(s, o.other7);
    for (size_t i = 0; i < s.mesh.vert.size(); ++i) {
      const bool now = ed.IsLive(int(i));
      if (int(i) >= s.n0) {
        if (now) p.created.push_back(Back(s, int(i)));
      } else if (liveBefore[i] && !now) {
        p.deleted.push_back(Back(s, int(i)));
      }
    }
    return p;
  }

  template <class Op>
  CompositePrediction Run(const std::vector<int>& core, const std::vector<int>& request, int k, Op op) {
    for (int v : request)
      if (!Live(v)) {
        CompositePrediction p;
        p.result = Result::Fail("vertex " + std::to_string(v) + " is not a live vertex of the mesh");
        p.exact = true;
        return p;
      }
    // A run can also reach the cut border without leaving a trace there (steps tried and
    // undone, separatrix tracing), so one run is never trusted alone: the region grows until
    // two consecutive sizes give the same outcome, the larger one with its border untouched.
    bool touched = false;
    CompositePrediction prev = RunOnce(core, k, op, touched);
    int size = std::max(k, 2);
    for (int g = 0; g < 2; ++g) {
      size *= 2;
      bool touchedNext = false;
      CompositePrediction next = RunOnce(core, size, op, touchedNext);
      next.grown = g > 0;
      if (Same(prev, next) && !(next && touchedNext)) {
        next.exact = true;
        return next;
      }
      prev = next;
    }
    prev.exact = false;
    return prev;
  }

  static bool Same(const CompositePrediction& a, const CompositePrediction& b) {
    if (bool(a) != bool(b)) return false;
    if (!a) return true;
    return a.irregular == b.irregular && a.atomicSteps == b.atomicSteps && a.lead == b.lead &&
           a.partner == b.partner && a.survivor == b.survivor && a.pair5 == b.pair5 && a.pair7 == b.pair7 &&
           a.other5 == b.other5 && a.other7 == b.other7 && a.created == b.created && a.deleted == b.deleted;
  }

  MeshType& m_;
  const SurfaceProjector* original_;
  CompositeOptions opt_;
  GeometryOptions geom_;
};

}  // namespace irregular
}  // namespace vcg_ext
