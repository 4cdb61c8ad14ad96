// filter_irregular: a set of element indices (vertices or faces) for one local query.
//
// Why: the local queries run after every edit (k-rings, the faces an edit changed) asked a
// hash set whether they had seen an element; hashing was a tenth of Automatic Reduction's
// time. Here membership is a stamp per index: Begin() starts a new, empty set in O(1) by
// taking a new stamp, Insert and Contains are one array access. The array grows with the
// mesh (amortized O(1) per element the mesh gains), never per query.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace vcg_ext {
namespace irregular {

class StampSet {
 public:
  /// Starts a new empty set of indices below n.
  void Begin(size_t n) {
    if (stamps_.size() < n) stamps_.resize(std::max(n, 2 * stamps_.size()), 0);
    if (++current_ == 0) {  // the stamps wrapped around: forget them all, once in 2^32 sets
      std::fill(stamps_.begin(), stamps_.end(), 0u);
      current_ = 1;
    }
  }
  /// Adds i; false if it was already in.
  bool Insert(size_t i) {
    if (stamps_[i] == current_) return false;
    stamps_[i] = current_;
    return true;
  }
  bool Contains(size_t i) const { return stamps_[i] == current_; }
  /// Gives the array back (a later Begin grows it again).
  void Release() {
    std::vector<uint32_t>().swap(stamps_);
    current_ = 0;
  }

 private:
  std::vector<uint32_t> stamps_;
  uint32_t current_ = 0;
};

}  // namespace irregular
}  // namespace vcg_ext
