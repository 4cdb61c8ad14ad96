// Unit tests of vcg_ext/irregular/slot_pool.h: with the pool on, a split takes the slots a
// committed collapse left (and only those), the dry run's index of a created vertex is the one
// the split gives, a rollback gives the slots back bit for bit and in order, and random
// sequences of edits, commits and rollbacks keep every invariant with fewer slots.
#include <gtest/gtest.h>

#include <random>

#include <vcg_ext/irregular/atomic_ops.h>
#include <vcg_ext/irregular/graph_ops.h>
#include <vcg_ext/irregular/mesh_checks.h>

#include "test_mesh.h"
#include "test_util.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {

/// Collapses vertex 0 of a hex patch into a neighbour: u = 0 dies with two faces.
template <class MeshT>
void CollapseCentre(MeshEditor<MeshT>& ed, int* u, std::vector<int>* deadFaces) {
  MeshT& m = ed.Mesh();
  *u = 0;
  const int v = ed.Index(ed.Star(0).neighbors[2]);
  std::vector<char> wasDead(m.face.size());
  for (size_t i = 0; i < m.face.size(); ++i) wasDead[i] = m.face[i].IsD();
  ASSERT_TRUE(ed.Collapse(*u, v).ok);
  for (size_t i = 0; i < m.face.size(); ++i)
    if (m.face[i].IsD() && !wasDead[i]) deadFaces->push_back(int(i));
  ASSERT_EQ(deadFaces->size(), 2u);
}

/// A regular interior vertex far from the centre and two neighbours three apart (d1 = d2 = 2).
template <class MeshT>
void SplitSite(MeshEditor<MeshT>& ed, int* w, int* a, int* b) {
  MeshT& m = ed.Mesh();
  for (size_t i = 1; i < m.vert.size(); ++i) {
    const int c = int(i);
    if (!ed.IsLive(c) || ed.IsBoundary(c) || ed.Valence(c) != 6) continue;
    bool nearCentre = false;
    for (auto* n : ed.Star(c).neighbors) nearCentre = nearCentre || ed.Valence(ed.Index(n)) != 6 || ed.IsBoundary(ed.Index(n));
    if (nearCentre) continue;
    VertexStar<MeshT> s = ed.Star(c);
    *w = c, *a = ed.Index(s.neighbors[0]), *b = ed.Index(s.neighbors[3]);
    return;
  }
  FAIL() << "no regular site";
}

/// A hex patch whose centre was collapsed and committed, with the pool on: the pool holds u
/// and the two dead faces.
struct PooledPatch {
  TMesh m;
  MeshEditor<TMesh> ed{m};
  int u = -1;
  std::vector<int> dead;
  explicit PooledPatch(int radius) {
    test::HexPatch(m, radius);
    ed.slotPool().Enable(true);
    CollapseCentre(ed, &u, &dead);
    ed.Commit();
  }
};

}  // namespace

TEST(SlotPool, SplitAfterACommittedCollapseTakesItsSlots) {
  PooledPatch p(5);
  TMesh& m = p.m;
  MeshEditor<TMesh>& ed = p.ed;
  const int u = p.u;
  const std::vector<int>& dead = p.dead;
  EXPECT_EQ(ed.slotPool().PooledVertices(), 1u);
  EXPECT_EQ(ed.slotPool().PooledFaces(), 2u);
  const size_t nv = m.vert.size(), nf = m.face.size();
  const int vn = m.vn, fn = m.fn;
  int w, a, b;
  SplitSite(ed, &w, &a, &b);
  EXPECT_EQ(ed.NextCreatedVertex(0), u);  // what a dry run names the new vertex
  EXPECT_EQ(ed.NextCreatedVertex(1), int(nv));
  auto before = test::Valences(m);
  int x = -1;
  ASSERT_TRUE(ed.Split(w, a, b, &x).ok);
  EXPECT_EQ(x, u);
  EXPECT_EQ(m.vert.size(), nv);  // nothing appended
  EXPECT_EQ(m.face.size(), nf);
  EXPECT_EQ(m.vn, vn + 1);
  EXPECT_EQ(m.fn, fn + 2);
  EXPECT_FALSE(m.vert[size_t(u)].IsD());
  for (int f : dead) {
    EXPECT_FALSE(m.face[size_t(f)].IsD());
    bool hasX = false;
    for (int z = 0; z < 3; ++z) hasX = hasX || m.face[size_t(f)].V(z) == &m.vert[size_t(u)];
    EXPECT_TRUE(hasX) << "a reused face holds the new vertex";
  }
  // where the new vertex is: between w's old position and the far side of its new star
  EXPECT_LT(vcg::Distance(m.vert[size_t(u)].P(), m.vert[size_t(w)].P()), 1.5f);
  auto after = test::Valences(m);
  EXPECT_EQ(after[size_t(w)], 5);
  EXPECT_EQ(after[size_t(u)], 5);
  EXPECT_EQ(after[size_t(a)], before[size_t(a)] + 1);
  EXPECT_EQ(after[size_t(b)], before[size_t(b)] + 1);
  EXPECT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
  EXPECT_TRUE(test::AdjacencyEqualsRebuild(m));
  EXPECT_EQ(ed.slotPool().PooledVertices(), 0u);
  EXPECT_EQ(ed.slotPool().PooledFaces(), 0u);
}

TEST(SlotPool, AnUncommittedCollapseKeepsItsSlots) {
  TMesh m;
  test::HexPatch(m, 5);
  MeshEditor<TMesh> ed(m);
  ed.slotPool().Enable(true);
  int u;
  std::vector<int> dead;
  CollapseCentre(ed, &u, &dead);  // not committed: its rollback may bring u back
  const size_t nv = m.vert.size();
  int w, a, b, x = -1;
  SplitSite(ed, &w, &a, &b);
  EXPECT_EQ(ed.NextCreatedVertex(0), int(nv));
  ASSERT_TRUE(ed.Split(w, a, b, &x).ok);
  EXPECT_EQ(x, int(nv));
  EXPECT_TRUE(m.vert[size_t(u)].IsD());
}

TEST(SlotPool, OffAppendsAsVcgDoes) {
  TMesh m;
  test::HexPatch(m, 5);
  MeshEditor<TMesh> ed(m);  // the default
  int u;
  std::vector<int> dead;
  CollapseCentre(ed, &u, &dead);
  ed.Commit();
  const size_t nv = m.vert.size();
  int w, a, b, x = -1;
  SplitSite(ed, &w, &a, &b);
  ASSERT_TRUE(ed.Split(w, a, b, &x).ok);
  EXPECT_EQ(x, int(nv));
  EXPECT_EQ(ed.slotPool().PooledVertices(), 0u);
}

TEST(SlotPool, RollbackGivesTheSlotsBackBitForBit) {
  TMesh src;
  test::HexPatch(src, 5);
  test::TOMesh m;  // optional components, as MeshLab's CMeshO
  test::CopyAsCMeshO(src, m);
  MeshEditor<test::TOMesh> ed(m);
  ed.slotPool().Enable(true);
  int u;
  std::vector<int> dead;
  CollapseCentre(ed, &u, &dead);
  ed.Commit();
  const std::vector<double> snap = test::OcfSnapshot(m);
  int w, a, b, x = -1;
  SplitSite(ed, &w, &a, &b);
  auto cp = ed.Mark();
  ASSERT_TRUE(ed.Split(w, a, b, &x).ok);
  ASSERT_EQ(x, u);
  ed.RollbackTo(cp);
  EXPECT_EQ(test::OcfSnapshot(m), snap);
  EXPECT_TRUE(m.vert[size_t(u)].IsD());
  EXPECT_EQ(ed.slotPool().PooledVertices(), 1u);
  EXPECT_EQ(ed.slotPool().PooledFaces(), 2u);
  // the same split again takes the same slots
  EXPECT_EQ(ed.NextCreatedVertex(0), u);
  ASSERT_TRUE(ed.Split(w, a, b, &x).ok);
  EXPECT_EQ(x, u);
  EXPECT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
}

TEST(SlotPool, TheAtomicDryRunNamesTheReusedSlot) {
  PooledPatch p(6);
  TMesh& m = p.m;
  MeshEditor<TMesh>& ed = p.ed;
  const int u = p.u;
  int w, a, b;
  SplitSite(ed, &w, &a, &b);
  AtomicOperations<TMesh> atomic(ed);
  // quadruple generation by a split (fig. 8): the prediction names the created vertex, and
  // the operation gives it that slot, with the predicted valences
  int checked = 0;
  for (int k = 0; k < 6; ++k) {
    AtomicPrediction pr = atomic.PredictQuadrupleGeneration(w, k, AtomicOperations<TMesh>::QuadrupleVia::Split);
    if (!pr || pr.created.empty()) continue;
    EXPECT_EQ(pr.created[0], u);
    auto cp = ed.Mark();
    AtomicOutcome o = atomic.Apply(pr);
    ASSERT_TRUE(o) << o.result.reason;
    ASSERT_FALSE(o.created.empty());
    EXPECT_EQ(o.created[0], u);
    EXPECT_EQ(o.changes, pr.changes);
    EXPECT_EQ(o.irregular, pr.irregular);
    EXPECT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
    ed.RollbackTo(cp);
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

TEST(SlotPool, RandomSequencesKeepInvariantsInFewerSlots) {
  size_t slots[2] = {0, 0};
  for (int on = 0; on < 2; ++on) {
    TMesh m;
    test::Icosphere(m, 4);
    MeshEditor<TMesh> ed(m);
    ed.slotPool().Enable(on == 1);
    std::mt19937 rng(11);
    int done = 0;
    for (int it = 0; it < 3000; ++it) {
      int v = int(rng() % m.vert.size());
      if (!ed.IsLive(v)) continue;
      VertexStar<TMesh> s = ed.Star(v);
      const int k = int(rng() % s.neighbors.size());
      const int y = ed.Index(s.neighbors[size_t(k)]);
      const int kind = int(rng() % 3);
      const bool check = it % 20 == 0;
      test::MeshSnapshot snap;
      if (check) snap = test::Snapshot(m);
      auto cp = ed.Mark();
      Result r = kind == 0 ? ed.Flip(v, y)
                 : kind == 1 ? ed.Collapse(v, y)
                             : ed.Split(v, y, ed.Index(s.neighbors[size_t((k + 3) % s.neighbors.size())]));
      if (r.ok && rng() % 4 == 0) {  // an edit tried and undone
        ed.RollbackTo(cp);
        if (check) ASSERT_EQ(test::Snapshot(m), snap) << "a rollback changed the mesh at step " << it;
        continue;
      }
      done += r.ok;
      if (check) {
        ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason << " at step " << it;
        ASSERT_TRUE(test::AdjacencyEqualsRebuild(m)) << "at step " << it;
      }
      if (rng() % 3 == 0) ed.Commit();
    }
    EXPECT_GT(done, 1000);
    ASSERT_TRUE(CheckInvariants(m).ok) << CheckInvariants(m).reason;
    EXPECT_TRUE(test::AdjacencyEqualsRebuild(m));
    slots[on] = m.vert.size();
  }
  EXPECT_LT(slots[1], slots[0]) << "the pool took no slot";
  RecordProperty("vertex_slots_append", int(slots[0]));
  RecordProperty("vertex_slots_pool", int(slots[1]));
}
