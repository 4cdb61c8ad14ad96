// filter_irregular: a uniform hash grid of oriented sample points, for "which input samples lie
// in this box" queries in O(points in the box) (the local Hausdorff check of
// automatic_reduction.h).
#pragma once

#include <cmath>
#include <cstdint>
#include <unordered_map>
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
    for (size_t i = 0; i < points_.size(); ++i) {
      const auto& p = points_[i];
      cells_[Key(Cell(p[0]), Cell(p[1]), Cell(p[2]))].push_back(int(i));
    }
  }

  const vcg::Point3f& Point(int i) const { return points_[size_t(i)]; }
  const vcg::Point3f& Normal(int i) const { return normals_[size_t(i)]; }
  size_t Size() const { return points_.size(); }

  /// Indices of the points inside box (closed).
  std::vector<int> InBox(const vcg::Box3<float>& box) const {
    std::vector<int> out;
    if (box.IsNull()) return out;
    for (int64_t x = Cell(box.min[0]); x <= Cell(box.max[0]); ++x)
      for (int64_t y = Cell(box.min[1]); y <= Cell(box.max[1]); ++y)
        for (int64_t z = Cell(box.min[2]); z <= Cell(box.max[2]); ++z) {
          auto it = cells_.find(Key(x, y, z));
          if (it == cells_.end()) continue;
          for (int i : it->second)
            if (box.IsIn(points_[size_t(i)])) out.push_back(i);
        }
    return out;
  }

 private:
  int64_t Cell(float c) const { return int64_t(std::floor(c / cell_)); }
  static uint64_t Key(int64_t x, int64_t y, int64_t z) {
    // 21 bits per axis: enough for any mesh at any cell size used here
    return (uint64_t(x & 0x1FFFFF) << 42) | (uint64_t(y & 0x1FFFFF) << 21) | uint64_t(z & 0x1FFFFF);
  }
  float cell_ = 1.f;
  std::vector<vcg::Point3f> points_, normals_;
  std::unordered_map<uint64_t, std::vector<int>> cells_;
};

}  // namespace irregular
}  // namespace vcg_ext
