// filter_irregular: closest-point queries on a frozen copy of the original surface.
//
// Relaxation moves vertices and then projects them back onto the surface the user started
// with (paper sec. 8), not onto the drifting edited mesh. This keeps its own copy of the
// original mesh and a vcg uniform grid over its faces (vcg::GridStaticPtr), and answers
// closest-point queries with vcg's grid search (vcg::GridClosest, as
// vcg::tri::GetClosestFaceBase runs it) or, from a hint face, over the few cells within the
// hint's distance (ClosestFrom). Both test a face's bounding box before vcg's point-face
// distance (BoxedPointDistance): the native bench on bunny00 at 20K, 27.07 G -> 26.04 G
// instructions (callgrind), the same meshes to within 4e-8 of the diagonal.
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
    vcg::tri::FaceTmark<PMesh> marker;
    marker.SetMesh(const_cast<PMesh*>(&copy_));
    auto* f = vcg::GridClosest(const_cast<Grid&>(grid_), BoxedDistanceFunctor(), marker, p, md, d, q);
    if (face) *face = f;
    if (f == nullptr) {
      if (dist) *dist = md;
      return p;
    }
    if (dist) *dist = d;
    if (normal) *normal = f->N();
    return q;
  }

  /// Closest, starting from a face the caller expects near p (hint: any face of Mesh(), or
  /// nullptr). The search looks only at the grid cells within r of p, r the smaller of maxDist
  /// and the hint's distance: every face nearer than r overlaps one of them. That is one to
  /// eight cells when p lies next to the hint (a vertex relaxed a fraction of an edge) or when
  /// maxDist is under a cell (the edit guard's reach), where vcg's search goes on to every cell
  /// within a cell diagonal (up to 64) when p's own cell holds nothing. (Scanning p's own cell
  /// first, to shrink the box, saved nothing: the hints are already that good.) The same distance as Closest, and the same answer when
  /// nothing is within maxDist; where two faces are equally near (p over their shared edge),
  /// the point may differ in the last bits. A box over kHintCells cells falls back to Closest.
  Coord ClosestFrom(const proj_detail::PFace* hint, const Coord& p, float* dist = nullptr, Coord* normal = nullptr,
                    float maxDist = 0, const proj_detail::PFace** face = nullptr) const {
    const float md = maxDist > 0 ? maxDist : diag_;
    float best = md;
    Coord q = p;
    const proj_detail::PFace* winner = nullptr;
    if (hint != nullptr && !hint->IsD() && vcg::face::PointDistanceBase(*hint, p, best, q)) winner = hint;
    vcg::Box3i ib;
    grid_.BoxToIBox(vcg::Box3f(p, best), ib);
    ib.Intersect(vcg::Box3i(vcg::Point3i(0, 0, 0), grid_.siz - vcg::Point3i(1, 1, 1)));
    if (!ib.IsNull()) {
      const vcg::Point3i span = ib.max - ib.min + vcg::Point3i(1, 1, 1);
      if (span[0] * span[1] * span[2] > kHintCells) return Closest(p, dist, normal, maxDist, face);
      Grid& g = const_cast<Grid&>(grid_);
      for (int z = ib.min[2]; z <= ib.max[2]; ++z)
        for (int y = ib.min[1]; y <= ib.max[1]; ++y)
          for (int x = ib.min[0]; x <= ib.max[0]; ++x) {
            Grid::CellIterator first, last;
            g.Grid(x, y, z, first, last);
            // a face in several of these cells is measured once a cell: cheaper than marking
            for (auto l = first; l != last; ++l) {
              const proj_detail::PFace* f = &**l;
              Coord t;
              if (f != winner && !f->IsD() && BoxedPointDistance(*f, p, best, t)) winner = f, q = t;
            }
          }
    }
    if (face) *face = winner;
    if (winner == nullptr) {
      if (dist) *dist = md;
      return p;
    }
    if (dist) *dist = best;
    if (normal) *normal = winner->cN();
    return q;
  }

  /// Closest for vertex `key` of an edited mesh, starting from the face found for that key the
  /// last time (ClosestFrom): relaxation projects the same vertices round after round, each a
  /// little farther along. The hints are a cache only (any face is a valid hint; a reused or
  /// foreign key costs a full search): they do not make the projector's answers depend on
  /// history beyond the last bits of ClosestFrom's ties. Not thread-safe (neither is the rest
  /// of a reduction); 8 bytes per key.
  Coord ClosestForVertex(size_t key, const Coord& p) const {
    if (key >= vertexHint_.size()) vertexHint_.resize(std::max(key + 1, 2 * vertexHint_.size()), nullptr);
    const proj_detail::PFace* f = nullptr;
    const Coord q = ClosestFrom(vertexHint_[key], p, nullptr, nullptr, 0, &f);
    vertexHint_[key] = f;
    return q;
  }

  /// The face ClosestForVertex last found for `key` (nullptr if none): a hint for points near
  /// that vertex (the edit guard's probes of the faces around it).
  const proj_detail::PFace* VertexHint(size_t key) const { return key < vertexHint_.size() ? vertexHint_[key] : nullptr; }

  /// vcg's point-face distance (vcg::face::PointDistanceBase), after a test of p against the
  /// face's bounding box grown by dist: a face whose box is farther than the best distance so
  /// far cannot beat it, and most faces of a cell are such (they lie beside p, not under it,
  /// and vcg's test of the face's plane passes them on to the full computation).
  static bool BoxedPointDistance(const proj_detail::PFace& f, const Coord& p, float& dist, Coord& q) {
    const Coord &a = f.cP(0), &b = f.cP(1), &c = f.cP(2);
    for (int i = 0; i < 3; ++i) {
      if (p[i] + dist < std::min(a[i], std::min(b[i], c[i]))) return false;
      if (p[i] - dist > std::max(a[i], std::max(b[i], c[i]))) return false;
    }
    return vcg::face::PointDistanceBase(f, p, dist, q);
  }

  /// BoxedPointDistance as vcg's grid search calls a distance (vcg::GridClosest's functor).
  struct BoxedDistanceFunctor {
    typedef vcg::Point3f QueryType;
    static const vcg::Point3f& Pos(const QueryType& p) { return p; }
    bool operator()(const proj_detail::PFace& f, const QueryType& p, float& dist, vcg::Point3f& q) const {
      return BoxedPointDistance(f, p, dist, q);
    }
  };

  /// Is p within r of face f (a face of Mesh())? One point-face distance (see
  /// MeshDistanceGrid::NearFace).
  static bool NearFace(const proj_detail::PFace* f, const Coord& p, float r) {
    if (f == nullptr) return false;
    float d = r;
    Coord q;
    return vcg::face::PointDistanceBase(*f, p, d, q);
  }

  /// Is p within r of `hint`, or else of the face VertexHint gives for one of keys[0..n) (the
  /// vertices p lies among)? The latter becomes the hint. A witness only: any face of Mesh()
  /// within r proves p's distance at most r, whatever the keys (the edit guard's probes and
  /// the final Hausdorff measure skip their searches so).
  bool NearHints(const proj_detail::PFace*& hint, const Coord& p, float r, const size_t* keys, size_t n) const {
    if (NearFace(hint, p, r)) return true;
    for (size_t k = 0; k < n; ++k) {
      const proj_detail::PFace* h = VertexHint(keys[k]);
      if (h != hint && NearFace(h, p, r)) {
        hint = h;
        return true;
      }
    }
    return false;
  }

  float Diagonal() const { return diag_; }
  const PMesh& Mesh() const { return copy_; }

 private:
  typedef vcg::GridStaticPtr<proj_detail::PFace, float> Grid;
  /// ClosestFrom's bound on the cells a hint's box may cover before it falls back to vcg's
  /// search (a 3x3x3 block: p within about a cell of the hint).
  static constexpr int kHintCells = 27;
  PMesh copy_;
  mutable std::vector<const proj_detail::PFace*> vertexHint_;
  Grid grid_;
  float diag_ = 1;
};

}  // namespace irregular
}  // namespace vcg_ext
