// Unit tests of vcg_ext/irregular/edit_session.h: the logic of the interactive edit tool
// (issue 16): picking, the direction under the cursor, steps, undo, cancellation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include <vcg_ext/irregular/composite_prediction.h>
#include <vcg_ext/irregular/edit_session.h>
#include <vcg_ext/irregular/mesh_checks.h>

#include "test_mesh.h"
#include "test_util.h"

using namespace vcg_ext::irregular;
using test::TMesh;
typedef TMesh::CoordType P3;

namespace {

/// A regular torus with one generated 5-5-7-7 quadruple whose pairs lie `spacing` steps apart.
struct QuadMesh {
  TMesh m;
  int pair5 = -1, pair7 = -1, other5 = -1, other7 = -1;
};

void MakeQuadruple(QuadMesh& q, int spacing, bool planar) {
  int centre;
  if (planar) {
    test::HexPatch(q.m, 14);
    centre = 0;
  } else {
    test::RegularTorus(q.m, 40, 40);
    centre = 20 * 40 + 20;
  }
  SurfaceProjector original(q.m);
  MeshEditor<TMesh> ed(q.m);
  CompositeOperations<TMesh> co(ed, &original);
  CompositeOutcome g = co.GenerateQuadruple(centre, 0, spacing);
  ASSERT_TRUE(g) << g.result.reason;
  q.pair5 = g.pair5, q.pair7 = g.pair7, q.other5 = g.other5, q.other7 = g.other7;
  ASSERT_EQ(test::IrregularVertices(q.m).size(), 4u);
}

int ValenceOf(TMesh& m, int v) { return StarOf<TMesh>(&m.vert[size_t(v)]).Valence(); }

std::set<int> IrregularSet(TMesh& m) {
  std::vector<int> v = test::IrregularVertices(m);
  return std::set<int>(v.begin(), v.end());
}

/// MeshLab's renderer reads vert[0..vn) and face[0..fn): the session keeps no deleted element.
::testing::AssertionResult Compact(const TMesh& m) {
  if (m.vert.size() == size_t(m.vn) && m.face.size() == size_t(m.fn)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "vert.size() " << m.vert.size() << " vn " << m.vn << " face.size() "
                                       << m.face.size() << " fn " << m.fn;
}

/// Orthographic projection onto the xy plane (the screen of a camera looking down -z).
vcg::Point2d Ortho(const P3& p) { return vcg::Point2d(p[0], p[1]); }

}  // namespace

TEST(EditSession, PicksTheIrregularVertexUnderTheClickAndItsNearestPartner) {
  QuadMesh q;
  MakeQuadruple(q, 4, true);
  EditSession<TMesh> s(q.m);
  EXPECT_FALSE(s.HasPair());
  // a click a little off the v5 of the moved pair: it leads, its adjacent v7 is the partner
  const P3 click = q.m.vert[size_t(q.pair5)].P() + P3(0.2f, 0.1f, 0);
  ASSERT_TRUE(s.PickAt(click).ok) << s.Message();
  EXPECT_EQ(s.Lead(), q.pair5);
  EXPECT_EQ(s.Partner(), q.pair7);
  EXPECT_TRUE(s.HasPair());
  // the other pair: its v7 picked leads, its v5 follows
  ASSERT_TRUE(s.PickAt(q.m.vert[size_t(q.other7)].P()).ok) << s.Message();
  EXPECT_EQ(s.Lead(), q.other7);
  EXPECT_EQ(s.Partner(), q.other5);
  // a second click picks the partner
  ASSERT_TRUE(s.PickPartner(q.pair5).ok) << s.Message();
  EXPECT_EQ(s.Lead(), q.other7);
  EXPECT_EQ(s.Partner(), q.pair5);
  // a click on a regular vertex is refused with the reason; the pair stays
  int regular = -1;
  for (size_t i = 0; i < q.m.vert.size() && regular < 0; ++i) {
    const P3 p = q.m.vert[i].P();
    if (p.Norm() > 6 && p.Norm() < 8) regular = int(i);
  }
  ASSERT_GE(regular, 0);
  ASSERT_EQ(ValenceOf(q.m, regular), 6);
  Result r = s.PickAt(q.m.vert[size_t(regular)].P());
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(s.Message(), "vertex " + std::to_string(regular) + " is regular (valence 6): click an irregular vertex");
  EXPECT_EQ(s.Lead(), q.other7);
  EXPECT_EQ(s.Partner(), q.pair5);
  // far from the mesh
  EXPECT_FALSE(s.PickAt(P3(100, 100, 0)).ok);
  EXPECT_NE(s.Message().find("no vertex within"), std::string::npos) << s.Message();
  // a partner that is regular, or the lead itself
  EXPECT_FALSE(s.PickPartner(regular).ok);
  EXPECT_FALSE(s.PickPartner(s.Lead()).ok);
  EXPECT_EQ(s.Partner(), q.pair5);
  // a boundary vertex (valence 3 at a corner of the hexagon, 4 on a side): refused
  int corner = -1;
  for (size_t i = 0; i < q.m.vert.size() && corner < 0; ++i)
    if (StarOf<TMesh>(&q.m.vert[i]).boundary) corner = int(i);
  EXPECT_FALSE(s.PickVertex(corner).ok);
  EXPECT_NE(s.Message().find("boundary"), std::string::npos) << s.Message();
}

TEST(EditSession, PicksThePairFromTheSelection) {
  QuadMesh q;
  MakeQuadruple(q, 4, false);
  EditSession<TMesh> s(q.m);
  EXPECT_FALSE(s.PickFromSelection().ok);  // nothing selected
  q.m.vert[size_t(q.other7)].SetS();
  q.m.vert[size_t(q.pair5)].SetS();
  ASSERT_TRUE(s.PickFromSelection().ok) << s.Message();
  EXPECT_EQ(s.Lead(), q.pair5);  // the lower valence leads
  EXPECT_EQ(s.Partner(), q.other7);
  q.m.vert[size_t(q.other5)].SetS();
  EXPECT_FALSE(s.PickFromSelection().ok);
  EXPECT_NE(s.Message().find("3 are selected"), std::string::npos) << s.Message();
  q.m.vert[size_t(q.other5)].ClearS();
  q.m.vert[size_t(q.other7)].ClearS();
  ASSERT_TRUE(s.PickFromSelection().ok) << s.Message();  // one: its nearest partner
  EXPECT_EQ(s.Lead(), q.pair5);
  EXPECT_EQ(s.Partner(), q.pair7);
}

TEST(EditSession, DirectionUnderTheCursorWithAnOrthographicProjection) {
  QuadMesh q;
  MakeQuadruple(q, 4, true);
  EditSession<TMesh> s(q.m);
  ASSERT_TRUE(s.PickVertex(q.pair5).ok) << s.Message();
  ASSERT_EQ(s.Partner(), q.pair7);
  auto dirs = s.Directions();
  ASSERT_EQ(dirs.size(), 6u);
  // on the flat lattice every move of an adjacent 5-7 pair is possible
  int accepted = 0;
  for (auto& d : dirs) accepted += d.accepted;
  EXPECT_EQ(accepted, 6);
  // the six arrows point six different ways, about 60 degrees apart; each screen vector along
  // an arrow, and turned 20 degrees off it, selects that arrow
  for (auto& d : dirs) {
    if (!d.accepted) continue;
    const vcg::Point2d a = Ortho(d.to) - Ortho(d.from);
    ASSERT_GT(a.Norm(), 0.3) << "direction " << d.k;
    EXPECT_EQ(s.DirectionToward(Ortho, a), d.k);
    for (double turn : {-20.0, 20.0}) {
      const double t = turn * M_PI / 180;
      const vcg::Point2d b(a[0] * std::cos(t) - a[1] * std::sin(t), a[0] * std::sin(t) + a[1] * std::cos(t));
      EXPECT_EQ(s.DirectionToward(Ortho, b), d.k) << "direction " << d.k << " turned " << turn;
    }
  }
  // the six arrows are spread around: sorted by angle, consecutive ones 30..90 degrees apart
  std::vector<double> angles;
  for (auto& d : dirs) {
    const vcg::Point2d a = Ortho(d.to) - Ortho(d.from);
    angles.push_back(std::atan2(a[1], a[0]) * 180 / M_PI);
  }
  std::sort(angles.begin(), angles.end());
  for (size_t i = 0; i < angles.size(); ++i) {
    double gap = (i + 1 < angles.size() ? angles[i + 1] : angles[0] + 360) - angles[i];
    EXPECT_GT(gap, 25) << i;
    EXPECT_LT(gap, 95) << i;
  }
  EXPECT_EQ(s.DirectionToward(Ortho, vcg::Point2d(0, 0)), -1);
  EXPECT_TRUE(s.DirectionsKnown());
  EXPECT_TRUE(s.Direction(3).to == dirs[3].to);
  EXPECT_FALSE(s.Direction(6).accepted);
  s.ClearPair();
  EXPECT_FALSE(s.DirectionsKnown());
  EXPECT_TRUE(s.Directions().empty());
  EXPECT_EQ(s.DirectionToward(Ortho, vcg::Point2d(1, 0)), -1);
  EXPECT_FALSE(s.Direction(0).accepted);
  ASSERT_TRUE(s.PickVertex(q.pair5).ok);
  EXPECT_FALSE(s.DirectionsKnown());
  // a point target: the step that brings the lead closest
  const P3 far = dirs[2].from + (dirs[2].to - dirs[2].from) * 10;
  EXPECT_EQ(s.DirectionTowardPoint(far), 2);
}

TEST(EditSession, StepMovesThePairWhereTheDryRunSaid) {
  QuadMesh q;
  MakeQuadruple(q, 4, true);
  EditSession<TMesh> s(q.m);
  ASSERT_TRUE(s.PickVertex(q.pair5).ok);
  for (int k = 0; k < 6; ++k) {
    const int l0 = s.Lead(), p0 = s.Partner();
    auto dirs = s.Directions();
    ASSERT_TRUE(dirs[size_t(k)].accepted) << dirs[size_t(k)].reason;
    // the scratch-copy dry run of the same move names the same vertices
    CompositePredictor<TMesh> pr(q.m, &s.Original());
    CompositePrediction p = pr.PredictMovePair(l0, p0, k, 1);
    ASSERT_TRUE(bool(p)) << p.result.reason;
    const test::MeshSnapshot before = test::Snapshot(q.m);
    std::set<int> neighbours;
    for (auto n : StarOf<TMesh>(&q.m.vert[size_t(l0)]).neighbors) neighbours.insert(int(vcg::tri::Index(q.m, n)));
    const P3 leadWas = q.m.vert[size_t(l0)].P();
    ASSERT_TRUE(s.Step(k).ok) << s.Message();
    EXPECT_EQ(s.Lead(), dirs[size_t(k)].lead);
    EXPECT_EQ(s.Partner(), dirs[size_t(k)].partner);
    EXPECT_TRUE(q.m.vert[size_t(s.Lead())].P() == dirs[size_t(k)].to);
    if (p.exact) {
      EXPECT_EQ(s.Lead(), p.lead);
      EXPECT_EQ(s.Partner(), p.partner);
    }
    // the pair is still an adjacent 5-7 pair; everything else touched is regular
    EXPECT_EQ(ValenceOf(q.m, s.Lead()), 5);
    EXPECT_EQ(ValenceOf(q.m, s.Partner()), 7);
    EXPECT_EQ(IrregularSet(q.m), (std::set<int>{s.Lead(), s.Partner(), q.other5, q.other7}));
    for (int v : s.Touched()) {
      // (a step that deleted elements also lists the slots it truncated, now past the end)
      if (size_t(v) >= q.m.vert.size()) continue;
      if (v == s.Lead() || v == s.Partner() || v == q.other5 || v == q.other7 || q.m.vert[size_t(v)].IsD()) continue;
      auto st = StarOf<TMesh>(&q.m.vert[size_t(v)]);
      EXPECT_EQ(st.Valence(), RegularValenceOf(st)) << "vertex " << v;
    }
    // the lead moved one step: onto a neighbour it had (or a vertex a split created), about
    // one edge length away
    const bool created = size_t(s.Lead()) >= before.verts.size();
    EXPECT_TRUE(created || neighbours.count(s.Lead())) << "direction " << k << ": lead " << l0 << " -> " << s.Lead();
    const double d = double((q.m.vert[size_t(s.Lead())].P() - leadWas).Norm());
    EXPECT_GT(d, 0.4) << "direction " << k;
    EXPECT_LT(d, 1.6) << "direction " << k;
    // nothing outside the touched region changed
    const test::MeshSnapshot after = test::Snapshot(q.m);
    std::set<int> touched(s.Touched().begin(), s.Touched().end());
    for (size_t v = 0; v < before.verts.size(); ++v)
      if (!touched.count(int(v))) ASSERT_LT(v, after.verts.size()) << "vertex " << v << " truncated, not touched";
    for (size_t v = 0; v < std::min(before.verts.size(), after.verts.size()); ++v)
      if (!touched.count(int(v))) EXPECT_TRUE(before.verts[v] == after.verts[v]) << "vertex " << v << " changed";
    Result inv = CheckInvariants(q.m);
    ASSERT_TRUE(inv.ok) << inv.reason;
    // the picking grid followed the step: a click on the moved lead picks it
    const int lead = s.Lead(), partner = s.Partner();
    ASSERT_TRUE(s.PickAt(q.m.vert[size_t(lead)].P()).ok) << s.Message();
    EXPECT_EQ(s.Lead(), lead);
    EXPECT_EQ(s.Partner(), partner);
  }
  // and an undo: the lead of the state before picks again, where it is now
  ASSERT_TRUE(s.Undo());
  const int lead = s.Lead();
  ASSERT_TRUE(s.PickAt(q.m.vert[size_t(lead)].P()).ok) << s.Message();
  EXPECT_EQ(s.Lead(), lead);
}

TEST(EditSession, UndoRestoresTheMeshBitIdentically) {
  for (int n : {1, 3, 150}) {
    QuadMesh q;
    MakeQuadruple(q, 5, false);
    EditSession<TMesh> s(q.m);
    ASSERT_TRUE(s.PickVertex(q.pair7).ok);
    const int l0 = s.Lead(), p0 = s.Partner();
    const test::MeshSnapshot start = test::Snapshot(q.m);
    std::mt19937 rng(7 + unsigned(n));
    std::vector<test::MeshSnapshot> states{start};
    std::vector<std::pair<int, int>> pairs{{l0, p0}};
    int deleting = 0;
    for (int i = 0; i < n; ++i) {
      std::vector<int> ok;
      for (auto& d : s.Directions())
        if (d.accepted) ok.push_back(d.k);
      ASSERT_FALSE(ok.empty()) << "step " << i;
      const int vn0 = q.m.vn, fn0 = q.m.fn;
      ASSERT_TRUE(s.Step(ok[rng() % ok.size()]).ok) << s.Message();
      ASSERT_TRUE(Compact(q.m)) << "step " << i;
      deleting += q.m.vn < vn0 || q.m.fn < fn0;
      if (n <= 3) states.push_back(test::Snapshot(q.m));
      pairs.push_back({s.Lead(), s.Partner()});
    }
    if (n == 150) EXPECT_GT(deleting, 0) << "no step deleted elements: the compaction went untested";
    EXPECT_EQ(s.UndoDepth(), n);
    Result inv = CheckInvariants(q.m);
    ASSERT_TRUE(inv.ok) << inv.reason;
    for (int i = n; i-- > 0;) {
      ASSERT_TRUE(s.Undo()) << i;
      ASSERT_TRUE(Compact(q.m)) << "undo " << i;
      if (n <= 3) EXPECT_TRUE(test::Snapshot(q.m) == states[size_t(i)]) << "after undoing step " << i + 1;
      EXPECT_EQ(s.Lead(), pairs[size_t(i)].first);
      EXPECT_EQ(s.Partner(), pairs[size_t(i)].second);
    }
    EXPECT_TRUE(test::Snapshot(q.m) == start) << n << " steps undone";
    EXPECT_EQ(s.Lead(), l0);
    EXPECT_EQ(s.Partner(), p0);
    EXPECT_FALSE(s.Undo());
    EXPECT_EQ(s.Message(), "nothing to undo");
    EXPECT_TRUE(test::Snapshot(q.m) == start);
    // redo replays the undone steps exactly
    if (n <= 3) {
      EXPECT_EQ(s.RedoDepth(), n);
      for (int i = 1; i <= n; ++i) {
        ASSERT_TRUE(s.Redo()) << s.Message();
        ASSERT_TRUE(Compact(q.m));
        EXPECT_TRUE(test::Snapshot(q.m) == states[size_t(i)]) << "after redoing step " << i;
        EXPECT_EQ(s.Lead(), pairs[size_t(i)].first);
      }
      EXPECT_FALSE(s.Redo());
      ASSERT_TRUE(s.Undo());
      ASSERT_TRUE(s.PickVertex(s.Partner()).ok);  // a new pick forgets what could be redone
      EXPECT_FALSE(s.Redo());
    }
  }
}

TEST(EditSession, UndoBeyondTheDepthIsRefusedCleanly) {
  QuadMesh q;
  MakeQuadruple(q, 5, false);
  EditSessionOptions opt;
  opt.undoDepth = 4;
  EditSession<TMesh> s(q.m, opt);
  ASSERT_TRUE(s.PickVertex(q.pair5).ok);
  std::vector<test::MeshSnapshot> states{test::Snapshot(q.m)};
  for (int i = 0; i < 7; ++i) {
    int k = -1;
    for (auto& d : s.Directions())
      if (d.accepted && k < 0 && d.k == (i % 2 ? 1 : 0)) k = d.k;
    ASSERT_GE(k, 0);
    ASSERT_TRUE(s.Step(k).ok) << s.Message();
    states.push_back(test::Snapshot(q.m));
  }
  EXPECT_EQ(s.UndoDepth(), 4);
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(s.Undo());
  EXPECT_TRUE(test::Snapshot(q.m) == states[3]);  // the three oldest steps were committed
  const int lead = s.Lead(), partner = s.Partner();
  EXPECT_FALSE(s.Undo());
  EXPECT_EQ(s.Message(), "nothing to undo");
  EXPECT_TRUE(test::Snapshot(q.m) == states[3]);
  EXPECT_EQ(s.Lead(), lead);
  EXPECT_EQ(s.Partner(), partner);
  EXPECT_TRUE(CheckInvariants(q.m).ok);
}

TEST(EditSession, RefusedStepsChangeNothingAndSayWhy) {
  QuadMesh q;
  MakeQuadruple(q, 3, true);
  EditSession<TMesh> s(q.m);
  EXPECT_FALSE(s.Step(0).ok);  // no pair
  EXPECT_NE(s.Message().find("no pair is picked"), std::string::npos) << s.Message();
  ASSERT_TRUE(s.PickVertex(q.pair5).ok);
  const test::MeshSnapshot before = test::Snapshot(q.m);
  EXPECT_FALSE(s.Step(6).ok);
  EXPECT_EQ(s.Message(), "direction 7 does not exist: the directions are 1 to 6");
  // march the pair into the hexagon's boundary until a direction is refused there
  int refused = -1;
  for (int i = 0; i < 30 && refused < 0; ++i) {
    auto dirs = s.Directions();
    for (auto& d : dirs)
      if (!d.accepted && refused < 0) refused = d.k;
    if (refused >= 0) break;
    ASSERT_TRUE(s.Step(0).ok) << s.Message();
  }
  ASSERT_GE(refused, 0) << "no direction was ever refused";
  const test::MeshSnapshot mid = test::Snapshot(q.m);
  const int depth = s.UndoDepth(), lead = s.Lead(), partner = s.Partner();
  const std::string why = s.Directions()[size_t(refused)].reason;
  EXPECT_FALSE(why.empty());
  EXPECT_FALSE(s.Step(refused).ok);
  EXPECT_NE(s.Message().find(why), std::string::npos) << s.Message() << " / " << why;
  EXPECT_TRUE(test::Snapshot(q.m) == mid);
  EXPECT_EQ(s.UndoDepth(), depth);
  EXPECT_EQ(s.Lead(), lead);
  EXPECT_EQ(s.Partner(), partner);
  while (s.Undo()) {
  }
  EXPECT_TRUE(test::Snapshot(q.m) == before);
}

/// Random states: random pairs (adjacent 5-7, non-adjacent 5-5, 5-7, 7-7) after random steps;
/// every arrow's verdict is the step's, the step ends where the arrow ends, and undo restores.
TEST(EditSession, ArrowsAgreeWithStepsOnRandomStates) {
  std::mt19937 rng(2024);
  int checked = 0, accepted = 0, refused = 0;
  for (int round = 0; round < 8; ++round) {
    QuadMesh q;
    MakeQuadruple(q, 2 + round % 3, round % 2 == 0);
    EditSession<TMesh> s(q.m);
    const int all[4] = {q.pair5, q.pair7, q.other5, q.other7};
    const int lead = all[rng() % 4];
    int partner = all[rng() % 4];
    while (partner == lead) partner = all[rng() % 4];
    ASSERT_TRUE(s.PickVertex(lead).ok);
    ASSERT_TRUE(s.PickPartner(partner).ok);
    for (int walk = 0; walk < 3; ++walk) {
      auto dirs = s.Directions();
      std::vector<int> ok;
      for (auto& d : dirs) {
        const test::MeshSnapshot before = test::Snapshot(q.m);
        const int l = s.Lead(), p = s.Partner();
        Result r = s.Step(d.k);
        ++checked;
        EXPECT_EQ(d.accepted, r.ok) << "round " << round << " direction " << d.k << ": arrow says "
                                    << (d.accepted ? "ok" : d.reason) << ", step says " << s.Message();
        if (r.ok) {
          ++accepted;
          ok.push_back(d.k);
          EXPECT_EQ(s.Lead(), d.lead);
          EXPECT_EQ(s.Partner(), d.partner);
          EXPECT_TRUE(q.m.vert[size_t(s.Lead())].P() == d.to);
          Result inv = CheckInvariants(q.m);
          EXPECT_TRUE(inv.ok) << inv.reason;
          ASSERT_TRUE(s.Undo());
        } else {
          ++refused;
          EXPECT_FALSE(s.Message().empty());
        }
        EXPECT_TRUE(test::Snapshot(q.m) == before) << "round " << round << " direction " << d.k;
        EXPECT_EQ(s.Lead(), l);
        EXPECT_EQ(s.Partner(), p);
      }
      if (ok.empty()) break;
      ASSERT_TRUE(s.Step(ok[rng() % ok.size()]).ok);
    }
  }
  std::printf("arrows vs steps: %d checked, %d accepted, %d refused\n", checked, accepted, refused);
  EXPECT_GT(accepted, 50);
  EXPECT_GT(refused, 0);
}

TEST(EditSession, CancelsAQuadrupleThroughTheSession) {
  QuadMesh q;
  MakeQuadruple(q, 2, false);
  const test::MeshSnapshot before = test::Snapshot(q.m);
  EditSession<TMesh> s(q.m);
  ASSERT_TRUE(s.PickVertex(q.pair5).ok);
  EXPECT_FALSE(s.CancelTriple().ok);  // no v5 or v7 would make a triple: refused, unchanged
  EXPECT_TRUE(test::Snapshot(q.m) == before);
  ASSERT_TRUE(s.CancelQuadruple().ok) << s.Message();
  EXPECT_TRUE(Compact(q.m));
  EXPECT_TRUE(test::IrregularVertices(q.m).empty());
  EXPECT_FALSE(s.HasPair());
  EXPECT_TRUE(CheckInvariants(q.m).ok);
  ASSERT_TRUE(s.Undo());
  EXPECT_TRUE(Compact(q.m));
  EXPECT_TRUE(test::Snapshot(q.m) == before);
  EXPECT_EQ(s.Lead(), q.pair5);
}

TEST(EditSession, CancelsATripleThroughTheSession) {
  TMesh m;
  test::Icosphere(m, 3);
  int v5 = -1;
  for (size_t i = 0; i < m.vert.size() && v5 < 0; ++i)
    if (ValenceOf(m, int(i)) == 5) v5 = int(i);
  CompositeOutcome g;
  {
    SurfaceProjector original(m);
    MeshEditor<TMesh> ed(m);
    CompositeOperations<TMesh> co(ed, &original);
    g = co.GenerateTriple(v5, 0, 2);
    ASSERT_TRUE(g) << g.result.reason;
  }
  const std::set<int> irregularBefore = IrregularSet(m);
  ASSERT_EQ(irregularBefore.size(), 14u);
  const test::MeshSnapshot before = test::Snapshot(m);
  EditSession<TMesh> s(m);
  ASSERT_TRUE(s.PickVertex(g.pair5).ok);
  ASSERT_TRUE(s.PickPartner(g.pair7).ok);
  ASSERT_TRUE(s.CancelTriple().ok) << s.Message();
  EXPECT_TRUE(Compact(m));
  // 12 v5 again: the triple left one v5, the session's new lead
  std::vector<int> irr = test::IrregularVertices(m);
  EXPECT_EQ(irr.size(), 12u);
  for (int v : irr) EXPECT_EQ(ValenceOf(m, v), 5);
  EXPECT_EQ(ValenceOf(m, s.Lead()), 5);
  EXPECT_TRUE(CheckInvariants(m).ok);
  ASSERT_TRUE(s.Undo());
  EXPECT_TRUE(test::Snapshot(m) == before);
  EXPECT_EQ(s.Lead(), g.pair5);
  EXPECT_EQ(s.Partner(), g.pair7);
}

// MeshLab's CMeshO keeps adjacency and attributes as optional components (vector_ocf): the
// session's spare capacity (Reserve) and its undo must work there too.
TEST(EditSession, OptionalComponentsLikeCMeshO) {
  QuadMesh q;
  MakeQuadruple(q, 3, false);
  test::TOMesh m;
  test::CopyAsCMeshO(q.m, m);
  const std::vector<double> start = test::OcfSnapshot(m);
  EditSession<test::TOMesh> s(m);
  EXPECT_TRUE(test::OcfSnapshot(m) == start);  // reserving room changed nothing
  ASSERT_TRUE(s.PickAt(m.vert[size_t(q.pair5)].P()).ok) << s.Message();
  EXPECT_EQ(s.Lead(), q.pair5);
  EXPECT_EQ(s.Partner(), q.pair7);
  int steps = 0;
  for (int i = 0; i < 12; ++i) {
    for (auto& d : s.Directions())
      if (d.accepted) {
        ASSERT_TRUE(s.Step(d.k).ok) << s.Message();
        ++steps;
        break;
      }
  }
  EXPECT_EQ(steps, 12);
  EXPECT_TRUE(CheckInvariants(m).ok);
  while (s.Undo()) {
  }
  EXPECT_TRUE(test::OcfSnapshot(m) == start);
}

// The compaction on optional components (vector_ocf: VF / FF adjacency and wedge texture
// coordinates live beside the vectors, and truncating drops them): random steps, deleting ones
// among them, keep the mesh compact, and undoing all of them restores it bit for bit.
TEST(EditSession, OptionalComponentsDeletingStepsUndo) {
  QuadMesh q;
  MakeQuadruple(q, 5, false);
  test::TOMesh m;
  test::CopyAsCMeshO(q.m, m);
  const std::vector<double> start = test::OcfSnapshot(m);
  EditSession<test::TOMesh> s(m);
  ASSERT_TRUE(s.PickVertex(q.pair7).ok) << s.Message();
  std::mt19937 rng(11);
  int deleting = 0, steps = 0;
  for (int i = 0; i < 150; ++i) {
    std::vector<int> ok;
    for (auto& d : s.Directions())
      if (d.accepted) ok.push_back(d.k);
    if (ok.empty()) break;
    const int vn0 = m.vn, fn0 = m.fn;
    ASSERT_TRUE(s.Step(ok[rng() % ok.size()]).ok) << s.Message();
    ++steps;
    ASSERT_TRUE(m.vert.size() == size_t(m.vn) && m.face.size() == size_t(m.fn)) << "step " << i;
    deleting += m.vn < vn0 || m.fn < fn0;
  }
  std::printf("ocf: %d steps, %d of them deleted elements\n", steps, deleting);
  EXPECT_GT(steps, 100);
  EXPECT_GT(deleting, 0);
  Result inv = CheckInvariants(m);
  ASSERT_TRUE(inv.ok) << inv.reason;
  while (s.Undo()) ASSERT_TRUE(m.vert.size() == size_t(m.vn) && m.face.size() == size_t(m.fn));
  EXPECT_TRUE(test::OcfSnapshot(m) == start);
}

// A step that deletes elements (a collapse inside the move) leaves the mesh compact (MeshLab's
// renderer needs it): the last vertices and faces move into the holes, journaled, so the pair
// is where the dry run said, the invariants hold, and undo restores the mesh bit for bit
// (the vectors grow back). Random steps from a quadruple until one deletes elements.
TEST(EditSession, DeletingStepKeepsTheMeshCompactAndUndoable) {
  QuadMesh q;
  MakeQuadruple(q, 5, false);
  ASSERT_TRUE(Compact(q.m));
  EditSession<TMesh> s(q.m);
  ASSERT_TRUE(s.PickVertex(q.pair7).ok);
  std::mt19937 rng(11);
  int deleting = 0;
  for (int i = 0; i < 400 && deleting < 3; ++i) {
    std::vector<EditDirection<P3>> ok;
    for (auto& d : s.Directions())
      if (d.accepted) ok.push_back(d);
    ASSERT_FALSE(ok.empty()) << "step " << i;
    const EditDirection<P3> d = ok[rng() % ok.size()];
    const int vn0 = q.m.vn, fn0 = q.m.fn;
    const size_t vs0 = q.m.vert.size(), fs0 = q.m.face.size();
    const test::MeshSnapshot before = test::Snapshot(q.m);
    const int l0 = s.Lead(), p0 = s.Partner();
    ASSERT_TRUE(s.Step(d.k).ok) << s.Message();
    ASSERT_TRUE(Compact(q.m)) << "step " << i;
    Result inv = CheckInvariants(q.m);
    ASSERT_TRUE(inv.ok) << "step " << i << ": " << inv.reason;
    EXPECT_EQ(s.Lead(), d.lead) << "step " << i;
    EXPECT_EQ(s.Partner(), d.partner) << "step " << i;
    EXPECT_EQ(q.m.vert[size_t(s.Lead())].P(), d.to) << "step " << i;
    EXPECT_NE(ValenceOf(q.m, s.Lead()), 6);
    if (q.m.vn >= vn0 && q.m.fn >= fn0) continue;
    ++deleting;
    // the touched vertices cover the moved and the truncated slots
    std::vector<int> t = s.Touched();
    for (size_t v = q.m.vert.size(); v < vs0; ++v)
      EXPECT_TRUE(std::binary_search(t.begin(), t.end(), int(v))) << "truncated vertex " << v << " not touched";
    EXPECT_LE(q.m.face.size(), fs0);
    // undo grows the vectors back, bit for bit; redo gives the same compact mesh
    const test::MeshSnapshot after = test::Snapshot(q.m);
    ASSERT_TRUE(s.Undo());
    ASSERT_TRUE(Compact(q.m));
    EXPECT_TRUE(test::Snapshot(q.m) == before) << "undo of deleting step " << i;
    EXPECT_EQ(q.m.vert.size(), vs0);
    EXPECT_EQ(s.Lead(), l0);
    EXPECT_EQ(s.Partner(), p0);
    inv = CheckInvariants(q.m);
    ASSERT_TRUE(inv.ok) << inv.reason;
    ASSERT_TRUE(s.Redo()) << s.Message();
    ASSERT_TRUE(Compact(q.m));
    EXPECT_TRUE(test::Snapshot(q.m) == after) << "redo of deleting step " << i;
    // picking still finds the lead at its (possibly new) index
    ASSERT_TRUE(s.PickAt(q.m.vert[size_t(s.Lead())].P()).ok) << s.Message();
    ASSERT_TRUE(s.PickPartner(d.partner).ok) << s.Message();
  }
  EXPECT_GT(deleting, 0) << "no step deleted elements in 400 random steps";
}

// Step(k) on a known arrow applies the arrow's captured trial (EditJournal::Replay) instead of
// running the move again. Two sessions on two copies of the same mesh walk the same random
// steps, one through the arrows (replayed steps), one calling Step(k) on an unknown state
// (computed steps): after every step the meshes are bit-identical (positions, flags, every
// adjacency), the pair and Touched() agree; undoing everything restores the start. Far pairs
// (the sec. 7.1.1 pipeline) and adjacent ones, deleting steps among them, plain vertices and
// CMeshO's optional components.
template <class M, class Snap>
void ReplayedStepsEqualComputedSteps(M& a, M& b, int lead, int partner, unsigned seed, int steps, Snap snap,
                                     int* deleting) {
  const auto start = snap(a);
  ASSERT_TRUE(snap(b) == start);
  EditSession<M> sa(a), sb(b);
  ASSERT_TRUE(sa.PickVertex(lead).ok && sa.PickPartner(partner).ok) << sa.Message();
  ASSERT_TRUE(sb.PickVertex(lead).ok && sb.PickPartner(partner).ok) << sb.Message();
  std::mt19937 rng(seed);
  for (int i = 0; i < steps; ++i) {
    std::vector<int> ok;
    for (auto& d : sa.Directions())
      if (d.accepted) ok.push_back(d.k);
    ASSERT_TRUE(sa.DirectionsKnown());
    if (ok.empty()) break;
    const int k = ok[rng() % ok.size()];
    const int fn0 = a.fn;
    ASSERT_TRUE(sa.Step(k).ok) << sa.Message();
    ASSERT_TRUE(sb.Step(k).ok) << "step " << i << ": replayed but refused when computed: " << sb.Message();
    *deleting += a.fn < fn0;
    ASSERT_TRUE(snap(a) == snap(b)) << "step " << i << " direction " << k;
    EXPECT_EQ(sa.Lead(), sb.Lead());
    EXPECT_EQ(sa.Partner(), sb.Partner());
    EXPECT_EQ(sa.Touched(), sb.Touched());
    EXPECT_EQ(sa.Message(), sb.Message());
    Result inv = CheckInvariants(a);
    ASSERT_TRUE(inv.ok) << "step " << i << ": " << inv.reason;
  }
  // refused arrows answer from their trial, with the computed step's reason
  for (auto& d : sa.Directions())
    if (!d.accepted) {
      EXPECT_FALSE(sa.Step(d.k).ok);
      EXPECT_FALSE(sb.Step(d.k).ok);
      EXPECT_EQ(sa.Message(), sb.Message());
    }
  while (sa.Undo()) {
  }
  EXPECT_TRUE(snap(a) == start);
}

TEST(EditSession, ReplayedStepsEqualComputedSteps) {
  int deleting = 0, cases = 0;
  for (int round = 0; round < 4; ++round) {
    QuadMesh qa, qb;
    MakeQuadruple(qa, 3 + round % 2, false);
    MakeQuadruple(qb, 3 + round % 2, false);
    // rounds 0, 1: the adjacent 5-7 pair; 2: a 5-7 pair several edges apart; 3: a 5-5 pair
    const int partner = round < 2 ? qa.pair7 : round == 2 ? qa.other7 : qa.other5;
    ReplayedStepsEqualComputedSteps(qa.m, qb.m, qa.pair5, partner, 31u + unsigned(round), 15,
                                    [](TMesh& m) { return test::Snapshot(m); }, &deleting);
    ++cases;
    test::TOMesh oa, ob;
    test::CopyAsCMeshO(qa.m, oa);
    test::CopyAsCMeshO(qa.m, ob);  // (qa is back at its start; qb is where the walk left it)
    ReplayedStepsEqualComputedSteps(oa, ob, qa.pair7, round < 2 ? qa.pair5 : qa.other5, 77u + unsigned(round), 15,
                                    [](test::TOMesh& m) { return test::OcfSnapshot(m); }, &deleting);
    ++cases;
  }
  std::printf("replayed = computed: %d walks, %d deleting steps\n", cases, deleting);
  EXPECT_GT(deleting, 0);
}

// A captured edit applied to a mesh that is not the one it was captured on (other sizes) is
// refused and changes nothing.
TEST(EditJournal, ReplayRefusesAnotherState) {
  QuadMesh q;
  MakeQuadruple(q, 3, false);
  MeshEditor<TMesh> ed(q.m);
  auto cp = ed.Mark();
  AtomicOperations<TMesh> ops(ed);
  ASSERT_TRUE(ops.MovePair57(q.pair5, q.pair7, 0));
  auto replay = ed.journal().CaptureSince(cp);
  const test::MeshSnapshot moved = test::Snapshot(q.m);
  ed.RollbackTo(cp);
  const test::MeshSnapshot start = test::Snapshot(q.m);
  // applied to the state it came from: the same result, and undone by a rollback
  auto cp2 = ed.Mark();
  ASSERT_TRUE(ed.journal().Apply(replay));
  EXPECT_TRUE(test::Snapshot(q.m) == moved);
  ed.RollbackTo(cp2);
  EXPECT_TRUE(test::Snapshot(q.m) == start);
  // another state (one more vertex): refused, nothing changed
  vcg::tri::Allocator<TMesh>::AddVertices(q.m, 1);
  const test::MeshSnapshot other = test::Snapshot(q.m);
  EXPECT_FALSE(ed.journal().Apply(replay));
  EXPECT_TRUE(test::Snapshot(q.m) == other);
}

// The GUI computes the arrows one trial at a time over idle frames (DirectionKnown tells it
// which are missing); a key pressed before its arrow is known runs the move itself, with the
// same result as through the arrow.
TEST(EditSession, DirectionsAreKnownOneAtATime) {
  QuadMesh q;
  MakeQuadruple(q, 4, false);
  EditSession<TMesh> s(q.m);
  for (int k = 0; k < 6; ++k) EXPECT_FALSE(s.DirectionKnown(k));  // no pair yet
  ASSERT_TRUE(s.PickVertex(q.pair5).ok && s.PickPartner(q.other7).ok) << s.Message();
  for (int k = 0; k < 6; ++k) EXPECT_FALSE(s.DirectionKnown(k));
  s.Direction(2);
  EXPECT_TRUE(s.DirectionKnown(2));
  EXPECT_FALSE(s.DirectionKnown(1));
  EXPECT_FALSE(s.DirectionsKnown());
  EXPECT_FALSE(s.DirectionKnown(6));
  for (int k = 0; k < 6; ++k) s.Direction(k);
  EXPECT_TRUE(s.DirectionsKnown());
  int accepted = -1;
  for (auto& d : s.Directions())
    if (d.accepted) accepted = d.k;
  ASSERT_GE(accepted, 0);
  ASSERT_TRUE(s.Step(accepted).ok) << s.Message();
  for (int k = 0; k < 6; ++k) EXPECT_FALSE(s.DirectionKnown(k)) << "the arrows of the old state are forgotten";
}
