// Unit tests of every configuration of the paper's figs. 7 and 8 (atomic_ops.h), by direction,
// on constructed lattices whose vertices carry lattice coordinates: where every irregular
// vertex ends up, the valence of every touched vertex, nothing else changed, the invariants;
// and the agreement of every dry run (Predict...) with the real operation on random requests.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <tuple>

#include <vcg_ext/irregular/atomic_ops.h>
#include <vcg_ext/irregular/mesh_checks.h>

#include "test_mesh.h"
#include "test_util.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {

/// A cone of `d` 60-degree lattice wedges glued around vertex 0 (valence d; every other
/// interior vertex regular), flattened with the wedges' angles scaled to 360/d degrees.
/// Lattice coordinates: vertex (s, i, j) = i steps along ray s plus j along ray s+1, i >= 1,
/// j >= 0, i + j <= radius; coords[v] gives them (centre: (0, 0, 0)).
struct LatticeCone {
  TMesh m;
  int d = 6;
  std::map<std::tuple<int, int, int>, int> index;
  std::vector<std::tuple<int, int, int>> coords;

  int Id(int s, int i, int j) const {
    s = ((s % d) + d) % d;
    if (i == 0 && j == 0) return 0;
    if (i == 0) return Id(s + 1, j, 0);  // on ray s+1
    auto it = index.find(std::make_tuple(s, i, j));
    return it == index.end() ? -1 : it->second;
  }
  /// The centre's neighbour on ray s.
  int N(int s) const { return Id(s, 1, 0); }
};

void MakeCone(LatticeCone& c, int d, int radius) {
  c.d = d;
  TMesh& m = c.m;
  m.Clear();
  c.coords.push_back(std::make_tuple(0, 0, 0));
  for (int s = 0; s < d; ++s)
    for (int i = 1; i <= radius; ++i)
      for (int j = 0; i + j <= radius; ++j) {
        c.index[std::make_tuple(s, i, j)] = int(c.coords.size());
        c.coords.push_back(std::make_tuple(s, i, j));
      }
  vcg::tri::Allocator<TMesh>::AddVertices(m, c.coords.size());
  for (size_t v = 0; v < c.coords.size(); ++v) {
    int s, i, j;
    std::tie(s, i, j) = c.coords[v];
    const float a0 = 2 * float(M_PI) * s / d, a1 = 2 * float(M_PI) * (s + 1) / d;
    m.vert[v].P() = vcg::Point3f(i * std::cos(a0) + j * std::cos(a1), i * std::sin(a0) + j * std::sin(a1), 0.f);
  }
  auto face = [&](int a, int b, int e) {
    if (a >= 0 && b >= 0 && e >= 0) vcg::tri::Allocator<TMesh>::AddFace(m, &m.vert[size_t(a)], &m.vert[size_t(b)], &m.vert[size_t(e)]);
  };
  for (int s = 0; s < d; ++s)
    for (int i = 0; i < radius; ++i)
      for (int j = 0; i + j < radius; ++j) {
        face(c.Id(s, i, j), c.Id(s, i + 1, j), c.Id(s, i, j + 1));
        if (i + j + 2 <= radius) face(c.Id(s, i + 1, j), c.Id(s, i + 1, j + 1), c.Id(s, i, j + 1));
      }
  test::UpdateTopology(m);
}

/// Interior vertices whose valence is not 6 (the cone's rim is a boundary: not counted).
std::map<int, int> InteriorIrregular(TMesh& m) {
  auto vf = ComputeValences(m);
  std::map<int, int> r;
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD() && vf.referenced[i] && !vf.boundary[i] && vf.valence[i] != 6) r[int(i)] = vf.valence[i];
  return r;
}

/// The outcome changed exactly the valences it states (created vertices included) and moved
/// no vertex but those of its graph operations' ends (a collapse survivor, the split halves).
void ExpectOnlyStatedChanges(TMesh& m, const std::vector<int>& before, const std::vector<vcg::Point3f>& pos,
                             const AtomicOutcome& out) {
  auto after = test::Valences(m);
  std::set<int> mayMove;
  for (const GraphStep& s : out.steps)
    if (s.kind != GraphStep::kFlip) mayMove.insert(s.kind == GraphStep::kCollapse ? s.y : s.x);
  for (size_t i = 0; i < before.size(); ++i) {
    auto it = out.changes.find(int(i));
    if (it != out.changes.end()) {
      EXPECT_EQ(m.vert[i].IsD() ? 0 : after[i], it->second) << "vertex " << i;
    } else {
      EXPECT_EQ(after[i], before[i]) << "vertex " << i << " changed valence but is not in the outcome";
      if (!mayMove.count(int(i))) EXPECT_EQ(m.vert[i].P(), pos[i]) << "vertex " << i << " moved";
    }
  }
  for (size_t i = before.size(); i < after.size(); ++i) EXPECT_TRUE(out.changes.count(int(i))) << "new vertex " << i;
  Result inv = CheckInvariants(m);
  EXPECT_TRUE(inv.ok) << inv.reason;
}

std::vector<vcg::Point3f> Positions(TMesh& m) {
  std::vector<vcg::Point3f> p;
  for (auto& v : m.vert) p.push_back(v.P());
  return p;
}

}  // namespace

// Fig. 7 for a v5: the moved v5 goes to the neighbour in the sector (n0 at 0 degrees, n1 at
// 72, n2 at 144, n3 at 216, n4 at 288); sector 3 (180 degrees) holds no edge, so the v5 moves
// into the new vertex of a split between n2 and n3. Every via and side.
TEST(AtomicFig7, V5EverySectorEveryConfigurationLandsOnItsLatticeSite) {
  const int expectSite[6] = {0, 1, 2, -1, 3, 4};  // ray of the neighbour the v5 moves to
  int applied = 0;
  for (int k = 0; k < 6; ++k)
    for (AtomicVia via : {AtomicVia::Flip, AtomicVia::Collapse, AtomicVia::Split})
      for (PairSide side : {PairSide::Ccw, PairSide::Cw}) {
        LatticeCone c;
        MakeCone(c, 5, 6);
        MeshEditor<TMesh> ed(c.m);
        AtomicOperations<TMesh> ops(ed);
        const int p = 0, ref = c.N(0);
        const auto faces = test::CanonicalFaces(c.m);
        AtomicPrediction pr = ops.PredictVertexMove(p, k, ref, via, side);
        const bool wedge = expectSite[k] < 0;
        if (wedge && via != AtomicVia::Split) {
          EXPECT_FALSE(pr) << "sector " << k << ": only a split moves a v5 into a new vertex";
          continue;
        }
        ASSERT_TRUE(pr) << "sector " << k << " via " << int(via) << " side " << int(side) << ": " << pr.result.reason;
        EXPECT_EQ(pr.sector, k);
        EXPECT_EQ(pr.via, via);
        EXPECT_EQ(pr.side, side);
        const auto before = test::Valences(c.m);
        const auto pos = Positions(c.m);
        const int created = int(c.m.vert.size());
        AtomicOutcome o = ops.Apply(pr);
        ASSERT_TRUE(o) << o.result.reason;
        ++applied;
        ExpectOnlyStatedChanges(c.m, before, pos, o);
        // where the irregular vertices are, by lattice coordinates
        const int s = expectSite[k];
        int moved, p5, p7;
        if (!wedge) {
          const int a = side == PairSide::Ccw ? 1 : -1;
          moved = c.N(s);
          if (via == AtomicVia::Flip) p5 = c.N(s + a), p7 = a > 0 ? c.Id(s, 1, 1) : c.Id(s - 1, 1, 1);
          else if (via == AtomicVia::Collapse) p5 = c.N(s + 2 * a), p7 = p;
          else p5 = created, p7 = c.Id(s, 2, 0);
        } else {
          // between n2 and n3: split n2 (new vertex toward n3; pair (n2, q) clockwise) or
          // split n3 (new vertex toward n2; pair (n3, q) counter-clockwise)
          moved = created;
          p5 = side == PairSide::Cw ? c.N(2) : c.N(3);
          p7 = side == PairSide::Cw ? c.Id(2, 2, 0) : c.Id(3, 2, 0);
        }
        EXPECT_EQ(o.moved, moved) << o.description;
        EXPECT_EQ(o.pair5, p5) << o.description;
        EXPECT_EQ(o.pair7, p7) << o.description;
        std::map<int, int> want = {{moved, 5}, {p5, 5}, {p7, 7}};
        EXPECT_EQ(InteriorIrregular(c.m), want) << o.description;
        EXPECT_EQ(o.irregular, (std::vector<int>{moved, p5, p7}));
        EXPECT_TRUE(ed.Adjacent(p5, p7));
        // the inverse (fig. 7 read backwards, collapses replaced by splits) leaves one v5
        AtomicOutcome r = ops.MoveWithPairRemoval(o.irregular);
        ASSERT_TRUE(r) << o.description << ": " << r.result.reason;
        auto left = InteriorIrregular(c.m);
        ASSERT_EQ(left.size(), 1u) << o.description;
        EXPECT_EQ(left.begin()->second, 5);
        EXPECT_EQ(r.moved, left.begin()->first);
        if (via == AtomicVia::Flip) EXPECT_EQ(test::CanonicalFaces(c.m), faces) << "a flip is its own inverse";
        ASSERT_TRUE(CheckInvariants(c.m).ok);
      }
  EXPECT_EQ(applied, 5 * 6 + 2);
}

// Fig. 7 for a v7 (edges at multiples of 360/7 degrees): sector 3 is nearest to both n3 and
// n4 and takes n3 (ties go counter-clockwise first), so the v7 moves to n0, n1, n2, n3, n5, n6.
// No collapse moves a v7 (refused with the reason).
TEST(AtomicFig7, V7EverySectorEveryConfigurationLandsOnItsLatticeSite) {
  const int expectSite[6] = {0, 1, 2, 3, 5, 6};
  int applied = 0;
  for (int k = 0; k < 6; ++k)
    for (AtomicVia via : {AtomicVia::Flip, AtomicVia::Collapse, AtomicVia::Split})
      for (PairSide side : {PairSide::Ccw, PairSide::Cw}) {
        LatticeCone c;
        MakeCone(c, 7, 6);
        MeshEditor<TMesh> ed(c.m);
        AtomicOperations<TMesh> ops(ed);
        const int p = 0;
        AtomicPrediction pr = ops.PredictVertexMove(p, k, c.N(0), via, side);
        if (via == AtomicVia::Collapse) {
          EXPECT_FALSE(pr);
          EXPECT_NE(pr.result.reason.find("no edge collapse moves a v7"), std::string::npos) << pr.result.reason;
          continue;
        }
        ASSERT_TRUE(pr) << pr.result.reason;
        const auto before = test::Valences(c.m);
        const auto pos = Positions(c.m);
        const int created = int(c.m.vert.size());
        AtomicOutcome o = ops.Apply(pr);
        ASSERT_TRUE(o) << o.result.reason;
        ++applied;
        ExpectOnlyStatedChanges(c.m, before, pos, o);
        const int s = expectSite[k], a = side == PairSide::Ccw ? 1 : -1;
        int p5, p7;
        if (via == AtomicVia::Flip) p5 = c.N(s + a), p7 = c.N(s + 2 * a);
        else p5 = p, p7 = c.N(s + 3 * a);
        EXPECT_EQ(o.moved, c.N(s)) << o.description;
        EXPECT_EQ(o.pair5, p5) << o.description;
        EXPECT_EQ(o.pair7, p7) << o.description;
        EXPECT_EQ(InteriorIrregular(c.m), (std::map<int, int>{{c.N(s), 7}, {p5, 5}, {p7, 7}})) << o.description;
        if (via == AtomicVia::Split) EXPECT_EQ(o.created, std::vector<int>{created});
        AtomicOutcome r = ops.MoveWithPairRemoval(o.irregular);
        ASSERT_TRUE(r) << o.description << ": " << r.result.reason;
        auto left = InteriorIrregular(c.m);
        ASSERT_EQ(left.size(), 1u);
        EXPECT_EQ(left.begin()->second, 7);
        ASSERT_TRUE(CheckInvariants(c.m).ok);
      }
  EXPECT_EQ(applied, 6 * 4);
}

// Without a via or side, the first configuration that passes: a flip, pair counter-clockwise.
TEST(AtomicFig7, AnyPrefersTheFlipAndTheCounterClockwisePair) {
  LatticeCone c;
  MakeCone(c, 5, 5);
  MeshEditor<TMesh> ed(c.m);
  AtomicOperations<TMesh> ops(ed);
  AtomicPrediction pr = ops.PredictVertexMove(0, 1, c.N(0));
  ASSERT_TRUE(pr);
  EXPECT_EQ(pr.via, AtomicVia::Flip);
  EXPECT_EQ(pr.side, PairSide::Ccw);
  EXPECT_EQ(pr.moved, c.N(1));
  // toward a point: the sector of its direction
  EXPECT_EQ(ops.SectorToward(0, c.m.vert[size_t(c.N(2))].P(), c.N(0)), 2);
  // a reference that is not a neighbour is refused
  EXPECT_FALSE(ops.PredictVertexMove(0, 1, c.Id(0, 3, 0)));
}

// Fig. 8 in every sector and every variant on a flat lattice: the quadruple's exact sites, and
// the removal that makes the lattice regular again.
TEST(AtomicFig8, QuadrupleEverySectorEveryVariantAndItsRemoval) {
  typedef AtomicOperations<TMesh>::QuadrupleVia QV;
  for (int k = 0; k < 6; ++k)
    for (QV via : {QV::Flip, QV::Split, QV::CollapseSplit}) {
      LatticeCone c;
      MakeCone(c, 6, 6);
      MeshEditor<TMesh> ed(c.m);
      AtomicOperations<TMesh> ops(ed);
      const auto faces = test::CanonicalFaces(c.m);
      const int p = 0;
      AtomicPrediction pr = ops.PredictQuadrupleGenerationInSector(p, k, via, c.N(0));
      ASSERT_TRUE(pr) << pr.result.reason;
      EXPECT_EQ(pr.sector, k);
      const auto before = test::Valences(c.m);
      const auto pos = Positions(c.m);
      const int created = int(c.m.vert.size());
      AtomicOutcome o = ops.Apply(pr);
      ASSERT_TRUE(o) << o.result.reason;
      ExpectOnlyStatedChanges(c.m, before, pos, o);
      std::map<int, int> want;
      if (via == QV::Flip) want = {{p, 5}, {c.N(k), 5}, {c.N(k - 1), 7}, {c.N(k + 1), 7}};
      else if (via == QV::Split) want = {{p, 5}, {created, 5}, {c.N(k), 7}, {c.N(k + 3), 7}};
      else want = {{c.N(k - 1), 5}, {c.N(k + 1), 5}, {c.N(k + 3), 7}, {c.Id(k, 2, 0), 7}};
      EXPECT_EQ(InteriorIrregular(c.m), want) << o.description;
      EXPECT_EQ(o.fives.size(), 2u);
      EXPECT_EQ(o.sevens.size(), 2u);
      if (via == QV::CollapseSplit) {
        EXPECT_EQ(o.deleted, std::vector<int>{c.N(k)});
        EXPECT_EQ(o.created, std::vector<int>{created});
        EXPECT_EQ(o.steps.size(), 2u);
      }
      AtomicPrediction rp = ops.PredictRemoval(o.irregular);
      ASSERT_TRUE(rp) << o.description << ": " << rp.result.reason;
      AtomicOutcome r = ops.RemoveQuadruple(o.irregular);
      ASSERT_TRUE(r) << o.description << ": " << r.result.reason;
      EXPECT_EQ(r.steps, rp.steps);
      EXPECT_TRUE(InteriorIrregular(c.m).empty()) << o.description << " then " << r.description;
      if (via == QV::Flip) EXPECT_EQ(test::CanonicalFaces(c.m), faces);
      ASSERT_TRUE(CheckInvariants(c.m).ok);
    }
}

namespace {

/// One random request, predicted then applied; checks the agreement. Returns 1 if applied.
struct AgreementStats {
  int requests = 0, predictedOk = 0, applied = 0, geometryRefusals = 0;
};

void CheckAgreement(TMesh& m, MeshEditor<TMesh>& ed, const AtomicPrediction& pr,
                    const std::function<AtomicOutcome()>& real, AgreementStats& st) {
  ++st.requests;
  const auto snap = test::Snapshot(m);
  const auto before = test::Valences(m);
  AtomicOutcome o = real();
  if (!pr) {
    ASSERT_FALSE(o) << "predicted refusal (" << pr.result.reason << ") but applied " << o.description;
    EXPECT_EQ(o.result.reason, pr.result.reason);
    ASSERT_TRUE(test::Snapshot(m) == snap) << "a refused operation changed the mesh";
    return;
  }
  ++st.predictedOk;
  if (!o) {
    // only the fold check, which topology cannot predict, may refuse a predicted operation
    EXPECT_FALSE(pr.geometryChecked);
    EXPECT_TRUE(o.result.reason.find("fold") != std::string::npos ||
                o.result.reason.find("degenerate") != std::string::npos)
        << "predicted " << pr.description << ", refused: " << o.result.reason;
    ++st.geometryRefusals;
    ASSERT_TRUE(test::Snapshot(m) == snap) << "a refused operation changed the mesh";
    return;
  }
  ++st.applied;
  EXPECT_EQ(o.steps, pr.steps);
  EXPECT_EQ(o.changes, pr.changes);
  EXPECT_EQ(o.irregular, pr.irregular);
  EXPECT_EQ(o.moved, pr.moved);
  EXPECT_EQ(o.pair5, pr.pair5);
  EXPECT_EQ(o.pair7, pr.pair7);
  EXPECT_EQ(o.created, pr.created);
  EXPECT_EQ(o.deleted, pr.deleted);
  // the valences, recomputed from scratch, are the predicted ones and no others changed
  auto after = test::Valences(m);
  for (size_t i = 0; i < after.size(); ++i) {
    auto it = pr.changes.find(int(i));
    const int now = m.vert[i].IsD() ? 0 : after[i];
    if (it != pr.changes.end()) EXPECT_EQ(now, it->second) << "vertex " << i << " after " << o.description;
    else if (i < before.size()) EXPECT_EQ(now, before[i]) << "vertex " << i << " after " << o.description;
  }
  for (int v : pr.fives) EXPECT_EQ(ed.Valence(v), 5);
  for (int v : pr.sevens) EXPECT_EQ(ed.Valence(v), 7);
}

void RandomAgreement(TMesh& m, unsigned seed, int requests, AgreementStats& st) {
  typedef AtomicOperations<TMesh>::QuadrupleVia QV;
  MeshEditor<TMesh> ed(m);
  AtomicOperations<TMesh> ops(ed);
  std::mt19937 rng(seed);
  for (int it = 0; it < requests && !::testing::Test::HasFatalFailure(); ++it) {
    const int v = int(rng() % m.vert.size());
    if (!ed.IsLive(v) || ed.IsBoundary(v)) continue;
    VertexStar<TMesh> s = ed.Star(v);
    const int d = s.Valence();
    const int ref = rng() % 3 == 0 ? -1 : ed.Index(s.neighbors[rng() % s.neighbors.size()]);
    const int k = int(rng() % 6);
    const int kind = int(rng() % 4);
    if (kind == 0 || d == 5 || d == 7) {
      // fig. 7 by sector, or fig. 6 when there is a partner
      int partner = -1;
      for (auto n : s.neighbors)
        if (ed.Valence(ed.Index(n)) == 12 - d) partner = ed.Index(n);
      if (partner >= 0 && rng() % 2) {
        const int a = d == 5 ? v : partner, b = d == 5 ? partner : v;
        CheckAgreement(m, ed, ops.PredictMovePair57(a, b, k), [&] { return ops.MovePair57(a, b, k); }, st);
      } else {
        const AtomicVia via = AtomicVia(rng() % 4);
        const PairSide side = PairSide(rng() % 3);
        CheckAgreement(m, ed, ops.PredictVertexMove(v, k, ref, via, side),
                       [&] { return ops.MoveVertexWithPairGeneration(v, k, ref, via, side); }, st);
      }
    } else if (kind == 1) {
      const QV via = QV(rng() % 3);
      CheckAgreement(m, ed, ops.PredictQuadrupleGenerationInSector(v, k, via, ref),
                     [&] { return ops.GenerateQuadrupleInSector(v, k, via, ref); }, st);
    } else {
      // removal of the irregular vertices around v (the last ones made, when there are)
      std::vector<int> group;
      for (int w : test::IrregularVertices(m))
        if ((m.vert[size_t(w)].P() - m.vert[size_t(v)].P()).Norm() < 3 * (s.neighbors[0]->P() - m.vert[size_t(v)].P()).Norm())
          group.push_back(w);
      const size_t want = kind == 2 ? 3 : 4;
      if (group.size() < want) continue;
      group.resize(want);
      if (want == 3)
        CheckAgreement(m, ed, ops.PredictRemoval(group), [&] { return ops.MoveWithPairRemoval(group); }, st);
      else
        CheckAgreement(m, ed, ops.PredictRemoval(group), [&] { return ops.RemoveQuadruple(group); }, st);
    }
    ed.Commit();
    if (it % 50 == 0) ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
  }
}

}  // namespace

TEST(AtomicAgreement, DryRunsAgreeWithTheOperationsOnALatticeWithIrregularVertices) {
  TMesh m;
  test::RegularTorus(m, 30, 30);
  {
    MeshEditor<TMesh> ed(m);
    AtomicOperations<TMesh> ops(ed);
    for (int v : {5 * 30 + 5, 15 * 30 + 20, 22 * 30 + 8}) ASSERT_TRUE(ops.GenerateQuadruple(v, 0, false));
    ed.Commit();
  }
  AgreementStats st;
  RandomAgreement(m, 7, 1500, st);
  std::printf("lattice: %d requests, %d predicted to pass, %d applied, %d refused by the fold check\n", st.requests,
              st.predictedOk, st.applied, st.geometryRefusals);
  EXPECT_GT(st.requests, 500);
  EXPECT_GT(st.applied, 100);
  EXPECT_TRUE(CheckInvariants(m).ok);
}

TEST(AtomicAgreement, DryRunsAgreeWithTheOperationsOnACorpusMesh) {
  TMesh m;
  ASSERT_TRUE(test::LoadCorpus(m, "knot1.off"));
  AgreementStats st;
  RandomAgreement(m, 11, 1500, st);
  std::printf("knot1: %d requests, %d predicted to pass, %d applied, %d refused by the fold check\n", st.requests,
              st.predictedOk, st.applied, st.geometryRefusals);
  EXPECT_GT(st.requests, 500);
  EXPECT_GT(st.applied, 100);
  EXPECT_TRUE(CheckInvariants(m).ok);
  EXPECT_TRUE(test::AdjacencyEqualsRebuild(m));
}

// Simulate() gives the real verdict, fold check included, and leaves the mesh as it was.
TEST(AtomicAgreement, SimulationChecksGeometryWithoutEditing) {
  TMesh m;
  ASSERT_TRUE(test::LoadCorpus(m, "knot1.off"));
  MeshEditor<TMesh> ed(m);
  AtomicOperations<TMesh> ops(ed);
  std::mt19937 rng(3);
  int checked = 0;
  for (int it = 0; it < 300; ++it) {
    const int v = int(rng() % m.vert.size());
    if (ed.Valence(v) != 6) continue;
    const auto snap = test::Snapshot(m);
    AtomicPrediction p = ops.Simulate(ops.PredictQuadrupleGenerationInSector(v, int(rng() % 6), AtomicOperations<TMesh>::QuadrupleVia(rng() % 3)));
    ASSERT_TRUE(test::Snapshot(m) == snap);
    if (!p.result && !p.geometryChecked) continue;
    ++checked;
    AtomicOutcome o = ops.Apply(p);
    EXPECT_EQ(bool(o), bool(p.result)) << p.result.reason << " / " << o.result.reason;
    ed.Commit();
  }
  EXPECT_GT(checked, 50);
}
