// Benchmark: a composite pair move of L steps costs O(L) (paper sec. 7.1), on a 1M-face mesh.
// Mesh: a regular torus of 708 x 708 x 2 = 1,002,528 faces (a corpus model subdivided four
// times, knot1, is used for L = 10 and 100: its own irregular vertices block longer paths).
#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include <vcg_ext/irregular/composite_ops.h>

#include "../tests/unit/test_mesh.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {

struct Fixture {
  TMesh m;
  std::unique_ptr<SurfaceProjector> original;
};

Fixture* Torus() {
  static std::unique_ptr<Fixture> f;
  if (f) return f.get();
  f.reset(new Fixture);
  test::RegularTorus(f->m, 708, 708, 200.f, 60.f);
  f->original.reset(new SurfaceProjector(f->m));
  return f.get();
}

void BM_MovePairLSteps(benchmark::State& st) {
  Fixture* f = Torus();
  const int L = int(st.range(0));
  CompositeOptions opt;
  opt.relax = st.range(1) != 0;
  MeshEditor<TMesh> ed(f->m);
  CompositeOperations<TMesh> co(ed, f->original.get(), opt);
  const auto setup = ed.Mark();
  AtomicOutcome g = co.atomic().GenerateQuadruple(354 * 708 + 354, 0, false);
  if (!g) {
    st.SkipWithError(g.result.reason.c_str());
    return;
  }
  const int v5 = g.irregular[0], v7 = g.irregular[2];
  // the direction that leads away from the partner pair
  int dir = -1;
  for (int d = 0; d < 6 && dir < 0; ++d) {
    auto cp = ed.Mark();
    if (co.MoveAdjacentPair57(v5, v7, d, 3)) dir = d;
    ed.RollbackTo(cp);
  }
  int ok = 0;
  for (auto _ : st) {
    auto cp = ed.Mark();
    CompositeOutcome o = co.MoveAdjacentPair57(v5, v7, dir, L);
    ok += o.result.ok;
    if (!o) st.SkipWithError(o.result.reason.c_str());
    st.PauseTiming();
    ed.RollbackTo(cp);
    st.ResumeTiming();
  }
  ed.RollbackTo(setup);
  st.counters["faces"] = double(f->m.fn);
  st.counters["us_per_step"] = benchmark::Counter(double(L) * double(st.iterations()), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  st.counters["ok"] = ok;
}

}  // namespace

BENCHMARK(BM_MovePairLSteps)->ArgsProduct({{10, 100, 1000}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
