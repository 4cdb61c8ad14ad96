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
// All operations refuse boundary vertices and edges: the paper's operations are defined on
// closed surfaces, and a boundary vertex is regular at valence 4, so they act away from it.
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
  void RollbackTo(const Checkpoint& c) { journal_.RollbackTo(c); }
  void Commit() { journal_.Commit(); }

  VertexType* V(int i) { return &m_.vert[size_t(i)]; }
  int Index(const VertexType* v) const { return int(vcg::tri::Index(m_, v)); }
  bool IsLive(int i) const { return i >= 0 && size_t(i) < m_.vert.size() && !m_.vert[size_t(i)].IsD() && m_.vert[size_t(i)].cVFp(); }
  VertexStar<MeshType> Star(int i) { return StarOf<MeshType>(V(i)); }
  int Valence(int i) { return Star(i).Valence(); }
  bool IsBoundary(int i) { return Star(i).boundary; }
  bool Adjacent(int a, int b) { return Star(a).IndexOf(V(b)) >= 0; }

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
  /// Can edge (x, y) be flipped? Topology only: interior manifold edge, distinct opposite
  /// vertices that are not already joined, x and y keep valence >= 3.
  Result CanFlip(int x, int y) {
    if (!IsLive(x) || !IsLive(y)) return Result::Fail("a vertex of the edge does not exist");
    CornerT c;
    if (!EdgeCorner(x, y, c)) return Fail("vertices ", x, " and ", y, " are not joined by an edge");
    if (c.f->FFp(c.z) == c.f) return Fail("edge (", x, ", ", y, ") lies on the boundary");
    if (IsBoundary(x) || IsBoundary(y)) return Fail("edge (", x, ", ", y, ") touches the boundary");
    int o[2];
    Opposites(x, y, o);
    if (o[0] == o[1]) return Fail("edge (", x, ", ", y, ") has the same vertex on both sides");
    if (Adjacent(o[0], o[1]))
      return Fail("flipping edge (", x, ", ", y, ") would duplicate the existing edge (", o[0], ", ", o[1], ")");
    if (Valence(x) <= 3 || Valence(y) <= 3)
      return Fail("flipping edge (", x, ", ", y, ") would leave a vertex of valence 2");
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
  /// Can u be collapsed into v? Interior edge, link condition (u and v share exactly the two
  /// opposite vertices), and every valence stays >= 3.
  Result CanCollapse(int u, int v) {
    if (!IsLive(u) || !IsLive(v)) return Result::Fail("a vertex of the edge does not exist");
    if (!Adjacent(u, v)) return Fail("vertices ", u, " and ", v, " are not joined by an edge");
    VertexStar<MeshType> su = Star(u), sv = Star(v);
    if (su.boundary || sv.boundary) return Fail("edge (", u, ", ", v, ") touches the boundary");
    int o[2];
    Opposites(u, v, o);
    int common = 0;
    for (VertexType* n : su.neighbors)
      if (sv.IndexOf(n) >= 0) ++common;
    if (common != 2 || o[0] == o[1])
      return Fail("collapsing edge (", u, ", ", v, ") would break the surface (link condition: its ends share ",
                  common, " neighbours instead of 2)");
    if (Valence(o[0]) <= 3 || Valence(o[1]) <= 3)
      return Fail("collapsing edge (", u, ", ", v, ") would leave a vertex of valence 2");
    if (su.Valence() + sv.Valence() - 4 < 3)
      return Fail("collapsing edge (", u, ", ", v, ") would leave a vertex of valence < 3");
    Result seam = attr_.StarSeamless(su);  // attributes: interpolation needs one texture around u, v
    if (seam) seam = attr_.StarSeamless(sv);
    if (!seam) return Fail("collapsing edge (", u, ", ", v, ") cannot carry the texture: ", seam.reason);
    return Result::Ok();
  }

  /// Collapses edge (u, v): u is deleted, v survives at the midpoint (or, if that folds the
  /// surface, at v's or u's position). Returns Ok with v surviving.
  Result Collapse(int u, int v) {
    Result ok = CanCollapse(u, v);
    if (!ok) return ok;
    const CoordType pu = V(u)->P(), pv = V(v)->P();
    Result last;
    for (CoordType target : {(pu + pv) / ScalarType(2), pv, pu}) {
      last = CollapseAt(u, v, target);
      if (last) return last;
    }
    return Fail("collapsing edge (", u, ", ", v, ") ", last.reason);
  }

  // ---------------------------------------------------------------- vertex split
  /// Can w be split along its edges to a and b? w interior, a != b both neighbours of w.
  Result CanSplit(int w, int a, int b) {
    if (!IsLive(w) || !IsLive(a) || !IsLive(b)) return Result::Fail("a vertex of the split does not exist");
    VertexStar<MeshType> s = Star(w);
    if (s.boundary) return Fail("vertex ", w, " lies on the boundary");
    if (a == b) return Fail("a vertex split needs two different edges of vertex ", w);
    if (s.IndexOf(V(a)) < 0 || s.IndexOf(V(b)) < 0)
      return Fail("vertices ", a, " and ", b, " must both be neighbours of vertex ", w);
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

  Result CollapseAt(int ui, int vi, const CoordType& target) {
    Checkpoint cp = Mark();
    VertexType* u = V(ui);
    VertexType* v = V(vi);
    VertexStar<MeshType> su = Star(ui);
    const int k = su.IndexOf(v);
    const int n = int(su.corners.size());
    // f0 = (u, v, b) is corner k; f1 = (u, a, v) is corner k-1.
    CornerT c0 = su.corners[size_t(k)], c1 = su.corners[size_t((k + n - 1) % n)];
    FaceType* f0 = c0.f;
    FaceType* f1 = c1.f;
    VertexType* a = c1.f->V((c1.z + 1) % 3);
    VertexType* b = c0.f->V((c0.z + 2) % 3);
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
    const auto carried = attr_.BeforeCollapse(u, v, f0, region, target);  // attributes at target

    // Glue the outer neighbours of f0 across its edges (v,b) and (b,u), and of f1 across
    // (u,a) and (a,v): each pair becomes one edge once f0, f1 vanish.
    auto glue = [&](FaceType* f, int e1, int e2) {
      FaceType* g = f->FFp(e1);
      int gi = f->FFi(e1);
      FaceType* h = f->FFp(e2);
      int hi = f->FFi(e2);
      journal_.SaveFace(g);
      journal_.SaveFace(h);
      g->FFp(gi) = h;
      g->FFi(gi) = hi;
      h->FFp(hi) = g;
      h->FFi(hi) = gi;
    };
    glue(f0, (c0.z + 1) % 3, (c0.z + 2) % 3);
    glue(f1, c1.z, (c1.z + 1) % 3);
    // f0 = (u, v, b): glued edges (v,b) and (b,u); f1 = (u, a, v): edges (u,a) and (a,v).
    // Every other face of u now uses v.
    std::vector<FaceType*> changed;
    for (auto& c : su.corners) {
      if (c.f == f0 || c.f == f1) continue;
      journal_.SaveFace(c.f);
      c.f->V(c.z) = v;
      changed.push_back(c.f);
    }
    journal_.SaveFace(f0);
    journal_.SaveFace(f1);
    journal_.SaveVertex(u);
    journal_.SaveVertex(v);
    vcg::tri::Allocator<MeshType>::DeleteFace(m_, *f0);
    vcg::tri::Allocator<MeshType>::DeleteFace(m_, *f1);
    vcg::tri::Allocator<MeshType>::DeleteVertex(m_, *u);
    v->P() = target;
    for (auto& c : sv.corners)
      if (c.f != f0 && c.f != f1) changed.push_back(c.f);
    for (FaceType* f : changed) {
      journal_.SaveFace(f);
      UpdateNormal(f);
    }
    RelinkVF(v);
    RelinkVF(a);
    RelinkVF(b);
    // vcg's Allocator fixes the pointers of live elements only when a later split reallocates
    // the vertex or face vector: the dead ones' would dangle. Clear them once the live VF
    // lists no longer pass through them (the journal above restores them by index).
    u->VFp() = nullptr;
    u->VFi() = -1;
    for (FaceType* dead : {f0, f1})
      for (int z = 0; z < 3; ++z) {
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
    vcg::tri::Allocator<MeshType>::AddVertices(m_, 1);
    vcg::tri::Allocator<MeshType>::AddFaces(m_, 2);
    const int xi = int(m_.vert.size()) - 1;
    FaceType* fb = &m_.face[m_.face.size() - 2];
    FaceType* fa = &m_.face[m_.face.size() - 1];
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
    CoordType ref(0, 0, 0);
    ScalarType refArea = 0;
    for (auto& c : st.corners) {
      ref += (c.f->P(1) - c.f->P(0)) ^ (c.f->P(2) - c.f->P(0));
      refArea += Area(c.f);
    }
    refArea /= ScalarType(n);
    // New positions: each half moves a share s toward the centroid of its own neighbours.
    CoordType c1(0, 0, 0), c2(0, 0, 0);
    for (auto& c : g1) c1 += c.f->V((c.z + 1) % 3)->P();
    c1 += b->P();
    c1 /= ScalarType(g1.size() + 1);
    for (auto& c : g2) c2 += c.f->V((c.z + 1) % 3)->P();
    c2 += a->P();
    c2 /= ScalarType(g2.size() + 1);
    const CoordType p = w->P();
    const auto carried = attr_.BeforeSplit(st, g1.front().f, g1.back().f, p + (c1 - p) * s, p + (c2 - p) * s);

    x->ImportData(*w);
    x->ClearS();
    x->VFp() = nullptr;
    x->VFi() = 0;
    journal_.SaveVertex(w);
    w->P() = p + (c1 - p) * s;
    x->P() = p + (c2 - p) * s;
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
    auto link = [&](FaceType* f, int e, FaceType* g, int ge) {
      journal_.SaveFace(f);
      journal_.SaveFace(g);
      f->FFp(e) = g;
      f->FFi(e) = ge;
      g->FFp(ge) = f;
      g->FFi(ge) = e;
    };
    link(fa, 2, ga.f, ga.z);                 // (a, w) ~ (w, a)
    link(fa, 1, xa.f, (xa.z + 2) % 3);       // (x, a) ~ (a, x)
    link(fb, 0, gb.f, (gb.z + 2) % 3);       // (w, b) ~ (b, w)
    link(fb, 1, xb.f, xb.z);                 // (b, x) ~ (x, b)
    link(fa, 0, fb, 2);                      // (w, x) ~ (x, w)
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

  MeshType& m_;
  Journal journal_;
  GeometryOptions geom_;
  AttributeTransfer<MeshType> attr_;
};

}  // namespace irregular
}  // namespace vcg_ext
