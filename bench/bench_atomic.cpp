// Benchmark: cost of each atomic operation (paper sec. 6.2) on a ~10K-face mesh (hand, subdivided once) and a
// ~1.2M-face mesh (bunny00 subdivided twice). Local edits must cost the same on both.
//   build/bench/bench_atomic [--benchmark_filter=...]
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include <vcg_ext/irregular/atomic_ops.h>

#include "../tests/unit/test_mesh.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {

struct Fixture {
  TMesh m;
  std::vector<int> targets;  // regular vertices with a regular 1-ring, spread over the mesh
};

Fixture* Load(const char* name, int refinements) {
  static std::map<std::string, std::unique_ptr<Fixture>> cache;
  std::string key = std::string(name) + std::to_string(refinements);
  auto& slot = cache[key];
  if (slot) return slot.get();
  slot.reset(new Fixture);
  TMesh& m = slot->m;
  if (!test::LoadCorpus(m, name)) test::Icosphere(m, 5);
  for (int r = 0; r < refinements; ++r) {
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    vcg::tri::Refine<TMesh, vcg::tri::MidPoint<TMesh>>(m, vcg::tri::MidPoint<TMesh>(&m), 0);
  }
  test::UpdateTopology(m);
  // (No reserve(): it would move the vectors behind vcg's back. Splits that grow them pay an
  // amortized O(1) reallocation, done by vcg's Allocator, which fixes every pointer.)
  auto vf = ComputeValences(m);
  MeshEditor<TMesh> ed(m);
  for (size_t i = 0; i < m.vert.size() && slot->targets.size() < 64; i += 7) {
    if (vf.valence[i] != 6 || vf.boundary[i]) continue;
    bool ok = true;  // regular 3-ring: no direction is blocked by the mesh's own irregular vertices
    std::vector<int> ring{int(i)};
    for (int r = 0; r < 3 && ok; ++r) {
      std::vector<int> next;
      for (int q : ring)
        for (auto n : ed.Star(q).neighbors) {
          int ni = int(vcg::tri::Index(m, n));
          ok = ok && vf.valence[size_t(ni)] == 6 && !vf.boundary[size_t(ni)];
          next.push_back(ni);
        }
      ring = next;
    }
    if (ok) slot->targets.push_back(int(i));
  }
  return slot.get();
}

const char* kMesh[] = {"hand.off", "bunny00.off"};  // 2390 faces x 4 = 9560; 75408 x 16
const int kRefine[] = {1, 2};

void Label(benchmark::State& st, Fixture* f) {
  st.counters["faces"] = double(f->m.fn);
}

// 5-5-7-7 generation by flip and its removal (two edge flips).
void BM_QuadrupleFlipRoundTrip(benchmark::State& st) {
  Fixture* f = Load(kMesh[st.range(0)], kRefine[st.range(0)]);
  MeshEditor<TMesh> ed(f->m);
  AtomicOperations<TMesh> ops(ed);
  size_t k = 0;
  int applied = 0;
  for (auto _ : st) {
    int v = f->targets[k++ % f->targets.size()];
    AtomicOutcome g = ops.GenerateQuadruple(v, 0, false);
    AtomicOutcome r = ops.RemoveQuadruple(g.irregular);
    applied += r.result.ok;
    ed.Commit();
  }
  st.counters["applied"] = applied;
  Label(st, f);
}

// 5-5-7-7 generation by vertex split and its removal (an edge collapse).
void BM_QuadrupleSplitCollapseRoundTrip(benchmark::State& st) {
  Fixture* f = Load(kMesh[st.range(0)], kRefine[st.range(0)]);
  MeshEditor<TMesh> ed(f->m);
  AtomicOperations<TMesh> ops(ed);
  size_t k = 0;
  int applied = 0;
  for (auto _ : st) {
    int v = f->targets[k++ % f->targets.size()];
    AtomicOutcome g = ops.GenerateQuadruple(v, 0, true);
    AtomicOutcome r = ops.RemoveQuadruple(g.irregular);
    applied += r.result.ok;
    ed.Commit();
  }
  st.counters["applied"] = applied;
  Label(st, f);
}

// One 5-7 pair move in direction `dir`, undone by the journal (rollback is O(touched) too).
void BM_PairMove(benchmark::State& st) {
  Fixture* f = Load(kMesh[st.range(0)], kRefine[st.range(0)]);
  const int dir = int(st.range(1));
  MeshEditor<TMesh> ed(f->m);
  AtomicOperations<TMesh> ops(ed);
  // a 5-7 pair: generate a quadruple, then move one pair away from the other
  int v = f->targets[0];
  const auto setup = ed.Mark();  // undone at the end: the framework calls this several times
  AtomicOutcome g = ops.GenerateQuadruple(v, 0, false);
  if (!g) {
    st.SkipWithError(g.result.reason.c_str());
    return;
  }
  int v5 = g.irregular[0], v7 = g.irregular[2];
  // move the pair 3 steps away from its partner so that no direction is blocked
  const auto other = f->m.vert[size_t(g.irregular[1])].P();
  for (int s = 0; s < 3; ++s) {
    int best = -1;
    float bestDist = -1;
    for (int d = 0; d < 6; ++d) {
      auto cp = ed.Mark();
      AtomicOutcome o = ops.MovePair57(v5, v7, d);
      if (o && (f->m.vert[size_t(o.irregular[0])].P() - other).Norm() > bestDist)
        bestDist = (f->m.vert[size_t(o.irregular[0])].P() - other).Norm(), best = d;
      ed.RollbackTo(cp);
    }
    if (best < 0) break;
    AtomicOutcome o = ops.MovePair57(v5, v7, best);
    v5 = o.irregular[0];
    v7 = o.irregular[1];
  }
  int applied = 0;
  for (auto _ : st) {
    auto cp = ed.Mark();
    AtomicOutcome o = ops.MovePair57(v5, v7, dir);
    applied += o.result.ok;
    ed.RollbackTo(cp);
  }
  st.counters["applied"] = applied;
  Label(st, f);
  ed.RollbackTo(setup);
}

// v5/v7 move with 5-7 pair generation followed by its inverse (pair removal).
void BM_MoveWithGenerationAndRemoval(benchmark::State& st) {
  Fixture* f = Load(kMesh[st.range(0)], kRefine[st.range(0)]);
  MeshEditor<TMesh> ed(f->m);
  AtomicOperations<TMesh> ops(ed);
  const auto setup = ed.Mark();
  AtomicOutcome g;
  for (size_t t = 1; t < f->targets.size() && !g; ++t) g = ops.GenerateQuadruple(f->targets[t], 0, false);
  if (!g) {
    st.SkipWithError(g.result.reason.c_str());
    return;
  }
  const int v7 = g.irregular[2];
  int k = 0;
  for (int t = 0; t < 7; ++t) {
    auto cp = ed.Mark();
    if (ops.MoveWithPairGeneration(v7, t)) { k = t; ed.RollbackTo(cp); break; }
    ed.RollbackTo(cp);
  }
  int applied = 0;
  for (auto _ : st) {
    auto cp = ed.Mark();
    AtomicOutcome o = ops.MoveWithPairGeneration(v7, k);
    AtomicOutcome r = ops.MoveWithPairRemoval(o.irregular);
    applied += r.result.ok;
    ed.RollbackTo(cp);  // keeps the journal short; the removal already restored the faces
  }
  st.counters["applied"] = applied;
  Label(st, f);
  ed.RollbackTo(setup);
}

}  // namespace

BENCHMARK(BM_QuadrupleFlipRoundTrip)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_QuadrupleSplitCollapseRoundTrip)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PairMove)->ArgsProduct({{0, 1}, {0, 1, 2, 3, 4, 5}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MoveWithGenerationAndRemoval)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
