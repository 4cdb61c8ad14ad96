// Unit tests of vcg_ext/irregular/leftover_reasons.h: why each irregular vertex stays, on
// constructed meshes (exact reasons per vertex) and on a reduced corpus mesh (counts).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <map>
#include <vector>

#include <vcg/complex/algorithms/stat.h>

#include <vcg_ext/irregular/automatic_reduction.h>
#include <vcg_ext/irregular/composite_ops.h>
#include <vcg_ext/irregular/leftover_reasons.h>
#include <vcg_ext/irregular/mesh_checks.h>
#include <vcg_ext/irregular/remeshing.h>

#include <wrap/io_trimesh/export_off.h>

#include "test_mesh.h"
#include "test_util.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {
/// Adds a 5-5-7-7 quadruple at vertex v whose pairs are `spacing` steps apart (no
/// relaxation: positions stay on the constructed surface). Returns {a5, a7, b5, b7}.
std::vector<int> AddQuadruple(TMesh& m, int v, int spacing) {
  MeshEditor<TMesh> ed(m);
  CompositeOptions opt;
  opt.relax = false;
  CompositeOperations<TMesh> co(ed, nullptr, opt);
  CompositeOutcome q = co.GenerateQuadruple(v, 0, spacing);
  EXPECT_TRUE(q) << q.result.reason;
  ed.Commit();
  if (!q) return {};
  std::vector<int> r = q.irregular;  // {a5, a7, b5, b7}
  return r;
}

std::map<int, LeftoverReason> Reasons(const LeftoverReport& r) {
  std::map<int, LeftoverReason> out;
  for (auto& v : r.vertices) out[v.vertex] = v.reason;
  return out;
}

void ExpectCountsAddUp(const LeftoverReport& r) {
  int sum = 0;
  for (int k = 0; k < kLeftoverReasons; ++k) sum += r.counts[k];
  EXPECT_EQ(sum, r.total);
  EXPECT_EQ(r.total, int(r.vertices.size()));
  EXPECT_EQ(r.boundary + r.protectedCount + r.caps + r.saddles + r.thin + r.noPartner + r.budget + r.noRoute + r.untried,
            r.total);
}
}  // namespace

// The twelve v5 of an icosphere are caps: the angle defect of their 3-ring (about 37 of 642
// vertices, 4 pi in all) is above half of pi / 3.
TEST(LeftoverReasons, TheTwelveV5OfASphereAreCaps) {
  TMesh m;
  test::Icosphere(m, 3);
  LeftoverReport r = ExplainLeftovers(m);
  EXPECT_EQ(r.total, 12);
  EXPECT_EQ(r.caps, 12) << r.Summary();
  ExpectCountsAddUp(r);
  for (auto& v : r.vertices) {
    EXPECT_EQ(v.valence, 5);
    EXPECT_GT(v.curvature, M_PI / 6);
    EXPECT_TRUE(v.Has(LeftoverReason::NoPartner));  // a v5 needs a v7 or a pair: none here
    EXPECT_FALSE(v.Has(LeftoverReason::Thin));
  }
}

// On a torus (radii 3 and 1) a quadruple on the inner equator: its two v7 are saddles; its two
// v5 sit on negative curvature (no cap) and have a partner (the other pair, 3 steps away):
// the one around which the driver reports undone edits is "budget", the other "untried", or
// "no route" once the driver reports that its strategies were tried there.
// A quadruple across the top circle: a v7 is a saddle only on negative curvature, the rest
// untried; with a travel bound of 2 edges (its pairs are 3 steps apart), "no partner" unless
// curvature explains it.
TEST(LeftoverReasons, SaddlesBudgetUntriedAndNoPartnerOnATorus) {
  TMesh m;
  test::RegularTorus(m, 72, 24, 3.f, 1.f);
  const std::vector<int> inner = AddQuadruple(m, 10 * 24 + 12, 3);  // j = 12: the inner equator
  const std::vector<int> top = AddQuadruple(m, 46 * 24 + 6, 3);     // j = 6: the top circle
  ASSERT_EQ(inner.size(), 4u);
  ASSERT_EQ(top.size(), 4u);
  ASSERT_EQ(test::IrregularVertices(m).size(), 8u);
  std::vector<int> undone(m.vert.size(), 0);
  undone[size_t(inner[0])] = 2;
  LeftoverOptions opt;
  opt.undone = &undone;
  LeftoverReport r = ExplainLeftovers(m, opt);
  ExpectCountsAddUp(r);
  std::map<int, LeftoverReason> why = Reasons(r);
  EXPECT_EQ(why[inner[1]], LeftoverReason::Saddle);
  EXPECT_EQ(why[inner[3]], LeftoverReason::Saddle);
  EXPECT_EQ(why[inner[0]], LeftoverReason::Budget);
  EXPECT_EQ(why[inner[2]], LeftoverReason::Untried);
  // the top quadruple spans the circles j = 5 (positive curvature) and j = 9 (negative): only
  // its v7 at j = 9 is a saddle; its v5 at j = 9 and its v7 at j = 5 sit on curvature of the
  // other sign than their valence's, so neither is forced there
  int topSaddles = 0;
  for (auto& v : r.vertices) {
    if (std::find(top.begin(), top.end(), v.vertex) == top.end()) continue;
    const int j = v.vertex % 24;
    ASSERT_TRUE(j == 5 || j == 9) << j;
    const bool saddle = v.valence == 7 && j == 9;
    EXPECT_EQ(v.reason, saddle ? LeftoverReason::Saddle : LeftoverReason::Untried) << v.vertex;
    EXPECT_EQ(v.curvature > 0, j == 5);
    topSaddles += saddle;
  }
  EXPECT_EQ(topSaddles, 1);
  EXPECT_EQ(r.saddles, 3);
  EXPECT_EQ(r.budget, 1);
  EXPECT_EQ(r.untried, 4);
  EXPECT_EQ(r.noRoute, 0);  // nothing says the strategies were tried
  for (auto& v : r.vertices) {
    EXPECT_GE(v.partner, 0);
    EXPECT_LE(v.partnerDistance, 4);
  }
  // the driver reports that its strategies were tried from inner[2] and one top vertex (and
  // from a saddle, which stays a saddle): those two are "no route", the other three untried
  // ones stay "untried"
  const int topUntried = [&] {
    for (auto& v : r.vertices)
      if (v.reason == LeftoverReason::Untried && std::find(top.begin(), top.end(), v.vertex) != top.end())
        return v.vertex;
    return -1;
  }();
  ASSERT_GE(topUntried, 0);
  std::vector<char> tried(m.vert.size(), 0);
  tried[size_t(inner[2])] = tried[size_t(topUntried)] = tried[size_t(inner[1])] = 1;
  LeftoverOptions withTried = opt;
  withTried.tried = &tried;
  LeftoverReport rt = ExplainLeftovers(m, withTried);
  ExpectCountsAddUp(rt);
  std::map<int, LeftoverReason> whyTried = Reasons(rt);
  EXPECT_EQ(whyTried[inner[2]], LeftoverReason::NoRoute);
  EXPECT_EQ(whyTried[topUntried], LeftoverReason::NoRoute);
  EXPECT_EQ(whyTried[inner[1]], LeftoverReason::Saddle);
  EXPECT_EQ(whyTried[inner[0]], LeftoverReason::Budget);
  EXPECT_EQ(rt.noRoute, 2);
  EXPECT_EQ(rt.untried, 2);
  EXPECT_EQ(rt.saddles, 3);
  EXPECT_EQ(rt.budget, 1);
  EXPECT_NE(rt.Summary().find("2 no route"), std::string::npos) << rt.Summary();
  LeftoverOptions near = opt;
  near.reach = 2;
  LeftoverReport rn = ExplainLeftovers(m, near, top);
  ExpectCountsAddUp(rn);
  EXPECT_EQ(rn.total, 4);
  // with nothing within reach a vertex's share of the surface is the widest (6 rings): the
  // v5 on the positive side now collects enough curvature to be a cap
  EXPECT_EQ(rn.noPartner, 2) << rn.Summary();
  EXPECT_EQ(rn.saddles, 1);
  EXPECT_EQ(rn.caps, 1);
  for (auto& v : rn.vertices) {
    EXPECT_EQ(v.curvatureRings, 6);
    if (v.reason == LeftoverReason::Cap) EXPECT_EQ(v.vertex % 24, 5);
  }
}

// A thin torus (tube radius 0.3 with 8 edges around it: about 2 edge lengths across): every
// vertex of a quadruple on it is on a thin part, measured as about 2 edge lengths thick.
TEST(LeftoverReasons, ThinTube) {
  TMesh m;
  test::RegularTorus(m, 60, 8, 3.f, 0.3f);
  const std::vector<int> q = AddQuadruple(m, 30 * 8 + 2, 3);
  ASSERT_EQ(q.size(), 4u);
  LeftoverReport r = ExplainLeftovers(m);
  ExpectCountsAddUp(r);
  EXPECT_EQ(r.total, 4);
  EXPECT_EQ(r.onThinPart, 4) << r.Summary();
  for (auto& v : r.vertices) {
    EXPECT_TRUE(v.Has(LeftoverReason::Thin));
    EXPECT_GT(v.thickness, 1.0);
    EXPECT_LT(v.thickness, 3.0);
    EXPECT_TRUE(v.reason == LeftoverReason::Thin || v.reason == LeftoverReason::Cap || v.reason == LeftoverReason::Saddle)
        << LeftoverReasonName(v.reason);
  }
  // the thick torus of the previous test has no thin part
  TMesh t;
  test::RegularTorus(t, 72, 24, 3.f, 1.f);
  const std::vector<int> q2 = AddQuadruple(t, 30 * 24 + 6, 3);
  LeftoverReport rt = ExplainLeftovers(t);
  EXPECT_EQ(rt.onThinPart, 0) << rt.Summary();
}

// Irregular vertices on or next to the boundary of a planar patch are "boundary"; frozen ones
// (and their neighbours) "protected".
TEST(LeftoverReasons, BoundaryAndProtected) {
  TMesh m;
  test::HexPatch(m, 8);
  // the patch's vertex at axial (7, 0): next to the boundary
  int v = -1;
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (std::abs(m.vert[i].P()[0] - 7.f) < 1e-4f && std::abs(m.vert[i].P()[1]) < 1e-4f) v = int(i);
  ASSERT_GE(v, 0);
  MeshEditor<TMesh> ed(m);
  AtomicOperations<TMesh> ops(ed);
  AtomicOutcome g = ops.GenerateQuadruple(v, 0, false);
  ASSERT_TRUE(g) << g.result.reason;
  ed.Commit();
  LeftoverReport r = ExplainLeftovers(m);
  ExpectCountsAddUp(r);
  EXPECT_GE(r.boundary, 1) << r.Summary();
  for (auto& lv : r.vertices) {
    bool near = lv.boundary;
    for (auto* n : StarOf<TMesh>(&m.vert[size_t(lv.vertex)]).neighbors) near = near || StarOf<TMesh>(n).boundary;
    EXPECT_EQ(lv.reason == LeftoverReason::Boundary, near) << lv.vertex;
  }
  std::vector<char> frozen(m.vert.size(), 0);
  for (auto& lv : r.vertices) frozen[size_t(lv.vertex)] = 1;
  LeftoverOptions opt;
  opt.frozen = &frozen;
  LeftoverReport rp = ExplainLeftovers(m, opt);
  EXPECT_EQ(rp.protectedCount + rp.boundary, rp.total);
  EXPECT_EQ(rp.protectedCount, r.total - r.boundary);
}

namespace {
/// A corpus mesh remeshed to about n vertices and reduced; *input: the surface as loaded.
bool Reduced(TMesh& m, const char* name, int n, ReductionReport* rep) {
  if (!test::LoadCorpus(m, name)) return false;
  SurfaceProjector input(m);
  RemeshOptions ro;
  ro.targetEdgeLength = EdgeLengthForVertexCount(vcg::tri::Stat<TMesh>::ComputeMeshArea(m), n);
  RemeshIsotropic(m, ro);
  AutomaticReduction<TMesh> ar(m, input);
  *rep = ar.Run();
  return true;
}
}  // namespace

// bunny00 remeshed to about 3000 vertices and reduced: every leftover has one reason, the
// counts add up to the leftover count, and the v5 at the tip of the ear (the mesh's top-most
// vertex, or within 3 rings of it) is a cap.
TEST(LeftoverReasons, ReducedBunnyCountsAddUpAndTheEarTipIsACap) {
  TMesh m;
  ReductionReport rep;
  ASSERT_TRUE(Reduced(m, "bunny00.off", 3000, &rep)) << "corpus mesh missing (run scripts/setup.sh)";
  ASSERT_TRUE(rep) << rep.result.reason;
  LeftoverReport r = ExplainLeftovers(m);
  std::printf("bunny00 (3000 vertices) after the reduction: %s\n", r.Summary().c_str());
  ExpectCountsAddUp(r);
  EXPECT_EQ(r.total, int(test::IrregularVertices(m).size()));
  EXPECT_GT(r.caps, 0);
  EXPECT_GT(r.saddles, 0);
  int top = 0;
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (m.vert[i].P()[1] > m.vert[size_t(top)].P()[1]) top = int(i);
  const std::vector<int> tip = KRing(m, {top}, 3);
  int tipFives = 0;
  for (auto& v : r.vertices) {
    if (v.valence != 5 || !std::binary_search(tip.begin(), tip.end(), v.vertex)) continue;
    ++tipFives;
    EXPECT_EQ(v.reason, LeftoverReason::Cap) << v.vertex << ": " << LeftoverReasonName(v.reason);
    EXPECT_GT(v.curvature, M_PI / 6);
  }
  EXPECT_GE(tipFives, 1);
  // One analysis remembers which vertices are irregular and the charges of their clusters
  // from vertex to vertex: each answer is the one a fresh analysis gives for that vertex alone.
  LeftoverAnalysis<TMesh> shared(m, LeftoverOptions());
  int withPartner = 0;
  for (auto& v : r.vertices) {
    const LeftoverVertex a = shared.ExplainVertex(v.vertex);
    const LeftoverVertex b = LeftoverAnalysis<TMesh>(m, LeftoverOptions()).ExplainVertex(v.vertex);
    EXPECT_EQ(a.partner, b.partner) << v.vertex;
    EXPECT_EQ(a.partnerDistance, b.partnerDistance) << v.vertex;
    EXPECT_EQ(a.nearestIrregular, b.nearestIrregular) << v.vertex;
    EXPECT_EQ(a.flags, b.flags) << v.vertex;
    EXPECT_EQ(a.reason, v.reason) << v.vertex;
    withPartner += a.partner >= 0;
    // ShapeOf (the far meetings' filter): ExplainVertex's shape tests and partner, nothing else
    const LeftoverVertex sh = shared.ShapeOf(v.vertex);
    const unsigned shapeBits = (1u << int(LeftoverReason::Cap)) | (1u << int(LeftoverReason::Saddle)) |
                               (1u << int(LeftoverReason::Thin));
    EXPECT_EQ(sh.flags & ~shapeBits, 0u) << v.vertex;
    EXPECT_EQ(sh.flags, a.flags & shapeBits) << v.vertex;
    EXPECT_EQ(sh.partner, a.partner) << v.vertex;
    EXPECT_EQ(sh.partnerDistance, a.partnerDistance) << v.vertex;
    EXPECT_EQ(sh.curvature, a.curvature) << v.vertex;
    EXPECT_EQ(sh.curvatureRings, a.curvatureRings) << v.vertex;
    EXPECT_EQ(sh.thickness, a.thickness) << v.vertex;
  }
  EXPECT_GT(withPartner, 0);
  EXPECT_LT(withPartner, r.total);  // both answers occur
  // the plan for what is left: every meeting uses sites of the right kinds
  DislocationAnalysis<TMesh> da(m);
  MeetingPlan plan = da.Plan();
  std::printf("plan: %s\n", plan.Summary().c_str());
  for (auto& pm : plan.meetings) {
    EXPECT_EQ(pm.vertices.size(), pm.kind == MeetingKind::Quadruple ? 4u : 3u);
    EXPECT_LE(pm.distance, pm.kind == MeetingKind::LoneTriple ? 24 : 12);
  }
}

// Measurement (run by hand): FI_MEASURE_MODEL=knot1.off FI_MEASURE_VERTICES=19000
// [FI_MEASURE_REDUCED=/tmp/knot1_reduced.off: reuse that reduced mesh, or save it there]
// build/tests/unit_tests --gtest_also_run_disabled_tests --gtest_filter='*MeasureCorpus*'
TEST(LeftoverReasons, DISABLED_MeasureCorpus) {
  const char* model = std::getenv("FI_MEASURE_MODEL");
  const char* size = std::getenv("FI_MEASURE_VERTICES");
  const char* saved = std::getenv("FI_MEASURE_REDUCED");
  TMesh m;
  ReductionReport rep;
  int mask = 0;
  if (saved && vcg::tri::io::ImporterOFF<TMesh>::Open(m, saved, mask) == 0) {
    test::UpdateTopology(m);
    rep.result = Result::Ok();
    rep.irregularAfter = int(test::IrregularVertices(m).size());
  } else {
    ASSERT_TRUE(Reduced(m, model ? model : "knot1.off", size ? std::atoi(size) : 19000, &rep));
    ASSERT_TRUE(rep) << rep.result.reason;
    if (saved) vcg::tri::io::ExporterOFF<TMesh>::Save(m, saved);
  }
  const auto t0 = std::chrono::steady_clock::now();
  LeftoverReport r = ExplainLeftovers(m);
  const auto t1 = std::chrono::steady_clock::now();
  DislocationAnalysis<TMesh> da(m);
  MeetingPlan plan = da.Plan();
  const auto t2 = std::chrono::steady_clock::now();
  ExpectCountsAddUp(r);
  std::printf("%s, %d vertices: irregular %d -> %d in %.1f s\n  reasons (%.3f s): %s\n  plan (%.3f s): %s\n",
              model ? model : "knot1.off", m.vn, rep.irregularBefore, rep.irregularAfter, rep.seconds,
              std::chrono::duration<double>(t1 - t0).count(), r.Summary().c_str(),
              std::chrono::duration<double>(t2 - t1).count(), plan.Summary().c_str());
  if (!std::getenv("FI_MEASURE_APPLY")) return;
  // what the plan's meetings give when applied with the composite operations (no edit guard)
  SurfaceProjector self(m);
  const ShapeMeasures before = MeasureShape(m);
  MeshEditor<TMesh> ed(m);
  CompositeOperations<TMesh> co(ed, &self);
  int done = 0, refused = 0;
  for (const PlannedMeeting& pm : plan.meetings) {
    bool live = true;
    for (int v : pm.vertices) live = live && ed.IsLive(v) && ed.Valence(v) != 6;
    if (!live) continue;
    CompositeOutcome o = pm.kind == MeetingKind::Quadruple ? co.CancelQuadruple(pm.vertices) : co.CancelTriple(pm.vertices);
    (o ? done : refused)++;
    if (!o) std::printf("  refused: %s: %s\n", pm.Describe().c_str(), o.result.reason.c_str());
  }
  ed.Commit();
  EXPECT_TRUE(CheckInvariants(m).ok);
  const ShapeMeasures after = MeasureShape(m);
  std::printf("  applied %d meetings (%d refused): %zu irregular vertices left; smallest angle %.1f -> %.1f, "
              "under 30 degrees %.3f%% -> %.3f%%, Hausdorff to the reduced mesh %.3f%%\n",
              done, refused, test::IrregularVertices(m).size(), before.minAngleDeg, after.minAngleDeg,
              100 * before.shareBelow30, 100 * after.shareBelow30, HausdorffPercent(m, self));
}
