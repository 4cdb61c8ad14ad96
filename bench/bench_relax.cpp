// Benchmark: relaxation (paper sec. 8) on ~10K, ~200K (104K vertices) and ~1.2M faces:
// one local sweep over the whole mesh, one global round (assembly + conjugate gradients +
// guarded step), and a local or global relaxation of the 2-ring around one edit, as the
// composite filters run after every step (its time must not grow with the mesh: O(region)).
// BM_GlobalQuality: the Relax filter's global mode (10 rounds, creases over 60 degrees fixed,
// boundary sliding) on raw corpus meshes, with the smallest angle, the share of triangles
// under 30 degrees and eq. 5's energy before and after as counters.
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

// What a composite operation runs after each step: the relaxation of the 2-ring of an edit
// (5 local sweeps, or 3 global rounds). O(region): its time must not grow with the mesh.
void TwoRingAfterEdit(benchmark::State& st, RelaxMode mode) {
  Fixture* f = Load(int(st.range(0)));
  RelaxOptions o;
  o.mode = mode;
  o.iterations = mode == RelaxMode::Global ? 3 : 5;
  size_t k = 0;
  for (auto _ : st) {
    int v = int((k++ * 7919) % f->m.vert.size());
    std::vector<int> ring = KRing(f->m, {v}, 2);
    Relax(f->m, ring, f->original.get(), o);
  }
  Counters(st, f);
}
void BM_LocalTwoRingAfterEdit(benchmark::State& st) { TwoRingAfterEdit(st, RelaxMode::Local); }
void BM_GlobalTwoRingAfterEdit(benchmark::State& st) { TwoRingAfterEdit(st, RelaxMode::Global); }

const char* kQualityMesh[] = {"bear.off", "bunny00.off", "fandisk.off"};

void BM_GlobalQuality(benchmark::State& st) {
  const char* name = kQualityMesh[st.range(0)];
  RelaxReport total;
  ShapeMeasures before, after;
  int moved = 0;
  for (auto _ : st) {
    st.PauseTiming();
    TMesh m;
    if (!test::LoadCorpus(m, name)) {
      st.SkipWithError("corpus mesh missing (run scripts/setup.sh)");
      return;
    }
    SurfaceProjector original(m);
    BoundaryCurve curve(m);
    std::vector<char> crease = CreaseVertices(m, 60);
    std::vector<int> all;
    for (size_t i = 0; i < m.vert.size(); ++i) all.push_back(int(i));
    RelaxOptions o;
    o.mode = RelaxMode::Global;
    o.iterations = 10;
    o.featureAngleDeg = 60;
    o.boundaryCurve = &curve;
    before = MeasureShape(m);
    st.ResumeTiming();
    total = GlobalRelax(m, all, &original, o, &crease);
    st.PauseTiming();
    after = MeasureShape(m);
    moved = total.moved;
    st.ResumeTiming();
  }
  st.SetLabel(name);
  st.counters["min_angle_before"] = before.minAngleDeg;
  st.counters["min_angle_after"] = after.minAngleDeg;
  st.counters["pct_below30_before"] = 100 * before.shareBelow30;
  st.counters["pct_below30_after"] = 100 * after.shareBelow30;
  st.counters["energy_before"] = total.energyBefore;
  st.counters["energy_after"] = total.energyAfter;
  st.counters["rounds"] = total.rounds;
  st.counters["moves"] = moved;
}

}  // namespace

BENCHMARK(BM_LocalSweepWholeMesh)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_GlobalRoundWholeMesh)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_LocalTwoRingAfterEdit)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_GlobalTwoRingAfterEdit)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_GlobalQuality)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_MAIN();
