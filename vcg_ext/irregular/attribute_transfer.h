// filter_irregular: carrying a textured or painted mesh's attributes through the graph
// operations (issue 13, item 5): per-wedge texture coordinates, face colour and quality, and
// per-vertex colour, quality and texture coordinates.
//
// Rules (what each operation writes; every value not named here is left as it was):
//   * Texture coordinates (per wedge and per vertex) are interpolated: a corner or vertex that
//     moves to a new position takes the value the old surface had at that position: linear
//     along the collapsed edge, barycentric in the face of the split vertex's old star closest
//     to the new position. On a mesh whose texture coordinates are an affine function of
//     position (a planar parametrisation) the result is exactly that function there.
//   * Colours and qualities (per face and per vertex) are copied, never averaged: a quality
//     that labels regions stays a label, a painted border stays sharp, and every value after
//     an edit is one the input had.
//   * Flip (x, y) -> (o0, o1): every corner of the two new faces takes the texture coordinate
//     its vertex had in the old faces. Face colour and quality: both new faces take those of
//     the larger old face. The diagonals of the quad cross at one point P, and each new face
//     overlaps the old face (x, y, o) in proportion to the distance of o from the edge (x, y),
//     that is to the old face's area: so the larger old face is the one each new face
//     overlaps most. Values are copied, never averaged (a quality that labels regions stays
//     a label).
//   * Collapse u -> v, v moved to a point t of the way from v to u: the corner at v of every
//     surviving face of both stars takes the texture coordinate at that point of the edge, and
//     so does v's vertex texture coordinate; v's colour and quality are those of the end
//     nearer the target (v's own at the midpoint).
//   * Split w -> (w, w'): the corners at w and w' take the texture coordinates at their new
//     positions (and so do their vertex texture coordinates); w' copies w's colour and
//     quality; each new face takes the colour and quality of the old face it borders across
//     its old edge ((w, w', a) that of (w, a, .), (w, b, w') that of (., b, w)).
//   * Custom per-vertex and per-face attributes (vcg's named attributes, of a type unknown
//     here) cannot be interpolated: they are copied. A split's new vertex copies w's values and
//     each new face those of the old face it borders; a flip's and a collapse's surviving
//     elements keep their own values (the collapsed vertex's are dropped).
//
// Refusals, with the reason:
//   * a texture seam (the dry runs CanFlip / CanCollapse / CanSplit report it too): an edge
//     whose two faces give one of its ends different texture coordinates (or use different
//     textures, WT().N()). A flip of a seam edge, or a collapse or split of a vertex with a
//     seam edge, would glue two unrelated parts of the texture together; interpolation cannot
//     carry it.
//   * a texture fold (a geometric check, when GeometryOptions::checkFolds; like the fold check
//     in space, only the operation finds it): a changed face whose texture triangle turns over
//     or collapses relative to the faces it replaces. Where those faces already disagree in
//     orientation (a texture folded before the edit) there is nothing to keep and no check.
//
// After a move that keeps the connectivity (relaxation), AttributeResampler gives each moved
// vertex the texture coordinates of the surface before the move at its new position.
//
// Zero overhead: every function first asks vcglib whether the mesh has the component
// (tri::HasPerWedgeTexCoord etc.: compile-time for static components, run-time for the
// optional ones of MeshLab's CMeshO) and does nothing if it has none.
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/space/distance3.h>
#include <vcg/space/triangle3.h>

#include "result.h"
#include "topology.h"

namespace vcg_ext {
namespace irregular {

template <class MeshType>
class AttributeTransfer {
 public:
  typedef typename MeshType::FaceType FaceType;
  typedef typename MeshType::VertexType VertexType;
  typedef typename MeshType::CoordType CoordType;
  typedef typename MeshType::ScalarType ScalarType;
  typedef typename FaceType::TexCoordType WedgeTex;
  typedef typename FaceType::ColorType FaceColor;
  typedef typename FaceType::QualityType FaceQuality;
  typedef typename VertexType::TexCoordType VertTex;
  typedef typename VertexType::ColorType VertColor;
  typedef typename VertexType::QualityType VertQuality;

  explicit AttributeTransfer(MeshType& m) : m_(m) {}

  bool HasWedgeTex() const { return vcg::tri::HasPerWedgeTexCoord(m_); }
  bool HasFaceColor() const { return vcg::tri::HasPerFaceColor(m_); }
  bool HasFaceQuality() const { return vcg::tri::HasPerFaceQuality(m_); }
  bool HasVertColor() const { return vcg::tri::HasPerVertexColor(m_); }
  bool HasVertQuality() const { return vcg::tri::HasPerVertexQuality(m_); }
  bool HasVertTex() const { return vcg::tri::HasPerVertexTexCoord(m_); }

  // ------------------------------------------------------------------ seams (dry run)
  /// Ok unless edge z of f is a texture seam (see the header). O(1).
  Result EdgeSeamless(FaceType* f, int z) const {
    if (!HasWedgeTex()) return Result::Ok();
    FaceType* g = f->FFp(z);
    if (g == nullptr || g == f) return Result::Ok();  // a boundary edge has one side only
    const int w = f->FFi(z);
    // f runs the edge V(z) -> V(z+1), g runs it back: g->V(w) = f->V(z+1).
    const int fz[2] = {z, (z + 1) % 3}, gz[2] = {(w + 1) % 3, w};
    for (int k = 0; k < 2; ++k) {
      const WedgeTex &a = f->WT(fz[k]), &b = g->WT(gz[k]);
      if (a.N() != b.N()) {
        std::ostringstream o;
        o << "faces of two different textures (texture " << a.N() << " and " << b.N() << ") meet at edge ("
          << Idx(f->V(z)) << ", " << Idx(f->V((z + 1) % 3)) << ")";
        return Result::Fail(o.str());
      }
      if (a.P() != b.P()) {
        std::ostringstream o;
        o << "edge (" << Idx(f->V(z)) << ", " << Idx(f->V((z + 1) % 3))
          << ") is a texture seam (its two faces give vertex " << Idx(f->V(fz[k]))
          << " different texture coordinates)";
        return Result::Fail(o.str());
      }
    }
    return Result::Ok();
  }

  /// Ok unless an edge at the star's centre is a texture seam. O(valence).
  Result StarSeamless(const VertexStar<MeshType>& s) const {
    if (!HasWedgeTex()) return Result::Ok();
    for (auto& c : s.corners) {
      Result r = EdgeSeamless(c.f, c.z);  // the edge from the centre to neighbour k
      if (!r) return r;
    }
    return Result::Ok();
  }

  // ------------------------------------------------------------------ flip
  struct FlipCarry {
    std::vector<std::pair<VertexType*, WedgeTex>> tex;  ///< each of x, y, o0, o1 and its coordinate
    FaceColor color;
    FaceQuality quality = FaceQuality();
    double uvArea = 0, uvAbs = 0;  ///< signed and absolute texture area of the two old faces
  };

  /// Before flipping edge z of f (x = V(z), y = V(z+1)). Precondition: EdgeSeamless(f, z).
  FlipCarry BeforeFlip(FaceType* f, int z) const {
    FlipCarry c;
    FaceType* g = f->FFp(z);
    const int w = f->FFi(z);
    if (HasWedgeTex()) {
      for (int i = 0; i < 3; ++i) c.tex.push_back({f->V(i), f->WT(i)});
      c.tex.push_back({g->V((w + 2) % 3), g->WT((w + 2) % 3)});
      AddUV(f, c.uvArea, c.uvAbs);
      AddUV(g, c.uvArea, c.uvAbs);
    }
    FaceType* larger = Area(f) >= Area(g) ? f : g;  // ties: the face left of x -> y
    if (HasFaceColor()) c.color = larger->C();
    if (HasFaceQuality()) c.quality = larger->Q();
    return c;
  }

  /// After the flip: writes the new faces f, g (already journaled). Returns the texture fold
  /// check (Options: GeometryOptions).
  template <class Options>
  Result AfterFlip(const FlipCarry& c, FaceType* f, FaceType* g, const Options& opt) const {
    for (FaceType* h : {f, g}) {
      if (HasWedgeTex())
        for (int i = 0; i < 3; ++i)
          for (auto& vt : c.tex)
            if (vt.first == h->V(i)) h->WT(i) = vt.second;
      if (HasFaceColor()) h->C() = c.color;
      if (HasFaceQuality()) h->Q() = c.quality;
    }
    return CheckTextureFolds({f, g}, c.uvArea, c.uvAbs, 2, opt);
  }

  // ------------------------------------------------------------------ collapse
  struct CollapseCarry {
    double t = 0;  ///< the target's share of the way from v to u
    WedgeTex tex;
    VertColor color;
    VertQuality quality = VertQuality();
    VertTex vtex;
    double uvArea = 0, uvAbs = 0;
    int faces = 0;
  };

  /// Before collapsing u into v, v moving to target. f0 is a face of the edge, star lists
  /// every face of u and v (for the fold reference). Precondition: both stars seamless.
  CollapseCarry BeforeCollapse(VertexType* u, VertexType* v, FaceType* f0, const std::vector<FaceType*>& star,
                               const CoordType& target) const {
    CollapseCarry c;
    const CoordType d = u->P() - v->P();
    const double len2 = double(d.SquaredNorm());
    c.t = len2 > 0 ? std::min(1.0, std::max(0.0, double((target - v->P()).dot(d)) / len2)) : 0.0;
    if (HasWedgeTex()) {
      int iu = 0, iv = 0;
      for (int i = 0; i < 3; ++i) {
        if (f0->V(i) == u) iu = i;
        if (f0->V(i) == v) iv = i;
      }
      const double w[2] = {1 - c.t, c.t};
      c.tex = Mix(std::vector<WedgeTex>{f0->WT(iv), f0->WT(iu)}, w);
      for (FaceType* f : star) AddUV(f, c.uvArea, c.uvAbs);
      c.faces = int(star.size());
    }
    const double w[2] = {1 - c.t, c.t};
    VertexType* nearer = c.t > 0.5 ? u : v;  // colour and quality are copied, not mixed
    if (HasVertColor()) c.color = nearer->C();
    if (HasVertQuality()) c.quality = nearer->Q();
    if (HasVertTex()) c.vtex = Mix(std::vector<VertTex>{v->T(), u->T()}, w);
    return c;
  }

  /// After the collapse: every surviving face around v (journaled) and v (journaled).
  template <class Options>
  Result AfterCollapse(const CollapseCarry& c, VertexType* v, const std::vector<FaceType*>& changed,
                       const Options& opt) const {
    if (HasWedgeTex())
      for (FaceType* f : changed)
        for (int i = 0; i < 3; ++i)
          if (f->V(i) == v) f->WT(i) = c.tex;
    if (HasVertColor()) v->C() = c.color;
    if (HasVertQuality()) v->Q() = c.quality;
    if (HasVertTex()) v->T() = c.vtex;
    return CheckTextureFolds(changed, c.uvArea, c.uvAbs, c.faces, opt);
  }

  // ------------------------------------------------------------------ split
  struct SplitCarry {
    WedgeTex texW, texX;  ///< at the new positions of w and w'
    std::vector<std::pair<VertexType*, WedgeTex>> ring;  ///< each neighbour's coordinate
    FaceColor colorA, colorB;
    FaceQuality qualityA = FaceQuality(), qualityB = FaceQuality();
    VertTex vtexW, vtexX;
    double uvArea = 0, uvAbs = 0;
    int faces = 0;
    FaceType *nearA = nullptr, *nearB = nullptr;  ///< the old faces the new ones border
  };

  /// Before splitting the star's centre w into w at pw and w' at px; fa and fb are the old
  /// faces (w, a, .) and (., b, w) the new faces (w, w', a) and (w, b, w') border.
  /// Precondition: the star is seamless; positions are still the old ones.
  SplitCarry BeforeSplit(const VertexStar<MeshType>& s, FaceType* fa, FaceType* fb, const CoordType& pw,
                         const CoordType& px) const {
    SplitCarry c;
    c.nearA = fa;
    c.nearB = fb;
    if (HasFaceColor()) c.colorA = fa->C(), c.colorB = fb->C();
    if (HasFaceQuality()) c.qualityA = fa->Q(), c.qualityB = fb->Q();
    if (!HasWedgeTex() && !HasVertTex()) return c;
    const std::vector<FrozenFace> star = Freeze(s);
    const Sampled w = Sample(star, pw), x = Sample(star, px);
    c.texW = w.tex, c.vtexW = w.vtex;
    c.texX = x.tex, c.vtexX = x.vtex;
    if (HasWedgeTex()) {
      for (const FrozenFace& f : star)
        for (int j = 1; j < 3; ++j) c.ring.push_back({f.v[j], f.tex[j]});
      for (auto& k : s.corners) AddUV(k.f, c.uvArea, c.uvAbs);
      c.faces = int(s.corners.size());
    }
    return c;
  }

  // ------------------------------------------------------------------ the old surface
  /// A face of a star as it was: corners ordered from the centre, positions and texture
  /// coordinates.
  struct FrozenFace {
    VertexType* v[3];
    CoordType p[3];
    WedgeTex tex[3];
    VertTex vtex[3];
  };
  /// The texture coordinates of the old surface at one point.
  struct Sampled {
    WedgeTex tex;
    VertTex vtex;
  };

  /// Copies the faces of a star. O(valence).
  std::vector<FrozenFace> Freeze(const VertexStar<MeshType>& s) const {
    std::vector<FrozenFace> out;
    for (auto& k : s.corners) {
      FrozenFace f;
      for (int j = 0; j < 3; ++j) {
        const int z = (k.z + j) % 3;
        f.v[j] = k.f->V(z);
        f.p[j] = k.f->cP(z);
        if (HasWedgeTex()) f.tex[j] = k.f->WT(z);
        if (HasVertTex()) f.vtex[j] = f.v[j]->T();
      }
      out.push_back(f);
    }
    return out;
  }

  /// The attributes of the frozen surface at q: barycentric interpolation in the face closest
  /// to q (q projected on it; a point outside every face takes the closest point of the
  /// closest face, so nothing is extrapolated). O(faces).
  Sampled Sample(const std::vector<FrozenFace>& faces, const CoordType& q) const {
    size_t best = 0;
    double bestDist = 1e300;
    CoordType bary(1, 0, 0);
    for (size_t k = 0; k < faces.size(); ++k) {
      const FrozenFace& f = faces[k];
      vcg::Triangle3<ScalarType> t(f.p[0], f.p[1], f.p[2]);
      ScalarType dist;
      CoordType closest;
      vcg::TrianglePointDistance(t, q, dist, closest);
      if (double(dist) < bestDist) bestDist = double(dist), best = k, bary = Barycentric(f.p, closest);
    }
    Sampled r;
    if (faces.empty()) return r;
    const FrozenFace& f = faces[best];
    const double w[3] = {bary[0], bary[1], bary[2]};
    if (HasWedgeTex()) r.tex = Mix(std::vector<WedgeTex>{f.tex[0], f.tex[1], f.tex[2]}, w);
    if (HasVertTex()) r.vtex = Mix(std::vector<VertTex>{f.vtex[0], f.vtex[1], f.vtex[2]}, w);
    return r;
  }

  /// After the split: the new faces fa = (w, w', a), fb = (w, b, w'), every face of the old
  /// star (all journaled) and the vertices w, w'.
  template <class Options>
  Result AfterSplit(const SplitCarry& c, VertexType* w, VertexType* x, FaceType* fa, FaceType* fb,
                    const std::vector<FaceType*>& changed, const Options& opt) const {
    if (HasWedgeTex())
      for (FaceType* f : changed)
        for (int i = 0; i < 3; ++i) {
          if (f->V(i) == w)
            f->WT(i) = c.texW;
          else if (f->V(i) == x)
            f->WT(i) = c.texX;
          else if (f == fa || f == fb)
            for (auto& vt : c.ring)
              if (vt.first == f->V(i)) f->WT(i) = vt.second;
        }
    if (HasFaceColor()) fa->C() = c.colorA, fb->C() = c.colorB;
    if (HasFaceQuality()) fa->Q() = c.qualityA, fb->Q() = c.qualityB;
    // colour and quality: x->ImportData(*w) copied w's
    if (HasVertTex()) w->T() = c.vtexW, x->T() = c.vtexX;
    // Custom attributes: copied into the new elements only, so the journal need not save them
    // (rolling back truncates the new elements).
    for (auto& a : m_.vert_attr) a._handle->CopyValue(vcg::tri::Index(m_, x), vcg::tri::Index(m_, w), a._handle);
    for (auto& a : m_.face_attr) {
      a._handle->CopyValue(vcg::tri::Index(m_, fa), vcg::tri::Index(m_, c.nearA), a._handle);
      a._handle->CopyValue(vcg::tri::Index(m_, fb), vcg::tri::Index(m_, c.nearB), a._handle);
    }
    return CheckTextureFolds(changed, c.uvArea, c.uvAbs, c.faces, opt);
  }

 private:
  long Idx(const VertexType* v) const { return long(vcg::tri::Index(m_, v)); }

  static ScalarType Area(const FaceType* f) {
    return ((f->cP(1) - f->cP(0)) ^ (f->cP(2) - f->cP(0))).Norm() / 2;
  }
  /// Signed area of f's texture triangle.
  static double UVArea(const FaceType* f) {
    const auto a = f->cWT(0).P(), b = f->cWT(1).P(), c = f->cWT(2).P();
    return 0.5 * (double(b[0] - a[0]) * double(c[1] - a[1]) - double(b[1] - a[1]) * double(c[0] - a[0]));
  }
  static void AddUV(const FaceType* f, double& sum, double& abs) {
    const double a = UVArea(f);
    sum += a;
    abs += std::fabs(a);
  }

  /// Every changed face's texture triangle keeps the orientation of the `faces` old faces it
  /// replaces (signed texture areas summing to refSum, absolute ones to refAbs) and a share
  /// opt.minAreaRatio of their mean texture area. Where the old faces already disagree in
  /// orientation the texture is folded there before the edit (e.g. a planar projection on a
  /// curved surface): there is no orientation to keep, and no check.
  template <class Options>
  Result CheckTextureFolds(const std::vector<FaceType*>& changed, double refSum, double refAbs, int faces,
                           const Options& opt) const {
    if (!HasWedgeTex() || !opt.checkFolds || refSum == 0 || faces == 0) return Result::Ok();
    if (std::fabs(refSum) < refAbs * (1 - 1e-9)) return Result::Ok();  // already folded
    const double refMean = refAbs / faces;
    for (FaceType* f : changed) {
      if (f->IsD()) continue;
      const double a = UVArea(f);
      if (a * refSum <= 0 || std::fabs(a) < opt.minAreaRatio * refMean)
        return Result::Fail("would fold the texture (a triangle's texture coordinates would turn over or collapse)");
    }
    return Result::Ok();
  }

  /// Barycentric coordinates of q (a point of the triangle's plane) in triangle p, clamped
  /// to the triangle against rounding.
  static CoordType Barycentric(const CoordType (&p)[3], const CoordType& q) {
    const CoordType n = (p[1] - p[0]) ^ (p[2] - p[0]);
    const double nn = double(n.SquaredNorm());
    if (nn <= 0) return CoordType(1, 0, 0);
    CoordType b(ScalarType(double(((p[1] - q) ^ (p[2] - q)).dot(n)) / nn),
                ScalarType(double(((p[2] - q) ^ (p[0] - q)).dot(n)) / nn), ScalarType(0));
    b[2] = 1 - b[0] - b[1];
    for (int i = 0; i < 3; ++i) b[i] = std::max(b[i], ScalarType(0));
    return b / (b[0] + b[1] + b[2]);
  }

  /// Weighted sum of texture coordinates (the texture index of the first).
  template <class Tex, size_t N>
  static Tex Mix(const std::vector<Tex>& t, const double (&w)[N]) {
    Tex r = t[0];
    double u = 0, v = 0;
    for (size_t i = 0; i < N; ++i) u += w[i] * double(t[i].U()), v += w[i] * double(t[i].V());
    r.U() = typename Tex::ScalarType(u);
    r.V() = typename Tex::ScalarType(v);
    return r;
  }
  MeshType& m_;
};

/// Carries attributes through moves that keep the connectivity (relaxation, paper sec. 8):
/// each moved vertex takes the values the surface had, before the move, at its new position,
/// so a texture stays where it was on the surface instead of sliding with the vertices.
/// Usage: construct on the vertices that may move, move them, call Resample().
/// Only texture coordinates are re-sampled (colours and qualities stay with their vertex, as
/// the edits copy them). A vertex with a texture seam at it keeps its wedge texture
/// coordinates (which side of the seam would be ambiguous).
/// O(sum of the valences of the moving vertices) for each of the two calls.
template <class MeshType>
class AttributeResampler {
 public:
  typedef typename MeshType::VertexType VertexType;
  typedef typename MeshType::CoordType CoordType;
  typedef AttributeTransfer<MeshType> Transfer;

  AttributeResampler(MeshType& m, const std::vector<int>& moving) : m_(m), attr_(m) {
    if (!attr_.HasWedgeTex() && !attr_.HasVertTex()) return;  // nothing to carry
    for (int v : moving) {
      VertexType* vp = &m.vert[size_t(v)];
      if (vp->IsD() || vp->cVFp() == nullptr) continue;
      VertexStar<MeshType> s = StarOf<MeshType>(vp);
      if (!s.manifold || s.corners.empty()) continue;
      entries_.push_back(Entry{v, vp->P(), attr_.Freeze(s), bool(attr_.StarSeamless(s))});
    }
  }

  /// Writes the re-sampled values of every vertex that moved; returns how many moved.
  int Resample() {
    int moved = 0;
    for (const Entry& e : entries_) {
      VertexType* vp = &m_.vert[size_t(e.v)];
      if (vp->IsD() || vp->P() == e.p) continue;
      const typename Transfer::Sampled s = attr_.Sample(e.star, vp->P());
      if (attr_.HasWedgeTex() && e.seamless)
        for (auto& c : StarOf<MeshType>(vp).corners) c.f->WT(c.z) = s.tex;
      if (attr_.HasVertTex()) vp->T() = s.vtex;
      ++moved;
    }
    return moved;
  }

 private:
  struct Entry {
    int v;
    CoordType p;  ///< where it was
    std::vector<typename Transfer::FrozenFace> star;
    bool seamless;
  };
  MeshType& m_;
  Transfer attr_;
  std::vector<Entry> entries_;
};

}  // namespace irregular
}  // namespace vcg_ext
