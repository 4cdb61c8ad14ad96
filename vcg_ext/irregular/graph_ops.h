// filter_irregular: graph editing operations (paper sec. 6.1): edge flip, edge collapse,
// vertex split, each with a validity check and a local update of FF and VF adjacency.
//
// Valence effects (d = valence; paper sec. 6.1):
//   Flip(x, y), opposite vertices o1, o2:    x, y: d-1;  o1, o2: d+1.
//   Collapse(u -> v), opposite vertices a, b: v: d(u)+d(v)-4;  a, b: d-1;  u is deleted.
//   Split(w; a, b), the edges (w,a), (w,b) part the other edges of w into d1 (from a to b
//     counter-clockwise) and d2 (from b to a): w keeps the first group, d(w) = d1+3; a new
//     vertex w' takes the second, d(w') = d2+3; a, b: d+1.
//
// Vertices are named by index into m.vert (pointers move when elements are added).
//
// Boundaries. The paper defines the operations on closed surfaces; here they also act on and
// next to a boundary whenever the result is a manifold with a consistent boundary (each
// boundary vertex keeps one fan of faces, so exactly two boundary edges). Think of every
// boundary loop as closed by a virtual cone vertex: the rules below are the closed-surface
// rules (link condition, valence >= 3) applied to that closed surface. A boundary vertex has
// valence >= 2 (one face), an interior one >= 3.
//   Flip: an interior edge may touch the boundary (its ends or opposites on it); a boundary
//     edge is never flipped.
//   Collapse(u -> v):
//     - interior edge, u interior, v on the boundary: v survives where it is (on the boundary
//       curve); link condition: u and v share exactly the two opposite vertices.
//       Valences: v: d(u)+d(v)-4; opposites: d-1.
//     - interior edge, u on the boundary and v interior: refused (collapse v into u instead,
//       so the boundary vertex survives);
//     - interior edge with both ends on the boundary: refused, it would pinch the surface
//       (the merged vertex would have two fans);
//     - boundary edge (u, v) with apex a (the one face): link condition for boundary edges,
//       u and v share exactly the neighbour a; v survives at the midpoint of the edge (or at
//       v, or u: all on the boundary polyline; at the corner when one end is a corner, see
//       topology.h); valences: v: d(u)+d(v)-3, a: d-1.
//   Split(w; a, b) of a boundary vertex w: both (w,a) and (w,b) must be interior edges. The
//     half that holds the boundary (the faces next to the two boundary edges) stays on the
//     boundary at w's position; the other half becomes an interior vertex. Which half is
//     which follows the same rule as inside: w keeps the edges from a to b counter-clockwise.
//   SplitBoundary(w; a): the inverse of a boundary-edge collapse: w splits along one interior
//     edge (w, a) into two boundary vertices joined by a new boundary edge (see there).
// Every operation is journaled (journal.h): a refused operation, including one refused by the
// geometric check after trying it, leaves the mesh exactly as it was.
// Attributes are carried (attribute_transfer.h): texture coordinates by interpolation, face
// and vertex colours and qualities by copy; an edit across a texture seam is refused, by the
// dry run too.
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/simplex/face/topology.h>

#include "attribute_transfer.h"
#include "journal.h"
#include "result.h"
#include "slot_pool.h"
#include "topology.h"

namespace vcg_ext {
namespace irregular {

/// Geometric validity of an edit. Defaults keep the surface free of folds.
struct GeometryOptions {
  bool checkFolds = true;        ///< refuse an edit whose new faces fold against the old ones
  double maxNormalTurnDeg = 80;  ///< a changed face may turn at most this much from the
                                 ///< (area-weighted) normal of the faces it replaces
  double minAreaRatio = 1e-4;    ///< a changed face must keep this share of the mean old area
};

template <class MeshType>
class MeshEditor {
 public:
  typedef typename MeshType::FaceType FaceType;
  typedef typename MeshType::VertexType VertexType;
  typedef typename MeshType::CoordType CoordType;
  typedef typename MeshType::ScalarType ScalarType;
  typedef EditJournal<MeshType> Journal;
  typedef typename Journal::Checkpoint Checkpoint;
  typedef Corner<FaceType> CornerT;

  /// Precondition: FF and VF adjacency are up to date (vcg UpdateTopology FaceFace and
  /// VertexFace) on a manifold, consistently oriented triangle mesh.
  explicit MeshEditor(MeshType& m, GeometryOptions g = GeometryOptions()) : m_(m), journal_(m), geom_(g), attr_(m) {}

  MeshType& Mesh() { return m_; }
  Journal& journal() { return journal_; }
  GeometryOptions& geometry() { return geom_; }
  Checkpoint Mark() const { return journal_.Mark(); }
  void RollbackTo(const Checkpoint& c) {
    journal_.RollbackTo(c);
    slots_.RollbackTo(c);
  }
  void Commit() {
    slots_.Harvest(m_, journal_);
    journal_.Commit();
  }
  /// Dead slots for new elements (slot_pool.h): off by default; Automatic Reduction turns it on.
  SlotPool<MeshType>& slotPool() { return slots_; }
  /// Index the k-th vertex a split creates from now will get (k = 0: the next one).
  int NextCreatedVertex(int k) const { return slots_.NextVertex(m_, k); }

  VertexType* V(int i) { return &m_.vert[size_t(i)]; }
  int Index(const VertexType* v) const { return int(vcg::tri::Index(m_, v)); }
  bool IsLive(int i) const { return i >= 0 && size_t(i) < m_.vert.size() && !m_.vert[size_t(i)].IsD() && m_.vert[size_t(i)].cVFp(); }
  VertexStar<MeshType> Star(int i) { return StarOf<MeshType>(V(i)); }
  int Valence(int i) { return irregular::Valence<MeshType>(V(i)); }
  bool IsBoundary(int i) { return OnBoundary<MeshType>(V(i)); }
  /// Valence of vertex i if it is interior, -1 on the boundary (topology.h: one walk for both).
  int InteriorValence(int i) { return irregular::InteriorValence<MeshType>(V(i)); }
  /// Smallest valence a vertex may keep: 2 on the boundary (one face), 3 inside.
  static int MinValence(bool boundary) { return boundary ? 2 : 3; }
  /// Is (x, y) an edge with a face on one side only? False if they are not joined.
  bool IsBoundaryEdge(int x, int y) {
    CornerT c;
    return EdgeCorner(x, y, c) && c.f->FFp(c.z) == c.f;
  }
  bool Adjacent(int a, int b) { return Star(a).IndexOf(V(b)) >= 0; }
  /// Attributes: Ok when no texture seam runs through the star of vertex i (per-wedge texture
  /// coordinates agree across every edge at i), the condition this editor's splits check; for
  /// operations built beside it (boundary_ops.h's ear split).
  Result StarSeamless(int i) { return attr_.StarSeamless(Star(i)); }

  /// The vertices opposite to edge (x, y): o[0] on the left of x->y (in the face x, y, o0),
  /// o[1] on the right. False if the edge does not exist or lies on the boundary.
  bool Opposites(int x, int y, int o[2]) {
    CornerT c;
    if (!EdgeCorner(x, y, c)) return false;
    FaceType* g = c.f->FFp(c.z);
    if (g == c.f) return false;
    o[0] = Index(c.f->V((c.z + 2) % 3));
    o[1] = Index(g->V((c.f->FFi(c.z) + 2) % 3));
    return true;
  }

  // ---------------------------------------------------------------- edge flip
  /// Can edge (x, y) be flipped? Topology only: interior manifold edge (its ends may lie on
  /// the boundary), distinct opposite vertices that are not already joined, x and y keep
  /// valence >= 3 (>= 2 on the boundary).
  Result CanFlip(int x, int y) {
    if (!IsLive(x) || !IsLive(y)) return Result::Fail("a vertex of the edge does not exist");
    CornerT c;
    if (!EdgeCorner(x, y, c)) return Fail("vertices ", x, " and ", y, " are not joined by an edge");
    if (c.f->FFp(c.z) == c.f) return Fail("edge (", x, ", ", y, ") lies on the boundary (a boundary edge cannot be flipped)");
    int o[2];
    Opposites(x, y, o);
    if (o[0] == o[1]) return Fail("edge (", x, ", ", y, ") has the same vertex on both sides");
    if (Adjacent(o[0], o[1]))
      return Fail("flipping edge (", x, ", ", y, ") would duplicate the existing edge (", o[0], ", ", o[1], ")");
    for (int e : {x, y}) {
      VertexStar<MeshType> se = Star(e);
      if (se.Valence() - 1 < MinValence(se.boundary))
        return Fail("flipping edge (", x, ", ", y, ") would leave ", se.boundary ? "boundary vertex " : "vertex ", e,
                    " with valence ", se.Valence() - 1);
    }
    Result seam = attr_.EdgeSeamless(c.f, c.z);  // attributes: the flip would mix the seam's sides
    if (!seam) return Fail("flipping edge (", x, ", ", y, ") would mix the two sides of a texture seam: ", seam.reason);
    return Result::Ok();
  }

  /// Flips edge (x, y) into (o0, o1) using vcg::face::FlipEdge, then repairs VF locally.
  Result Flip(int x, int y) {
    Result ok = CanFlip(x, y);
    if (!ok) return ok;
    Checkpoint cp = Mark();
    CornerT c;
    EdgeCorner(x, y, c);
    FaceType* f = c.f;
    const int z = c.z;
    FaceType* g = f->FFp(z);
    const int w = f->FFi(z);
    int o[2];
    Opposites(x, y, o);
    const CoordType ref = RegionNormal({f, g});
    const ScalarType refArea = (Area(f) + Area(g)) / 2;
    const auto carried = attr_.BeforeFlip(f, z);  // attributes: texcoords by vertex, colour
    // FlipEdge rewires f, g and the FF slots of the two outer faces across f's edge z+1 and
    // g's edge w+1.
    journal_.SaveFace(f);
    journal_.SaveFace(g);
    if (f->FFp((z + 1) % 3) != f) journal_.SaveFace(f->FFp((z + 1) % 3));
    if (g->FFp((w + 1) % 3) != g) journal_.SaveFace(g->FFp((w + 1) % 3));
    vcg::face::FlipEdge(*f, z);
    UpdateNormal(f);
    UpdateNormal(g);
    for (int v : {x, y, o[0], o[1]}) RelinkVF(V(v));
    Result geo = CheckGeometry({f, g}, ref, refArea);
    if (geo) geo = attr_.AfterFlip(carried, f, g, geom_);
    if (!geo) {
      RollbackTo(cp);
      return Fail("flipping edge (", x, ", ", y, ") ", geo.reason);
    }
    return Result::Ok();
  }

  // ---------------------------------------------------------------- edge collapse
  /// Can u be collapsed into v? Link condition (u and v share exactly the two opposite
  /// vertices; on a boundary edge, exactly its apex), every valence stays >= 3 (>= 2 on the
  /// boundary), and the boundary stays consistent (see the header comment: a boundary vertex
  /// survives, an interior edge between two boundary vertices is refused).
  Result CanCollapse(int u, int v) {
    if (!IsLive(u) || !IsLive(v)) return Result::Fail("a vertex of the edge does not exist");
    if (!Adjacent(u, v)) return Fail("vertices ", u, " and ", v, " are not joined by an edge");
    VertexStar<MeshType> su = Star(u), sv = Star(v);
    if (IsBoundaryEdge(u, v)) return CanCollapseBoundaryEdge(u, v, su, sv);
    if (su.boundary && sv.boundary)
      return Fail("edge (", u, ", ", v, ") joins two boundary vertices through the inside: collapsing it would pinch "
                  "the surface");
    if (su.boundary)
      return Fail("vertex ", u, " lies on the boundary: collapse ", v, " into ", u,
                  " instead, so that the boundary vertex survives");
    int o[2];
    Opposites(u, v, o);
    int common = 0;
    for (VertexType* n : su.neighbors)
      if (sv.IndexOf(n) >= 0) ++common;
    if (common != 2 || o[0] == o[1])
      return Fail("collapsing edge (", u, ", ", v, ") would break the surface (link condition: its ends share ",
                  common, " neighbours instead of 2)");
    for (int q : {o[0], o[1]}) {
      VertexStar<MeshType> sq = Star(q);
      if (sq.Valence() - 1 < MinValence(sq.boundary))
        return Fail("collapsing edge (", u, ", ", v, ") would leave a vertex of valence ", sq.Valence() - 1);
    }
    if (su.Valence() + sv.Valence() - 4 < MinValence(sv.boundary))
      return Fail("collapsing edge (", u, ", ", v, ") would leave a vertex of valence < 3");
    Result seam = attr_.StarSeamless(su);  // attributes: interpolation needs one texture around u, v
    if (seam) seam = attr_.StarSeamless(sv);
    if (!seam) return Fail("collapsing edge (", u, ", ", v, ") cannot carry the texture: ", seam.reason);
    return Result::Ok();
  }

  /// Collapses edge (u, v): u is deleted, v survives at the midpoint (or, if that folds the
  /// surface, at v's or u's position). Returns Ok with v surviving. A boundary vertex v that
  /// survives an interior edge stays where it is; on a boundary edge the survivor stays on
  /// the boundary polyline, at the corner if exactly one end is a corner (topology.h).
  Result Collapse(int u, int v) {
    Result ok = CanCollapse(u, v);
    if (!ok) return ok;
    const CoordType pu = V(u)->P(), pv = V(v)->P();
    std::vector<CoordType> targets{(pu + pv) / ScalarType(2), pv, pu};
    if (IsBoundaryEdge(u, v)) {
      const bool cu = IsBoundaryCorner(CornerAngleDeg(Star(u))), cv = IsBoundaryCorner(CornerAngleDeg(Star(v)));
      if (cu != cv) targets = {cu ? pu : pv};
    } else if (IsBoundary(v)) {
      targets = {pv};
    }
    Result last;
    for (const CoordType& target : targets) {
      last = CollapseAt(u, v, target);
      if (last) return last;
    }
    return Fail("collapsing edge (", u, ", ", v, ") ", last.reason);
  }

  // ---------------------------------------------------------------- vertex split
  /// Can w be split along its edges to a and b? a != b both neighbours of w; on a boundary
  /// vertex both edges must be interior (not the two boundary edges of w).
  Result CanSplit(int w, int a, int b) {
    if (!IsLive(w) || !IsLive(a) || !IsLive(b)) return Result::Fail("a vertex of the split does not exist");
    VertexStar<MeshType> s = Star(w);
    if (a == b) return Fail("a vertex split needs two different edges of vertex ", w);
    const int i = s.IndexOf(V(a)), j = s.IndexOf(V(b));
    if (i < 0 || j < 0) return Fail("vertices ", a, " and ", b, " must both be neighbours of vertex ", w);
    if (s.boundary) {
      const int last = s.Valence() - 1;
      for (int k : {i, j})
        if (k == 0 || k == last)
          return Fail("edge (", w, ", ", Index(s.neighbors[size_t(k)]), ") lies on the boundary: a boundary vertex is "
                      "split along two interior edges");
    }
    Result seam = attr_.StarSeamless(s);  // attributes: interpolation needs one texture around w
    if (!seam) return Fail("splitting vertex ", w, " cannot carry the texture: ", seam.reason);
    return Result::Ok();
  }

  /// Splits w into w (keeping the edges from a to b counter-clockwise) and a new vertex
  /// (keeping those from b to a), joined by a new edge; adds faces (w, b, w') and (w, w', a).
  /// *created receives the new vertex index.
  Result Split(int w, int a, int b, int* created = nullptr) {
    Result ok = CanSplit(w, a, b);
    if (!ok) return ok;
    Result last;
    for (ScalarType s : {ScalarType(1) / 3, ScalarType(1) / 6, ScalarType(0.05)}) {
      last = SplitWith(w, a, b, s, created);
      if (last) return last;
    }
    return Fail("splitting vertex ", w, " ", last.reason);
  }

  /// Where Split(w, a, b) puts w and the new vertex, without editing the mesh: false if the
  /// split cannot be done or its places are not certain. With the fold check on
  /// (GeometryOptions::checkFolds), a split refused at share 1/3 retries at smaller shares, so
  /// only the first share's places are known; with it off (a topology-only probe) the first
  /// share always holds. Exact to the bit: SplitWith computes its places with the same
  /// function. Precondition: CanSplit(w, a, b).
  bool PredictSplitPlaces(int w, int a, int b, CoordType& pw, CoordType& px) {
    if (geom_.checkFolds) return false;
    VertexStar<MeshType> st = Star(w);
    const int i = st.IndexOf(V(a)), j = st.IndexOf(V(b));
    if (i < 0 || j < 0 || i == j) return false;
    SplitPlaces(st, V(w)->P(), i, j, ScalarType(1) / 3, pw, px);
    return true;
  }

  // ---------------------------------------------------------------- boundary vertex split
  /// Can boundary vertex w be split along its interior edge to a, the inverse of collapsing a
  /// boundary edge? w on the boundary, (w, a) an interior edge.
  Result CanSplitBoundary(int w, int a) {
    if (!IsLive(w) || !IsLive(a)) return Result::Fail("a vertex of the split does not exist");
    VertexStar<MeshType> s = Star(w);
    if (!s.boundary) return Fail("vertex ", w, " does not lie on the boundary");
    const int i = s.IndexOf(V(a));
    if (i < 0) return Fail("vertex ", a, " is not a neighbour of vertex ", w);
    if (i == 0 || i == s.Valence() - 1)
      return Fail("edge (", w, ", ", a, ") lies on the boundary: a boundary vertex is split along an interior edge");
    Result seam = attr_.StarSeamless(s);  // attributes: interpolation needs one texture around w
    if (!seam) return Fail("splitting boundary vertex ", w, " cannot carry the texture: ", seam.reason);
    return Result::Ok();
  }

  /// Splits boundary vertex w along its interior edge to a into two boundary vertices joined
  /// by a new boundary edge, adding the face (w, a, x). With w's fan nb[0..n] (nb[0], nb[n]
  /// its boundary neighbours) and a = nb[i]: w keeps nb[0..i], the new vertex x takes
  /// nb[i..n]. Valences: w: i + 2, x: n - i + 2, a: +1 (sec. 6.1 rules on the surface closed
  /// by a cone vertex: the inverse of Collapse across the new edge). w moves a share of the
  /// way towards nb[0], x towards nb[n]: both stay on the boundary polyline.
  /// *created receives x.
  Result SplitBoundary(int w, int a, int* created = nullptr) {
    Result ok = CanSplitBoundary(w, a);
    if (!ok) return ok;
    Result last;
    for (ScalarType s : {ScalarType(1) / 3, ScalarType(1) / 6, ScalarType(0.05)}) {
      last = SplitBoundaryWith(w, a, s, created);
      if (last) return last;
    }
    return Fail("splitting boundary vertex ", w, " ", last.reason);
  }

  /// Recomputes the VF list of v from its fan, found through FF from any live corner of v.
  /// O(valence). Journals every face it relinks.
  void RelinkVF(VertexType* v) {
    CornerT start = LiveCorner(v);
    journal_.SaveVertex(v);
    if (start.f == nullptr) {
      v->VFp() = nullptr;
      v->VFi() = 0;
      return;
    }
    // rewind clockwise to the boundary (or once round), then walk counter-clockwise
    CornerT c = start;
    for (;;) {
      CornerT p = NextCornerCW(c);
      if (p.f == nullptr || (p.f == start.f && p.z == start.z)) break;
      c = p;
    }
    const CornerT first = c;
    v->VFp() = first.f;
    v->VFi() = first.z;
    for (;;) {
      CornerT n = NextCornerCCW(c);
      journal_.SaveFace(c.f);
      if (n.f == nullptr || (n.f == first.f && n.z == first.z)) {
        c.f->VFp(c.z) = nullptr;
        c.f->VFi(c.z) = 0;
        break;
      }
      c.f->VFp(c.z) = n.f;
      c.f->VFi(c.z) = n.z;
      c = n;
    }
  }

 private:
  /// CanCollapse for a boundary edge (u, v) with apex a: the link condition of the surface
  /// closed by a virtual cone vertex (u and v share only a), and a keeps valence >= 2 (or 3).
  /// The isolated triangle (a boundary loop of three edges) fails the latter.
  Result CanCollapseBoundaryEdge(int u, int v, const VertexStar<MeshType>& su, const VertexStar<MeshType>& sv) {
    CornerT c;
    EdgeCorner(u, v, c);
    const int a = Index(c.f->V((c.z + 2) % 3));
    int common = 0;
    for (VertexType* q : su.neighbors)
      if (sv.IndexOf(q) >= 0) ++common;
    if (common != 1)
      return Fail("collapsing boundary edge (", u, ", ", v, ") would break the surface (link condition: its ends share ",
                  common, " neighbours instead of 1)");
    VertexStar<MeshType> sa = Star(a);
    if (sa.Valence() - 1 < MinValence(sa.boundary))
      return Fail("collapsing boundary edge (", u, ", ", v, ") would leave vertex ", a, " with valence ",
                  sa.Valence() - 1, " (the triangle would vanish)");
    if (su.Valence() + sv.Valence() - 3 < 2)
      return Fail("collapsing boundary edge (", u, ", ", v, ") would leave a vertex of valence < 2");
    Result seam = attr_.StarSeamless(su);  // attributes: interpolation needs one texture around u, v
    if (seam) seam = attr_.StarSeamless(sv);
    if (!seam) return Fail("collapsing boundary edge (", u, ", ", v, ") cannot carry the texture: ", seam.reason);
    return Result::Ok();
  }

  template <class... Args>
  static Result Fail(const Args&... args) {
    std::ostringstream o;
    using expand = int[];
    (void)expand{0, ((o << args), 0)...};
    return Result::Fail(o.str());
  }

  /// The corner (f, z) of x whose edge z runs from x to y.
  bool EdgeCorner(int x, int y, CornerT& out) {
    VertexStar<MeshType> s = Star(x);
    int k = s.IndexOf(V(y));
    if (k < 0) return false;
    if (k < int(s.corners.size())) {
      out = s.corners[size_t(k)];
      return true;
    }
    // the last neighbour of a boundary fan: the edge belongs to the last corner, as its
    // edge (z+2); express it from the face's point of view as edge z of corner (z+2)
    CornerT c = s.corners.back();
    out = CornerT{c.f, (c.z + 2) % 3};  // edge from V(z+2)=y to V(z)=x: a boundary edge
    return true;
  }

  /// A live corner of v: its VF entry when valid, else nullptr.
  CornerT LiveCorner(VertexType* v) {
    for (vcg::face::VFIterator<FaceType> it(v); !it.End(); ++it)
      if (!it.F()->IsD() && it.F()->V(it.I()) == v) return CornerT{it.F(), it.I()};
    return CornerT();
  }

  static ScalarType Area(const FaceType* f) {
    return ((f->cP(1) - f->cP(0)) ^ (f->cP(2) - f->cP(0))).Norm() / 2;
  }
  CoordType RegionNormal(std::initializer_list<FaceType*> faces) {
    CoordType n(0, 0, 0);
    for (FaceType* f : faces) n += (f->P(1) - f->P(0)) ^ (f->P(2) - f->P(0));
    return n;
  }
  void UpdateNormal(FaceType* f) {
    CoordType n = (f->P(1) - f->P(0)) ^ (f->P(2) - f->P(0));
    ScalarType l = n.Norm();
    if (l > 0) n /= l;
    f->N() = n;
  }

  /// Every changed face must turn at most maxNormalTurnDeg from the reference normal and keep
  /// a non-negligible area.
  Result CheckGeometry(const std::vector<FaceType*>& changed, CoordType ref, ScalarType refArea) {
    if (!geom_.checkFolds) return Result::Ok();
    ScalarType rl = ref.Norm();
    if (rl == 0) return Result::Ok();
    ref /= rl;
    const double c = std::cos(geom_.maxNormalTurnDeg * M_PI / 180.0);
    for (FaceType* f : changed) {
      if (f->IsD()) continue;
      CoordType n = (f->P(1) - f->P(0)) ^ (f->P(2) - f->P(0));
      ScalarType l = n.Norm();
      if (l / 2 < geom_.minAreaRatio * refArea) return Result::Fail("would create a degenerate triangle");
      if (double(n.dot(ref)) / double(l) < c) return Result::Fail("would fold the surface (a triangle would turn over)");
    }
    return Result::Ok();
  }

  /// Makes edge e of f and edge ge of g adjacent (FF, both ways), journaling both faces.
  void LinkFaces(FaceType* f, int e, FaceType* g, int ge) {
    journal_.SaveFace(f);
    journal_.SaveFace(g);
    f->FFp(e) = g;
    f->FFi(e) = ge;
    g->FFp(ge) = f;
    g->FFi(ge) = e;
  }

  /// The places of a split of st's centre w (at p) along its neighbours i and j (star indices):
  /// corners i .. j-1 stay with w, corners j .. i-1 go to the new vertex. Each half moves a
  /// share s toward the centroid of its own neighbours (both split edges' far ends included).
  /// A boundary w: the half whose corners wrap around the boundary gap (w's if i > j, else the
  /// new vertex's) keeps the boundary and stays at w's position, on the boundary curve.
  static void SplitPlaces(const VertexStar<MeshType>& st, const CoordType& p, int i, int j, ScalarType s, CoordType& pw,
                          CoordType& px) {
    const int n = int(st.corners.size());
    CoordType c1(0, 0, 0), c2(0, 0, 0);
    int n1 = 0, n2 = 0;
    for (int k = i; k != j; k = (k + 1) % n, ++n1) c1 += st.corners[size_t(k)].f->V((st.corners[size_t(k)].z + 1) % 3)->P();
    c1 += st.neighbors[size_t(j)]->P();
    c1 /= ScalarType(n1 + 1);
    for (int k = j; k != i; k = (k + 1) % n, ++n2) c2 += st.corners[size_t(k)].f->V((st.corners[size_t(k)].z + 1) % 3)->P();
    c2 += st.neighbors[size_t(i)]->P();
    c2 /= ScalarType(n2 + 1);
    const bool wKeepsBoundary = st.boundary && i > j, xTakesBoundary = st.boundary && i < j;
    pw = wKeepsBoundary ? p : p + (c1 - p) * s;
    px = xTakesBoundary ? p : p + (c2 - p) * s;
  }

  /// The fold check's reference for a split: the area-weighted normal of the star and its
  /// mean face area.
  void StarReference(const VertexStar<MeshType>& st, CoordType& ref, ScalarType& refArea) {
    ref = CoordType(0, 0, 0);
    refArea = 0;
    for (auto& c : st.corners) {
      ref += (c.f->P(1) - c.f->P(0)) ^ (c.f->P(2) - c.f->P(0));
      refArea += Area(c.f);
    }
    refArea /= ScalarType(st.corners.size());
  }

  Result CollapseAt(int ui, int vi, const CoordType& target) {
    Checkpoint cp = Mark();
    VertexType* u = V(ui);
    VertexType* v = V(vi);
    VertexStar<MeshType> su = Star(ui);
    const int k = su.IndexOf(v);
    const int n = int(su.corners.size());
    // f0 = (u, v, b) is corner k; f1 = (u, a, v) is corner k-1. On a boundary edge (u is then
    // on the boundary, v its first or last neighbour) only one of them exists.
    const bool hasF0 = !su.boundary || k < n, hasF1 = !su.boundary || k > 0;
    CornerT c0 = hasF0 ? su.corners[size_t(k)] : CornerT(), c1 = hasF1 ? su.corners[size_t((k + n - 1) % n)] : CornerT();
    FaceType* f0 = c0.f;
    FaceType* f1 = c1.f;
    VertexType* a = f1 ? c1.f->V((c1.z + 1) % 3) : nullptr;
    VertexType* b = f0 ? c0.f->V((c0.z + 2) % 3) : nullptr;
    std::vector<FaceType*> region;
    for (auto& c : su.corners) region.push_back(c.f);
    VertexStar<MeshType> sv = Star(vi);
    for (auto& c : sv.corners) region.push_back(c.f);
    CoordType ref(0, 0, 0);
    ScalarType refArea = 0;
    for (FaceType* f : region) {
      ref += (f->P(1) - f->P(0)) ^ (f->P(2) - f->P(0));
      refArea += Area(f);
    }
    refArea /= ScalarType(region.size());
    // attributes at target, read from a face of the edge (on a boundary edge only one exists)
    const auto carried = attr_.BeforeCollapse(u, v, f0 ? f0 : f1, region, target);

    // Glue the outer neighbours of f0 across its edges (v,b) and (b,u), and of f1 across
    // (u,a) and (a,v): each pair becomes one edge once f0, f1 vanish. If one side was the
    // boundary, the merged edge is a boundary edge of the other (CanCollapse refuses both).
    auto glue = [&](FaceType* f, int e1, int e2) {
      FaceType* g = f->FFp(e1);
      int gi = f->FFi(e1);
      FaceType* h = f->FFp(e2);
      int hi = f->FFi(e2);
      if (g == f) std::swap(g, h), std::swap(gi, hi);
      journal_.SaveFace(g);
      if (h == f) {
        g->FFp(gi) = g;
        g->FFi(gi) = gi;
        return;
      }
      journal_.SaveFace(h);
      g->FFp(gi) = h;
      g->FFi(gi) = hi;
      h->FFp(hi) = g;
      h->FFi(hi) = gi;
    };
    if (f0) glue(f0, (c0.z + 1) % 3, (c0.z + 2) % 3);
    if (f1) glue(f1, c1.z, (c1.z + 1) % 3);
    // f0 = (u, v, b): glued edges (v,b) and (b,u); f1 = (u, a, v): edges (u,a) and (a,v).
    // Every other face of u now uses v.
    std::vector<FaceType*> changed;
    for (auto& c : su.corners) {
      if (c.f == f0 || c.f == f1) continue;
      journal_.SaveFace(c.f);
      c.f->V(c.z) = v;
      changed.push_back(c.f);
    }
    for (FaceType* dead : {f0, f1})
      if (dead) journal_.SaveFace(dead);
    journal_.SaveVertex(u);
    journal_.SaveVertex(v);
    for (FaceType* dead : {f0, f1})
      if (dead) vcg::tri::Allocator<MeshType>::DeleteFace(m_, *dead);
    vcg::tri::Allocator<MeshType>::DeleteVertex(m_, *u);
    // v's own faces may all be gone (an ear collapsed across a boundary edge): then start its
    // VF list from one of u's faces, which are v's now. (Otherwise leave it: the VF order, and
    // so the order of stars, stays what it was before boundary editing existed.)
    bool vKeepsAFace = false;
    for (auto& c : sv.corners) vKeepsAFace = vKeepsAFace || (c.f != f0 && c.f != f1);
    for (auto& c : su.corners)
      if (!vKeepsAFace && c.f != f0 && c.f != f1) {
        v->VFp() = c.f;
        v->VFi() = c.z;
        break;
      }
    v->P() = target;
    for (auto& c : sv.corners)
      if (c.f != f0 && c.f != f1) changed.push_back(c.f);
    for (FaceType* f : changed) {
      journal_.SaveFace(f);
      UpdateNormal(f);
    }
    RelinkVF(v);
    if (a) RelinkVF(a);
    if (b) RelinkVF(b);
    // vcg's Allocator fixes the pointers of live elements only when a later split reallocates
    // the vertex or face vector: the dead ones' would dangle. Clear them once the live VF
    // lists no longer pass through them (the journal above restores them by index).
    u->VFp() = nullptr;
    u->VFi() = -1;
    for (FaceType* dead : {f0, f1})
      for (int z = 0; dead && z < 3; ++z) {
        dead->V(z) = nullptr;
        dead->FFp(z) = nullptr;
        dead->VFp(z) = nullptr;
        dead->VFi(z) = -1;
      }
    Result geo = CheckGeometry(changed, ref, refArea);
    if (geo) geo = attr_.AfterCollapse(carried, v, changed, geom_);
    if (!geo) {
      RollbackTo(cp);
      return geo;
    }
    return Result::Ok();
  }

  Result SplitWith(int wi, int ai, int bi, ScalarType s, int* created) {
    Checkpoint cp = Mark();
    // Allocate first: adding elements may move the vectors, so take pointers afterwards.
    int xi, nf[2];
    slots_.Take(m_, journal_, 1, 2, &xi, nf);
    FaceType* fb = &m_.face[size_t(nf[0])];
    FaceType* fa = &m_.face[size_t(nf[1])];
    VertexType* w = V(wi);
    VertexType* x = V(xi);
    VertexType* a = V(ai);
    VertexType* b = V(bi);
    VertexStar<MeshType> st = Star(wi);
    const int n = int(st.corners.size());
    const int i = st.IndexOf(a), j = st.IndexOf(b);
    // group 1: corners i .. j-1 stay with w; group 2: corners j .. i-1 go to x.
    std::vector<CornerT> g1, g2;
    for (int k = i; k != j; k = (k + 1) % n) g1.push_back(st.corners[size_t(k)]);
    for (int k = j; k != i; k = (k + 1) % n) g2.push_back(st.corners[size_t(k)]);
    CoordType ref;
    ScalarType refArea;
    StarReference(st, ref, refArea);
    CoordType pw, px;
    SplitPlaces(st, w->P(), i, j, s, pw, px);
    const auto carried = attr_.BeforeSplit(st, g1.front().f, g1.back().f, pw, px);

    x->ImportData(*w);
    x->ClearS();
    x->VFp() = nullptr;
    x->VFi() = 0;
    journal_.SaveVertex(w);
    w->P() = pw;
    x->P() = px;
    std::vector<FaceType*> changed{fa, fb};
    for (auto& c : g2) {
      journal_.SaveFace(c.f);
      c.f->V(c.z) = x;
      changed.push_back(c.f);
    }
    for (auto& c : g1) changed.push_back(c.f);
    // The faces on both sides of the old edges (w,a) and (w,b).
    CornerT ga = g1.front();                // (w, a, .): edge z = (w, a)
    CornerT gb = g1.back();                 // (w, ., b): edge z+2 = (b, w)
    CornerT xb = g2.front();                // (x, b, .): edge z = (x, b)
    CornerT xa = g2.back();                 // (x, ., a): edge z+2 = (a, x)
    FaceType* proto = ga.f;
    fa->ImportData(*proto);
    fb->ImportData(*proto);
    fa->ClearS();
    fb->ClearS();
    // fb = (w, b, x), fa = (w, x, a)
    fb->V(0) = w; fb->V(1) = b; fb->V(2) = x;
    fa->V(0) = w; fa->V(1) = x; fa->V(2) = a;
    for (int z = 0; z < 3; ++z) {
      fa->VFp(z) = nullptr; fa->VFi(z) = 0;
      fb->VFp(z) = nullptr; fb->VFi(z) = 0;
    }
    LinkFaces(fa, 2, ga.f, ga.z);                 // (a, w) ~ (w, a)
    LinkFaces(fa, 1, xa.f, (xa.z + 2) % 3);       // (x, a) ~ (a, x)
    LinkFaces(fb, 0, gb.f, (gb.z + 2) % 3);       // (w, b) ~ (b, w)
    LinkFaces(fb, 1, xb.f, xb.z);                 // (b, x) ~ (x, b)
    LinkFaces(fa, 0, fb, 2);                      // (w, x) ~ (x, w)
    for (FaceType* f : changed) {
      journal_.SaveFace(f);
      UpdateNormal(f);
    }
    x->VFp() = fa;  // a live corner to start from: fa = (w, x, a)
    x->VFi() = 1;
    for (VertexType* q : {w, x, a, b}) RelinkVF(q);
    Result geo = CheckGeometry(changed, ref, refArea);
    if (geo) geo = attr_.AfterSplit(carried, w, x, fa, fb, changed, geom_);
    if (!geo) {
      RollbackTo(cp);
      return geo;
    }
    if (created) *created = xi;
    return Result::Ok();
  }

  Result SplitBoundaryWith(int wi, int ai, ScalarType s, int* created) {
    Checkpoint cp = Mark();
    int xi, fi;
    slots_.Take(m_, journal_, 1, 1, &xi, &fi);
    FaceType* F = &m_.face[size_t(fi)];
    VertexType* w = V(wi);
    VertexType* x = V(xi);
    VertexType* a = V(ai);
    VertexStar<MeshType> st = Star(wi);
    const int n = int(st.corners.size());
    const int i = st.IndexOf(a);
    CoordType ref;
    ScalarType refArea;
    StarReference(st, ref, refArea);
    const CoordType p = w->P(), first = st.neighbors.front()->P(), lastP = st.neighbors.back()->P();
    const CornerT before = st.corners[size_t(i - 1)];  // (w, nb[i-1], a): edge z+2 runs a -> w
    const CornerT after = st.corners[size_t(i)];       // (x, a, nb[i+1]): edge z runs x -> a
    // attributes: the new face (w, a, x) takes colour and quality from the face it borders
    // across (a, x); texture coordinates are sampled from the old star at the new positions
    const auto carried = attr_.BeforeSplit(st, after.f, after.f, p + (first - p) * s, p + (lastP - p) * s);
    x->ImportData(*w);
    x->ClearS();
    x->VFp() = nullptr;
    x->VFi() = 0;
    journal_.SaveVertex(w);
    w->P() = p + (first - p) * s;
    x->P() = p + (lastP - p) * s;
    std::vector<FaceType*> changed{F};
    for (int k = i; k < n; ++k) {
      CornerT c = st.corners[size_t(k)];
      journal_.SaveFace(c.f);
      c.f->V(c.z) = x;
      changed.push_back(c.f);
    }
    for (int k = 0; k < i; ++k) changed.push_back(st.corners[size_t(k)].f);
    F->ImportData(*after.f);
    F->ClearS();
    F->V(0) = w;
    F->V(1) = a;
    F->V(2) = x;
    for (int z = 0; z < 3; ++z) {
      F->VFp(z) = nullptr;
      F->VFi(z) = 0;
    }
    LinkFaces(F, 0, before.f, (before.z + 2) % 3);  // (w, a) ~ (a, w)
    LinkFaces(F, 1, after.f, after.z);              // (a, x) ~ (x, a)
    F->FFp(2) = F;                             // (x, w): the new boundary edge
    F->FFi(2) = 2;
    for (FaceType* f : changed) {
      journal_.SaveFace(f);
      UpdateNormal(f);
    }
    x->VFp() = F;
    x->VFi() = 2;
    for (VertexType* q : {w, x, a}) RelinkVF(q);
    Result geo = CheckGeometry(changed, ref, refArea);
    if (geo) geo = attr_.AfterSplit(carried, w, x, F, F, changed, geom_);
    if (!geo) {
      RollbackTo(cp);
      return geo;
    }
    if (created) *created = xi;
    return Result::Ok();
  }

  MeshType& m_;
  Journal journal_;
  SlotPool<MeshType> slots_;
  GeometryOptions geom_;
  AttributeTransfer<MeshType> attr_;
};

}  // namespace irregular
}  // namespace vcg_ext
