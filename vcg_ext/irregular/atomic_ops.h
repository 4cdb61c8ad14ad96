// filter_irregular: the five atomic semantic operations of the paper (sec. 6.2, figs. 6-8),
// built from the graph operations of graph_ops.h.
//
// Direction convention (used everywhere in the plugin):
//   * 5-7 pair movement: directions 0..5 turn counter-clockwise around the v5, starting at
//     the v7. Let n0 = v7, n1 .. n4 be the v5's neighbours counter-clockwise, and m0 = v5,
//     m1 .. m6 the v7's neighbours counter-clockwise (so n1 = m6 and n4 = m1):
//       0  split the v7 along (v7, m4): v7 -> v5 (keeps m5, m6), m4 -> v7      (toward n1 side)
//       1  flip edge (v7, n1):          n1 -> v5, the vertex beyond -> v7
//       2  collapse n1 into the v5:     the v5 becomes the v7, n2 -> v5
//       3  collapse n4 into the v5:     the v5 becomes the v7, n3 -> v5
//       4  flip edge (v7, n4):          n4 -> v5, the vertex beyond -> v7
//       5  split the v7 along (v7, m3): v7 -> v5 (keeps m1, m2), m3 -> v7      (toward n4 side)
//     On a regular neighbourhood each moves the pair one step and keeps it adjacent.
//   * Single-vertex operations (move with 5-7 generation, 5-5-7-7 generation) take a
//     neighbour index k counted counter-clockwise from a reference neighbour n0 (by default
//     the neighbour with the smallest vertex index, so scripts are deterministic).
//
// Every operation states the valence change of each vertex it touches (AtomicOutcome::changes)
// and checks it after the edit; it refuses (and rolls back) if the neighbourhood is not the
// one the semantics need (e.g. a vertex that must be regular is not).
//
// What cannot be done (paper sec. 5) is refused with the theorem, never attempted:
// a single irregular vertex cannot move alone (Theorem 5.1) and a 5-7 pair cannot cancel
// (Theorem 5.5); see ImpossibleRequest().
#pragma once

#include <algorithm>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "graph_ops.h"

namespace vcg_ext {
namespace irregular {

/// What an atomic operation did.
struct AtomicOutcome {
  Result result = Result::Fail("not applied");
  std::string description;              ///< e.g. "flip edge (12, 40)"
  std::map<int, int> changes;           ///< vertex index -> valence after (deleted: 0)
  std::vector<int> irregular;           ///< the irregular vertices the operation leaves (the
                                        ///< moved pair, the generated quadruple, ...)
  explicit operator bool() const { return result.ok; }
};

/// Sec. 5: the messages for requests that are impossible in any triangulation.
struct ImpossibleRequest {
  static std::string MoveSingleVertex() {
    return "A single irregular vertex cannot be moved alone: in a convex region around it, the "
           "distances to the sides of the boundary determine its position uniquely when its valence "
           "is not a multiple of 6 (Li et al., Theorem 5.1). Move it together with a partner "
           "(a 5-7 pair), or use 'move with 5-7 pair generation', which moves it and leaves a 5-7 pair.";
  }
  static std::string CancelPair57() {
    return "A 5-7 pair cannot be cancelled: no retriangulation of a convex region around it is free of "
           "irregular vertices (Li et al., Theorem 5.5). Cancel triples instead (5-5-7 into one v5, "
           "5-7-7 into one v7) or 5-5-7-7 quadruples.";
  }
};

template <class MeshType>
class AtomicOperations {
 public:
  typedef MeshEditor<MeshType> Editor;
  typedef typename Editor::VertexType VertexType;

  explicit AtomicOperations(Editor& ed) : ed_(ed) {}

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

  // ------------------------------------------------------------ 1. 5-7 pair movement
  AtomicOutcome MovePair57(int v5, int v7, int dir) {
    AtomicOutcome out;
    Result pre = RequireInterior({v5, v7});
    if (!pre) return Refuse(out, pre.reason);
    if (ed_.Valence(v5) != 5 || ed_.Valence(v7) != 7)
      return Refuse(out, Str("a 5-7 pair needs a vertex of valence 5 and one of valence 7; vertices ", v5, " and ", v7,
                             " have valences ", ed_.Valence(v5), " and ", ed_.Valence(v7)));
    if (!ed_.Adjacent(v5, v7)) return Refuse(out, Str("vertices ", v5, " and ", v7, " are not adjacent"));
    if (dir < 0 || dir > 5) return Refuse(out, "the direction must be 0..5");
    auto n = [&](int k) { return NeighbourFrom(v5, v7, k); };
    auto m = [&](int k) { return NeighbourFrom(v7, v5, k); };
    auto cp = ed_.Mark();
    std::map<int, int> expect;
    std::vector<int> pair;
    Result r;
    if (dir == 1 || dir == 4) {
      const int y = n(dir);
      int o[2];
      ed_.Opposites(v7, y, o);
      const int z = o[0] == v5 ? o[1] : o[0];
      Result reg = RequireRegular({y, z});
      if (!reg) return Refuse(out, reg.reason);
      out.description = Str("flip edge (", v7, ", ", y, ")");
      expect = {{v5, 6}, {v7, 6}, {y, 5}, {z, 7}};
      pair = {y, z};
      r = ed_.Flip(v7, y);
    } else if (dir == 2 || dir == 3) {
      const int x = n(dir == 2 ? 1 : 4), c = n(dir == 2 ? 2 : 3);
      Result reg = RequireRegular({x, c});
      if (!reg) return Refuse(out, reg.reason);
      out.description = Str("collapse vertex ", x, " into ", v5);
      expect = {{v5, 7}, {v7, 6}, {c, 5}, {x, 0}};
      pair = {c, v5};
      r = ed_.Collapse(x, v5);
    } else {
      const int b = m(dir == 0 ? 4 : 3);
      Result reg = RequireRegular({b});
      if (!reg) return Refuse(out, reg.reason);
      int created = -1;
      out.description = Str("split vertex ", v7, " along edges (", v7, ", ", v5, ") and (", v7, ", ", b, ")");
      // Split keeps, for the old vertex, the edges from its first to its second argument.
      r = dir == 0 ? ed_.Split(v7, b, v5, &created) : ed_.Split(v7, v5, b, &created);
      if (r) expect = {{v7, 5}, {created, 6}, {v5, 6}, {b, 7}};
      pair = {v7, b};
    }
    return Finish(out, r, cp, expect, pair);
  }

  // ------------------------------------------------------------ 2. move with 5-7 generation
  /// A v5 (v7) moves one step toward its neighbour k and leaves an adjacent 5-7 pair.
  ///   v5 at p: flip the link edge (n_k, n_k+1); p -> 6, n_k -> 5 (the moved v5),
  ///            n_k+1 -> 5 and the vertex z beyond the edge -> 7 (the generated pair).
  ///   v7 at p: flip the edge (p, n_k); p -> 6, n_k -> 5 and n_k-1 -> 7 (the generated pair),
  ///            n_k+1 -> 7 (the moved v7).
  AtomicOutcome MoveWithPairGeneration(int p, int k, int ref = -1) {
    AtomicOutcome out;
    Result pre = RequireInterior({p});
    if (!pre) return Refuse(out, pre.reason);
    const int d = ed_.Valence(p);
    if (d != 5 && d != 7)
      return Refuse(out, Str("vertex ", p, " has valence ", d, "; this operation moves a v5 or a v7"));
    if (k < 0 || k >= d) return Refuse(out, Str("the direction must be 0..", d - 1, " for a v", d));
    auto cp = ed_.Mark();
    std::map<int, int> expect;
    std::vector<int> after;
    Result r;
    const int nk = NeighbourFrom(p, ref, k), nk1 = NeighbourFrom(p, ref, k + 1), nkm = NeighbourFrom(p, ref, k - 1);
    if (d == 5) {
      int o[2];
      if (!ed_.Opposites(nk, nk1, o)) return Refuse(out, "the link edge lies on the boundary");
      const int z = o[0] == p ? o[1] : o[0];
      Result reg = RequireRegular({nk, nk1, z});
      if (!reg) return Refuse(out, reg.reason);
      out.description = Str("v5 ", p, " -> ", nk, ", new 5-7 pair (", nk1, ", ", z, "): flip edge (", nk, ", ", nk1, ")");
      expect = {{p, 6}, {nk, 5}, {nk1, 5}, {z, 7}};
      after = {nk, nk1, z};
      r = ed_.Flip(nk, nk1);
    } else {
      Result reg = RequireRegular({nk, nk1, nkm});
      if (!reg) return Refuse(out, reg.reason);
      out.description = Str("v7 ", p, " -> ", nk1, ", new 5-7 pair (", nk, ", ", nkm, "): flip edge (", p, ", ", nk, ")");
      expect = {{p, 6}, {nk, 5}, {nkm, 7}, {nk1, 7}};
      after = {nk1, nk, nkm};
      r = ed_.Flip(p, nk);
    }
    return Finish(out, r, cp, expect, after);
  }

  // ------------------------------------------------------------ 3. move with 5-7 removal
  /// The inverse of MoveWithPairGeneration: a v5 (v7) next to a 5-7 pair moves one step and
  /// the pair disappears, i.e. an adjacent 5-5-7 triple becomes one v5 and a 5-7-7 triple one
  /// v7. The three vertices must be close (each within one edge of another); the operation
  /// searches the flips and collapses around them for the one that does exactly this.
  AtomicOutcome MoveWithPairRemoval(const std::vector<int>& triple) {
    AtomicOutcome out;
    if (triple.size() != 3) return Refuse(out, "a triple cancellation needs exactly three vertices");
    Result pre = RequireInterior(triple);
    if (!pre) return Refuse(out, pre.reason);
    int n5 = 0, n7 = 0;
    for (int v : triple) {
      int d = ed_.Valence(v);
      n5 += d == 5;
      n7 += d == 7;
    }
    if (!((n5 == 2 && n7 == 1) || (n5 == 1 && n7 == 2)))
      return Refuse(out, "a triple cancellation needs a 5-5-7 or a 5-7-7 triple (valences 5, 5, 7 or 5, 7, 7)");
    const int survivor = n5 == 2 ? 5 : 7;
    return SearchCancellation(out, triple, 2, survivor,
                              Str(n5 == 2 ? "5-5-7" : "5-7-7", " triple cancelled into one v", survivor));
  }

  // ------------------------------------------------------------ 4. quadruple generation
  /// A regular vertex p becomes part of a 5-5-7-7 quadruple contained in two triangles.
  ///   byFlip:  flip (p, n_k): p, n_k -> 5; n_k-1, n_k+1 -> 7.
  ///   bySplit: split p along (p, n_k), (p, n_k+3): p and the new vertex -> 5; n_k, n_k+3 -> 7.
  AtomicOutcome GenerateQuadruple(int p, int k, bool bySplit, int ref = -1) {
    AtomicOutcome out;
    Result pre = RequireInterior({p});
    if (!pre) return Refuse(out, pre.reason);
    if (ed_.Valence(p) != 6)
      return Refuse(out, Str("a 5-5-7-7 quadruple is generated from a regular vertex; vertex ", p, " has valence ",
                             ed_.Valence(p)));
    if (k < 0 || k > 5) return Refuse(out, "the direction must be 0..5");
    auto cp = ed_.Mark();
    const int nk = NeighbourFrom(p, ref, k);
    std::map<int, int> expect;
    std::vector<int> after;
    Result r;
    if (!bySplit) {
      const int a = NeighbourFrom(p, ref, k - 1), b = NeighbourFrom(p, ref, k + 1);
      Result reg = RequireRegular({nk, a, b});
      if (!reg) return Refuse(out, reg.reason);
      out.description = Str("flip edge (", p, ", ", nk, ")");
      expect = {{p, 5}, {nk, 5}, {a, 7}, {b, 7}};
      after = {p, nk, a, b};
      r = ed_.Flip(p, nk);
    } else {
      const int b = NeighbourFrom(p, ref, k + 3);
      Result reg = RequireRegular({nk, b});
      if (!reg) return Refuse(out, reg.reason);
      int created = -1;
      out.description = Str("split vertex ", p, " along edges (", p, ", ", nk, ") and (", p, ", ", b, ")");
      r = ed_.Split(p, nk, b, &created);
      if (r) {
        expect = {{p, 5}, {created, 5}, {nk, 7}, {b, 7}};
        after = {p, created, nk, b};
      }
    }
    return Finish(out, r, cp, expect, after);
  }

  // ------------------------------------------------------------ 5. quadruple removal
  /// The inverse: a 5-5-7-7 quadruple in the configuration of fig. 8 (two triangles) becomes
  /// regular. Searches the flips and collapses among the four vertices.
  AtomicOutcome RemoveQuadruple(const std::vector<int>& quad) {
    AtomicOutcome out;
    if (quad.size() != 4) return Refuse(out, "a quadruple removal needs exactly four vertices");
    Result pre = RequireInterior(quad);
    if (!pre) return Refuse(out, pre.reason);
    int n5 = 0, n7 = 0;
    for (int v : quad) {
      n5 += ed_.Valence(v) == 5;
      n7 += ed_.Valence(v) == 7;
    }
    if (n5 != 2 || n7 != 2) return Refuse(out, "a quadruple removal needs two v5 and two v7");
    return SearchCancellation(out, quad, 4, 0, "5-5-7-7 quadruple removed");
  }

 private:
  template <class... Args>
  static std::string Str(const Args&... args) {
    std::ostringstream o;
    using expand = int[];
    (void)expand{0, ((o << args), 0)...};
    return o.str();
  }

  static AtomicOutcome& Refuse(AtomicOutcome& out, const std::string& why) {
    out.result = Result::Fail(why);
    return out;
  }

  Result RequireInterior(const std::vector<int>& vs) {
    for (int v : vs) {
      if (!ed_.IsLive(v)) return Result::Fail(Str("vertex ", v, " does not exist"));
      if (ed_.IsBoundary(v))
        return Result::Fail(Str("vertex ", v, " lies on the boundary; these operations work on interior vertices"));
    }
    return Result::Ok();
  }

  Result RequireRegular(const std::vector<int>& vs) {
    for (int v : vs) {
      if (v < 0 || !ed_.IsLive(v)) return Result::Fail("the operation would reach past the mesh");
      if (ed_.IsBoundary(v))
        return Result::Fail(Str("the operation would touch boundary vertex ", v));
      if (ed_.Valence(v) != 6)
        return Result::Fail(Str("vertex ", v, " (valence ", ed_.Valence(v),
                                ") is in the way: this step needs regular vertices around the irregular ones; "
                                "try another direction or move the other irregular vertex first"));
    }
    return Result::Ok();
  }

  /// Checks the stated valence changes; rolls back and refuses if they do not hold.
  AtomicOutcome& Finish(AtomicOutcome& out, Result r, typename Editor::Checkpoint cp, const std::map<int, int>& expect,
                        const std::vector<int>& irregular) {
    if (!r) {
      ed_.RollbackTo(cp);
      return Refuse(out, r.reason);
    }
    for (auto& kv : expect) {
      const int got = ed_.IsLive(kv.first) ? ed_.Valence(kv.first) : 0;
      if (got != kv.second) {
        ed_.RollbackTo(cp);
        return Refuse(out, Str("internal check failed: vertex ", kv.first, " has valence ", got, " instead of ",
                               kv.second, " after ", out.description));
      }
    }
    out.changes = expect;
    out.irregular = irregular;
    out.result = Result::Ok();
    return out;
  }

  /// Candidate graph operation for FindAndApply.
  struct Candidate {
    int kind;  // 0 flip (x, y); 1 collapse x into y; 2 split x along (x, y), (x, z)
    int x, y, z;
  };

  /// Cancellation test for SearchCancellation: `cancelled` irregular vertices disappear, at most
  /// one of valence `survivor` (0 = none) remains, and no irregular vertex outside the group is
  /// touched.
  AtomicOutcome SearchCancellation(AtomicOutcome& out, const std::vector<int>& group, int cancelled, int survivor,
                                   const std::string& what) {
    AtomicOutcome found = FindAndApply(group, [&](const std::map<int, int>& before, const std::map<int, int>& after) {
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
    }, what, false);
    if (found) return out = found;
    return Refuse(out, Str("no single flip or collapse cancels these vertices: bring them closer first (",
                           what.substr(0, what.find(' ')), " cancellation needs them within one edge of each other, "
                           "as in the paper's figs. 7 and 8)"));
  }

 public:
  /// Predicts the valence changes of every flip, collapse (and, if withSplits, vertex split)
  /// around the group (its vertices and their neighbours) without editing (sec. 6.1 rules),
  /// and applies the first, in a deterministic order, whose prediction passes `test(before,
  /// after)` and whose group vertices are all touched. In `after`, a deleted vertex has valence
  /// 0 and a vertex created by a split has index -1. O(size of the neighbourhood squared).
  AtomicOutcome FindAndApply(const std::vector<int>& group,
                             const std::function<bool(const std::map<int, int>&, const std::map<int, int>&)>& test,
                             const std::string& what, bool withSplits = true) {
    AtomicOutcome out;
    std::vector<int> area = group;
    for (int v : group) {
      VertexStar<MeshType> s = ed_.Star(v);
      for (VertexType* n : s.neighbors) area.push_back(ed_.Index(n));
    }
    std::sort(area.begin(), area.end());
    area.erase(std::unique(area.begin(), area.end()), area.end());
    std::map<int, int> valence;
    auto val = [&](int v) {
      auto it = valence.find(v);
      if (it != valence.end()) return it->second;
      return valence[v] = ed_.Valence(v);
    };
    struct Scored {
      Candidate c;
      int o[2];
      int d1, d2;
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
          sc.c = Candidate{0, v, w, -1};
          cands.push_back(sc);
          sc.c = Candidate{1, w, v, -1};
          cands.push_back(sc);
        }
        if (!withSplits) continue;
        for (int l = 0; l < d; ++l) {
          if (l == k) continue;
          Scored sc;
          sc.c = Candidate{2, v, w, ed_.Index(s.neighbors[size_t(l)])};
          sc.d1 = ((l - k - 1) % d + d) % d;  // neighbours strictly between a = n_k and b = n_l
          sc.d2 = d - 2 - sc.d1;
          sc.o[0] = sc.o[1] = -1;
          cands.push_back(sc);
        }
      }
    }
    for (const Scored& sc : cands) {
      const Candidate& c = sc.c;
      const int* o = sc.o;
      std::vector<int> touched = c.kind == 2 ? std::vector<int>{c.x, c.y, c.z} : std::vector<int>{c.x, c.y, o[0], o[1]};
      bool covers = true;
      for (int g : group) covers = covers && std::find(touched.begin(), touched.end(), g) != touched.end();
      if (!covers) continue;
      std::map<int, int> before, pred;
      for (int t : touched) before[t] = val(t);
      const int dx = val(c.x), dy = val(c.y);
      if (c.kind == 0) {
        pred = {{c.x, dx - 1}, {c.y, dy - 1}, {o[0], val(o[0]) + 1}, {o[1], val(o[1]) + 1}};
      } else if (c.kind == 1) {
        pred = {{c.x, 0}, {c.y, dx + dy - 4}, {o[0], val(o[0]) - 1}, {o[1], val(o[1]) - 1}};
      } else {
        pred = {{c.x, sc.d1 + 3}, {-1, sc.d2 + 3}, {c.y, dy + 1}, {c.z, val(c.z) + 1}};
      }
      if (!test(before, pred)) continue;
      auto cp = ed_.Mark();
      int created = -1;
      Result r = c.kind == 0 ? ed_.Flip(c.x, c.y) : c.kind == 1 ? ed_.Collapse(c.x, c.y) : ed_.Split(c.x, c.y, c.z, &created);
      if (!r) {
        ed_.RollbackTo(cp);
        continue;
      }
      out.description = what + (c.kind == 0   ? Str(": flip edge (", c.x, ", ", c.y, ")")
                                : c.kind == 1 ? Str(": collapse vertex ", c.x, " into ", c.y)
                                              : Str(": split vertex ", c.x, " along edges to ", c.y, " and ", c.z));
      if (c.kind == 2) {
        pred[created] = pred[-1];
        pred.erase(-1);
      }
      std::vector<int> left;
      for (auto& kv : pred)
        if (kv.second != 6 && kv.second != 0) left.push_back(kv.first);
      return Finish(out, r, cp, pred, left);
    }
    return Refuse(out, "no single flip, collapse or split around these vertices does it");
  }

 private:
  Editor& ed_;
};

}  // namespace irregular
}  // namespace vcg_ext
