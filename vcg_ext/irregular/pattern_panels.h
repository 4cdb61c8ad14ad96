// filter_irregular: geometry replacement (paper Fig. 1 middle and right, Fig. 14d): every
// pattern region becomes a panel in a new mesh.
//
// A panel is built from its region's faces (region_outline.h: vertices split into fans, so any
// region works: disks, annuli, strips around a torus, regions touching themselves at a vertex):
//   1. copy: the region's faces with their own vertices (panels share no vertex);
//   2. inset: every outline vertex moves into the region, in the tangent plane of its region
//      faces (normal: area-weighted mean of their normals), along the bisector of its two
//      outline edges, by inset / sin(half the region's angle there) (a miter, capped at 5
//      times the inset), so that both outline edges move inwards by exactly inset = opt.inset x
//      the mean edge length of m (on a flat region; on a curved one, to first order), then back
//      onto the surface: to the closest point of its region faces. Vertices inside the region
//      stay. The inset must stay below the region's inradius, about 0.28
//      edge lengths for a single triangle, or the copy folds;
//   3. extrude (opt.extrude != 0): the top is the inset copy moved by h = opt.extrude x mean
//      edge length along each vertex normal (into the surface when negative), the bottom is the
//      inset copy reversed, and each outline edge gets a side wall of two triangles (all
//      reversed when h < 0, so that normals point out of the shell). Each panel is then a closed, manifold,
//      consistently oriented shell (outward normals), one per connected component of the
//      region; a region without outline (a whole closed component) gives two shells, top and
//      bottom. With extrude = 0 the panel is the inset copy alone, an open surface.
// Sides: panelSidesHistogram[s] counts panels whose outline has s corners over all its loops;
// a corner is an outline vertex where the region does not hold exactly 3 faces (the
// straight-line rule, region_outline.h): 6 for a hexagonal cell around a v6, 5 around a v5,
// 0 for a strip of width one between two straight edge lines.
// Colour: when `out` has per-face colour, every face of a panel takes opt.regionColors[region]
// when given (the Pattern filter passes the colours it paints m with, so panels match the
// pattern whatever m's colours were before), else the colour of its region's first face in m
// if m has per-face colour, else PanelPaletteColor(region).
//
// Preconditions: FF (and VF) adjacency up to date on m, a manifold, consistently oriented
// mesh; labels.faceRegion indexed like m.face. Postconditions: m is not modified; `out` holds
// only the panels (no adjacency computed; bounding box updated; the caller updates normals).
// Cost O(F + V).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/space/distance3.h>
#include <vcg/space/triangle3.h>

#include "pattern_result.h"
#include "region_outline.h"

namespace vcg_ext {
namespace irregular {

struct PanelOptions {
  double inset = 0.15;    ///< inset of each panel's outline, as a fraction of the mean edge length
  double extrude = 0.25;  ///< extrusion along the normal, as a fraction of the mean edge length (0: flat; < 0: inwards)
  std::vector<vcg::Color4b> regionColors;  ///< colour per region id; empty: m's face colour, else a palette
};

struct PanelReport {
  bool ok = true;
  std::string reason;
  int panels = 0;
  std::vector<int> panelSidesHistogram;  ///< [s] = panels whose outline has s sides
  double meanEdgeLength = 0;             ///< of m: the unit of inset and extrude
};

/// A distinct colour per region id (golden-ratio hue walk), for panels when m has no face colour.
inline vcg::Color4b PanelPaletteColor(int region) {
  const double h = std::fmod(0.13 + 0.618033988749895 * region, 1.0) * 6.0;
  const double s = 0.55, v = 0.92, c = v * s, x = c * (1 - std::fabs(std::fmod(h, 2.0) - 1)), mm = v - c;
  double r = 0, g = 0, b = 0;
  switch (int(h) % 6) {
    case 0: r = c, g = x; break;
    case 1: r = x, g = c; break;
    case 2: g = c, b = x; break;
    case 3: g = x, b = c; break;
    case 4: r = x, b = c; break;
    default: r = c, b = x; break;
  }
  auto q = [&](double t) { return (unsigned char)std::lround(255 * (t + mm)); };
  return vcg::Color4b(q(r), q(g), q(b), 255);
}

/// Mean length of m's edges, each counted once. O(F).
template <class MeshType>
double MeanEdgeLength(const MeshType& cm) {
  MeshType& m = const_cast<MeshType&>(cm);
  double sum = 0;
  long n = 0;
  for (auto& f : m.face) {
    if (f.IsD()) continue;
    for (int z = 0; z < 3; ++z)
      if (f.FFp(z) == &f || &f < f.FFp(z)) {
        sum += vcg::Distance(f.P(z), f.P((z + 1) % 3));
        ++n;
      }
  }
  return n ? sum / n : 0;
}

/// The point of the faces `fan` (indices into R.faces, corners at positions p) closest to x:
/// puts an inset vertex back on the surface (step 2). O(fan size).
template <class C>
C OnFan(const C& x, const std::vector<size_t>& fan, const RegionOutline& R, const std::vector<C>& p) {
  typedef typename C::ScalarType S;
  C best = x;
  S bestDist = std::numeric_limits<S>::max();
  for (size_t i : fan) {
    const auto& c = R.corners[i];
    const vcg::Triangle3<S> t(p[size_t(c[0])], p[size_t(c[1])], p[size_t(c[2])]);
    S d;
    C y;
    vcg::TrianglePointDistance(t, x, d, y);
    if (d < bestDist) bestDist = d, best = y;
  }
  return best;
}

/// Writes into `out` (cleared first) one panel per region of `labels` over `m`. `m` is only read.
template <class MeshType>
PanelReport BuildPanels(const MeshType& cm, const PatternLabels& labels, const PanelOptions& opt, MeshType& out) {
  typedef typename MeshType::CoordType C;
  typedef typename MeshType::ScalarType S;
  MeshType& m = const_cast<MeshType&>(cm);  // read only: vcg's accessors are not const
  PanelReport rep;
  auto fail = [&](std::string why) {
    rep.ok = false;
    rep.reason = "panels: " + why;
    return rep;
  };
  if (!labels.ok) return fail("the pattern failed: " + labels.reason);
  if (labels.faceRegion.size() != m.face.size()) return fail("the pattern does not match the mesh (face count)");
  if (opt.inset < 0) return fail("the inset must not be negative");
  const int regions = int(labels.regionKind.size());
  std::vector<std::vector<int>> facesOf(size_t(std::max(regions, 0)));
  for (size_t i = 0; i < m.face.size(); ++i) {
    if (m.face[i].IsD()) continue;
    const int r = labels.faceRegion[i];
    if (r < 0 || r >= regions) return fail("face " + std::to_string(i) + " has no region");
    facesOf[size_t(r)].push_back(int(i));
  }
  rep.meanEdgeLength = MeanEdgeLength(m);
  const double delta = opt.inset * rep.meanEdgeLength, height = opt.extrude * rep.meanEdgeLength;
  const bool colorOut = vcg::tri::HasPerFaceColor(out), colorIn = vcg::tri::HasPerFaceColor(m);

  std::vector<C> pos;
  std::vector<std::array<int, 3>> tris;
  std::vector<vcg::Color4b> colors;
  for (int r = 0; r < regions; ++r) {
    const std::vector<int>& fr = facesOf[size_t(r)];
    if (fr.empty()) continue;
    RegionOutline R = BuildRegionOutline(m, fr);
    rep.panels++;
    const int sides = R.Corners();
    if (int(rep.panelSidesHistogram.size()) <= sides) rep.panelSidesHistogram.resize(size_t(sides) + 1, 0);
    rep.panelSidesHistogram[size_t(sides)]++;
    const vcg::Color4b col = size_t(r) < opt.regionColors.size() ? opt.regionColors[size_t(r)]
                             : colorIn                             ? m.face[size_t(fr[0])].C()
                                                                   : PanelPaletteColor(r);

    const int nv = R.Vertices();
    std::vector<C> p((size_t(nv))), n(size_t(nv), C(0, 0, 0));
    for (int v = 0; v < nv; ++v) p[size_t(v)] = m.vert[size_t(R.source[size_t(v)])].P();
    for (size_t i = 0; i < R.faces.size(); ++i) {
      const auto& c = R.corners[i];
      const C fn = (p[size_t(c[1])] - p[size_t(c[0])]) ^ (p[size_t(c[2])] - p[size_t(c[0])]);
      for (int z = 0; z < 3; ++z) n[size_t(c[size_t(z)])] += fn;
    }
    for (C& x : n) x.Normalize();
    std::vector<std::vector<size_t>> fansAt((size_t(nv)));  // region faces at each outline vertex
    for (size_t i = 0; i < R.faces.size(); ++i)
      for (int z = 0; z < 3; ++z)
        if (R.onOutline[size_t(R.corners[i][size_t(z)])]) fansAt[size_t(R.corners[i][size_t(z)])].push_back(i);
    std::vector<C> q = p;  // inset positions
    for (const auto& loop : R.loops) {
      const size_t L = loop.size();
      for (size_t k = 0; k < L; ++k) {
        const int a = loop[(k + L - 1) % L], b = loop[k], c = loop[(k + 1) % L];
        C e1 = p[size_t(b)] - p[size_t(a)], e2 = p[size_t(c)] - p[size_t(b)];
        e1.Normalize();
        e2.Normalize();
        const C nb = n[size_t(b)];
        const C in1 = nb ^ e1, in2 = nb ^ e2;  // the region lies on the left of each outline edge
        C dir = in1 + in2;
        double len = delta;
        if (dir.Norm() < 1e-6) {
          dir = in1;
        } else {
          dir.Normalize();
          len = delta / std::max(double(dir.dot(in1)), 0.2);
        }
        q[size_t(b)] = OnFan(p[size_t(b)] + dir * S(len), fansAt[size_t(b)], R, p);
      }
    }
    const int base = int(pos.size());
    for (int v = 0; v < nv; ++v) pos.push_back(q[size_t(v)] + n[size_t(v)] * S(height));
    for (const auto& c : R.corners) tris.push_back({base + c[0], base + c[1], base + c[2]});
    if (height != 0) {
      const size_t first = tris.size() - R.corners.size();
      const int bot = int(pos.size());
      for (int v = 0; v < nv; ++v) pos.push_back(q[size_t(v)]);
      for (const auto& c : R.corners) tris.push_back({bot + c[0], bot + c[2], bot + c[1]});
      for (const auto& loop : R.loops)
        for (size_t k = 0; k < loop.size(); ++k) {
          const int a = loop[k], b = loop[(k + 1) % loop.size()];
          // the top holds a->b, the bottom b->a: the wall holds b->a on top, a->b at the bottom
          tris.push_back({base + b, base + a, bot + a});
          tris.push_back({base + b, bot + a, bot + b});
        }
      // extruded into the surface (height < 0): the top lies below the bottom, so the shell is
      // turned inside out; reverse it to keep the normals outwards
      if (height < 0)
        for (size_t t = first; t < tris.size(); ++t) std::swap(tris[t][1], tris[t][2]);
    }
    colors.resize(tris.size(), col);
  }
  out.Clear();
  if (!pos.empty()) {
    auto vi = vcg::tri::Allocator<MeshType>::AddVertices(out, pos.size());
    for (size_t i = 0; i < pos.size(); ++i, ++vi) vi->P() = pos[i];
    auto fi = vcg::tri::Allocator<MeshType>::AddFaces(out, tris.size());
    for (size_t i = 0; i < tris.size(); ++i, ++fi) {
      for (int z = 0; z < 3; ++z) fi->V(z) = &out.vert[size_t(tris[i][size_t(z)])];
      if (colorOut) fi->C() = colors[i];
    }
  }
  vcg::tri::UpdateBounding<MeshType>::Box(out);
  return rep;
}

}  // namespace irregular
}  // namespace vcg_ext
