// Unit tests of the direction machinery (directions.h) and of the atomic operations by
// direction (atomic_ops.h): fig. 6 numbered by the angle of the pair's displacement, fig. 7
// and fig. 8 by 60-degree sector from a reference edge, on a flat lattice patch where the
// angles are exact.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include <vcg_ext/irregular/atomic_ops.h>
#include <vcg_ext/irregular/directions.h>
#include <vcg_ext/irregular/mesh_checks.h>

#include "test_mesh.h"
#include "test_util.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {

/// Index of the vertex at lattice (axial) coordinates (q, r) of a HexPatch, by position.
int At(TMesh& m, int q, int r) {
  const vcg::Point3f p(q + 0.5f * r, r * std::sqrt(3.f) / 2.f, 0.f);
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD() && (m.vert[i].P() - p).Norm() < 1e-4f) return int(i);
  return -1;
}

double AngleDeg(const vcg::Point3f& d) {
  double a = std::atan2(double(d[1]), double(d[0])) * 180.0 / M_PI;
  return a < 0 ? a + 360.0 : a;
}

}  // namespace

TEST(Directions, SectorsAreSixtyDegreesCentredOnMultiplesOfSixty) {
  EXPECT_EQ(SectorOfAngle(0), 0);
  EXPECT_EQ(SectorOfAngle(29.9), 0);
  EXPECT_EQ(SectorOfAngle(30), 1);
  EXPECT_EQ(SectorOfAngle(330), 0);
  EXPECT_EQ(SectorOfAngle(329.9), 5);
  EXPECT_EQ(SectorOfAngle(-10), 0);
  EXPECT_EQ(SectorOfAngle(180), 3);
  EXPECT_DOUBLE_EQ(AngleGap(350, 10), 20);
}

TEST(Directions, FrameOnTheFlatLatticeMeasuresCounterClockwiseFromTheReference) {
  TMesh m;
  test::HexPatch(m, 3);
  const int c = At(m, 0, 0), e = At(m, 1, 0), ne = At(m, 0, 1), w = At(m, -1, 0);
  TangentFrame<TMesh> f = FrameAt<TMesh>(&m.vert[size_t(c)], &m.vert[size_t(e)]);
  ASSERT_TRUE(f.valid);
  EXPECT_NEAR(f.AngleOf(m.vert[size_t(ne)].P()), 60, 1e-4);
  EXPECT_NEAR(f.AngleOf(m.vert[size_t(w)].P()), 180, 1e-4);
  TangentFrame<TMesh> g = FrameAt<TMesh>(&m.vert[size_t(c)], &m.vert[size_t(ne)]);
  EXPECT_NEAR(g.AngleOf(m.vert[size_t(e)].P()), 300, 1e-4);
  // no reference: the projected +X axis
  TangentFrame<TMesh> h = FrameAt<TMesh>(&m.vert[size_t(c)], nullptr);
  EXPECT_NEAR(h.AngleOf(m.vert[size_t(e)].P()), 0, 1e-4);
}

// Fig. 6: the six moves of an adjacent 5-7 pair ordered by the direction of the pair's
// displacement (midpoint before -> after), counter-clockwise from the v5-to-v7 edge.
TEST(Directions, PairMoveNumberingFollowsTheAngle) {
  TMesh m;
  test::HexPatch(m, 9);
  MeshEditor<TMesh> ed(m);
  ed.geometry().checkFolds = false;  // positions after collapses/splits are irrelevant here
  AtomicOperations<TMesh> ops(ed);
  // a 5-7 pair from a flip quadruple at the centre: flip (c, e): c, e -> 5; the ends of the
  // new edge -> 7. Take the pair (c, v7 above) and measure from there; the partner pair is
  // two edges away, outside the 1-ring the moves touch on the pair's far side.
  const int c = At(m, 0, 0), e = At(m, 1, 0);
  ASSERT_TRUE(ed.Flip(c, e));
  int v5 = c, v7 = At(m, 0, 1);
  ASSERT_EQ(ed.Valence(v5), 5);
  ASSERT_EQ(ed.Valence(v7), 7);
  // take the pair three flips away from its partner (v5 and v7 on the partner's far side)
  const vcg::Point3f partner = m.vert[size_t(e)].P();
  for (int step = 0; step < 3; ++step) {
    int best = -1;
    float far = -1;
    for (int dir : {1, 4}) {
      AtomicPrediction p = ops.PredictMovePair57(v5, v7, dir);
      if (!p) continue;
      const vcg::Point3f q = (m.vert[size_t(p.pair5)].P() + m.vert[size_t(p.pair7)].P()) / 2.f;
      if ((q - partner).Norm() > far) far = (q - partner).Norm(), best = dir;
    }
    ASSERT_GE(best, 0);
    AtomicOutcome o = ops.MovePair57(v5, v7, best);
    ASSERT_TRUE(o) << o.result.reason;
    v5 = o.pair5, v7 = o.pair7;
  }
  ed.Commit();
  auto pos = [&](int v) { return m.vert[size_t(v)].P(); };
  const vcg::Point3f mid = (pos(v5) + pos(v7)) / 2.f;
  const double edge = AngleDeg(pos(v7) - pos(v5));
  std::set<int> sectors;
  for (int k = 0; k < 6; ++k) {
    const int dir = AtomicOperations<TMesh>::PairDirectionByAngle(k);
    auto cp = ed.Mark();
    AtomicOutcome o = ops.MovePair57(v5, v7, dir);
    ASSERT_TRUE(o) << "k " << k << ": " << o.result.reason;
    const vcg::Point3f d = (pos(o.pair5) + pos(o.pair7)) / 2.f - mid;
    double a = AngleDeg(d) - edge;
    if (a < 0) a += 360;
    std::printf("k %d (dir %d): %s, displacement angle %.1f, length %.2f\n", k, dir, o.description.c_str(), a, d.Norm());
    EXPECT_EQ(SectorOfAngle(a), k) << o.description << ": angle " << a;
    sectors.insert(SectorOfAngle(a));
    ed.RollbackTo(cp);
  }
  EXPECT_EQ(sectors.size(), 6u);
}
