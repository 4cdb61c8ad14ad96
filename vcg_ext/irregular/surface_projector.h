// filter_irregular: closest-point queries on a frozen copy of the original surface.
//
// Relaxation moves vertices and then projects them back onto the surface the user started
// with (paper sec. 8), not onto the drifting edited mesh. This keeps its own copy of the
// original mesh and a vcg uniform grid over its faces (vcg::GridStaticPtr), and answers
// closest-point queries with vcg::tri::GetClosestFaceBase.
#pragma once

#include <algorithm>
#include <memory>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/closest.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/space/index/grid_static_ptr.h>

namespace vcg_ext {
namespace irregular {

/// A light mesh type for the frozen copy (positions and face normals only: the closest-point
/// search and the edit guard's samples read face normals; a vertex normal, unread, would cost
/// 12 bytes a vertex, 7 MB at 1.2M faces).
namespace proj_detail {
class PVertex;
class PFace;
struct PUsedTypes : public vcg::UsedTypes<vcg::Use<PVertex>::AsVertexType, vcg::Use<PFace>::AsFaceType> {};
class PVertex : public vcg::Vertex<PUsedTypes, vcg::vertex::Coord3f, vcg::vertex::BitFlags> {};
class PFace : public vcg::Face<PUsedTypes, vcg::face::VertexRef, vcg::face::Normal3f, vcg::face::BitFlags,
                                vcg::face::Mark> {};
class PMesh : public vcg::tri::TriMesh<std::vector<PVertex>, std::vector<PFace>> {};
}  // namespace proj_detail

class SurfaceProjector {
 public:
  typedef proj_detail::PMesh PMesh;
  typedef vcg::Point3f Coord;

  /// Copies the live faces of m. O(F log F) once.
  template <class MeshType>
  explicit SurfaceProjector(const MeshType& m) {
    std::vector<int> remap(m.vert.size(), -1);
    int nv = 0;
    for (size_t i = 0; i < m.vert.size(); ++i)
      if (!m.vert[i].IsD()) remap[i] = nv++;
    vcg::tri::Allocator<PMesh>::AddVertices(copy_, size_t(nv));
    for (size_t i = 0; i < m.vert.size(); ++i)
      if (remap[i] >= 0) copy_.vert[size_t(remap[i])].P() = vcg::Point3f::Construct(m.vert[i].cP());
    int nf = 0;
    for (auto& f : m.face) nf += !f.IsD();
    vcg::tri::Allocator<PMesh>::AddFaces(copy_, size_t(nf));
    size_t k = 0;
    for (auto& f : m.face) {
      if (f.IsD()) continue;
      for (int z = 0; z < 3; ++z)
        copy_.face[k].V(z) = &copy_.vert[size_t(remap[vcg::tri::Index(m, f.cV(z))])];
      ++k;
    }
    vcg::tri::UpdateBounding<PMesh>::Box(copy_);
    vcg::tri::UpdateNormal<PMesh>::PerFaceNormalized(copy_);
    // vcg's grid inflates its box by one cell only; a point within a rounding error of that
    // box's max corner then maps to a cell past the end (GridClosest asserts). Points we query
    // are near the surface, so a margin of a few percent of the diagonal keeps them inside.
    vcg::Box3<float> box = copy_.bbox;
    box.Offset(0.05f * copy_.bbox.Diag() + 1e-6f);
    // vcg's default is one cell per face; a surface crosses only about F^(2/3) of the cells of a
    // 3D grid, so each crossed cell then holds about F^(1/3) faces (34 at 40K faces), and every
    // query measures them all. 16 cells per face brings that near the surface's own sampling
    // (bunny at 20K vertices: the reduction's time 11.1 s -> 8.6 s, same counts); capped at 2M
    // cells (16 MB of cell pointers; inputs above 131K faces get fewer cells per face) so that
    // on million-face inputs the grid does not set the run's memory peak (issue 14: at most 3x
    // a run that only loads and saves).
    const size_t cells = std::min<size_t>(16 * copy_.face.size(), size_t(1) << 21);
    grid_.Set(copy_.face.begin(), copy_.face.end(), box, int(std::max<size_t>(cells, 1)));
    diag_ = copy_.bbox.Diag();
  }

  /// Closest point of the original surface to p (p itself if nothing lies within maxDist;
  /// maxDist <= 0 means the bounding-box diagonal). dist receives the distance.
  /// face, if given, receives the closest face (nullptr if none).
  Coord Closest(const Coord& p, float* dist = nullptr, Coord* normal = nullptr, float maxDist = 0,
                const proj_detail::PFace** face = nullptr) const {
    float md = maxDist > 0 ? maxDist : diag_;
    float d = md;
    Coord q = p;
    auto* f = vcg::tri::GetClosestFaceBase(const_cast<PMesh&>(copy_), const_cast<Grid&>(grid_), p, md, d, q);
    if (face) *face = f;
    if (f == nullptr) {
      if (dist) *dist = md;
      return p;
    }
    if (dist) *dist = d;
    if (normal) *normal = f->N();
    return q;
  }

  /// Is p within r of face f (a face of Mesh())? One point-face distance (see
  /// MeshDistanceGrid::NearFace).
  static bool NearFace(const proj_detail::PFace* f, const Coord& p, float r) {
    if (f == nullptr) return false;
    float d = r;
    Coord q;
    return vcg::face::PointDistanceBase(*f, p, d, q);
  }

  float Diagonal() const { return diag_; }
  const PMesh& Mesh() const { return copy_; }

 private:
  typedef vcg::GridStaticPtr<proj_detail::PFace, float> Grid;
  PMesh copy_;
  Grid grid_;
  float diag_ = 1;
};

}  // namespace irregular
}  // namespace vcg_ext
