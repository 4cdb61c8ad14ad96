// filter_irregular: the angle polish of the automatic reduction (automatic_reduction.h), its
// last guarded step before the final relaxation.
//
// Why: the final local sweeps are kept or dropped as a whole (FinalRelax: one Hausdorff
// measurement decides), and where they are dropped the triangles that transports left sheared
// stay as they were. Issue 14 asks for at most 1% of the triangles under 30 degrees; the cow
// at 20K (pymeshlab) had 1.21%, most of them between 20 and 30 degrees among regular vertices,
// in clusters where pairs had passed. Here each such triangle gets its own local relaxation
// under the edit guard (the same Hausdorff, crease and angle checks as an edit), kept only if
// it leaves fewer triangles under the bound around it.
//
// Preconditions: as EditGuard (guard's mesh with FF/VF adjacency, journaled editor, inside
// the reduction's snapshot). Postconditions: connectivity unchanged (positions only); every
// kept relaxation passed the guard and lowered the count of triangles under `deg` in its
// 2-ring; a refused one is rolled back exactly. Cost: one scan of the faces, then O(1) per
// triangle found.
#pragma once

#include <vector>

#include "edit_guard.h"
#include "reduction_options.h"

namespace vcg_ext {
namespace irregular {

/// How the polish went: triangles under the bound when it began, relaxations kept and refused.
struct AnglePolishReport {
  int below = 0, kept = 0, refused = 0;
};

/// Relaxes, one at a time, the 2-ring of each live face with an angle under `deg` whose
/// vertices are not all frozen, under the guard; `rounds` passes over what is still under it.
template <class MeshType>
AnglePolishReport PolishAngles(MeshType& m, EditGuard<MeshType>& guard, ReductionReport& rep, double deg,
                               int rounds) {
  typedef typename MeshType::FaceType FaceType;
  MeshEditor<MeshType>& ed = guard.ed();
  AnglePolishReport out;
  auto below = [&](const FaceType* f) { return EditGuard<MeshType>::MinAngle(f) < deg; };
  for (int round = 0; round < rounds; ++round) {
    std::vector<std::vector<int>> todo;
    for (auto& f : m.face) {
      if (f.IsD() || !below(&f)) continue;
      std::vector<int> seeds;
      for (int z = 0; z < 3; ++z) {
        const int v = ed.Index(f.V(z));
        if (!guard.state().Frozen(v)) seeds.push_back(v);
      }
      if (!seeds.empty()) todo.push_back(seeds);
    }
    if (round == 0) out.below = int(todo.size());
    int keptThisRound = 0;
    for (const std::vector<int>& seeds : todo) {
      const int before = guard.CountBelowAround(seeds, deg);
      if (before == 0) continue;  // an earlier relaxation fixed it
      // subjects: none (no irregular vertex is this edit's subject, so a refusal is not a
      // leftover's reason); refusals are not counted as the reduction's undone edits either
      const std::vector<int> none;
      GuardedEdit<MeshType> g(guard, rep, seeds, &none);
      guard.RelaxAround(seeds);
      if (guard.CountBelowAround(seeds, deg) < before && g.Verdict(seeds) == GuardVerdict::Kept) {
        g.Keep(seeds);
        ++out.kept;
        ++keptThisRound;
      } else {
        g.Undo();
        ++out.refused;
      }
    }
    if (keptThisRound == 0) break;
  }
  return out;
}

}  // namespace irregular
}  // namespace vcg_ext
