// filter_irregular: type change (paper sec. 6.3, fig. 9): type splitting of a vk (k > 7) into
// k-6 v7, of a v4 (v3) into two (three) v5, and type aggregation, its inverse, with dry runs.
//
// Derivation from the valence rules of sec. 6.1 (graph_ops.h; docs/type_change.svg):
//   Split(w; a, b) with d1 edges of w strictly between a and b on w's side and d2 on the new
//   vertex's side: d(w) = d1+3, d(w') = d2+3, a and b +1.  Collapse(u -> v): d(v) = d(u)+d(v)-4,
//   the two opposite vertices -1, u deleted.
//
//  * vk, k > 7: the "chain" configuration. Name the neighbours of the vk r0 .. r(k-1)
//    counter-clockwise from the orientation neighbour r0. The first split cuts a cap off the
//    vk along (r0, r4): the new vertex x1 keeps r1, r2, r3 (d = 3+3 = 6), the vk keeps the
//    rest and loses 2 (k-2); r0 and r4 (regular) become v7. Each following "zip" split
//    p = 1, 2, ... along (r(4+p), r(k-p)) gives the new vertex exactly {r(k-p+1), x_p, r(3+p)}
//    between its ends (d = 6) and lowers the vk by 2 again; r(4+p) and r(k-p) become v7. The
//    vk becomes a chain x1 - x2 - ... - w of regular vertices with two rows of v7 along its
//    sides: for even k after (k-6)/2 splits w is a v6 and the k-6 side vertices are the v7s;
//    for odd k after (k-7)/2 splits w is the v7 at the end of the chain ("odd v7 at the
//    vertex"), or, with the first cap of 4 (split along (r0, r5): x1 = 4+3 = v7), the odd v7
//    is the first cap ("odd v7 at the first cap"). Every side vertex must be a regular interior
//    vertex; the caps (3 or 4 neighbours at each end) and everything else keep their valence.
//  * v4: collapse its neighbour r_s into it: d = 6+4-4 = 6, the opposite neighbours r(s-1),
//    r(s+1) drop to v5 (they must be regular). The v4's vertex survives as a regular vertex.
//  * v3: the same collapse: d = 6+3-4 = 5, so the v3's vertex and r(s-1), r(s+1) are the three
//    v5, forming a triangle.
//  * Absorbing (TypeSplitRequest::absorb, the fallback of Reduce): a neighbour the configuration
//    moves toward 6 may be irregular (a v5 side of the chain becomes a v6, a v7 beside the
//    collapse a v6), an irregular r_s may merge into a v4 (v3) when the merged vertex is a v5,
//    v6 or v7, and a v8 with a v7 neighbour r0 may flip the edge between them (flip: v8 -> v7,
//    r0 -> v6, r1 and r(k-1) +1): every touched vertex still ends a v5, v6 or v7.
//  * Aggregation of n v7 (n >= 2): merges of 2 or 3 at a time into the growing aggregate R:
//    start with a pair facing each other across an edge (x, y) of two regular vertices
//    (collapse: 6+6-4 = 8, the pair -1), or with a selected v7 as R; then collapse a regular
//    neighbour x of R into R when both vertices opposite to (R, x) are selected v7s (R +2), or
//    a selected v7 neighbour c when both opposite to (R, c) are selected v7s (R +3). A search
//    (bounded) finds an order; the chain split above is undone by it.
//  * Aggregation of two v5 into a v4: split their common regular neighbour t along the two,
//    keeping on t's side the one vertex between them (d(t) = 1+3 = 4, the new vertex 3+3 = 6);
//    three v5 forming a triangle into a v3: split one of them along the other two, keeping the
//    empty side (0+3 = 3, the new vertex 3+3 = 6). Two adjacent v5 cannot become a v4 (sec. 3).
//
// Dry runs (PredictTypeSplit, PredictAggregation) plan on a scratch copy of the rings involved
// (TopologyScratch: CCW neighbour cycles read lazily from the mesh), so they name the exact
// graph operations, created and deleted vertices and every touched valence without editing the
// mesh. Geometry (the fold check of each graph operation) is not predicted: the real operation
// may still refuse with "would fold the surface". The real operations run the same plan through
// MeshEditor and its journal: all or nothing.
#pragma once

#include <algorithm>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "graph_ops.h"
#include "graph_step.h"

namespace vcg_ext {
namespace irregular {


/// What a type split or aggregation does (or would do).
struct TypeChangeOutcome {
  Result status = Result::Fail("not planned");
  int resultVertex = -1;       ///< split: the vertex that was the vk (v3/v4), now regular, a v7 or a v5;
                               ///< aggregation: the v(6+n) (v4, v3)
  std::vector<int> produced;   ///< split: the v7s (v5s) it leaves, sorted; aggregation: empty
  std::vector<int> absorbed;   ///< neighbours that were irregular and became regular (absorb mode)
  std::vector<int> created;    ///< new vertices, in order
  std::vector<int> deleted;    ///< vertices removed by collapses
  std::vector<GraphStep> steps;
  std::map<int, int> valences; ///< valence after, of every vertex the plan touches (not the deleted)
  bool geometryPredicted = false;  ///< dry runs do not check folds; real runs did
  int orientation = -1;        ///< split: the orientation (sector) used
  std::string log;
  explicit operator bool() const { return status.ok; }
};

/// Type splitting request (sec. 6.3).
struct TypeSplitRequest {
  /// The configurations (header comment). kFlipV8 needs `absorb`: a v8 with a v7 neighbour
  /// r0 flips the edge between them (v8 -> v7, r0 -> v6, its two neighbours beside the edge
  /// +1: v7s), the fallback when no chain orientation avoids the irregular neighbours.
  enum Configuration { kAnyConfiguration, kChain, kCollapse, kFlipV8 };
  Configuration configuration = kAnyConfiguration;
  int vertex = -1;
  /// The neighbour r0 the configuration starts at, counted counter-clockwise from the
  /// vertex's neighbour of smallest index; -1: the first orientation that works.
  /// vk: the first cap is r1..r3 (r1..r4); v4, v3: r0 is the neighbour collapsed into it;
  /// kFlipV8: r0 is the v7 neighbour the flipped edge joins.
  int orientation = -1;
  /// Odd k: where the odd v7 goes: the vertex itself, at the far end of the chain (false), or
  /// the first cap (true). With orientation -1 the other place is tried too (after this one).
  bool oddV7AtFirstCap = false;
  /// Allow changing a neighbouring irregular vertex that the configuration moves to valence 6
  /// (a v5 on the side of the chain, a v7 opposite the collapse: it cancels with one produced
  /// v7 (v5)), or merging an irregular neighbour into a v4 (v3) when the merged vertex is a
  /// v5, v6 or v7. Every vertex touched still ends a v5, v6 or v7. Default: refuse, no other
  /// irregular vertex changes.
  bool absorb = false;
};

/// Type aggregation request: n >= 2 v7 into a v(6+n), two v5 into a v4, three into a v3.
struct AggregationRequest {
  std::vector<int> group;
  int at = -1;  ///< preferred aggregate vertex (a member or a vertex between them); -1: any
};

/// A combinatorial scratch copy of the neighbourhood a plan touches: each vertex's CCW
/// neighbour cycle, read from the mesh the first time it is asked for. Collapse and Split
/// follow sec. 6.1 exactly as MeshEditor does, so a plan simulated here names the real ids.
template <class MeshType>
class TopologyScratch {
 public:
  explicit TopologyScratch(MeshEditor<MeshType>& ed) : ed_(ed) {}

  bool IsLive(int v) { return created_.count(v) ? !dead_.count(v) : (ed_.IsLive(v) && !dead_.count(v)); }
  bool IsBoundary(int v) {
    Load(v);
    return boundary_[v];
  }
  const std::vector<int>& Ring(int v) {
    Load(v);
    return ring_[v];
  }
  int Valence(int v) { return int(Ring(v).size()); }
  int IndexIn(int v, int w) {
    const std::vector<int>& r = Ring(v);
    auto it = std::find(r.begin(), r.end(), w);
    return it == r.end() ? -1 : int(it - r.begin());
  }
  bool Adjacent(int a, int b) { return IndexIn(a, b) >= 0; }
  /// Vertices opposite to edge (x, y): o[0] in face (x, y, o0), o[1] in face (y, x, o1).
  bool Opposites(int x, int y, int o[2]) {
    if (IsBoundary(x)) return false;
    const std::vector<int>& r = Ring(x);
    const int i = IndexIn(x, y), n = int(r.size());
    if (i < 0) return false;
    o[0] = r[size_t((i + 1) % n)];
    o[1] = r[size_t((i + n - 1) % n)];
    return true;
  }
  /// Vertices whose ring changed, created vertices included; deleted ones excluded.
  std::set<int> Touched() const {
    std::set<int> t;
    for (int v : touched_)
      if (!dead_.count(v)) t.insert(v);
    return t;
  }

  /// MeshEditor::CanCollapse on the scratch copy; also refuses to change a boundary ring.
  Result CanCollapse(int u, int v) {
    if (!IsLive(u) || !IsLive(v)) return Result::Fail("a vertex of the edge does not exist");
    if (!Adjacent(u, v)) return Fail("vertices ", u, " and ", v, " are not joined by an edge");
    if (IsBoundary(u) || IsBoundary(v)) return Fail("edge (", u, ", ", v, ") touches the boundary");
    int o[2];
    Opposites(u, v, o);
    int common = 0;
    for (int n : Ring(u))
      if (Adjacent(v, n)) ++common;
    if (common != 2 || o[0] == o[1])
      return Fail("collapsing edge (", u, ", ", v, ") would break the surface (link condition: its ends share ", common,
                  " neighbours instead of 2)");
    for (int x : o)
      if (IsBoundary(x)) return Fail("collapsing edge (", u, ", ", v, ") would change the boundary vertex ", x);
    if (Valence(o[0]) <= 3 || Valence(o[1]) <= 3)
      return Fail("collapsing edge (", u, ", ", v, ") would leave a vertex of valence 2");
    if (Valence(u) + Valence(v) - 4 < 3) return Fail("collapsing edge (", u, ", ", v, ") would leave a vertex of valence < 3");
    return Result::Ok();
  }
  /// Collapse(u -> v) as MeshEditor::Collapse: u's ring between the two opposite vertices
  /// takes u's place in v's ring.
  void Collapse(int u, int v) {
    std::vector<int> ru = Ring(u), rv = Ring(v);
    const int du = int(ru.size());
    std::rotate(ru.begin(), ru.begin() + IndexIn(u, v), ru.end());  // ru = v, p1, ..., p(du-1)
    std::rotate(rv.begin(), rv.begin() + IndexIn(v, u), rv.end());  // rv = u, p(du-1), ..., p1
    std::vector<int> nv(rv.begin() + 1, rv.end());
    for (int t = 2; t <= du - 2; ++t) nv.push_back(ru[size_t(t)]);
    Set(v, nv);
    for (int x : {ru[1], ru[size_t(du - 1)]}) Erase(x, u);
    for (int t = 2; t <= du - 2; ++t) Replace(ru[size_t(t)], u, v);
    dead_.insert(u);
  }
  /// MeshEditor::CanFlip on the scratch copy; also refuses to change a boundary ring.
  Result CanFlip(int x, int y) {
    if (!IsLive(x) || !IsLive(y)) return Result::Fail("a vertex of the edge does not exist");
    if (!Adjacent(x, y)) return Fail("vertices ", x, " and ", y, " are not joined by an edge");
    if (IsBoundary(x) || IsBoundary(y)) return Fail("edge (", x, ", ", y, ") touches the boundary");
    int o[2];
    Opposites(x, y, o);
    if (o[0] == o[1]) return Fail("edge (", x, ", ", y, ") has the same vertex on both sides");
    if (IsBoundary(o[0]) || IsBoundary(o[1])) return Fail("flipping edge (", x, ", ", y, ") would change the boundary");
    if (Adjacent(o[0], o[1]))
      return Fail("flipping edge (", x, ", ", y, ") would duplicate the existing edge (", o[0], ", ", o[1], ")");
    if (Valence(x) <= 3 || Valence(y) <= 3) return Fail("flipping edge (", x, ", ", y, ") would leave a vertex of valence 2");
    return Result::Ok();
  }
  /// Flip(x, y) as MeshEditor::Flip: the edge becomes (o0, o1).
  void Flip(int x, int y) {
    int o[2];
    Opposites(x, y, o);
    Erase(x, y);
    Erase(y, x);
    InsertNextTo(o[0], x, o[1], true);  // around o0: x, then y (face (o0, x, y))
    InsertNextTo(o[1], y, o[0], true);  // around o1: y, then x (face (o1, y, x))
  }

  /// Split(w; a, b) as MeshEditor::Split: w keeps a..b CCW, the new vertex b..a. Returns it.
  int Split(int w, int a, int b) {
    std::vector<int> rw = Ring(w);
    const int n = int(rw.size()), i = IndexIn(w, a), j = IndexIn(w, b);
    const int x = ed_.NextCreatedVertex(createdCount_++);  // the index the real split will give
    created_.insert(x);
    std::vector<int> keep, give;
    for (int k = i;; k = (k + 1) % n) {
      keep.push_back(rw[size_t(k)]);
      if (k == j) break;
    }
    for (int k = j;; k = (k + 1) % n) {
      give.push_back(rw[size_t(k)]);
      if (k == i) break;
    }
    keep.push_back(x);
    give.push_back(w);
    boundary_[x] = false;
    Set(w, keep);
    Set(x, give);
    for (size_t k = 1; k + 2 < give.size(); ++k) Replace(give[k], w, x);  // strictly between b and a
    // face (a, w, x): x follows w around a; face (b, x, w): x precedes w around b
    InsertNextTo(a, w, x, true);
    InsertNextTo(b, w, x, false);
    return x;
  }

 private:
  template <class... Args>
  static Result Fail(const Args&... args) {
    return Result::Fail(Str(args...));
  }
  void Load(int v) {
    if (ring_.count(v)) return;
    std::vector<int> r;
    bool b = true;
    if (ed_.IsLive(v)) {
      VertexStar<MeshType> s = ed_.Star(v);
      for (auto* n : s.neighbors) r.push_back(ed_.Index(n));
      b = s.boundary;
    }
    ring_[v] = r;
    boundary_[v] = b;
  }
  void Set(int v, const std::vector<int>& r) {
    Load(v);
    ring_[v] = r;
    touched_.insert(v);
  }
  void Replace(int v, int from, int to) {
    std::vector<int> r = Ring(v);
    std::replace(r.begin(), r.end(), from, to);
    Set(v, r);
  }
  void Erase(int v, int w) {
    std::vector<int> r = Ring(v);
    r.erase(std::remove(r.begin(), r.end(), w), r.end());
    Set(v, r);
  }
  void InsertNextTo(int v, int w, int x, bool after) {
    std::vector<int> r = Ring(v);
    const int i = IndexIn(v, w);
    r.insert(r.begin() + (after ? i + 1 : i), x);
    Set(v, r);
  }

  MeshEditor<MeshType>& ed_;
  int createdCount_ = 0;  ///< splits simulated so far (the next gets NextCreatedVertex of it)
  std::unordered_map<int, std::vector<int>> ring_;
  std::unordered_map<int, bool> boundary_;
  std::set<int> dead_, created_, touched_;
};

/// Type splitting and aggregation (sec. 6.3) with their dry runs. See the header comment for
/// the configurations. Precondition: as MeshEditor (FF and VF up to date, manifold, oriented).
template <class MeshType>
class TypeChange {
 public:
  typedef MeshEditor<MeshType> Editor;
  typedef TopologyScratch<MeshType> Scratch;
  /// Called after every graph operation of a real run: (description, vertices around it),
  /// e.g. to relax the 2-ring (composite_ops.h). May move vertices, not change topology.
  typedef std::function<void(const std::string&, const std::vector<int>&)> StepHook;

  explicit TypeChange(Editor& ed) : ed_(ed) {}

  // ------------------------------------------------------------ type splitting
  /// Dry run of TypeSplit: the plan, without editing the mesh. Folds are not predicted.
  TypeChangeOutcome PredictTypeSplit(const TypeSplitRequest& req) {
    std::vector<TypeChangeOutcome> plans = SplitPlans(req, 1);
    return plans.front();
  }

  /// Type splitting: a vk (k > 7) becomes k-6 v7, a v4 two v5, a v3 three v5; no other
  /// irregular vertex changes (unless req.absorb). With orientation -1 the orientations are
  /// tried in order until one passes the fold checks too. All or nothing.
  TypeChangeOutcome TypeSplit(const TypeSplitRequest& req, const StepHook& hook = StepHook()) {
    std::vector<TypeChangeOutcome> plans = SplitPlans(req, req.orientation < 0 ? 1 << 20 : 1);
    return Run(plans, hook);
  }

  // ------------------------------------------------------------ aggregation
  TypeChangeOutcome PredictAggregation(const AggregationRequest& req) { return AggregationPlans(req).front(); }

  /// Aggregation, the inverse of type splitting. All or nothing.
  TypeChangeOutcome Aggregate(const AggregationRequest& req, const StepHook& hook = StepHook()) {
    return Run(AggregationPlans(req), hook);
  }

 private:
  static TypeChangeOutcome Refusal(const std::string& why) {
    TypeChangeOutcome o;
    o.status = Result::Fail(why);
    return o;
  }

  /// The neighbours of v counter-clockwise, starting at the one of smallest index.
  std::vector<int> ReferenceRing(int v) {
    std::vector<int> r;
    for (auto* n : ed_.Star(v).neighbors) r.push_back(ed_.Index(n));
    std::rotate(r.begin(), std::min_element(r.begin(), r.end()), r.end());
    return r;
  }

  /// Finishes a plan simulated on `s`: valences of the touched vertices, produced vertices
  /// (if `split`: the irregular vertices it leaves, created or whose valence changed).
  void Close(TypeChangeOutcome& o, Scratch& s, bool split) {
    for (int v : s.Touched()) o.valences[v] = s.Valence(v);
    for (auto& kv : o.valences)
      if (split && kv.second != 6 && (!ed_.IsLive(kv.first) || ed_.Valence(kv.first) != kv.second))
        o.produced.push_back(kv.first);
    std::sort(o.produced.begin(), o.produced.end());
    for (auto& st : o.steps)
      if (st.kind == GraphStep::kSplit) o.created.push_back(st.created);
      else if (st.kind == GraphStep::kCollapse) o.deleted.push_back(st.x);
    o.status = Result::Ok();
  }

  /// A vertex the configuration raises by one (a split end) or lowers by one (a collapse's
  /// opposite): empty if allowed, else why not. Regular interior vertices are; with absorb,
  /// so is an irregular one that becomes regular.
  std::string Bystander(Scratch& s, int x, int delta, int whose, const std::string& role, bool absorb,
                        std::vector<int>* absorbed) {
    if (s.IsBoundary(x)) return Str("vertex ", x, " (", role, " of ", whose, ") lies on the boundary");
    const int d = s.Valence(x);
    if (d == 6) return std::string();
    if (absorb && d + delta == 6) {
      absorbed->push_back(x);
      return std::string();
    }
    return Str("vertex ", x, " (", role, " of ", whose, ") has valence ", d, " and would become a v", d + delta);
  }

  /// Plans of the split of req.vertex, in the order they are tried: one per orientation when
  /// req.orientation < 0 (at most `most`), else the asked one. Never empty: a refusal instead.
  std::vector<TypeChangeOutcome> SplitPlans(const TypeSplitRequest& req, int most) {
    const int v = req.vertex;
    if (!ed_.IsLive(v)) return {Refusal(Str("vertex ", v, " does not exist"))};
    if (ed_.IsBoundary(v)) return {Refusal(Str("vertex ", v, " lies on the boundary: type splitting acts on interior vertices"))};
    const int k = ed_.Valence(v);
    if (k >= 5 && k <= 7)
      return {Refusal(Str("vertex ", v, " has valence ", k, ": only v3, v4 and vk with k > 7 are split into v5s or v7s"))};
    const std::vector<int> ring = ReferenceRing(v);
    if (req.orientation >= k)
      return {Refusal(Str("orientation ", req.orientation, " does not exist: vertex ", v, " has ", k, " neighbours (0..", k - 1, ")"))};
    if ((req.configuration == TypeSplitRequest::kChain && k < 8) ||
        (req.configuration == TypeSplitRequest::kCollapse && k > 4) ||
        (req.configuration == TypeSplitRequest::kFlipV8 && k != 8))
      return {Refusal(Str("that configuration does not apply to a v", k, ": the chain splits a vk with k > 7, the "
                          "collapse a v4 or v3, the flip a v8"))};
    if (req.configuration == TypeSplitRequest::kFlipV8 && !req.absorb)
      return {Refusal("the flip configuration changes a v7 neighbour into a v6: allow absorbing neighbours to use it")};
    std::vector<TypeChangeOutcome> plans;
    std::vector<std::string> why;
    const int from = req.orientation < 0 ? 0 : req.orientation, to = req.orientation < 0 ? k : req.orientation + 1;
    for (int s = from; s < to && int(plans.size()) < most; ++s) {
      std::vector<int> r(ring.begin() + s, ring.end());
      r.insert(r.end(), ring.begin(), ring.begin() + s);
      // odd k with the orientation left open: both places of the odd v7, the asked one first
      const bool allowed = req.configuration == TypeSplitRequest::kAnyConfiguration ||
                           req.configuration == (k > 7 ? TypeSplitRequest::kChain : TypeSplitRequest::kCollapse);
      for (int variant = 0; allowed && variant < (k > 7 && k % 2 == 1 && req.orientation < 0 ? 2 : 1); ++variant) {
        TypeSplitRequest q = req;
        q.oddV7AtFirstCap = req.oddV7AtFirstCap != (variant == 1);
        std::string fail;
        TypeChangeOutcome o = k > 7 ? ChainPlan(v, r, q, &fail) : CollapsePlan(v, r, q, &fail);
        o.orientation = s;
        if (o) plans.push_back(o);
        else if (variant == 0) why.push_back(Str("orientation ", s, ": ", fail));
      }
    }
    // the flip configuration of a v8, after every chain (it changes a v7 neighbour)
    const bool flip = req.configuration == TypeSplitRequest::kFlipV8 ||
                      (req.configuration == TypeSplitRequest::kAnyConfiguration && req.absorb);
    for (int s = from; flip && k == 8 && s < to && int(plans.size()) < most; ++s) {
      std::vector<int> r(ring.begin() + s, ring.end());
      r.insert(r.end(), ring.begin(), ring.begin() + s);
      std::string fail;
      TypeChangeOutcome o = FlipPlan(v, r, req, &fail);
      o.orientation = s;
      if (o) plans.push_back(o);
      else if (req.configuration == TypeSplitRequest::kFlipV8) why.push_back(Str("orientation ", s, ": ", fail));
    }
    if (!plans.empty()) return plans;
    std::string reason = Str("vertex ", v, " (v", k, ") cannot be split into ", k > 7 ? "v7s" : "v5s",
                             req.orientation < 0 ? " in any orientation" : "", " without changing another irregular vertex: ");
    for (size_t i = 0; i < why.size() && i < 4; ++i) reason += (i ? "; " : "") + why[i];
    if (why.size() > 4) reason += "; ...";
    reason += k > 7 ? ". Choose another orientation, move the irregular neighbours away first (Move Pair), or allow absorbing "
                      "neighbouring v5s"
                    : ". Choose another orientation, move the irregular neighbours away first (Move Pair), or allow absorbing "
                      "neighbouring v7s";
    return {Refusal(reason)};
  }

  /// The chain configuration of a vk (k > 7) with neighbours r (r[0]: the orientation).
  TypeChangeOutcome ChainPlan(int v, const std::vector<int>& r, const TypeSplitRequest& req, std::string* fail) {
    const int k = int(r.size());
    const bool odd = k % 2 == 1, capFirst = odd && req.oddV7AtFirstCap;
    const int cap = capFirst ? 4 : 3;  // the first cap is r1..r(cap)
    const int zips = odd ? (k - 9) / 2 : (k - 8) / 2;
    // (first, last) of the part of the ring the vk keeps in each split; the new vertex takes
    // the rest. First split: ends r(cap+1), r0; zip p: ends r(cap+1+p), r(k-p).
    std::vector<std::pair<int, int>> ends{{cap + 1, 0}};
    for (int p = 1; p <= zips; ++p) ends.push_back({cap + 1 + p, k - p});
    Scratch s(ed_);
    TypeChangeOutcome o;
    for (auto& e : ends)
      for (int idx : {e.first, e.second}) {
        const std::string b = Bystander(s, r[size_t(idx)], +1, v, "a side neighbour of the chain", req.absorb, &o.absorbed);
        if (!b.empty()) {
          *fail = b;
          return Refusal(b);
        }
      }
    for (auto& e : ends) {
      GraphStep st;
      st.kind = GraphStep::kSplit;
      st.x = v;
      st.y = r[size_t(e.first)];
      st.z = r[size_t(e.second)];
      st.created = s.Split(v, st.y, st.z);
      o.steps.push_back(st);
    }
    o.resultVertex = v;
    Close(o, s, true);
    return o;
  }

  /// The collapse configuration of a v4 or v3 with neighbours r: r[0] collapses into v.
  TypeChangeOutcome CollapsePlan(int v, const std::vector<int>& r, const TypeSplitRequest& req, std::string* fail) {
    const int k = int(r.size());
    Scratch s(ed_);
    TypeChangeOutcome o;
    auto refuse = [&](const std::string& why) {
      *fail = why;
      return Refusal(why);
    };
    if (s.IsBoundary(r[0])) return refuse(Str("vertex ", r[0], " (the neighbour collapsed into ", v, ") lies on the boundary"));
    const int merged = s.Valence(r[0]) + k - 4;  // 6 (v4) or 5 (v3) when r0 is regular
    if (s.Valence(r[0]) != 6) {
      // absorb: an irregular r0 may merge when the merged vertex is still a v5, v6 or v7
      if (!req.absorb || merged < 5 || merged > 7)
        return refuse(Str("vertex ", r[0], " (the neighbour collapsed into ", v, ") has valence ", s.Valence(r[0]),
                          ", not 6: the merged vertex would be a v", merged));
      o.absorbed.push_back(r[0]);
    }
    for (int x : {r[1], r[size_t(k - 1)]}) {
      const std::string b = Bystander(s, x, -1, v, "a neighbour beside the collapsed edge", req.absorb, &o.absorbed);
      if (!b.empty()) return refuse(b);
    }
    Result can = s.CanCollapse(r[0], v);
    if (!can) return refuse(can.reason);
    GraphStep st;
    st.kind = GraphStep::kCollapse;
    st.x = r[0];
    st.y = v;
    s.Collapse(r[0], v);
    o.steps.push_back(st);
    o.resultVertex = v;
    Close(o, s, true);
    return o;
  }

  /// The flip configuration of a v8 (absorb): flip (v, r0) with r0 a v7: v -> v7, r0 -> v6,
  /// r1 and r7 +1.
  TypeChangeOutcome FlipPlan(int v, const std::vector<int>& r, const TypeSplitRequest& req, std::string* fail) {
    Scratch s(ed_);
    TypeChangeOutcome o;
    auto refuse = [&](const std::string& why) {
      *fail = why;
      return Refusal(why);
    };
    if (s.IsBoundary(r[0]) || s.Valence(r[0]) != 7)
      return refuse(Str("vertex ", r[0], " (the neighbour of ", v, " the flip configuration needs) is not an interior v7"));
    o.absorbed.push_back(r[0]);
    for (int x : {r[1], r[size_t(r.size() - 1)]}) {
      const std::string b = Bystander(s, x, +1, v, "a neighbour beside the flipped edge", req.absorb, &o.absorbed);
      if (!b.empty()) return refuse(b);
    }
    Result can = s.CanFlip(v, r[0]);
    if (!can) return refuse(can.reason);
    GraphStep st;
    st.kind = GraphStep::kFlip;
    st.x = v;
    st.y = r[0];
    s.Flip(v, r[0]);
    o.steps.push_back(st);
    o.resultVertex = v;
    Close(o, s, true);
    return o;
  }

  // ------------------------------------------------------------ aggregation plans
  std::vector<TypeChangeOutcome> AggregationPlans(const AggregationRequest& req) {
    std::vector<int> g = req.group;
    std::sort(g.begin(), g.end());
    g.erase(std::unique(g.begin(), g.end()), g.end());
    if (g.size() < 2) return {Refusal("aggregation needs at least two vertices (v7s, or two or three v5s)")};
    int n5 = 0, n7 = 0;
    for (int v : g) {
      if (!ed_.IsLive(v)) return {Refusal(Str("vertex ", v, " does not exist"))};
      if (ed_.IsBoundary(v)) return {Refusal(Str("vertex ", v, " lies on the boundary: aggregation acts on interior vertices"))};
      n5 += ed_.Valence(v) == 5;
      n7 += ed_.Valence(v) == 7;
    }
    if (n5 != int(g.size()) && n7 != int(g.size()))
      return {Refusal("aggregation merges only v7s (into a v8, v9, ...) or only v5s (two into a v4, three into a v3)")};
    if (n5 > 3) return {Refusal("at most three v5 can merge (into a v3)")};
    return {n7 ? MergeV7(g, req.at) : MergeV5(g, req.at)};
  }

  /// Two v5: split their common regular neighbour; three v5 in a triangle: split one of them.
  TypeChangeOutcome MergeV5(const std::vector<int>& g, int at) {
    Scratch s(ed_);
    std::vector<int> cand;  // the vertex to split
    std::vector<std::pair<int, int>> along;
    std::string why;
    if (g.size() == 2) {
      const int a = g[0], b = g[1];
      if (s.Adjacent(a, b))
        return Refusal(Str("the v5s ", a, " and ", b, " are adjacent: two adjacent v5 cannot become a v4 (sec. 3). Two v5 "
                           "merge when they are two edges apart with one regular vertex between them on each side of a common "
                           "neighbour, as splitting a v4 leaves them"));
      for (int t : s.Ring(a)) {
        if (!s.Adjacent(b, t)) continue;
        if (s.IsBoundary(t) || s.Valence(t) != 6) {
          why = Str("their common neighbour ", t, " has valence ", s.Valence(t), ", not 6");
          continue;
        }
        const int n = s.Valence(t), i = s.IndexIn(t, a), j = s.IndexIn(t, b);
        if ((j - i + n) % n == 2) cand.push_back(t), along.push_back({a, b});       // t keeps a..b: one between
        else if ((i - j + n) % n == 2) cand.push_back(t), along.push_back({b, a});
        else why = Str("on their common neighbour ", t, " they are not one vertex apart");
      }
      if (cand.empty())
        return Refusal(Str("the v5s ", a, " and ", b, " cannot become a v4: ",
                           why.empty() ? "they have no common neighbour" : why,
                           ". Two v5 merge when they are two edges apart with a regular common neighbour on which they "
                           "are one vertex apart (as splitting a v4 leaves them); move them there first (Move Pair)"));
    } else {
      for (int t : g) {
        const int a = t == g[0] ? g[1] : g[0], b = t == g[2] ? g[1] : g[2];
        const int n = s.Valence(t), i = s.IndexIn(t, a), j = s.IndexIn(t, b);
        if (i < 0 || j < 0) continue;
        if ((j - i + n) % n == 1) cand.push_back(t), along.push_back({a, b});
        else if ((i - j + n) % n == 1) cand.push_back(t), along.push_back({b, a});
      }
      if (cand.empty())
        return Refusal(Str("the v5s ", g[0], ", ", g[1], " and ", g[2], " cannot become a v3: three v5 merge when they are "
                           "the corners of one triangle (as splitting a v3 leaves them)"));
    }
    size_t pick = 0;
    for (size_t i = 0; i < cand.size(); ++i)
      if (cand[i] == at) pick = i;
    if (at >= 0 && cand[pick] != at)
      return Refusal(Str("vertex ", at, " cannot become the v", 8 - int(g.size()), " of these v5s; vertex ", cand[0], " can"));
    GraphStep st;
    st.kind = GraphStep::kSplit;
    st.x = cand[pick];
    st.y = along[pick].first;
    st.z = along[pick].second;
    st.created = s.Split(st.x, st.y, st.z);
    TypeChangeOutcome o;
    o.steps.push_back(st);
    o.resultVertex = st.x;
    Close(o, s, false);
    return o;
  }

  struct MergeState {
    int r = -1;                 ///< the aggregate so far (-1: not started)
    std::set<int> left;         ///< selected v7s not merged yet
    std::vector<GraphStep> steps;
  };

  /// n v7: a depth-first search over merges of 2 or 3 into the aggregate (header comment).
  TypeChangeOutcome MergeV7(const std::vector<int>& g, int at) {
    Scratch base(ed_);
    const std::set<int> group(g.begin(), g.end());
    std::vector<std::pair<MergeState, int>> starts;  // (state after the start, preference)
    auto regular = [&](Scratch& s, int x) { return !group.count(x) && !s.IsBoundary(x) && s.Valence(x) == 6; };
    std::set<std::pair<int, int>> seen;
    for (int gv : g)
      for (int x : base.Ring(gv)) {
        if (!regular(base, x)) continue;
        for (int y : base.Ring(x)) {
          if (!regular(base, y) || seen.count({std::min(x, y), std::max(x, y)})) continue;
          int o[2];
          if (!base.Opposites(x, y, o) || !group.count(o[0]) || !group.count(o[1])) continue;
          seen.insert({std::min(x, y), std::max(x, y)});
          MergeState st;
          st.r = (y == at || (x != at && y < x)) ? y : x;
          const int u = st.r == x ? y : x;
          st.left = group;
          st.left.erase(o[0]);
          st.left.erase(o[1]);
          GraphStep c;
          c.kind = GraphStep::kCollapse;
          c.x = u;
          c.y = st.r;
          st.steps.push_back(c);
          starts.push_back({st, (x == at || y == at) ? 0 : g.size() % 2 == 0 ? 1 : 2});
        }
      }
    for (int gv : g) {
      MergeState st;
      st.r = gv;
      st.left = group;
      st.left.erase(gv);
      starts.push_back({st, gv == at ? 0 : g.size() % 2 == 1 ? 1 : 2});
    }
    // preferred starts first (through `at`; a facing pair for even n, a seed for odd n), then
    // the oldest aggregate (smallest index): a round trip gives back the split vertex
    std::stable_sort(starts.begin(), starts.end(), [](const std::pair<MergeState, int>& a, const std::pair<MergeState, int>& b) {
      return a.second != b.second ? a.second < b.second : a.first.r < b.first.r;
    });
    budget_ = 20000;
    MergeState best;
    size_t bestLeft = group.size() + 1;
    for (auto& sp : starts) {
      if (at >= 0 && sp.second != 0) break;  // an asked aggregate: only starts through it
      Scratch s(ed_);
      bool ok = true;
      for (auto& st : sp.first.steps) {
        Result can = s.CanCollapse(st.x, st.y);
        if (!can) ok = false;
        else s.Collapse(st.x, st.y);
      }
      if (!ok) continue;
      MergeState done;
      if (Search(s, sp.first, group, &done, &best, &bestLeft)) {
        Scratch fin(ed_);
        TypeChangeOutcome o;
        for (auto st : done.steps) {
          fin.Collapse(st.x, st.y);
          o.steps.push_back(st);
        }
        o.resultVertex = done.r;
        Close(o, fin, false);
        return o;
      }
    }
    if (best.r < 0)
      return Refusal(at >= 0 ? Str("vertex ", at, " cannot become the aggregate: no aggregation of these v7s starts at it")
                             : "no two of the selected v7s face each other across an edge of two regular vertices, and no "
                               "selected v7 has two others facing each other across one of its edges: v7s merge two or three "
                               "at a time when they are as type splitting leaves them (two rows along a chain of regular "
                               "vertices). Move them next to each other first (Move Pair)");
    std::string left;
    for (int x : best.left) left += (left.empty() ? "" : ", ") + std::to_string(x);
    return Refusal(Str("the selected v7s cannot all be merged: after merging ", group.size() - best.left.size(),
                       " of them into vertex ", best.r, ", the v7s ", left,
                       " are not two facing each other across an edge at it. Select v7s as type splitting leaves them (two "
                       "rows along a chain of regular vertices), or move them there first (Move Pair)"));
  }

  bool Search(Scratch& s, const MergeState& st, const std::set<int>& group, MergeState* done, MergeState* best,
              size_t* bestLeft) {
    if (st.left.size() < *bestLeft) *bestLeft = st.left.size(), *best = st;
    if (st.left.empty()) {
      *done = st;
      return true;
    }
    if (--budget_ < 0) return false;
    const std::vector<int> ring = s.Ring(st.r);
    for (int x : ring) {
      const bool member = st.left.count(x) > 0;  // a 3-merge; else a 2-merge through a regular x
      if (!member && (s.IsBoundary(x) || s.Valence(x) != 6)) continue;
      int o[2];
      if (!s.Opposites(st.r, x, o) || !st.left.count(o[0]) || !st.left.count(o[1])) continue;
      if (!s.CanCollapse(x, st.r)) continue;
      Scratch next = s;
      next.Collapse(x, st.r);
      MergeState ns = st;
      for (int y : {o[0], o[1], x}) ns.left.erase(y);
      GraphStep c;
      c.kind = GraphStep::kCollapse;
      c.x = x;
      c.y = st.r;
      ns.steps.push_back(c);
      if (Search(next, ns, group, done, best, bestLeft)) return true;
    }
    return false;
  }

  // ------------------------------------------------------------ running a plan
  /// Runs the first plan that passes the fold checks; rolls back and tries the next one
  /// otherwise. The outcome of a real run is its plan with geometryPredicted = true.
  TypeChangeOutcome Run(const std::vector<TypeChangeOutcome>& plans, const StepHook& hook) {
    if (!plans.front()) return plans.front();
    std::string last;
    for (const TypeChangeOutcome& plan : plans) {
      auto cp = ed_.Mark();
      Result r = Apply(plan, hook);
      if (r) {
        TypeChangeOutcome o = plan;
        o.geometryPredicted = true;
        return o;
      }
      ed_.RollbackTo(cp);
      if (r.reason.compare(0, 14, "internal error") == 0) return Refusal(r.reason);  // plan and mesh disagree
      last = r.reason;
      if (plans.size() > 1) last = Str("orientation ", plan.orientation, ": ", last);
    }
    // only the geometric checks refuse a plan the topology allowed
    return Refusal(Str(plans.size() > 1 ? "every orientation" : "the configuration",
                       " would fold the surface or leave a degenerate triangle (", last, ")"));
  }

  Result Apply(const TypeChangeOutcome& plan, const StepHook& hook) {
    for (const GraphStep& st : plan.steps) {
      Result r;
      std::vector<int> around;
      if (st.kind == GraphStep::kFlip) {
        int o[2] = {-1, -1};
        ed_.Opposites(st.x, st.y, o);
        r = ed_.Flip(st.x, st.y);
        around = {st.x, st.y, o[0], o[1]};
      } else if (st.kind == GraphStep::kCollapse) {
        int o[2] = {-1, -1};
        ed_.Opposites(st.x, st.y, o);
        r = ed_.Collapse(st.x, st.y);
        around = {st.y, o[0], o[1]};
      } else {
        int created = -1;
        r = ed_.Split(st.x, st.y, st.z, &created);
        if (r && created != st.created)
          return Result::Fail(Str("internal error: the split created vertex ", created, ", the plan said ", st.created));
        around = {st.x, created, st.y, st.z};
      }
      if (!r) return Result::Fail(Str(st.Describe(), ": ", r.reason));
      if (hook) hook(st.Describe(), around);
    }
    for (auto& kv : plan.valences)
      if (!ed_.IsLive(kv.first) || ed_.Valence(kv.first) != kv.second)
        return Result::Fail(Str("internal error: vertex ", kv.first, " has valence ",
                                ed_.IsLive(kv.first) ? ed_.Valence(kv.first) : 0, ", the plan said ", kv.second));
    return Result::Ok();
  }

  Editor& ed_;
  int budget_ = 0;
};

}  // namespace irregular
}  // namespace vcg_ext
