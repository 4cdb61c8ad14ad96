// filter_irregular: a uniform hash grid of oriented sample points, for "which input samples lie
// in this box" queries in O(points in the box) (the local Hausdorff check of
// automatic_reduction.h).
//
// Two levels: the points' cells, and blocks of kBlock^3 cells that say which cells can hold
// any. The samples are sparse (by default only the input's sharp edges), so most queries find
// nothing; a query box several cells wide then costs a few block lookups instead of one
// lookup per cell (the per-edit Hausdorff check asked about 125 cells per edited face, 8% of
// the reduction's time on the bunny).
#pragma once

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <algorithm>
#include <vector>

#include <vcg/space/box3.h>
#include <vcg/space/point3.h>

namespace vcg_ext {
namespace irregular {

class SampleGrid {
 public:
  /// cell: edge of a grid cell (about the size of the boxes queried).
  void Build(std::vector<vcg::Point3f> points, std::vector<vcg::Point3f> normals, double cell) {
    points_ = std::move(points);
    normals_ = std::move(normals);
    cell_ = cell > 0 ? float(cell) : 1.f;
    cells_.clear();
    blocks_.clear();
    for (size_t i = 0; i < points_.size(); ++i) {
      const auto& p = points_[i];
      const int64_t x = Cell(p[0]), y = Cell(p[1]), z = Cell(p[2]);
      cells_[Key(x, y, z)].push_back(int(i));
      blocks_.insert(Key(Block(x), Block(y), Block(z)));
    }
  }

  const vcg::Point3f& Point(int i) const { return points_[size_t(i)]; }
  const vcg::Point3f& Normal(int i) const { return normals_[size_t(i)]; }
  size_t Size() const { return points_.size(); }

  /// Indices of the points inside box (closed), each once, in no particular order.
  std::vector<int> InBox(const vcg::Box3<float>& box) const {
    std::vector<int> out;
    if (box.IsNull() || points_.empty()) return out;
    const int64_t lo[3] = {Cell(box.min[0]), Cell(box.min[1]), Cell(box.min[2])};
    const int64_t hi[3] = {Cell(box.max[0]), Cell(box.max[1]), Cell(box.max[2])};
    // the occupied blocks first; then the box's cells within each
    for (int64_t bx = Block(lo[0]); bx <= Block(hi[0]); ++bx)
      for (int64_t by = Block(lo[1]); by <= Block(hi[1]); ++by)
        for (int64_t bz = Block(lo[2]); bz <= Block(hi[2]); ++bz) {
          if (!blocks_.count(Key(bx, by, bz))) continue;
          const int64_t b[3] = {bx, by, bz};
          int64_t from[3], to[3];
          for (int a = 0; a < 3; ++a)
            from[a] = std::max(lo[a], b[a] * kBlock), to[a] = std::min(hi[a], b[a] * kBlock + kBlock - 1);
          for (int64_t x = from[0]; x <= to[0]; ++x)
            for (int64_t y = from[1]; y <= to[1]; ++y)
              for (int64_t z = from[2]; z <= to[2]; ++z) {
                auto it = cells_.find(Key(x, y, z));
                if (it == cells_.end()) continue;
                for (int i : it->second)
                  if (box.IsIn(points_[size_t(i)])) out.push_back(i);
              }
        }
    return out;
  }

 private:
  static constexpr int64_t kBlock = 8;  ///< cells per block edge
  int64_t Cell(float c) const { return int64_t(std::floor(c / cell_)); }
  /// The block of a cell index: floor division, also for negative indices.
  static int64_t Block(int64_t cell) { return cell >= 0 ? cell / kBlock : -((-cell + kBlock - 1) / kBlock); }
  static uint64_t Key(int64_t x, int64_t y, int64_t z) {
    // 21 bits per axis: enough for any mesh at any cell size used here
    return (uint64_t(x & 0x1FFFFF) << 42) | (uint64_t(y & 0x1FFFFF) << 21) | uint64_t(z & 0x1FFFFF);
  }
  float cell_ = 1.f;
  std::vector<vcg::Point3f> points_, normals_;
  std::unordered_map<uint64_t, std::vector<int>> cells_;
  std::unordered_set<uint64_t> blocks_;  ///< blocks holding at least one point
};

}  // namespace irregular
}  // namespace vcg_ext
