// Unit tests of vcg_ext/irregular/atomic_ops.h: the five atomic semantic operations (sec. 6.2)
// on constructed regular patches: exact valences of every vertex involved, every other vertex
// untouched, inverse operations restore the connectivity.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include <vcg_ext/irregular/atomic_ops.h>
#include <vcg_ext/irregular/mesh_checks.h>

#include "test_mesh.h"
#include "test_util.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {

// Valences changed exactly as the outcome states, nothing else changed.
void ExpectExactChanges(TMesh& m, const std::vector<int>& before, const AtomicOutcome& out) {
  auto after = test::Valences(m);
  for (size_t i = 0; i < before.size(); ++i) {
    auto it = out.changes.find(int(i));
    if (it != out.changes.end())
      EXPECT_EQ(after[i], it->second) << "vertex " << i;
    else
      EXPECT_EQ(after[i], before[i]) << "vertex " << i << " changed but is not in the outcome";
  }
  for (size_t i = before.size(); i < after.size(); ++i) EXPECT_TRUE(out.changes.count(int(i))) << "new vertex " << i;
  ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
}

}  // namespace

TEST(Atomic, QuadrupleGenerationByFlipAndItsRemoval) {
  TMesh m;
  test::RegularTorus(m, 24, 24);
  auto faces = test::CanonicalFaces(m);
  MeshEditor<TMesh> ed(m);
  AtomicOperations<TMesh> ops(ed);
  for (int k = 0; k < 6; ++k) {
    auto before = test::Valences(m);
    AtomicOutcome g = ops.GenerateQuadruple(100, k, false);
    ASSERT_TRUE(g) << g.result.reason;
    ExpectExactChanges(m, before, g);
    EXPECT_EQ(test::IrregularVertices(m).size(), 4u);
    AtomicOutcome r = ops.RemoveQuadruple(g.irregular);
    ASSERT_TRUE(r) << r.result.reason;
    EXPECT_EQ(test::IrregularVertices(m).size(), 0u);
    EXPECT_EQ(test::CanonicalFaces(m), faces) << "direction " << k;
  }
}

TEST(Atomic, QuadrupleGenerationBySplitAndItsRemoval) {
  TMesh m;
  test::RegularTorus(m, 24, 24);
  MeshEditor<TMesh> ed(m);
  AtomicOperations<TMesh> ops(ed);
  const int fn = m.fn;
  auto before = test::Valences(m);
  AtomicOutcome g = ops.GenerateQuadruple(200, 1, true);
  ASSERT_TRUE(g) << g.result.reason;
  ExpectExactChanges(m, before, g);
  EXPECT_EQ(m.fn, fn + 2);
  AtomicOutcome r = ops.RemoveQuadruple(g.irregular);
  ASSERT_TRUE(r) << r.result.reason;
  EXPECT_EQ(test::IrregularVertices(m).size(), 0u);
  EXPECT_EQ(m.fn, fn);
  ASSERT_TRUE(CheckInvariants(m).ok);
}

TEST(Atomic, QuadrupleRefusals) {
  TMesh m;
  test::RegularTorus(m, 16, 16);
  MeshEditor<TMesh> ed(m);
  AtomicOperations<TMesh> ops(ed);
  auto snap = test::Snapshot(m);
  EXPECT_FALSE(ops.RemoveQuadruple({1, 2, 3, 4}));  // all regular
  EXPECT_FALSE(ops.GenerateQuadruple(1, 7, false));  // bad direction
  EXPECT_EQ(test::Snapshot(m), snap);
}

// A 5-7 pair far from everything, moved in each of the six directions.
TEST(Atomic, PairMoveSixDirections) {
  TMesh m;
  test::RegularTorus(m, 40, 40);
  MeshEditor<TMesh> ed(m);
  AtomicOperations<TMesh> ops(ed);
  AtomicOutcome g = ops.GenerateQuadruple(20 * 40 + 20, 0, false);
  ASSERT_TRUE(g);
  int v5 = g.irregular[0], v7 = g.irregular[2];  // p (5) and n_k-1 (7) are adjacent
  ASSERT_TRUE(ed.Adjacent(v5, v7));
  // Take the pair 4 steps away from its partner pair: each step, the direction that moves
  // the v5 furthest from the partner's v5.
  const auto other = m.vert[size_t(g.irregular[1])].P();
  int moved = 0;
  for (int step = 0; step < 4; ++step) {
    int best = -1;
    float bestDist = -1;
    for (int dir = 0; dir < 6; ++dir) {
      auto cp = ed.Mark();
      AtomicOutcome o = ops.MovePair57(v5, v7, dir);
      if (o) {
        float dist = (m.vert[size_t(o.irregular[0])].P() - other).Norm();
        if (dist > bestDist) bestDist = dist, best = dir;
      }
      ed.RollbackTo(cp);
    }
    ASSERT_GE(best, 0);
    AtomicOutcome o = ops.MovePair57(v5, v7, best);
    ASSERT_TRUE(o);
    v5 = o.irregular[0];
    v7 = o.irregular[1];
    ++moved;
  }
  ASSERT_EQ(moved, 4);
  ed.Commit();
  int applied = 0;
  for (int dir = 0; dir < 6; ++dir) {
    auto cp = ed.Mark();
    auto before = test::Valences(m);
    auto irrBefore = test::IrregularVertices(m).size();
    AtomicOutcome o = ops.MovePair57(v5, v7, dir);
    if (!o) {
      ADD_FAILURE() << "direction " << dir << ": " << o.result.reason;
      continue;
    }
    ++applied;
    ExpectExactChanges(m, before, o);
    ASSERT_EQ(o.irregular.size(), 2u);
    EXPECT_EQ(ed.Valence(o.irregular[0]), 5);
    EXPECT_EQ(ed.Valence(o.irregular[1]), 7);
    EXPECT_TRUE(ed.Adjacent(o.irregular[0], o.irregular[1])) << "direction " << dir;
    EXPECT_EQ(test::IrregularVertices(m).size(), irrBefore);
    ed.RollbackTo(cp);
  }
  EXPECT_EQ(applied, 6);
}

// Flip moves are their own inverse: direction 1 then the flip back restores the faces.
TEST(Atomic, PairMoveInverseRestoresConnectivity) {
  TMesh m;
  test::RegularTorus(m, 30, 30);
  MeshEditor<TMesh> ed(m);
  AtomicOperations<TMesh> ops(ed);
  AtomicOutcome g = ops.GenerateQuadruple(15 * 30 + 15, 0, false);
  ASSERT_TRUE(g);
  const int v5 = g.irregular[0], v7 = g.irregular[2];
  auto faces = test::CanonicalFaces(m);
  for (int dir = 0; dir < 6; ++dir) {
    auto cp = ed.Mark();
    AtomicOutcome o = ops.MovePair57(v5, v7, dir);
    if (!o) { ed.RollbackTo(cp); continue; }
    // Search the inverse among the six moves of the new pair.
    bool restored = false;
    for (int back = 0; back < 6 && !restored; ++back) {
      auto cp2 = ed.Mark();
      AtomicOutcome b = ops.MovePair57(o.irregular[0], o.irregular[1], back);
      if (b && ed.Valence(v5) == 5 && test::Valences(m).size() >= 1) {
        // connectivity equal up to relabelling when a split and a collapse undo each other
        auto now = test::CanonicalFaces(m);
        restored = now.size() == faces.size() && test::IrregularVertices(m).size() == 4;
        if (o.description.find("flip") != std::string::npos) restored = restored && now == faces;
      }
      ed.RollbackTo(cp2);
    }
    EXPECT_TRUE(restored) << "no inverse for direction " << dir << " (" << o.description << ")";
    ed.RollbackTo(cp);
  }
}

TEST(Atomic, V5MoveWithPairGenerationAndRemoval) {
  TMesh m;
  test::Icosphere(m, 3);  // twelve v5 eight edges apart
  MeshEditor<TMesh> ed(m);
  AtomicOperations<TMesh> ops(ed);
  int p = -1;
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (ed.Valence(int(i)) == 5) { p = int(i); break; }
  ASSERT_GE(p, 0);
  auto faces = test::CanonicalFaces(m);
  for (int k = 0; k < 5; ++k) {
    auto before = test::Valences(m);
    AtomicOutcome o = ops.MoveWithPairGeneration(p, k);
    ASSERT_TRUE(o) << o.result.reason;
    ExpectExactChanges(m, before, o);
    EXPECT_EQ(ed.Valence(p), 6);
    EXPECT_EQ(test::IrregularVertices(m).size(), 14u);
    // moved v5 and the generated pair are adjacent to each other
    EXPECT_TRUE(ed.Adjacent(o.irregular[1], o.irregular[2]));
    AtomicOutcome r = ops.MoveWithPairRemoval(o.irregular);
    ASSERT_TRUE(r) << r.result.reason;
    EXPECT_EQ(test::IrregularVertices(m).size(), 12u);
    EXPECT_EQ(ed.Valence(p), 5);
    EXPECT_EQ(test::CanonicalFaces(m), faces);
  }
}

TEST(Atomic, V7MoveWithPairGenerationAndRemoval) {
  TMesh m;
  test::RegularTorus(m, 30, 30);
  MeshEditor<TMesh> ed(m);
  AtomicOperations<TMesh> ops(ed);
  AtomicOutcome g = ops.GenerateQuadruple(15 * 30 + 15, 0, false);
  ASSERT_TRUE(g);
  const int v7 = g.irregular[2];
  ed.Commit();
  auto faces = test::CanonicalFaces(m);
  int applied = 0;
  for (int k = 0; k < 7; ++k) {
    auto before = test::Valences(m);
    AtomicOutcome o = ops.MoveWithPairGeneration(v7, k);
    if (!o) {
      EXPECT_EQ(test::CanonicalFaces(m), faces);
      continue;
    }
    ++applied;
    ExpectExactChanges(m, before, o);
    EXPECT_EQ(test::IrregularVertices(m).size(), 6u);
    AtomicOutcome r = ops.MoveWithPairRemoval(o.irregular);
    ASSERT_TRUE(r) << r.result.reason;
    EXPECT_EQ(test::CanonicalFaces(m), faces);
  }
  EXPECT_GE(applied, 2);  // the partner pair blocks the other directions
}

TEST(Atomic, RefusalsLeaveTheMeshUnchanged) {
  TMesh m;
  test::Icosphere(m, 2);
  MeshEditor<TMesh> ed(m);
  AtomicOperations<TMesh> ops(ed);
  auto snap = test::Snapshot(m);
  int p = -1, r6 = -1;
  for (size_t i = 0; i < m.vert.size(); ++i) {
    if (ed.Valence(int(i)) == 5 && p < 0) p = int(i);
    if (ed.Valence(int(i)) == 6 && r6 < 0) r6 = int(i);
  }
  EXPECT_FALSE(ops.MovePair57(p, r6, 0));                  // not a 5-7 pair
  EXPECT_FALSE(ops.MoveWithPairGeneration(r6, 0));         // regular vertex
  EXPECT_FALSE(ops.MoveWithPairRemoval({p, r6, r6}));      // wrong triple
  EXPECT_FALSE(ops.GenerateQuadruple(p, 0, false));        // not regular
  EXPECT_EQ(test::Snapshot(m), snap);
}

// Random atomic operations on a real mesh: invariants after each one, refusals leave the
// mesh identical.
TEST(Atomic, RandomOperationsOnRealMesh) {
  TMesh m;
  if (!test::LoadCorpus(m, "knot1.off")) test::Icosphere(m, 4);
  MeshEditor<TMesh> ed(m);
  AtomicOperations<TMesh> ops(ed);
  std::mt19937 rng(11);
  int applied = 0;
  for (int it = 0; it < 1500; ++it) {
    int v = int(rng() % m.vert.size());
    if (!ed.IsLive(v)) continue;
    const int d = ed.Valence(v);
    const bool check = it % 10 == 0;
    test::MeshSnapshot snap;
    if (check) snap = test::Snapshot(m);
    AtomicOutcome o;
    int k = int(rng() % 7);
    if (d == 6) o = ops.GenerateQuadruple(v, k % 6, rng() % 2);
    else if (d == 5 || d == 7) {
      // a partner of the other type nearby makes a pair
      int partner = -1;
      for (auto n : ed.Star(v).neighbors)
        if (ed.Valence(ed.Index(n)) == 12 - d) partner = ed.Index(n);
      if (partner >= 0) o = d == 5 ? ops.MovePair57(v, partner, k % 6) : ops.MovePair57(partner, v, k % 6);
      else o = ops.MoveWithPairGeneration(v, k % d);
    } else continue;
    if (o) {
      ++applied;
      if (check) ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason << " after " << o.description;
    } else if (check) {
      ASSERT_EQ(test::Snapshot(m), snap) << o.result.reason;
    }
    ed.Commit();
  }
  EXPECT_GT(applied, 200);
  ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
  EXPECT_TRUE(test::AdjacencyEqualsRebuild(m));
}

// SetDescribing(false) (Automatic Reduction's setting) changes only the text: every 5-7 pair
// move predicted and applied on the bunny gives the same steps, valence changes,
// roles and mesh as with descriptions on, with empty descriptions.
TEST(Atomic, DescribingOffChangesOnlyTheText) {
  TMesh m;
  ASSERT_TRUE(test::LoadCorpus(m, "bunny00.off")) << "the corpus is installed by scripts/test.sh";
  MeshEditor<TMesh> ed(m);
  AtomicOperations<TMesh> told(ed), quiet(ed);
  quiet.SetDescribing(false);
  EXPECT_TRUE(told.Describing());
  EXPECT_FALSE(quiet.Describing());
  int predicted = 0, applied = 0, refused = 0;
  for (int v5 = 0; v5 < int(m.vert.size()) && applied < 150; ++v5) {
    if (!ed.IsLive(v5) || ed.IsBoundary(v5) || ed.Valence(v5) != 5) continue;
    std::vector<int> ring;  // indices: a split may move the vertex vector, and its pointers
    for (auto* nb : ed.Star(v5).neighbors) ring.push_back(ed.Index(nb));
    for (int v7 : ring) {
      if (ed.IsBoundary(v7) || ed.Valence(v7) != 7) continue;
      for (int dir = 0; dir < 6; ++dir) {
        const AtomicPrediction a = told.PredictMovePair57(v5, v7, dir), b = quiet.PredictMovePair57(v5, v7, dir);
        ++predicted;
        ASSERT_EQ(bool(a), bool(b));
        EXPECT_TRUE(b.description.empty());
        if (!a) {
          ++refused;
          EXPECT_FALSE(a.result.reason.empty());
          continue;
        }
        EXPECT_FALSE(a.description.empty());
        EXPECT_TRUE(a.changes == b.changes);
        EXPECT_EQ(a.irregular, b.irregular);
        EXPECT_EQ(a.pair5, b.pair5);
        EXPECT_EQ(a.pair7, b.pair7);
        ASSERT_EQ(a.steps.size(), b.steps.size());
        // applied by each, from the same mesh: the same outcome and the same mesh
        auto cp = ed.Mark();
        const AtomicOutcome oa = told.Apply(a);
        const test::MeshSnapshot sa = test::Snapshot(m);
        ed.RollbackTo(cp);
        const AtomicOutcome ob = quiet.Apply(b);
        ASSERT_EQ(bool(oa), bool(ob));
        EXPECT_TRUE(test::Snapshot(m) == sa);
        EXPECT_TRUE(oa.changes == ob.changes);
        EXPECT_EQ(oa.irregular, ob.irregular);
        EXPECT_TRUE(ob.description.empty());
        ed.RollbackTo(cp);
        applied += bool(oa);
      }
    }
  }
  EXPECT_GT(applied, 100);
  EXPECT_GT(refused, 10);
  RecordProperty("predicted", predicted);
}
