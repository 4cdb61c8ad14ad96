// filter_irregular: the five atomic semantic operations of the paper (sec. 6.2, figs. 6-8),
// built from the graph operations of graph_ops.h.
//
// Direction convention (used everywhere in the plugin):
//   * 5-7 pair movement (fig. 6): directions 0..5 turn counter-clockwise around the v5,
//     starting at the v7. Let n0 = v7, n1 .. n4 be the v5's neighbours counter-clockwise, and
//     m0 = v5, m1 .. m6 the v7's neighbours counter-clockwise (so n1 = m6 and n4 = m1):
//       0  split the v7 along (v7, m4): v7 -> v5 (keeps m5, m6), m4 -> v7      (toward n1 side)
//       1  flip edge (v7, n1):          n1 -> v5, the vertex beyond -> v7
//       2  collapse n1 into the v5:     the v5 becomes the v7, n2 -> v5
//       3  collapse n4 into the v5:     the v5 becomes the v7, n3 -> v5
//       4  flip edge (v7, n4):          n4 -> v5, the vertex beyond -> v7
//       5  split the v7 along (v7, m3): v7 -> v5 (keeps m1, m2), m3 -> v7      (toward n4 side)
//     On a regular neighbourhood each moves the pair one step and keeps it adjacent, and the
//     numbering is also the order of the pair's displacement by angle: direction k moves the
//     pair's midpoint into the k-th 60-degree sector counter-clockwise from the v5-to-v7 edge
//     (measured, PairDirectionByAngle).
//   * Single-vertex operations by direction (fig. 7 MoveVertexWithPairGeneration, fig. 8
//     GenerateQuadrupleInSector): direction k = the k-th 60-degree sector counter-clockwise
//     from a reference edge (p, ref), measured in p's tangent plane (directions.h); with no
//     reference, from the world +X axis projected into the tangent plane.
//   * The original single-vertex forms (MoveWithPairGeneration, GenerateQuadruple) take a
//     neighbour index k counted counter-clockwise from a reference neighbour (by default the
//     neighbour with the smallest vertex index); composite_ops.h uses them.
//
// Every operation has a dry run (Predict..., returning AtomicPrediction) that names the graph
// operations and the roles of the result (moved vertex, pair5/pair7, created, deleted) without
// editing the mesh; the operation itself applies exactly that prediction (Apply).
//
// Every operation states the valence change of each vertex it touches (AtomicOutcome::changes)
// and checks it after the edit; it refuses (and rolls back) if the neighbourhood is not the
// one the semantics need (e.g. a vertex that must be regular is not).
//
// What cannot be done (paper sec. 5: a single irregular vertex cannot move alone, Theorem 5.1;
// a 5-7 pair cannot cancel, Theorem 5.5) is decided on the theorems' conditions by
// impossibility.h, never attempted.
#pragma once

#include <algorithm>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "directions.h"
#include "graph_ops.h"
#include "graph_step.h"
#include "stamp_set.h"
#include "valence_changes.h"

namespace vcg_ext {
namespace irregular {


/// Which graph operation realises an atomic move (fig. 7): any, or one of the three.
enum class AtomicVia { Any = 0, Flip = 1, Collapse = 2, Split = 3 };
/// On which side of the moved vertex, seen from where it was, the generated 5-7 pair lies.
enum class PairSide { Any = 0, Ccw = 1, Cw = 2 };

/// The named roles of an atomic operation's result; shared by predictions and outcomes.
/// Vertex indices are those after the operation: a vertex a split creates gets the index the
/// editor gives it (MeshEditor::NextCreatedVertex: m.vert.size() when appended, or a dead
/// slot's, slot_pool.h), so a prediction names it too.
struct AtomicRoles {
  std::vector<GraphStep> steps;  ///< the graph operations, in order
  int moved = -1;                ///< the moved v5 or v7 (fig. 7), -1 if none
  int pair5 = -1, pair7 = -1;    ///< the 5 and the 7 of the (moved or generated) 5-7 pair
  std::vector<int> fives, sevens;  ///< every irregular vertex left, by valence (fig. 8: the quadruple)
  std::vector<int> created;      ///< vertices created (splits)
  std::vector<int> deleted;      ///< vertices deleted (collapses)
};

/// What an atomic operation did.
struct AtomicOutcome : AtomicRoles {
  Result result = Result::Fail("not applied");
  std::string description;              ///< e.g. "flip edge (12, 40)"
  ValenceChanges changes;               ///< vertex index -> valence after (deleted: 0)
  std::vector<int> irregular;           ///< the irregular vertices the operation leaves (the
                                        ///< moved pair, the generated quadruple, ...)
  explicit operator bool() const { return result.ok; }
};

/// What an atomic operation would do (a dry run): the same fields as AtomicOutcome, predicted
/// from topology (the valence rules of sec. 6.1) and the graph operations' Can* checks,
/// without editing the mesh. The fold check of the real operation depends on geometry:
/// geometryChecked is false unless the prediction was simulated (Simulate()).
struct AtomicPrediction : AtomicRoles {
  Result result = Result::Fail("not predicted");
  bool geometryChecked = false;
  std::string description;
  ValenceChanges changes;       ///< vertex index -> valence after (deleted: 0)
  std::vector<int> irregular;   ///< as AtomicOutcome::irregular will be
  // Fig. 7 configuration, for single-vertex moves:
  AtomicVia via = AtomicVia::Any;
  PairSide side = PairSide::Any;
  int site = -1;        ///< neighbour the moved vertex goes to (-1: a new vertex, see wedge)
  int wedge = -1;       ///< for a v5 moving into a new vertex: the neighbour after which it lies
  double angle = 0;     ///< direction of the move in degrees from the reference (directions.h)
  int sector = -1;      ///< sector 0..5 of that angle
  explicit operator bool() const { return result.ok; }
};

template <class MeshType>
class AtomicOperations {
 public:
  typedef MeshEditor<MeshType> Editor;
  typedef typename Editor::VertexType VertexType;

  explicit AtomicOperations(Editor& ed) : ed_(ed) {}

  /// Descriptions ("flip edge (12, 40)") and refusal reasons are written for people. A caller
  /// that reads neither turns them off: predictions and outcomes are then the same except that
  /// descriptions and reasons are empty. Automatic Reduction does (its searches make about a
  /// million predictions on bunny00, and their text was about 3% of its instructions).
  void SetDescribing(bool on) { describe_ = on; }
  bool Describing() const { return describe_; }

  /// Neighbour k of v counter-clockwise from reference neighbour ref (-1: the neighbour with
  /// the smallest index). -1 if v has no such neighbour.
  int NeighbourFrom(int v, int ref, int k) {
    VertexStar<MeshType> s = ed_.Star(v);
    if (s.neighbors.empty() || s.boundary) return -1;
    int i0 = 0;
    if (ref < 0) {
      for (size_t i = 1; i < s.neighbors.size(); ++i)
        if (ed_.Index(s.neighbors[i]) < ed_.Index(s.neighbors[size_t(i0)])) i0 = int(i);
    } else {
      i0 = s.IndexOf(ed_.V(ref));
      if (i0 < 0) return -1;
    }
    const int n = int(s.neighbors.size());
    return ed_.Index(s.neighbors[size_t(((i0 + k) % n + n) % n)]);
  }

  // ------------------------------------------------------------ 1. 5-7 pair movement (fig. 6)
  /// Moves the adjacent 5-7 pair (v5, v7) one step; dir in the original numbering 0..5 of
  /// this header's top comment. See PairDirectionByAngle for the numbering by angle.
  AtomicOutcome MovePair57(int v5, int v7, int dir) { return Apply(PredictMovePair57(v5, v7, dir)); }

  /// Dry run of MovePair57: the graph operation, where the pair lands (pair5, pair7), the
  /// created or deleted vertex, every valence change. Does not edit the mesh.
  AtomicPrediction PredictMovePair57(int v5, int v7, int dir) {
    const Result pair = CheckPair57(v5, v7);
    if (!pair) {
      AtomicPrediction out;
      return Refuse(out, pair.reason);
    }
    return PredictMovePair57Of(v5, v7, dir);
  }

  /// PredictMovePair57 for every direction 0..5 (out[dir]), the pair's own checks made once
  /// instead of six times (the reduction's StepCloser asks for all six at every step).
  void PredictMovePair57All(int v5, int v7, AtomicPrediction out[6]) {
    const Result pair = CheckPair57(v5, v7);
    for (int dir = 0; dir < 6; ++dir) {
      if (pair) {
        out[dir] = PredictMovePair57Of(v5, v7, dir);
      } else {
        out[dir] = AtomicPrediction();
        out[dir].result = pair;
      }
    }
  }

  /// Is (v5, v7) an adjacent interior 5-7 pair? PredictMovePair57's checks of the pair itself.
  Result CheckPair57(int v5, int v7) {
    Result pre = RequireInterior({v5, v7});
    if (!pre) return pre;
    if (ed_.Valence(v5) != 5 || ed_.Valence(v7) != 7)
      return Result::Fail(Say("a 5-7 pair needs a vertex of valence 5 and one of valence 7; vertices ", v5, " and ", v7,
                              " have valences ", ed_.Valence(v5), " and ", ed_.Valence(v7)));
    if (!ed_.Adjacent(v5, v7)) return Result::Fail(Say("vertices ", v5, " and ", v7, " are not adjacent"));
    return Result::Ok();
  }

 private:
  /// PredictMovePair57 after CheckPair57 passed.
  AtomicPrediction PredictMovePair57Of(int v5, int v7, int dir) {
    AtomicPrediction out;
    if (dir < 0 || dir > 5) return Refuse(out, "the direction must be 0..5");
    auto n = [&](int k) { return NeighbourFrom(v5, v7, k); };
    auto m = [&](int k) { return NeighbourFrom(v7, v5, k); };
    if (dir == 1 || dir == 4) {
      const int y = n(dir);
      int o[2];
      if (!ed_.Opposites(v7, y, o)) return Refuse(out, "the edge to flip lies on the boundary");
      const int z = o[0] == v5 ? o[1] : o[0];
      Result reg = RequireRegular({y, z});
      if (!reg) return Refuse(out, reg.reason);
      out.description = Say("flip edge (", v7, ", ", y, ")");
      out.steps = {StepFlip(v7, y)};
      out.changes = {{v5, 6}, {v7, 6}, {y, 5}, {z, 7}};
      out.pair5 = y, out.pair7 = z;
    } else if (dir == 2 || dir == 3) {
      const int x = n(dir == 2 ? 1 : 4), c = n(dir);
      Result reg = RequireRegular({x, c});
      if (!reg) return Refuse(out, reg.reason);
      out.description = Say("collapse vertex ", x, " into ", v5);
      out.steps = {StepCollapse(x, v5)};
      out.changes = {{v5, 7}, {v7, 6}, {c, 5}, {x, 0}};
      out.pair5 = c, out.pair7 = v5;
      out.deleted = {x};
    } else {
      const int b = m(dir == 0 ? 4 : 3);
      Result reg = RequireRegular({b});
      if (!reg) return Refuse(out, reg.reason);
      const int created = NextCreated(0);
      out.description = Say("split vertex ", v7, " along edges (", v7, ", ", v5, ") and (", v7, ", ", b, ")");
      // Split keeps, for the old vertex, the edges from its first to its second argument.
      out.steps = {dir == 0 ? StepSplit(v7, b, v5) : StepSplit(v7, v5, b)};
      out.changes = {{v7, 5}, {created, 6}, {v5, 6}, {b, 7}};
      out.pair5 = v7, out.pair7 = b;
      out.created = {created};
    }
    out.irregular = {out.pair5, out.pair7};
    out.result = Result::Ok();
    return Check(std::move(out));
  }

 public:
  /// Fig. 6 numbered by angle: direction k is the k-th of the six moves counted
  /// counter-clockwise (seen from outside) from the v5-to-v7 edge, by the direction in which
  /// the pair's midpoint moves on a regular lattice: k = 0 moves along the v5-to-v7 edge,
  /// k = 1 at 60 degrees from it, and so on (derived and tested in test_atomic_directions.cpp,
  /// PairMoveNumberingFollowsTheAngle). Returns the original dir of MovePair57.
  static int PairDirectionByAngle(int k) {
    static const int table[6] = {kPairByAngle0, kPairByAngle1, kPairByAngle2, kPairByAngle3, kPairByAngle4, kPairByAngle5};
    return k >= 0 && k < 6 ? table[k] : -1;
  }

  /// "Toward this point" for a pair: the direction (original numbering) among the six whose
  /// predicted move takes the pair's midpoint most nearly toward `point` (largest cosine
  /// between the midpoint's displacement and the direction to the point); -1 if none passes.
  int PairDirectionToward(int v5, int v7, const typename MeshType::CoordType& point) {
    typedef typename MeshType::CoordType CoordType;
    auto P = [&](int v) { return ed_.V(v)->P(); };
    const CoordType mid = (P(v5) + P(v7)) / 2, want = point - mid;
    int best = -1;
    double bestCos = -2;
    for (int dir = 0; dir < 6; ++dir) {
      AtomicPrediction pr = PredictMovePair57(v5, v7, dir);
      if (!pr) continue;
      const CoordType d = (P(pr.pair5) + P(pr.pair7)) / 2 - mid;
      const double len = double(d.Norm()) * double(want.Norm());
      const double c = len > 0 ? double(d.dot(want)) / len : -1;
      if (c > bestCos + 1e-9) bestCos = c, best = dir;
    }
    return best;
  }

  // ------------------------------------------------------------ 2. move with 5-7 generation (fig. 7)
  /// The original flip-only form (kept for composite_ops.h): a v5 (v7) moves one step toward
  /// its neighbour k (counted counter-clockwise from ref, -1: the neighbour of smallest
  /// index) and leaves an adjacent 5-7 pair.
  ///   v5 at p: flip the link edge (n_k, n_k+1); p -> 6, n_k -> 5 (the moved v5),
  ///            n_k+1 -> 5 and the vertex z beyond the edge -> 7 (the generated pair).
  ///   v7 at p: flip the edge (p, n_k); p -> 6, n_k -> 5 and n_k-1 -> 7 (the generated pair),
  ///            n_k+1 -> 7 (the moved v7).
  /// irregular = {moved, pair5, pair7}.
  AtomicOutcome MoveWithPairGeneration(int p, int k, int ref = -1) {
    return Apply(PredictMoveWithPairGeneration(p, k, ref));
  }

  AtomicPrediction PredictMoveWithPairGeneration(int p, int k, int ref = -1) {
    AtomicPrediction out;
    Result pre = RequireInterior({p});
    if (!pre) return Refuse(out, pre.reason);
    const int d = ed_.Valence(p);
    if (d != 5 && d != 7)
      return Refuse(out, Say("vertex ", p, " has valence ", d, "; this operation moves a v5 or a v7"));
    if (k < 0 || k >= d) return Refuse(out, Say("the direction must be 0..", d - 1, " for a v", d));
    const int nk = NeighbourFrom(p, ref, k), nk1 = NeighbourFrom(p, ref, k + 1), nkm = NeighbourFrom(p, ref, k - 1);
    if (d == 5) {
      int o[2];
      if (!ed_.Opposites(nk, nk1, o)) return Refuse(out, "the link edge lies on the boundary");
      const int z = o[0] == p ? o[1] : o[0];
      Result reg = RequireRegular({nk, nk1, z});
      if (!reg) return Refuse(out, reg.reason);
      out.description = Say("v5 ", p, " -> ", nk, ", new 5-7 pair (", nk1, ", ", z, "): flip edge (", nk, ", ", nk1, ")");
      out.steps = {StepFlip(nk, nk1)};
      out.changes = {{p, 6}, {nk, 5}, {nk1, 5}, {z, 7}};
      out.moved = nk, out.pair5 = nk1, out.pair7 = z;
    } else {
      Result reg = RequireRegular({nk, nk1, nkm});
      if (!reg) return Refuse(out, reg.reason);
      out.description = Say("v7 ", p, " -> ", nk1, ", new 5-7 pair (", nk, ", ", nkm, "): flip edge (", p, ", ", nk, ")");
      out.steps = {StepFlip(p, nk)};
      out.changes = {{p, 6}, {nk, 5}, {nkm, 7}, {nk1, 7}};
      out.moved = nk1, out.pair5 = nk, out.pair7 = nkm;
    }
    out.via = AtomicVia::Flip;
    out.site = out.moved;
    out.irregular = {out.moved, out.pair5, out.pair7};
    out.result = Result::Ok();
    return Check(std::move(out));
  }

  /// Every configuration of fig. 7 around the v5 or v7 p, derived from the valence rules of
  /// sec. 6.1 (n_0 .. n_d-1: p's neighbours counter-clockwise; "site": the neighbour the moved
  /// vertex goes to; "side": where the generated pair lies, seen from p, relative to the move):
  ///   v5 at p (needs the touched neighbours regular):
  ///     flip     ccw: flip link edge (n_j, n_j+1): p 6, n_j 5 (moved), n_j+1 5 + z 7 (pair)
  ///              cw:  flip link edge (n_j-1, n_j): p 6, n_j 5 (moved), n_j-1 5 + z 7 (pair)
  ///     collapse ccw: collapse n_j+1 into p: p 7, n_j 5 (moved), n_j+2 5 + p 7 (pair)
  ///              cw:  collapse n_j-1 into p: p 7, n_j 5 (moved), n_j-2 5 + p 7 (pair)
  ///     split    ccw: split n_j along (n_j, p), (n_j, q) (q: opposite p across n_j, 3 edges
  ///                   away), the new vertex c taking n_j+1's side: n_j 5 (moved), c 5 + q 7
  ///                   (pair), p 6;  cw: the same with c on n_j-1's side.
  ///     The v5 has five edges and six sectors: its sixth direction goes between two
  ///     neighbours, to a new vertex: the same split read the other way (moved = c, pair
  ///     = n_j + q; the paper's "same operation, two interpretations"), wedge = n_j.
  ///   v7 at p:
  ///     flip     ccw: flip (p, n_j+1): p 6, n_j 7 (moved), n_j+1 5 + n_j+2 7 (pair)
  ///              cw:  flip (p, n_j-1): p 6, n_j 7 (moved), n_j-1 5 + n_j-2 7 (pair)
  ///     split    ccw: split p along (p, n_j), (p, n_j+3), p keeping n_j+1, n_j+2: p 5, the
  ///                   new vertex 6, n_j 7 (moved), pair p 5 + n_j+3 7;  cw: along (p, n_j-3),
  ///                   (p, n_j): pair p 5 + n_j-3 7.
  ///     No collapse moves a v7: a collapse lowers valences only at the two vertices opposite
  ///     the edge (for p, a link edge (n_j, n_j+1), whose ends merge into a v8) or merges p
  ///     with a neighbour (valence 7 + d - 4 = 7 only for d = 4, not regular). So a v7 has
  ///     four configurations per direction, a v5 six.
  /// Each prediction carries site, wedge, via, side; angle and sector are measured in p's
  /// tangent plane from `ref` (directions.h; ref -1: the projected +X axis). Returned in a
  /// fixed order (by j, then flip, collapse, split, then ccw, cw, then new-vertex moves),
  /// each with its own verdict (result).
  std::vector<AtomicPrediction> VertexMoveConfigurations(int p, int ref = -1) {
    std::vector<AtomicPrediction> all;
    Result pre = RequireInterior({p});
    if (!pre) return all;
    const int d = ed_.Valence(p);
    if (d != 5 && d != 7) return all;
    VertexStar<MeshType> s = ed_.Star(p);
    std::vector<int> nb;
    for (VertexType* v : s.neighbors) nb.push_back(ed_.Index(v));
    auto n = [&](int j) { return nb[size_t(((j % d) + d) % d)]; };
    TangentFrame<MeshType> frame = FrameAt<MeshType>(ed_.V(p), ref >= 0 && ed_.IsLive(ref) ? ed_.V(ref) : nullptr);
    auto angleOf = [&](int v) { return frame.valid ? frame.AngleOf(ed_.V(v)->P()) : 0.0; };
    auto finish = [&](AtomicPrediction& c, int j, AtomicVia via, PairSide side, bool wedge) {
      c.via = via;
      c.side = side;
      if (wedge) {
        c.wedge = n(j);
        c.site = -1;
        const double a0 = angleOf(n(j));
        double a1 = angleOf(n(j + 1));
        if (a1 < a0) a1 += 360.0;
        c.angle = std::fmod((a0 + a1) / 2, 360.0);
      } else {
        c.site = n(j);
        c.angle = angleOf(n(j));
      }
      c.sector = SectorOfAngle(c.angle);
      c.irregular = {c.moved, c.pair5, c.pair7};
      all.push_back(Check(c));
    };
    const int created = NextCreated(0);
    for (int j = 0; j < d; ++j) {
      if (d == 5) {
        for (int s1 : {+1, -1}) {  // flip, ccw then cw
          AtomicPrediction c;
          const int other = n(j + s1), z = Beyond(n(j), other, p);
          c.steps = {StepFlip(n(j), other)};
          c.moved = n(j), c.pair5 = other, c.pair7 = z;
          c.changes = {{p, 6}, {n(j), 5}, {other, 5}};
          if (z >= 0) c.changes[z] = 7;
          c.description = Say("v5 ", p, " -> ", n(j), ", new 5-7 pair (", other, ", ", z, "): flip edge (", n(j), ", ",
                              other, ")");
          c.result = z < 0 ? Result::Fail("the link edge lies on the boundary") : RequireRegular({n(j), other, z});
          finish(c, j, AtomicVia::Flip, s1 > 0 ? PairSide::Ccw : PairSide::Cw, false);
        }
        for (int s1 : {+1, -1}) {  // collapse, ccw then cw
          AtomicPrediction c;
          const int x = n(j + s1), five = n(j + 2 * s1);
          c.steps = {StepCollapse(x, p)};
          c.moved = n(j), c.pair5 = five, c.pair7 = p;
          c.changes = {{p, 7}, {x, 0}, {n(j), 5}, {five, 5}};
          c.deleted = {x};
          c.description = Say("v5 ", p, " -> ", n(j), ", new 5-7 pair (", five, ", ", p, "): collapse vertex ", x,
                              " into ", p);
          c.result = RequireRegular({n(j), x, five});
          finish(c, j, AtomicVia::Collapse, s1 > 0 ? PairSide::Ccw : PairSide::Cw, false);
        }
        const int q = OppositeInStar(n(j), p);
        for (int s1 : {+1, -1}) {  // split, new vertex on n_j+1's side (ccw) or n_j-1's (cw)
          AtomicPrediction c;
          c.steps = {s1 > 0 ? StepSplit(n(j), p, q) : StepSplit(n(j), q, p)};
          c.moved = n(j), c.pair5 = created, c.pair7 = q;
          c.changes = {{p, 6}, {n(j), 5}, {created, 5}};
          if (q >= 0) c.changes[q] = 7;
          c.created = {created};
          c.description = Say("v5 ", p, " -> ", n(j), ", new 5-7 pair (new vertex ", created, ", ", q, "): ",
                              c.steps[0].Describe());
          c.result = q < 0 ? Result::Fail(Say("vertex ", n(j), " (valence ", ed_.Valence(n(j)),
                                              ") is in the way: this step needs regular vertices around the v5"))
                           : RequireRegular({n(j), q});
          finish(c, j, AtomicVia::Split, s1 > 0 ? PairSide::Ccw : PairSide::Cw, false);
        }
      } else {
        for (int s1 : {+1, -1}) {  // flip (p, n_j+-1)
          AtomicPrediction c;
          const int five = n(j + s1), seven = n(j + 2 * s1);
          c.steps = {StepFlip(p, five)};
          c.moved = n(j), c.pair5 = five, c.pair7 = seven;
          c.changes = {{p, 6}, {n(j), 7}, {five, 5}, {seven, 7}};
          c.description = Say("v7 ", p, " -> ", n(j), ", new 5-7 pair (", five, ", ", seven, "): flip edge (", p, ", ",
                              five, ")");
          c.result = RequireRegular({n(j), five, seven});
          finish(c, j, AtomicVia::Flip, s1 > 0 ? PairSide::Ccw : PairSide::Cw, false);
        }
        for (int s1 : {+1, -1}) {  // split p, keeping the two neighbours between n_j and n_j+-3
          AtomicPrediction c;
          const int seven = n(j + 3 * s1);
          c.steps = {s1 > 0 ? StepSplit(p, n(j), seven) : StepSplit(p, seven, n(j))};
          c.moved = n(j), c.pair5 = p, c.pair7 = seven;
          c.changes = {{p, 5}, {created, 6}, {n(j), 7}, {seven, 7}};
          c.created = {created};
          c.description = Say("v7 ", p, " -> ", n(j), ", new 5-7 pair (", p, ", ", seven, "): ", c.steps[0].Describe());
          c.result = RequireRegular({n(j), seven});
          finish(c, j, AtomicVia::Split, s1 > 0 ? PairSide::Ccw : PairSide::Cw, false);
        }
      }
    }
    if (d == 5) {
      for (int j = 0; j < d; ++j) {  // moves into a new vertex between n_j and n_j+1
        for (int s1 : {+1, -1}) {
          // s1 = +1: split n_j with the new vertex on n_j+1's side; the pair (n_j, q) lies cw.
          // s1 = -1: split n_j+1 with the new vertex on n_j's side; the pair lies ccw.
          AtomicPrediction c;
          const int w = s1 > 0 ? n(j) : n(j + 1), q = OppositeInStar(w, p);
          c.steps = {s1 > 0 ? StepSplit(w, p, q) : StepSplit(w, q, p)};
          c.moved = created, c.pair5 = w, c.pair7 = q;
          c.changes = {{p, 6}, {w, 5}, {created, 5}};
          if (q >= 0) c.changes[q] = 7;
          c.created = {created};
          c.description = Say("v5 ", p, " -> new vertex ", created, " between ", n(j), " and ", n(j + 1),
                              ", new 5-7 pair (", w, ", ", q, "): ", c.steps[0].Describe());
          c.result = q < 0 ? Result::Fail(Say("vertex ", w, " (valence ", ed_.Valence(w),
                                              ") is in the way: this step needs regular vertices around the v5"))
                           : RequireRegular({w, q});
          finish(c, j, AtomicVia::Split, s1 > 0 ? PairSide::Cw : PairSide::Ccw, true);
        }
      }
    }
    return all;
  }

  /// Fig. 7 by direction: the v5 or v7 p moves one step into sector `sector` (0..5, 60-degree
  /// sectors counter-clockwise from the reference edge (p, ref), directions.h) and leaves an
  /// adjacent 5-7 pair. The moved vertex goes to the neighbour whose edge lies in the sector,
  /// nearest its centre; a v5 whose sector holds none of its five edges moves into a new
  /// vertex between the two neighbours around the sector (a split). Among the configurations
  /// at that place, `via` and `side` choose; Any takes the first that passes, in the order
  /// flip, collapse, split, then pair counter-clockwise, clockwise. Does not edit the mesh.
  AtomicPrediction PredictVertexMove(int p, int sector, int ref = -1, AtomicVia via = AtomicVia::Any,
                                     PairSide side = PairSide::Any) {
    AtomicPrediction out;
    Result pre = RequireInterior({p});
    if (!pre) return Refuse(out, pre.reason);
    const int d = ed_.Valence(p);
    if (d != 5 && d != 7)
      return Refuse(out, Say("vertex ", p, " has valence ", d, "; this operation moves a v5 or a v7"));
    if (sector < 0 || sector > 5) return Refuse(out, "the direction must be 0..5");
    if (ref >= 0 && !ed_.Adjacent(p, ref))
      return Refuse(out, Say("the reference vertex ", ref, " is not a neighbour of vertex ", p));
    if (!FrameAt<MeshType>(ed_.V(p), ref >= 0 ? ed_.V(ref) : nullptr).valid)
      return Refuse(out, Say("vertex ", p, " has no tangent plane (degenerate faces around it)"));
    std::vector<AtomicPrediction> all = VertexMoveConfigurations(p, ref);
    // the place: the neighbour (else the new-vertex wedge) in the sector nearest its centre
    const double centre = 60.0 * sector;
    // (ties, within 1e-3 degrees, go to the smaller angle: the first counter-clockwise)
    int bestSite = -2, bestWedge = -2;
    double best = 1e9, bestAngle = 1e9;
    for (int pass = 0; pass < 2 && bestSite == -2; ++pass)
      for (const AtomicPrediction& c : all) {
        if ((pass == 0) != (c.site >= 0) || c.sector != sector) continue;
        const double g = AngleGap(c.angle, centre);
        if (g < best - 1e-3 || (g <= best + 1e-3 && c.angle < bestAngle))
          best = g, bestAngle = c.angle, bestSite = c.site, bestWedge = c.wedge;
      }
    if (bestSite == -2)
      return Refuse(out, Say("no edge of vertex ", p, " points into direction ", sector,
                             " (the 60-degree sector around ", int(centre), " degrees from the reference edge)"));
    const AtomicPrediction* firstMatch = nullptr;
    for (const AtomicPrediction& c : all) {
      if (c.site != bestSite || c.wedge != bestWedge) continue;
      if (via != AtomicVia::Any && c.via != via) continue;
      if (side != PairSide::Any && c.side != side) continue;
      if (c.result) return c;
      if (!firstMatch) firstMatch = &c;
    }
    if (!firstMatch)
      return Refuse(out, Say("no ", ViaName(via), " moves the v", d, " ", p, " in direction ", sector,
                             d == 7 && via == AtomicVia::Collapse
                                 ? " (no edge collapse moves a v7: see VertexMoveConfigurations)"
                                 : ""));
    return *firstMatch;
  }

  /// The sector (0..5) of the direction from p toward `point`, measured like PredictVertexMove.
  int SectorToward(int p, const typename MeshType::CoordType& point, int ref = -1) {
    TangentFrame<MeshType> f = FrameAt<MeshType>(ed_.V(p), ref >= 0 ? ed_.V(ref) : nullptr);
    return f.valid ? SectorOfAngle(f.AngleOf(point)) : -1;
  }

  /// Applies PredictVertexMove: irregular = {moved, pair5, pair7}.
  AtomicOutcome MoveVertexWithPairGeneration(int p, int sector, int ref = -1, AtomicVia via = AtomicVia::Any,
                                             PairSide side = PairSide::Any) {
    return Apply(PredictVertexMove(p, sector, ref, via, side));
  }

  // ------------------------------------------------------------ 4. quadruple generation (fig. 8)
  /// How a regular vertex becomes a 5-5-7-7 quadruple (fig. 8):
  ///   Flip:          flip (p, n_k): p, n_k -> 5; n_k-1, n_k+1 -> 7. The quadruple fills the
  ///                  two triangles of the new edge.
  ///   Split:         split p along (p, n_k), (p, n_k+3): p and the new vertex -> 5; n_k,
  ///                  n_k+3 -> 7 (two triangles: the new ones).
  ///   CollapseSplit: the paper's two-operation configuration through a v8 (drawn red in fig. 8):
  ///                  collapse n_k into p (p -> 6 + 6 - 4 = 8, n_k-1, n_k+1 -> 5), then split
  ///                  the v8 along its edges to n_k+3 and to q, the vertex opposite p across
  ///                  n_k, with three edges on each side (both halves -> 6; n_k+3, q -> 7).
  ///                  Quadruple: 5s n_k-1, n_k+1, 7s n_k+3, q; one vertex is deleted and one
  ///                  created. A single collapse cannot do it: merging two regular vertices
  ///                  always makes a v8 (sec. 6.1, d = 6 + 6 - 4); of the three 3|3 splits of
  ///                  the v8 whose ends are regular, this is the one symmetric about the
  ///                  collapsed edge.
  enum class QuadrupleVia { Flip = 0, Split = 1, CollapseSplit = 2 };

  /// The original form (k: neighbour index from ref, -1: smallest index). irregular =
  /// {p, n_k, n_k-1, n_k+1} (flip) or {p, created, n_k, n_k+3} (split): 5, 5, 7, 7.
  AtomicOutcome GenerateQuadruple(int p, int k, bool bySplit, int ref = -1) {
    return Apply(PredictQuadrupleGeneration(p, k, bySplit ? QuadrupleVia::Split : QuadrupleVia::Flip, ref));
  }

  /// Dry run of quadruple generation with k = neighbour index counted counter-clockwise from
  /// ref (-1: the neighbour of smallest index).
  AtomicPrediction PredictQuadrupleGeneration(int p, int k, QuadrupleVia via, int ref = -1) {
    AtomicPrediction out;
    Result pre = RequireInterior({p});
    if (!pre) return Refuse(out, pre.reason);
    if (ed_.Valence(p) != 6)
      return Refuse(out, Say("a 5-5-7-7 quadruple is generated from a regular vertex; vertex ", p, " has valence ",
                             ed_.Valence(p)));
    if (k < 0 || k > 5) return Refuse(out, "the direction must be 0..5");
    auto n = [&](int j) { return NeighbourFrom(p, ref, k + j); };
    const int nk = n(0);
    if (nk < 0) return Refuse(out, Say("the reference vertex ", ref, " is not a neighbour of vertex ", p));
    if (via == QuadrupleVia::Flip) {
      const int a = n(-1), b = n(1);
      out.result = RequireRegular({nk, a, b});
      out.description = Say("flip edge (", p, ", ", nk, ")");
      out.steps = {StepFlip(p, nk)};
      out.changes = {{p, 5}, {nk, 5}, {a, 7}, {b, 7}};
      out.irregular = {p, nk, a, b};
    } else if (via == QuadrupleVia::Split) {
      const int b = n(3), created = NextCreated(0);
      out.result = RequireRegular({nk, b});
      out.description = Say("split vertex ", p, " along edges (", p, ", ", nk, ") and (", p, ", ", b, ")");
      out.steps = {StepSplit(p, nk, b)};
      out.changes = {{p, 5}, {created, 5}, {nk, 7}, {b, 7}};
      out.irregular = {p, created, nk, b};
      out.created = {created};
    } else {
      const int a = n(-1), b = n(1), far = n(3), q = OppositeInStar(nk, p), created = NextCreated(0);
      out.result = q < 0 ? Result::Fail(Say("vertex ", nk, " (valence ", ed_.Valence(nk),
                                            ") is in the way: this step needs regular vertices around vertex ", p))
                         : RequireRegular({nk, a, b, far, q});
      out.description = Say("collapse vertex ", nk, " into ", p, " (a v8), then split it along edges (", p, ", ", q,
                            ") and (", p, ", ", far, ")");
      out.steps = {StepCollapse(nk, p), StepSplit(p, q, far)};
      out.changes = {{p, 6}, {nk, 0}, {created, 6}, {a, 5}, {b, 5}, {far, 7}};
      if (q >= 0) out.changes[q] = 7;
      out.irregular = {a, b, far, q};
      out.created = {created};
      out.deleted = {nk};
    }
    return Check(std::move(out));
  }

  /// Quadruple generation by direction: `sector` 0..5 is the 60-degree sector (directions.h)
  /// counted counter-clockwise from the reference edge (p, ref) (ref -1: the projected +X
  /// axis) that holds the edge (p, n_k) the operation is built on (the flipped edge, the
  /// first split edge, the collapsed edge). The neighbour nearest the sector's centre is n_k.
  AtomicPrediction PredictQuadrupleGenerationInSector(int p, int sector, QuadrupleVia via, int ref = -1) {
    AtomicPrediction out;
    Result pre = RequireInterior({p});
    if (!pre) return Refuse(out, pre.reason);
    if (sector < 0 || sector > 5) return Refuse(out, "the direction must be 0..5");
    if (ref >= 0 && !ed_.Adjacent(p, ref))
      return Refuse(out, Say("the reference vertex ", ref, " is not a neighbour of vertex ", p));
    const int nk = NeighbourInSector(p, sector, ref);
    if (nk < 0)
      return Refuse(out, Say("no edge of vertex ", p, " points into direction ", sector,
                             " (the 60-degree sector around ", 60 * sector, " degrees from the reference edge)"));
    AtomicPrediction r = PredictQuadrupleGeneration(p, 0, via, nk);
    FrameAngle(r, p, nk, ref);
    return r;
  }

  AtomicOutcome GenerateQuadrupleInSector(int p, int sector, QuadrupleVia via, int ref = -1) {
    return Apply(PredictQuadrupleGenerationInSector(p, sector, via, ref));
  }

  /// The neighbour of p whose edge lies in `sector` nearest its centre; -1 if none.
  int NeighbourInSector(int p, int sector, int ref = -1) {
    TangentFrame<MeshType> f = FrameAt<MeshType>(ed_.V(p), ref >= 0 ? ed_.V(ref) : nullptr);
    if (!f.valid) return -1;
    int best = -1;
    double gap = 1e9;
    double bestAngle = 1e9;
    for (VertexType* v : ed_.Star(p).neighbors) {
      const double a = f.AngleOf(v->P()), g = AngleGap(a, 60.0 * sector);
      if (SectorOfAngle(a) != sector) continue;
      if (g < gap - 1e-3 || (g <= gap + 1e-3 && a < bestAngle)) gap = g, bestAngle = a, best = ed_.Index(v);
    }
    return best;
  }

  // ------------------------------------------------------------ 3. move with 5-7 removal
  /// The inverse of move with pair generation (fig. 7 read in reverse, collapses replaced by
  /// splits): a v5 (v7) next to a 5-7 pair moves one step and the pair disappears, i.e. an
  /// adjacent 5-5-7 triple becomes one v5 and a 5-7-7 triple one v7. The three vertices
  /// must be close (each within one edge of another); the operation searches the flips and
  /// collapses around them, then the vertex splits (a split undoes a generation by collapse),
  /// for the one that does exactly this. moved = the survivor.
  AtomicOutcome MoveWithPairRemoval(const std::vector<int>& triple) {
    if (triple.size() != 3) {
      AtomicOutcome out;
      return Refuse(out, "a triple cancellation needs exactly three vertices");
    }
    return ApplyRemoval(triple);
  }

  // ------------------------------------------------------------ 5. quadruple removal
  /// The inverse of quadruple generation (fig. 8 read in reverse): a 5-5-7-7 quadruple
  /// becomes regular. Searches the single flips, collapses and splits among the four
  /// vertices, then the two-operation inverse of CollapseSplit: collapse the edge whose
  /// opposite vertices are the two v7 (making a v8), and split the v8 along its edges to the
  /// two v5 with three edges on each side.
  AtomicOutcome RemoveQuadruple(const std::vector<int>& quad) {
    if (quad.size() != 4) {
      AtomicOutcome out;
      return Refuse(out, "a quadruple removal needs exactly four vertices");
    }
    return ApplyRemoval(quad);
  }

  /// Dry run of MoveWithPairRemoval (3 vertices) or RemoveQuadruple (4 vertices): the first
  /// candidate the real operation tries. geometryChecked is false: if that candidate folds
  /// the surface, the real operation goes on to the next one (RemovalCandidates).
  AtomicPrediction PredictRemoval(const std::vector<int>& group) {
    AtomicPrediction out;
    Result pre = CheckRemovalGroup(group);
    if (!pre) return Refuse(out, pre.reason);
    std::vector<AtomicPrediction> c;
    for (int phase = 0; phase < RemovalPhases(group) && c.empty(); ++phase) c = RemovalCandidates(group, phase);
    if (c.empty()) {
      if (group.size() == 3)
        return Refuse(out, "no single flip, collapse or split cancels these vertices: bring them closer first (5-5-7 or "
                           "5-7-7 cancellation needs them within one edge of each other, as in the paper's fig. 7)");
      return Refuse(out, "no flip, collapse or split (nor the collapse and split through a v8) cancels these vertices: "
                         "bring them closer first (they must be in the configuration of the paper's fig. 8)");
    }
    return c.front();
  }

  /// The graph operations (or, for a quadruple, pairs of operations) that cancel the group,
  /// in the order the real operation tries them, each passing the topological checks, by
  /// phase: 0 single flips and collapses, 1 single vertex splits, 2 (quadruples) the collapse
  /// and split through a v8. Later phases are searched only when the earlier ones give nothing
  /// that applies, so a removal costs no more than before when a flip or collapse does it.
  std::vector<AtomicPrediction> RemovalCandidates(const std::vector<int>& group, int phase) {
    std::vector<AtomicPrediction> out;
    if (!CheckRemovalGroup(group)) return out;
    if (phase == 2) return group.size() == 4 ? CollapseSplitRemovals(group, "5-5-7-7 quadruple removed") : out;
    const bool splits = phase == 1;
    std::vector<AtomicPrediction> c;
    if (group.size() == 3) {
      int n5 = 0;
      for (int v : group) n5 += ed_.Valence(v) == 5;
      const int survivor = n5 == 2 ? 5 : 7;
      c = Candidates(group, CancellationTest(group, 2, survivor),
                     Say(n5 == 2 ? "5-5-7" : "5-7-7", " triple cancelled into one v", survivor), splits);
    } else {
      c = Candidates(group, CancellationTest(group, 4, 0), "5-5-7-7 quadruple removed", splits);
    }
    for (AtomicPrediction& p : c) {
      if (splits && p.steps[0].kind != GraphStep::kSplit) continue;
      if (group.size() == 3) p.moved = p.irregular.empty() ? -1 : p.irregular[0];
      out.push_back(p);
    }
    return out;
  }

  /// Number of RemovalCandidates phases for a group of this size.
  static int RemovalPhases(const std::vector<int>& group) { return group.size() == 4 ? 3 : 2; }

  /// Runs the prediction on the mesh and rolls it back: the verdict of the real operation,
  /// fold check included (geometryChecked = true). Leaves the mesh exactly as it was.
  AtomicPrediction Simulate(AtomicPrediction p) {
    if (!p.result) return p;
    auto cp = ed_.Mark();
    AtomicOutcome o = Apply(p);
    ed_.RollbackTo(cp);
    p.geometryChecked = true;
    p.result = o.result;
    return p;
  }

  /// Applies a prediction: runs its graph operations in order, checks every stated valence
  /// and the predicted indices of created vertices; all or nothing.
  AtomicOutcome Apply(const AtomicPrediction& p) {
    AtomicOutcome out;
    out.description = p.description;
    if (!p.result) {
      Refuse(out, p.result.reason);
      return out;
    }
    auto cp = ed_.Mark();
    size_t ci = 0;
    for (const GraphStep& s : p.steps) {
      int created = -1;
      Result r = s.kind == GraphStep::kFlip       ? ed_.Flip(s.x, s.y)
                 : s.kind == GraphStep::kCollapse ? ed_.Collapse(s.x, s.y)
                                                  : ed_.Split(s.x, s.y, s.z, &created);
      if (!r) {
        ed_.RollbackTo(cp);
        Refuse(out, p.steps.size() > 1 ? s.Describe() + ": " + r.reason : r.reason);
        return out;
      }
      if (s.kind == GraphStep::kSplit) {
        if (ci >= p.created.size() || created != p.created[ci]) {
          ed_.RollbackTo(cp);
          Refuse(out, Say("internal check failed: ", s.Describe(), " created vertex ", created));
          return out;
        }
        ++ci;
      }
    }
    static_cast<AtomicRoles&>(out) = static_cast<const AtomicRoles&>(p);
    // returned by name, not through Finish's reference: a copy of every outcome otherwise
    Finish(out, Result::Ok(), cp, p.changes, p.irregular);
    return out;
  }

 private:
  static AtomicOutcome& Refuse(AtomicOutcome& out, const std::string& why) {
    out.result = Result::Fail(why);
    return out;
  }
  /// Refuses a prediction the caller is about to return: moved out, not copied.
  static AtomicPrediction Refuse(AtomicPrediction& out, const std::string& why) {
    out.result = Result::Fail(why);
    return std::move(out);
  }

  static GraphStep StepFlip(int x, int y) { return GraphStep{GraphStep::kFlip, x, y, -1}; }
  static GraphStep StepCollapse(int x, int y) { return GraphStep{GraphStep::kCollapse, x, y, -1}; }
  static GraphStep StepSplit(int x, int y, int z) { return GraphStep{GraphStep::kSplit, x, y, z}; }

  static const char* ViaName(AtomicVia v) {
    return v == AtomicVia::Flip ? "edge flip" : v == AtomicVia::Collapse ? "edge collapse"
                                              : v == AtomicVia::Split  ? "vertex split"
                                                                       : "graph operation";
  }

  // Fig. 6 by angle (PairDirectionByAngle): the original dir of the k-th move by angle.
  // Measured on a flat lattice (test PairMoveNumberingFollowsTheAngle): the original numbering
  // already turns counter-clockwise from the v5-to-v7 edge, so the table is the identity.
  static const int kPairByAngle0 = 0, kPairByAngle1 = 1, kPairByAngle2 = 2, kPairByAngle3 = 3, kPairByAngle4 = 4,
                   kPairByAngle5 = 5;

  /// Index the k-th vertex a split creates from now would get (appended, or a dead slot's:
  /// slot_pool.h).
  int NextCreated(int k) { return ed_.NextCreatedVertex(k); }

  /// The vertex opposite `p` across edge (a, b); -1 if the edge is missing or on the boundary.
  int Beyond(int a, int b, int p) {
    int o[2];
    if (!ed_.Opposites(a, b, o)) return -1;
    return o[0] == p ? o[1] : o[1] == p ? o[0] : -1;
  }

  /// The neighbour of the regular interior vertex w three edges from p around w (the end of
  /// the edge opposite (w, p)); -1 if w is not a regular interior neighbour of p.
  int OppositeInStar(int w, int p) {
    if (w < 0 || !ed_.IsLive(w)) return -1;
    VertexStar<MeshType> s = ed_.Star(w);
    if (s.boundary || s.Valence() != 6) return -1;
    const int i = s.IndexOf(ed_.V(p));
    return i < 0 ? -1 : ed_.Index(s.neighbors[size_t((i + 3) % 6)]);
  }

  void FrameAngle(AtomicPrediction& r, int p, int v, int ref) {
    TangentFrame<MeshType> f = FrameAt<MeshType>(ed_.V(p), ref >= 0 ? ed_.V(ref) : nullptr);
    r.angle = f.valid ? f.AngleOf(ed_.V(v)->P()) : 0.0;
    r.sector = SectorOfAngle(r.angle);
  }

  /// Completes a topological prediction: the first graph operation's Can* check on the
  /// current mesh (later ones act on the mesh the first leaves: their preconditions follow
  /// from the regularity checks), and the irregular vertices it leaves, by valence.
  AtomicPrediction Check(AtomicPrediction p) {
    p.geometryChecked = false;
    p.fives.clear();
    p.sevens.clear();
    if (!p.result) return p;
    if (!p.steps.empty()) {
      const GraphStep& s = p.steps.front();
      Result r = s.kind == GraphStep::kFlip       ? ed_.CanFlip(s.x, s.y)
                 : s.kind == GraphStep::kCollapse ? ed_.CanCollapse(s.x, s.y)
                                                  : ed_.CanSplit(s.x, s.y, s.z);
      if (!r) {
        p.result = r;
        return p;
      }
    }
    for (auto& kv : p.changes) {
      if (kv.second == 5) p.fives.push_back(kv.first);
      if (kv.second == 7) p.sevens.push_back(kv.first);
    }
    p.result = Result::Ok();
    return p;
  }

  Result RequireInterior(const std::vector<int>& vs) {
    for (int v : vs) {
      if (!ed_.IsLive(v)) return Result::Fail(Say("vertex ", v, " does not exist"));
      if (ed_.IsBoundary(v))
        return Result::Fail(Say("vertex ", v, " lies on the boundary; these operations work on interior vertices"));
    }
    return Result::Ok();
  }

  Result RequireRegular(const std::vector<int>& vs) {
    for (int v : vs) {
      if (v < 0 || !ed_.IsLive(v)) return Result::Fail("the operation would reach past the mesh");
      const int d = ed_.InteriorValence(v);
      if (d < 0) return Result::Fail(Say("the operation would touch boundary vertex ", v));
      if (d != 6)
        return Result::Fail(Say("vertex ", v, " (valence ", d,
                                ") is in the way: this step needs regular vertices around the irregular ones; "
                                "try another direction or move the other irregular vertex first"));
    }
    return Result::Ok();
  }

  /// Checks the stated valence changes; rolls back and refuses if they do not hold.
  AtomicOutcome& Finish(AtomicOutcome& out, Result r, typename Editor::Checkpoint cp, const ValenceChanges& expect,
                        const std::vector<int>& irregular) {
    if (!r) {
      ed_.RollbackTo(cp);
      return Refuse(out, r.reason);
    }
    for (auto& kv : expect) {
      const int got = ed_.IsLive(kv.first) ? ed_.Valence(kv.first) : 0;
      if (got != kv.second) {
        ed_.RollbackTo(cp);
        return Refuse(out, Say("internal check failed: vertex ", kv.first, " has valence ", got, " instead of ",
                               kv.second, " after ", out.description));
      }
    }
    out.changes = expect;
    out.irregular = irregular;
    out.result = Result::Ok();
    return out;
  }

  Result CheckRemovalGroup(const std::vector<int>& group) {
    if (group.size() != 3 && group.size() != 4)
      return Result::Fail("a cancellation needs three (a triple) or four (a quadruple) vertices");
    Result pre = RequireInterior(group);
    if (!pre) return pre;
    int n5 = 0, n7 = 0;
    for (int v : group) {
      n5 += ed_.Valence(v) == 5;
      n7 += ed_.Valence(v) == 7;
    }
    if (group.size() == 3 && !((n5 == 2 && n7 == 1) || (n5 == 1 && n7 == 2)))
      return Result::Fail("a triple cancellation needs a 5-5-7 or a 5-7-7 triple (valences 5, 5, 7 or 5, 7, 7)");
    if (group.size() == 4 && (n5 != 2 || n7 != 2)) return Result::Fail("a quadruple removal needs two v5 and two v7");
    return Result::Ok();
  }

  typedef std::function<bool(const ValenceChanges&, const ValenceChanges&)> ChangeTest;

  /// Cancellation test: `cancelled` irregular vertices disappear, at most one of valence
  /// `survivor` (0 = none) remains, and no irregular vertex outside the group is touched.
  static ChangeTest CancellationTest(const std::vector<int> group, int cancelled, int survivor) {
    return [group, cancelled, survivor](const ValenceChanges& before, const ValenceChanges& after) {
      int irregularBefore = 0, irregularAfter = 0, survivors = 0;
      for (auto& kv : after) {
        const int b = before.count(kv.first) ? before.at(kv.first) : 0;
        const bool inGroup = std::find(group.begin(), group.end(), kv.first) != group.end();
        if (b != 6 && b != 0) ++irregularBefore;
        if (!inGroup && b != 6 && b != 0) return false;
        if (kv.second != 6 && kv.second != 0) {
          ++irregularAfter;
          if (kv.second != survivor) return false;
          ++survivors;
        }
      }
      return irregularBefore - irregularAfter == cancelled && survivors == (survivor ? 1 : 0);
    };
  }

  /// The real removal: the candidates of each phase in order, the first that applies.
  AtomicOutcome ApplyRemoval(const std::vector<int>& group) {
    AtomicPrediction p = PredictRemoval(group);
    AtomicOutcome out;
    if (!p) return Refuse(out, p.result.reason);
    for (int phase = 0; phase < RemovalPhases(group); ++phase) {
      AtomicOutcome o = ApplyFirst(RemovalCandidates(group, phase));
      if (o) return o;
      if (phase == 0 || out.result.reason.empty() || out.result.reason == "not applied") out = o;
    }
    return out;
  }

  /// The inverse of QuadrupleVia::CollapseSplit: an interior edge (u, v) of regular vertices
  /// whose opposite vertices are the two v7 of the quadruple; collapsing v into u makes a v8
  /// and the two v7 regular; the v8 then splits along its edges to the two v5, three edges
  /// on each side, which makes them regular and both halves regular.
  std::vector<AtomicPrediction> CollapseSplitRemovals(const std::vector<int>& quad, const std::string& what) {
    std::vector<AtomicPrediction> out;
    std::vector<int> fives, sevens;
    for (int v : quad) (ed_.Valence(v) == 5 ? fives : sevens).push_back(v);
    if (fives.size() != 2 || sevens.size() != 2) return out;
    VertexStar<MeshType> s7 = ed_.Star(sevens[0]);
    for (VertexType* uv : s7.neighbors) {
      const int u = ed_.Index(uv);
      for (VertexType* vv : ed_.Star(u).neighbors) {
        const int v = ed_.Index(vv);
        if (v <= u || ed_.InteriorValence(u) != 6 || ed_.InteriorValence(v) != 6) continue;
        int o[2];
        if (!ed_.Opposites(u, v, o)) continue;
        if (!((o[0] == sevens[0] && o[1] == sevens[1]) || (o[0] == sevens[1] && o[1] == sevens[0]))) continue;
        // u's ring after collapsing v into u: u's ring with v replaced by v's ring from the
        // vertex after u to the vertex before u (both counter-clockwise).
        std::vector<int> ru, rv, merged;
        for (VertexType* w : ed_.Star(u).neighbors) ru.push_back(ed_.Index(w));
        for (VertexType* w : ed_.Star(v).neighbors) rv.push_back(ed_.Index(w));
        const int iu = int(std::find(rv.begin(), rv.end(), u) - rv.begin());
        for (int w : ru) {
          if (w != v) {
            merged.push_back(w);
            continue;
          }
          for (int k = 2; k < 5; ++k) merged.push_back(rv[size_t((iu + k) % 6)]);
        }
        if (merged.size() != 8) continue;
        const int a = int(std::find(merged.begin(), merged.end(), fives[0]) - merged.begin());
        const int b = int(std::find(merged.begin(), merged.end(), fives[1]) - merged.begin());
        if (a >= 8 || b >= 8 || (a - b + 8) % 8 != 4) continue;
        AtomicPrediction p;
        p.steps = {StepCollapse(v, u), StepSplit(u, fives[0], fives[1])};
        const int created = NextCreated(0);
        p.changes = {{u, 6}, {v, 0}, {created, 6}, {fives[0], 6}, {fives[1], 6}, {sevens[0], 6}, {sevens[1], 6}};
        p.created = {created};
        p.deleted = {v};
        p.description = what + ": collapse vertex " + std::to_string(v) + " into " + std::to_string(u) +
                        " (a v8), then " + p.steps[1].Describe();
        p.result = Result::Ok();
        p = Check(std::move(p));
        if (p) out.push_back(p);
      }
    }
    return out;
  }

 public:
  /// Predicts the valence changes of every flip, collapse (and, if withSplits, vertex split)
  /// around the group (its vertices and their neighbours) without editing (sec. 6.1 rules),
  /// and applies the first, in a deterministic order, whose prediction passes `test(before,
  /// after)` and whose group vertices are all touched. In `after`, a deleted vertex has valence
  /// 0 and a vertex created by a split has index -1. O(size of the neighbourhood squared).
  AtomicOutcome FindAndApply(const std::vector<int>& group, const ChangeTest& test, const std::string& what,
                             bool withSplits = true, int minIrregularBefore = 0) {
    AtomicOutcome out = ApplyFirst(Candidates(group, test, what, withSplits, minIrregularBefore));
    if (!out) return Refuse(out, "no single flip, collapse or split around these vertices does it");
    return out;
  }

  /// Applies the first of the candidates (Candidates, the dry run) that applies, as
  /// FindAndApply does: for a caller that asks the dry run first and prepares the edit (its
  /// guard) only when there is something to apply.
  AtomicOutcome ApplyFirst(const std::vector<AtomicPrediction>& cands) {
    AtomicOutcome last;
    last.result = Result::Fail("no single flip, collapse or split around these vertices does it");
    for (const AtomicPrediction& c : cands) {
      AtomicOutcome o = Apply(c);
      if (o) return o;
      last = o;
    }
    return last;
  }

  /// The dry run of FindAndApply: every candidate whose predicted valence changes pass
  /// `test` and whose first graph operation passes its Can* check, in the order FindAndApply
  /// tries them. A created vertex has its predicted index (m.vert.size()).
  /// minIrregularBefore: a candidate whose vertices before hold fewer irregular vertices
  /// (valence != 6) is dropped before `test` is asked; a test that can only pass with at least
  /// that many (a removal of two: LocalCancellation::Reduces) gets the same candidates, without
  /// building the two valence lists of every candidate it would refuse (most of them: a
  /// step around a lone irregular vertex touches no other).
  std::vector<AtomicPrediction> Candidates(const std::vector<int>& group, const ChangeTest& test,
                                           const std::string& what, bool withSplits = true,
                                           int minIrregularBefore = 0) {
    std::vector<AtomicPrediction> result;
    std::vector<int> area = group;
    for (int v : group) {
      if (!ed_.IsLive(v)) return result;
      VertexStar<MeshType> s = ed_.Star(v);
      for (VertexType* n : s.neighbors) area.push_back(ed_.Index(n));
    }
    std::sort(area.begin(), area.end());
    area.erase(std::unique(area.begin(), area.end()), area.end());
    // each valence walked once per call, remembered in a stamped array (no map, no allocation
    // per call: the array grows with the mesh only)
    const size_t nv = ed_.Mesh().vert.size();
    valenceSeen_.Begin(nv);
    if (valenceOf_.size() < nv) valenceOf_.resize(std::max(nv, 2 * valenceOf_.size()));
    auto val = [&](int v) {
      if (valenceSeen_.Insert(size_t(v))) valenceOf_[size_t(v)] = ed_.Valence(v);
      return valenceOf_[size_t(v)];
    };
    struct Scored {
      GraphStep c;
      int o[2];
      int d1, d2;
    };
    // Only a step whose touched vertices cover the whole group can change all of it: the
    // others are dropped as they are enumerated (most of them; no allocation for those).
    auto covers = [&](int a, int b, int c, int d) {
      for (int g : group)
        if (g != a && g != b && g != c && g != d) return false;
      return true;
    };
    std::vector<Scored> cands;
    for (int v : area) {
      VertexStar<MeshType> s = ed_.Star(v);
      if (s.boundary) continue;
      const int d = int(s.neighbors.size());
      for (int k = 0; k < d; ++k) {
        const int w = ed_.Index(s.neighbors[size_t(k)]);
        if (w > v) {  // each edge once; a collapse removes the higher index
          Scored sc;
          sc.o[0] = ed_.Index(s.neighbors[size_t((k + 1) % d)]);
          sc.o[1] = ed_.Index(s.neighbors[size_t((k + d - 1) % d)]);
          sc.d1 = sc.d2 = 0;
          if (covers(v, w, sc.o[0], sc.o[1])) {
            sc.c = StepFlip(v, w);
            cands.push_back(sc);
            sc.c = StepCollapse(w, v);
            cands.push_back(sc);
          }
        }
        if (!withSplits) continue;
        for (int l = 0; l < d; ++l) {
          if (l == k) continue;
          const int u = ed_.Index(s.neighbors[size_t(l)]);
          if (!covers(v, w, u, u)) continue;
          Scored sc;
          sc.c = StepSplit(v, w, u);
          sc.d1 = ((l - k - 1) % d + d) % d;  // neighbours strictly between a = n_k and b = n_l
          sc.d2 = d - 2 - sc.d1;
          sc.o[0] = sc.o[1] = -1;
          cands.push_back(sc);
        }
      }
    }
    const int created = NextCreated(0);
    // Flat arrays (valence_changes.h): most candidates fail the test, and as std::maps the two
    // cost a tenth of Automatic Reduction's time in node copies.
    ValenceChanges before, pred;
    for (const Scored& sc : cands) {
      const GraphStep& c = sc.c;
      const int* o = sc.o;
      if (minIrregularBefore > 0) {
        const int n = c.kind == GraphStep::kSplit ? (val(c.x) != 6) + (val(c.y) != 6) + (val(c.z) != 6)
                                                  : (val(c.x) != 6) + (val(c.y) != 6) + (val(o[0]) != 6) +
                                                        (o[1] != o[0] && val(o[1]) != 6);
        if (n < minIrregularBefore) continue;
      }
      if (c.kind == GraphStep::kSplit)
        before = {{c.x, val(c.x)}, {c.y, val(c.y)}, {c.z, val(c.z)}};
      else
        before = {{c.x, val(c.x)}, {c.y, val(c.y)}, {o[0], val(o[0])}, {o[1], val(o[1])}};
      const int dx = val(c.x), dy = val(c.y);
      if (c.kind == GraphStep::kFlip) {
        pred = {{c.x, dx - 1}, {c.y, dy - 1}, {o[0], val(o[0]) + 1}, {o[1], val(o[1]) + 1}};
      } else if (c.kind == GraphStep::kCollapse) {
        pred = {{c.x, 0}, {c.y, dx + dy - 4}, {o[0], val(o[0]) - 1}, {o[1], val(o[1]) - 1}};
      } else {
        pred = {{c.x, sc.d1 + 3}, {-1, sc.d2 + 3}, {c.y, dy + 1}, {c.z, val(c.z) + 1}};
      }
      if (!test(before, pred)) continue;
      AtomicPrediction p;
      p.steps = {c};
      if (describe_)
        p.description = what + ": " + (c.kind == GraphStep::kSplit
                                           ? Str("split vertex ", c.x, " along edges to ", c.y, " and ", c.z)
                                           : c.Describe());
      if (c.kind == GraphStep::kSplit) {
        pred[created] = pred[-1];
        pred.erase(-1);
        p.created = {created};
      }
      if (c.kind == GraphStep::kCollapse) p.deleted = {c.x};
      p.changes = pred;
      for (auto& kv : pred)
        if (kv.second != 6 && kv.second != 0) p.irregular.push_back(kv.first);
      p.result = Result::Ok();
      p = Check(std::move(p));
      if (p) result.push_back(std::move(p));
    }
    return result;
  }

  /// Gives back the per-vertex scratch of Candidates (a later call grows it again).
  void ReleaseScratch() {
    valenceSeen_.Release();
    std::vector<int>().swap(valenceOf_);
  }

 private:
  /// Str(args...) when describing (SetDescribing), else an empty string without formatting.
  template <class... Args>
  std::string Say(const Args&... args) const {
    return describe_ ? Str(args...) : std::string();
  }

  Editor& ed_;
  bool describe_ = true;
  StampSet valenceSeen_;        ///< Candidates: the vertices whose valence it has walked
  std::vector<int> valenceOf_;  ///< ... and their valences
};

}  // namespace irregular
}  // namespace vcg_ext
