// Unit tests of vcg_ext/irregular/composite_prediction.h: the dry runs of the composite
// operations agree with the real operations on random requests (fixed seed), and leave the
// user's mesh bit-identical.
#include <gtest/gtest.h>

#include <cstdio>
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
  int requests = 0, agreed = 0, applied = 0, exact = 0, inexactDisagreed = 0;
};

/// Predicts, checks the mesh is untouched, applies, compares the verdict and named results.
/// Returns the real outcome (the mesh is edited when it succeeds).
template <class Predict, class Apply>
CompositeOutcome Check(TMesh& m, Predict predict, Apply apply, Tally& t, const std::string& what) {
  const test::MeshSnapshot before = test::Snapshot(m);
  const int n0 = int(m.vert.size());
  CompositePrediction p = predict();
  EXPECT_TRUE(test::Snapshot(m) == before) << what << ": the prediction changed the mesh";
  CompositeOutcome o = apply();
  ++t.requests;
  t.exact += p.exact;
  bool same = bool(p) == bool(o);
  if (same && o) {
    ++t.applied;
    same = p.irregular == o.irregular && p.atomicSteps == o.atomicSteps && p.lead == o.lead &&
           p.partner == o.partner && p.survivor == o.survivor && p.pair5 == o.pair5 && p.pair7 == o.pair7 &&
           p.other5 == o.other5 && p.other7 == o.other7;
    for (int c : p.created) same = same && c >= n0 && c < int(m.vert.size()) && !m.vert[size_t(c)].IsD();
    for (int d : p.deleted) same = same && d < n0 && m.vert[size_t(d)].IsD();
  }
  if (!o) EXPECT_TRUE(test::Snapshot(m) == before) << what;
  t.agreed += same;
  if (p.exact) EXPECT_TRUE(same) << what << ": predicted " << (p ? "ok" : p.result.reason) << ", real "
                                 << (o ? "ok" : o.result.reason);
  else t.inexactDisagreed += !same;
  return o;
}

void RandomRequests(TMesh& base, const char* name, int rounds, unsigned seed) {
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
    const int kind = r % 3;
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
  std::printf("%s: %d requests, %d predictions agree with the real operation (%d applied), %d exact, "
              "%d inexact disagreed\n", name, t.requests, t.agreed, t.applied, t.exact, t.inexactDisagreed);
  EXPECT_GT(t.applied, 0) << name;
}
}  // namespace

TEST(CompositePrediction, TorusRandomRequestsAgree) {
  TMesh m;
  test::RegularTorus(m, 24, 12);
  RandomRequests(m, "torus", 30, 7u);
}

TEST(CompositePrediction, IcosphereRandomRequestsAgree) {
  TMesh m;
  test::Icosphere(m, 3);
  RandomRequests(m, "icosphere", 30, 11u);
}

TEST(CompositePrediction, Knot1RandomRequestsAgree) {
  TMesh m;
  ASSERT_TRUE(test::LoadCorpus(m, "knot1.off"));
  test::UpdateTopology(m);
  RandomRequests(m, "knot1", 30, 13u);
}
