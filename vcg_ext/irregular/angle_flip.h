// filter_irregular: the angle flips of the automatic reduction (automatic_reduction.h), after
// the angle polish (angle_polish.h) and before the final relaxation.
//
// Why: relaxation moves vertices and cannot open a triangle whose shape its connectivity
// forces. A triangle under 30 degrees whose longest edge joins two vertices of valence 6 or 7
// and whose opposite vertices have valence 5 or 6 can often be opened by flipping that edge,
// without raising the number of irregular vertices: such a flip moves a 5-7 pair one edge
// (sec. 6.2) or trades a 7 for a 5 next to it. Issue 14 asks for at most 1% of triangles under
// 30 degrees; the man at 20K kept 3.74% after the polish (0.9.25), where an estimate on the
// output found 224 of its 1423 such triangles with a count-neutral flip that enlarges the
// smallest angle.
//
// A flip is kept only if it passes the edit guard (edit_guard.h: Hausdorff, crease, angle and
// boundary checks, after local relaxation of its 2-ring), turns no triangle over, does not
// raise the interior irregular count, and leaves fewer triangles under the bound around it.
//
// Preconditions: as EditGuard (the guard's mesh with FF/VF adjacency, journaled editor, inside
// the reduction's snapshot, the running count started). Postconditions: every kept flip passed
// the above; a refused one is rolled back exactly; the interior irregular count is not higher
// than before. Cost: one scan of the faces, then O(1) per triangle found.
#pragma once

#include <algorithm>
#include <vector>

#include "edit_guard.h"
#include "reduction_options.h"

namespace vcg_ext {
namespace irregular {

/// How the flips went: triangles under the bound when they began, flips kept and tried.
struct AngleFlipReport {
  int below = 0, kept = 0, tried = 0;
};

/// For each live face with an angle under `deg`, flips its longest edge (x, y) into (o1, o2)
/// when: the edge and its four vertices are interior and free; the valences after the flip
/// (x, y: one less; o1, o2: one more) all lie in 5..7 and hold no more irregular vertices than
/// before; the two new triangles' smallest angle is larger than the two old ones'; and, after
/// local relaxation, the guard passes it, nothing turned over and fewer triangles under `deg`
/// are left around it.
template <class MeshType>
AngleFlipReport FlipSqueezedEdges(MeshType& m, EditGuard<MeshType>& guard, ReductionReport& rep, double deg) {
  typedef typename MeshType::FaceType FaceType;
  MeshEditor<MeshType>& ed = guard.ed();
  ReductionState<MeshType>& state = guard.state();
  AngleFlipReport out;
  // the faces first: a kept flip changes the faces around it, which the scan would meet again
  std::vector<std::pair<int, int>> edges;  // the longest edge of each triangle under the bound
  for (auto& f : m.face) {
    if (f.IsD() || EditGuard<MeshType>::MinAngle(&f) >= deg) continue;
    ++out.below;
    int z = 0;  // the longest edge (V(z), V(z+1))
    double longest = -1;
    for (int k = 0; k < 3; ++k) {
      const double l = double((f.cP((k + 1) % 3) - f.cP(k)).SquaredNorm());
      if (l > longest) longest = l, z = k;
    }
    if (f.FFp(z) == &f) continue;  // a boundary edge
    edges.emplace_back(ed.Index(f.V(z)), ed.Index(f.V((z + 1) % 3)));
  }
  const std::vector<int> none;  // no subject: a refusal is no leftover's reason
  for (const auto& e : edges) {
    const int x = e.first, y = e.second;
    if (!ed.IsLive(x) || !ed.IsLive(y) || !ed.Adjacent(x, y)) continue;  // an earlier flip changed it
    int o[2];
    if (!ed.Opposites(x, y, o)) continue;
    const int quad[4] = {x, y, o[0], o[1]};
    int valence[4], irregularBefore = 0, irregularAfter = 0;
    bool ok = o[0] != o[1];
    for (int k = 0; k < 4 && ok; ++k) {
      const VertexStar<MeshType> s = ed.Star(quad[k]);
      ok = !s.boundary && !state.Frozen(quad[k]);
      valence[k] = s.Valence();
      const int after = valence[k] + (k < 2 ? -1 : 1);
      ok = ok && after >= 5 && after <= 7;
      irregularBefore += valence[k] != 6;
      irregularAfter += after != 6;
    }
    if (!ok || irregularAfter > irregularBefore) continue;
    const auto &px = ed.V(x)->cP(), &py = ed.V(y)->cP(), &p0 = ed.V(o[0])->cP(), &p1 = ed.V(o[1])->cP();
    const double oldMin = std::min(relax_detail::MinAngleDegOf(px, py, p0), relax_detail::MinAngleDegOf(px, py, p1));
    const double newMin = std::min(relax_detail::MinAngleDegOf(p0, p1, px), relax_detail::MinAngleDegOf(p0, p1, py));
    if (newMin <= oldMin) continue;
    const std::vector<int> seeds(quad, quad + 4);
    const int before = guard.CountBelowAround(seeds, deg);
    const bool foldedBefore = guard.FoldsAround(seeds);
    ++out.tried;
    GuardedEdit<MeshType> g(guard, rep, seeds, &none);
    if (!ed.Flip(x, y)) {
      g.Undo();
      continue;
    }
    guard.RelaxAround(seeds);
    if ((foldedBefore || !guard.FoldsAround(seeds)) && state.CountChange(seeds) <= 0 && guard.CountBelowAround(seeds, deg) < before &&
        g.Verdict(seeds) == GuardVerdict::Kept) {
      g.Keep(seeds);
      ++out.kept;
    } else {
      g.Undo();
    }
  }
  return out;
}

}  // namespace irregular
}  // namespace vcg_ext
