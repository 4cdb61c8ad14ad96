// filter_irregular: directions a person can name, in the tangent plane of a vertex.
//
// A direction around vertex p is an angle measured counter-clockwise (seen from outside the
// surface) in p's tangent plane, from a reference direction:
//   * the edge from p to a reference neighbour chosen by the caller, or
//   * when there is none, the world +X axis projected into the tangent plane (+Y when the
//     tangent plane is nearly perpendicular to X), so the same mesh and the same vertex always
//     give the same numbering, whatever the vertex indices.
// Sector k (k = 0..5) is the 60-degree sector centred on the angle 60k: [60k - 30, 60k + 30).
// The sector is about geometry, not neighbour index: a v5 has 5 edges and a v7 has 7, but
// both have six sectors.
// The tangent plane is the plane orthogonal to the area-weighted normal of p's faces.
#pragma once

#include <cmath>
#include <vector>

#include "topology.h"

namespace vcg_ext {
namespace irregular {

/// A tangent frame at a vertex: unit normal n, unit reference axis x (in the plane), y = n ^ x.
template <class MeshType>
struct TangentFrame {
  typedef typename MeshType::CoordType CoordType;
  typedef typename MeshType::VertexType VertexType;
  CoordType origin, n, x, y;
  bool valid = false;

  /// Angle in degrees, in [0, 360), of the projection of (q - origin), counter-clockwise from x.
  double AngleOf(const CoordType& q) const {
    const CoordType d = q - origin;
    double a = std::atan2(double(d.dot(y)), double(d.dot(x))) * 180.0 / M_PI;
    if (a < 0) a += 360.0;
    if (a >= 360.0) a -= 360.0;
    return a;
  }
};

/// The sector (0..5) that contains the angle (degrees): sector k spans [60k - 30, 60k + 30).
inline int SectorOfAngle(double deg) {
  double a = std::fmod(deg + 30.0, 360.0);
  if (a < 0) a += 360.0;
  int k = int(a / 60.0);
  return k > 5 ? 5 : k;
}

/// Smallest absolute difference of two angles, in degrees (0..180).
inline double AngleGap(double a, double b) {
  double d = std::fmod(std::fabs(a - b), 360.0);
  return d > 180.0 ? 360.0 - d : d;
}

/// The tangent frame of v (from its star), with reference axis toward neighbour `ref` or, if
/// ref is null, the projected world +X (or +Y). Invalid if v has no faces or a degenerate fan.
template <class MeshType>
TangentFrame<MeshType> FrameAt(typename MeshType::VertexType* v, typename MeshType::VertexType* ref) {
  typedef typename MeshType::CoordType CoordType;
  TangentFrame<MeshType> f;
  VertexStar<MeshType> s = StarOf<MeshType>(v);
  if (s.corners.empty()) return f;
  f.origin = v->P();
  CoordType n(0, 0, 0);
  for (auto& c : s.corners) n += (c.f->P(1) - c.f->P(0)) ^ (c.f->P(2) - c.f->P(0));
  if (n.Norm() == 0) return f;
  f.n = n / n.Norm();
  CoordType axis;
  if (ref != nullptr) {
    axis = ref->P() - v->P();
  } else {
    axis = std::fabs(double(f.n[0])) > 0.9 ? CoordType(0, 1, 0) : CoordType(1, 0, 0);
  }
  axis = axis - f.n * axis.dot(f.n);
  if (axis.Norm() == 0) return f;
  f.x = axis / axis.Norm();
  f.y = f.n ^ f.x;
  f.valid = true;
  return f;
}

}  // namespace irregular
}  // namespace vcg_ext
