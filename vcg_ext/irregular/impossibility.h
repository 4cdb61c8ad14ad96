// filter_irregular: what cannot be done (paper sec. 5), decided on the theorems' conditions.
//
//  * Theorem 5.1: in a convex region R that contains exactly one irregular vertex v0, of a
//    valence that is not a multiple of 6, the interior of R cannot be remeshed so that it
//    still holds a single irregular vertex elsewhere: v0 cannot move alone inside R.
//  * Theorem 5.5: in a convex region R that contains exactly two irregular vertices v1, v2
//    with l(v1) + l(v2) = 12 (5-7, 4-8, 3-9), the interior of R cannot be retriangulated free
//    of irregular vertices: the pair cannot be cancelled inside R.
//
// The region checked is the largest k-ring neighbourhood around the vertex (around the pair
// and the connecting path between them, separatrix.h) that holds no other irregular vertex
// and does not reach the boundary. On a regular lattice a k-ring around a vertex is a
// hexagon, a convex region; around a pair it is contained in such a region. When the region
// is not empty of other irregular vertices (one lies within `near` rings), the theorem does
// not forbid an edit in a larger region, and the answer names that vertex and says what can
// be done with it instead (a pair move, sec. 7.1; a triple cancellation, sec. 7.2).
//
// Preconditions: FF and VF adjacency up to date on a manifold, consistently oriented mesh.
// Postconditions: the mesh is not modified. Cost: O(area of the rings searched).
#pragma once

#include <algorithm>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "separatrix.h"
#include "topology.h"

namespace vcg_ext {
namespace irregular {

/// The answer of a theorem check (sec. 5).
struct TheoremVerdict {
  bool applies = false;    ///< the theorem's condition holds: the request is impossible
  int freeRings = 0;       ///< rings around the vertex (pair) free of other irregular vertices
                           ///< and of the boundary, up to the search bound
  bool boundaryReached = false;  ///< the growth stopped at the boundary
  int nearest = -1;        ///< nearest other irregular vertex within the search bound, or -1
  int nearestValence = 0;
  int nearestDistance = -1;  ///< rings from the vertex (pair) to it
  std::string message;     ///< for the user: the theorem, or what can be done instead
};

template <class MeshType>
class ImpossibilityCheck {
 public:
  typedef typename MeshType::VertexType VertexType;

  /// near: rings within which another irregular vertex counts as "nearby" (the theorem then
  /// does not apply and that vertex is suggested); search: rings searched at most.
  explicit ImpossibilityCheck(MeshType& m, int near = 3, int search = 30) : m_(m), near_(near), search_(search) {}

  /// Theorem 5.1 for moving the single irregular vertex v alone.
  TheoremVerdict SingleVertexMove(int v) {
    TheoremVerdict r;
    const int d = Valence(v);
    Grow(std::vector<int>{v}, &r);
    std::ostringstream o;
    if (d % 6 == 0) {
      r.applies = false;
      o << "Theorem 5.1 does not forbid moving vertex " << v << ": its valence " << d << " is a multiple of 6.";
    } else if (r.nearest >= 0 && r.nearestDistance <= near_) {
      r.applies = false;
      o << "Vertex " << v << " (v" << d << ") cannot move alone (Theorem 5.1 forbids it in any convex region "
           "holding no other irregular vertex), but irregular vertex " << r.nearest << " (v"
        << r.nearestValence << ") is " << r.nearestDistance << " edge" << (r.nearestDistance == 1 ? "" : "s")
        << " away: select both and use 'Move Pair' (sec. 7.1), or move vertex " << v
        << " with 'move with 5-7 pair generation' (sec. 6.2).";
    } else {
      r.applies = true;
      o << "A single irregular vertex cannot be moved alone (Li et al., Theorem 5.1): the " << r.freeRings
        << "-ring around vertex " << v << " (v" << d << "), a convex region, contains no other irregular vertex"
        << (r.boundaryReached ? " (it reaches the boundary after that)" : "")
        << ", so no remeshing of it moves the vertex. ";
      if (r.nearest >= 0)
        o << "The nearest irregular vertex is " << r.nearest << " (v" << r.nearestValence << "), "
          << r.nearestDistance << " edges away: select both and use 'Move Pair'.";
      else
        o << "No other irregular vertex lies within " << search_ << " edges.";
      o << " Or use 'move with 5-7 pair generation', which moves it and leaves a 5-7 pair.";
    }
    r.message = o.str();
    return r;
  }

  /// Theorem 5.5 for cancelling the pair (a, b) alone, l(a) + l(b) = 12.
  TheoremVerdict PairCancellation(int a, int b) {
    TheoremVerdict r;
    const int da = Valence(a), db = Valence(b);
    std::ostringstream o;
    if (da + db != 12) {
      o << "Theorem 5.5 concerns pairs of opposite curvature (valences adding up to 12); vertices " << a << " and " << b
        << " have valences " << da << " and " << db << ".";
      r.message = o.str();
      return r;
    }
    std::vector<int> seeds{a, b};
    SeparatrixTracer<MeshType> tracer(m_);
    ConnectingPath p = tracer.Connect(a, b, search_);
    if (p)
      for (int x : p.Vertices()) seeds.push_back(x);
    Grow(seeds, &r, {a, b});
    const bool thirdNear = r.nearest >= 0 && r.nearestDistance <= near_;
    const int dc = r.nearestValence;
    const bool triple = thirdNear && (dc == 5 || dc == 7) && std::min(da, db) == 5;
    if (thirdNear) {
      r.applies = false;
      o << "The pair (" << a << ", " << b << ") cannot be cancelled alone (Theorem 5.5 forbids it in any convex "
           "region holding no other irregular vertex), but irregular vertex " << r.nearest << " (v"
        << dc << ") is " << r.nearestDistance << " edge" << (r.nearestDistance == 1 ? "" : "s") << " away";
      if (triple)
        o << ": with it the pair forms a " << (dc == 5 ? "5-5-7" : "5-7-7")
          << " triple, which can be cancelled into one v" << dc
          << " (sec. 7.2): select the three and use 'Cancel Triple'.";
      else
        o << ": reduce the vertices to valences 5 and 7 ('Reduce to Valence 5 and 7') and cancel them as triples "
             "or quadruples (sec. 7.2, 7.3).";
    } else {
      r.applies = true;
      o << "A pair of opposite curvature (v" << std::min(da, db) << "-v" << std::max(da, db)
        << ") cannot be cancelled (Li et al., Theorem 5.5): the " << r.freeRings << "-ring around vertices " << a
        << " and " << b << " and the path between them contains no other irregular vertex"
        << (r.boundaryReached ? " (it reaches the boundary after that)" : "")
        << ", and no retriangulation of a convex region holding only the pair is free of irregular vertices. ";
      if (r.nearest >= 0)
        o << "The nearest other irregular vertex is " << r.nearest << " (v" << dc << "), " << r.nearestDistance
          << " edges away: move the pair next to it ('Move Pair'), then cancel the triple or quadruple.";
      else
        o << "No other irregular vertex lies within " << search_ << " edges.";
    }
    r.message = o.str();
    return r;
  }

 private:
  int Index(const VertexType* v) const { return int(vcg::tri::Index(m_, v)); }
  int Valence(int v) { return irregular::Valence<MeshType>(&m_.vert[size_t(v)]); }

  /// Breadth-first rings from `seeds` (ring 0). freeRings: the largest k such that rings
  /// 1..k hold no boundary vertex and no irregular vertex other than `own` (default: the
  /// seeds). nearest: the lowest-index other irregular vertex of the first ring holding one.
  void Grow(const std::vector<int>& seeds, TheoremVerdict* r, std::vector<int> own = {}) {
    if (own.empty()) own = seeds;
    std::unordered_map<int, int> dist;
    std::vector<int> frontier;
    for (int s : seeds)
      if (dist.emplace(s, 0).second) frontier.push_back(s);
    bool blocked = false;
    for (int k = 1; k <= search_ && !frontier.empty(); ++k) {
      std::vector<int> next;
      for (int v : frontier)
        for (VertexType* n : StarOf<MeshType>(&m_.vert[size_t(v)]).neighbors) {
          const int w = Index(n);
          if (!dist.emplace(w, k).second) continue;
          next.push_back(w);
          VertexStar<MeshType> sw = StarOf<MeshType>(n);
          if (sw.boundary) {
            r->boundaryReached = r->boundaryReached || !blocked;
            blocked = true;
          } else if (sw.Valence() != 6 && std::find(own.begin(), own.end(), w) == own.end()) {
            blocked = true;
            if (r->nearest < 0 || w < r->nearest) r->nearest = w, r->nearestValence = sw.Valence(), r->nearestDistance = k;
          }
        }
      if (!blocked) r->freeRings = k;
      if (r->nearest >= 0) return;
      frontier.swap(next);
    }
  }

  MeshType& m_;
  int near_, search_;
};

}  // namespace irregular
}  // namespace vcg_ext
