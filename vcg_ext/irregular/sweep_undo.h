// filter_irregular: undoing the final relaxation sweeps of Automatic Reduction where they did
// harm, and only there.
//
// The final local sweeps (AutomaticReduction::FinalRelax) move every free vertex of the mesh
// and are checked afterwards, not move by move: against the angle bound and against the
// Hausdorff budget (with the run's verified margin). Before 0.9.25 one triangle under the bound,
// or one sample past the margin, made every sweep of the whole mesh be undone (at 20K vertices,
// 10 of the full set's 20 inputs). SweepUndo puts back, where they were before the sweeps, the
// vertices around what went wrong, round by round; the caller undoes everything only when the
// rounds do not get there.
//
// Preconditions: `all` holds the indices of the vertices the sweeps may have moved (live),
// `before` their positions before the sweeps (before[i] for all[i]); the connectivity has not
// changed since. Postconditions: a vertex is either where the sweeps put it or at its position
// before them; the face normals of the mesh are recomputed when a vertex was put back.
#pragma once

#include <algorithm>
#include <vector>

#include <vcg/complex/complex.h>

#include "mesh_distance_grid.h"
#include "quality.h"
#include "relaxation.h"
#include "surface_projector.h"

namespace vcg_ext {
namespace irregular {

template <class MeshType>
class SweepUndo {
 public:
  typedef typename MeshType::CoordType CoordType;
  typedef typename MeshType::VertexType VertexType;

  SweepUndo(MeshType& m, const std::vector<int>& all, const std::vector<CoordType>& before)
      : m_(m), before_(before), slot_(m.vert.size(), -1) {
    for (size_t i = 0; i < all.size(); ++i) slot_[size_t(all[i])] = int(i);
  }

  /// Vertices put back so far (each counted once: a vertex put back stays there).
  int PutBack() const { return putBack_; }

  /// Puts back the corners the sweeps moved of each triangle they pushed under minAngleDeg: a
  /// triangle whose smallest angle is now under both the bound and its own smallest angle
  /// before the sweeps. A vertex put back next to a relaxed one can squeeze a triangle between
  /// them, which the next round finds (the positions before have none, so the rounds can only
  /// end there); at most `rounds` rounds. After it (unless the rounds ran out) no triangle is
  /// under the bound unless it was before the sweeps, and none lost angle there: the sweeps
  /// neither raise the share under the bound nor lower the smallest angle (issue 14 asks this
  /// of the global relaxation). Putting back the corners' 1-rings too moved 3-4x as many
  /// vertices back and left as many or more triangles under 30 degrees (the full set at 20K:
  /// the man 3.80% against 3.74%). O(F) per round. True when none is left.
  bool UnderAngle(double minAngleDeg, int rounds) {
    std::vector<int> seeds;
    for (int round = 0; round <= rounds; ++round) {
      seeds.clear();
      for (auto& f : m_.face) {
        if (f.IsD()) continue;
        const double after = relax_detail::FaceMinAngleDeg(&f);
        if (after >= minAngleDeg) continue;
        const double was = relax_detail::MinAngleDegOf(BeforeOf(f.cV(0)), BeforeOf(f.cV(1)), BeforeOf(f.cV(2)));
        if (after >= was - 1e-9) continue;
        for (int z = 0; z < 3; ++z) seeds.push_back(int(vcg::tri::Index(m_, f.cV(z))));
      }
      if (seeds.empty()) return true;
      if (round == rounds || Put(seeds) == 0) return false;  // (0: cannot happen, such a triangle has a moved corner)
    }
    return false;
  }

  /// Puts back the vertices around the samples of the symmetric Hausdorff measure
  /// (HausdorffPercent's samples) that lie farther than `bound` (absolute) from the other
  /// surface: the corners of an edited sample (a vertex, or a point of a face), and the corners
  /// of the edited face closest to an input sample. One measurement's worth of work (a grid
  /// over the edited mesh, O(F log F)). Returns how many were put back (0: none of those
  /// vertices had moved, or no sample is past the bound).
  int BeyondDistance(const SurfaceProjector& original, float bound) {
    std::vector<int> seeds;
    // the edited surface's samples against the input (as OneSidedHausdorff: the hints only
    // ever answer "within the bound", so no sample past it is missed)
    const proj_detail::PFace* hint = nullptr;
    MaxSampleDistance(m_, [&](const vcg::Point3f& p, double, const size_t* corners, size_t n) {
      if (original.NearHints(hint, p, bound, corners, n)) return 0.0;
      float d = 0;
      const proj_detail::PFace* f = nullptr;
      original.ClosestFrom(hint, p, &d, nullptr, 0, &f);
      if (f) hint = f;
      if (d > bound)
        for (size_t k = 0; k < n; ++k) seeds.push_back(int(corners[k]));
      return double(d);
    });
    // the input's samples against the edited surface: the edited face closest to each
    {
      MeshDistanceGrid<MeshType> edited(m_);
      const float reach = edited.Diagonal();
      uint32_t last = MeshDistanceGrid<MeshType>::kNoFace;
      MaxSampleDistance(original.Mesh(), [&](const vcg::Point3f& p, double, const size_t*, size_t) {
        if (edited.NearFace(last, p, bound)) return 0.0;
        const float d = edited.Distance(p, reach);
        const uint32_t t = edited.LastClosest();
        if (t != MeshDistanceGrid<MeshType>::kNoFace) {
          last = t;
          if (d > bound)
            for (int z = 0; z < 3; ++z) seeds.push_back(int(vcg::tri::Index(m_, m_.face[t].cV(z))));
        }
        return double(d);
      });
    }
    return Put(seeds);
  }

 private:
  CoordType BeforeOf(const VertexType* v) const {
    const int k = slot_[size_t(vcg::tri::Index(m_, v))];
    return k < 0 ? v->cP() : before_[size_t(k)];
  }
  /// Puts back the seeds (any order, repeats allowed) the sweeps moved; the face normals after.
  /// How many.
  int Put(std::vector<int>& seeds) {
    std::sort(seeds.begin(), seeds.end());
    seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
    int put = 0;
    for (int v : seeds) {
      const int k = slot_[size_t(v)];
      if (k < 0 || m_.vert[size_t(v)].P() == before_[size_t(k)]) continue;
      m_.vert[size_t(v)].P() = before_[size_t(k)];
      ++put;
    }
    if (put > 0)
      for (auto& f : m_.face)
        if (!f.IsD()) f.N() = vcg::TriangleNormal(f).Normalize();
    putBack_ += put;
    return put;
  }

  MeshType& m_;
  const std::vector<CoordType>& before_;
  std::vector<int> slot_;  ///< per vertex index: its place in all/before, or -1 (not moved by the sweeps)
  int putBack_ = 0;
};

}  // namespace irregular
}  // namespace vcg_ext
