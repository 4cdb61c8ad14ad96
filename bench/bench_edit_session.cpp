// Benchmark of the interactive edit tool's logic (vcg_ext/irregular/edit_session.h, issue 16):
// on a regular torus of about 1M faces with one generated 5-5-7-7 quadruple, a pair is picked
// and moved step by step; each key press costs Step(k) plus the Directions() of the new state
// (the arrows the GUI draws next), and each Ctrl+Z an Undo(). Prints median and max per step
// in ms. The GUI's re-upload of buffers is not part of it. Step(k) runs on a known arrow, so it
// applies that arrow's captured trial (edit_session.h); each of the six trials is also timed
// alone (the GUI computes them one per idle tick).
//   usage: bench_edit_session [faces=1000000] [steps=200] [pair=adjacent|apart|same] [relax=1]
//   adjacent: the generated adjacent 5-7 pair; apart: the v5 of one pair with the v7 of the
//   other (a non-adjacent 5-7 pair, sec. 7.1.1 pipeline); same: the two v5 (a 5-5 pair).
// The setup (the frozen original surface, the picking grid) is timed separately: it runs once
// per use of the tool.
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <vcg_ext/irregular/edit_session.h>

#include "../tests/unit/test_mesh.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {
typedef std::chrono::steady_clock Clock;
double Ms(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }
/// This thread's CPU time in ms: unlike wall time, not inflated when the scheduler gives the
/// core to another process for a tick (4 ms at HZ = 250) on a shared machine.
double CpuMs() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

struct Stats {
  std::vector<double> t;
  void Add(double x) { t.push_back(x); }
  void Print(const char* what) {
    if (t.empty()) return;
    std::vector<double> s = t;
    std::sort(s.begin(), s.end());
    std::printf("  %-34s n=%4zu  median %7.3f ms  p90 %7.3f ms  max %7.3f ms\n", what, s.size(), s[s.size() / 2],
                s[std::min(s.size() - 1, s.size() * 9 / 10)], s.back());
  }
};
}  // namespace

int main(int argc, char** argv) {
  const long faces = argc > 1 ? std::atol(argv[1]) : 1000000;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 200;
  const std::string pair = argc > 3 ? argv[3] : "adjacent";
  const bool relax = argc > 4 ? std::atoi(argv[4]) != 0 : true;
  // an n x k torus has 2nk faces; k = n / 2 keeps the triangles near equilateral for R = 3r
  const int n = std::max(20, int(std::lround(std::sqrt(double(faces))))), k = std::max(10, n / 2);
  TMesh m;
  auto t0 = Clock::now();
  test::RegularTorus(m, n, k, 3.f, 1.f);
  auto t1 = Clock::now();
  std::printf("torus %d x %d: %zu vertices, %zu faces (built in %.0f ms)\n", n, k, m.vert.size(), m.face.size(), Ms(t0, t1));
  int p5, p7, o5, o7;
  {
    SurfaceProjector original(m);
    MeshEditor<TMesh> ed(m);
    CompositeOperations<TMesh> co(ed, &original);
    CompositeOutcome g = co.GenerateQuadruple((n / 2) * k + k / 2, 0, 6);
    if (!g) {
      std::printf("generation refused: %s\n", g.result.reason.c_str());
      return 1;
    }
    p5 = g.pair5, p7 = g.pair7, o5 = g.other5, o7 = g.other7;
  }
  EditSessionOptions opt;
  opt.relax = relax;
  t0 = Clock::now();
  EditSession<TMesh> s(m, opt);
  t1 = Clock::now();
  std::printf("session start (frozen original surface): %.0f ms\n", Ms(t0, t1));
  t0 = Clock::now();
  Result r = s.PickAt(m.vert[size_t(p5)].P());
  t1 = Clock::now();
  std::printf("first pick (builds the picking grid): %.1f ms: %s\n", Ms(t0, t1), s.Message().c_str());
  if (!r) return 1;
  t0 = Clock::now();
  s.PickAt(m.vert[size_t(p5)].P());
  t1 = Clock::now();
  std::printf("second pick: %.3f ms\n", Ms(t0, t1));
  if (pair == "apart") s.PickPartner(o7);
  else if (pair == "same") s.PickPartner(o5);
  else if (s.Partner() != p7) s.PickPartner(p7);
  std::printf("pair: %d (valence %s) and %d, %s, relax %d\n", s.Lead(), pair == "same" ? "5-5" : "5-7", s.Partner(),
              pair.c_str(), int(relax));

  Stats dirs, step, trial, press, pressCpu, undo;
  std::mt19937 rng(1);
  t0 = Clock::now();
  s.Directions();
  t1 = Clock::now();
  dirs.Add(Ms(t0, t1));
  int done = 0;
  for (int i = 0; i < steps; ++i) {
    std::vector<int> ok;
    for (auto& d : s.Directions())
      if (d.accepted) ok.push_back(d.k);
    if (ok.empty()) break;
    // a random walk that mostly keeps one heading, like a user holding a key
    const int kk = (rng() % 4 != 0 && std::count(ok.begin(), ok.end(), i / 25 % 6)) ? i / 25 % 6 : ok[rng() % ok.size()];
    const double cpu0 = CpuMs();
    auto a = Clock::now();
    Result sr = s.Step(kk);
    auto b = Clock::now();
    const double stepCpu = CpuMs() - cpu0;
    double slowest = 0;
    int slowK = -1;
    for (int d = 0; d < 6; ++d) {  // = Directions(), one trial at a time to name the slow one
      auto x = Clock::now();
      const double tc = CpuMs();
      s.Direction(d);
      const double t = Ms(x, Clock::now());
      trial.Add(CpuMs() - tc);
      if (t > slowest) slowest = t, slowK = d;
    }
    auto c = Clock::now();
    const double cpu = CpuMs() - cpu0;
    if (!sr) {
      std::printf("step %d refused: %s\n", i, s.Message().c_str());
      break;
    }
    ++done;
    if (Ms(a, c) > 4)
      std::printf("  slow key press %d: step %.2f ms, directions %.2f ms (slowest: direction %d, %.2f ms, %s); CPU %.2f ms\n",
                  i, Ms(a, b), Ms(b, c), slowK + 1, slowest, s.Direction(slowK).accepted ? "accepted" : "refused", cpu);
    step.Add(stepCpu);
    dirs.Add(Ms(b, c));
    press.Add(Ms(a, c));
    pressCpu.Add(cpu);
  }
  // what the steps did, to compare two builds: a hash of every position and face corner
  unsigned long long h = 1469598103934665603ull;
  auto mix = [&h](unsigned long long x) { h = (h ^ x) * 1099511628211ull; };
  for (const auto& v : m.vert)
    for (int c = 0; c < 3; ++c) {
      float f = v.cP()[c];
      unsigned int bits;
      std::memcpy(&bits, &f, sizeof bits);
      mix(bits);
    }
  for (const auto& f : m.face)
    for (int c = 0; c < 3; ++c) mix((unsigned long long)(f.cV(c) - &m.vert[0]));
  std::printf("after %d steps: %zu vertices, %zu faces, pair %d-%d, state hash %016llx\n", done, m.vert.size(),
              m.face.size(), s.Lead(), s.Partner(), h);
  while (s.UndoDepth() > 0) {
    auto a = Clock::now();
    s.Undo();
    auto b = Clock::now();
    undo.Add(Ms(a, b));
  }
  std::printf("%d steps done, then undone\n", done);
  step.Print("Step(k), replayed, CPU");
  trial.Print("one arrow's trial, CPU");
  dirs.Print("Directions() (six trial steps)");
  press.Print("key press: Step + Directions");
  pressCpu.Print("key press, CPU time of the thread");
  undo.Print("Undo()");
  return 0;
}
