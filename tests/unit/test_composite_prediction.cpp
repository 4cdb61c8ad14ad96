// Unit tests of vcg_ext/irregular/composite_prediction.h: the dry runs of the composite
// operations agree with the real operations on random requests (fixed seed), and leave the
// user's mesh bit-identical.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <vcg_ext/irregular/composite_prediction.h>
#include <vcg_ext/irregular/mesh_checks.h>

#include "test_mesh.h"
#include "test_util.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {
struct Tally {
  int requests = 0, agreed = 0, applied = 0, exact = 0, grown = 0, inexactDisagreed = 0;
  std::map<std::string, std::array<int, 3>> byKind;  ///< requests, agreed, applied
};

std::string Ids(const std::vector<int>& v) {
  std::string s = "{";
  for (int x : v) s += (s.size() > 1 ? "," : "") + std::to_string(x);
  return s + "}";
}

/// Predicts, checks the mesh is untouched, applies, compares the verdict and named results.
/// Returns the real outcome (the mesh is edited when it succeeds).
template <class Predict, class Apply>
CompositeOutcome Check(TMesh& m, Predict predict, Apply apply, Tally& t, const std::string& what) {
  const test::MeshSnapshot before = test::Snapshot(m);
  const int n0 = int(m.vert.size());
  std::vector<char> liveBefore(m.vert.size());
  for (size_t i = 0; i < m.vert.size(); ++i) liveBefore[i] = !m.vert[i].IsD();
  CompositePrediction p = predict();
  EXPECT_TRUE(test::Snapshot(m) == before) << what << ": the prediction changed the mesh";
  CompositeOutcome o = apply();
  ++t.requests;
  t.exact += p.exact;
  t.grown += p.grown;
  bool same = bool(p) == bool(o);
  if (same && o) {
    ++t.applied;
    same = p.irregular == o.irregular && p.atomicSteps == o.atomicSteps && p.lead == o.lead &&
           p.partner == o.partner && p.survivor == o.survivor && p.pair5 == o.pair5 && p.pair7 == o.pair7 &&
           p.other5 == o.other5 && p.other7 == o.other7;
    // created / deleted: exactly the vertices the real operation added (live) and deleted
    std::vector<int> created, deleted;
    for (int i = n0; i < int(m.vert.size()); ++i)
      if (!m.vert[size_t(i)].IsD()) created.push_back(i);
    for (int i = 0; i < n0; ++i)
      if (liveBefore[size_t(i)] && m.vert[size_t(i)].IsD()) deleted.push_back(i);
    same = same && p.created == created && p.deleted == deleted;
  }
  if (!o) EXPECT_TRUE(test::Snapshot(m) == before) << what;
  t.agreed += same;
  auto& kind = t.byKind[what];
  ++kind[0], kind[1] += same, kind[2] += bool(o);
  if (p.exact)
    EXPECT_TRUE(same) << what << ": predicted " << (p ? "ok" : p.result.reason) << " in " << p.atomicSteps
                      << " steps leaving " << Ids(p.irregular) << " (created " << Ids(p.created) << ", deleted "
                      << Ids(p.deleted) << "), real " << (o ? "ok" : o.result.reason) << " in " << o.atomicSteps
                      << " steps leaving " << Ids(o.irregular);
  else t.inexactDisagreed += !same;
  return o;
}

void RandomRequests(TMesh& base, const char* name, int rounds, unsigned seed, int rings = 12) {
  std::mt19937 rng(seed);
  SurfaceProjector original(base);
  CompositeOptions opt;
  Tally t;
  auto vf = ComputeValences(base);
  std::vector<int> v57, v6;
  for (size_t i = 0; i < base.vert.size(); ++i) {
    if (base.vert[i].IsD()) continue;
    const int d = vf.valence[i];
    if (d == 5 || d == 7) v57.push_back(int(i));
    if (d == 6 && !vf.IsIrregular(i)) v6.push_back(int(i));
  }
  ASSERT_FALSE(v6.empty());
  auto pick = [&](const std::vector<int>& from) { return from[rng() % from.size()]; };
  for (int r = 0; r < rounds; ++r) {
    TMesh m;
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, base);
    test::UpdateTopology(m);
    MeshEditor<TMesh> ed(m);
    CompositeOperations<TMesh> co(ed, &original, opt);
    CompositePredictor<TMesh> pr(m, &original, opt);
    pr.rings = rings;
    const int kind = r % 4;
    const int k = int(rng() % 7), spacing = 1 + int(rng() % 3);
    if (kind == 0 && !v57.empty()) {
      // a triple, then its cancellation or a pair movement
      const int v = pick(v57);
      CompositeOutcome g = Check(m, [&] { return pr.PredictGenerateTriple(v, k, spacing); },
                                 [&] { return co.GenerateTriple(v, k, spacing); }, t, "GenerateTriple");
      if (!g) continue;
      ed.Commit();
      if (rng() % 2) {
        const std::vector<int> tri = g.irregular;
        Check(m, [&] { return pr.PredictCancelTriple(tri); }, [&] { return co.CancelTriple(tri); }, t, "CancelTriple");
      } else {
        const int lead = g.pair5, partner = g.survivor, kk = int(rng() % 6), steps = 1 + int(rng() % 2);
        Check(m, [&] { return pr.PredictMovePair(lead, partner, kk, steps); },
              [&] { return co.MovePair(lead, partner, kk, steps); }, t, "MovePair");
      }
    } else if (kind == 1) {
      const int v = pick(v6);
      CompositeOutcome g = Check(m, [&] { return pr.PredictGenerateQuadruple(v, k, spacing); },
                                 [&] { return co.GenerateQuadruple(v, k, spacing); }, t, "GenerateQuadruple");
      if (!g) continue;
      ed.Commit();
      const std::vector<int> quad = g.irregular;
      Check(m, [&] { return pr.PredictCancelQuadruple(quad); }, [&] { return co.CancelQuadruple(quad); }, t,
            "CancelQuadruple");
    } else if (kind == 3) {
      // a quadruple, then one of its pairs moved toward a point a few edges away
      const int v = pick(v6);
      CompositeOutcome g = Check(m, [&] { return pr.PredictGenerateQuadruple(v, k, 1); },
                                 [&] { return co.GenerateQuadruple(v, k, 1); }, t, "GenerateQuadruple");
      if (!g) continue;
      ed.Commit();
      int w = g.pair5;
      for (int s = 0, n = 2 + int(rng() % 4); s < n; ++s) {
        auto star = StarOf<TMesh>(&m.vert[size_t(w)]);
        w = int(vcg::tri::Index(m, star.neighbors[rng() % star.neighbors.size()]));
      }
      const int a5 = g.pair5, a7 = g.pair7;
      const TMesh::CoordType target = m.vert[size_t(w)].P();
      Check(m, [&] { return pr.PredictMovePair57Toward(a5, a7, target); },
            [&] { return co.MovePair57Toward(a5, a7, target); }, t, "MovePair57Toward");
    } else {
      const int v = pick(v6), dx = int(rng() % 6), dy = int(rng() % 6), x = 1 + int(rng() % 2), y = int(rng() % 2);
      CompositeOutcome g = Check(m, [&] { return pr.PredictGenerateQuadrupleShape(v, k, dx, x, dy, y); },
                                 [&] { return co.GenerateQuadrupleShape(v, k, dx, x, dy, y); }, t, "GenerateQuadrupleShape");
      if (!g) continue;
      ed.Commit();
      const int a5 = g.pair5, a7 = g.pair7, dir = int(rng() % 6), steps = 1 + int(rng() % 3);
      Check(m, [&] { return pr.PredictMoveAdjacentPair57(a5, a7, dir, steps); },
            [&] { return co.MoveAdjacentPair57(a5, a7, dir, steps); }, t, "MoveAdjacentPair57");
    }
    EXPECT_TRUE(CheckInvariants(m).ok) << name << ": " << CheckInvariants(m).reason;
  }
  std::printf("%s (rings %d): %d requests, %d predictions agree with the real operation (%d applied), %d exact, "
              "%d grown, %d inexact disagreed\n", name, rings, t.requests, t.agreed, t.applied, t.exact, t.grown,
              t.inexactDisagreed);
  for (auto& k : t.byKind) std::printf("  %-24s %3d requests, %3d agree, %3d applied\n", k.first.c_str(), k.second[0], k.second[1], k.second[2]);
  EXPECT_GT(t.applied, 0) << name;
  // a predictor that always answered "not exact" would pass the agreement check vacuously
  if (rings >= 12) EXPECT_GE(10 * t.exact, 9 * t.requests) << name << ": too few exact predictions";
  else EXPECT_GT(t.grown, 0) << name << ": the small region never had to grow";
  EXPECT_GE(10 * t.agreed, 9 * t.requests) << name;
}
}  // namespace

TEST(CompositePrediction, TorusRandomRequestsAgree) {
  TMesh m;
  test::RegularTorus(m, 24, 12);
  RandomRequests(m, "torus", 40, 7u);
}

TEST(CompositePrediction, IcosphereRandomRequestsAgree) {
  TMesh m;
  test::Icosphere(m, 3);
  RandomRequests(m, "icosphere", 40, 11u);
}

TEST(CompositePrediction, Knot1RandomRequestsAgree) {
  TMesh m;
  ASSERT_TRUE(test::LoadCorpus(m, "knot1.off"));
  test::UpdateTopology(m);
  RandomRequests(m, "knot1", 40, 13u);
}

// A region too small on purpose (no rings beyond the steps): the operations reach the cut
// border, the prediction grows once, and whatever it calls exact still agrees.
TEST(CompositePrediction, SmallRegionGrowsAndStaysHonest) {
  TMesh m;
  ASSERT_TRUE(test::LoadCorpus(m, "knot1.off"));
  test::UpdateTopology(m);
  RandomRequests(m, "knot1", 40, 17u, 0);
}


// MeshLab's CMeshO keeps adjacency and attributes as optional components: the scratch must
// enable them like the user's mesh (else no FF/VF there).
TEST(CompositePrediction, OptionalComponentsLikeCMeshO) {
  test::TOMesh m;
  TMesh base;
  test::RegularTorus(base, 24, 12);
  test::CopyAsCMeshO(base, m);
  SurfaceProjector original(m);
  int agreed = 0, applied = 0;
  std::mt19937 rng(5u);
  for (int r = 0; r < 10; ++r) {
    const int v = int(rng() % m.vert.size()), k = int(rng() % 6), spacing = 1 + int(rng() % 3);
    const std::vector<double> before = test::OcfSnapshot(m);
    CompositePredictor<test::TOMesh> pr(m, &original);
    CompositePrediction p = pr.PredictGenerateQuadruple(v, k, spacing);
    EXPECT_TRUE(test::OcfSnapshot(m) == before);
    MeshEditor<test::TOMesh> ed(m);
    CompositeOperations<test::TOMesh> co(ed, &original);
    const auto cp = ed.Mark();
    CompositeOutcome o = co.GenerateQuadruple(v, k, spacing);
    const bool same = bool(p) == bool(o) && (!o || (p.irregular == o.irregular && p.atomicSteps == o.atomicSteps));
    EXPECT_TRUE(same || !p.exact) << "vertex " << v;
    agreed += same;
    applied += bool(o);
    if (o) ed.RollbackTo(cp);  // next request on the same torus
  }
  std::printf("TOMesh torus: 10 requests, %d agree, %d applied\n", agreed, applied);
  EXPECT_GT(applied, 0);
}
