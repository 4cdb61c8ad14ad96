// Unit tests of vcg_ext/irregular/pattern_panels.h (paper Fig. 1, Fig. 14d): panels from
// hand-made labellings where the count, the sides, the shells and the inset positions are
// known exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/stat.h>
#include <vcg/complex/append.h>
#include <vcg_ext/irregular/mesh_checks.h>
#include <vcg_ext/irregular/pattern_panels.h>
#include <vcg_ext/irregular/star_pattern.h>

#include "test_mesh.h"
#include "test_pattern_mesh.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {
/// Labels: region r+1 for the faces around cells[r], region 0 for the rest.
PatternLabels CellsAround(TMesh& m, const std::vector<int>& cells) {
  PatternLabels P;
  P.faceRegion.assign(m.face.size(), 0);
  P.regionKind = {RegionKind::Background};
  for (int c : cells) {
    const int id = int(P.regionKind.size());
    P.regionKind.push_back(RegionKind::Cell);
    for (size_t i = 0; i < m.face.size(); ++i)
      for (int z = 0; z < 3; ++z)
        if (vcg::tri::Index(m, m.face[i].V(z)) == size_t(c)) P.faceRegion[i] = id;
  }
  return P;
}
/// The panels mesh is a set of closed, manifold, consistently oriented shells (or, flat, of
/// manifold consistently oriented surfaces): vcg's Clean and mesh_checks.h.
void ExpectCleanShells(TMesh& out, bool closed, int components) {
  test::UpdateTopology(out);
  EXPECT_EQ(vcg::tri::Clean<TMesh>::CountNonManifoldEdgeFF(out), 0);
  EXPECT_EQ(vcg::tri::Clean<TMesh>::CountNonManifoldVertexFF(out), 0);
  bool oriented = false, orientable = false;
  vcg::tri::Clean<TMesh>::OrientCoherentlyMesh(out, oriented, orientable);
  EXPECT_TRUE(oriented);
  EXPECT_TRUE(orientable);
  EXPECT_EQ(vcg::tri::Clean<TMesh>::IsWaterTight(out), closed);
  EXPECT_EQ(vcg::tri::Clean<TMesh>::CountConnectedComponents(out), components);
  Result r = CheckInvariants(out);
  EXPECT_TRUE(r.ok) << r.reason;
}
}  // namespace

// One v5 in a flat patch of radius 6 (180 faces): the cell around the v5 (5 faces), the cell
// around a regular vertex (6 faces), the rest. Sides: 5, 6, and the rest's outline: 5 corners
// of the patch (2 faces each) + 5 + 6 around the holes (4 faces each) = 16.
TEST(PatternPanels, HandMadeCellsCountsSidesAndShells) {
  TMesh m;
  test::NGonPatch(m, 5, 6);
  ASSERT_EQ(m.fn, 180);
  const int regular = test::NGonIndex(5, 3, 1, 1);
  ASSERT_EQ(Valence<TMesh>(&m.vert[size_t(regular)]), 6);
  PatternLabels P = CellsAround(m, {0, regular});
  TMesh out;
  PanelOptions o;  // extruded
  PanelReport rep = BuildPanels(m, P, o, out);
  ASSERT_TRUE(rep.ok) << rep.reason;
  EXPECT_EQ(rep.panels, 3);
  std::vector<int> sides(17, 0);
  sides[5] = sides[6] = sides[16] = 1;
  EXPECT_EQ(rep.panelSidesHistogram, sides);
  // top + bottom + two wall triangles per outline edge: 5 + 6 + (30 + 5 + 6) outline edges
  EXPECT_EQ(out.fn, 2 * 180 + 2 * (5 + 6 + 41));
  ExpectCleanShells(out, true, 3);
  // flat: the region copies alone, as open surfaces
  o.extrude = 0;
  TMesh flat;
  rep = BuildPanels(m, P, o, flat);
  ASSERT_TRUE(rep.ok);
  EXPECT_EQ(flat.fn, 180);
  ExpectCleanShells(flat, false, 3);
  EXPECT_EQ(vcg::tri::Clean<TMesh>::CountHoles(flat), 1 + 1 + 3);
}

// The hexagonal cell around the centre of a flat unit lattice: each outline vertex moves
// towards the centre by inset / sin 60, so each outline edge moves inwards by exactly the
// inset; the centre stays; extruded, the top is the inset copy lifted by extrude along +z.
TEST(PatternPanels, InsetAndExtrudePositionsAreExact) {
  TMesh m;
  test::HexPatch(m, 4);
  PatternLabels P = CellsAround(m, {0});
  PanelOptions o;
  o.inset = 0.1;
  o.extrude = 0.25;
  TMesh out;
  PanelReport rep = BuildPanels(m, P, o, out);
  ASSERT_TRUE(rep.ok) << rep.reason;
  EXPECT_NEAR(rep.meanEdgeLength, 1.0, 1e-6);
  EXPECT_EQ(rep.panels, 2);
  std::vector<int> sides(13, 0);
  sides[6] = 1;   // the hexagonal cell
  sides[12] = 1;  // the rest: the patch's 6 corners and the 6 around the hole
  EXPECT_EQ(rep.panelSidesHistogram, sides);
  // the cell's panel: vertices near the centre (within 1.1 in xy)
  int top = 0, bottom = 0, centre = 0;
  const double inner = 1.0 - 0.1 / std::sin(M_PI / 3);
  for (auto& v : out.vert) {
    const vcg::Point3f p = v.P();
    const double r = std::hypot(p[0], p[1]);
    if (r > 1.1) continue;
    EXPECT_TRUE(std::fabs(p[2]) < 1e-6 || std::fabs(p[2] - 0.25) < 1e-6) << p[2];
    (p[2] > 0.1 ? top : bottom)++;
    if (r < 1e-6) {
      ++centre;
      continue;
    }
    EXPECT_NEAR(r, inner, 1e-5);
    // the inset outline vertex lies on the bisector of its original vertex: at 0, 60, ... degrees
    const double a = std::atan2(p[1], p[0]) * 180 / M_PI;
    EXPECT_NEAR(std::remainder(a, 60.0), 0.0, 1e-3);
    // distance to the original outline edge lines (x cos(30 + 60k) + y sin(...) = cos 30): 0.1
    const double k = std::round((a - 30) / 60), t = (30 + 60 * k) * M_PI / 180;
    const double d = std::cos(M_PI / 6) - (p[0] * std::cos(t) + p[1] * std::sin(t));
    EXPECT_NEAR(d, 0.1, 1e-5);
  }
  EXPECT_EQ(top, 7);
  EXPECT_EQ(bottom, 7);
  EXPECT_EQ(centre, 2);
  ExpectCleanShells(out, true, 2);
  // extruded into the surface: the top at z = -0.25, still closed shells with outward normals
  o.extrude = -0.25;
  TMesh in;
  ASSERT_TRUE(BuildPanels(m, P, o, in).ok);
  int below = 0;
  for (auto& v : in.vert) below += std::fabs(v.P()[2] + 0.25) < 1e-6 ? 1 : 0;
  EXPECT_EQ(size_t(below) * 2, in.vert.size());
  ExpectCleanShells(in, true, 2);
  EXPECT_GT(vcg::tri::Stat<TMesh>::ComputeMeshVolume(in), 0);
  EXPECT_GT(vcg::tri::Stat<TMesh>::ComputeMeshVolume(out), 0);
}

// Width-one strips around a regular torus (the faces of one row of quads): every panel is an
// annulus without corners; extruded, a closed torus-shaped shell each.
TEST(PatternPanels, StripsAroundATorusHaveNoCorners) {
  TMesh m;
  const int n = 12, k = 8;
  test::RegularTorus(m, n, k);
  PatternLabels P;
  P.faceRegion.resize(m.face.size());
  for (size_t i = 0; i < m.face.size(); ++i) P.faceRegion[i] = int((i / 2) % size_t(k));  // face 2(i*k+j)+{0,1}: row j
  P.regionKind.assign(size_t(k), RegionKind::StripeA);
  TMesh out;
  PanelReport rep = BuildPanels(m, P, PanelOptions(), out);
  ASSERT_TRUE(rep.ok) << rep.reason;
  EXPECT_EQ(rep.panels, k);
  EXPECT_EQ(rep.panelSidesHistogram, std::vector<int>{k});
  EXPECT_EQ(out.fn, k * (2 * 2 * n + 2 * 2 * n));
  ExpectCleanShells(out, true, k);
}

// Face colour: with per-face colour in both meshes, every panel face takes its region's colour.
TEST(PatternPanels, PanelsTakeTheRegionColour) {
  TMesh base;
  test::NGonPatch(base, 5, 5);
  test::TAMesh m, out;
  test::CopyWithAttributes(base, m);
  StarOptions so;
  so.radius = 2;
  PatternLabels P = ComputeStars(m, so);
  ASSERT_TRUE(P.ok) << P.reason;
  const vcg::Color4b palette[2] = {vcg::Color4b(200, 30, 30, 255), vcg::Color4b(30, 30, 200, 255)};
  for (size_t i = 0; i < m.face.size(); ++i) m.face[i].C() = palette[P.faceRegion[i]];
  PanelReport rep = BuildPanels(m, P, PanelOptions(), out);
  ASSERT_TRUE(rep.ok) << rep.reason;
  EXPECT_EQ(rep.panels, 2);
  int red = 0, blue = 0;
  for (auto& f : out.face) (f.C() == palette[0] ? red : blue)++;
  // the star of radius 2 around a v5 is the whole disk of radius 2: 20 faces top and bottom,
  // two wall triangles along each of the 10 edges of ring 2
  EXPECT_EQ(red, 2 * 20 + 2 * 10);
  EXPECT_EQ(blue, out.fn - red);
  for (auto& f : out.face) EXPECT_TRUE(f.C() == palette[0] || f.C() == palette[1]);
}

// On a curved surface the inset outline is put back on the surface: with no extrusion every
// panel vertex lies on the input mesh (a point moved in the tangent plane alone would be off
// it by about inset^2 / 2 on the unit sphere, 1e-4 here).
TEST(PatternPanels, InsetVerticesStayOnACurvedSurface) {
  TMesh m;
  test::Icosphere(m, 3);
  StarOptions so;
  so.radius = 2;
  PatternLabels P = ComputeStars(m, so);
  ASSERT_TRUE(P.ok) << P.reason;
  PanelOptions o;
  o.extrude = 0;
  TMesh out;
  PanelReport rep = BuildPanels(m, P, o, out);
  ASSERT_TRUE(rep.ok) << rep.reason;
  double worst = 0;
  int moved = 0;
  for (auto& v : out.vert) {
    double best = 1e9;
    for (auto& f : m.face) {
      float d;
      vcg::Point3f c;
      vcg::TrianglePointDistance(vcg::Triangle3<float>(f.P(0), f.P(1), f.P(2)), v.P(), d, c);
      best = std::min(best, double(d));
    }
    worst = std::max(worst, best);
    moved += std::fabs(v.P().Norm() - 1) > 1e-6 ? 1 : 0;  // off the vertices' sphere: inset
  }
  EXPECT_LT(worst, 1e-5);
  EXPECT_GT(moved, 100);
}
