// filter_irregular: operations that let irregular vertices leave or enter a mesh through its
// boundary (issue 13, item 4), built from the boundary graph operations of graph_ops.h.
//
// Derivation (sec. 6.1 valence rules, applied to the surface closed by a cone vertex over each
// boundary loop; docs/boundary_operations.svg draws them). On a smooth stretch of boundary a
// vertex is regular at valence 4 (topology.h, the boundary valence rule), so a boundary v3
// carries the defect of a v5 and a boundary v5 that of a v7; eq. 2 counts both. Two graph
// operations move one unit of defect between the inside and the boundary, and nothing else:
//
//   (A) boundary-edge collapse u -> w, apex c (the face (u, w, c)):
//         w: d(u) + d(w) - 3,  c: d(c) - 1.
//       With u, w regular (4, 4): w becomes 5 (a boundary "v7") and c loses one.
//       So an interior v7 at c becomes regular and its defect moves onto the boundary at w.
//       With u a boundary v3: w = 3 + 4 - 3 = 4, the boundary irregularity is cancelled.
//   (B) boundary split of w along its interior edge to c (graph_ops.h SplitBoundary; w's fan
//       nb[0..n], c = nb[i]):  w: i + 2,  new x: n - i + 2,  c: d(c) + 1.
//       With w regular (n = 3) and c a v5: c becomes 6 and one of w, x is a boundary v3 (the
//       v5 has left the inside through the boundary). With w a boundary v5 (n = 4) and i = 2:
//       w and x are both 4, so the v5 cancels the boundary v7.
//
// The operations below compose (A) and (B):
//   Absorb(v)        an interior v5 next to the boundary: (B) at a boundary neighbour b of v
//                    (b chosen so that the fewest boundary vertices end irregular: a boundary
//                    v5 is cancelled when there is one); an interior v7 that is the apex of a
//                    boundary edge: (A) on that edge (a boundary v3 end is cancelled first).
//   AbsorbPair(5, 7) an adjacent interior 5-7 pair next to the boundary: Absorb of the 7 by
//                    (A), then Absorb of the 5 by (B) (or the other order if that one is
//                    blocked). Its defects (+1, -1) land on the boundary: if they meet a
//                    boundary v5 and v3 there, both cancel and nothing irregular is left;
//                    on a smooth regular stretch they stay as a boundary 5-7 pair (valences
//                    3 and 5, adjacent): (A) puts the apex in the middle of the survivor's
//                    fan, so (B) there cannot split it into 4 + 4. In a lattice this is a
//                    dislocation leaving through the boundary as a step; the boundary rule
//                    counts the step regular only where the boundary is kinked (120 / 240).
//   MoveAlongBoundary(b, side)  a boundary v3 b on a smooth stretch (boundary neighbours p
//                    on `side`, c on the other, interior neighbour a) moves towards p: (A)
//                    collapses b into c (c: 3 + 4 - 3 = 4, the v3 is gone, a becomes an
//                    interior v5), then (B) splits p along its edge to a (a: 6 again), and
//                    the half of p next to c is the boundary v3. The vertex count is kept.
//   GeneratePair(b, side)  a regular boundary vertex b (valence 4, fan nb[0..3]) emits an
//                    interior 5-7 pair by one flip of its interior edge (b, y), y = nb[1] for
//                    side 0, nb[2] for side 1 (opposites: the boundary neighbour o_b and the
//                    interior o_i): y 6 -> 5 and o_i 6 -> 7 are the pair (adjacent), b 4 -> 3
//                    and o_b 4 -> 5 the boundary 5-7 pair it leaves behind. AbsorbPair of
//                    the new pair cancels both again.
//
// Dry runs. Predict*() runs the operation under the journal and rolls it back (the result
// is then exact by construction, and costs the same O(1) local work); the graph-level Can*
// of graph_ops.h are the topological dry runs each step goes through.
// All operations are all-or-nothing (journal.h). Outcomes name their vertices.
#pragma once

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "graph_ops.h"
#include "topology.h"

namespace vcg_ext {
namespace irregular {

/// What a boundary operation did (or, from Predict*, would do). Vertex indices are those of
/// the mesh during the edit (a collapse deletes, a split appends).
struct BoundaryOutcome {
  Result result;
  std::string description;
  int absorbed = -1;       ///< the interior vertex that became regular (Absorb), or -1
  int boundaryVertex = -1; ///< the first of boundaryIrregular, -1 if none
  std::vector<int> boundaryIrregular;  ///< touched boundary vertices irregular afterwards (boundary valence rule)
  int v5 = -1, v7 = -1;    ///< the pair absorbed (AbsorbPair) or generated (GeneratePair)
  int created = -1;        ///< vertex added by a boundary split, or -1
  int deleted = -1;        ///< vertex removed by a boundary-edge collapse, or -1
  std::map<int, int> changes;  ///< valence after the edit of every touched vertex (0: deleted)
  explicit operator bool() const { return result.ok; }
};

template <class MeshType>
class BoundaryOperations {
 public:
  typedef MeshEditor<MeshType> Editor;

  explicit BoundaryOperations(Editor& ed) : ed_(ed) {}

  BoundaryOutcome PredictAbsorb(int v) { return Trial([&] { return Absorb(v); }); }
  BoundaryOutcome PredictAbsorbPair(int p5, int p7) { return Trial([&] { return AbsorbPair(p5, p7); }); }
  BoundaryOutcome PredictMoveAlongBoundary(int b, int side) {
    return Trial([&] { return MoveAlongBoundary(b, side); });
  }
  BoundaryOutcome PredictGeneratePair(int b, int side) { return Trial([&] { return GeneratePair(b, side); }); }

  /// Absorb an interior v5 or v7 next to the boundary (header: (A), (B)).
  BoundaryOutcome Absorb(int v) {
    BoundaryOutcome out;
    if (!ed_.IsLive(v)) return Fail(out, "vertex " + S(v) + " does not exist");
    VertexStar<MeshType> st = ed_.Star(v);
    if (st.boundary) return Fail(out, "vertex " + S(v) + " already lies on the boundary");
    const int d = st.Valence();
    if (d == 5) return AbsorbV5(v, out);
    if (d == 7) return AbsorbV7(v, out);
    return Fail(out, "only an interior v5 or v7 can be absorbed into the boundary; vertex " + S(v) +
                         " has valence " + S(d));
  }

  /// Absorb an adjacent interior 5-7 pair next to the boundary; nothing irregular is left
  /// where the configuration allows it (header).
  BoundaryOutcome AbsorbPair(int p5, int p7) {
    BoundaryOutcome out;
    if (!ed_.IsLive(p5) || !ed_.IsLive(p7)) return Fail(out, "a vertex of the pair does not exist");
    if (ed_.Valence(p5) == 7 && ed_.Valence(p7) == 5) std::swap(p5, p7);
    if (ed_.IsBoundary(p5) || ed_.IsBoundary(p7)) return Fail(out, "the pair must be interior");
    if (ed_.Valence(p5) != 5 || ed_.Valence(p7) != 7 || !ed_.Adjacent(p5, p7))
      return Fail(out, "a 5-7 pair is an interior v5 and an interior v7 joined by an edge");
    auto cp = ed_.Mark();
    for (int order = 0; order < 2; ++order) {
      BoundaryOutcome a = Absorb(order == 0 ? p7 : p5);
      BoundaryOutcome b = a ? Absorb(order == 0 ? p5 : p7) : a;
      if (a && b) {
        out.v5 = p5;
        out.v7 = p7;
        out.absorbed = -1;
        out.created = a.created >= 0 ? a.created : b.created;
        out.deleted = a.deleted >= 0 ? a.deleted : b.deleted;
        out.changes = a.changes;
        for (auto& kv : b.changes) out.changes[kv.first] = kv.second;
        SetBoundaryIrregular(out, Keys(out.changes));
        out.description = "absorbed the 5-7 pair (" + S(p5) + ", " + S(p7) + "): " + a.description + "; " +
                          b.description;
        return out;
      }
      ed_.RollbackTo(cp);
      out.result = a ? b.result : a.result;
    }
    return Fail(out, "the 5-7 pair (" + S(p5) + ", " + S(p7) + ") cannot be absorbed here: " + out.result.reason);
  }

  /// Move a boundary v3 on a smooth stretch one vertex along the boundary; side 0 towards
  /// its first boundary neighbour (the fan's start), 1 towards the other.
  BoundaryOutcome MoveAlongBoundary(int b, int side) {
    BoundaryOutcome out;
    if (!ed_.IsLive(b)) return Fail(out, "vertex " + S(b) + " does not exist");
    VertexStar<MeshType> st = ed_.Star(b);
    if (!st.boundary) return Fail(out, "vertex " + S(b) + " does not lie on the boundary");
    if (st.Valence() != 3 || IsBoundaryCorner(CornerAngleDeg(st)))
      return Fail(out, "only a boundary vertex of valence 3 on a smooth stretch of boundary (a boundary v5) moves "
                       "along the boundary; vertex " + S(b) + " has valence " + S(st.Valence()) +
                       (IsBoundaryCorner(CornerAngleDeg(st)) ? " at a corner" : ""));
    // p: the boundary neighbour it moves towards; c: the other one; apex: the interior
    // neighbour (the apex of both boundary edges of b).
    const int p = ed_.Index(side == 0 ? st.neighbors.front() : st.neighbors.back());
    const int c = ed_.Index(side == 0 ? st.neighbors.back() : st.neighbors.front());
    const int apex = ed_.Index(st.neighbors[1]);
    auto cp = ed_.Mark();
    std::map<int, int> before = Ring({b, c, p, apex});
    Result r = ed_.Collapse(b, c);  // (A): c: 3 + 4 - 3 = 4, the apex becomes an interior v5
    if (!r) return Fail(out, "the boundary v3 at " + S(b) + " cannot be collapsed into " + S(c) + ": " + r.reason);
    int created = -1;
    Result s = ed_.SplitBoundary(p, apex, &created);  // (B) at p: the v5 leaves again, on p's side
    if (!s) {
      ed_.RollbackTo(cp);
      return Fail(out, "moving the boundary v3 at " + S(b) + " along the boundary: " + s.reason);
    }
    out.deleted = b;
    out.created = created;
    out.changes = Changes(before, {created});
    SetBoundaryIrregular(out, {p, created, c});
    out.description = "moved the boundary v3 from vertex " + S(b) + " along the boundary (collapse into " + S(c) +
                      ", split of " + S(p) + " along the edge to " + S(apex) + ")";
    return out;
  }

  /// Generate an interior 5-7 pair from the regular boundary vertex b (valence 4 on a smooth
  /// stretch) by flipping its interior edge nb[1] (side 0) or nb[2] (side 1); header.
  BoundaryOutcome GeneratePair(int b, int side) {
    BoundaryOutcome out;
    if (!ed_.IsLive(b)) return Fail(out, "vertex " + S(b) + " does not exist");
    VertexStar<MeshType> st = ed_.Star(b);
    if (!st.boundary) return Fail(out, "vertex " + S(b) + " does not lie on the boundary");
    if (st.Valence() != 4 || IsBoundaryCorner(CornerAngleDeg(st)))
      return Fail(out, "a pair is generated from a regular boundary vertex (valence 4 on a smooth stretch); vertex " +
                           S(b) + " has valence " + S(st.Valence()) +
                           (IsBoundaryCorner(CornerAngleDeg(st)) ? " at a corner" : ""));
    const int y = ed_.Index(st.neighbors[side == 0 ? 1 : 2]);
    const int oi = ed_.Index(st.neighbors[side == 0 ? 2 : 1]);
    const int ob = ed_.Index(side == 0 ? st.neighbors[0] : st.neighbors[3]);
    if (ed_.IsBoundary(y) || ed_.IsBoundary(oi) || ed_.Valence(y) != 6 || ed_.Valence(oi) != 6)
      return Fail(out, "the interior neighbours of boundary vertex " + S(b) +
                           " must be regular interior vertices to take the new pair");
    std::map<int, int> before = Ring({b, y});
    Result r = ed_.Flip(b, y);
    if (!r) return Fail(out, "generating a pair at boundary vertex " + S(b) + ": " + r.reason);
    out.v5 = y;
    out.v7 = oi;
    out.changes = Changes(before, {});
    SetBoundaryIrregular(out, {b, ob});
    out.description = "generated the 5-7 pair (" + S(y) + ", " + S(oi) + ") from boundary vertex " + S(b) +
                      " (flip of edge (" + S(b) + ", " + S(y) + "))";
    return out;
  }

 private:
  static std::string S(long long x) { return std::to_string(x); }

  static BoundaryOutcome Fail(BoundaryOutcome& out, const std::string& why) {
    out.result = Result::Fail(why);
    return out;
  }

  template <class F>
  BoundaryOutcome Trial(F f) {
    auto cp = ed_.Mark();
    BoundaryOutcome o = f();
    ed_.RollbackTo(cp);
    return o;
  }

  /// Valences of the given vertices and their 1-rings, to report what changed.
  std::map<int, int> Ring(const std::vector<int>& vs) {
    std::map<int, int> r;
    for (int v : vs) {
      if (!ed_.IsLive(v)) continue;
      r[v] = ed_.Valence(v);
      for (auto* n : ed_.Star(v).neighbors) r[ed_.Index(n)] = ed_.Valence(ed_.Index(n));
    }
    return r;
  }
  std::map<int, int> Changes(const std::map<int, int>& before, const std::vector<int>& extra) {
    std::map<int, int> ch;
    for (auto& kv : before) {
      const int now = ed_.IsLive(kv.first) ? ed_.Valence(kv.first) : 0;
      if (now != kv.second) ch[kv.first] = now;
    }
    for (int v : extra)
      if (v >= 0 && ed_.IsLive(v)) {
        auto it = before.find(v);
        if (it == before.end() || it->second != ed_.Valence(v)) ch[v] = ed_.Valence(v);
      }
    return ch;
  }
  /// Records which of vs (live boundary vertices) are irregular by the boundary valence rule.
  void SetBoundaryIrregular(BoundaryOutcome& out, const std::vector<int>& vs) {
    out.boundaryIrregular.clear();
    for (int v : vs) {
      if (v < 0 || !ed_.IsLive(v)) continue;
      VertexStar<MeshType> s = ed_.Star(v);
      if (s.boundary && s.Valence() != RegularValenceOf(s) &&
          std::find(out.boundaryIrregular.begin(), out.boundaryIrregular.end(), v) == out.boundaryIrregular.end())
        out.boundaryIrregular.push_back(v);
    }
    out.boundaryVertex = out.boundaryIrregular.empty() ? -1 : out.boundaryIrregular.front();
  }
  std::vector<int> Keys(const std::map<int, int>& ch) {
    std::vector<int> k;
    for (auto& kv : ch) k.push_back(kv.first);
    return k;
  }

  /// (B) at the boundary neighbour of v whose halves end closest to regular (4 each).
  BoundaryOutcome AbsorbV5(int v, BoundaryOutcome& out) {
    VertexStar<MeshType> st = ed_.Star(v);
    int best = -1, bestScore = 1 << 30;
    for (auto* n : st.neighbors) {
      const int b = ed_.Index(n);
      VertexStar<MeshType> sb = ed_.Star(b);
      if (!sb.boundary) continue;
      const int nc = int(sb.corners.size()), i = sb.IndexOf(ed_.V(v));
      const int score = std::abs(i + 2 - 4) + std::abs(nc - i + 2 - 4);
      if (ed_.CanSplitBoundary(b, v) && score < bestScore) best = b, bestScore = score;
    }
    if (best < 0) return Fail(out, "vertex " + S(v) + " is not next to the boundary (no neighbour on it)");
    std::map<int, int> before = Ring({v, best});
    int created = -1;
    Result r = ed_.SplitBoundary(best, v, &created);
    if (!r) return Fail(out, "absorbing v5 " + S(v) + " at boundary vertex " + S(best) + ": " + r.reason);
    out.absorbed = v;
    out.created = created;
    out.changes = Changes(before, {created});
    SetBoundaryIrregular(out, {best, created});
    out.description = "absorbed v5 " + S(v) + " into the boundary (split of boundary vertex " + S(best) + ")";
    return out;
  }

  /// (A) on a boundary edge whose apex is v; an end that is a boundary v3 is the one removed.
  BoundaryOutcome AbsorbV7(int v, BoundaryOutcome& out) {
    VertexStar<MeshType> st = ed_.Star(v);
    const int d = st.Valence();
    int bu = -1, bw = -1;
    for (int k = 0; k < d && bu < 0; ++k) {
      const int x = ed_.Index(st.neighbors[size_t(k)]), y = ed_.Index(st.neighbors[size_t((k + 1) % d)]);
      if (!ed_.IsBoundaryEdge(x, y)) continue;
      // remove the end that is irregular (a boundary v3 cancels), else the first
      const bool yFirst = ed_.Valence(y) == 3 && ed_.Valence(x) != 3;
      for (int t = 0; t < 2 && bu < 0; ++t) {
        const int u = (t == 0) == yFirst ? y : x, w = u == x ? y : x;
        if (ed_.CanCollapse(u, w)) bu = u, bw = w;
      }
    }
    if (bu < 0) return Fail(out, "v7 " + S(v) + " is not the apex of a boundary edge that can be collapsed");
    std::map<int, int> before = Ring({v, bu, bw});
    Result r = ed_.Collapse(bu, bw);
    if (!r) return Fail(out, "absorbing v7 " + S(v) + " by collapsing boundary edge (" + S(bu) + ", " + S(bw) + "): " +
                                 r.reason);
    out.absorbed = v;
    out.deleted = bu;
    out.changes = Changes(before, {});
    SetBoundaryIrregular(out, {bw});
    out.description = "absorbed v7 " + S(v) + " into the boundary (collapse of boundary edge (" + S(bu) + ", " +
                      S(bw) + "))";
    return out;
  }

  Editor& ed_;
};

}  // namespace irregular
}  // namespace vcg_ext
