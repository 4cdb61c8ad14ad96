// filter_irregular: distances from points to the live faces of a mesh, without copying it.
//
// HausdorffPercent (quality.h) measures the input's samples against the edited mesh. It used to
// build a SurfaceProjector of the edited mesh: a second copy of the mesh plus a vcg grid of up
// to 8M cells (~200 MB at a million faces, next to everything else the run holds). This copies
// nothing of the mesh: it reads the faces' corners from the mesh itself (converted to float
// when a face is measured), and keeps a sparse uniform grid stored as sorted arrays: the
// occupied cells' keys, an offset per cell and the faces of each cell (indices into m.face; a
// face is in every cell its box overlaps). Cells are two mean edge lengths wide, so a point near
// the surface looks at a cell or a few of its neighbours (those nearer than the best distance
// so far). About 17 bytes per face. Cells one edge wide hold fewer faces but a face lies in
// more of them: bunny00 subdivided twice (1.2M faces), 68 MB (57 bytes a face, with copies of
// the corners then) and 5.5 s for the input's samples, against 42 MB and 8.5 s with two: the
// grid is built at the end of a reduction, next to everything else the run holds, where memory
// counts more. Copying the corners (three vertex indices a face, a float position a vertex)
// cost 18 more bytes a face.
//
// The distance of a point to a face is vcg's (vcg::face::PointDistanceBase, the test vcg's grid
// search runs), on the face's corners converted to float and its normal computed as vcg's
// UpdateNormal::PerFaceNormalized computes it: so Distance() returns, to the bit, what
// SurfaceProjector::Closest on a copy of the same mesh returns (test_memory.cpp checks it).
//
// Preconditions: |cell coordinates| < 2^20 (a mesh less than a million mean edge lengths
// across); the mesh stays as it is while the grid lives (it reads the mesh's faces). Costs:
// O(F log F) to build, O(faces in the cells near p) per query; a point farther than 8 cells from
// every face scans the list of occupied cells.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/simplex/face/distance.h>
#include <vcg/space/box3.h>
#include <vcg/space/point3.h>

namespace vcg_ext {
namespace irregular {

namespace distance_grid_detail {
/// What vcg::face::PointDistanceBase reads of a face: corners (cP, and cV()->cP() on the edge
/// cases), the normal, the bounding box; float, like SurfaceProjector's copy.
struct Corner {
  vcg::Point3f p;
  const vcg::Point3f& cP() const { return p; }
};
struct FaceView {
  typedef float ScalarType;
  typedef vcg::Point3f CoordType;
  Corner v[3];
  vcg::Point3f n;
  const vcg::Point3f& cP(int i) const { return v[i].p; }
  const Corner* cV(int i) const { return &v[i]; }
  const vcg::Point3f& cN() const { return n; }
  void GetBBox(vcg::Box3f& bb) const {
    bb.Set(cP(0));
    bb.Add(cP(1));
    bb.Add(cP(2));
  }
};
}  // namespace distance_grid_detail

template <class MeshType>
class MeshDistanceGrid {
 public:
  /// Indexes the live faces of m.
  explicit MeshDistanceGrid(const MeshType& m) : m_(m) {
    for (const auto& v : m.vert)
      if (!v.IsD()) diagBox_.Add(vcg::Point3f::Construct(v.cP()));
    double sum = 0;
    long edges = 0;
    for (const auto& f : m.face) {
      if (f.IsD()) continue;
      for (int z = 0; z < 3; ++z, ++edges) sum += double((f.cP(z) - f.cP((z + 1) % 3)).Norm());
    }
    cell_ = float(std::max(kCellEdges * (edges ? sum / double(edges) : 1.0), 1e-12));
    // the occupied cells: every cell a face's box overlaps, gathered in an open-addressing set
    // (8 bytes a slot, at most 70% full) rather than as one key per face and cell, sorted
    {
      std::vector<uint64_t> set(size_t(1) << 16, kEmpty);
      size_t used = 0;
      auto insert = [&](std::vector<uint64_t>& table, uint64_t k) {
        const size_t mask = table.size() - 1;
        for (size_t h = (k * 0x9E3779B97F4A7C15ull) >> 20 & mask;; h = (h + 1) & mask) {
          if (table[h] == k) return false;
          if (table[h] == kEmpty) return table[h] = k, true;
        }
      };
      for (uint32_t t = 0; t < m.face.size(); ++t)
        if (!m.face[t].IsD()) ForCells(Box(t), [&](uint64_t k) {
          if (!insert(set, k)) return;
          if (10 * ++used <= 7 * set.size()) return;
          std::vector<uint64_t> bigger(2 * set.size(), kEmpty);
          for (uint64_t x : set)
            if (x != kEmpty) insert(bigger, x);
          set.swap(bigger);
        });
      cellKeys_.reserve(used);
      for (uint64_t x : set)
        if (x != kEmpty) cellKeys_.push_back(x);
    }
    std::sort(cellKeys_.begin(), cellKeys_.end());
    // faces per cell (counts, then offsets), then the faces themselves
    cellStart_.assign(cellKeys_.size() + 1, 0);
    for (uint32_t t = 0; t < m.face.size(); ++t)
      if (!m.face[t].IsD()) ForCells(Box(t), [&](uint64_t k) { ++cellStart_[CellOf(k) + 1]; });
    for (size_t c = 0; c < cellKeys_.size(); ++c) cellStart_[c + 1] += cellStart_[c];
    cellFaces_.resize(cellStart_.back());
    std::vector<uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (uint32_t t = 0; t < m.face.size(); ++t)
      if (!m.face[t].IsD()) ForCells(Box(t), [&](uint64_t k) { cellFaces_[fill[CellOf(k)]++] = t; });
    lastQuery_.assign(m.face.size(), 0);
    hasFF_ = vcg::tri::HasFFAdjacency(m);
  }

  /// Bytes held, for memory accounting.
  size_t Bytes() const {
    return cellKeys_.capacity() * 8 + (cellStart_.capacity() + cellFaces_.capacity() + lastQuery_.capacity()) * 4;
  }

  /// The bounding-box diagonal of the live vertices (as a SurfaceProjector of m reports it).
  float Diagonal() const { return diagBox_.Diag(); }

  /// Is p within r of face t or of a face next to it (FF, when the mesh has it)? One to four
  /// point-face distances: for a maximum of distances (the one-sided Hausdorff distance), a
  /// sample that a face near the last one's closest face keeps within the maximum so far cannot
  /// raise it, and needs no search.
  bool NearFace(uint32_t t, const vcg::Point3f& p, float r) const {
    if (t >= m_.face.size() || m_.face[t].IsD()) return false;
    float d = r;
    if (Measure(t, p, d)) return true;
    if (!hasFF_) return false;
    for (int z = 0; z < 3; ++z) {
      const auto* g = m_.face[t].cFFp(z);
      if (g == nullptr || g == &m_.face[t]) continue;
      if (Measure(uint32_t(g - &m_.face[0]), p, d)) return true;
    }
    return false;
  }
  /// The face the last Distance() found closest (kNoFace if none within its maxDist).
  uint32_t LastClosest() const { return closest_; }
  static constexpr uint32_t kNoFace = ~uint32_t(0);

  /// Distance from p to the closest live face, or maxDist if none is closer.
  float Distance(const vcg::Point3f& p, float maxDist) {
    closest_ = kNoFace;
    if (cellKeys_.empty()) return maxDist;
    if (++query_ == 0) {  // the stamps wrapped around: start them again
      std::fill(lastQuery_.begin(), lastQuery_.end(), 0);
      query_ = 1;
    }
    float best = maxDist;
    const int64_t c[3] = {Cell(p[0]), Cell(p[1]), Cell(p[2])};
    // Shells of cells around p's cell, nearest first. A face not measured yet lies only in
    // cells outside the block searched, so it is at least as far from p as the nearest wall of
    // the block that has occupied cells behind it: stop once the best distance is within that
    // (less a margin for the rounding of the cell coordinates).
    for (int64_t r = 0; r <= kShells; ++r) {
      Shell(c, r, p, best);
      bool covered = true;
      float wall = std::numeric_limits<float>::max();
      for (int a = 0; a < 3; ++a) {
        if (c[a] - r > cellMin_[a]) covered = false, wall = std::min(wall, p[a] - float(c[a] - r) * cell_);
        if (c[a] + r < cellMax_[a]) covered = false, wall = std::min(wall, float(c[a] + r + 1) * cell_ - p[a]);
      }
      if (covered || best < wall - kMargin * cell_) return best;
    }
    // Far from every face (never so for a point near the surface): every other cell whose box
    // is nearer than the best so far.
    for (size_t cell = 0; cell < cellKeys_.size(); ++cell) {
      int64_t x[3];
      Decode(cellKeys_[cell], x);
      bool inBlock = true;
      for (int a = 0; a < 3; ++a) inBlock = inBlock && std::abs(x[a] - c[a]) <= kShells;
      if (inBlock || BoxDistance(x[0], x[1], x[2], p) - kMargin * cell_ >= best) continue;
      for (uint32_t k = cellStart_[cell]; k < cellStart_[cell + 1]; ++k) Test(cellFaces_[k], p, best);
    }
    return best;
  }

 private:
  static constexpr size_t kNone = size_t(-1);
  static constexpr uint64_t kEmpty = ~uint64_t(0);  ///< no key has all 64 bits set (63 are used)
  static constexpr double kCellEdges = 2;  ///< cell edge, in mean edge lengths
  static constexpr int64_t kShells = 8;    ///< shells searched around a point before scanning every cell
  static constexpr float kMargin = 1e-4f;  ///< share of a cell kept back for rounding
  typedef distance_grid_detail::Corner Corner;
  typedef distance_grid_detail::FaceView FaceView;

  int64_t Cell(float x) const { return int64_t(std::floor(x / cell_)); }
  static uint64_t Key(int64_t x, int64_t y, int64_t z) {
    return (uint64_t(x & 0x1FFFFF) << 42) | (uint64_t(y & 0x1FFFFF) << 21) | uint64_t(z & 0x1FFFFF);
  }
  /// Cell coordinates of a key (21 bits each, two's complement: |coordinate| < 2^20 cells).
  static void Decode(uint64_t key, int64_t x[3]) {
    for (int a = 0; a < 3; ++a) {
      int64_t v = int64_t((key >> (42 - 21 * a)) & 0x1FFFFF);
      x[a] = v >= (int64_t(1) << 20) ? v - (int64_t(1) << 21) : v;
    }
  }
  /// Distance from p to the box of cell (x, y, z).
  float BoxDistance(int64_t x, int64_t y, int64_t z, const vcg::Point3f& p) const {
    const int64_t xyz[3] = {x, y, z};
    float d2 = 0;
    for (int a = 0; a < 3; ++a) {
      const float lo = float(xyz[a]) * cell_, hi = float(xyz[a] + 1) * cell_;
      const float d = p[a] < lo ? lo - p[a] : p[a] > hi ? p[a] - hi : 0.f;
      d2 += d * d;
    }
    return std::sqrt(d2);
  }
  /// Measures the faces of the cells at Chebyshev distance r from cell c (within the occupied
  /// range).
  void Shell(const int64_t c[3], int64_t r, const vcg::Point3f& p, float& best) {
    auto visit = [&](int64_t x, int64_t y, int64_t z) {
      // a cell whose box is farther than the best so far holds nothing nearer
      if (BoxDistance(x, y, z, p) - kMargin * cell_ >= best) return;
      const size_t cell = Find(Key(x, y, z));
      if (cell == kNone) return;
      for (uint32_t k = cellStart_[cell]; k < cellStart_[cell + 1]; ++k) Test(cellFaces_[k], p, best);
    };
    const int64_t zlo = std::max(c[2] - r, cellMin_[2]), zhi = std::min(c[2] + r, cellMax_[2]);
    for (int64_t x = std::max(c[0] - r, cellMin_[0]); x <= std::min(c[0] + r, cellMax_[0]); ++x)
      for (int64_t y = std::max(c[1] - r, cellMin_[1]); y <= std::min(c[1] + r, cellMax_[1]); ++y) {
        if (std::abs(x - c[0]) == r || std::abs(y - c[1]) == r) {
          for (int64_t z = zlo; z <= zhi; ++z) visit(x, y, z);
        } else {
          if (c[2] - r >= cellMin_[2] && c[2] - r <= cellMax_[2]) visit(x, y, c[2] - r);
          if (r > 0 && c[2] + r >= cellMin_[2] && c[2] + r <= cellMax_[2]) visit(x, y, c[2] + r);
        }
      }
  }
  size_t Find(uint64_t key) const {
    auto it = std::lower_bound(cellKeys_.begin(), cellKeys_.end(), key);
    return it != cellKeys_.end() && *it == key ? size_t(it - cellKeys_.begin()) : kNone;
  }
  size_t CellOf(uint64_t key) const { return size_t(std::lower_bound(cellKeys_.begin(), cellKeys_.end(), key) - cellKeys_.begin()); }

  /// Face t's corners in float, as SurfaceProjector's copy has them.
  vcg::Point3f Corner3f(uint32_t t, int z) const { return vcg::Point3f::Construct(m_.face[t].cP(z)); }
  vcg::Box3f Box(uint32_t t) const {
    vcg::Box3f b;
    for (int z = 0; z < 3; ++z) b.Add(Corner3f(t, z));
    return b;
  }
  /// Calls fn with the key of every cell b overlaps; remembers the range of the occupied cells.
  template <class Fn>
  void ForCells(const vcg::Box3f& b, Fn fn) {
    const int64_t lo[3] = {Cell(b.min[0]), Cell(b.min[1]), Cell(b.min[2])};
    const int64_t hi[3] = {Cell(b.max[0]), Cell(b.max[1]), Cell(b.max[2])};
    for (int a = 0; a < 3; ++a) {
      cellMin_[a] = std::min(cellMin_[a], lo[a]);
      cellMax_[a] = std::max(cellMax_[a], hi[a]);
    }
    for (int64_t x = lo[0]; x <= hi[0]; ++x)
      for (int64_t y = lo[1]; y <= hi[1]; ++y)
        for (int64_t z = lo[2]; z <= hi[2]; ++z) fn(Key(x, y, z));
  }

  /// vcg's point-face distance on face t, as SurfaceProjector's float copy has it.
  void Test(uint32_t t, const vcg::Point3f& p, float& best) {
    if (lastQuery_[t] == query_) return;  // a face in several cells is measured once
    lastQuery_[t] = query_;
    if (Measure(t, p, best)) closest_ = t;
  }
  /// vcg's point-face distance on face t if under d (then d is set and true returned).
  bool Measure(uint32_t t, const vcg::Point3f& p, float& d) const {
    FaceView view;
    for (int z = 0; z < 3; ++z) view.v[z].p = Corner3f(t, z);
    // a face whose box is farther than d cannot come under it: skip vcg's test and the normal
    // (the same answer; most faces of a cell lie beside p)
    for (int a = 0; a < 3; ++a) {
      if (p[a] + d < std::min(view.v[0].p[a], std::min(view.v[1].p[a], view.v[2].p[a]))) return false;
      if (p[a] - d > std::max(view.v[0].p[a], std::max(view.v[1].p[a], view.v[2].p[a]))) return false;
    }
    // UpdateNormal::PerFaceNormalized: the cross product of the edges from corner 0, normalized
    view.n = (view.cP(1) - view.cP(0)) ^ (view.cP(2) - view.cP(0));
    view.n.Normalize();
    vcg::Point3f q;
    return !m_.face[t].IsD() && vcg::face::PointDistanceBase(view, p, d, q);
  }

  const MeshType& m_;
  float cell_ = 1;
  vcg::Box3f diagBox_;
  int64_t cellMin_[3] = {std::numeric_limits<int64_t>::max(), std::numeric_limits<int64_t>::max(),
                         std::numeric_limits<int64_t>::max()};
  int64_t cellMax_[3] = {std::numeric_limits<int64_t>::min(), std::numeric_limits<int64_t>::min(),
                         std::numeric_limits<int64_t>::min()};  ///< range of the occupied cells
  std::vector<uint64_t> cellKeys_;     ///< occupied cells, sorted
  std::vector<uint32_t> cellStart_;    ///< per cell: where its faces start in cellFaces_ (one more at the end)
  std::vector<uint32_t> cellFaces_;    ///< indices into m.face (live faces), cell by cell
  std::vector<uint32_t> lastQuery_;    ///< per face index: the last query that measured it
  uint32_t query_ = 0;
  uint32_t closest_ = kNoFace;         ///< the face the last Distance() found closest
  bool hasFF_ = false;                 ///< the mesh has face-face adjacency (NearFace reads it)
};

}  // namespace irregular
}  // namespace vcg_ext
