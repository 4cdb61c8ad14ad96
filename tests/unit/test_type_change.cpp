// Unit tests of vcg_ext/irregular/type_change.h (paper sec. 6.3, fig. 9): type splitting and
// aggregation on cone patches (a vk at the centre of k sectors of the regular lattice, every
// other interior vertex regular), asserting where the v7s (v5s) end up by vertex id, the
// valence of every touched vertex, that nothing else changed, and the invariants (eq. 2).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <vcg_ext/irregular/composite_ops.h>
#include <vcg_ext/irregular/mesh_checks.h>
#include <vcg_ext/irregular/type_change.h>

#include "test_mesh.h"
#include "test_util.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {

using test::BuildCone;
using test::ConePatch;

/// vertex -> valence of every live interior vertex that is irregular.
std::map<int, int> Irregular(TMesh& m) {
  std::map<int, int> r;
  auto vf = ComputeValences(m);
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD() && vf.referenced[i] && !vf.boundary[i] && vf.valence[i] != 6) r[int(i)] = vf.valence[i];
  return r;
}

/// Asserts that every vertex outside `touched` kept its valence and position, and that the
/// touched ones have the valences the outcome lists.
void ExpectOnlyTouched(TMesh& m, const std::vector<int>& valBefore, const std::vector<vcg::Point3f>& posBefore,
                       const TypeChangeOutcome& o, const std::set<int>& moved) {
  std::vector<int> val = test::Valences(m);
  for (size_t i = 0; i < valBefore.size(); ++i) {
    if (std::find(o.deleted.begin(), o.deleted.end(), int(i)) != o.deleted.end()) {
      EXPECT_TRUE(m.vert[i].IsD()) << "vertex " << i;
      continue;
    }
    if (o.valences.count(int(i))) EXPECT_EQ(val[i], o.valences.at(int(i))) << "touched vertex " << i;
    else EXPECT_EQ(val[i], valBefore[i]) << "untouched vertex " << i;
    if (!moved.count(int(i))) EXPECT_EQ(m.vert[i].P(), posBefore[i]) << "vertex " << i << " moved";
  }
  for (int c : o.created) {
    ASSERT_TRUE(o.valences.count(c));
    EXPECT_EQ(val[size_t(c)], o.valences.at(c));
  }
}

std::vector<vcg::Point3f> Positions(TMesh& m) {
  std::vector<vcg::Point3f> p;
  for (auto& v : m.vert) p.push_back(v.P());
  return p;
}

void ExpectValid(TMesh& m) {
  Result r = CheckInvariants(m);
  EXPECT_TRUE(r.ok) << r.reason;
  EXPECT_TRUE(test::AdjacencyEqualsRebuild(m));
}

/// Splits the centre of a cone of k sectors with the given request; checks the exact v7s /
/// v5s (lattice ids), the valences, that nothing else changed; returns the outcome.
TypeChangeOutcome SplitCentre(TMesh& m, TypeSplitRequest req, const std::vector<int>& expectProduced,
                              const std::map<int, int>& expectIrregular) {
  MeshEditor<TMesh> ed(m);
  TypeChange<TMesh> tc(ed);
  const std::vector<int> val = test::Valences(m);
  const std::vector<vcg::Point3f> pos = Positions(m);
  TypeChangeOutcome p = tc.PredictTypeSplit(req);
  EXPECT_EQ(test::Valences(m), val);  // the dry run edits nothing
  TypeChangeOutcome o = tc.TypeSplit(req);
  EXPECT_TRUE(o) << o.status.reason;
  if (!o) return o;
  EXPECT_EQ(o.produced, expectProduced);
  EXPECT_EQ(Irregular(m), expectIrregular);
  EXPECT_EQ(p.steps, o.steps);
  EXPECT_EQ(p.valences, o.valences);
  std::set<int> moved(o.created.begin(), o.created.end());
  moved.insert(req.vertex);  // splits move the split vertex; a collapse moves the survivor
  ExpectOnlyTouched(m, val, pos, o, moved);
  ExpectValid(m);
  return o;
}

}  // namespace

// ---------------------------------------------------------------- type splitting, vk

TEST(TypeChange, ConePatchHasOneIrregularVertex) {
  for (int k : {3, 4, 8, 9, 10, 12}) {
    TMesh m;
    ConePatch c = BuildCone(m, k);
    EXPECT_EQ(Irregular(m), (std::map<int, int>{{0, k}})) << "k = " << k;
    for (int s = 0; s < k; ++s) EXPECT_EQ(test::Valences(m)[size_t(c.Ring(s))], 6);
    ExpectValid(m);
  }
}

TEST(TypeChange, V8BecomesTwoV7AcrossTheNewEdge) {
  // r0 = 1 .. r7 = 8; the split along (r4, r0): the new vertex keeps r1..r3, both are v6,
  // r0 and r4 become v7 facing each other across the new edge.
  TMesh m;
  BuildCone(m, 8);
  const int n = int(m.vert.size());
  TypeSplitRequest req;
  req.vertex = 0;
  req.orientation = 0;
  TypeChangeOutcome o = SplitCentre(m, req, {1, 5}, {{1, 7}, {5, 7}});
  ASSERT_TRUE(o);
  EXPECT_EQ(o.created, (std::vector<int>{n}));
  EXPECT_EQ(o.resultVertex, 0);
  MeshEditor<TMesh> ed(m);
  EXPECT_EQ(ed.Valence(0), 6);
  EXPECT_EQ(ed.Valence(n), 6);
  int opp[2];
  ASSERT_TRUE(ed.Opposites(0, n, opp));
  EXPECT_EQ(std::set<int>(opp, opp + 2), (std::set<int>{1, 5}));
  // the new vertex holds the first cap r1, r2, r3
  for (int r : {2, 3, 4}) EXPECT_TRUE(ed.Adjacent(n, r) && !ed.Adjacent(0, r));
}

TEST(TypeChange, V8EveryOrientationGivesTheOppositePair) {
  for (int s = 0; s < 8; ++s) {
    TMesh m;
    ConePatch c = BuildCone(m, 8);
    TypeSplitRequest req;
    req.vertex = 0;
    req.orientation = s;
    std::vector<int> v7{c.Ring(s), c.Ring(s + 4)};
    std::sort(v7.begin(), v7.end());
    SplitCentre(m, req, v7, {{v7[0], 7}, {v7[1], 7}});
  }
}

TEST(TypeChange, V9OddV7AtTheVertexOrAtTheFirstCap) {
  {
    TMesh m;
    BuildCone(m, 9);
    TypeSplitRequest req;
    req.vertex = 0;
    req.orientation = 0;
    // v9 -> the vertex keeps r4..r0 (v7), r0 = 1 and r4 = 5 become v7
    SplitCentre(m, req, {0, 1, 5}, {{0, 7}, {1, 7}, {5, 7}});
  }
  {
    TMesh m;
    BuildCone(m, 9);
    const int n = int(m.vert.size());
    TypeSplitRequest req;
    req.vertex = 0;
    req.orientation = 0;
    req.oddV7AtFirstCap = true;
    // the first cap r1..r4 goes to the new vertex (v7); the vertex is a v6; r0 = 1, r5 = 6 are v7
    TypeChangeOutcome o = SplitCentre(m, req, {1, 6, n}, {{1, 7}, {6, 7}, {n, 7}});
    EXPECT_EQ(test::Valences(m)[0], 6);
  }
}

TEST(TypeChange, V10BecomesAChainWithFourV7OnItsSides) {
  // k = 10: split along (r4, r0), then the zip along (r5, r9): chain x1 - x2 - centre, the
  // v7s r0, r4, r5, r9 = 1, 5, 6, 10; caps r1..r3 and r6..r8 untouched.
  TMesh m;
  BuildCone(m, 10);
  const int n = int(m.vert.size());
  TypeSplitRequest req;
  req.vertex = 0;
  req.orientation = 0;
  TypeChangeOutcome o = SplitCentre(m, req, {1, 5, 6, 10}, {{1, 7}, {5, 7}, {6, 7}, {10, 7}});
  ASSERT_TRUE(o);
  EXPECT_EQ(o.created, (std::vector<int>{n, n + 1}));
  MeshEditor<TMesh> ed(m);
  EXPECT_TRUE(ed.Adjacent(n, n + 1));  // the chain
  EXPECT_TRUE(ed.Adjacent(n + 1, 0));
  EXPECT_FALSE(ed.Adjacent(n, 0));
  for (int v : {0, n, n + 1}) EXPECT_EQ(ed.Valence(v), 6);
}

TEST(TypeChange, V12BecomesSixV7InTwoRows) {
  // k = 12: splits (r4, r0), (r5, r11), (r6, r10): v7s r0, r4, r5, r6, r10, r11.
  TMesh m;
  BuildCone(m, 12);
  TypeSplitRequest req;
  req.vertex = 0;
  req.orientation = 0;
  TypeChangeOutcome o =
      SplitCentre(m, req, {1, 5, 6, 7, 11, 12}, {{1, 7}, {5, 7}, {6, 7}, {7, 7}, {11, 7}, {12, 7}});
  ASSERT_TRUE(o);
  EXPECT_EQ(o.steps.size(), 3u);
  // rows: r4 r5 r6 on one side and r0 r11 r10 on the other, each row a path
  MeshEditor<TMesh> ed(m);
  EXPECT_TRUE(ed.Adjacent(5, 6) && ed.Adjacent(6, 7));
  EXPECT_TRUE(ed.Adjacent(1, 12) && ed.Adjacent(12, 11));
}

TEST(TypeChange, OrientationRotatesTheChainByOneNeighbour) {
  for (int k : {10, 12}) {
    for (int s : {1, 5}) {
      TMesh m;
      ConePatch c = BuildCone(m, k);
      std::vector<int> v7;
      std::map<int, int> irr;
      // sides: r(s), r(s+4) ... r(s+4+p), r(s-p)
      v7 = {c.Ring(s), c.Ring(s + 4)};
      for (int p = 1; p <= (k - 8) / 2; ++p) v7.push_back(c.Ring(s + 4 + p)), v7.push_back(c.Ring(s - p));
      std::sort(v7.begin(), v7.end());
      for (int v : v7) irr[v] = 7;
      TypeSplitRequest req;
      req.vertex = 0;
      req.orientation = s;
      SplitCentre(m, req, v7, irr);
    }
  }
}

// ---------------------------------------------------------------- type splitting, v4 and v3

TEST(TypeChange, V4BecomesTwoV5BesideTheCollapsedNeighbour) {
  for (int s = 0; s < 4; ++s) {
    TMesh m;
    ConePatch c = BuildCone(m, 4);
    TypeSplitRequest req;
    req.vertex = 0;
    req.orientation = s;
    std::vector<int> v5{c.Ring(s - 1), c.Ring(s + 1)};
    std::sort(v5.begin(), v5.end());
    TypeChangeOutcome o = SplitCentre(m, req, v5, {{v5[0], 5}, {v5[1], 5}});
    ASSERT_TRUE(o);
    EXPECT_EQ(o.deleted, (std::vector<int>{c.Ring(s)}));
    EXPECT_EQ(test::Valences(m)[0], 6);
    EXPECT_TRUE(o.created.empty());
  }
}

TEST(TypeChange, V3BecomesThreeV5InATriangle) {
  TMesh m;
  ConePatch c = BuildCone(m, 3);
  TypeSplitRequest req;
  req.vertex = 0;
  req.orientation = 0;
  // r0 = 1 collapses into the centre: the centre, r1 = 2, r2 = 3 are the v5s
  TypeChangeOutcome o = SplitCentre(m, req, {0, 2, 3}, {{0, 5}, {2, 5}, {3, 5}});
  ASSERT_TRUE(o);
  EXPECT_EQ(o.deleted, (std::vector<int>{c.Ring(0)}));
  MeshEditor<TMesh> ed(m);
  EXPECT_TRUE(ed.Adjacent(0, 2) && ed.Adjacent(2, 3) && ed.Adjacent(0, 3));
}

// ---------------------------------------------------------------- refusals and absorbing

TEST(TypeChange, IrregularSideNeighbourBlocksAnOrientationAndIsNamed) {
  TMesh m;
  ConePatch c = BuildCone(m, 8);
  MeshEditor<TMesh> ed(m);
  // make r0 = 1 a v5 without touching the centre: flip the edge from r0 to its outer
  // neighbour (2, 0) of sector 0
  ASSERT_TRUE(ed.Flip(c.Ring(0), c.Id(0, 2, 0)).ok);
  ed.Commit();
  ASSERT_EQ(ed.Valence(1), 5);
  const auto snap = test::Snapshot(m);
  TypeChange<TMesh> tc(ed);
  TypeSplitRequest req;
  req.vertex = 0;
  req.orientation = 0;
  TypeChangeOutcome p = tc.PredictTypeSplit(req);
  TypeChangeOutcome o = tc.TypeSplit(req);
  EXPECT_FALSE(o);
  EXPECT_EQ(p.status.reason, o.status.reason);
  EXPECT_NE(o.status.reason.find("vertex 1 "), std::string::npos) << o.status.reason;
  EXPECT_NE(o.status.reason.find("valence 5"), std::string::npos) << o.status.reason;
  EXPECT_EQ(test::Snapshot(m), snap);
  // automatic orientation: the first one whose sides are regular (r1, r5 = 2, 6)
  const auto irrBefore = Irregular(m);
  req.orientation = -1;
  o = tc.TypeSplit(req);
  ASSERT_TRUE(o) << o.status.reason;
  EXPECT_EQ(o.orientation, 1);
  EXPECT_EQ(o.produced, (std::vector<int>{2, 6}));
  auto irr = Irregular(m);
  for (auto& kv : irrBefore)
    if (kv.first != 0) EXPECT_EQ(irr[kv.first], kv.second) << "irregular vertex " << kv.first << " changed";
  ExpectValid(m);
}

TEST(TypeChange, AbsorbLetsASideV5BecomeRegular) {
  TMesh m;
  ConePatch c = BuildCone(m, 8);
  MeshEditor<TMesh> ed(m);
  ASSERT_TRUE(ed.Flip(c.Ring(0), c.Id(0, 2, 0)).ok);
  ed.Commit();
  TypeChange<TMesh> tc(ed);
  TypeSplitRequest req;
  req.vertex = 0;
  req.orientation = 0;
  req.absorb = true;
  TypeChangeOutcome o = tc.TypeSplit(req);
  ASSERT_TRUE(o) << o.status.reason;
  EXPECT_EQ(o.absorbed, (std::vector<int>{1}));
  EXPECT_EQ(o.produced, (std::vector<int>{5}));
  EXPECT_EQ(ed.Valence(1), 6);
  ExpectValid(m);
}

TEST(TypeChange, RefusalsLeaveTheMeshUnchanged) {
  TMesh m;
  BuildCone(m, 8);
  MeshEditor<TMesh> ed(m);
  TypeChange<TMesh> tc(ed);
  const auto snap = test::Snapshot(m);
  TypeSplitRequest req;
  req.vertex = 1;  // a v6
  EXPECT_FALSE(tc.TypeSplit(req));
  req.vertex = 0;
  req.orientation = 8;  // no such neighbour
  EXPECT_FALSE(tc.TypeSplit(req));
  req.orientation = -1;
  req.vertex = int(m.vert.size()) - 1;  // on the boundary
  TypeChangeOutcome o = tc.TypeSplit(req);
  EXPECT_FALSE(o);
  EXPECT_NE(o.status.reason.find("boundary"), std::string::npos);
  EXPECT_EQ(test::Snapshot(m), snap);
}

// ---------------------------------------------------------------- aggregation

namespace {
/// Faces as sorted vertex triples with `rename` applied (a vertex a round trip recreates under
/// a new index).
std::vector<std::array<int, 3>> Faces(TMesh& m, const std::map<int, int>& rename = {}) {
  std::vector<std::array<int, 3>> f = test::CanonicalFaces(m);
  for (auto& t : f) {
    for (int& v : t)
      if (rename.count(v)) v = rename.at(v);
    while (t[0] > t[1] || t[0] > t[2]) std::rotate(t.begin(), t.begin() + 1, t.end());
  }
  std::sort(f.begin(), f.end());
  return f;
}
}  // namespace

TEST(TypeChange, RoundTripSplitThenAggregateGivesBackTheVk) {
  for (int k : {8, 9, 10, 12}) {
    for (bool capFirst : {false, true}) {
      if (capFirst && k % 2 == 0) continue;
      TMesh m;
      BuildCone(m, k);
      const auto faces = Faces(m);
      const auto pos = Positions(m);
      MeshEditor<TMesh> ed(m);
      TypeChange<TMesh> tc(ed);
      TypeSplitRequest req;
      req.vertex = 0;
      req.orientation = 2;
      req.oddV7AtFirstCap = capFirst;
      TypeChangeOutcome s = tc.TypeSplit(req);
      ASSERT_TRUE(s) << s.status.reason;
      ASSERT_EQ(int(s.produced.size()), k - 6);
      AggregationRequest ag;
      ag.group = s.produced;
      ag.at = capFirst ? -1 : 0;
      TypeChangeOutcome p = tc.PredictAggregation(ag);
      TypeChangeOutcome a = tc.Aggregate(ag);
      ASSERT_TRUE(a) << "k = " << k << ": " << a.status.reason;
      EXPECT_EQ(p.steps, a.steps);
      EXPECT_EQ(p.valences, a.valences);
      EXPECT_EQ(Irregular(m).size(), 1u);
      EXPECT_EQ(test::Valences(m)[size_t(a.resultVertex)], k);
      if (!capFirst) {
        // the same vertex, the same faces: every split undone
        EXPECT_EQ(a.resultVertex, 0) << "k = " << k;
        EXPECT_EQ(Faces(m), faces) << "k = " << k;
      } else {
        // the first cap (a created vertex) is the aggregate's seed: the faces are those of the
        // cone with the centre renamed
        EXPECT_EQ(Faces(m, {{a.resultVertex, 0}}), faces) << "k = " << k;
      }
      for (size_t i = 1; i < pos.size(); ++i)
        if (!s.valences.count(int(i))) EXPECT_EQ(m.vert[i].P(), pos[i]);
      ExpectValid(m);
    }
  }
}

TEST(TypeChange, DefaultAggregateOfAnEvenChainIsTheOldestVertex) {
  TMesh m;
  BuildCone(m, 10);
  MeshEditor<TMesh> ed(m);
  TypeChange<TMesh> tc(ed);
  TypeSplitRequest req;
  req.vertex = 0;
  TypeChangeOutcome s = tc.TypeSplit(req);
  ASSERT_TRUE(s);
  AggregationRequest ag;
  ag.group = s.produced;
  TypeChangeOutcome a = tc.Aggregate(ag);
  ASSERT_TRUE(a) << a.status.reason;
  EXPECT_EQ(a.resultVertex, 0);
  EXPECT_EQ(test::Valences(m)[0], 10);
  EXPECT_EQ(Irregular(m), (std::map<int, int>{{0, 10}}));
  EXPECT_EQ(a.deleted.size(), 2u);  // the chain's two new vertices
}

TEST(TypeChange, V4AndV3RoundTrip) {
  for (int k : {3, 4}) {
    for (int s = 0; s < k; ++s) {
      TMesh m;
      ConePatch c = BuildCone(m, k);
      const auto faces = Faces(m);
      MeshEditor<TMesh> ed(m);
      TypeChange<TMesh> tc(ed);
      TypeSplitRequest req;
      req.vertex = 0;
      req.orientation = s;
      TypeChangeOutcome sp = tc.TypeSplit(req);
      ASSERT_TRUE(sp) << sp.status.reason;
      AggregationRequest ag;
      ag.group = sp.produced;
      ag.at = 0;
      TypeChangeOutcome a = tc.Aggregate(ag);
      ASSERT_TRUE(a) << "k = " << k << ": " << a.status.reason;
      EXPECT_EQ(a.resultVertex, 0);
      ASSERT_EQ(a.created.size(), 1u);
      EXPECT_EQ(Irregular(m), (std::map<int, int>{{0, k}}));
      // the collapsed neighbour r_s comes back as the created vertex
      EXPECT_EQ(Faces(m, {{a.created[0], c.Ring(s)}}), faces) << "k = " << k << " orientation " << s;
      ExpectValid(m);
    }
  }
}

namespace {
/// Builds a cone of k sectors and splits its centre in the given orientation, for good.
TypeChangeOutcome SplitCone(TMesh& m, int k, int orientation) {
  BuildCone(m, k);
  MeshEditor<TMesh> ed(m);
  TypeChange<TMesh> tc(ed);
  TypeSplitRequest req;
  req.vertex = 0;
  req.orientation = orientation;
  return tc.TypeSplit(req);
}
}  // namespace

TEST(TypeChange, AggregationRefusalsSayWhy) {
  TMesh m;
  ASSERT_TRUE(SplitCone(m, 12, 0));  // v7s 1, 5, 6, 7, 11, 12
  MeshEditor<TMesh> ed(m);
  TypeChange<TMesh> tc(ed);
  const auto snap = test::Snapshot(m);
  // two v7 of the same row are adjacent: not facing each other across an edge
  AggregationRequest ag;
  ag.group = {5, 6};
  TypeChangeOutcome a = tc.Aggregate(ag);
  EXPECT_FALSE(a);
  EXPECT_NE(a.status.reason.find("Move"), std::string::npos) << a.status.reason;
  EXPECT_EQ(tc.PredictAggregation(ag).status.reason, a.status.reason);
  // a v7 and a v6 (r2 = 3, in the first cap)
  ag.group = {5, 3};
  EXPECT_FALSE(tc.Aggregate(ag));
  // one vertex
  ag.group = {5};
  EXPECT_FALSE(tc.Aggregate(ag));
  EXPECT_EQ(test::Snapshot(m), snap);
  // a facing pair (r4 = 5 and r0 = 1, across the edge of the first cap's vertex) merges
  ag.group = {1, 5};
  a = tc.Aggregate(ag);
  ASSERT_TRUE(a) << a.status.reason;
  EXPECT_EQ(test::Valences(m)[size_t(a.resultVertex)], 8);
  ExpectValid(m);
}

TEST(TypeChange, AdjacentV5CannotBecomeAV4) {
  TMesh m;
  ASSERT_TRUE(SplitCone(m, 3, 0));  // v5s 0, 2, 3 in a triangle
  MeshEditor<TMesh> ed(m);
  TypeChange<TMesh> tc(ed);
  const auto snap = test::Snapshot(m);
  AggregationRequest ag;
  ag.group = {0, 2};
  TypeChangeOutcome a = tc.Aggregate(ag);
  EXPECT_FALSE(a);
  EXPECT_NE(a.status.reason.find("adjacent"), std::string::npos) << a.status.reason;
  EXPECT_EQ(test::Snapshot(m), snap);
  // the three together are a triangle: a v3
  ag.group = {0, 2, 3};
  a = tc.Aggregate(ag);
  ASSERT_TRUE(a) << a.status.reason;
  EXPECT_EQ(ed.Valence(a.resultVertex), 3);
  EXPECT_EQ(Irregular(m), (std::map<int, int>{{a.resultVertex, 3}}));
  ExpectValid(m);
}

TEST(TypeChange, CompositeReduceAndAggregateDelegate) {
  // CompositeOperations::ReduceTo57 / Aggregate (the filters' path) with relaxation.
  TMesh m;
  BuildCone(m, 10);
  SurfaceProjector original(m);
  MeshEditor<TMesh> ed(m);
  CompositeOperations<TMesh> co(ed, &original);
  CompositeOutcome r = co.ReduceTo57(0);
  ASSERT_TRUE(r) << r.result.reason;
  EXPECT_EQ(r.irregular, (std::vector<int>{1, 5, 6, 10}));  // orientation 0 is the first that works
  EXPECT_EQ(r.atomicSteps, 2);
  EXPECT_EQ(Irregular(m), (std::map<int, int>{{1, 7}, {5, 7}, {6, 7}, {10, 7}}));
  ExpectValid(m);
  CompositeOutcome a = co.Aggregate(r.irregular);
  ASSERT_TRUE(a) << a.result.reason;
  EXPECT_EQ(a.irregular, (std::vector<int>{0}));
  EXPECT_EQ(Irregular(m), (std::map<int, int>{{0, 10}}));
  ExpectValid(m);
}

// ---------------------------------------------------------------- dry run agreement

namespace {
enum { kRefused, kFolded, kDone };
/// The real outcome `o` agrees with the dry run `p`: both refused for the same reason, or only
/// the fold check (which the dry run does not predict) refused, or the same plan was done
/// (when the same orientation was taken) with the predicted valences.
int AgreeWithDryRun(TMesh& m, const test::MeshSnapshot& before, const TypeChangeOutcome& p, const TypeChangeOutcome& o) {
  if (!p || !o) {
    EXPECT_EQ(test::Snapshot(m), before);
    EXPECT_FALSE(o);
    if (!p) EXPECT_EQ(p.status.reason, o.status.reason);
    else EXPECT_NE(o.status.reason.find("fold"), std::string::npos) << o.status.reason;
    return p ? kFolded : kRefused;
  }
  if (p.orientation == o.orientation) {
    EXPECT_EQ(p.steps, o.steps);
    EXPECT_EQ(p.valences, o.valences);
    EXPECT_EQ(p.produced, o.produced);
    EXPECT_EQ(p.created, o.created);
    EXPECT_EQ(p.deleted, o.deleted);
    EXPECT_EQ(p.resultVertex, o.resultVertex);
  }
  MeshEditor<TMesh> ed(m);
  for (auto& kv : o.valences) EXPECT_EQ(ed.Valence(kv.first), kv.second);
  ExpectValid(m);
  return kDone;
}
}  // namespace

TEST(TypeChange, DryRunsAgreeWithTheOperationsOnRandomRequests) {
  std::mt19937 rng(1234);
  int splits = 0, refusedSplits = 0, aggregations = 0, refusedAggregations = 0, geometric = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const int ks[] = {3, 4, 8, 9, 10, 11, 12};
    const int k = ks[rng() % 7];
    TMesh m;
    ConePatch c = BuildCone(m, k, 7);
    MeshEditor<TMesh> ed(m);
    // a few random flips around the centre make irregular neighbours
    const int flips = int(rng() % 4);
    for (int f = 0; f < flips; ++f) {
      const int s = int(rng() % unsigned(k));
      const int x = c.Id(s, 1 + int(rng() % 2), int(rng() % 2));
      VertexStar<TMesh> st = ed.Star(x);
      if (st.boundary) continue;
      const int y = ed.Index(st.neighbors[rng() % st.neighbors.size()]);
      if (y == 0) continue;
      ed.Flip(x, y);
    }
    ed.Commit();
    TypeChange<TMesh> tc(ed);
    TypeSplitRequest req;
    req.vertex = 0;
    req.orientation = rng() % 3 == 0 ? -1 : int(rng() % unsigned(ed.Valence(0) + 1));
    req.oddV7AtFirstCap = rng() % 2;
    req.absorb = rng() % 3 == 0;
    // dry run, then the operation: counted into `done` or `refused`; true when done
    auto run = [&](const std::function<TypeChangeOutcome()>& predict, const std::function<TypeChangeOutcome()>& real,
                   int& done, int& refused, TypeChangeOutcome* out) {
      const auto snap = test::Snapshot(m);
      TypeChangeOutcome p = predict();
      EXPECT_EQ(test::Snapshot(m), snap);  // the dry run edits nothing
      *out = real();
      const int r = AgreeWithDryRun(m, snap, p, *out);
      ++(r == kDone ? done : r == kRefused ? refused : geometric);
      return r == kDone;
    };
    TypeChangeOutcome o, a;
    if (!run([&] { return tc.PredictTypeSplit(req); }, [&] { return tc.TypeSplit(req); }, splits, refusedSplits, &o))
      continue;
    // aggregate a random subset of two or more of the produced vertices
    std::vector<int> group = o.produced;
    std::shuffle(group.begin(), group.end(), rng);
    if (group.size() > 2) group.resize(2 + rng() % (group.size() - 1));
    AggregationRequest ag;
    ag.group = group;
    if (!run([&] { return tc.PredictAggregation(ag); }, [&] { return tc.Aggregate(ag); }, aggregations,
             refusedAggregations, &a))
      continue;
    const int d = ed.Valence(a.resultVertex);
    const bool v7s = o.valences.count(group[0]) && o.valences.at(group[0]) == 7;
    EXPECT_EQ(d, v7s ? 6 + int(group.size()) : 6 - int(group.size()));
  }
  std::printf("splits %d, refused %d; aggregations %d, refused %d; refused by the fold check %d\n", splits,
              refusedSplits, aggregations, refusedAggregations, geometric);
  EXPECT_GT(splits, 40);
  EXPECT_GT(aggregations, 10);
  EXPECT_GT(refusedSplits + refusedAggregations, 5);
}

// ---------------------------------------------------------------- absorbing configurations

TEST(TypeChange, FlipConfigurationOfAV8WithAV7Neighbour) {
  TMesh m;
  ConePatch c = BuildCone(m, 8);
  MeshEditor<TMesh> ed(m);
  // make r0 = 1 a v7: flip the outer edge ((2,0), (1,1)) of sector 0, whose opposites are r0
  // and (2,1)
  ASSERT_TRUE(ed.Flip(c.Id(0, 2, 0), c.Id(0, 1, 1)).ok);
  ed.Commit();
  ASSERT_EQ(ed.Valence(1), 7);
  TypeChange<TMesh> tc(ed);
  TypeSplitRequest req;
  req.vertex = 0;
  req.orientation = 0;
  req.configuration = TypeSplitRequest::kFlipV8;
  EXPECT_FALSE(tc.TypeSplit(req));  // it changes the v7 neighbour: needs absorb
  req.absorb = true;
  const std::vector<int> val = test::Valences(m);
  const std::vector<vcg::Point3f> pos = Positions(m);
  TypeChangeOutcome p = tc.PredictTypeSplit(req);
  TypeChangeOutcome o = tc.TypeSplit(req);
  ASSERT_TRUE(o) << o.status.reason;
  EXPECT_EQ(p.steps, o.steps);
  // the centre becomes a v7, r0 a v6, r1 = 2 and r7 = 8 v7s
  EXPECT_EQ(o.produced, (std::vector<int>{0, 2, 8}));
  EXPECT_EQ(o.absorbed, (std::vector<int>{1}));
  EXPECT_EQ(val[1], 7);
  EXPECT_EQ(test::Valences(m)[1], 6);
  EXPECT_FALSE(ed.Adjacent(0, 1));
  EXPECT_TRUE(ed.Adjacent(2, 8));
  ExpectOnlyTouched(m, val, pos, o, {});
  ExpectValid(m);
}

TEST(TypeChange, AbsorbMergesAnIrregularNeighbourIntoAV4) {
  TMesh m;
  ConePatch c = BuildCone(m, 4);
  MeshEditor<TMesh> ed(m);
  // r0 = 1 becomes a v7 (flip the outer edge of sector 0 as above)
  ASSERT_TRUE(ed.Flip(c.Id(0, 2, 0), c.Id(0, 1, 1)).ok);
  ed.Commit();
  ASSERT_EQ(ed.Valence(1), 7);
  TypeChange<TMesh> tc(ed);
  TypeSplitRequest req;
  req.vertex = 0;
  req.orientation = 0;
  TypeChangeOutcome strict = tc.TypeSplit(req);
  EXPECT_FALSE(strict);
  EXPECT_NE(strict.status.reason.find("vertex 1 "), std::string::npos) << strict.status.reason;
  req.absorb = true;
  TypeChangeOutcome o = tc.TypeSplit(req);
  ASSERT_TRUE(o) << o.status.reason;
  // 7 + 4 - 4: the merged vertex 0 is a v7; r1 = 2 and r3 = 4 are the v5s
  EXPECT_EQ(o.produced, (std::vector<int>{0, 2, 4}));
  EXPECT_EQ(o.absorbed, (std::vector<int>{1}));
  EXPECT_EQ(test::Valences(m)[0], 7);
  ExpectValid(m);
}

TEST(TypeChange, TorusV8BesideTwoV5KeepsThemAndRoundTrips) {
  // A closed surface (eq. 2 with chi = 0): collapsing a lattice edge of a regular torus makes
  // a v8 with two v5 neighbours (the collapse's opposite vertices). The split must take an
  // orientation whose sides avoid them, leave them as they are, and aggregate back.
  TMesh m;
  test::RegularTorus(m, 24, 24);
  MeshEditor<TMesh> ed(m);
  const int c = 12 * 24 + 12;
  const int x = ed.Index(ed.Star(c).neighbors[0]);
  int opp[2];
  ASSERT_TRUE(ed.Opposites(x, c, opp));
  ASSERT_TRUE(ed.Collapse(x, c).ok);
  ed.Commit();
  ASSERT_EQ(Irregular(m), (std::map<int, int>{{c, 8}, {opp[0], 5}, {opp[1], 5}}));
  const auto faces = test::CanonicalFaces(m);
  TypeChange<TMesh> tc(ed);
  TypeSplitRequest req;
  req.vertex = c;
  TypeChangeOutcome s = tc.TypeSplit(req);
  ASSERT_TRUE(s) << s.status.reason;
  ASSERT_EQ(s.produced.size(), 2u);
  std::map<int, int> expect{{opp[0], 5}, {opp[1], 5}, {s.produced[0], 7}, {s.produced[1], 7}};
  EXPECT_EQ(Irregular(m), expect);
  for (int v : s.produced) EXPECT_TRUE(v != opp[0] && v != opp[1]);
  ExpectValid(m);
  AggregationRequest ag;
  ag.group = s.produced;
  TypeChangeOutcome a = tc.Aggregate(ag);
  ASSERT_TRUE(a) << a.status.reason;
  EXPECT_EQ(a.resultVertex, c);
  EXPECT_EQ(test::CanonicalFaces(m), faces);
  ExpectValid(m);
}
