// filter_irregular: a spatial hash of a mesh's vertices for picking (edit_session.h).
//
// Cells are cubes of the pick radius, keyed by their integer coordinates; a cell holds the
// indices of the vertices whose position lay in it when last binned. Build() is O(V) once;
// Refresh(vertices) re-bins only the given vertices (and the vertices appended or truncated
// since the last refresh), so an edit that touches O(L) vertices costs O(L), never O(V).
// Queries read current positions, so a vertex that moved without being re-binned is still
// found if it moved less than one cell: ForEachNear scans one cell more than the radius needs.
// Deleted vertices stay binned until refreshed; callers skip them (the query does not).
// Build reserves room (twice the cells, an eighth more vertices; empty cells are kept) so a
// refresh does not rehash or reallocate in the middle of an edit.
// vcg's GridStaticPtr is static (no local update), hence this small hash.
#pragma once

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <vcg/complex/complex.h>

namespace vcg_ext {
namespace irregular {

template <class MeshType>
class PickGrid {
 public:
  typedef typename MeshType::CoordType CoordType;

  explicit PickGrid(MeshType& m) : m_(m) {}

  bool Built() const { return built_; }
  /// Mean edge length of the live faces (measured by Build).
  double MeanEdge() const { return meanEdge_; }

  /// Bins every live vertex; cells of size `cell` (<= 0: 1.5 mean edge lengths). O(V + F).
  void Build(double cell) {
    double sum = 0;
    long n = 0;
    for (auto& f : m_.face) {
      if (f.IsD()) continue;
      for (int z = 0; z < 3; ++z) sum += double((f.cP(z) - f.cP((z + 1) % 3)).Norm()), ++n;
    }
    meanEdge_ = n > 0 ? sum / double(n) : 1.0;
    cell_ = cell > 0 ? cell : 1.5 * meanEdge_;
    if (!(cell_ > 0)) cell_ = 1;
    cells_.clear();
    key_.reserve(m_.vert.size() + m_.vert.size() / 8 + 1024);
    key_.assign(m_.vert.size(), kNone);
    for (size_t i = 0; i < m_.vert.size(); ++i) Rebin(int(i));
    // room for new cells, so that a refresh never rehashes the whole table (O(V))
    cells_.reserve(2 * cells_.size() + 1024);
    built_ = true;
  }

  /// Re-bins the given vertices, drops the bins of vertices past the end of m.vert (an undo
  /// truncated them) and bins the vertices appended since the last refresh. O(given + changed).
  void Refresh(const std::vector<int>& touched) {
    if (!built_) return;
    for (size_t i = m_.vert.size(); i < key_.size(); ++i) Remove(int(i));
    const size_t old = key_.size();
    key_.resize(m_.vert.size(), kNone);
    for (size_t i = old; i < key_.size(); ++i) Rebin(int(i));
    for (int v : touched)
      if (v >= 0 && size_t(v) < key_.size()) Rebin(v);
  }

  /// Calls f(vertex, distance) for every binned vertex within r of p (deleted ones included).
  template <class F>
  void ForEachNear(const CoordType& p, double r, F f) const {
    const int reach = int(std::ceil(r / cell_)) + 1;  // +1: vertices moved since binned
    const long cx = Cell(p[0]), cy = Cell(p[1]), cz = Cell(p[2]);
    for (long x = cx - reach; x <= cx + reach; ++x)
      for (long y = cy - reach; y <= cy + reach; ++y)
        for (long z = cz - reach; z <= cz + reach; ++z) {
          auto it = cells_.find(Key(x, y, z));
          if (it == cells_.end()) continue;
          for (int v : it->second) {
            if (size_t(v) >= m_.vert.size()) continue;
            const double d = double((m_.vert[size_t(v)].cP() - p).Norm());
            if (d <= r) f(v, d);
          }
        }
  }

 private:
  static constexpr uint64_t kNone = ~uint64_t(0);

  long Cell(double x) const {
    double c = std::floor(x / cell_);
    const double lim = double(1 << 20) - 1;
    return long(std::max(-lim, std::min(lim, c)));
  }
  static uint64_t Key(long x, long y, long z) {
    const uint64_t m = (uint64_t(1) << 21) - 1;
    return ((uint64_t(x) & m) << 42) | ((uint64_t(y) & m) << 21) | (uint64_t(z) & m);
  }
  uint64_t KeyOf(int v) const {
    const auto& vert = m_.vert[size_t(v)];
    if (vert.IsD()) return kNone;
    return Key(Cell(vert.cP()[0]), Cell(vert.cP()[1]), Cell(vert.cP()[2]));
  }
  void Remove(int v) {
    if (size_t(v) >= key_.size() || key_[size_t(v)] == kNone) return;
    auto it = cells_.find(key_[size_t(v)]);
    if (it != cells_.end()) {
      auto& c = it->second;
      for (size_t i = 0; i < c.size(); ++i)
        if (c[i] == v) {
          c[i] = c.back();
          c.pop_back();
          break;
        }
    }
    key_[size_t(v)] = kNone;
  }
  void Rebin(int v) {
    const uint64_t k = KeyOf(v);
    if (k == key_[size_t(v)]) return;
    Remove(v);
    if (k == kNone) return;
    cells_[k].push_back(v);
    key_[size_t(v)] = k;
  }

  MeshType& m_;
  bool built_ = false;
  double cell_ = 1, meanEdge_ = 1;
  std::unordered_map<uint64_t, std::vector<int>> cells_;
  std::vector<uint64_t> key_;  ///< the cell each vertex is binned in (kNone: not binned)
};

}  // namespace irregular
}  // namespace vcg_ext
