// Tests of vcg_ext/irregular/thin_creases.h: the crease lines that are a thin part's rim, which
// the automatic reduction does not keep sharp.

#include <gtest/gtest.h>

#include <memory>

#include <vcg/complex/complex.h>

#include <vcg/complex/algorithms/create/platonic.h>
#include <vcg/complex/algorithms/refine.h>
#include <vcg/complex/algorithms/stat.h>

#include <vcg_ext/irregular/automatic_reduction.h>
#include <vcg_ext/irregular/mesh_checks.h>
#include <vcg_ext/irregular/quality.h>
#include <vcg_ext/irregular/remeshing.h>
#include <vcg_ext/irregular/surface_projector.h>
#include <vcg_ext/irregular/thin_creases.h>

#include "test_mesh.h"

using namespace vcg_ext::irregular;
using test::TMesh;

namespace {

/// A closed box of the given size, its faces split until no edge is longer than maxEdge.
void RefinedBox(TMesh& m, double sx, double sy, double sz, double maxEdge) {
  vcg::tri::Box<TMesh>(m, vcg::Box3<TMesh::ScalarType>(TMesh::CoordType(0, 0, 0), TMesh::CoordType(sx, sy, sz)));
  test::UpdateTopology(m);
  while (vcg::tri::Refine<TMesh>(m, vcg::tri::MidPoint<TMesh>(&m), TMesh::ScalarType(maxEdge))) test::UpdateTopology(m);
  test::UpdateTopology(m);
}

int Count(const std::vector<char>& flags) {
  int n = 0;
  for (char c : flags) n += c != 0;
  return n;
}

}  // namespace

// A slab one edge length thick: its twelve edges (90-degree creases, one connected line that runs
// straight but at its eight corners) are the rim of a thin part, and are dropped, every edge of
// them; a box as deep as it is wide has the same line, kept whole. Off (thinEdges 0), nothing is
// dropped. The line finders with and without adjacency (the edited mesh's, the guard's copy of
// the input's) find the same vertices, and a probe of the slab judges the box's copy of it
// (another mesh) as it judges its own.
TEST(ThinCreases, ASlabsRimIsDroppedABoxsEdgesAreKept) {
  for (int thick : {0, 1}) {
    TMesh m;
    const double size[3] = {8, 8, thick ? 8.0 : 0.5};
    RefinedBox(m, size[0], size[1], size[2], 0.6);
    ASSERT_TRUE(CheckInvariants(m).ok);
    std::vector<CreaseLineEdge> lines = CreaseLineEdgesOf(m, 60, 8, 0.9);
    const std::vector<char> flags = LineVertices(lines, m.vert.size());
    EXPECT_EQ(flags, CreaseLineVertices(m, 60, 8));
    SurfaceProjector copy(m);
    EXPECT_EQ(LineVertices(CreaseLineEdgesOfSoup(copy.Mesh(), 60, 8, 0.9), copy.Mesh().vert.size()), flags);
    // every vertex on the box's twelve edges, and no other
    int onEdges = 0;
    for (auto& v : m.vert) {
      int extreme = 0;
      for (int k = 0; k < 3; ++k) extreme += std::abs(v.P()[k]) < 1e-6 || std::abs(v.P()[k] - size[k]) < 1e-6;
      onEdges += extreme >= 2;
    }
    const int onLines = Count(flags);
    ASSERT_EQ(onLines, onEdges);
    ASSERT_GT(onLines, 40);
    // on the slab every edge of the line is thin but the four short ones down its corners (their
    // faces look out sideways, at nothing)
    ThinRimProbe<TMesh> probe(m, 4);
    int thinEdges = 0, upright = 0;
    for (const CreaseLineEdge& e : lines) {
      thinEdges += probe.Thin(e);
      upright += std::abs(e.nA[2]) < 1e-9 && std::abs(e.nB[2]) < 1e-9;
    }
    EXPECT_EQ(upright, thick ? 4 * 16 : 4);  // 8 long, split to 0.5
    EXPECT_EQ(thinEdges, thick ? 0 : int(lines.size()) - upright);
    std::vector<CreaseLineEdge> kept = lines;
    const int dropped = DropThinLines(kept, m.vert.size(), probe);
    EXPECT_EQ(dropped, thick ? 0 : 1);
    EXPECT_EQ(kept.size(), thick ? lines.size() : 0u);
  }
}

// The lion (corpus, raw, 6.5K vertices; its head is a shell with ears two sheets thick): the four
// crease lines around its ears are thin rims. Left unprotected, the reduction keeps fewer
// irregular vertices (the rims' neighbours can be edited and relaxed), within the Hausdorff
// budget, and the mesh stays valid. The same on a remeshing of the lion measured against the raw
// lion (the filter's remeshing first): its rims are judged against the remeshed mesh, the raw
// lion's lines (the guard's crease samples) against the same mesh.
TEST(AutomaticReduction, ThinRimsAreNotKeptSharp) {
  for (int remeshed : {0, 1}) {
    int left[2] = {0, 0};
    for (int drop : {0, 1}) {
      TMesh m;
      ASSERT_TRUE(test::LoadCorpus(m, "lion.off")) << "corpus mesh missing (run scripts/setup.sh)";
      SurfaceProjector input(m);
      if (remeshed) {
        RemeshOptions ro;
        ro.targetEdgeLength = EdgeLengthForVertexCount(vcg::tri::Stat<TMesh>::ComputeMeshArea(m), 6000);
        RemeshIsotropic(m, ro);
      }
      ReductionOptions opt;
      if (!drop) opt.creaseThinEdges = 0;
      const ReductionReport r = AutomaticReduction<TMesh>(m, input, opt).Run();
      ASSERT_TRUE(r) << r.result.reason;
      const Result inv = CheckInvariants(m);
      ASSERT_TRUE(inv.ok) << inv.reason;
      EXPECT_FALSE(r.allUndone);
      EXPECT_LE(HausdorffPercent(m, input), opt.hausdorffBudgetPercent);
      // the ears' rims: four lines on the raw lion, three on its remeshing
      EXPECT_EQ(r.thinRimLines, drop ? (remeshed ? 3 : 4) : 0);
      left[drop] = r.irregularAfter;
      std::printf("lion (%s), thin rims %s: %d rims dropped, %d -> %d interior irregular vertices\n",
                  remeshed ? "remeshed to 6K" : "raw", drop ? "dropped" : "kept", r.thinRimLines, r.irregularBefore,
                  r.irregularAfter);
    }
    // 397 -> 351 raw; on the remeshing at 6K, 134 -> 135 (the ears are a few edges wide there:
    // little to gain; at 20K, 183 -> 126, native bench)
    if (!remeshed) EXPECT_LT(left[1] + 30, left[0]);
  }
}
