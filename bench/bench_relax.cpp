// Benchmark: relaxation (paper sec. 8) on ~10K, ~200K (104K vertices) and ~1.2M faces:
// one local sweep over the whole mesh, one global round (assembly + sparse LDLT + projection),
// and a local relaxation of the 2-ring around one edit, as the composite filters run after
// every step.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include <vcg_ext/irregular/quality.h>
#include <vcg_ext/irregular/relaxation.h>

#include "../tests/unit/test_mesh.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {

struct Fixture {
  TMesh m;
  std::unique_ptr<SurfaceProjector> original;
  std::vector<int> all;
};

const char* kMesh[] = {"hand.off", "armadillo.off", "bunny00.off"};
const int kRefine[] = {1, 1, 2};

Fixture* Load(int which) {
  static std::map<int, std::unique_ptr<Fixture>> cache;
  auto& f = cache[which];
  if (f) return f.get();
  f.reset(new Fixture);
  if (!test::LoadCorpus(f->m, kMesh[which])) test::Icosphere(f->m, 5);
  for (int r = 0; r < kRefine[which]; ++r) {
    vcg::tri::UpdateTopology<TMesh>::FaceFace(f->m);
    vcg::tri::Refine<TMesh, vcg::tri::MidPoint<TMesh>>(f->m, vcg::tri::MidPoint<TMesh>(&f->m), 0);
  }
  test::UpdateTopology(f->m);
  f->original.reset(new SurfaceProjector(f->m));
  for (size_t i = 0; i < f->m.vert.size(); ++i) f->all.push_back(int(i));
  return f.get();
}

void Counters(benchmark::State& st, Fixture* f) {
  st.counters["faces"] = double(f->m.fn);
  st.counters["vertices"] = double(f->m.vn);
}

void BM_LocalSweepWholeMesh(benchmark::State& st) {
  Fixture* f = Load(int(st.range(0)));
  RelaxOptions o;
  o.iterations = 1;
  for (auto _ : st) LocalRelax(f->m, f->all, f->original.get(), o);
  Counters(st, f);
}

void BM_GlobalRoundWholeMesh(benchmark::State& st) {
  Fixture* f = Load(int(st.range(0)));
  RelaxOptions o;
  o.mode = RelaxMode::Global;
  o.iterations = 1;
  double solve = 0;
  for (auto _ : st) solve += GlobalRelax(f->m, f->all, f->original.get(), o).solveSeconds;
  st.counters["solve_s"] = solve / double(st.iterations());
  Counters(st, f);
}

// What a composite operation runs after each step: 5 local sweeps over the 2-ring of an edit.
void BM_LocalTwoRingAfterEdit(benchmark::State& st) {
  Fixture* f = Load(int(st.range(0)));
  RelaxOptions o;
  o.iterations = 5;
  size_t k = 0;
  for (auto _ : st) {
    int v = int((k++ * 7919) % f->m.vert.size());
    std::vector<int> ring = KRing(f->m, {v}, 2);
    LocalRelax(f->m, ring, f->original.get(), o);
  }
  Counters(st, f);
}

}  // namespace

BENCHMARK(BM_LocalSweepWholeMesh)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_GlobalRoundWholeMesh)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_LocalTwoRingAfterEdit)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
