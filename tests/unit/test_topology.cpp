// Unit tests of vcg_ext/irregular/topology.h, mesh_checks.h and legend.h on procedural shapes
// with exact counts, and on corpus meshes.
#include <gtest/gtest.h>

#include <vcg_ext/irregular/legend.h>
#include <vcg_ext/irregular/mesh_checks.h>
#include <vcg_ext/irregular/topology.h>

#include "test_mesh.h"

using namespace vcg_ext::irregular;
using test::TMesh;

TEST(Topology, IcosahedronHasTwelveV5) {
  TMesh m;
  test::Icosahedron(m);
  TopologySummary s = Summarize(m);
  EXPECT_EQ(s.vertices, 12);
  EXPECT_EQ(s.faces, 20);
  EXPECT_EQ(s.edges, 30);
  EXPECT_EQ(s.histogram.at(5), 12);
  EXPECT_EQ(s.irregular, 12);
  EXPECT_EQ(s.eulerCharacteristic, 2);
  EXPECT_EQ(s.genus, 0);
  EXPECT_EQ(s.boundaryLoops, 0);
  EXPECT_TRUE(s.GaussBonnetHolds());
  for (auto& v : m.vert) EXPECT_EQ(Valence<TMesh>(&v), 5);
  EXPECT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
}

TEST(Topology, SubdividedIcosphereStillTwelveV5) {
  TMesh m;
  test::Icosphere(m, 3);
  TopologySummary s = Summarize(m);
  EXPECT_EQ(s.faces, 20 * 64);
  EXPECT_EQ(s.vertices, 642);
  EXPECT_EQ(s.histogram.at(5), 12);
  EXPECT_EQ(s.histogram.at(6), 630);
  EXPECT_EQ(s.irregular, 12);
  EXPECT_EQ(s.gaussBonnetSum, 12);
  EXPECT_TRUE(s.GaussBonnetHolds());
  EXPECT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
}

TEST(Topology, RegularTorusHasNoIrregularVertex) {
  TMesh m;
  test::RegularTorus(m, 24, 12);
  TopologySummary s = Summarize(m);
  EXPECT_EQ(s.vertices, 288);
  EXPECT_EQ(s.irregular, 0);
  EXPECT_EQ(s.histogram.size(), 1u);
  EXPECT_EQ(s.eulerCharacteristic, 0);
  EXPECT_EQ(s.genus, 1);
  EXPECT_TRUE(s.GaussBonnetHolds());
  EXPECT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
}

TEST(Topology, HexDiscWithBoundary) {
  TMesh m;
  test::HexPatch(m, 4);
  TopologySummary s = Summarize(m);
  EXPECT_EQ(s.vertices, 61);          // 3 r (r + 1) + 1
  EXPECT_EQ(s.faces, 96);             // 6 r^2
  EXPECT_EQ(s.boundaryLoops, 1);
  EXPECT_EQ(s.boundaryEdges, 24);
  EXPECT_EQ(s.eulerCharacteristic, 1);
  EXPECT_EQ(s.genus, 0);
  EXPECT_EQ(s.histogram.at(6), 37);   // interior: hexagon of radius 3
  // boundary: 6 corners of valence 3, 18 side vertices of valence 4
  EXPECT_EQ(s.boundaryHistogram.at(3), 6);
  EXPECT_EQ(s.boundaryHistogram.at(4), 18);
  // the corners span 120 degrees: regular at valence 3 by the boundary valence rule, so the
  // disc has no irregular vertex, while eq. 2 still counts them against 4 (sum 6 = 6 chi)
  EXPECT_EQ(s.irregular, 0);
  EXPECT_EQ(s.boundaryIrregular, 0);
  EXPECT_EQ(s.boundaryCorners, 6);
  EXPECT_EQ(s.equivalentHistogram.at(6), 61);
  EXPECT_EQ(s.gaussBonnetSum, 6);
  EXPECT_TRUE(s.GaussBonnetHolds());
  VertexStar<TMesh> centre = StarOf<TMesh>(&m.vert[0]);
  EXPECT_FALSE(centre.boundary);
  EXPECT_EQ(centre.Valence(), 6);
  EXPECT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
  ValenceField<TMesh> vf = ComputeValences(m);
  for (size_t i = 0; i < m.vert.size(); ++i) {
    VertexStar<TMesh> st = StarOf<TMesh>(&m.vert[i]);
    EXPECT_EQ(st.Valence(), vf.valence[i]);
    EXPECT_EQ(st.boundary, bool(vf.boundary[i]));
    // the one-walk query agrees with the two it replaces, whichever face the VF entry names
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(InteriorValence<TMesh>(&m.vert[i]), vf.boundary[i] ? -1 : vf.valence[i]) << "vertex " << i;
      EXPECT_EQ(OnBoundary<TMesh>(&m.vert[i]), bool(vf.boundary[i]));
      EXPECT_EQ(Valence<TMesh>(&m.vert[i]), vf.valence[i]);
      if (st.corners.size() > size_t(k + 1)) {
        m.vert[i].VFp() = st.corners[size_t(k + 1)].f;
        m.vert[i].VFi() = st.corners[size_t(k + 1)].z;
      }
    }
  }
}

TEST(Topology, BoundaryValenceRule) {
  EXPECT_EQ(RegularBoundaryValence(180), 4);
  EXPECT_EQ(RegularBoundaryValence(120), 3);
  EXPECT_EQ(RegularBoundaryValence(60), 2);
  EXPECT_EQ(RegularBoundaryValence(240), 5);
  EXPECT_EQ(RegularBoundaryValence(300), 6);
  EXPECT_EQ(RegularBoundaryValence(90), 3);    // 1.5 rounds up
  EXPECT_EQ(RegularBoundaryValence(20), 2);    // at least one face
  EXPECT_EQ(RegularBoundaryValence(150), 4);   // the smooth stretch is [150, 210)
  EXPECT_EQ(RegularBoundaryValence(149.9), 3);
  EXPECT_EQ(RegularBoundaryValence(209.9), 4);
  EXPECT_EQ(RegularBoundaryValence(210), 5);
  EXPECT_FALSE(IsBoundaryCorner(170));
  EXPECT_TRUE(IsBoundaryCorner(140));
  EXPECT_EQ(EquivalentValence(3, 4), 5);
  EXPECT_EQ(EquivalentValence(3, 3), 6);
  EXPECT_EQ(EquivalentValence(7, 6), 7);
  // the corner angle of a lattice vertex on a side of the hexagon is 3 x 60 degrees
  TMesh m;
  test::HexPatch(m, 2);
  ValenceField<TMesh> vf = ComputeValences(m);
  for (size_t i = 0; i < m.vert.size(); ++i) {
    VertexStar<TMesh> st = StarOf<TMesh>(&m.vert[i]);
    if (!st.boundary) continue;
    EXPECT_NEAR(CornerAngleDeg(st), 60.0 * double(st.corners.size()), 1e-4);
    EXPECT_EQ(RegularValenceOf(st), vf.regular[i]);
  }
}

TEST(Topology, StarIsCounterClockwise) {
  TMesh m;
  test::HexPatch(m, 2);
  VertexStar<TMesh> s = StarOf<TMesh>(&m.vert[0]);
  ASSERT_EQ(s.Valence(), 6);
  // consecutive neighbours turn left (CCW) around the centre in the z = 0 plane
  for (int k = 0; k < 6; ++k) {
    auto a = s.neighbors[k]->P(), b = s.neighbors[(k + 1) % 6]->P();
    EXPECT_GT(a[0] * b[1] - a[1] * b[0], 0.f);
  }
}

TEST(Legend, SelectionAndColours) {
  TMesh m;
  test::HexPatch(m, 3);
  ValenceField<TMesh> vf = ComputeValences(m);
  PaintValences(m, vf, true);
  // the 6 corners (valence 3 at 120 degrees) are regular by the boundary valence rule
  EXPECT_EQ(SelectByValence(m, vf, IrregularSelection::AllIrregular, 0), 0);
  EXPECT_EQ(SelectByValence(m, vf, IrregularSelection::OnlyValence, 5), 0);
  EXPECT_EQ(SelectByValence(m, vf, IrregularSelection::OnlyValence, 6), int(m.vert.size()));
  EXPECT_EQ(SelectByValence(m, vf, IrregularSelection::None, 0), int(m.vert.size()));  // unchanged
  for (size_t i = 0; i < m.vert.size(); ++i) EXPECT_EQ(m.vert[i].C(), LegendColor(6)) << i;
  // pull a corner out to 180 degrees: now a boundary v3 on a smooth stretch, i.e. a v5
  int corner = -1;
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (vf.boundary[i] && vf.valence[i] == 3) corner = int(i);
  ASSERT_GE(corner, 0);
  VertexStar<TMesh> cs = StarOf<TMesh>(&m.vert[size_t(corner)]);
  // inwards until the corner angle is about 167 degrees; its two boundary neighbours close
  // from 180 to about 157 degrees and stay regular at 4
  const vcg::Point3f mid = (cs.neighbors.front()->P() + cs.neighbors.back()->P()) * 0.5f;
  m.vert[size_t(corner)].P() = mid + (m.vert[size_t(corner)].P() - mid) * 0.2f;
  vf = ComputeValences(m);
  EXPECT_TRUE(vf.IsIrregular(size_t(corner)));
  EXPECT_FALSE(vf.IsCorner(size_t(corner)));
  EXPECT_EQ(vf.Equivalent(size_t(corner)), 5);
  EXPECT_EQ(SelectByValence(m, vf, IrregularSelection::AllIrregular, 0), 1);
  EXPECT_TRUE(m.vert[size_t(corner)].IsS());
  EXPECT_EQ(m.vert[0].Q(), 6.f);
}

TEST(Checks, DiagnoseFindsNonManifoldEdge) {
  TMesh m;
  test::HexPatch(m, 1);
  // a third face on the edge (0, 1)
  vcg::tri::Allocator<TMesh>::AddVertices(m, 1);
  m.vert.back().P() = vcg::Point3f(0.5f, 0.f, 1.f);
  vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[0], &m.vert[1], &m.vert.back());
  test::UpdateTopology(m);
  InputReport r = DiagnoseInput(m);
  EXPECT_GT(r.nonManifoldEdges, 0);
  Result v = r.Verdict();
  EXPECT_FALSE(v.ok);
  EXPECT_NE(v.reason.find("Repair non Manifold Edges"), std::string::npos);
}

TEST(Checks, DiagnoseFindsNonManifoldVertex) {
  // two triangles sharing only a vertex
  TMesh m;
  vcg::tri::Allocator<TMesh>::AddVertices(m, 5);
  m.vert[0].P() = vcg::Point3f(0, 0, 0);
  m.vert[1].P() = vcg::Point3f(1, 0, 0);
  m.vert[2].P() = vcg::Point3f(0, 1, 0);
  m.vert[3].P() = vcg::Point3f(-1, 0, 0);
  m.vert[4].P() = vcg::Point3f(0, -1, 0);
  vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[0], &m.vert[1], &m.vert[2]);
  vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[0], &m.vert[3], &m.vert[4]);
  test::UpdateTopology(m);
  InputReport r = DiagnoseInput(m);
  EXPECT_EQ(r.nonManifoldVertices, 1);
  EXPECT_NE(r.Verdict().reason.find("Repair non Manifold Vertices"), std::string::npos);
}

TEST(Checks, CleanMeshPasses) {
  TMesh m;
  test::Icosphere(m, 2);
  EXPECT_TRUE(DiagnoseInput(m).Verdict().ok);
}

class Corpus : public ::testing::TestWithParam<const char*> {};

TEST_P(Corpus, GaussBonnetAndInvariants) {
  TMesh m;
  ASSERT_TRUE(test::LoadCorpus(m, GetParam())) << "missing " << GetParam() << " (run scripts/setup.sh)";
  ASSERT_TRUE(DiagnoseInput(m).Verdict().ok) << DiagnoseInput(m).Verdict().reason;
  TopologySummary s = Summarize(m);
  EXPECT_TRUE(s.GaussBonnetHolds());
  EXPECT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
  ValenceField<TMesh> vf = ComputeValences(m);
  for (size_t i = 0; i < m.vert.size(); i += 97) EXPECT_EQ(Valence<TMesh>(&m.vert[i]), vf.valence[i]);
  for (size_t i = 0; i < m.vert.size(); ++i)
    ASSERT_EQ(InteriorValence<TMesh>(&m.vert[i]), vf.boundary[i] ? -1 : vf.valence[i]) << "vertex " << i;
}

INSTANTIATE_TEST_SUITE_P(Real, Corpus, ::testing::Values("bunny00.off", "knot1.off", "elephant.off", "fandisk.off", "mushroom.off"));
