// filter_irregular: composite semantic operations (paper sec. 6.3 and 7), built from the
// atomic operations of atomic_ops.h.
//
//  * Type change (sec. 6.3): split a vk (k > 7) into k-6 v7, a v4 (v3) into two (three) v5;
//    aggregation back: a group of v7 (v5) becomes one higher (lower) valence vertex.
//  * Pair movement (sec. 7.1): an adjacent 5-7 pair moves n steps along a straight line;
//    a non-adjacent 5-7, 5-5 or 7-7 pair moves by the three-step pipeline of sec. 7.1.1:
//    (1) one vertex moves one step and generates a 5-7 pair, (2) the generated pair is
//    transported to the partner along the connecting path of two separatrix segments and
//    their turn point (separatrix.h), (3) it cancels there, moving the partner one step.
//  * Triple cancellation (sec. 7.2): a 5-7 pair of the triple is transported to the third
//    vertex until the atomic removal applies; quadruple cancellation (sec. 7.3) likewise.
//  * Generation (sec. 7.3): the inverse of cancellation; the new vertices are placed n steps
//    apart.
// Every composite operation is all or nothing: on failure the journal restores the mesh.
// Each step is followed, optionally, by local relaxation of its 2-ring (sec. 8), which keeps
// the triangles usable so the next step's fold check passes.
#pragma once

#include <algorithm>
#include <functional>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "atomic_ops.h"
#include "attribute_transfer.h"
#include "relaxation.h"
#include "separatrix.h"
#include "type_change.h"

namespace vcg_ext {
namespace irregular {

struct CompositeOptions {
  bool relax = true;           ///< local relaxation of the 2-ring after every atomic step
  int relaxIterations = 3;     ///< sweeps per step
  int maxTransportSteps = 200; ///< bound on pair steps while transporting toward a partner
  const std::vector<char>* crease = nullptr;  ///< per vertex index, 1 = never moved by the relaxation (the
                                              ///< automatic reduction's crease lines); null: none
  std::function<void(int, const char*)> progress;  ///< (percent, message), may be empty
};

struct CompositeOutcome {
  Result result = Result::Fail("not applied");
  std::vector<int> irregular;  ///< the irregular vertices the operation leaves (every caller's
                               ///< list; the named fields below say which is which)
  int atomicSteps = 0;         ///< atomic operations applied
  std::string log;             ///< one line per step
  // Named results (-1 when the operation does not produce them):
  int lead = -1;      ///< pair movement: where the lead vertex ended
  int partner = -1;   ///< pair movement: where the partner ended
  int survivor = -1;  ///< triple cancellation: the vertex left (a v5 for 5-5-7, a v7 for 5-7-7);
                      ///< triple generation: the moved v5 / v7
  int pair5 = -1, pair7 = -1;  ///< generation: the generated 5-7 pair (triple), or the pair that
                               ///< moved away (quadruple)
  int other5 = -1, other7 = -1;  ///< quadruple generation: the pair that stayed
  explicit operator bool() const { return result.ok; }
};

/// SeparatrixTracer::Connect(a, b, maxLength), the same path, by iterative deepening:
/// Connect traces every ray of a and b to its bound, so a full call costs
/// (d(a) + d(b)) * maxLength star queries even for vertices a few edges apart. Here Connect
/// runs with segment bounds 8, 32, 128, ... and stops at the first bound B that holds the
/// path found (Length() <= B): every path as short, and the same tie-break order, lies within
/// B, so the full call finds the same path - with one exception, checked: Connect remembers
/// only the first ray of a (in star order) to reach each vertex, so where a ray of a wraps
/// around a closed surface and crosses the path beyond B, the full call sees that crossing
/// instead. The rays of a before the path's own are traced to maxLength for it; if one
/// meets the path beyond B, the full call is made. Cost O((d(a) + d(b)) * L) for a path of
/// length L, plus up to d(a) full rays; at most about 2 full calls when there is no path.
template <class MeshType>
ConnectingPath ConnectByDeepening(SeparatrixTracer<MeshType>& tracer, MeshType& m, int a, int b, int maxLength) {
  for (int bound = std::min(8, maxLength);; bound = std::min(maxLength, 4 * bound)) {
    ConnectingPath p = tracer.Connect(a, b, bound);
    if (bound >= maxLength) return p;
    if (!p || p.Length() > bound) continue;
    // the exception: a ray of a before the path's first edge that meets the path beyond the
    // bound (Connect's loop over a's rays: up to b, the last vertex only if regular)
    const std::vector<int> path = p.Vertices();
    const VertexStar<MeshType> star = StarOf<MeshType>(&m.vert[size_t(a)]);
    const int own = star.IndexOf(&m.vert[size_t(path[1])]);
    bool crossed = false;
    for (int r = 0; r < own && !crossed; ++r) {
      const Separatrix ray = tracer.Trace(a, int(vcg::tri::Index(m, star.neighbors[size_t(r)])), maxLength);
      const bool lastIsRegular = ray.end == Separatrix::End::MaxLength || ray.end == Separatrix::End::Loop;
      for (int i = 1; i <= ray.Length() && !crossed; ++i) {
        const int v = ray.vertices[size_t(i)];
        if (v == b || (i == ray.Length() && !lastIsRegular)) break;
        crossed = i > bound && std::find(path.begin(), path.end(), v) != path.end();
      }
    }
    return crossed ? tracer.Connect(a, b, maxLength) : p;
  }
}

template <class MeshType>
class CompositeOperations {
 public:
  typedef MeshEditor<MeshType> Editor;
  typedef typename MeshType::CoordType CoordType;

  CompositeOperations(Editor& ed, const SurfaceProjector* original, CompositeOptions opt = CompositeOptions())
      : ed_(ed), ops_(ed), original_(original), opt_(opt) {}

  AtomicOperations<MeshType>& atomic() { return ops_; }

  // ------------------------------------------------------------ type change (sec. 6.3)
  /// Splits v (valence k > 7) into k-6 v7, or a v4 (v3) into two (three) v5 (type_change.h:
  /// the chain configuration, the collapse configuration), in the first orientation that keeps
  /// every other irregular vertex unchanged; failing that, one that absorbs neighbouring
  /// irregular vertices into regular ones. After it v is replaced by v5s or v7s only.
  /// out.irregular: the v7s (v5s) produced. A v5, v6 or v7 is left as it is.
  CompositeOutcome ReduceTo57(int v) {
    CompositeOutcome out;
    auto cp = ed_.Mark();
    if (!ed_.IsLive(v) || ed_.IsBoundary(v)) return Fail(out, cp, Str("vertex ", v, " is not an interior vertex"));
    const int d = ed_.Valence(v);
    if (d == 5 || d == 6 || d == 7) {
      out.result = Result::Ok();
      if (d != 6) out.irregular = {v};
      return out;
    }
    TypeChange<MeshType> tc(ed_);
    auto hook = [&](const std::string& what, const std::vector<int>& around) {
      ++out.atomicSteps;
      Step(out, what, around);
    };
    TypeSplitRequest req;
    req.vertex = v;
    TypeChangeOutcome o = tc.TypeSplit(req, hook);
    if (!o) {
      out.atomicSteps = 0;
      out.log.clear();
      req.absorb = true;
      TypeChangeOutcome lenient = tc.TypeSplit(req, hook);
      if (!lenient) return Fail(out, cp, o.status.reason);
      o = lenient;
    }
    out.irregular = o.produced;
    out.result = Result::Ok();
    return out;
  }

  /// Aggregation, the inverse of type splitting (type_change.h): the selected v7s become one
  /// v(6+n) by collapses merging two or three at a time, two v5 a v4 and three v5 a v3 by one
  /// split. out.irregular: the aggregate.
  CompositeOutcome Aggregate(const std::vector<int>& group) {
    CompositeOutcome out;
    auto cp = ed_.Mark();
    TypeChange<MeshType> tc(ed_);
    AggregationRequest req;
    req.group = group;
    TypeChangeOutcome o = tc.Aggregate(req, [&](const std::string& what, const std::vector<int>& around) {
      ++out.atomicSteps;
      Step(out, what, around);
    });
    if (!o) return Fail(out, cp, o.status.reason);
    out.irregular = {o.resultVertex};
    out.result = Result::Ok();
    return out;
  }

  // ------------------------------------------------------------ pair movement (sec. 7.1)
  /// Moves an adjacent 5-7 pair `steps` steps: the first step goes in direction `dir`
  /// (atomic_ops.h convention), the next ones continue in the same direction on the surface
  /// (the step that best continues the first displacement). O(steps).
  CompositeOutcome MoveAdjacentPair57(int v5, int v7, int dir, int steps) {
    CompositeOutcome out;
    auto cp = ed_.Mark();
    CoordType heading(0, 0, 0);  // the last step's displacement: "straight on" on a curved surface
    for (int s = 0; s < steps; ++s) {
      Progress(100 * s / std::max(1, steps), "Moving the 5-7 pair");
      AtomicOutcome o;
      if (s == 0) {
        const CoordType before = Mid(v5, v7);
        o = ops_.MovePair57(v5, v7, dir);
        if (o) heading = Mid(o.irregular[0], o.irregular[1]) - before;
      } else {
        // Repeating the same atomic move parallel-transports the pair (sec. 6.2, fig. 6); when
        // that is blocked, take the move that best continues the way so far.
        const CoordType before = Mid(v5, v7);
        o = ops_.MovePair57(v5, v7, dir);
        if (!o) o = BestStep(v5, v7, heading);
        if (o) {
          CoordType d = Mid(o.irregular[0], o.irregular[1]) - before;
          if (d.Norm() > 0) heading = heading.Normalize() + d.Normalize();
        }
      }
      if (!o) return Fail(out, cp, Str("step ", s + 1, " of ", steps, ": ", o.result.reason));
      ++out.atomicSteps;
      v5 = o.irregular[0];
      v7 = o.irregular[1];
      Step(out, o.description, {v5, v7});
    }
    out.irregular = {v5, v7};
    out.result = Result::Ok();
    return out;
  }

  /// Moves an adjacent 5-7 pair step by step toward a point (e.g. picked on the surface) until
  /// no step brings it closer, at most maxTransportSteps steps.
  CompositeOutcome MovePair57Toward(int v5, int v7, CoordType target) {
    CompositeOutcome out;
    auto cp = ed_.Mark();
    if (ed_.Valence(v5) != 5 || ed_.Valence(v7) != 7 || !ed_.Adjacent(v5, v7))
      return Fail(out, cp, "moving toward a point works on an adjacent 5-7 pair");
    for (int s = 0; s < opt_.maxTransportSteps; ++s) {
      Progress(100 * s / opt_.maxTransportSteps, "Moving the 5-7 pair toward the point");
      AtomicOutcome o = StepToward(v5, v7, target);
      if (!o) break;
      ++out.atomicSteps;
      v5 = o.irregular[0];
      v7 = o.irregular[1];
      Step(out, o.description, {v5, v7});
    }
    if (out.atomicSteps == 0) return Fail(out, cp, "the pair cannot get any closer to the point");
    out.irregular = {v5, v7};
    out.result = Result::Ok();
    return out;
  }

  /// Moves a pair (5-7, 5-5 or 7-7; adjacent or not) one step per repetition with the
  /// pipeline of sec. 7.1.1: `lead` moves one step toward its neighbour k (counted from the
  /// neighbour of smallest index; as in MoveWithPairGeneration a v5 lands on neighbour k, a
  /// v7 on neighbour k + 1) generating a 5-7 pair, the pair is transported to
  /// `partner` and cancelled there, moving the partner one step.
  /// Which step the partner makes is chosen, among the cancellations the triple admits (and
  /// the two readings of the lead's flip, fig. 7), so that
  ///  * a 5-7 pair translates (sec. 7.1.1: "the relative position of the two vertices remains
  ///    the same"): the connecting path from the lead to the partner keeps its two segment
  ///    lengths and its turn, and the partner steps the way the lead stepped;
  ///  * a 5-5 or 7-7 pair moves symmetrically (sec. 7.1.2: Δd1 = Δd3, Δd2 = Δd4): the partner
  ///    makes the mirrored step, opposite to the lead's.
  /// The step direction is compared on the surface (the two displacement vectors, at most a
  /// few edges of parallel transport apart on the connecting path). Refused, with the mesh
  /// unchanged, when no choice realises the translation of a 5-7 pair.
  /// out.lead / out.partner: where the two vertices ended. O(steps * L).
  CompositeOutcome MovePair(int lead, int partner, int k, int steps) {
    CompositeOutcome out;
    auto cp = ed_.Mark();
    for (int v : {lead, partner})
      if (!ed_.IsLive(v) || ed_.IsBoundary(v)) return Fail(out, cp, Str("vertex ", v, " is not an interior vertex"));
    const int dl = ed_.Valence(lead), dp = ed_.Valence(partner);
    if ((dl != 5 && dl != 7) || (dp != 5 && dp != 7))
      return Fail(out, cp, "pair movement works on v5 and v7 (reduce other valences first with 'Reduce to Valence 5 and 7')");
    if (dl != dp && ed_.Adjacent(lead, partner)) {
      const int v5 = dl == 5 ? lead : partner, v7 = dl == 5 ? partner : lead;
      out = MoveAdjacentPair57(v5, v7, ((k % 6) + 6) % 6, steps);
      if (out) out.lead = dl == 5 ? out.irregular[0] : out.irregular[1], out.partner = dl == 5 ? out.irregular[1] : out.irregular[0];
      return out;
    }
    for (int s = 0; s < steps; ++s) {
      Progress(100 * s / std::max(1, steps), "Moving the pair");
      Result r = PipelineStep(out, lead, partner, k);
      if (!r) return Fail(out, cp, Str("step ", s + 1, " of ", steps, ": ", r.reason));
    }
    out.irregular = {lead, partner};
    out.lead = lead;
    out.partner = partner;
    out.result = Result::Ok();
    return out;
  }

  // ------------------------------------------------------------ cancellation (sec. 7.2, 7.3)
  /// Cancels a 5-5-7 triple into one v5 or a 5-7-7 triple into one v7 (sec. 7.2). Let v be
  /// the vertex of the odd valence (the v7 of 5-5-7), u the other vertex nearer to it, w the
  /// third one:
  ///  (1) the 5-7 pair (u, v) moves toward w (adjacent: atomic moves, fig. 6; not adjacent:
  ///      the pipeline of sec. 7.1.1, translating the pair) until v is adjacent to w;
  ///  (2) the adjacent 5-7 pair (v, w) moves toward u until the atomic removal applies;
  ///  (3) the atomic v5 (v7) movement and 5-7 removal leaves one vertex: out.survivor.
  /// So three mutually non-adjacent vertices can be cancelled. All or nothing.
  CompositeOutcome CancelTriple(const std::vector<int>& triple) {
    CompositeOutcome out;
    auto cp = ed_.Mark();
    if (triple.size() != 3) return Fail(out, cp, "a triple cancellation needs exactly three vertices");
    std::vector<int> d;
    for (int v : triple) {
      if (!ed_.IsLive(v) || ed_.IsBoundary(v)) return Fail(out, cp, Str("vertex ", v, " is not an interior vertex"));
      d.push_back(ed_.Valence(v));
    }
    std::vector<int> sd = d;
    std::sort(sd.begin(), sd.end());
    if (sd != std::vector<int>{5, 5, 7} && sd != std::vector<int>{5, 7, 7})
      return Fail(out, cp, "a triple cancellation needs a 5-5-7 or a 5-7-7 triple");
    if (Finish3(out, triple)) return out;
    const int odd = sd[1] == 5 ? 7 : 5;
    int v = -1;
    std::vector<int> same;
    for (int x : triple) {
      if (v < 0 && ed_.Valence(x) == odd) v = x;
      else same.push_back(x);
    }
    if (same.size() != 2) return Fail(out, cp, "internal: the triple has no vertex of the odd valence");
    auto dist = [&](int a, int b) { return double((ed_.V(a)->P() - ed_.V(b)->P()).Norm()); };
    int u = same[0], w = same[1];
    if (ed_.Adjacent(v, w) || (!ed_.Adjacent(v, u) && dist(v, w) < dist(v, u))) std::swap(u, w);
    // now u is adjacent to v, or (neither adjacent) the nearer one
    if (!ed_.Adjacent(v, w)) {
      // phase 1: the pair (u, v) travels to w
      Result r = ed_.Adjacent(u, v) ? MoveAdjacentPairNextTo(out, u, v, w) : MovePairNextTo(out, u, v, w);
      if (!r) return Fail(out, cp, Str("moving the 5-7 pair (", u, ", ", v, ") to vertex ", w, ": ", r.reason));
      if (out.survivor >= 0) return Done3(out);
    }
    // phase 2: the adjacent pair (v, w) travels to u and the triple cancels there
    int p5 = ed_.Valence(v) == 5 ? v : w, p7 = p5 == v ? w : v;
    int survivor = -1;
    Result t = TransportAndCancel(out, p5, p7, u, &survivor);
    if (!t) return Fail(out, cp, t.reason);
    out.survivor = survivor;
    return Done3(out);
  }

  /// Cancels a 5-5-7-7 quadruple made of two adjacent 5-7 pairs: one pair is transported to
  /// the other until the atomic quadruple removal applies. Refused when the two pairs cannot
  /// annihilate (sec. 7.3: opposite sides of the enclosing polygon must match).
  CompositeOutcome CancelQuadruple(const std::vector<int>& quad) {
    CompositeOutcome out;
    auto cp = ed_.Mark();
    if (quad.size() != 4) return Fail(out, cp, "a quadruple cancellation needs exactly four vertices");
    std::vector<int> v5, v7;
    for (int v : quad) {
      if (!ed_.IsLive(v) || ed_.IsBoundary(v)) return Fail(out, cp, Str("vertex ", v, " is not an interior vertex"));
      (ed_.Valence(v) == 5 ? v5 : v7).push_back(v);
      if (ed_.Valence(v) != 5 && ed_.Valence(v) != 7) return Fail(out, cp, "a quadruple is two v5 and two v7");
    }
    if (v5.size() != 2) return Fail(out, cp, "a quadruple is two v5 and two v7");
    const std::vector<int> quad0 = quad;
    // fig. 11's polygon of the quadruple as selected, reported when the cancellation fails
    // (measured on the mesh, whose other irregular vertices bend the straight paths, so it
    // explains a failure rather than predicting one)
    SeparatrixTracer<MeshType> tracer(ed_.Mesh());
    const QuadruplePolygon before = tracer.Polygon(quad0, opt_.maxTransportSteps);
    {
      AtomicOutcome r = ops_.RemoveQuadruple(quad);
      if (r) {
        ++out.atomicSteps;
        Step(out, r.description, {});
        out.result = Result::Ok();
        return out;
      }
    }
    // pair up: (v5[0], partner) adjacent, the other pair adjacent too
    int a5 = v5[0], b5 = v5[1], a7 = -1, b7 = -1;
    if (ed_.Adjacent(a5, v7[0]) && ed_.Adjacent(b5, v7[1])) a7 = v7[0], b7 = v7[1];
    else if (ed_.Adjacent(a5, v7[1]) && ed_.Adjacent(b5, v7[0])) a7 = v7[1], b7 = v7[0];
    if (a7 < 0) return Fail(out, cp, "the quadruple must consist of two adjacent 5-7 pairs; move them into pairs first");
    // transport pair (a5, a7) to (b5, b7) until the removal applies
    Result t = Transport(out, a5, a7, {b5, b7}, [&]() {
      AtomicOutcome r = ops_.RemoveQuadruple({a5, a7, b5, b7});
      if (!r) return false;
      ++out.atomicSteps;
      Step(out, r.description, {a5, b5});
      return true;
    });
    if (t) {
      out.result = Result::Ok();
      return out;
    }
    // Say what happened: the pairs met and do not annihilate (fig. 11's condition), or the
    // transport was blocked or hit the step cap before they met.
    bool met = false;
    for (int x : {a5, a7})
      for (int y : {b5, b7}) met = met || (ed_.IsLive(x) && ed_.IsLive(y) && (x == y || ed_.Adjacent(x, y)));
    const std::string sides = before.result.ok ? " The connecting paths of the quadruple as selected, (x_i, y_i) = " +
                                           before.Sides() +
                                           (before.OppositeSidesMatch() ? ", do match on opposite sides."
                                                                        : ", do not match on opposite sides.")
                                     : std::string();
    if (!met)
      return Fail(out, cp, "the 5-7 pair (" + Str(quad0[0]) + "...) could not be brought to the other pair: " + t.reason +
                               "." + sides);
    return Fail(out, cp, "the two 5-7 pairs met but do not annihilate (" + t.reason +
                             "): they are not in the configuration of fig. 11 (sec. 7.3: the four connecting paths must "
                             "form a polygon whose opposite sides match, x_i = x_{i+2}, y_i = y_{i+2}; otherwise one 5-7 "
                             "pair could be removed alone, which Theorem 5.5 forbids)." + sides);
  }

  // ------------------------------------------------------------ generation with a shape
  /// Moves the adjacent 5-7 pair exactly `steps` times by the same atomic move `dir` (fig. 6:
  /// repeating a move parallel-transports the pair along a straight line); fails, without
  /// substituting another move, where that move is blocked.
  Result MoveStraight(CompositeOutcome& out, int& p5, int& p7, int dir, int steps) {
    for (int s = 0; s < steps; ++s) {
      AtomicOutcome o = ops_.MovePair57(p5, p7, dir);
      if (!o) return Result::Fail(Str("step ", s + 1, " of ", steps, " in direction ", dir, ": ", o.result.reason));
      ++out.atomicSteps;
      p5 = o.irregular[0];
      p7 = o.irregular[1];
      Step(out, o.description, {p5, p7});
    }
    return Result::Ok();
  }

  /// Sec. 7.3, fig. 11: a regular vertex becomes a 5-5-7-7 quadruple (atomic flip, fig. 8)
  /// whose second 5-7 pair is then placed exactly: `x` atomic steps in pair direction dirX,
  /// then `y` in direction dirY (atomic_ops.h's pair directions, 0..5 around the v5 from the
  /// v7). The four vertices then span the parallelogram of fig. 11 with sides (x, y) and the
  /// pair's edge, whose opposite sides match by construction, so CancelQuadruple can undo it.
  /// out.pair5/pair7: the moved pair; out.other5/other7: the pair that stayed.
  CompositeOutcome GenerateQuadrupleShape(int v, int k, int dirX, int x, int dirY, int y) {
    CompositeOutcome out;
    auto cp = ed_.Mark();
    AtomicOutcome g = ops_.GenerateQuadruple(v, k, false);
    if (!g) return Fail(out, cp, g.result.reason);
    ++out.atomicSteps;
    Step(out, g.description, g.irregular);
    // g.irregular = {p, n_k, n_k-1, n_k+1}: pairs (p, n_k-1) and (n_k, n_k+1)
    int a5 = g.irregular[0], a7 = g.irregular[2];
    const int b5 = g.irregular[1], b7 = g.irregular[3];
    Result r = MoveStraight(out, a5, a7, dirX, x);
    if (r) r = MoveStraight(out, a5, a7, dirY, y);
    if (!r) return Fail(out, cp, Str("placing the generated 5-7 pair: ", r.reason));
    for (int keep : {b5, b7})
      if (!ed_.IsLive(keep) || (ed_.Valence(keep) != 5 && ed_.Valence(keep) != 7))
        return Fail(out, cp, "the moved pair ran into the pair that stayed: choose other directions or longer sides");
    out.irregular = {a5, a7, b5, b7};
    out.pair5 = a5, out.pair7 = a7, out.other5 = b5, out.other7 = b7;
    out.result = Result::Ok();
    return out;
  }

  // ------------------------------------------------------------ generation (sec. 7.3)
  /// A v5 (v7) becomes a 5-5-7 (5-7-7) triple; the generated 5-7 pair is moved `spacing`
  /// steps away from it. k: direction as in MoveWithPairGeneration.
  CompositeOutcome GenerateTriple(int v, int k, int spacing) {
    CompositeOutcome out;
    auto cp = ed_.Mark();
    AtomicOutcome g = ops_.MoveWithPairGeneration(v, k);
    if (!g) return Fail(out, cp, g.result.reason);
    ++out.atomicSteps;
    Step(out, g.description, g.irregular);
    int p5 = -1, p7 = -1;
    for (size_t i = 1; i < g.irregular.size(); ++i) (ed_.Valence(g.irregular[i]) == 5 ? p5 : p7) = g.irregular[i];
    if (!MoveApart(out, p5, p7, g.irregular[0], spacing)) return Fail(out, cp, out.result.reason);
    out.irregular = {g.irregular[0], p5, p7};
    out.survivor = g.irregular[0], out.pair5 = p5, out.pair7 = p7;
    out.result = Result::Ok();
    return out;
  }

  /// A regular vertex becomes a 5-5-7-7 quadruple; one of its 5-7 pairs is moved `spacing`
  /// steps away from the other.
  CompositeOutcome GenerateQuadruple(int v, int k, int spacing) {
    CompositeOutcome out;
    auto cp = ed_.Mark();
    AtomicOutcome g = ops_.GenerateQuadruple(v, k, false);
    if (!g) return Fail(out, cp, g.result.reason);
    ++out.atomicSteps;
    Step(out, g.description, g.irregular);
    // g.irregular = {p, n_k, n_k-1, n_k+1}: pairs (p, n_k-1) and (n_k, n_k+1)
    int a5 = g.irregular[0], a7 = g.irregular[2], b5 = g.irregular[1], b7 = g.irregular[3];
    if (!MoveApart(out, a5, a7, Mid(b5, b7), spacing, {b5, b7})) return Fail(out, cp, out.result.reason);
    out.irregular = {a5, a7, b5, b7};
    out.pair5 = a5, out.pair7 = a7, out.other5 = b5, out.other7 = b7;
    out.result = Result::Ok();
    return out;
  }

 private:
  CompositeOutcome& Fail(CompositeOutcome& out, typename Editor::Checkpoint cp, const std::string& why) {
    ed_.RollbackTo(cp);
    out.result = Result::Fail(why);
    out.irregular.clear();
    return out;
  }

  void Progress(int pct, const char* what) {
    if (opt_.progress) opt_.progress(pct, what);
  }

  void Step(CompositeOutcome& out, const std::string& what, const std::vector<int>& around) {
    out.log += what + "\n";
    RelaxAround(around);
  }

  void RelaxAround(const std::vector<int>& seeds) {
    if (!opt_.relax || seeds.empty()) return;
    std::vector<int> live;
    for (int v : seeds)
      if (ed_.IsLive(v)) live.push_back(v);
    RelaxOptions ro;
    ro.iterations = opt_.relaxIterations;
    // Relaxation moves positions only; journal them so a failed composite rolls back exactly.
    std::vector<int> ring = KRing(ed_.Mesh(), live, 2);
    for (int v : ring) ed_.journal().SaveVertex(ed_.V(v));
    for (int v : ring)
      for (auto& c : ed_.Star(v).corners) ed_.journal().SaveFace(c.f);
    // texture coordinates re-sampled where the vertices moved to (the faces are journaled)
    AttributeResampler<MeshType> texture(ed_.Mesh(), ring);
    LocalRelax(ed_.Mesh(), ring, original_, ro, opt_.crease);
    texture.Resample();
  }

  CoordType Mid(int a, int b) { return (ed_.V(a)->P() + ed_.V(b)->P()) / 2; }

  /// Tries the six atomic moves of the 5-7 pair (each rolled back) and applies the one with
  /// the highest score(outcome) above `floor` (ties: the lower direction); fails with
  /// `whyNone` when no move scores above it. 7 atomic moves.
  AtomicOutcome BestMove(int v5, int v7, const std::function<double(const AtomicOutcome&)>& score, double floor,
                         const std::string& whyNone) {
    int best = -1;
    double bestScore = floor;
    for (int dir = 0; dir < 6; ++dir) {
      auto cp = ed_.Mark();
      AtomicOutcome o = ops_.MovePair57(v5, v7, dir);
      if (o) {
        const double sc = score(o);
        if (sc > bestScore) bestScore = sc, best = dir;
      }
      ed_.RollbackTo(cp);
    }
    if (best < 0) {
      AtomicOutcome none;
      none.result = Result::Fail(whyNone);
      return none;
    }
    return ops_.MovePair57(v5, v7, best);
  }

  /// The atomic pair move whose displacement best continues `heading`.
  AtomicOutcome BestStep(int v5, int v7, const CoordType& heading) {
    const CoordType from = Mid(v5, v7);
    return BestMove(v5, v7, [&](const AtomicOutcome& o) {
      CoordType d = Mid(o.irregular[0], o.irregular[1]) - from;
      return double(d.dot(heading)) / (double(d.Norm()) * double(heading.Norm()) + 1e-30);
    }, -std::numeric_limits<double>::max(),
       "the pair is blocked in every direction (irregular vertices or folds around it)");
  }

  /// The atomic pair move that brings the pair's midpoint closest to target; never onto the
  /// vertices of `avoid`.
  // `target` by value: callers pass a vertex position, and a vertex split reallocates the
  // vertex vector under it.
  AtomicOutcome StepToward(int v5, int v7, CoordType target, const std::vector<int>& avoid = {}) {
    return BestMove(v5, v7, [&](const AtomicOutcome& o) {
      for (int a : avoid)
        if (!ed_.IsLive(a)) return -std::numeric_limits<double>::max();
      return -double((Mid(o.irregular[0], o.irregular[1]) - target).Norm());
    }, -double((Mid(v5, v7) - target).Norm()),
       "the 5-7 pair cannot get closer (blocked by irregular vertices, folds, or already as close as it can)");
  }

  // ------------------------------------------------------------ the sec. 7.1.1 pipeline
  /// Bonus a 5-7 pair's candidate gets when the connecting path keeps its shape (a translation).
  static constexpr double kShapeKept = 10.0;

  /// The atomic removal of the triple `group` (a 5-7 pair next to a third vertex, fig. 7 read
  /// backwards) whose survivor passes acceptSurvivor(key): key is the survivor's vertex index,
  /// or -1 for a vertex a split would create. Same test as AtomicOperations::MoveWithPairRemoval
  /// (two of the three disappear, one vertex of the survivor's valence is left, no other
  /// irregular vertex is touched), over flips, collapses and also vertex splits (fig. 7 read
  /// backwards turns its collapses into splits, sec. 6.2; MoveWithPairRemoval tries no split).
  AtomicOutcome RemovalWithSurvivor(const std::vector<int>& group, const std::function<bool(int)>& acceptSurvivor) {
    if (!WithinTwoEdges(group)) {
      // FindAndApply's candidates (atomic_ops.h) must touch the whole group, and what one
      // operation touches (a flip's or a collapse's two triangles, a split's vertex and two
      // of its neighbours) lies within 2 edges of each other: no candidate exists, so its
      // enumeration (hundreds of predictions) is skipped. The common case: the transport
      // asks before every step whether the pair has arrived.
      AtomicOutcome none;
      none.result = Result::Fail("no single flip, collapse or split around these vertices does it");
      return none;
    }
    int n5 = 0;
    for (int v : group) n5 += ed_.Valence(v) == 5;
    const int survivorValence = n5 == 2 ? 5 : 7;
    return ops_.FindAndApply(group, [&](const ValenceChanges& before, const ValenceChanges& after) {
      int irregularBefore = 0, irregularAfter = 0, key = -2;
      for (auto& kv : after) {
        const int b = before.count(kv.first) ? before.at(kv.first) : 0;
        const bool inGroup = std::find(group.begin(), group.end(), kv.first) != group.end();
        if (b != 6 && b != 0) ++irregularBefore;
        if (!inGroup && b != 6 && b != 0) return false;
        if (kv.second != 6 && kv.second != 0) {
          if (kv.second != survivorValence || key != -2) return false;
          ++irregularAfter;
          key = kv.first;
        }
      }
      return irregularBefore - irregularAfter == 2 && key != -2 && acceptSurvivor(key);
    }, Str(n5 == 2 ? "5-5-7" : "5-7-7", " triple cancelled into one v", survivorValence), true);
  }

  /// Every two vertices of `group` live and at most 2 edges apart (the same, adjacent, or
  /// with a common neighbour). O(|group|^2 * valence^2).
  bool WithinTwoEdges(const std::vector<int>& group) {
    for (int v : group)
      if (!ed_.IsLive(v)) return false;
    std::vector<VertexStar<MeshType>> stars;
    for (int v : group) stars.push_back(ed_.Star(v));
    for (size_t i = 0; i < group.size(); ++i)
      for (size_t j = i + 1; j < group.size(); ++j) {
        if (group[i] == group[j] || stars[i].IndexOf(ed_.V(group[j])) >= 0) continue;
        const auto& a = stars[i].neighbors;
        const auto& b = stars[j].neighbors;
        if (std::find_first_of(a.begin(), a.end(), b.begin(), b.end()) == a.end()) return false;
      }
    return true;
  }

  /// How well the step (lead: leadFrom -> newLead, partner: partnerFrom -> newPartner) realises
  /// sec. 7.1: for a 5-7 pair (translate) the cosine between the two displacements, plus
  /// kShapeKept when the connecting path keeps its segment lengths (and its turn, when they
  /// differ); for a 5-5 or 7-7 pair minus that cosine (the mirrored step).
  double StepScore(int newLead, int newPartner, const CoordType& leadFrom, const CoordType& partnerFrom,
                   const ConnectingPath& before, bool translate) {
    const CoordType a = ed_.V(newLead)->P() - leadFrom, b = ed_.V(newPartner)->P() - partnerFrom;
    const double na = double(a.Norm()), nb = double(b.Norm());
    const double c = na > 0 && nb > 0 ? double(a.dot(b)) / (na * nb) : 0.0;
    if (!translate) return -c;
    double sc = c;
    if (before) {
      SeparatrixTracer<MeshType> tracer(ed_.Mesh());
      ConnectingPath after = ConnectByDeepening(tracer, ed_.Mesh(), newLead, newPartner, opt_.maxTransportSteps);
      if (after && after.L1() == before.L1() && after.L2() == before.L2() &&
          (before.L1() == before.L2() || after.turnTriangles == before.turnTriangles))
        sc += kShapeKept;
    }
    return sc;
  }

  /// The reading of the lead's flip (fig. 7: the same flip moves the vertex onto either of two
  /// new irregular vertices): MoveWithPairGeneration(lead, genK), with the lead landing on x.
  struct LeadFlip {
    int genK;
  };

  /// The two flips of fig. 7 that move `lead` onto its neighbour j (index from the reference).
  std::vector<LeadFlip> LeadFlips(int lead, int j) {
    const int d = ed_.Valence(lead);
    auto m = [d](int i) { return ((i % d) + d) % d; };
    // v5: flip (n_j, n_j+1) or (n_j-1, n_j); v7: flip (p, n_j-1) or (p, n_j+1)
    if (d == 5) return {LeadFlip{m(j)}, LeadFlip{m(j - 1)}};
    return {LeadFlip{m(j - 1)}, LeadFlip{m(j + 1)}};
  }

  /// Sec. 7.1.1 with one reading of the lead's flip: the lead moves onto x, the generated pair
  /// is transported to the partner, and the cancellation with the best StepScore is applied
  /// (*score). Leaves the edits applied (the caller rolls back).
  Result RunPipeline(CompositeOutcome& out, LeadFlip flip, int x, int& lead, int& partner, const ConnectingPath& before,
                     const CoordType& leadFrom, const CoordType& partnerFrom, bool translate, double* score) {
    const int dl = ed_.Valence(lead);
    AtomicOutcome g = ops_.MoveWithPairGeneration(lead, flip.genK);
    if (!g) return Result::Fail(Str("the lead vertex cannot move that way: ", g.result.reason));
    ++out.atomicSteps;
    Step(out, g.description, g.irregular);
    if (std::find(g.irregular.begin(), g.irregular.end(), x) == g.irregular.end() || ed_.Valence(x) != dl)
      return Result::Fail("the lead's flip does not move it onto that neighbour");
    int p5 = -1, p7 = -1;
    for (int v : g.irregular)
      if (v != x) (ed_.Valence(v) == 5 ? p5 : p7) = v;
    if (p5 < 0 || p7 < 0) return Result::Fail("the lead's flip did not leave a 5-7 pair");
    const int target = partner;
    int newPartner = -1;
    double best = -std::numeric_limits<double>::max();
    Result t = Transport(out, p5, p7, {target}, [&]() {
      // every cancellation of the triple, each tried and undone; the best one is re-applied
      const std::vector<int> triple{p5, p7, target};
      const int firstNew = int(ed_.Mesh().vert.size());
      std::set<int> tried;
      int bestKey = -3;
      for (int guard = 0; guard < 16; ++guard) {
        auto cp = ed_.Mark();
        AtomicOutcome r = RemovalWithSurvivor(triple, [&](int key) { return !tried.count(key); });
        if (!r) break;
        const int sv = r.irregular.empty() ? -1 : r.irregular[0];
        const int key = sv >= firstNew ? -1 : sv;
        const double sc = sv >= 0 && ed_.IsLive(x) ? StepScore(x, sv, leadFrom, partnerFrom, before, translate)
                                                  : -std::numeric_limits<double>::max();
        if (sc > best) best = sc, bestKey = key;
        ed_.RollbackTo(cp);
        tried.insert(key);
      }
      if (bestKey == -3) return false;
      AtomicOutcome r = RemovalWithSurvivor(triple, [&](int key) { return key == bestKey; });
      if (!r) return false;
      ++out.atomicSteps;
      Step(out, r.description, r.irregular);
      newPartner = r.irregular.empty() ? -1 : r.irregular[0];
      return true;
    });
    if (!t) return Result::Fail(Str("transporting the generated 5-7 pair to vertex ", target, ": ", t.reason));
    if (newPartner < 0 || !ed_.IsLive(x) || ed_.Valence(x) != dl)
      return Result::Fail("the generated pair's transport disturbed the lead vertex");
    lead = x;
    partner = newPartner;
    *score = best;
    return Result::Ok();
  }

  /// A pipeline reading's score that realises the step: the 5-7 pair keeps its shape
  /// (translation), or the partner moves by the mirror image (5-5, 7-7).
  static bool GoodEnough(bool translate, double score) {
    return translate ? score >= kShapeKept + 0.5 : score >= 0.5;
  }

  /// One step of MovePair (sec. 7.1.1): tries both readings of the lead's flip and keeps the
  /// one whose cancellation best realises the translation (5-7) or the mirrored step (5-5,
  /// 7-7). On failure the mesh is as before.
  Result PipelineStep(CompositeOutcome& out, int& lead, int& partner, int k) {
    const int dl = ed_.Valence(lead), dp = ed_.Valence(partner);
    const bool translate = dl != dp;
    // as MoveWithPairGeneration: a v5 moves onto its neighbour k, a v7 onto neighbour k + 1
    const int j = (((dl == 7 ? k + 1 : k) % dl) + dl) % dl;
    const int x = ops_.NeighbourFrom(lead, -1, j);
    if (x < 0) return Result::Fail(Str("vertex ", lead, " has no neighbour ", j));
    SeparatrixTracer<MeshType> tracer(ed_.Mesh());
    const ConnectingPath before = ConnectByDeepening(tracer, ed_.Mesh(), lead, partner, opt_.maxTransportSteps);
    const CoordType leadFrom = ed_.V(lead)->P(), partnerFrom = ed_.V(partner)->P();
    const std::vector<LeadFlip> flips = LeadFlips(lead, j);
    int bestFlip = -1;
    double bestScore = -std::numeric_limits<double>::max();
    std::string why;
    for (size_t i = 0; i < flips.size(); ++i) {
      auto cp = ed_.Mark();
      CompositeOutcome scratch;
      int l = lead, p = partner;
      double sc = 0;
      Result r = RunPipeline(scratch, flips[i], x, l, p, before, leadFrom, partnerFrom, translate, &sc);
      // The last reading tried, when it wins and is good enough, is kept as it is: re-running
      // it from the same state would rebuild the identical mesh (rollback restores every
      // element and vector size, so even the new vertices' ids repeat).
      if (r && i + 1 == flips.size() && sc > bestScore && GoodEnough(translate, sc)) {
        out.atomicSteps += scratch.atomicSteps;
        out.log += scratch.log;
        lead = l, partner = p;
        return r;
      }
      ed_.RollbackTo(cp);
      if (!r) {
        if (why.empty()) why = r.reason;
        continue;
      }
      if (sc > bestScore) bestScore = sc, bestFlip = int(i);
    }
    if (bestFlip < 0) return Result::Fail(why);
    if (translate && !GoodEnough(translate, bestScore))
      return Result::Fail(Str("no cancellation of the generated pair next to vertex ", partner,
                              " moves it by the lead's step: the 5-7 pair would not keep its relative position "
                              "(sec. 7.1.1); try another direction or lead with the other vertex"));
    if (!translate && !GoodEnough(translate, bestScore))
      return Result::Fail(Str("no cancellation next to vertex ", partner,
                              " moves it by the mirror image of the lead's step (sec. 7.1.2: a 5-5 or 7-7 pair moves "
                              "symmetrically); try another direction"));
    double sc = 0;
    auto cp = ed_.Mark();
    const int lead0 = lead, partner0 = partner;
    Result r = RunPipeline(out, flips[size_t(bestFlip)], x, lead, partner, before, leadFrom, partnerFrom, translate, &sc);
    if (!r) ed_.RollbackTo(cp), lead = lead0, partner = partner0;
    return r;
  }

  // ------------------------------------------------------------ triple cancellation helpers
  /// Applies the atomic removal when the triple is already close enough; sets out.survivor.
  bool Finish3(CompositeOutcome& out, const std::vector<int>& triple) {
    AtomicOutcome r = RemovalWithSurvivor(triple, [](int) { return true; });
    if (!r) return false;
    ++out.atomicSteps;
    Step(out, r.description, r.irregular);
    out.survivor = r.irregular.empty() ? -1 : r.irregular[0];
    Done3(out);
    return true;
  }

  CompositeOutcome& Done3(CompositeOutcome& out) {
    out.irregular = out.survivor >= 0 ? std::vector<int>{out.survivor} : std::vector<int>{};
    out.result = Result::Ok();
    return out;
  }

  /// Phase 1 of sec. 7.2 for an adjacent 5-7 pair (u, v): atomic moves toward w until v is
  /// adjacent to w (or the triple cancels: out.survivor).
  Result MoveAdjacentPairNextTo(CompositeOutcome& out, int& u, int& v, int w) {
    for (int s = 0; s < opt_.maxTransportSteps; ++s) {
      if (ed_.Adjacent(v, w)) return Result::Ok();
      if (Finish3(out, {u, v, w})) return Result::Ok();
      int p5 = ed_.Valence(u) == 5 ? u : v, p7 = p5 == u ? v : u;
      AtomicOutcome o = StepToward(p5, p7, ed_.V(w)->P(), {w});
      if (!o) return o.result;
      ++out.atomicSteps;
      Step(out, o.description, o.irregular);
      // the pair keeps its roles: the vertex of u's valence is the new u
      const bool uIs5 = p5 == u;
      u = uIs5 ? o.irregular[0] : o.irregular[1];
      v = uIs5 ? o.irregular[1] : o.irregular[0];
    }
    return Result::Fail(Str("the pair did not reach vertex ", w, " within ", opt_.maxTransportSteps, " steps"));
  }

  /// Phase 1 of sec. 7.2 for a non-adjacent 5-7 pair (u, v): pipeline steps (sec. 7.1.1) led
  /// by v onto its neighbour nearest to w, while that brings v closer, until v is adjacent to
  /// w (or the triple cancels). O(L) pipeline steps of O(L) each.
  Result MovePairNextTo(CompositeOutcome& out, int& u, int& v, int w) {
    for (int s = 0; s < opt_.maxTransportSteps; ++s) {
      if (ed_.Adjacent(v, w)) return Result::Ok();
      if (Finish3(out, {u, v, w})) return Result::Ok();
      if (ed_.Adjacent(u, v)) return MoveAdjacentPairNextTo(out, u, v, w);
      // v's neighbours closer to w than v, nearest first
      VertexStar<MeshType> st = ed_.Star(v);
      const CoordType pw = ed_.V(w)->P();
      const double here = double((ed_.V(v)->P() - pw).Norm());
      std::vector<std::pair<double, int>> cand;
      for (int k = 0; k < st.Valence(); ++k) {
        const int x = ops_.NeighbourFrom(v, -1, k);
        const double dx = double((ed_.V(x)->P() - pw).Norm());
        if (dx < here) cand.push_back({dx, k});
      }
      std::sort(cand.begin(), cand.end());
      Result last = Result::Fail(Str("vertex ", v, " has no neighbour closer to vertex ", w));
      bool moved = false;
      for (auto& c : cand) {
        int l = v, p = u;
        last = PipelineStep(out, l, p, c.second);
        if (last) {
          v = l, u = p, moved = true;
          break;
        }
      }
      if (!moved) return last;
    }
    return Result::Fail(Str("the pair did not reach vertex ", w, " within ", opt_.maxTransportSteps, " steps"));
  }

  /// Transports the 5-7 pair (p5, p7) to `target` and cancels the triple it forms there
  /// (sec. 7.1.1 steps 2-3, sec. 7.2). *survivor: the vertex that remains.
  Result TransportAndCancel(CompositeOutcome& out, int p5, int p7, int target, int* survivor) {
    Result t = Transport(out, p5, p7, {target}, [&]() {
      AtomicOutcome r = RemovalWithSurvivor({p5, p7, target}, [](int) { return true; });
      if (!r) return false;
      ++out.atomicSteps;
      Step(out, r.description, r.irregular);
      *survivor = r.irregular.empty() ? target : r.irregular[0];
      return true;
    });
    if (!t) return Result::Fail(Str("transporting the 5-7 pair to vertex ", target, ": ", t.reason));
    return t;
  }

  /// Sec. 7.1.1 step 2: moves the 5-7 pair (p5, p7) to the vertices `targets` by atomic pair
  /// moves along the connecting path (two separatrix segments and their turn point, see
  /// separatrix.h) from the nearer pair vertex to the nearer target. Before every step
  /// `arrived()` is asked to finish (it applies the cancellation and returns true when it
  /// can). Where no move advances along the path (an irregular vertex or a fold in the way),
  /// one greedy step brings the pair closer in space and the path is traced again from there.
  /// O(steps) atomic moves, plus O(path length) per path traced.
  Result Transport(CompositeOutcome& out, int& p5, int& p7, const std::vector<int>& targets,
                   const std::function<bool()>& arrived) {
    std::unordered_map<int, int> along;  // path vertex -> position on the path
    int progress = 0;
    for (int s = 0; s <= opt_.maxTransportSteps; ++s) {
      if (arrived()) return Result::Ok();
      if (s == opt_.maxTransportSteps) break;
      if (along.empty()) progress = TracePath(out, p5, p7, targets, &along);
      AtomicOutcome o = along.empty() ? AtomicOutcome() : StepAlong(p5, p7, along, &progress, targets);
      if (!o) {
        // blocked: one greedy step toward the targets' centroid, then trace the path again
        CoordType c(0, 0, 0);
        for (int t : targets) c += ed_.V(t)->P();
        c /= float(targets.size());
        o = StepToward(p5, p7, c, targets);
        if (!o) {
          // no single move gets closer (e.g. the pair must go round the vertex it came from):
          // the shortest sequence of at most kDetourDepth moves that does
          std::vector<int> dirs = Detour(p5, p7, c, targets);
          if (dirs.empty()) return o.result;
          for (size_t i = 0; i + 1 < dirs.size(); ++i) {
            AtomicOutcome d = ops_.MovePair57(p5, p7, dirs[i]);
            if (!d) return d.result;
            ++out.atomicSteps;
            p5 = d.irregular[0];
            p7 = d.irregular[1];
            Step(out, d.description + "  (detour)", {p5, p7});
          }
          o = ops_.MovePair57(p5, p7, dirs.back());
          if (!o) return o.result;
        }
        out.log += "  (path blocked: greedy step)\n";
        along.clear();
      }
      ++out.atomicSteps;
      p5 = o.irregular[0];
      p7 = o.irregular[1];
      Step(out, o.description, {p5, p7});
    }
    return Result::Fail(Str("the 5-7 pair did not get there within ", opt_.maxTransportSteps, " steps"));
  }

  static constexpr int kDetourDepth = 5;

  /// The shortest sequence (at most kDetourDepth atomic moves of fig. 6) that brings the
  /// pair's midpoint closer to `target` by a quarter of its current edge length, never
  /// removing a vertex of `keep`; ties: the closest end, then the lower directions. Tried and
  /// undone; empty when there is none. At most 6 + 36 + 216 atomic moves.
  std::vector<int> Detour(int p5, int p7, CoordType target, const std::vector<int>& keep) {
    const double start = double((Mid(p5, p7) - target).Norm());
    const double gain = 0.25 * double((ed_.V(p5)->P() - ed_.V(p7)->P()).Norm());
    for (int depth = 1; depth <= kDetourDepth; ++depth) {
      std::vector<int> best, cur;
      double bestD = start - gain;
      std::function<void(int, int)> dfs = [&](int a5, int a7) {
        if (int(cur.size()) == depth) {
          const double d = double((Mid(a5, a7) - target).Norm());
          if (d < bestD) bestD = d, best = cur;
          return;
        }
        for (int dir = 0; dir < 6; ++dir) {
          auto cp = ed_.Mark();
          AtomicOutcome o = ops_.MovePair57(a5, a7, dir);
          bool ok = bool(o);
          for (int k : keep) ok = ok && ed_.IsLive(k) && ed_.Valence(k) != 6;
          if (ok) {
            cur.push_back(dir);
            dfs(o.irregular[0], o.irregular[1]);
            cur.pop_back();
          }
          ed_.RollbackTo(cp);
        }
      };
      dfs(p5, p7);
      if (!best.empty()) return best;
    }
    return {};
  }

  /// The shortest connecting path from p5 or p7 to one of `targets`, as vertex -> position;
  /// empty when there is none. Returns the pair's position on it (0: its first vertex).
  int TracePath(CompositeOutcome& out, int p5, int p7, const std::vector<int>& targets,
                std::unordered_map<int, int>* along) {
    SeparatrixTracer<MeshType> tracer(ed_.Mesh());
    ConnectingPath best;
    for (int from : {p5, p7})
      for (int t : targets) {
        ConnectingPath p = ConnectByDeepening(tracer, ed_.Mesh(), from, t, opt_.maxTransportSteps);
        if (p && (!best || p.Length() < best.Length())) best = p;
      }
    along->clear();
    if (!best) return 0;
    std::vector<int> v = best.Vertices();
    for (size_t i = 0; i < v.size(); ++i) along->emplace(v[i], int(i));
    out.log += Str("  separatrix path from ", v.front(), " to ", v.back(), ": ", best.L1(), " + ", best.L2(),
                   " edges", best.turn >= 0 ? Str(", turn point ", best.turn) : std::string(), "\n");
    return 0;
  }

  /// The atomic move of the 5-7 pair that puts one of its vertices furthest along the path,
  /// past *progress (ties: the other vertex further along, then the lower direction); never
  /// removes a vertex of `keep`. Fails when no move advances.
  AtomicOutcome StepAlong(int p5, int p7, const std::unordered_map<int, int>& along, int* progress,
                          const std::vector<int>& keep) {
    auto at = [&](int v) {
      auto it = along.find(v);
      return it == along.end() || !ed_.IsLive(v) ? -1 : it->second;
    };
    // score in [far, far + 1): the furthest vertex first, the other one as a tie-break
    const double span = double(along.size()) + 2;
    AtomicOutcome o = BestMove(p5, p7, [&](const AtomicOutcome& c) {
      for (int k : keep)
        if (!ed_.IsLive(k)) return -std::numeric_limits<double>::max();
      const int a = at(c.irregular[0]), b = at(c.irregular[1]);
      return double(std::max(a, b)) + double(std::min(a, b) + 1) / span;
    }, double(*progress) + 0.5, "no pair move advances along the separatrix path");
    if (o) *progress = std::max(at(o.irregular[0]), at(o.irregular[1]));
    return o;
  }

  /// Edges from the vertices `from` to the nearer of a and b (breadth-first, at most `limit`
  /// rings; limit + 1 when further). O(limit^2) on a lattice.
  int HopsTo(const std::vector<int>& from, int a, int b, int limit) {
    std::unordered_map<int, int> d;
    std::vector<int> q;
    for (int f : from)
      if (ed_.IsLive(f) && d.emplace(f, 0).second) q.push_back(f);
    for (size_t i = 0; i < q.size(); ++i) {
      const int v = q[i], dv = d[v];
      if (v == a || v == b) return dv;
      if (dv >= limit) continue;
      for (auto* n : ed_.Star(v).neighbors) {
        const int w = ed_.Index(n);
        if (d.emplace(w, dv + 1).second) q.push_back(w);
      }
    }
    return limit + 1;
  }

  /// Moves the pair `spacing` atomic steps away from the vertices `keep` (the vertex it was
  /// generated next to, or the other pair), never toward them: each step goes to a position
  /// at least as many edges from them as before, preferring more edges, then the larger
  /// distance in space; the first choice's direction is repeated while it qualifies (a
  /// straight line, fig. 6). Fails, without moving back, when every qualifying move is blocked.
  bool MoveApart(CompositeOutcome& out, int& p5, int& p7, int anchor, int spacing) {
    return MoveApart(out, p5, p7, ed_.V(anchor)->P(), spacing, {anchor});
  }
  bool MoveApart(CompositeOutcome& out, int& p5, int& p7, CoordType anchor, int spacing, const std::vector<int>& keep) {
    const int limit = spacing + 4;
    auto kept = [&]() {
      for (int k : keep)
        if (!ed_.IsLive(k) || (ed_.Valence(k) != 5 && ed_.Valence(k) != 7)) return false;
      return true;
    };
    // (edges from the kept vertices to each vertex of the pair, summed; distance in space)
    auto where = [&](int a, int b) {
      return std::make_pair(HopsTo(keep, a, a, limit) + HopsTo(keep, b, b, limit), double((Mid(a, b) - anchor).Norm()));
    };
    int lastDir = -1;
    for (int s = 0; s < spacing; ++s) {
      const auto here = where(p5, p7);
      int best = -1;
      std::pair<int, double> bestAt(here.first, -1.0);
      for (int dir = 0; dir < 6; ++dir) {
        auto cp = ed_.Mark();
        AtomicOutcome c = ops_.MovePair57(p5, p7, dir);
        if (c && kept()) {
          const auto at = where(c.irregular[0], c.irregular[1]);
          const bool straight = dir == lastDir && at.first > here.first;
          const bool straightChosen = best >= 0 && best == lastDir;
          if (at.first >= here.first && (straight || (!straightChosen && at > bestAt))) bestAt = at, best = dir;
        }
        ed_.RollbackTo(cp);
      }
      if (best < 0) {
        out.result = Result::Fail(Str("the generated pair cannot move further apart after ", s, " of ", spacing,
                                      " steps (every move that does not come back closer is blocked)"));
        return false;
      }
      AtomicOutcome o = ops_.MovePair57(p5, p7, best);
      if (!o) {
        out.result = o.result;
        return false;
      }
      lastDir = best;
      ++out.atomicSteps;
      p5 = o.irregular[0];
      p7 = o.irregular[1];
      Step(out, o.description, {p5, p7});
    }
    return true;
  }

  Editor& ed_;
  AtomicOperations<MeshType> ops_;
  const SurfaceProjector* original_;
  CompositeOptions opt_;
};

}  // namespace irregular
}  // namespace vcg_ext
