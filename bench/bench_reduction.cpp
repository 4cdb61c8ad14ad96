// Benchmark of the automatic reduction (vcg_ext/irregular/automatic_reduction.h) on corpus
// meshes, without MeshLab: each model is remeshed isotropically to about N vertices (vcglib's
// IsotropicRemeshing, the code behind MeshLab's "Isotropic Explicit Remeshing"), then reduced
// with the default options. Prints one row per model.
//   usage: bench_reduction [vertices=20000] [option=value ...] [model.off|model.ply ...]
// vertices 0: reduce the model as loaded (no remeshing). A model is a corpus name or a path
// (containing '/').
// options (ReductionOptions fields; maxTravel sets glideTravel and maxRefusals as the filter
// does, SetFilterTravel, unless they are given): maxTravel, glideTravel, targetsPerPair, maxSweeps,
// localRelaxIterations, minAngle, budget (Hausdorff, percent of the diagonal), maxRefusals
// (maxRefusalsPerRegion; 0: no bound), partialAbsorption (0/1), reuseDeadSlots (0/1), boundarySlide (0/1),
// refusedRouteMemo (0/1), farMeetingReach, farMeetingTravel (0: no far meetings), farMeetingRounds,
// nearMeetingTries (0: no near meetings), nearMeetingTriesPerKept, angleRepairRounds, angleRepairSlack, travelReference (travelReferenceVertices),
// maxTravelScale, creaseDeg, creaseStraightShare, anglePolish (anglePolishDeg; 0: none), anglePolishRounds, partialSweepUndo (0/1),
// angleFlips (0/1), aggregate (0/1: aggregateLeftovers), gatherRadius, gatherTries, gatherTriesPerGathered, boundaryRings, boundaryTravel (the boundary stage's rings and maxTravel).
// files: saveRemeshed=<path> writes the remeshed input (OFF), saveResult=<path> the result, for
// profiling the reduction alone on a fixed input and for comparing two runs byte by byte (with
// several models, the model's name is appended).
// memory (issue 14's memory target): timeLimit=<s> (0: none, the default), memory=1 prints the
// resident memory (VmRSS, VmHWM of /proc/self/status) at every stage the reduction reports and
// the peak of the whole process at the end; loadOnly=1 only loads the model(s) and saves them
// (saveResult), the baseline the reduction's peak is compared with; peakFile=<path> writes the
// process's peak (VmHWM, MiB) there at the end.
// The end-to-end comparison with MeshLab's remeshing through meshlabserver is
// scripts/bench_reduction.py; this executable isolates the algorithm's own time.
#include <chrono>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

#include <vcg/complex/algorithms/stat.h>
#include <wrap/io_trimesh/export_off.h>
#include <wrap/io_trimesh/import_off.h>
#include <wrap/io_trimesh/import_ply.h>

#include <vcg_ext/irregular/automatic_reduction.h>
#include <vcg_ext/irregular/quality.h>
#include <vcg_ext/irregular/remeshing.h>

#include "../tests/unit/test_mesh.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {
bool LoadPath(TMesh& m, const std::string& file) {
  // A PLY (such as the pymeshlab benchmark's saved peer output) loads bit-exact, so a native run
  // reproduces the filter's; OFF text rounds the coordinates.
  int mask = 0;
  const bool ply = file.size() > 4 && file.compare(file.size() - 4, 4, ".ply") == 0;
  if (ply ? vcg::tri::io::ImporterPLY<TMesh>::Open(m, file.c_str(), mask) != 0
          : vcg::tri::io::ImporterOFF<TMesh>::Open(m, file.c_str(), mask) != 0)
    return false;
  vcg::tri::Clean<TMesh>::RemoveUnreferencedVertex(m);
  vcg::tri::Allocator<TMesh>::CompactEveryVector(m);
  test::UpdateTopology(m);
  return true;
}

/// glibc's heap: what is allocated (in the heap and as separate mappings) and what the heap holds
/// freed (resident until trimmed), in MiB; zeros elsewhere.
struct HeapMiB {
  double used = 0, freed = 0;
};
HeapMiB Heap() {
  HeapMiB h;
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
  const struct mallinfo2 mi = mallinfo2();
  h.used = double(mi.uordblks + mi.hblkhd) / 1048576.0;
  h.freed = double(mi.fordblks) / 1048576.0;
#endif
  return h;
}

/// A line of /proc/self/status ("VmRSS", "VmHWM") in MiB, or -1 where there is none.
double StatusMiB(const char* key) {
  FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return -1;
  char line[256];
  double mib = -1;
  const size_t n = std::strlen(key);
  while (std::fgets(line, sizeof line, f))
    if (std::strncmp(line, key, n) == 0 && line[n] == ':') mib = std::atof(line + n + 1) / 1024.0;
  std::fclose(f);
  return mib;
}

void Save(TMesh& m, const std::string& file, const std::string& model, size_t models) {
  std::string out = file;
  if (models > 1) out += "." + model.substr(model.find_last_of('/') + 1);
  vcg::tri::io::ExporterOFF<TMesh>::Save(m, out.c_str());
}
}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 20000;
  std::vector<std::string> models;
  ReductionOptions opt;
  std::string saveRemeshed, saveResult, peakFile;
  bool memory = false, loadOnly = false, listLeftovers = false;
  int maxTravel = opt.maxTravel, glideTravel = -1, maxRefusals = -1;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    const size_t eq = a.find('=');
    if (eq == std::string::npos) {
      models.push_back(a);
      continue;
    }
    const std::string key = a.substr(0, eq);
    if (key == "saveRemeshed" || key == "saveResult" || key == "peakFile") {
      (key == "saveRemeshed" ? saveRemeshed : key == "saveResult" ? saveResult : peakFile) = a.substr(eq + 1);
      continue;
    }
    const double v = std::atof(a.c_str() + eq + 1);
    if (key == "maxTravel") maxTravel = int(v);
    else if (key == "glideTravel") glideTravel = int(v);
    else if (key == "targetsPerPair") opt.targetsPerPair = int(v);
    else if (key == "maxSweeps") opt.maxSweeps = int(v);
    else if (key == "localRelaxIterations") opt.localRelaxIterations = int(v);
    else if (key == "minAngle") opt.minAngleDeg = v;
    else if (key == "angleAllowance") opt.angleAllowancePercent = v;
    else if (key == "angleFloor") opt.angleFloorDeg = v;
    else if (key == "budget") opt.hausdorffBudgetPercent = v;
    else if (key == "maxRefusals") maxRefusals = int(v);
    else if (key == "angleRepairRounds") opt.angleRepairRounds = int(v);
    else if (key == "angleRepairSlack") opt.angleRepairSlackDeg = v;
    else if (key == "travelReference") opt.travelReferenceVertices = int(v);
    else if (key == "maxTravelScale") opt.maxTravelScale = v;
    else if (key == "partialAbsorption") opt.partialAbsorption = v != 0;
    else if (key == "reuseDeadSlots") opt.reuseDeadSlots = v != 0;
    else if (key == "boundarySlide") opt.boundarySlide = v != 0;
    else if (key == "boundaryRings") opt.boundary.rings = int(v);
    else if (key == "boundaryTravel") opt.boundary.maxTravel = int(v);
    else if (key == "refusedRouteMemo") opt.refusedRouteMemo = v != 0;
    else if (key == "partialSweepUndo") opt.partialSweepUndo = v != 0;
    else if (key == "angleFlips") opt.angleFlips = v != 0;
    else if (key == "aggregate") opt.aggregateLeftovers = v != 0;
    else if (key == "gatherRadius") opt.gatherRadius = int(v);
    else if (key == "gatherTries") opt.gatherTries = int(v);
    else if (key == "gatherTriesPerGathered") opt.gatherTriesPerGathered = int(v);
    else if (key == "creaseDeg") opt.creaseDeg = v;
    else if (key == "creaseThinEdges") opt.creaseThinEdges = v;
    else if (key == "creaseStraightShare") opt.creaseStraightShare = v;
    else if (key == "anglePolish") opt.anglePolishDeg = v;
    else if (key == "anglePolishRounds") opt.anglePolishRounds = int(v);
    else if (key == "timeLimit") opt.timeLimitSeconds = v > 0 ? v : opt.timeLimitSeconds;
    else if (key == "farMeetingReach") opt.farMeetingReach = v;
    else if (key == "farMeetingTravel") opt.farMeetingTravel = v;
    else if (key == "farMeetingRounds") opt.farMeetingRounds = int(v);
    else if (key == "nearMeetingTries") opt.nearMeetingTries = int(v);
    else if (key == "nearMeetingTriesPerKept") opt.nearMeetingTriesPerKept = int(v);
    else if (key == "memory") memory = v != 0;
    else if (key == "loadOnly") loadOnly = v != 0;
    else if (key == "listLeftovers") listLeftovers = v != 0;
    else {
      std::fprintf(stderr, "unknown option %s\n", key.c_str());
      return 2;
    }
  }
  // the filter's settings for its travel parameter, then what was given explicitly
  SetFilterTravel(opt, maxTravel);
  if (glideTravel >= 0) opt.glideTravel = glideTravel;
  if (maxRefusals >= 0) opt.maxRefusalsPerRegion = maxRefusals;
  if (models.empty())
    models = {"bunny00.off", "armadillo.off", "fandisk.off", "camel.off", "homer.off", "elephant.off", "knot1.off"};
  std::printf("%-14s %7s %6s %8s %6s %7s %8s %7s %8s %8s %8s %7s %7s\n", "model", "V", "chi", "irr.in", "irr", "irr%",
              "H%diag", "minang", "<30deg%", "remesh_s", "reduce_s", "retries", "gaveup");
  for (const std::string& name : models) {
    TMesh m;
    const bool path = name.find('/') != std::string::npos;
    if (!(path ? LoadPath(m, name) : test::LoadCorpus(m, name))) {
      std::printf("%-14s missing\n", name.c_str());
      continue;
    }
    if (loadOnly) {
      if (!saveResult.empty()) Save(m, saveResult, name, models.size());
      std::printf("%-14s loaded and saved: %d vertices, %d faces\n", name.c_str(), m.vn, m.fn);
      continue;
    }
    SurfaceProjector input(m);
    if (memory) {
      auto last = std::make_shared<std::string>();
      auto lastPct = std::make_shared<int>(-1);
      opt.progress = [last, lastPct, &m](int pct, const char* what) {
        // at every stage, and every 5 percent within one (the sweeps report one stage each)
        if (*last != what || pct / 5 != *lastPct / 5) {
          *last = what;
          *lastPct = pct;
          // the vectors' sizes and capacities: a vector that outgrows its room is copied whole
          const HeapMiB h = Heap();
          // the process's CPU time so far: where a stage's time goes
          std::printf("  memory: %-45s %3d%% cpu %7.2f s, rss %7.1f MiB, peak %7.1f MiB; heap used %7.1f, freed %6.1f MiB; "
                      "vert %zu/%zu (%d live), face %zu/%zu\n", what, pct, double(std::clock()) / CLOCKS_PER_SEC,
                      StatusMiB("VmRSS"), StatusMiB("VmHWM"), h.used, h.freed, m.vert.size(), m.vert.capacity(), m.vn,
                      m.face.size(), m.face.capacity());
          std::fflush(stdout);
        }
        return true;
      };
    }
    auto t0 = std::chrono::steady_clock::now();
    RemeshOptions ro;
    ro.targetEdgeLength = EdgeLengthForVertexCount(vcg::tri::Stat<TMesh>::ComputeMeshArea(m), n);
    if (n > 0) RemeshIsotropic(m, ro);
    if (!saveRemeshed.empty()) Save(m, saveRemeshed, name, models.size());
    auto t1 = std::chrono::steady_clock::now();
    AutomaticReduction<TMesh> ar(m, input, opt);
    ReductionReport r = ar.Run();
    auto t2 = std::chrono::steady_clock::now();
    if (memory)  // before the measurements below, which allocate grids of their own
      std::printf("  memory: %-45s rss %7.1f MiB, peak %7.1f MiB\n", "after the run", StatusMiB("VmRSS"),
                  StatusMiB("VmHWM"));
    if (!r) {
      std::printf("%-14s refused: %s\n", name.c_str(), r.result.reason.c_str());
      continue;
    }
    if (!saveResult.empty()) Save(m, saveResult, name, models.size());
    ShapeMeasures s = MeasureShape(m);
    std::printf("%-14s %7d %6d %8d %6d %7.2f %8.3f %7.1f %8.2f %8.2f %8.2f %5d %4d/%d%s\n", name.c_str(), m.vn,
                Summarize(m).eulerCharacteristic, r.irregularBefore, r.irregularAfter, 100.0 * r.irregularAfter / m.vn,
                HausdorffPercent(m, input), s.minAngleDeg, 100 * s.shareBelow30,
                std::chrono::duration<double>(t1 - t0).count(), std::chrono::duration<double>(t2 - t1).count(), r.budgetRetries, int(r.gaveUp.size()), r.gaveUpVertices, r.allUndone ? " (all undone)" : "");
    std::printf("  %s; travel %d; undone %d (angle %d, Hausdorff %d, frozen %d, boundary %d); angle polish %d of %d, flips %d of %d; "
                "angle repairs kept %d; far meetings %d of %d, near %d of %d in %d rounds%s\n",
                r.leftovers.Summary().c_str(), r.travel, r.undone, r.undoneAngle, r.undoneHausdorff, r.undoneFrozen,
                r.undoneBoundary, r.anglePolished, r.anglePolishBelow, r.angleFlips, r.angleFlipsTried, r.angleRepairs, r.farMeetingsKept, r.farMeetings,
                r.nearMeetingsKept, r.nearMeetings, r.meetingRounds,
                r.finalSweepsUndone                 ? "; final sweeps undone"
                : r.finalSweepsRestored > 0 ? "; final sweeps undone around triangles under the bound or samples past the margin"
                                                    : "");
    if (r.finalSweepsRestored > 0) std::printf("  final sweeps: %d vertices put back\n", r.finalSweepsRestored);
    if (r.thinRimLines > 0) std::printf("  crease lines not kept sharp as thin parts' rims: %d\n", r.thinRimLines);
    if (r.boundaryIrregularBefore > 0) {
      const auto& bs = r.boundaryStage;
      std::printf("  boundary: %d -> %d irregular (limit %d); stage: %d candidates, absorbed %d v5, %d v7, %d pairs "
                  "(%d moved), %d hops, cancelled %d, added %d, undone %d, refused %d, %ld attempts in %d calls\n",
                  r.boundaryIrregularBefore, r.boundaryIrregularAfter, bs.boundaryLimit, bs.candidates, bs.absorbedV5,
                  bs.absorbedV7, bs.absorbedPairs, bs.pairsMoved, bs.hops, bs.cancelled, bs.boundaryAdded, bs.undone,
                  bs.refused, bs.attempts, bs.calls);
    }
    if (opt.aggregateLeftovers)
      std::printf("  aggregated: %d v4 and %d v8 of %d pairs tried; %d of them gathered, of %d walks%s\n", r.aggregatedV4,
                  r.aggregatedV8, r.aggregationsTried, r.gathered, r.gathersTried,
                  r.gatherBoundReached ? " (stopped at the bound)" : "");
    std::printf("  kept: %d type splits, %d local cancellations, %d transports (%d pair steps), %d glides, %d split-and-absorbs (%d partial)\n",
                r.typeSplits, r.localCancellations, r.transports, r.pairSteps, r.glides, r.splitAbsorptions, r.partialAbsorptions);
    if (listLeftovers)  // one line per leftover: why it stays (leftover_reasons.h) and what is around it
      for (const LeftoverVertex& lv : r.leftovers.vertices)
        std::printf("  leftover v%d valence %d %s: partner %d at %d edges, nearest irregular %d, curvature %.3f "
                    "(%d rings), thickness %.1f, undone nearby %d, at (%g %g %g)\n",
                    lv.vertex, lv.valence, LeftoverReasonName(lv.reason), lv.partner, lv.partnerDistance,
                    lv.nearestIrregular, lv.curvature, lv.curvatureRings, lv.thickness, lv.undoneNearby,
                    double(m.vert[size_t(lv.vertex)].P()[0]), double(m.vert[size_t(lv.vertex)].P()[1]),
                    double(m.vert[size_t(lv.vertex)].P()[2]));
    std::fflush(stdout);
  }
  const double peak = StatusMiB("VmHWM");
  if (memory || loadOnly) std::printf("peak resident memory (VmHWM): %.1f MiB\n", peak);
  if (!peakFile.empty()) {
    if (FILE* f = std::fopen(peakFile.c_str(), "w")) {
      std::fprintf(f, "%.1f\n", peak);
      std::fclose(f);
    }
  }
  return 0;
}
