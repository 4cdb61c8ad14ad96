// The boundary stage of the automatic reduction (boundary_reduction.h): interior irregular
// vertices near a hole moved into the boundary or cancelled there. Constructed patches check the
// exact outcome (which vertices end irregular, their valences, the report's named counts, the
// budget rule, the guard's veto, frozen vertices); corpus meshes with holes, remeshed, check the
// counts (interior drops, boundary never above the input's) with a trivial guard and with an
// angle / Hausdorff guard written here, invariants after every edit.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include <vcg/complex/algorithms/stat.h>

#include <vcg_ext/irregular/automatic_reduction.h>
#include <vcg_ext/irregular/boundary_reduction.h>
#include <vcg_ext/irregular/mesh_checks.h>
#include <vcg_ext/irregular/quality.h>
#include <vcg_ext/irregular/remeshing.h>

#include "test_boundary_mesh.h"
#include "test_mesh.h"
#include "test_util.h"

using namespace vcg_ext::irregular;
using test::At;
using test::ExpectValid;
using test::TMesh;

namespace {

typedef IrregularVertexLists Irregular;
Irregular IrregularOf(TMesh& m) { return IrregularVerticesByPlace(m); }

int LiveVertices(TMesh& m) { return Summarize(m).vertices; }

/// A guard that accepts every edit, and checks the invariants (with eq. 2) after each.
struct CheckingGuard {
  explicit CheckingGuard(TMesh& mm) : m(mm) {}
  TMesh& m;
  int edits = 0, broken = 0;
  std::string firstProblem;
  BoundaryEditGuard Make() {
    BoundaryEditGuard g;
    g.accept = [this](const std::vector<int>&) {
      ++edits;
      Result r = CheckInvariants(m);
      if (!r.ok || !Summarize(m).GaussBonnetHolds()) {
        if (broken++ == 0) firstProblem = r.reason;
      }
      return true;
    };
    return g;
  }
};

/// HexPatch(4) with a boundary v3 under an interior v7: SplitBoundary of the side vertex (2, 2)
/// along its edge to its first interior neighbour. Returns {v7, v3}.
std::pair<int, int> V7OverBoundaryV3(TMesh& m) {
  test::HexPatch(m, 4);
  MeshEditor<TMesh> ed(m);
  const int w = At(m, 2, 2);
  const int c = ed.Index(ed.Star(w).neighbors[1]);
  EXPECT_TRUE(ed.SplitBoundary(w, c).ok);
  ed.Commit();
  return {c, w};
}

}  // namespace

TEST(BoundaryReduction, CountsInteriorAndBoundarySeparately) {
  TMesh m;
  const auto cw = V7OverBoundaryV3(m);
  IrregularByPlace c = CountIrregularByPlace(m);
  EXPECT_EQ(c.interior, 1);
  EXPECT_EQ(c.boundary, 1);
  EXPECT_EQ(c.Total(), 1 + 1);
  Irregular ir = IrregularOf(m);
  EXPECT_EQ(ir.interior, std::vector<int>{cw.first});
  EXPECT_EQ(ir.boundary, std::vector<int>{cw.second});
  // a plain hexagonal patch: corners of 120 degrees at valence 3 are regular
  TMesh h;
  test::HexPatch(h, 3);
  c = CountIrregularByPlace(h);
  EXPECT_EQ(c.interior, 0);
  EXPECT_EQ(c.boundary, 0);
}

// An interior v7 at the apex of a boundary edge with a boundary v3 end: the boundary-edge
// collapse (A) removes the v3 and makes the v7 regular. Both irregular vertices cancel.
TEST(BoundaryReduction, CancelsAV7AgainstTheBoundaryV3UnderIt) {
  TMesh m;
  const auto cw = V7OverBoundaryV3(m);
  const int v7 = cw.first, v3 = cw.second;
  ASSERT_EQ(LiveVertices(m), 62);
  MeshEditor<TMesh> ed(m);
  CheckingGuard cg(m);
  BoundaryReduction<TMesh> br(ed, nullptr, cg.Make());
  EXPECT_EQ(br.BoundaryLimit(), 1);
  BoundaryReductionReport r = br.Run();
  EXPECT_EQ(r.candidates, 1);
  EXPECT_EQ(r.interiorBefore, 1);
  EXPECT_EQ(r.boundaryBefore, 1);
  EXPECT_EQ(r.interiorAfter, 0);
  EXPECT_EQ(r.boundaryAfter, 0);
  EXPECT_EQ(r.absorbedV7, 1);
  EXPECT_EQ(r.absorbedV5, 0);
  EXPECT_EQ(r.absorbedPairs, 0);
  EXPECT_EQ(r.cancelled, 1);
  EXPECT_EQ(r.boundaryAdded, 0);
  EXPECT_EQ(r.undone, 0);
  EXPECT_EQ(r.refused, 0);
  EXPECT_EQ(cg.edits, 1);
  EXPECT_EQ(cg.broken, 0) << cg.firstProblem;
  ed.Commit();
  EXPECT_TRUE(m.vert[size_t(v3)].IsD());  // the v3 end is the one collapsed away
  EXPECT_EQ(ed.Valence(v7), 6);
  Irregular ir = IrregularOf(m);
  EXPECT_TRUE(ir.interior.empty());
  EXPECT_TRUE(ir.boundary.empty());
  EXPECT_EQ(LiveVertices(m), 61);  // back to HexPatch(4)'s 3 r (r + 1) + 1
  ExpectValid(m);
}

// A boundary-edge collapse between two regular side vertices leaves a boundary v5 (valence 5)
// over an interior v5; the stage splits the boundary v5 along its edge to the v5 (B): both
// halves get valence 4, the v5 becomes regular.
TEST(BoundaryReduction, CancelsAV5AgainstABoundaryV5) {
  TMesh m;
  test::HexPatch(m, 4);
  const int u = At(m, 3, 1), w = At(m, 2, 2), apex = At(m, 2, 1);
  {
    MeshEditor<TMesh> ed(m);
    ASSERT_TRUE(ed.Collapse(u, w).ok);
    ed.Commit();
    ASSERT_EQ(ed.Valence(w), 5);
    ASSERT_EQ(ed.Valence(apex), 5);
  }
  Irregular ir = IrregularOf(m);
  ASSERT_EQ(ir.interior, std::vector<int>{apex});
  ASSERT_EQ(ir.boundary, std::vector<int>{w});
  const size_t oldSize = m.vert.size();
  MeshEditor<TMesh> ed(m);
  CheckingGuard cg(m);
  BoundaryReduction<TMesh> br(ed, nullptr, cg.Make());
  BoundaryReductionReport r = br.Run();
  EXPECT_EQ(r.absorbedV5, 1);
  EXPECT_EQ(r.absorbedV7, 0);
  EXPECT_EQ(r.cancelled, 1);
  EXPECT_EQ(r.interiorAfter, 0);
  EXPECT_EQ(r.boundaryAfter, 0);
  EXPECT_EQ(cg.broken, 0) << cg.firstProblem;
  ed.Commit();
  ASSERT_EQ(m.vert.size(), oldSize + 1);  // the split's new half
  const int x = int(oldSize);
  EXPECT_EQ(ed.Valence(apex), 6);
  EXPECT_EQ(ed.Valence(w), 4);
  EXPECT_EQ(ed.Valence(x), 4);
  EXPECT_TRUE(ed.IsBoundary(w) && ed.IsBoundary(x));
  ir = IrregularOf(m);
  EXPECT_TRUE(ir.interior.empty());
  EXPECT_TRUE(ir.boundary.empty());
  EXPECT_EQ(LiveVertices(m), 61);
  ExpectValid(m);
}

namespace {
/// GeneratePair at boundary vertex b (leaving the boundary 5-7 pair b = 3, ob = 5), then the
/// interior pair moved `steps` pair steps away from b (each step: the move taking the pair's
/// midpoint farthest from b). *v5, *v7: where the pair ends.
void PairMovedInward(TMesh& m, int b, int steps, int* v5, int* v7) {
  MeshEditor<TMesh> ed(m);
  BoundaryOperations<TMesh> bo(ed);
  AtomicOperations<TMesh> ops(ed);
  BoundaryOutcome g = bo.GeneratePair(b, 0);
  ASSERT_TRUE(g) << g.result.reason;
  *v5 = g.v5, *v7 = g.v7;
  for (int s = 0; s < steps; ++s) {
    int best = -1;
    double far = -1;
    for (int dir = 0; dir < 6; ++dir) {
      AtomicPrediction p = ops.PredictMovePair57(*v5, *v7, dir);
      if (!p) continue;
      const double d = double((((m.vert[size_t(p.pair5)].P() + m.vert[size_t(p.pair7)].P()) / 2) -
                               m.vert[size_t(b)].P()).Norm());
      if (d > far) far = d, best = dir;
    }
    ASSERT_GE(best, 0);
    AtomicOutcome o = ops.MovePair57(*v5, *v7, best);
    ASSERT_TRUE(o) << o.result.reason;
    *v5 = o.pair5, *v7 = o.pair7;
  }
  ed.Commit();
  ASSERT_FALSE(ed.Adjacent(*v5, b) || ed.Adjacent(*v7, b));
}

/// The stage on a mesh whose only irregular vertices are the pair of PairMovedInward (2 steps)
/// and the boundary pair it left: the pair is moved back and absorbed whole, the boundary pair
/// cancelled, nothing irregular is left and the vertex count is the patch's.
void ExpectPairBroughtBackAndCancelled(TMesh& m, int b, int liveVertices) {
  int v5 = -1, v7 = -1;
  PairMovedInward(m, b, 2, &v5, &v7);
  Irregular ir = IrregularOf(m);
  std::vector<int> pair{v5, v7};
  std::sort(pair.begin(), pair.end());
  ASSERT_EQ(ir.interior, pair);
  ASSERT_EQ(ir.boundary.size(), 2u);
  MeshEditor<TMesh> ed(m);
  CheckingGuard cg(m);
  BoundaryReduction<TMesh> br(ed, nullptr, cg.Make());
  BoundaryReductionReport r = br.Run();
  EXPECT_EQ(r.candidates, 2);
  EXPECT_EQ(r.absorbedPairs, 1);
  EXPECT_EQ(r.pairsMoved, 1);
  EXPECT_EQ(r.pairSteps, 2);
  EXPECT_EQ(r.cancelled, 2);
  EXPECT_EQ(r.interiorBefore, 2);
  EXPECT_EQ(r.boundaryBefore, 2);
  EXPECT_EQ(r.interiorAfter, 0);
  EXPECT_EQ(r.boundaryAfter, 0);
  EXPECT_EQ(cg.broken, 0) << cg.firstProblem;
  ed.Commit();
  ir = IrregularOf(m);
  EXPECT_TRUE(ir.interior.empty());
  EXPECT_TRUE(ir.boundary.empty());
  EXPECT_EQ(LiveVertices(m), liveVertices);
  ExpectValid(m);
}
}  // namespace

// A 5-7 pair generated from the outer boundary and moved two pair steps inward: the stage moves
// it back (dry runs choose the steps toward the nearest boundary irregular vertex) and absorbs
// it whole, cancelling the boundary pair.
TEST(BoundaryReduction, MovesAPairBackToTheBoundaryAndCancelsIt) {
  TMesh m;
  test::HexPatch(m, 5);
  ExpectPairBroughtBackAndCancelled(m, At(m, 3, 2), 91);  // HexPatch(5): 3 r (r + 1) + 1
}

// The same at a hole: an annulus (HexPatch(6) without the faces within 2 rings of the centre;
// the hole's corners of 240 degrees are regular at valence 5), the pair generated at the side
// vertex (1, 1) of the hole.
TEST(BoundaryReduction, MovesAPairBackToAHoleAndCancelsIt) {
  TMesh m;
  test::HexPatchWithHole(m, 6, 2);
  const int live = LiveVertices(m);
  ASSERT_TRUE(IrregularOf(m).interior.empty());
  ASSERT_TRUE(IrregularOf(m).boundary.empty());
  ExpectPairBroughtBackAndCancelled(m, At(m, 1, 1), live);
}

// The budget rule: a lone interior v5 next to a regular stretch of boundary can only be
// absorbed by leaving a boundary v3 there (dI = -1, dB = +1). With the input's boundary count
// (0) as the limit it stays; with a limit of 1 it is absorbed and the new boundary v3 is the
// only irregular vertex left.
TEST(BoundaryReduction, NeverExceedsTheBoundaryLimit) {
  auto make = [](TMesh& m) {
    test::HexPatch(m, 4);
    const int c = At(m, 4, 0);
    VertexStar<TMesh> cs = StarOf<TMesh>(&m.vert[size_t(c)]);
    const vcg::Point3f mid = (cs.neighbors.front()->P() + cs.neighbors.back()->P()) * 0.5f;
    m.vert[size_t(c)].P() = mid + (m.vert[size_t(c)].P() - mid) * 0.2f;  // flatten the corner: a boundary v3
    test::UpdateTopology(m);
    MeshEditor<TMesh> ed(m);
    EXPECT_TRUE(ed.Collapse(c, At(m, 3, 1)).ok);  // (A): the v3 is cancelled, (3, 0) becomes a v5
    ed.Commit();
    return At(m, 3, 0);
  };
  {
    TMesh m;
    const int in = make(m);
    ASSERT_EQ(IrregularOf(m).interior, std::vector<int>{in});
    ASSERT_TRUE(IrregularOf(m).boundary.empty());
    const auto snap = test::Snapshot(m);
    MeshEditor<TMesh> ed(m);
    CheckingGuard cg(m);
    BoundaryReduction<TMesh> br(ed, nullptr, cg.Make());
    EXPECT_EQ(br.BoundaryLimit(), 0);
    BoundaryReductionReport r = br.Run();
    EXPECT_EQ(r.candidates, 1);
    EXPECT_EQ(r.Kept(), 0);
    EXPECT_EQ(r.refused, 1);
    EXPECT_EQ(r.interiorAfter, 1);
    EXPECT_EQ(r.boundaryAfter, 0);
    EXPECT_EQ(cg.edits, 0);
    EXPECT_EQ(test::Snapshot(m), snap);
  }
  {
    TMesh m;
    const int in = make(m);
    const size_t oldSize = m.vert.size();
    MeshEditor<TMesh> ed(m);
    CheckingGuard cg(m);
    BoundaryReductionOptions opt;
    opt.boundaryLimit = 1;
    BoundaryReduction<TMesh> br(ed, nullptr, cg.Make(), nullptr, opt);
    BoundaryReductionReport r = br.Run();
    EXPECT_EQ(r.absorbedV5, 1);
    EXPECT_EQ(r.boundaryAdded, 1);
    EXPECT_EQ(r.cancelled, 0);
    EXPECT_EQ(r.interiorAfter, 0);
    EXPECT_EQ(r.boundaryAfter, 1);
    EXPECT_EQ(cg.broken, 0) << cg.firstProblem;
    ed.Commit();
    EXPECT_EQ(ed.Valence(in), 6);
    Irregular ir = IrregularOf(m);
    EXPECT_TRUE(ir.interior.empty());
    // the boundary v3 is the half the split created
    ASSERT_EQ(ir.boundary, std::vector<int>{int(oldSize)});
    EXPECT_EQ(ed.Valence(int(oldSize)), 3);
    ExpectValid(m);
  }
}

// The guard's veto: every edit it refuses is rolled back, the mesh is exactly as it was.
TEST(BoundaryReduction, GuardRefusalLeavesTheMeshUnchanged) {
  TMesh m;
  const auto cw = V7OverBoundaryV3(m);
  const auto snap = test::Snapshot(m);
  MeshEditor<TMesh> ed(m);
  std::vector<int> around;
  int asked = 0;
  BoundaryEditGuard g;
  g.begin = [&](const std::vector<int>& a) { around = a; };
  g.accept = [&](const std::vector<int>&) {
    ++asked;
    return false;
  };
  BoundaryReduction<TMesh> br(ed, nullptr, g);
  BoundaryReductionReport r = br.Run();
  EXPECT_EQ(r.Kept(), 0);
  EXPECT_EQ(r.undone, 1);  // the second phase does not ask again for the edit refused in the first
  EXPECT_EQ(asked, 1);
  EXPECT_EQ(r.refused, 1);
  EXPECT_EQ(r.interiorAfter, 1);
  EXPECT_EQ(r.boundaryAfter, 1);
  EXPECT_NE(std::find(around.begin(), around.end(), cw.first), around.end());
  EXPECT_NE(std::find(around.begin(), around.end(), cw.second), around.end());
  EXPECT_EQ(test::Snapshot(m), snap);
}

// Frozen vertices: a frozen candidate is not a candidate; an edit that would touch a frozen
// vertex, or a face around one, is refused.
TEST(BoundaryReduction, FrozenVerticesAreNeverTouched) {
  for (int which = 0; which < 2; ++which) {
    TMesh m;
    const auto cw = V7OverBoundaryV3(m);
    const auto snap = test::Snapshot(m);
    MeshEditor<TMesh> ed(m);
    std::vector<char> frozen(m.vert.size(), 0);
    frozen[size_t(which == 0 ? cw.first : cw.second)] = 1;
    CheckingGuard cg(m);
    BoundaryReduction<TMesh> br(ed, nullptr, cg.Make(), &frozen);
    BoundaryReductionReport r = br.Run();
    EXPECT_EQ(r.candidates, which == 0 ? 0 : 1);
    EXPECT_EQ(r.Kept(), 0);
    EXPECT_EQ(cg.edits, 0);
    EXPECT_EQ(test::Snapshot(m), snap);
  }
}

// ---------------------------------------------------------------- corpus meshes with holes
namespace {

/// Smallest angle (degrees) of the faces around the 2-ring of the vertices (every face the
/// guard's relaxation of the 2-ring can change).
double MinAngleAround(TMesh& m, const std::vector<int>& vs) {
  double mn = 180;
  for (int v : KRing(m, vs, 2))
    for (auto& c : StarOf<TMesh>(&m.vert[size_t(v)]).corners)
      for (int z = 0; z < 3; ++z) mn = std::min(mn, FaceAngleDeg(c.f, z));
  return mn;
}

/// The guard a driver would build: local relaxation of the 2-ring (projected on the input,
/// boundary vertices sliding along the input's boundary), then the smallest angle must stay
/// above min(30, before) and the faces' centroids and edge midpoints within the Hausdorff budget
/// (0.5% of the diagonal) of the input. Checks the invariants after every edit.
struct AngleHausdorffGuard {
  TMesh& m;
  MeshEditor<TMesh>& ed;
  const SurfaceProjector& input;
  BoundaryCurve curve;
  double budget, angleBefore = 180;
  int edits = 0, refused = 0, broken = 0;
  int angleRefusals = 0, distanceRefusals = 0;
  std::string firstProblem;
  AngleHausdorffGuard(TMesh& mm, MeshEditor<TMesh>& e, const SurfaceProjector& in)
      : m(mm), ed(e), input(in), curve(mm), budget(0.005 * double(in.Diagonal())) {}

  std::vector<int> Live(const std::vector<int>& vs) {
    std::vector<int> l;
    for (int v : vs)
      if (ed.IsLive(v)) l.push_back(v);
    return l;
  }
  void Relax(const std::vector<int>& seeds) {
    std::vector<int> ring = KRing(m, Live(seeds), 2);
    for (int v : ring) {
      ed.journal().SaveVertex(ed.V(v));
      for (auto& c : ed.Star(v).corners) ed.journal().SaveFace(c.f);
    }
    RelaxOptions ro;
    ro.iterations = 3;
    ro.boundaryCurve = &curve;
    LocalRelax(m, ring, &input, ro);
  }
  bool Within(const std::vector<int>& touched) {
    for (int v : KRing(m, Live(touched), 2))
      for (auto& c : ed.Star(v).corners) {
        const auto* f = c.f;
        std::vector<vcg::Point3f> probes{(f->cP(0) + f->cP(1) + f->cP(2)) / 3.f};
        for (int z = 0; z < 3; ++z) probes.push_back((f->cP(z) + f->cP((z + 1) % 3)) / 2.f);
        for (auto& p : probes) {
          float d = 0;
          input.Closest(p, &d, nullptr, float(2 * budget));
          if (double(d) > budget) return false;
        }
      }
    return true;
  }
  BoundaryEditGuard Make() {
    BoundaryEditGuard g;
    g.begin = [this](const std::vector<int>& around) { angleBefore = MinAngleAround(m, around); };
    g.relax = [this](const std::vector<int>& seeds) { Relax(seeds); };
    g.accept = [this](const std::vector<int>& touched) {
      Relax(touched);
      Result r = CheckInvariants(m);
      if (!r.ok && broken++ == 0) firstProblem = r.reason;
      const bool angle = MinAngleAround(m, Live(touched)) >= std::min(30.0, angleBefore);
      const bool near = angle && Within(touched);
      if (!angle) ++angleRefusals;
      if (angle && !near) ++distanceRefusals;
      near ? ++edits : ++refused;
      return near;
    };
    return g;
  }
};

struct CorpusCase {
  const char* name;
  int vertices;
};

class BoundaryReductionCorpus : public ::testing::TestWithParam<CorpusCase> {};

/// The corpus mesh remeshed to about n vertices; *input: the surface as loaded.
void Remeshed(TMesh& m, const CorpusCase& c, std::unique_ptr<SurfaceProjector>* input) {
  ASSERT_TRUE(test::LoadCorpus(m, c.name)) << "missing corpus mesh " << c.name << " (run scripts/setup.sh)";
  input->reset(new SurfaceProjector(m));
  RemeshOptions ro;
  ro.targetEdgeLength = EdgeLengthForVertexCount(vcg::tri::Stat<TMesh>::ComputeMeshArea(m), c.vertices);
  RemeshIsotropic(m, ro);
  test::UpdateTopology(m);
  ASSERT_TRUE(CheckInvariants(m).ok);
  ASSERT_GT(Summarize(m).boundaryLoops, 0) << c.name << " has no boundary";
}

}  // namespace

TEST_P(BoundaryReductionCorpus, TrivialGuard) {
  TMesh m;
  std::unique_ptr<SurfaceProjector> input;
  Remeshed(m, GetParam(), &input);
  if (HasFatalFailure()) return;
  const IrregularByPlace before = CountIrregularByPlace(m);
  MeshEditor<TMesh> ed(m);
  CheckingGuard cg(m);
  BoundaryReduction<TMesh> br(ed, input.get(), cg.Make());
  BoundaryReductionReport total;
  for (int call = 0; call < 3; ++call) {  // as the driver would, once per sweep
    BoundaryReductionReport r = br.Run();
    EXPECT_EQ(r.boundaryLimit, before.boundary);
    EXPECT_LE(r.boundaryAfter, before.boundary);
    EXPECT_LE(r.interiorAfter, r.interiorBefore);
    total.Add(r);
    // the counts kept edit by edit agree with a full recount
    const IrregularByPlace now = CountIrregularByPlace(m);
    EXPECT_EQ(now.interior, r.interiorAfter);
    EXPECT_EQ(now.boundary, r.boundaryAfter);
    if (r.Kept() == 0) break;
  }
  EXPECT_EQ(cg.broken, 0) << cg.firstProblem;
  EXPECT_EQ(total.interiorBefore, before.interior);
  EXPECT_EQ(total.boundaryBefore, before.boundary);
  EXPECT_LT(total.interiorAfter, before.interior);
  EXPECT_LE(total.boundaryAfter, before.boundary);
  EXPECT_EQ(CountFoldedEdges(m), 0);
  ed.Commit();
  ExpectValid(m);
  std::printf("%s (%d vertices), trivial guard: interior %d -> %d, boundary %d -> %d; absorbed v5 %d, v7 %d, "
              "pairs %d (%d steps), hops %d, cancelled %d, boundary added %d\n",
              GetParam().name, LiveVertices(m), before.interior, total.interiorAfter, before.boundary,
              total.boundaryAfter, total.absorbedV5, total.absorbedV7, total.absorbedPairs, total.pairSteps,
              total.hops, total.cancelled, total.boundaryAdded);
}

TEST_P(BoundaryReductionCorpus, AngleAndHausdorffGuard) {
  TMesh m;
  std::unique_ptr<SurfaceProjector> input;
  Remeshed(m, GetParam(), &input);
  if (HasFatalFailure()) return;
  const IrregularByPlace before = CountIrregularByPlace(m);
  const double angleBefore = MeasureShape(m).minAngleDeg;
  MeshEditor<TMesh> ed(m);
  AngleHausdorffGuard guard(m, ed, *input);
  BoundaryReduction<TMesh> br(ed, input.get(), guard.Make());
  BoundaryReductionReport r = br.Run();
  BoundaryReductionReport r2 = br.Run();
  EXPECT_EQ(guard.broken, 0) << guard.firstProblem;
  EXPECT_LT(r2.interiorAfter, before.interior);
  EXPECT_LE(r2.boundaryAfter, before.boundary);
  const IrregularByPlace now = CountIrregularByPlace(m);
  EXPECT_EQ(now.interior, r2.interiorAfter);
  EXPECT_EQ(now.boundary, r2.boundaryAfter);
  EXPECT_EQ(CountFoldedEdges(m), 0);
  EXPECT_GE(MeasureShape(m).minAngleDeg, std::min(angleBefore, 30.0) - 1e-6);
  ed.Commit();
  ExpectValid(m);
  std::printf("%s (%d vertices), angle/Hausdorff guard: interior %d -> %d, boundary %d -> %d; absorbed v5 %d, "
              "v7 %d, pairs %d, hops %d, cancelled %d, boundary added %d, undone %d (angle %d, distance %d)\n",
              GetParam().name, LiveVertices(m), before.interior, now.interior, before.boundary, now.boundary,
              r.absorbedV5 + r2.absorbedV5, r.absorbedV7 + r2.absorbedV7, r.absorbedPairs + r2.absorbedPairs,
              r.hops + r2.hops,
              r.cancelled + r2.cancelled,
              r.boundaryAdded + r2.boundaryAdded, r.undone + r2.undone, guard.angleRefusals, guard.distanceRefusals);
}

// The stage once more after a whole reduction (which already runs it once per sweep), on what
// is left near the holes. The limit is the input's boundary count; the reduction's edit guard
// keeps the count at most that, and the stage may only lower it further.
TEST(BoundaryReductionRuns, AfterTheInteriorReductionOnMeshWithBorder) {
  TMesh m;
  std::unique_ptr<SurfaceProjector> input;
  Remeshed(m, CorpusCase{"mesh_with_border.off", 3000}, &input);
  if (HasFatalFailure()) return;
  const IrregularByPlace remeshed = CountIrregularByPlace(m);
  {
    AutomaticReduction<TMesh> ar(m, *input);
    ASSERT_TRUE(ar.Run());
  }
  const IrregularByPlace reduced = CountIrregularByPlace(m);
  EXPECT_LE(reduced.boundary, remeshed.boundary);
  MeshEditor<TMesh> ed(m);
  AngleHausdorffGuard guard(m, ed, *input);
  BoundaryReductionOptions opt;
  opt.boundaryLimit = remeshed.boundary;
  BoundaryReduction<TMesh> br(ed, input.get(), guard.Make(), nullptr, opt);
  int kept = 0;
  for (int call = 0; call < 3; ++call) {
    BoundaryReductionReport r = br.Run();
    kept += r.Kept();
    EXPECT_LE(r.boundaryAfter, std::max(remeshed.boundary, r.boundaryBefore));
    if (r.Kept() == 0) break;
  }
  EXPECT_EQ(guard.broken, 0) << guard.firstProblem;
  const IrregularByPlace now = CountIrregularByPlace(m);
  EXPECT_LE(now.interior, reduced.interior);
  EXPECT_LE(now.boundary, std::max(remeshed.boundary, reduced.boundary));
  EXPECT_EQ(CountFoldedEdges(m), 0);
  ed.Commit();
  ExpectValid(m);
  std::printf("mesh_with_border (%d vertices): remeshed interior %d / boundary %d -> reduced %d / %d -> boundary "
              "stage %d / %d (%d edits kept; guard refused %d by angle, %d by distance)\n",
              LiveVertices(m), remeshed.interior, remeshed.boundary, reduced.interior, reduced.boundary, now.interior,
              now.boundary, kept, guard.angleRefusals, guard.distanceRefusals);
}

// Two runs on the same input give the same mesh (no clock, no hash order in the decisions).
TEST(BoundaryReductionRuns, Deterministic) {
  TMesh a, b;
  std::unique_ptr<SurfaceProjector> input;
  Remeshed(a, CorpusCase{"holes.off", 3000}, &input);
  if (HasFatalFailure()) return;
  vcg::tri::Append<TMesh, TMesh>::MeshCopy(b, a);
  test::UpdateTopology(b);
  std::vector<BoundaryReductionReport> reports;
  for (TMesh* m : {&a, &b}) {
    MeshEditor<TMesh> ed(*m);
    AngleHausdorffGuard guard(*m, ed, *input);
    BoundaryReduction<TMesh> br(ed, input.get(), guard.Make());
    reports.push_back(br.Run());
    ed.Commit();
  }
  EXPECT_GT(reports[0].Kept(), 0);
  EXPECT_EQ(reports[0].Kept(), reports[1].Kept());
  EXPECT_EQ(reports[0].undone, reports[1].undone);
  EXPECT_EQ(test::CanonicalFaces(a), test::CanonicalFaces(b));
  ASSERT_EQ(a.vert.size(), b.vert.size());
  for (size_t i = 0; i < a.vert.size(); ++i)
    if (!a.vert[i].IsD()) EXPECT_EQ(a.vert[i].P(), b.vert[i].P()) << "vertex " << i;
}

INSTANTIATE_TEST_SUITE_P(Holes, BoundaryReductionCorpus,
                         ::testing::Values(CorpusCase{"mushroom.off", 3000}, CorpusCase{"holes.off", 3000},
                                           CorpusCase{"three_peaks.off", 3000},
                                           CorpusCase{"mesh_with_border.off", 3000}),
                         [](const ::testing::TestParamInfo<CorpusCase>& i) {
                           std::string n = i.param.name;
                           return n.substr(0, n.find('.'));
                         });
