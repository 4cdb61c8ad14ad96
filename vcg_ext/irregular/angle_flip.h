// filter_irregular: the angle flips of the automatic reduction (automatic_reduction.h), after
// the angle polish (angle_polish.h) and before the final relaxation.
//
// Why: relaxation moves vertices and cannot open a triangle whose shape its connectivity
// forces. A flip lowers the valence of its edge's ends by one and raises that of the opposite
// vertices by one; where all four end in 5..7 with no more irregular vertices than before, it
// opens a triangle under 30 degrees without raising the irregular count: it moves a 5-7 pair
// one edge (sec. 6.2), trades a 7 for a 5 next to it, or removes a quadruple the sweeps left.
// Issue 14 asks for at most 1% of triangles under 30 degrees; the man at 20K kept 3.74% after
// the polish (0.9.25): 100 of its 1441 such triangles had such a flip, 20 were kept (3.63%).
// The others lie among regular vertices, where any flip adds four irregular vertices.
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
    // a flip changes the valences of these four only, all interior: the count's change is
    // known before the flip (ReductionState::CountChange would give the same after it)
    int irregularBefore = 0, irregularAfter = 0;
    bool ok = o[0] != o[1];
    for (int k = 0; k < 4 && ok; ++k) {
      const VertexStar<MeshType> s = ed.Star(quad[k]);
      const int valence = s.Valence(), after = valence + (k < 2 ? -1 : 1);
      ok = !s.boundary && !state.Frozen(quad[k]) && after >= 5 && after <= 7;
      irregularBefore += valence != 6;
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
    // a region that already had a turned-over triangle (slivers on thin parts) is judged by
    // the rest: a flip is refused only for turning one over itself
    if ((foldedBefore || !guard.FoldsAround(seeds)) && guard.CountBelowAround(seeds, deg) < before &&
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
