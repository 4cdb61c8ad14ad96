// Unit tests of vcg_ext/irregular/relaxation.h and quality.h (paper sec. 8).
#include <gtest/gtest.h>

#include <random>

#include <vcg_ext/irregular/atomic_ops.h>
#include <vcg_ext/irregular/mesh_checks.h>
#include <vcg_ext/irregular/quality.h>
#include <vcg_ext/irregular/relaxation.h>

#include "test_mesh.h"
#include "test_util.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {
std::vector<int> AllVertices(TMesh& m) {
  std::vector<int> r;
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD()) r.push_back(int(i));
  return r;
}
void Perturb(TMesh& m, float amount, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-amount, amount);
  for (auto& v : m.vert) v.P() += vcg::Point3f(u(rng), u(rng), 0);
}
}  // namespace

class RelaxModes : public ::testing::TestWithParam<RelaxMode> {};

// On a perturbed planar lattice, relaxation recovers near-equilateral triangles and never
// changes connectivity.
TEST_P(RelaxModes, PerturbedGridBecomesEquilateral) {
  TMesh m;
  test::HexPatch(m, 8);
  SurfaceProjector plane(m);
  Perturb(m, 0.3f, 5);
  test::UpdateTopology(m);
  auto faces = test::CanonicalFaces(m);
  ShapeMeasures before = MeasureShape(m);
  RelaxOptions opt;
  opt.mode = GetParam();
  opt.iterations = GetParam() == RelaxMode::Global ? 5 : 30;
  RelaxReport rep = Relax(m, AllVertices(m), &plane, opt);
  ShapeMeasures after = MeasureShape(m);
  EXPECT_EQ(test::CanonicalFaces(m), faces);
  EXPECT_GT(rep.moved, 0);
  EXPECT_GT(after.meanMinAngleDeg, before.meanMinAngleDeg);
  EXPECT_GT(after.meanMinAngleDeg, 55.0) << "mean min angle " << after.meanMinAngleDeg;
  EXPECT_LT(after.edgeLengthSpread, before.edgeLengthSpread);
  for (auto& v : m.vert) EXPECT_NEAR(v.P()[2], 0.f, 1e-5f);  // stays on the original plane
  EXPECT_TRUE(CheckInvariants(m).ok);
}

// After connectivity edits on a real mesh, relaxation improves angles and stays on the surface.
TEST_P(RelaxModes, RealMeshAfterEditsImprovesAndStaysOnSurface) {
  TMesh m;
  ASSERT_TRUE(test::LoadCorpus(m, "knot1.off")) << "corpus mesh missing (run scripts/setup.sh)";
  SurfaceProjector original(m);
  MeshEditor<TMesh> ed(m);
  AtomicOperations<TMesh> ops(ed);
  std::vector<int> touched;
  for (size_t i = 0; i < m.vert.size(); i += 37) {
    AtomicOutcome o = ops.GenerateQuadruple(int(i), 0, false);
    if (o) touched.insert(touched.end(), o.irregular.begin(), o.irregular.end());
  }
  ASSERT_GT(touched.size(), 20u);
  auto faces = test::CanonicalFaces(m);
  ShapeMeasures before = MeasureShape(m);
  RelaxOptions opt;
  opt.mode = GetParam();
  opt.iterations = 5;
  std::vector<int> region = KRing(m, touched, 2);
  Relax(m, region, &original, opt);
  ShapeMeasures after = MeasureShape(m);
  EXPECT_EQ(test::CanonicalFaces(m), faces);
  EXPECT_GT(after.meanMinAngleDeg, before.meanMinAngleDeg);
  EXPECT_LE(after.shareBelow30, before.shareBelow30);
  double worst = 0;
  for (int v : region) {
    float d = 0;
    original.Closest(m.vert[size_t(v)].P(), &d);
    worst = std::max(worst, double(d));
  }
  EXPECT_LT(worst, 1e-4 * original.Diagonal());
  EXPECT_LT(HausdorffPercent(m, original), 0.5);
  EXPECT_TRUE(CheckInvariants(m).ok);
}

INSTANTIATE_TEST_SUITE_P(Modes, RelaxModes, ::testing::Values(RelaxMode::Local, RelaxMode::Global));

TEST(Relaxation, GlobalConvergesInFewerSweepsThanLocal) {
  TMesh a, b;
  test::HexPatch(a, 10);
  test::HexPatch(b, 10);
  SurfaceProjector plane(a);
  Perturb(a, 0.3f, 9);
  Perturb(b, 0.3f, 9);
  test::UpdateTopology(a);
  test::UpdateTopology(b);
  RelaxOptions lo, go;
  lo.iterations = 3;
  go.mode = RelaxMode::Global;
  go.iterations = 3;
  LocalRelax(a, AllVertices(a), &plane, lo);
  GlobalRelax(b, AllVertices(b), &plane, go);
  EXPECT_GT(MeasureShape(b).meanMinAngleDeg, MeasureShape(a).meanMinAngleDeg);
}

TEST(Relaxation, CreaseVerticesStayFixed) {
  TMesh m;
  ASSERT_TRUE(test::LoadCorpus(m, "fandisk.off")) << "corpus mesh missing (run scripts/setup.sh)";
  SurfaceProjector original(m);
  std::vector<char> crease = CreaseVertices(m, 40.0);
  int nCrease = 0;
  for (char c : crease) nCrease += c;
  ASSERT_GT(nCrease, 50);
  std::vector<vcg::Point3f> before;
  for (auto& v : m.vert) before.push_back(v.P());
  RelaxOptions opt;
  opt.featureAngleDeg = 40;
  opt.iterations = 3;
  LocalRelax(m, AllVertices(m), &original, opt, &crease);
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (crease[i]) EXPECT_EQ(m.vert[i].P(), before[i]);
}

TEST(Quality, MeasuresOnEquilateralLattice) {
  TMesh m;
  test::HexPatch(m, 3);
  ShapeMeasures s = MeasureShape(m);
  EXPECT_NEAR(s.minAngleDeg, 60.0, 1e-3);
  EXPECT_NEAR(s.shareBelow30, 0.0, 1e-12);
  EXPECT_NEAR(s.edgeLengthSpread, 0.0, 1e-5);
  SurfaceProjector self(m);
  EXPECT_NEAR(HausdorffPercent(m, self), 0.0, 1e-4);
}

// With a BoundaryCurve, boundary vertices slide along the boundary as it was: a side vertex
// pushed along its side comes back towards the middle of its boundary neighbours and stays on
// the polyline; the six 120-degree corners stay exactly where they are. Without it, every
// boundary vertex stays fixed.
TEST(Relaxation, BoundaryVerticesSlideAlongTheBoundaryCornersFixed) {
  for (int withCurve = 0; withCurve < 2; ++withCurve) {
    TMesh m;
    test::HexPatch(m, 4);
    BoundaryCurve curve(m);
    ASSERT_EQ(curve.Segments(), 24u);
    // push every side vertex a quarter edge along its side (towards its first boundary neighbour)
    std::vector<int> side, corner;
    for (size_t i = 0; i < m.vert.size(); ++i) {
      VertexStar<TMesh> st = StarOf<TMesh>(&m.vert[i]);
      if (!st.boundary) continue;
      (st.Valence() == 3 ? corner : side).push_back(int(i));
    }
    ASSERT_EQ(corner.size(), 6u);
    ASSERT_EQ(side.size(), 18u);
    std::vector<vcg::Point3f> pushed;
    for (int v : side) {
      VertexStar<TMesh> st = StarOf<TMesh>(&m.vert[size_t(v)]);
      m.vert[size_t(v)].P() += (st.neighbors.front()->P() - m.vert[size_t(v)].P()) * 0.25f;
    }
    for (auto& v : m.vert) pushed.push_back(v.P());
    auto offMid = [&](int v) {
      VertexStar<TMesh> st = StarOf<TMesh>(&m.vert[size_t(v)]);
      return ((st.neighbors.front()->P() + st.neighbors.back()->P()) * 0.5f - m.vert[size_t(v)].P()).Norm();
    };
    double before = 0;
    for (int v : side) before += offMid(v);
    std::vector<int> all;
    for (size_t i = 0; i < m.vert.size(); ++i) all.push_back(int(i));
    RelaxOptions ro;
    ro.iterations = 20;
    ro.boundaryCurve = withCurve ? &curve : nullptr;
    LocalRelax(m, all, nullptr, ro);
    double after = 0;
    for (int v : side) after += offMid(v);
    for (int v : corner) EXPECT_EQ(m.vert[size_t(v)].P(), pushed[size_t(v)]) << "corner " << v;
    if (withCurve) {
      EXPECT_LT(after, 0.2 * before);
      for (int v : side) {
        double d = 1;
        curve.Closest(m.vert[size_t(v)].P(), &d);
        EXPECT_LT(d, 1e-5) << "vertex " << v << " left the boundary";
        EXPECT_NE(m.vert[size_t(v)].P(), pushed[size_t(v)]);
      }
    } else {
      for (int v : side) EXPECT_EQ(m.vert[size_t(v)].P(), pushed[size_t(v)]);
    }
    EXPECT_TRUE(CheckInvariants(m).ok);
    EXPECT_EQ(CountFoldedEdges(m), 0);
  }
}
