// filter_irregular: a uniform hash grid of oriented sample points, for "which input samples lie
// in this box" queries in O(points in the box) (the local Hausdorff check of
// automatic_reduction.h).
//
// Samples at the same point with the same tag are one point with all their distinct normals:
// the sharp-edge samples repeat each vertex once per sharp edge and face around it, and each
// edge midpoint once per face (on a thin part of the man, 37,812 samples at 11,419 points).
// A check whose answer depends on the point alone then runs once per point; one that asks
// "does any of its normals ..." gets the same answer as over the separate samples.
//
// Two levels: blocks of kBlock^3 cells, hashed, each with a bit per cell that holds points
// and those points. The samples are sparse (by default only the input's sharp edges), so most
// queries find nothing; a query box several cells wide then costs a few block lookups and a
// bit test per cell, instead of a hash lookup per cell (the per-edit Hausdorff check asked
// about 125 cells per edited face, 8% of the reduction's time on the bunny; with the lookups
// per occupied cell still 7% on the bull under pymeshlab, 0.9.22).
#pragma once

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <algorithm>
#include <vector>

#include <vcg/space/box3.h>
#include <vcg/space/point3.h>

namespace vcg_ext {
namespace irregular {

class SampleGrid {
 public:
  /// points[i] with normals[i] and tags[i] (empty tags: all 0); cell: edge of a grid cell
  /// (about the size of the boxes queried). Equal points with equal tags are merged, in the
  /// order each point is first seen; each keeps its distinct normals in the order seen.
  /// merged (if given): per input point, the index of the merged point it became.
  void Build(const std::vector<vcg::Point3f>& points, const std::vector<vcg::Point3f>& normals, double cell,
             const std::vector<char>& tags = {}, std::vector<int>* merged = nullptr) {
    points_.clear();
    tags_.clear();
    normals_.clear();
    normalStart_.assign(1, 0);
    {
      // merge: (tag, point) -> merged index; then each merged point's normals, grouped
      struct Key3 {
        float x, y, z;
        char t;
        bool operator==(const Key3& o) const { return x == o.x && y == o.y && z == o.z && t == o.t; }
      };
      struct Hash3 {
        size_t operator()(const Key3& k) const {
          // +0.f: -0 and 0 compare equal, so they must hash alike
          const std::hash<float> h;
          return ((h(k.x + 0.f) * 31 + h(k.y + 0.f)) * 31 + h(k.z + 0.f)) * 31 + size_t(k.t);
        }
      };
      std::unordered_map<Key3, int, Hash3> index;
      index.reserve(points.size());
      std::vector<int> of(points.size());
      for (size_t i = 0; i < points.size(); ++i) {
        const char t = i < tags.size() ? tags[i] : 0;
        auto in = index.emplace(Key3{points[i][0], points[i][1], points[i][2], t}, int(points_.size()));
        if (in.second) points_.push_back(points[i]), tags_.push_back(t);
        of[i] = in.first->second;
      }
      std::vector<int> count(points_.size() + 1, 0);
      for (size_t i = 0; i < points.size(); ++i) ++count[size_t(of[i]) + 1];
      for (size_t k = 1; k < count.size(); ++k) count[k] += count[k - 1];
      std::vector<vcg::Point3f> grouped(points.size());
      std::vector<int> fill(count.begin(), count.end() - 1);
      for (size_t i = 0; i < points.size(); ++i) grouped[size_t(fill[size_t(of[i])]++)] = normals[i];
      // the distinct normals of each point, in the order seen
      for (size_t k = 0; k < points_.size(); ++k) {
        const size_t first = normals_.size();
        for (int j = count[k]; j < count[k + 1]; ++j)
          if (std::find(normals_.begin() + long(first), normals_.end(), grouped[size_t(j)]) == normals_.end())
            normals_.push_back(grouped[size_t(j)]);
        normalStart_.push_back(int(normals_.size()));
      }
      if (merged) merged->swap(of);
    }
    cell_ = cell > 0 ? float(cell) : 1.f;
    blockOf_.clear();
    blocks_.clear();
    // each block's (cell within the block, point) pairs, then sorted: a block's points cell by
    // cell in bit order, each cell's in increasing point order
    std::vector<std::vector<std::pair<int, int>>> members;
    for (size_t i = 0; i < points_.size(); ++i) {
      const auto& p = points_[i];
      const int64_t c[3] = {Cell(p[0]), Cell(p[1]), Cell(p[2])};
      const int64_t b[3] = {Block(c[0]), Block(c[1]), Block(c[2])};
      const auto in = blockOf_.emplace(Key(b[0], b[1], b[2]), int(blocks_.size()));
      if (in.second) blocks_.emplace_back(), members.emplace_back();
      members[size_t(in.first->second)].emplace_back(LocalCell(c[0], c[1], c[2], b), int(i));
    }
    for (size_t b = 0; b < blocks_.size(); ++b) {
      std::sort(members[b].begin(), members[b].end());
      CellBlock& blk = blocks_[b];
      int last = -1;
      for (const auto& lp : members[b]) {
        if (lp.first != last) {
          blk.occupied[lp.first >> 6] |= uint64_t(1) << (lp.first & 63);
          blk.start.push_back(int(blk.points.size()));
          last = lp.first;
        }
        blk.points.push_back(lp.second);
      }
      blk.start.push_back(int(blk.points.size()));
      for (int w = 1; w < kWords; ++w) blk.rank[w] = blk.rank[w - 1] + __builtin_popcountll(blk.occupied[w - 1]);
    }
  }

  const vcg::Point3f& Point(int i) const { return points_[size_t(i)]; }
  char Tag(int i) const { return tags_[size_t(i)]; }
  /// Point i's distinct normals: [NormalsBegin(i), NormalsEnd(i)).
  const vcg::Point3f* NormalsBegin(int i) const { return normals_.data() + normalStart_[size_t(i)]; }
  const vcg::Point3f* NormalsEnd(int i) const { return normals_.data() + normalStart_[size_t(i) + 1]; }
  /// Does one of point i's normals satisfy pred?
  template <class Pred>
  bool AnyNormal(int i, Pred pred) const {
    for (const vcg::Point3f* n = NormalsBegin(i); n != NormalsEnd(i); ++n)
      if (pred(*n)) return true;
    return false;
  }
  /// Merged points (see Build).
  size_t Size() const { return points_.size(); }

  /// Indices of the points inside box (closed), each once, in no particular order.
  std::vector<int> InBox(const vcg::Box3<float>& box) const {
    std::vector<int> out;
    InBox(box, out);
    return out;
  }
  /// The same into out (cleared first), whose room is reused.
  void InBox(const vcg::Box3<float>& box, std::vector<int>& out) const {
    out.clear();
    if (box.IsNull() || points_.empty()) return;
    const int64_t lo[3] = {Cell(box.min[0]), Cell(box.min[1]), Cell(box.min[2])};
    const int64_t hi[3] = {Cell(box.max[0]), Cell(box.max[1]), Cell(box.max[2])};
    // the occupied blocks first; then the box's cells within each, an empty cell skipped by
    // its bit (a query box is several cells wide on each axis, and most of its cells are empty)
    for (int64_t bx = Block(lo[0]); bx <= Block(hi[0]); ++bx)
      for (int64_t by = Block(lo[1]); by <= Block(hi[1]); ++by)
        for (int64_t bz = Block(lo[2]); bz <= Block(hi[2]); ++bz) {
          const auto found = blockOf_.find(Key(bx, by, bz));
          if (found == blockOf_.end()) continue;
          const CellBlock& blk = blocks_[size_t(found->second)];
          const int64_t b[3] = {bx, by, bz};
          int64_t from[3], to[3];
          for (int a = 0; a < 3; ++a)
            from[a] = std::max(lo[a], b[a] * kBlock), to[a] = std::min(hi[a], b[a] * kBlock + kBlock - 1);
          // A column of a block's cells along z (fixed x, y) is one byte of its occupancy bits
          // (LocalCell): the occupied cells of the box's run along it are the set bits of that
          // byte within the run, visited in increasing z as a cell-by-cell loop would.
          const int zlo = int(from[2] - b[2] * kBlock), zhi = int(to[2] - b[2] * kBlock);
          const uint64_t runMask = ((uint64_t(2) << zhi) - 1) & ~((uint64_t(1) << zlo) - 1);
          for (int64_t x = from[0]; x <= to[0]; ++x)
            for (int64_t y = from[1]; y <= to[1]; ++y) {
              const int column = LocalCell(x, y, b[2] * kBlock, b);
              const uint64_t word = blk.occupied[column >> 6];
              for (uint64_t run = (word >> (column & 63)) & runMask; run != 0; run &= run - 1) {
                const int local = column + __builtin_ctzll(run);
                const uint64_t bit = uint64_t(1) << (local & 63);
                const int k = blk.rank[local >> 6] + __builtin_popcountll(word & (bit - 1));
                for (int j = blk.start[size_t(k)]; j < blk.start[size_t(k) + 1]; ++j) {
                  const int i = blk.points[size_t(j)];
                  if (box.IsIn(points_[size_t(i)])) out.push_back(i);
                }
              }
            }
        }
  }

 private:
  static constexpr int64_t kBlock = 8;  ///< cells per block edge
  static constexpr int kWords = int(kBlock * kBlock * kBlock / 64);
  static_assert(kBlock == 8, "InBox reads a column of a block's cells as one byte of its occupancy bits");
  /// The cells of a block that hold points, and their points.
  struct CellBlock {
    uint64_t occupied[kWords] = {};  ///< bit LocalCell: the cell holds a point
    int rank[kWords] = {};           ///< occupied cells in the words before each word
    std::vector<int> start;          ///< per occupied cell in bit order, its first entry in points; then the end
    std::vector<int> points;         ///< point indices, cell by cell, each cell's in increasing order
  };
  int64_t Cell(float c) const { return int64_t(std::floor(c / cell_)); }
  /// The block of a cell index: floor division, also for negative indices.
  static int64_t Block(int64_t cell) { return cell >= 0 ? cell / kBlock : -((-cell + kBlock - 1) / kBlock); }
  /// A cell's place in its block b (block indices): (x * kBlock + y) * kBlock + z of its offsets
  /// from the block's corner.
  static int LocalCell(int64_t x, int64_t y, int64_t z, const int64_t b[3]) {
    return int(((x - b[0] * kBlock) * kBlock + (y - b[1] * kBlock)) * kBlock + (z - b[2] * kBlock));
  }
  static uint64_t Key(int64_t x, int64_t y, int64_t z) {
    // 21 bits per axis: enough for any mesh at any cell size used here
    return (uint64_t(x & 0x1FFFFF) << 42) | (uint64_t(y & 0x1FFFFF) << 21) | uint64_t(z & 0x1FFFFF);
  }
  float cell_ = 1.f;
  std::vector<vcg::Point3f> points_, normals_;  ///< merged points; their normals, point by point
  std::vector<int> normalStart_{0};             ///< point i's normals: [normalStart_[i], normalStart_[i + 1])
  std::vector<char> tags_;
  std::unordered_map<uint64_t, int> blockOf_;   ///< block key -> its index in blocks_ (blocks holding a point)
  std::vector<CellBlock> blocks_;
};

}  // namespace irregular
}  // namespace vcg_ext
