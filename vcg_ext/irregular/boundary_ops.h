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
//                    By connectivity this is a renaming: the result is the same triangulation
//                    with the new vertex in the deleted one's place (or p in it and the new
//                    vertex in p's); only positions change, the v3 slides along the boundary
//                    polyline (test MoveAlongBoundaryIsARenamingOfTheConnectivity). A single
//                    boundary irregular vertex cannot move through the lattice on its own, as
//                    a single v5 cannot inside (sec. 5); a boundary pair can (below).
//   GeneratePair(b, side)  a regular boundary vertex b (valence 4, fan nb[0..3]) emits an
//                    interior 5-7 pair by one flip of its interior edge (b, y), y = nb[1] for
//                    side 0, nb[2] for side 1 (opposites: the boundary neighbour o_b and the
//                    interior o_i): y 6 -> 5 and o_i 6 -> 7 are the pair (adjacent), b 4 -> 3
//                    and o_b 4 -> 5 the boundary 5-7 pair it leaves behind. AbsorbPair of
//                    the new pair cancels both again.
//   MoveBoundaryPair(a, b, toward, steps)  a boundary 5-7 pair: two boundary vertices joined
//                    by a boundary edge on a smooth stretch, x of valence 3 and y of valence 5
//                    (deviations -1 and +1 from the regular 4; what GeneratePair and AbsorbPair
//                    leave). In a lattice it is a one-edge kink of the boundary (a 120 and a 240
//                    degree corner) that the boundary shape does not account for; it moves
//                    along the boundary like a 5-7 pair inside (fig. 6), one graph operation per
//                    step (docs/boundary_pair_move.svg), with p, x, y, q consecutive on the
//                    boundary and a the single interior neighbour (apex) of x:
//     towards the 3 (C): collapse the apex a (an interior v6) into x, which stays where it is
//                    (an interior edge into a boundary vertex, sec. 6.1: x: d(a) + 3 - 4 = 5;
//                    the opposites p, y: -1). The pair is now (p, x): one step towards p.
//                    p = 5 before (a boundary v7 there): p ends at 4, the pair has cancelled it
//                    and x (5) is what is left.
//     towards the 5 (E): the ear split of y, the inverse of (C): a new boundary vertex e takes
//                    y's place between x and q with the two faces (x, y, e), (y, q, e); y
//                    becomes interior (5 + 1 = 6), e has valence 3, x and q: +1. The pair is
//                    now (e, q). q = 3 before: q ends at 4 and e (3) is what is left.
//     meeting a pair of opposite sign, both cancel and nothing is left:
//       q5' p3' x3 y5, towards p (a bump): (A) collapses x into p (p: 3 + 3 - 3 = 3, a: 6 -> 5),
//                    then (C) collapses a into p (p: 5 + 3 - 4 = 4, q', y: 5 -> 4).
//       x3 y5 q5' r3', towards q (a notch): (E) at y (x: 4, e: 3, q: 6), (E) at q (e: 4,
//                    e': 3, r: 4, q: interior 7), then (A) collapses e' into r (r: 3 + 4 - 3 = 4,
//                    its apex q: 7 -> 6).
//                    Eq. 2 is kept by each step: it counts every boundary vertex against 4.
//   GenerateBoundaryPairs(b)  the inverse of the bump cancellation: (E) at a regular boundary
//                    vertex b (b: interior 5, e: 3, its boundary neighbours n0, nn: 5), then (B)
//                    splits e along its edge to b (e and the new e': 3 each, b: 6). Left: two
//                    boundary pairs of opposite sign, n0 5 - e 3 and e' 3 - nn 5 (a one-row bump),
//                    nothing irregular inside.
//   EarSplit(y)      (E) on its own: the graph operation the paper's three do not cover (it
//                    adds one vertex and two faces at the boundary, the inverse of collapsing
//                    an interior vertex into a boundary vertex of valence 3).
//
// Dry runs (issue 13, item 3). Predict*() copies the few rings the operation can reach - the
// (steps + scratchRings)-ring of the vertices named - into a scratch mesh (scratch_region.h,
// shared with composite_prediction.h), runs the real operation there with the same geometry
// options and maps the outcome back to the user's ids (created vertices get the ids the real
// operation would append, deleted ones their own; numbers in the reason and description that
// are vertex ids are renamed too). The user's mesh is only read; its journal logs nothing.
// The scratch's cut border looks like a mesh boundary to these operations, so a run is trusted
// only when it agrees with a run on twice the radius and left the border's scratchMargin rings
// untouched (exact = true); otherwise the largest of three radii is reported, exact = false.
// Cost O((steps + scratchRings)^2) per prediction, never a pass over the whole mesh. The
// graph-level Can* of graph_ops.h are the topological dry runs each step goes through.
// All operations are all-or-nothing (journal.h). Outcomes name their vertices.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "graph_ops.h"
#include "scratch_region.h"
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
  bool exact = false;  ///< Predict*: two scratch radii agreed and the run stayed clear of the cut border (header)
  explicit operator bool() const { return result.ok; }
};

/// Which way MoveBoundaryPair moves a boundary 5-7 pair.
enum class BoundaryPairDirection { TowardThree = 0, TowardFive = 1 };

/// What MoveBoundaryPair did (or, from its Predict, would do). Vertex indices as in
/// BoundaryOutcome.
struct BoundaryPairOutcome {
  Result result;
  std::string description;
  int v3 = -1, v5 = -1;   ///< the boundary pair where it ended (valences 3 and 5); -1 if cancelled
  int survivor = -1;      ///< cancelled against one boundary irregular vertex: the one left, else -1
  bool cancelled = false; ///< the pair met a boundary irregular vertex or pair of opposite sign
  int steps = 0;          ///< steps made (a cancellation is the last one)
  int other3 = -1, other5 = -1;  ///< GenerateBoundaryPairs: the second pair (the first is v3, v5)
  std::vector<int> created;  ///< vertices added by ear splits (E)
  std::vector<int> deleted;  ///< vertices removed by collapses (A), (C)
  std::map<int, int> changes;  ///< valence after the edit of every touched vertex (0: deleted)
  std::vector<int> boundaryIrregular;  ///< touched boundary vertices irregular afterwards
  bool exact = false;  ///< Predict*: two scratch radii agreed and the run stayed clear of the cut border (header)
  explicit operator bool() const { return result.ok; }
};

template <class MeshType>
class BoundaryOperations {
 public:
  typedef MeshEditor<MeshType> Editor;

  explicit BoundaryOperations(Editor& ed) : ed_(ed) {}

  /// Dry runs (header): each one runs the operation on a scratch copy of the rings around the
  /// vertices involved (scratch_region.h) and says what it would do, in the user's ids; the
  /// user's mesh is only read and the editor's journal logs nothing.
  BoundaryOutcome PredictAbsorb(int v) {
    return OnScratch<BoundaryOutcome>({v}, {v}, 0, [&](BoundaryOperations& o, const Region* r) { return o.Absorb(To(r, v)); });
  }
  BoundaryOutcome PredictAbsorbPair(int p5, int p7) {
    return OnScratch<BoundaryOutcome>({p5, p7}, {p5, p7}, 0, [&](BoundaryOperations& o, const Region* r) {
      return o.AbsorbPair(To(r, p5), To(r, p7));
    });
  }
  BoundaryOutcome PredictMoveAlongBoundary(int b, int side) {
    return OnScratch<BoundaryOutcome>({b}, {b}, 1, [&](BoundaryOperations& o, const Region* r) {
      return o.MoveAlongBoundary(To(r, b), side);
    });
  }
  BoundaryOutcome PredictGeneratePair(int b, int side) {
    return OnScratch<BoundaryOutcome>({b}, {b}, 0, [&](BoundaryOperations& o, const Region* r) {
      return o.GeneratePair(To(r, b), side);
    });
  }
  BoundaryPairOutcome PredictMoveBoundaryPair(int a, int b, BoundaryPairDirection toward, int steps) {
    // steps < 1 is refused before anything is edited: OnScratch then asks the user's editor
    return OnScratch<BoundaryPairOutcome>(steps < 1 ? std::vector<int>{-1} : std::vector<int>{a, b}, {a, b}, steps,
                                          [&](BoundaryOperations& o, const Region* r) {
                                            return o.MoveBoundaryPair(To(r, a), To(r, b), toward, steps);
                                          });
  }

  /// Rings copied around the vertices of a dry run beyond its steps (the operations read and
  /// edit at most two rings around each step; the rest keeps the cut border out of reach).
  int scratchRings = 6;
  /// Rings next to the scratch's cut border whose change makes a dry run inexact.
  int scratchMargin = 2;

  /// Moves the boundary 5-7 pair (a, b) (header: two boundary vertices joined by a boundary
  /// edge, valences 3 and 5, both irregular by the boundary valence rule) `steps` steps along
  /// the boundary towards its valence-3 vertex or its valence-5 vertex; where it meets a
  /// boundary irregular vertex or pair of opposite sign it cancels (header) and stops there.
  /// O(steps). All or nothing.
  BoundaryPairOutcome MoveBoundaryPair(int a, int b, BoundaryPairDirection toward, int steps) {
    BoundaryPairOutcome out;
    const auto cp = ed_.Mark();
    auto fail = [&](const std::string& why) {
      ed_.RollbackTo(cp);
      out = BoundaryPairOutcome();
      out.result = Result::Fail(why);
      return out;
    };
    if (steps < 1) return fail("the number of steps must be at least 1");
    if (!ed_.IsLive(a) || !ed_.IsLive(b)) return fail("a vertex of the boundary pair does not exist");
    if (ed_.Valence(a) == 5 && ed_.Valence(b) == 3) std::swap(a, b);
    if (!ed_.IsBoundary(a) || !ed_.IsBoundary(b) || !ed_.IsBoundaryEdge(a, b) || ed_.Valence(a) != 3 ||
        ed_.Valence(b) != 5)
      return fail("a boundary 5-7 pair is two boundary vertices joined by a boundary edge, of valence 3 and 5; "
                  "vertices " + S(a) + " and " + S(b) + " have valence " + S(ed_.Valence(a)) + " and " +
                  S(ed_.Valence(b)) + (ed_.IsBoundaryEdge(a, b) ? "" : " and are not joined by a boundary edge"));
    for (int v : {a, b}) {
      VertexStar<MeshType> st = ed_.Star(v);
      if (RegularValenceOf(st) != 4)
        return fail("boundary vertex " + S(v) + " lies at a corner (regular valence " + S(RegularValenceOf(st)) +
                    "): the pair must lie on a smooth stretch of boundary, where it is irregular");
    }
    int x = a, y = b;  // x: the 3, y: the 5
    std::map<int, int> before;
    std::string log;
    for (int s = 0; s < steps && !out.cancelled; ++s) {
      Result r = toward == BoundaryPairDirection::TowardThree ? StepTowardThree(out, before, x, y, log)
                                                              : StepTowardFive(out, before, x, y, log);
      if (!r) return fail("step " + S(s + 1) + " of " + S(steps) + ": " + r.reason);
      ++out.steps;
    }
    out.v3 = out.cancelled ? -1 : x;
    out.v5 = out.cancelled ? -1 : y;
    out.changes = Changes(before, out.created);
    std::vector<int> touched = Keys(out.changes);
    SetBoundaryIrregularList(out.boundaryIrregular, touched);
    out.description = "moved the boundary 5-7 pair (" + S(a) + ", " + S(b) + ") " + S(out.steps) +
                      (out.steps == 1 ? " step" : " steps") + " towards its valence-" +
                      (toward == BoundaryPairDirection::TowardThree ? "3" : "5") + " vertex" + log +
                      (out.cancelled ? (out.survivor >= 0 ? "; it cancelled against the boundary irregular vertex it "
                                                            "met, leaving vertex " + S(out.survivor)
                                                          : "; it cancelled against the boundary pair it met")
                                     : "; it is now (" + S(x) + ", " + S(y) + ")");
    out.result = Result::Ok();
    return out;
  }

  BoundaryPairOutcome PredictGenerateBoundaryPairs(int b) {
    return OnScratch<BoundaryPairOutcome>({b}, {b}, 1, [&](BoundaryOperations& o, const Region* r) {
      return o.GenerateBoundaryPairs(To(r, b));
    });
  }

  /// Two boundary pairs of opposite sign from the regular boundary vertex b (header).
  /// out.v3, out.v5: the pair on the side of b's last boundary neighbour; out.other3,
  /// out.other5: the one on the side of its first.
  BoundaryPairOutcome GenerateBoundaryPairs(int b) {
    BoundaryPairOutcome out;
    if (!ed_.IsLive(b)) return FailPair(out, "vertex " + S(b) + " does not exist");
    VertexStar<MeshType> st = ed_.Star(b);
    if (!st.boundary) return FailPair(out, "vertex " + S(b) + " does not lie on the boundary");
    if (st.Valence() != 4 || RegularValenceOf(st) != 4)
      return FailPair(out, "boundary pairs are generated from a regular boundary vertex (valence 4 on a smooth "
                           "stretch); vertex " + S(b) + " has valence " + S(st.Valence()) +
                           (RegularValenceOf(st) != 4 ? " at a corner" : ""));
    const int n0 = ed_.Index(st.neighbors.front()), nn = ed_.Index(st.neighbors.back());
    if (ed_.Valence(n0) != 4 || ed_.Valence(nn) != 4)
      return FailPair(out, "the boundary neighbours of vertex " + S(b) + " must be regular (valence 4)");
    const auto cp = ed_.Mark();
    std::map<int, int> before;
    Remember(before, {b, n0, nn}, {});
    int e = -1, e2 = -1;
    Result r = EarSplit(b, &e);
    if (r) r = ed_.SplitBoundary(e, b, &e2);
    if (!r) {
      ed_.RollbackTo(cp);
      return FailPair(out, "generating boundary pairs at vertex " + S(b) + ": " + r.reason);
    }
    out.created = {e, e2};
    // e keeps its fan's start, e2 its end: find which boundary neighbour of b each one meets
    const int nearLast = ed_.Adjacent(e2, nn) ? e2 : e, nearFirst = nearLast == e2 ? e : e2;
    out.v3 = nearLast;
    out.v5 = nn;
    out.other3 = nearFirst;
    out.other5 = n0;
    out.changes = Changes(before, out.created);
    SetBoundaryIrregularList(out.boundaryIrregular, Keys(out.changes));
    out.steps = 1;
    out.description = "generated the boundary pairs (" + S(n0) + ", " + S(nearFirst) + ") and (" + S(nearLast) + ", " +
                      S(nn) + ") at boundary vertex " + S(b) + " (ear split, then split of " + S(e) +
                      " along its edge to " + S(b) + ")";
    out.result = Result::Ok();
    return out;
  }

  /// Can boundary vertex y take an ear split (E, header)? y on the boundary with a manifold
  /// fan and two different boundary neighbours.
  Result CanEarSplit(int y) {
    if (!ed_.IsLive(y)) return Result::Fail("vertex " + S(y) + " does not exist");
    VertexStar<MeshType> st = ed_.Star(y);
    if (!st.boundary || !st.manifold) return Result::Fail("vertex " + S(y) + " does not lie on the boundary");
    if (st.neighbors.front() == st.neighbors.back())
      return Result::Fail("the boundary of vertex " + S(y) + " is too short for an ear split");
    // the new faces copy texture coordinates from the corners they border: one texture around y
    Result seam = ed_.StarSeamless(y);
    if (!seam) return Result::Fail("the ear split of boundary vertex " + S(y) + " is refused: " + seam.reason);
    return Result::Ok();
  }

  /// The ear split (E) of boundary vertex y, boundary neighbours n0 (its fan's first) and nn
  /// (last): a new boundary vertex e at y's position with the faces (n0, y, e) and (y, nn, e);
  /// y becomes interior and moves a share of the way towards the centroid of its interior
  /// neighbours (trying 1/2, 1/3, 1/6 until no face folds). Valences: y: +1 (now interior),
  /// e: 3, n0, nn: +1. Face colour and quality are copied from the face each new face borders,
  /// wedge texture coordinates from the matching corners there. *created receives e.
  Result EarSplit(int y, int* created = nullptr) {
    Result ok = CanEarSplit(y);
    if (!ok) return ok;
    Result last;
    for (double share : {0.5, 1.0 / 3.0, 1.0 / 6.0}) {
      last = EarSplitWith(y, share, created);
      if (last) return last;
    }
    return Result::Fail("the ear split of boundary vertex " + S(y) + " " + last.reason);
  }

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

  static BoundaryPairOutcome FailPair(BoundaryPairOutcome& out, const std::string& why) {
    out.result = Result::Fail(why);
    return out;
  }

  static BoundaryOutcome Fail(BoundaryOutcome& out, const std::string& why) {
    out.result = Result::Fail(why);
    return out;
  }

  typedef ScratchRegion<MeshType> Region;
  static int To(const Region* r, int v) { return r ? r->ToScratch(v) : v; }

  /// Runs op on a scratch copy of the (steps + scratchRings)-ring of the seeds, then on twice
  /// that radius (and four times, if needed) until two radii agree and the larger run left the
  /// cut border's `scratchMargin` rings untouched (then exact = true), as composite_prediction.h
  /// does. A request naming a vertex that is not live (or a seed -1) is refused by the
  /// operation's first check, before any edit: it is answered by the user's editor directly.
  template <class Outcome, class Op>
  Outcome OnScratch(const std::vector<int>& seeds, const std::vector<int>& request, int steps, Op op) {
    bool direct = false;
    for (int v : seeds) direct = direct || !ed_.IsLive(v);
    for (int v : request) direct = direct || !ed_.IsLive(v);
    if (direct) {
      Outcome o = op(*this, nullptr);
      o.exact = true;
      return o;
    }
    // message numbers below pad are counts and valences, at or above it vertex ids
    int pad = 1000;
    while (pad <= steps) pad *= 10;
    int k = std::max(0, steps) + scratchRings;
    bool touched = false;
    Outcome prev = RunOnScratch<Outcome>(seeds, k, pad, op, touched);
    for (int g = 0; g < 2; ++g) {
      k *= 2;
      bool touchedNext = false;
      Outcome next = RunOnScratch<Outcome>(seeds, k, pad, op, touchedNext);
      if (SameOutcome(prev, next) && !touchedNext) {
        next.exact = true;
        return next;
      }
      prev = next;
    }
    prev.exact = false;
    return prev;
  }

  template <class Outcome, class Op>
  Outcome RunOnScratch(const std::vector<int>& seeds, int k, int pad, Op& op, bool& touched) {
    Region r;
    r.Extract(ed_.Mesh(), seeds, k, scratchMargin, pad);
    Editor sed(r.mesh, ed_.geometry());
    BoundaryOperations so(sed);
    so.scratchRings = scratchRings;
    so.scratchMargin = scratchMargin;
    const typename Region::GuardState before = r.Guard();
    Outcome o = op(so, &r);
    touched = !(before == r.Guard());
    BackToUser(r, o);
    return o;
  }

  static std::map<int, int> BackKeys(const Region& r, const std::map<int, int>& ch) {
    std::map<int, int> out;
    for (auto& kv : ch) out[r.Back(kv.first)] = kv.second;
    return out;
  }
  static void BackToUser(const Region& r, BoundaryOutcome& o) {
    o.result.reason = r.BackText(o.result.reason);
    o.description = r.BackText(o.description);
    o.absorbed = r.Back(o.absorbed), o.boundaryVertex = r.Back(o.boundaryVertex);
    o.boundaryIrregular = r.Back(o.boundaryIrregular);
    o.v5 = r.Back(o.v5), o.v7 = r.Back(o.v7), o.created = r.Back(o.created), o.deleted = r.Back(o.deleted);
    o.changes = BackKeys(r, o.changes);
  }
  static void BackToUser(const Region& r, BoundaryPairOutcome& o) {
    o.result.reason = r.BackText(o.result.reason);
    o.description = r.BackText(o.description);
    o.v3 = r.Back(o.v3), o.v5 = r.Back(o.v5), o.survivor = r.Back(o.survivor);
    o.other3 = r.Back(o.other3), o.other5 = r.Back(o.other5);
    o.created = r.Back(o.created), o.deleted = r.Back(o.deleted);
    o.changes = BackKeys(r, o.changes);
    o.boundaryIrregular = r.Back(o.boundaryIrregular);
  }
  static bool SameOutcome(const BoundaryOutcome& a, const BoundaryOutcome& b) {
    return a.result.ok == b.result.ok && a.result.reason == b.result.reason && a.description == b.description &&
           a.absorbed == b.absorbed && a.boundaryVertex == b.boundaryVertex &&
           a.boundaryIrregular == b.boundaryIrregular && a.v5 == b.v5 && a.v7 == b.v7 && a.created == b.created &&
           a.deleted == b.deleted && a.changes == b.changes;
  }
  static bool SameOutcome(const BoundaryPairOutcome& a, const BoundaryPairOutcome& b) {
    return a.result.ok == b.result.ok && a.result.reason == b.result.reason && a.description == b.description &&
           a.v3 == b.v3 && a.v5 == b.v5 && a.survivor == b.survivor && a.cancelled == b.cancelled &&
           a.steps == b.steps && a.other3 == b.other3 && a.other5 == b.other5 && a.created == b.created &&
           a.deleted == b.deleted && a.changes == b.changes && a.boundaryIrregular == b.boundaryIrregular;
  }

  typedef typename MeshType::FaceType FaceType;
  typedef typename MeshType::VertexType VertexType;
  typedef typename MeshType::CoordType CoordType;
  typedef typename MeshType::ScalarType ScalarType;

  /// Records the valences of vs and their rings that `before` does not have yet (a vertex
  /// seen first here still has its valence from before the operation, unless created by it).
  void Remember(std::map<int, int>& before, const std::vector<int>& vs, const std::vector<int>& created) {
    for (int v : vs) {
      if (!ed_.IsLive(v)) continue;
      std::vector<int> ring{v};
      for (auto* n : ed_.Star(v).neighbors) ring.push_back(ed_.Index(n));
      for (int w : ring)
        if (!before.count(w) && std::find(created.begin(), created.end(), w) == created.end())
          before[w] = ed_.Valence(w);
    }
  }

  /// A boundary vertex at a corner (boundary valence rule): its valence 3 or 5 is regular
  /// there, so a pair may neither pass it nor cancel against it.
  bool IsCornerVertex(int v) { return RegularValenceOf(ed_.Star(v)) != 4; }
  Result CornerStop(int v) {
    return Result::Fail("the pair has reached a corner of the boundary at vertex " + S(v) +
                        " (regular valence " + S(RegularValenceOf(ed_.Star(v))) + " there): it stops before it");
  }

  /// The boundary neighbour of boundary vertex v that is not w.
  int OtherBoundaryNeighbour(int v, int w) {
    VertexStar<MeshType> st = ed_.Star(v);
    const int f = ed_.Index(st.neighbors.front()), l = ed_.Index(st.neighbors.back());
    return f == w ? l : f;
  }

  /// One step of the pair (x: 3, y: 5) towards x (header: (C), or the bump cancellation).
  Result StepTowardThree(BoundaryPairOutcome& out, std::map<int, int>& before, int& x, int& y, std::string& log) {
    const int p = OtherBoundaryNeighbour(x, y);
    VertexStar<MeshType> sx = ed_.Star(x);
    if (sx.Valence() != 3) return Result::Fail("vertex " + S(x) + " no longer has valence 3");
    const int apex = ed_.Index(sx.neighbors[1]);
    if (ed_.IsBoundary(apex))
      return Result::Fail("the neighbour " + S(apex) + " of boundary vertex " + S(x) +
                          " lies on the boundary too: the strip is one triangle wide there");
    const int dp = ed_.Valence(p);
    if (IsCornerVertex(p)) return CornerStop(p);
    Remember(before, {x, y, p, apex}, out.created);
    if (dp == 3) {
      const int q = OtherBoundaryNeighbour(p, x);
      if (IsCornerVertex(q)) return CornerStop(q);
      if (ed_.Valence(q) != 5)
        return Result::Fail("the pair meets boundary vertex " + S(p) + " of valence 3 that is not part of a pair "
                            "of opposite sign: moving on would leave it with valence 2");
      Remember(before, {q}, out.created);
      // the bump q5 p3 x3 y5: (A) x into p, then (C) the apex into p
      Result r = ed_.Collapse(x, p);
      if (!r) return Result::Fail("cancelling against the boundary pair (" + S(q) + ", " + S(p) +
                                  "): collapsing boundary edge (" + S(x) + ", " + S(p) + "): " + r.reason);
      if (ed_.Valence(apex) != 5 || ed_.Valence(p) != 3)
        return Result::Fail("the boundary pairs (" + S(x) + ", " + S(y) + ") and (" + S(p) + ", " + S(q) +
                            ") do not share the interior vertex a cancellation needs");
      r = ed_.Collapse(apex, p);
      if (!r) return Result::Fail("cancelling against the boundary pair (" + S(q) + ", " + S(p) +
                                  "): collapsing vertex " + S(apex) + " into " + S(p) + ": " + r.reason);
      out.deleted.push_back(x);
      out.deleted.push_back(apex);
      log += "; collapsed boundary edge (" + S(x) + ", " + S(p) + ") and vertex " + S(apex) + " into " + S(p);
      out.cancelled = true;
      return Result::Ok();
    }
    if (ed_.Valence(apex) != 6)
      return Result::Fail("the interior neighbour " + S(apex) + " of the valence-3 vertex " + S(x) + " has valence " +
                          S(ed_.Valence(apex)) + ", not 6: collapsing it would not move the pair (move or remove "
                          "that irregular vertex first)");
    if (dp != 4 && dp != 5)
      return Result::Fail("the pair meets boundary vertex " + S(p) + " of valence " + S(dp) +
                          ": only a regular (4) or a valence-5 boundary vertex lets it pass or cancel");
    Result r = ed_.Collapse(apex, x);  // (C): x: 6 + 3 - 4 = 5; p, y: -1
    if (!r) return Result::Fail("collapsing vertex " + S(apex) + " into boundary vertex " + S(x) + ": " + r.reason);
    out.deleted.push_back(apex);
    log += "; collapsed " + S(apex) + " into " + S(x);
    if (dp == 5) {  // p: 5 -> 4, the pair cancelled the boundary v7 at p; x (5) is left
      out.cancelled = true;
      out.survivor = x;
      return Result::Ok();
    }
    y = x;
    x = p;
    return Result::Ok();
  }

  /// One step of the pair (x: 3, y: 5) towards y (header: (E), or the notch cancellation).
  Result StepTowardFive(BoundaryPairOutcome& out, std::map<int, int>& before, int& x, int& y, std::string& log) {
    const int q = OtherBoundaryNeighbour(y, x);
    if (ed_.Valence(y) != 5) return Result::Fail("vertex " + S(y) + " no longer has valence 5");
    const int dq = ed_.Valence(q);
    if (IsCornerVertex(q)) return CornerStop(q);
    Remember(before, {x, y, q}, out.created);
    int e = -1;
    if (dq == 5) {
      const int r3 = OtherBoundaryNeighbour(q, y);
      if (IsCornerVertex(r3)) return CornerStop(r3);
      if (ed_.Valence(r3) != 3)
        return Result::Fail("the pair meets boundary vertex " + S(q) + " of valence 5 that is not part of a pair of "
                            "opposite sign: moving on would give it valence 6");
      Remember(before, {r3}, out.created);
      // the notch x3 y5 q5 r3: (E) at y, (E) at q, (A) of the new boundary vertex into r3
      Result r = EarSplit(y, &e);
      if (!r) return Result::Fail("cancelling against the boundary pair (" + S(q) + ", " + S(r3) + "): " + r.reason);
      out.created.push_back(e);
      int e2 = -1;
      r = EarSplit(q, &e2);
      if (!r) return Result::Fail("cancelling against the boundary pair (" + S(q) + ", " + S(r3) + "): " + r.reason);
      out.created.push_back(e2);
      r = ed_.Collapse(e2, r3);  // r3: 3 + 4 - 3 = 4, its apex q: 7 -> 6
      if (!r) return Result::Fail("cancelling against the boundary pair (" + S(q) + ", " + S(r3) +
                                  "): collapsing boundary edge (" + S(e2) + ", " + S(r3) + "): " + r.reason);
      out.created.pop_back();  // e2 lived only inside this step
      log += "; ear splits of " + S(y) + " and " + S(q) + ", boundary edge collapse into " + S(r3);
      out.cancelled = true;
      return Result::Ok();
    }
    if (dq != 3 && dq != 4)
      return Result::Fail("the pair meets boundary vertex " + S(q) + " of valence " + S(dq) +
                          ": only a regular (4) or a valence-3 boundary vertex lets it pass or cancel");
    Result r = EarSplit(y, &e);  // (E): y interior 6, e: 3, x: 4, q: +1
    if (!r) return r;
    out.created.push_back(e);
    log += "; ear split of " + S(y) + " (new boundary vertex " + S(e) + ")";
    if (dq == 3) {  // q: 3 -> 4, the pair cancelled the boundary v5 at q; e (3) is left
      out.cancelled = true;
      out.survivor = e;
      return Result::Ok();
    }
    x = e;
    y = q;
    return Result::Ok();
  }

  static CoordType FaceNormal(const FaceType* f) { return (f->cP(1) - f->cP(0)) ^ (f->cP(2) - f->cP(0)); }
  static void SetNormal(MeshType& m, FaceType* f) {
    if (!vcg::tri::HasPerFaceNormal(m)) return;
    CoordType n = FaceNormal(f);
    const ScalarType l = n.Norm();
    if (l > 0) n /= l;
    f->N() = n;
  }

  Result EarSplitWith(int yi, double share, int* created) {
    MeshType& m = ed_.Mesh();
    auto cp = ed_.Mark();
    auto& journal = ed_.journal();
    // allocate first: adding elements may move the vectors (the star is read afterwards)
    int ei, nf[2];
    ed_.slotPool().Take(m, journal, 1, 2, &ei, nf);
    FaceType* F0 = &m.face[size_t(nf[0])];
    FaceType* F1 = &m.face[size_t(nf[1])];
    VertexType* y = ed_.V(yi);
    VertexType* e = ed_.V(ei);
    VertexStar<MeshType> st = ed_.Star(yi);
    VertexType* n0 = st.neighbors.front();
    VertexType* nn = st.neighbors.back();
    const Corner<FaceType> first = st.corners.front(), lastC = st.corners.back();
    // reference for the fold check: y's faces before the edit
    CoordType ref(0, 0, 0);
    ScalarType refArea = 0;
    for (auto& c : st.corners) {
      ref += FaceNormal(c.f);
      refArea += FaceNormal(c.f).Norm() / 2;
    }
    refArea /= ScalarType(st.corners.size());
    // y moves inside, towards the centroid of its interior neighbours; e takes its place
    CoordType inner(0, 0, 0);
    int ni = 0;
    for (size_t k = 1; k + 1 < st.neighbors.size(); ++k) inner += st.neighbors[k]->P(), ++ni;
    if (ni == 0) inner = (n0->P() + nn->P()) / 2, ni = 1;
    inner /= ScalarType(ni);
    const CoordType p = y->P();
    e->ImportData(*y);
    e->ClearS();
    journal.SaveVertex(y);
    y->P() = p + (inner - p) * ScalarType(share);
    e->P() = p;
    // the new faces take colour / quality / texture from the face they border
    F0->ImportData(*first.f);
    F1->ImportData(*lastC.f);
    F0->ClearS();
    F1->ClearS();
    F0->V(0) = n0; F0->V(1) = y; F0->V(2) = e;
    F1->V(0) = y; F1->V(1) = nn; F1->V(2) = e;
    if (vcg::tri::HasPerWedgeTexCoord(m)) {
      const int z0 = first.z, zl = lastC.z;
      F0->WT(0) = first.f->WT((z0 + 1) % 3);  // n0
      F0->WT(1) = first.f->WT(z0);            // y
      F0->WT(2) = first.f->WT(z0);            // e: at y's old place
      F1->WT(0) = lastC.f->WT(zl);            // y
      F1->WT(1) = lastC.f->WT((zl + 2) % 3);  // nn
      F1->WT(2) = lastC.f->WT(zl);            // e
    }
    for (int z = 0; z < 3; ++z) {
      F0->VFp(z) = nullptr; F0->VFi(z) = 0;
      F1->VFp(z) = nullptr; F1->VFi(z) = 0;
    }
    auto link = [&](FaceType* f, int ef, FaceType* g, int eg) {
      journal.SaveFace(f);
      journal.SaveFace(g);
      f->FFp(ef) = g; f->FFi(ef) = eg;
      g->FFp(eg) = f; g->FFi(eg) = ef;
    };
    link(F0, 0, first.f, first.z);              // (n0, y) ~ (y, n0), y's first boundary edge
    link(F1, 0, lastC.f, (lastC.z + 2) % 3);    // (y, nn) ~ (nn, y), its last
    link(F0, 1, F1, 2);                         // (y, e) ~ (e, y)
    F0->FFp(2) = F0; F0->FFi(2) = 2;            // (e, n0): boundary
    F1->FFp(1) = F1; F1->FFi(1) = 1;            // (nn, e): boundary
    std::vector<FaceType*> changed{F0, F1};
    for (auto& c : st.corners) changed.push_back(c.f);
    for (FaceType* f : changed) {
      journal.SaveFace(f);
      SetNormal(m, f);
    }
    e->VFp() = F0;
    e->VFi() = 2;
    for (VertexType* v : {y, e, n0, nn}) ed_.RelinkVF(v);
    // geometry: no face may fold against y's old faces or collapse
    if (ed_.geometry().checkFolds && ref.Norm() > 0) {
      ref /= ref.Norm();
      const double c = std::cos(ed_.geometry().maxNormalTurnDeg * M_PI / 180.0);
      for (FaceType* f : changed) {
        const CoordType n = FaceNormal(f);
        const double l = double(n.Norm());
        if (l / 2 < ed_.geometry().minAreaRatio * double(refArea) || double(n.dot(ref)) / l < c) {
          ed_.RollbackTo(cp);
          return Result::Fail(l / 2 < ed_.geometry().minAreaRatio * double(refArea)
                                  ? "would create a degenerate triangle"
                                  : "would fold the surface (a triangle would turn over)");
        }
      }
    }
    if (created) *created = ei;
    return Result::Ok();
  }

  /// The boundary vertices among vs that are irregular by the boundary valence rule.
  void SetBoundaryIrregularList(std::vector<int>& list, const std::vector<int>& vs) {
    list.clear();
    for (int v : vs) {
      if (v < 0 || !ed_.IsLive(v)) continue;
      VertexStar<MeshType> s = ed_.Star(v);
      if (s.boundary && s.Valence() != RegularValenceOf(s)) list.push_back(v);
    }
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
