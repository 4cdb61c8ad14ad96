// filter_irregular: isotropic remeshing as the optional first step of the automatic reduction
// (issue: "one click goes from a scan to a clean result"). A thin wrapper on vcglib's
// IsotropicRemeshing (Botsch-Kobbelt split / collapse / flip / smooth / project), so that the
// reduction starts from near-equilateral triangles of a chosen size.
//
// Preconditions: a vcg triangle mesh with FF and VF adjacency, per-vertex quality and marks,
// per-face marks (MeshLab's CMeshO has them all). Postconditions: FF and VF adjacency rebuilt,
// vectors compacted; the surface is projected on the input.
#pragma once

#include <vcg/complex/algorithms/isotropic_remeshing.h>
#include <vcg/complex/append.h>

namespace vcg_ext {
namespace irregular {

struct RemeshOptions {
  double targetEdgeLength = 0;  ///< absolute; <= 0: keep the mesh as it is
  int iterations = 10;          ///< vcglib passes (each splits, collapses, flips, smooths and projects)
  double featureAngleDeg = 30;  ///< edges with a sharper dihedral angle are kept as creases
};

/// Edge length that gives about `vertices` vertices on a surface of area `area` with
/// equilateral triangles: each vertex owns two triangles of area sqrt(3)/4 l^2.
inline double EdgeLengthForVertexCount(double area, int vertices) {
  return vertices > 0 ? std::sqrt(2.0 * area / (std::sqrt(3.0) * vertices)) : 0;
}

/// About how many vertices remeshing a surface of area `area` to edge length `length` makes
/// (the inverse of EdgeLengthForVertexCount). Lets a caller refuse a length that would need
/// more memory than a machine has before spending minutes on it.
inline double VertexCountForEdgeLength(double area, double length) {
  return length > 0 ? 2.0 * area / (std::sqrt(3.0) * length * length) : 0;
}

/// The most vertices RemeshIsotropic is asked to make (about 1.5 GB for MeshLab's mesh and
/// its projection copy): above it a caller refuses and suggests a longer edge.
constexpr double kMaxRemeshVertices = 4e6;

namespace detail {
// The remesher marks the faces of the surface it projects on, and we build its FF adjacency.
// With optional (Ocf) components, as in MeshLab's CMeshO, a fresh copy has neither until they
// are enabled (MeshLab's own filter does toProjectCopy.face.EnableMark()); static components
// need nothing.
template <class FaceContainer>
auto EnableFaceMarkAndFF(FaceContainer& c, int) -> decltype(c.EnableMark(), c.EnableFFAdjacency(), void()) {
  c.EnableMark();
  c.EnableFFAdjacency();
}
template <class FaceContainer>
void EnableFaceMarkAndFF(FaceContainer&, long) {}
}  // namespace detail

template <class MeshType>
void RemeshIsotropic(MeshType& m, const RemeshOptions& o) {
  if (o.targetEdgeLength <= 0) return;
  vcg::tri::Clean<MeshType>::RemoveUnreferencedVertex(m);
  vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
  vcg::tri::UpdateTopology<MeshType>::FaceFace(m);
  vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
  vcg::tri::UpdateBounding<MeshType>::Box(m);
  vcg::tri::UpdateNormal<MeshType>::PerVertexNormalizedPerFaceNormalized(m);
  MeshType input;
  detail::EnableFaceMarkAndFF(input.face, 0);
  vcg::tri::Append<MeshType, MeshType>::MeshCopy(input, m);
  vcg::tri::UpdateTopology<MeshType>::FaceFace(input);
  vcg::tri::UpdateBounding<MeshType>::Box(input);
  vcg::tri::UpdateNormal<MeshType>::PerVertexNormalizedPerFaceNormalized(input);
  typename vcg::tri::IsotropicRemeshing<MeshType>::Params p;
  p.SetTargetLen(typename MeshType::ScalarType(o.targetEdgeLength));
  p.SetFeatureAngleDeg(typename MeshType::ScalarType(o.featureAngleDeg));
  p.iter = o.iterations;
  p.maxSurfDist = typename MeshType::ScalarType(o.targetEdgeLength / 10);
  vcg::tri::IsotropicRemeshing<MeshType>::Do(m, input, p);
  vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
  vcg::tri::UpdateTopology<MeshType>::FaceFace(m);
  vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
  vcg::tri::UpdateBounding<MeshType>::Box(m);
  vcg::tri::UpdateNormal<MeshType>::PerVertexNormalizedPerFaceNormalized(m);
}

}  // namespace irregular
}  // namespace vcg_ext
