// filter_irregular: triangle quality and fidelity measures, used by tests, benchmarks and logs.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <vcg/complex/complex.h>

#include "mesh_distance_grid.h"
#include "surface_projector.h"

namespace vcg_ext {
namespace irregular {

struct ShapeMeasures {
  double minAngleDeg = 180;      ///< smallest angle of any triangle
  double meanMinAngleDeg = 0;    ///< mean over triangles of their smallest angle
  double shareBelow30 = 0;       ///< share of triangles whose smallest angle is under 30 degrees
  double edgeLengthMean = 0;
  double edgeLengthSpread = 0;   ///< standard deviation / mean of edge lengths
  int faces = 0;
};

/// Angles and edge lengths of the live faces. O(F).
template <class MeshType>
ShapeMeasures MeasureShape(const MeshType& m) {
  ShapeMeasures s;
  double sumMin = 0, sumL = 0, sumL2 = 0;
  long edges = 0, below = 0;
  for (auto& f : m.face) {
    if (f.IsD()) continue;
    double mn = 180;
    for (int z = 0; z < 3; ++z) {
      auto a = f.cP((z + 1) % 3) - f.cP(z), b = f.cP((z + 2) % 3) - f.cP(z);
      double la = a.Norm(), lb = b.Norm();
      double ang = (la > 0 && lb > 0) ? std::acos(std::max(-1.0, std::min(1.0, double(a.dot(b)) / (la * lb)))) * 180 / M_PI : 0;
      mn = std::min(mn, ang);
      sumL += la;
      sumL2 += la * la;
      ++edges;
    }
    s.minAngleDeg = std::min(s.minAngleDeg, mn);
    sumMin += mn;
    below += mn < 30;
    ++s.faces;
  }
  if (s.faces) {
    s.meanMinAngleDeg = sumMin / s.faces;
    s.shareBelow30 = double(below) / s.faces;
    s.edgeLengthMean = sumL / edges;
    double var = std::max(0.0, sumL2 / edges - s.edgeLengthMean * s.edgeLengthMean);
    s.edgeLengthSpread = s.edgeLengthMean > 0 ? std::sqrt(var) / s.edgeLengthMean : 0;
  }
  return s;
}

/// The largest distance(p) over samples of mesh a: its vertices, and on each face its centroid,
/// its edges' midpoints and third points, and three inner points (barycentric 0.6/0.2/0.2).
/// A superset of the independent oracle's samples (tests/oracle: fi_oracle.surface_samples), so
/// this is never below what the tests measure: with the midpoints and centroids alone, a coarse
/// input (elephant, 2775 vertices) measured 0.45% where the oracle found 0.51%. O(F) calls.
/// distance(p, mx, corners, n) gets the maximum so far: where p's distance is at most mx, it
/// may return any value up to mx (p cannot raise the maximum); elsewhere it must return the
/// distance. corners[0..n) are the indices in a.vert of the vertices p lies among (the vertex
/// itself, or the face's three corners), for a caller that knows something about them.
template <class MeshA, class DistanceFn>
double MaxSampleDistance(const MeshA& a, DistanceFn distance) {
  double mx = 0;
  size_t corners[3];
  auto probe = [&](const vcg::Point3f& p, size_t n) { mx = std::max(mx, double(distance(p, mx, corners, n))); };
  for (auto& v : a.vert)
    if (!v.IsD()) {
      corners[0] = size_t(&v - &a.vert[0]);
      probe(vcg::Point3f::Construct(v.cP()), 1);
    }
  for (auto& f : a.face) {
    if (f.IsD()) continue;
    const vcg::Point3f p[3] = {vcg::Point3f::Construct(f.cP(0)), vcg::Point3f::Construct(f.cP(1)),
                               vcg::Point3f::Construct(f.cP(2))};
    for (int z = 0; z < 3; ++z) corners[z] = size_t(f.cV(z) - &a.vert[0]);
    probe((p[0] + p[1] + p[2]) / 3.f, 3);
    for (int z = 0; z < 3; ++z) {
      const vcg::Point3f &u = p[z], &w = p[(z + 1) % 3];
      probe((u + w) / 2.f, 3);
      probe(u * (2.f / 3) + w * (1.f / 3), 3);
      probe(u * (1.f / 3) + w * (2.f / 3), 3);
      probe(u * 0.6f + w * 0.2f + p[(z + 2) % 3] * 0.2f, 3);
    }
  }
  return mx;
}

/// One-sided Hausdorff distance from mesh a to the surface of `to`, sampled at a's vertices,
/// edge midpoints and third points, face centroids and inner points (MaxSampleDistance). O(F log F).
template <class MeshType>
double OneSidedHausdorff(const MeshType& a, const SurfaceProjector& to) {
  // the last sample's closest face first, as for a MeshDistanceGrid below; failing that, the
  // input faces the projector last projected the sample's vertex or corners onto
  // (SurfaceProjector::VertexHint, keyed by a's vertex indices when a is the mesh the
  // projector relaxed, as in HausdorffPercent; any input face is a sound witness, so another
  // mesh only finds fewer): a point among corners on the input surface lies within its bulge.
  // Either witness answers "at most mx" only, so the maximum is what searching every sample
  // gives, up to the last bits of ClosestFrom's ties between faces sharing an edge (the
  // searches left start from other hints). Callgrind, native bench, the bull at 20K: this
  // side 786 M -> 626 M instructions, the whole run 33.67 G -> 33.50 G, the same files on all
  // 20 inputs of the full set.
  const proj_detail::PFace* hint = nullptr;
  return MaxSampleDistance(a, [&](const vcg::Point3f& p, double mx, const size_t* corners, size_t n) {
    if (mx > 0 && to.NearHints(hint, p, float(mx), corners, n)) return mx;
    float d = 0;
    const proj_detail::PFace* f = nullptr;
    to.ClosestFrom(hint, p, &d, nullptr, 0, &f);
    if (f) hint = f;
    return double(d);
  });
}

/// The same to the live faces of a mesh indexed by a MeshDistanceGrid (each query looks no
/// farther than the diagonal of that mesh, as SurfaceProjector::Closest does).
template <class MeshA, class MeshB>
double OneSidedHausdorff(const MeshA& a, MeshDistanceGrid<MeshB>& to) {
  const float reach = to.Diagonal();
  // Consecutive samples lie on the same face of a: the face found closest for the last one
  // (or one next to it) usually keeps the next one within the maximum so far, which then
  // needs no search; only a sample that may raise the maximum is searched for. The same
  // maximum, to the bit, at a fraction of the searches.
  uint32_t hint = MeshDistanceGrid<MeshB>::kNoFace;
  return MaxSampleDistance(a, [&](const vcg::Point3f& p, double mx, const size_t*, size_t) {
    if (mx > 0 && to.NearFace(hint, p, float(mx))) return mx;
    const float d = to.Distance(p, reach);
    if (to.LastClosest() != MeshDistanceGrid<MeshB>::kNoFace) hint = to.LastClosest();
    return double(d);
  });
}

/// Symmetric Hausdorff distance between the edited mesh and the original surface, in percent of
/// the original's bounding-box diagonal. The original's side is measured on a MeshDistanceGrid
/// of the edited mesh (face indices into it, ~14 bytes per face), not on a SurfaceProjector
/// copy of it (~200 MB more at a million faces): the same distances to the bit.
template <class MeshType>
double HausdorffPercent(const MeshType& edited, const SurfaceProjector& original) {
  double ab = OneSidedHausdorff(edited, original);
  MeshDistanceGrid<MeshType> editedSurface(edited);
  double ba = OneSidedHausdorff(original.Mesh(), editedSurface);
  return 100.0 * std::max(ab, ba) / original.Diagonal();
}

}  // namespace irregular
}  // namespace vcg_ext
