// filter_irregular: the valences of the few vertices one graph operation touches.
//
// Why: AtomicOperations::Candidates (atomic_ops.h) predicts, for every flip, collapse and split
// around a group, the valences before and after (sec. 6.1 rules) and asks a test whether to
// keep it. Most candidates fail. As std::map<int, int>, the two small maps cost a tenth of
// Automatic Reduction's time in node copies; here they are a fixed array.
//
// A ValenceChanges is a map from vertex index to valence with at most kCapacity entries,
// iterated in increasing index order (as std::map is), with std::map's insert semantics: a
// key given twice keeps its first value.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <map>
#include <stdexcept>
#include <utility>

namespace vcg_ext {
namespace irregular {

class ValenceChanges {
 public:
  typedef std::pair<int, int> value_type;
  /// A flip or collapse touches 4 vertices, a split 4 (one created); 6 leaves room.
  static constexpr size_t kCapacity = 6;

  ValenceChanges() = default;
  ValenceChanges(std::initializer_list<value_type> l) { Assign(l); }
  ValenceChanges& operator=(std::initializer_list<value_type> l) {
    Assign(l);
    return *this;
  }

  /// Adds (key, value) unless key is in already; false then (std::map::insert).
  bool Insert(int key, int value) {
    size_t i = LowerBound(key);
    if (i < n_ && a_[i].first == key) return false;
    if (n_ == kCapacity) throw std::length_error("ValenceChanges: more than kCapacity vertices");
    for (size_t j = n_; j > i; --j) a_[j] = a_[j - 1];
    a_[i] = value_type(key, value);
    ++n_;
    return true;
  }
  size_t count(int key) const { return Find(key) ? 1 : 0; }
  int at(int key) const {
    const value_type* p = Find(key);
    if (p == nullptr) throw std::out_of_range("ValenceChanges::at");
    return p->second;
  }
  /// The value of key, inserted as 0 if absent (std::map::operator[]).
  int& operator[](int key) {
    Insert(key, 0);
    return const_cast<value_type*>(Find(key))->second;
  }
  void erase(int key) {
    size_t i = LowerBound(key);
    if (i == n_ || a_[i].first != key) return;
    for (size_t j = i + 1; j < n_; ++j) a_[j - 1] = a_[j];
    --n_;
  }
  const value_type* begin() const { return a_; }
  const value_type* end() const { return a_ + n_; }
  size_t size() const { return n_; }
  bool empty() const { return n_ == 0; }
  std::map<int, int> ToMap() const { return std::map<int, int>(begin(), end()); }

 private:
  void Assign(std::initializer_list<value_type> l) {
    n_ = 0;
    for (auto& kv : l) Insert(kv.first, kv.second);
  }
  size_t LowerBound(int key) const {
    size_t i = 0;
    while (i < n_ && a_[i].first < key) ++i;
    return i;
  }
  const value_type* Find(int key) const {
    size_t i = LowerBound(key);
    return i < n_ && a_[i].first == key ? a_ + i : nullptr;
  }

  value_type a_[kCapacity];
  size_t n_ = 0;
};

}  // namespace irregular
}  // namespace vcg_ext
