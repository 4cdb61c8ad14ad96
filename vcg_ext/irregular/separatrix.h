// filter_irregular: separatrices and connecting paths with a turn point (paper sec. 5, 7.1.1).
//
// A path is straight when every interior vertex is regular and non-turning: at each interior
// vertex the path leaves by the edge opposite to the one it came in by, i.e. 3 positions
// further in the valence-6 fan, so both sides hold 3 triangles (sec. 5). A separatrix is a
// straight path that starts at an irregular vertex (Definition 5.3); traced from a vertex
// along one of its edges, it ends at the first irregular or boundary vertex.
//
// Two irregular vertices that no separatrix joins are joined by a path of two straight
// segments, one from each end, meeting at a turn point (sec. 7.1.1: "the intersection of two
// separatrices, each from one irregular vertex"); the 5-7 pair transport of composite_ops.h
// follows it. ConnectingPath traces every direction from both ends, so it costs
// O((d(a) + d(b)) * maxLength) star queries and memory, O(L) for a fixed bound.
//
// Preconditions (all functions): FF and VF adjacency up to date on a manifold, consistently
// oriented triangle mesh (what MeshEditor keeps); vertex indices refer to live vertices.
// Postconditions: the mesh is not modified.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "result.h"
#include "topology.h"

namespace vcg_ext {
namespace irregular {

/// A straight path traced from a vertex: vertices[0] is the start, vertices[1] the first
/// neighbour; every vertex strictly between the ends is regular interior and non-turning.
struct Separatrix {
  enum class End {
    Irregular,  ///< the last vertex is irregular (valence != 6) or the start itself
    Boundary,   ///< the last vertex lies on the boundary
    MaxLength,  ///< stopped after maxLength edges at a regular vertex
    Loop        ///< the next vertex would repeat one already on the path (closed surface); the
                ///< last vertex is the one before the repetition
  };
  std::vector<int> vertices;
  End end = End::MaxLength;
  int Length() const { return int(vertices.size()) - 1; }
};

/// The path joining a and b made of at most two straight segments (sec. 7.1.1).
///   first  = a ... turn (straight),   second = turn ... b (straight);
/// when a separatrix of a reaches b, the path is straight: first = a ... b, second empty,
/// turn = -1. turnTriangles: at the turn point, the number of triangles between the incoming
/// and the outgoing edge counter-clockwise (1, 2, 4 or 5; 3 would be straight).
struct ConnectingPath {
  Result result = Result::Fail("not searched");
  std::vector<int> first, second;
  int turn = -1;
  int turnTriangles = 3;
  int L1() const { return int(first.size()) - 1; }
  int L2() const { return second.empty() ? 0 : int(second.size()) - 1; }
  int Length() const { return L1() + L2(); }
  /// a ... turn ... b, each vertex once.
  std::vector<int> Vertices() const {
    std::vector<int> v = first;
    if (!second.empty()) v.insert(v.end(), second.begin() + 1, second.end());
    return v;
  }
  explicit operator bool() const { return result.ok; }
};

/// The polygon of a 5-5-7-7 quadruple (sec. 7.3, fig. 11): the four vertices in cyclic order
/// around their centroid, and side i = the connecting path from vertex i to vertex i+1, of
/// two straight segments of lengths (x_i, y_i) (x_i >= y_i: the order of the two segments
/// is not compared). Sec. 7.3: the quadruple can be generated from (cancelled into) a
/// regular triangulation only if opposite sides match, x_i = x_{i+2} and y_i = y_{i+2};
/// otherwise one of its 5-7 pairs could be removed alone, which Theorem 5.5 forbids.
struct QuadruplePolygon {
  Result result = Result::Fail("not computed");  ///< fails when a side cannot be traced
  int order[4] = {-1, -1, -1, -1};
  int x[4] = {0, 0, 0, 0}, y[4] = {0, 0, 0, 0};
  bool OppositeSidesMatch() const { return x[0] == x[2] && y[0] == y[2] && x[1] == x[3] && y[1] == y[3]; }
  std::string Sides() const {
    std::string s;
    for (int i = 0; i < 4; ++i)
      s += (i ? ", " : "") + std::string("(") + std::to_string(x[i]) + ", " + std::to_string(y[i]) + ")";
    return s;
  }
};

template <class MeshType>
class SeparatrixTracer {
 public:
  typedef typename MeshType::VertexType VertexType;

  explicit SeparatrixTracer(MeshType& m) : m_(m) {}

  /// Is v a vertex where a straight path may pass: interior, valence 6.
  bool IsRegularInterior(int v) {
    VertexStar<MeshType> s = StarOf<MeshType>(V(v));
    return !s.boundary && s.manifold && s.Valence() == 6;
  }

  /// The straight continuation at a regular interior vertex cur entered from prev: the
  /// neighbour 3 positions further in cur's fan. -1 if cur is not regular interior or prev is
  /// not its neighbour.
  int StraightNext(int prev, int cur) {
    VertexStar<MeshType> s = StarOf<MeshType>(V(cur));
    if (s.boundary || !s.manifold || s.Valence() != 6) return -1;
    const int i = s.IndexOf(V(prev));
    if (i < 0) return -1;
    return Index(s.neighbors[size_t((i + 3) % 6)]);
  }

  /// Traces the straight path from `start` through its neighbour `first` (precondition: they
  /// are adjacent) until an irregular or boundary vertex, at most maxLength edges, or a loop.
  /// The start itself may be irregular or regular (for a regular start this is just a straight
  /// line). O(length).
  Separatrix Trace(int start, int first, int maxLength) {
    Separatrix s;
    s.vertices = {start};
    std::unordered_set<int> seen{start};
    int prev = start, cur = first;
    for (;;) {
      if (seen.count(cur)) {
        s.end = Separatrix::End::Loop;
        // the path closes on itself: a closed separatrix when cur == start
        if (cur == start) s.vertices.push_back(cur);
        return s;
      }
      s.vertices.push_back(cur);
      seen.insert(cur);
      VertexStar<MeshType> st = StarOf<MeshType>(V(cur));
      if (st.boundary) {
        s.end = Separatrix::End::Boundary;
        return s;
      }
      if (st.Valence() != 6 || !st.manifold) {
        s.end = Separatrix::End::Irregular;
        return s;
      }
      if (s.Length() >= maxLength) {
        s.end = Separatrix::End::MaxLength;
        return s;
      }
      const int i = st.IndexOf(V(prev));
      const int next = Index(st.neighbors[size_t((i + 3) % 6)]);
      prev = cur;
      cur = next;
    }
  }

  /// All straight paths leaving v, one per edge, in the CCW order of v's star.
  std::vector<Separatrix> TraceAll(int v, int maxLength) {
    std::vector<Separatrix> r;
    VertexStar<MeshType> s = StarOf<MeshType>(V(v));
    for (VertexType* n : s.neighbors) r.push_back(Trace(v, Index(n), maxLength));
    return r;
  }

  /// The polygon of fig. 11 for the quadruple q (four distinct vertices): cyclic order by the
  /// angle around their centroid in the plane of the mean vertex normal, and the (x_i, y_i)
  /// of the connecting path between consecutive vertices (sides of one edge: (1, 0)).
  /// O(4 * Connect).
  QuadruplePolygon Polygon(const std::vector<int>& q, int maxLength) {
    QuadruplePolygon P;
    if (q.size() != 4) {
      P.result = Result::Fail("a quadruple has four vertices");
      return P;
    }
    typedef typename MeshType::CoordType C;
    C c(0, 0, 0), n(0, 0, 0);
    for (int v : q) {
      c += V(v)->P();
      VertexStar<MeshType> s = StarOf<MeshType>(V(v));
      for (auto& k : s.corners) n += vcg::TriangleNormal(*k.f);
    }
    c /= 4;
    if (n.Norm() == 0) n = C(0, 0, 1);
    n.Normalize();
    C u = V(q[0])->P() - c;
    u -= n * (u.dot(n));
    if (u.Norm() == 0) u = C(1, 0, 0);
    u.Normalize();
    const C w = n ^ u;
    std::vector<std::pair<double, int>> ang;
    for (int v : q) {
      const C d = V(v)->P() - c;
      ang.push_back({std::atan2(double(d.dot(w)), double(d.dot(u))), v});
    }
    std::sort(ang.begin(), ang.end());
    for (int i = 0; i < 4; ++i) P.order[i] = ang[size_t(i)].second;
    for (int i = 0; i < 4; ++i) {
      ConnectingPath p = Connect(P.order[i], P.order[(i + 1) % 4], maxLength);
      if (!p) {
        P.result = p.result;
        return P;
      }
      P.x[i] = std::max(p.L1(), p.L2());
      P.y[i] = std::min(p.L1(), p.L2());
    }
    P.result = Result::Ok();
    return P;
  }

  /// The shortest path from a to b made of a straight segment from a and one from b meeting
  /// at a regular turn point (or a single straight segment from a to b), each segment at most
  /// maxLength edges. Ties: the shorter first segment, then the CCW order of a's and b's stars.
  /// The minimal path is simple: a vertex shared by the two segments before the turn point
  /// would give a shorter one. Fails, with the reason, when no such path exists (an irregular
  /// vertex or the boundary blocks every line within maxLength).
  ConnectingPath Connect(int a, int b, int maxLength) {
    ConnectingPath p;
    if (a == b) {
      p.result = Result::Fail("the two vertices are the same");
      return p;
    }
    // index of every vertex reached from a: (ray, distance), first reach only
    std::vector<Separatrix> fromA = TraceAll(a, maxLength), fromB = TraceAll(b, maxLength);
    std::unordered_map<int, std::pair<int, int>> reachA;
    int bestLen = -1, bestL1 = 0, rayA = -1, rayB = -1, atA = 0, atB = 0;
    auto better = [&](int len, int l1) { return bestLen < 0 || len < bestLen || (len == bestLen && l1 < bestL1); };
    for (size_t r = 0; r < fromA.size(); ++r) {
      const Separatrix& s = fromA[r];
      for (int i = 1; i <= s.Length(); ++i) {
        const int v = s.vertices[size_t(i)];
        if (v == b) {  // a separatrix of a reaches b: straight
          if (better(i, i)) bestLen = i, bestL1 = i, rayA = int(r), atA = i, rayB = -1;
          break;
        }
        // only regular interior vertices can be turn points (the path's interior is regular)
        const bool lastIsRegular = s.end == Separatrix::End::MaxLength || s.end == Separatrix::End::Loop;
        if (i == s.Length() && !lastIsRegular) break;
        if (v != a && !reachA.count(v)) reachA[v] = {int(r), i};
      }
    }
    for (size_t r = 0; r < fromB.size(); ++r) {
      const Separatrix& s = fromB[r];
      for (int j = 1; j <= s.Length(); ++j) {
        const int v = s.vertices[size_t(j)];
        auto it = reachA.find(v);
        if (it == reachA.end()) continue;
        const int i = it->second.second;
        const Separatrix& sa = fromA[size_t(it->second.first)];
        // the incoming and outgoing edges at the turn point must differ (no backtracking)
        if (sa.vertices[size_t(i - 1)] == s.vertices[size_t(j - 1)]) continue;
        if (better(i + j, i)) bestLen = i + j, bestL1 = i, rayA = it->second.first, atA = i, rayB = int(r), atB = j;
      }
    }
    if (bestLen < 0) {
      p.result = Result::Fail("no path of two straight segments joins vertices " + std::to_string(a) + " and " +
                              std::to_string(b) + " within " + std::to_string(maxLength) +
                              " edges per segment: irregular vertices or the boundary block every line between them");
      return p;
    }
    const Separatrix& sa = fromA[size_t(rayA)];
    p.first.assign(sa.vertices.begin(), sa.vertices.begin() + atA + 1);
    if (rayB >= 0) {
      const Separatrix& sb = fromB[size_t(rayB)];
      p.second.assign(sb.vertices.begin(), sb.vertices.begin() + atB + 1);
      std::reverse(p.second.begin(), p.second.end());
      p.turn = p.first.back();
      VertexStar<MeshType> st = StarOf<MeshType>(V(p.turn));
      const int in = st.IndexOf(V(p.first[p.first.size() - 2])), out = st.IndexOf(V(p.second[1]));
      p.turnTriangles = ((out - in) % 6 + 6) % 6;
      if (p.turnTriangles == 3) {  // the two lines continue each other: one straight segment
        p.first.insert(p.first.end(), p.second.begin() + 1, p.second.end());
        p.second.clear();
        p.turn = -1;
      }
    }
    p.result = Result::Ok();
    return p;
  }

 private:
  VertexType* V(int i) { return &m_.vert[size_t(i)]; }
  int Index(const VertexType* v) const { return int(vcg::tri::Index(m_, v)); }

  MeshType& m_;
};

}  // namespace irregular
}  // namespace vcg_ext
