// filter_irregular: carrying a textured or painted mesh's attributes through the graph
// operations (issue 13, item 5): per-wedge texture coordinates, face colour and quality, and
// per-vertex colour, quality and texture coordinates.
//
// Rules (what each operation writes; every value not named here is left as it was):
//   * Interpolation: a corner or vertex that moves to a new position takes the value the old
//     surface had at that position: linear along the collapsed edge, barycentric inside the
//     old face of the split vertex's star that contains the new position. On a mesh whose
//     texture coordinates are an affine function of position (a planar parametrisation) the
//     result is exactly that function at the new position.
//   * Flip (x, y) -> (o0, o1): every corner of the two new faces takes the texture coordinate
//     its vertex had in the old faces. Face colour and quality: both new faces take those of
//     the larger old face. The diagonals of the quad cross at one point P, and each new face
//     overlaps the old face (x, y, o) in proportion to the distance of o from the edge (x, y),
//     that is to the old face's area: so the larger old face is the one each new face
//     overlaps most. Values are copied, never averaged (a quality that labels regions stays
//     a label).
//   * Collapse u -> v, v moved to a point t of the way from v to u: the corner at v of every
//     surviving face of both stars takes the texture coordinate at that point of the edge;
//     v's vertex colour, quality and texture coordinate are interpolated the same way.
//   * Split w -> (w, w'): the corners at w and w' take the texture coordinates at their new
//     positions; each new face takes the colour and quality of the old face it borders across
//     its old edge ((w, w', a) that of (w, a, .), (w, b, w') that of (., b, w)); the vertex
//     attributes of w and w' are interpolated at their new positions.
//   * Custom per-vertex and per-face attributes (vcg's named attributes, of a type unknown
//     here) cannot be interpolated: they are copied. A split's new vertex copies w's values and
//     each new face those of the old face it borders; a flip's and a collapse's surviving
//     elements keep their own values (the collapsed vertex's are dropped).
//
// Refusals, with the reason (dry runs report the same):
//   * a texture seam: an edge whose two faces give one of its ends different texture
//     coordinates (or use different textures, WT().N()). A flip of a seam edge, or a collapse
//     or split of a vertex with a seam edge, would glue two unrelated parts of the texture
//     together; interpolation cannot carry it.
//   * a texture fold (geometric check, when GeometryOptions::checkFolds): a changed face whose
//     texture triangle turns over or collapses relative to the faces it replaces.
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
  bool HasVertexAttributes() const { return HasVertColor() || HasVertQuality() || HasVertTex(); }

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
    return CheckTextureFolds({f, g}, c.uvArea, c.uvAbs / 2, opt);
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
    if (HasVertColor()) c.color = MixColor(std::vector<VertColor>{v->C(), u->C()}, w);
    if (HasVertQuality()) c.quality = VertQuality(w[0] * v->Q() + w[1] * u->Q());
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
    return CheckTextureFolds(changed, c.uvArea, c.faces ? c.uvAbs / c.faces : 0, opt);
  }

  // ------------------------------------------------------------------ split
  struct SplitCarry {
    WedgeTex texW, texX;  ///< at the new positions of w and w'
    std::vector<std::pair<VertexType*, WedgeTex>> ring;  ///< each neighbour's coordinate
    FaceColor colorA, colorB;
    FaceQuality qualityA = FaceQuality(), qualityB = FaceQuality();
    VertColor colorW, colorX;
    VertQuality qualityW = VertQuality(), qualityX = VertQuality();
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
    if (!HasWedgeTex() && !HasVertexAttributes()) return c;
    int fw = 0, fx = 0;
    CoordType bw = Locate(s, pw, &fw), bx = Locate(s, px, &fx);
    auto corner = [&](int k, int j) { return (s.corners[size_t(k)].z + j) % 3; };  // j = 0: w
    if (HasWedgeTex()) {
      auto tex = [&](int k, const CoordType& b) {
        FaceType* f = s.corners[size_t(k)].f;
        const double w[3] = {b[0], b[1], b[2]};
        return Mix(std::vector<WedgeTex>{f->WT(corner(k, 0)), f->WT(corner(k, 1)), f->WT(corner(k, 2))}, w);
      };
      c.texW = tex(fw, bw);
      c.texX = tex(fx, bx);
      for (size_t k = 0; k < s.corners.size(); ++k) {
        FaceType* f = s.corners[k].f;
        c.ring.push_back({f->V(corner(int(k), 1)), f->WT(corner(int(k), 1))});
        c.ring.push_back({f->V(corner(int(k), 2)), f->WT(corner(int(k), 2))});
        AddUV(f, c.uvArea, c.uvAbs);
      }
      c.faces = int(s.corners.size());
    }
    auto verts = [&](int k) {
      FaceType* f = s.corners[size_t(k)].f;
      return std::vector<VertexType*>{f->V(corner(k, 0)), f->V(corner(k, 1)), f->V(corner(k, 2))};
    };
    auto vertexValues = [&](int k, const CoordType& b, VertColor& col, VertQuality& q, VertTex& t) {
      std::vector<VertexType*> vs = verts(k);
      const double w[3] = {b[0], b[1], b[2]};
      if (HasVertColor()) col = MixColor(std::vector<VertColor>{vs[0]->C(), vs[1]->C(), vs[2]->C()}, w);
      if (HasVertQuality()) q = VertQuality(w[0] * vs[0]->Q() + w[1] * vs[1]->Q() + w[2] * vs[2]->Q());
      if (HasVertTex()) t = Mix(std::vector<VertTex>{vs[0]->T(), vs[1]->T(), vs[2]->T()}, w);
    };
    vertexValues(fw, bw, c.colorW, c.qualityW, c.vtexW);
    vertexValues(fx, bx, c.colorX, c.qualityX, c.vtexX);
    return c;
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
    if (HasVertColor()) w->C() = c.colorW, x->C() = c.colorX;
    if (HasVertQuality()) w->Q() = c.qualityW, x->Q() = c.qualityX;
    if (HasVertTex()) w->T() = c.vtexW, x->T() = c.vtexX;
    // Custom attributes: copied into the new elements only, so the journal need not save them
    // (rolling back truncates the new elements).
    for (auto& a : m_.vert_attr) a._handle->CopyValue(vcg::tri::Index(m_, x), vcg::tri::Index(m_, w), a._handle);
    for (auto& a : m_.face_attr) {
      a._handle->CopyValue(vcg::tri::Index(m_, fa), vcg::tri::Index(m_, c.nearA), a._handle);
      a._handle->CopyValue(vcg::tri::Index(m_, fb), vcg::tri::Index(m_, c.nearB), a._handle);
    }
    return CheckTextureFolds(changed, c.uvArea, c.faces ? c.uvAbs / c.faces : 0, opt);
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

  /// Every changed face's texture triangle keeps the orientation of the region it replaces
  /// (sign of refSum) and a share opt.minAreaRatio of its mean texture area refMean.
  template <class Options>
  Result CheckTextureFolds(const std::vector<FaceType*>& changed, double refSum, double refMean,
                           const Options& opt) const {
    if (!HasWedgeTex() || !opt.checkFolds || refSum == 0) return Result::Ok();
    for (FaceType* f : changed) {
      if (f->IsD()) continue;
      const double a = UVArea(f);
      if (a * refSum <= 0 || std::fabs(a) < opt.minAreaRatio * refMean)
        return Result::Fail("would fold the texture (a triangle's texture coordinates would turn over or collapse)");
    }
    return Result::Ok();
  }

  /// Barycentric coordinates of q (projected on the face's plane) in the face of the star
  /// that contains it best (the largest smallest coordinate); negative coordinates are
  /// clamped so colours are never extrapolated. *face receives the corner index.
  /// Coordinates are ordered from the centre: (centre, V(z+1), V(z+2)).
  static CoordType Locate(const VertexStar<MeshType>& s, const CoordType& q, int* face) {
    CoordType best(1, 0, 0);
    double bestMin = -1e300;
    *face = 0;
    for (size_t k = 0; k < s.corners.size(); ++k) {
      const FaceType* f = s.corners[k].f;
      const int z = s.corners[k].z;
      const CoordType p0 = f->cP(z), p1 = f->cP((z + 1) % 3), p2 = f->cP((z + 2) % 3);
      const CoordType n = (p1 - p0) ^ (p2 - p0);
      const double nn = double(n.SquaredNorm());
      if (nn <= 0) continue;
      CoordType b(ScalarType(double(((p1 - q) ^ (p2 - q)).dot(n)) / nn),
                  ScalarType(double(((p2 - q) ^ (p0 - q)).dot(n)) / nn), ScalarType(0));
      b[2] = 1 - b[0] - b[1];
      const double mn = std::min({double(b[0]), double(b[1]), double(b[2])});
      if (mn > bestMin) bestMin = mn, best = b, *face = int(k);
    }
    if (bestMin < 0) {
      for (int i = 0; i < 3; ++i) best[i] = std::max(best[i], ScalarType(0));
      best /= best[0] + best[1] + best[2];
    }
    return best;
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
  /// Weighted sum of colours, rounded to the nearest channel value.
  template <class Color, size_t N>
  static Color MixColor(const std::vector<Color>& c, const double (&w)[N]) {
    Color r = c[0];
    for (int ch = 0; ch < 4; ++ch) {
      double s = 0;
      for (size_t i = 0; i < N; ++i) s += w[i] * double(c[i][ch]);
      r[ch] = typename Color::ScalarType(std::lround(s));
    }
    return r;
  }

  MeshType& m_;
};

}  // namespace irregular
}  // namespace vcg_ext
