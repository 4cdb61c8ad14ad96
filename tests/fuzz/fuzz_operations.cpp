// Randomized run of every editing operation (tests/fuzz/operation_fuzzer.h) on procedural and
// corpus meshes. The test command runs a short, fixed-seed run; a long run is e.g.
//   build/tests/fuzz_operations --seconds 3600 --steps 5000
// (new seeds until the time is up). Exit status 1 and the failing seed, mesh and step on the
// first broken promise.
//   usage: fuzz_operations [--steps N] [--seconds S] [--seed K] [corpus.off ...]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "operation_fuzzer.h"

namespace {

struct NamedMesh {
  std::string name;
  std::function<bool(fuzz::TMesh&)> make;
};

std::vector<NamedMesh> Meshes(const std::vector<std::string>& corpus) {
  std::vector<NamedMesh> out = {
      {"icosphere(2)", [](fuzz::TMesh& m) { test::Icosphere(m, 2); return true; }},
      {"torus 24x12", [](fuzz::TMesh& m) { test::RegularTorus(m, 24, 12, 3.f, 1.f); return true; }},
      {"hexagonal patch (boundary)", [](fuzz::TMesh& m) { test::HexPatch(m, 6); return true; }},
  };
  for (const std::string& c : corpus) out.push_back({c, [c](fuzz::TMesh& m) { return test::LoadCorpus(m, c); }});
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  int steps = 400;
  double seconds = 0;
  uint32_t seed = 1;
  std::vector<std::string> corpus;
  for (int i = 1; i < argc; ++i) {
    auto next = [&] { return i + 1 < argc ? argv[++i] : "0"; };
    if (!std::strcmp(argv[i], "--steps")) steps = std::atoi(next());
    else if (!std::strcmp(argv[i], "--seconds")) seconds = std::atof(next());
    else if (!std::strcmp(argv[i], "--seed")) seed = uint32_t(std::atol(next()));
    else corpus.push_back(argv[i]);
  }
  if (corpus.empty()) corpus = {"knot1.off", "elephant.off", "mesh_with_border.off"};
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  std::map<fuzz::Op, int> applied, refused;
  long total = 0;
  int rounds = 0;
  do {
    for (const NamedMesh& nm : Meshes(corpus)) {
      fuzz::TMesh m;
      if (!nm.make(m)) {
        std::printf("skip %s (missing)\n", nm.name.c_str());
        continue;
      }
      fuzz::RandomChoices choices(seed);
      fuzz::OperationFuzzer fz(m, choices);
      fuzz::FuzzStats st = fz.Run(steps);
      total += st.steps;
      for (auto& kv : st.applied) applied[kv.first] += kv.second;
      for (auto& kv : st.refused) refused[kv.first] += kv.second;
      if (!st.ok()) {
        std::printf("FAILED: seed %u, mesh %s, %s\n", seed, nm.name.c_str(), st.failure.c_str());
        return 1;
      }
    }
    ++seed;
    ++rounds;
  } while (elapsed() < seconds);
  std::printf("%ld random operations in %d round(s), %.1f s, every check held\n", total, rounds, elapsed());
  std::printf("%-32s %8s %8s\n", "operation", "applied", "refused");
  for (int o = 0; o < int(fuzz::Op::Count); ++o)
    std::printf("%-32s %8d %8d\n", fuzz::OpName(fuzz::Op(o)), applied[fuzz::Op(o)], refused[fuzz::Op(o)]);
  return 0;
}
