// filter_irregular: the valences of the few vertices an atomic operation touches.
//
// Why: AtomicOperations (atomic_ops.h) predicts, for every flip, collapse and split around a
// group, the valences before and after (sec. 6.1 rules), and every prediction and outcome
// carries its valence changes. Automatic Reduction makes about a million of them on bunny00.
// As std::map<int, int>, their nodes cost a tenth of its time in Candidates (0.9.3), and the
// predictions' and outcomes' maps 2-3% more in allocation (0.9.19); here they live inline.
//
// A ValenceChanges is a map from vertex index to valence, iterated in increasing index order
// (as std::map is), with std::map's insert semantics: a key given twice keeps its first
// value. Up to kInline entries it allocates nothing (a graph operation touches 4 vertices, an
// atomic operation of sec. 6.2 at most 7); beyond, it grows on the heap.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <map>
#include <ostream>
#include <stdexcept>
#include <utility>

#include "small_vector.h"

namespace vcg_ext {
namespace irregular {

class ValenceChanges {
 public:
  /// An entry: first = vertex index, second = valence (the names of std::map's pairs).
  struct Entry {
    int first;
    int second;
    bool operator==(const Entry& o) const { return first == o.first && second == o.second; }
    bool operator!=(const Entry& o) const { return !(*this == o); }
  };
  typedef Entry value_type;
  typedef Entry* iterator;
  typedef const Entry* const_iterator;
  static constexpr size_t kInline = 8;

  ValenceChanges() = default;
  ValenceChanges(std::initializer_list<std::pair<int, int>> l) { Assign(l); }
  ValenceChanges& operator=(std::initializer_list<std::pair<int, int>> l) {
    Assign(l);
    return *this;
  }

  /// Adds (key, value) unless key is in already; false then (std::map::insert).
  bool Insert(int key, int value) {
    const size_t i = LowerBound(key);
    if (i < a_.size() && a_[i].first == key) return false;
    a_.push_back(Entry{key, value});
    for (size_t j = a_.size() - 1; j > i; --j) a_[j] = a_[j - 1];
    a_[i] = Entry{key, value};
    return true;
  }
  size_t count(int key) const { return Find(key) ? 1 : 0; }
  int at(int key) const {
    const Entry* p = Find(key);
    if (p == nullptr) throw std::out_of_range("ValenceChanges::at");
    return p->second;
  }
  /// The value of key, inserted as 0 if absent (std::map::operator[]).
  int& operator[](int key) {
    Insert(key, 0);
    return const_cast<Entry*>(Find(key))->second;
  }
  /// The entry of key, or end() (std::map::find).
  const Entry* find(int key) const {
    const Entry* p = Find(key);
    return p ? p : end();
  }
  void erase(int key) {
    const size_t i = LowerBound(key);
    if (i == a_.size() || a_[i].first != key) return;
    a_.erase(a_.begin() + i, a_.begin() + i + 1);
  }
  void clear() { a_.clear(); }
  Entry* begin() { return a_.begin(); }
  Entry* end() { return a_.end(); }
  const Entry* begin() const { return a_.begin(); }
  const Entry* end() const { return a_.end(); }
  size_t size() const { return a_.size(); }
  bool empty() const { return a_.empty(); }
  std::map<int, int> ToMap() const {
    std::map<int, int> m;
    for (const Entry& e : a_) m.emplace_hint(m.end(), e.first, e.second);
    return m;
  }
  bool operator==(const ValenceChanges& o) const {
    if (size() != o.size()) return false;
    for (size_t i = 0; i < size(); ++i)
      if (a_[i] != o.a_[i]) return false;
    return true;
  }
  bool operator!=(const ValenceChanges& o) const { return !(*this == o); }

 private:
  void Assign(std::initializer_list<std::pair<int, int>> l) {
    a_.clear();
    for (auto& kv : l) Insert(kv.first, kv.second);
  }
  size_t LowerBound(int key) const {
    size_t i = 0;
    while (i < a_.size() && a_[i].first < key) ++i;
    return i;
  }
  const Entry* Find(int key) const {
    const size_t i = LowerBound(key);
    return i < a_.size() && a_[i].first == key ? a_.begin() + i : nullptr;
  }

  SmallVector<Entry, kInline> a_;
};

inline std::ostream& operator<<(std::ostream& o, const ValenceChanges::Entry& e) {
  return o << e.first << ":" << e.second;
}

}  // namespace irregular
}  // namespace vcg_ext
