// filter_irregular: a vector that keeps its first N elements inside itself.
//
// Why: a vertex star (topology.h) is built for almost every question an edit asks, and most
// stars have 5-7 corners. With std::vector each star cost two heap allocations and two frees,
// about a tenth of Automatic Reduction's time; N = 12 holds every star of a valence up to 12
// without touching the heap, and a larger one spills to the heap transparently.
//
// Only what the stars need: trivially copyable T (pointers, small structs), contiguous storage
// (iterators are pointers), and the std::vector members used on stars.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <new>
#include <type_traits>

namespace vcg_ext {
namespace irregular {

template <class T, size_t N>
class SmallVector {
  static_assert(std::is_trivially_copyable<T>::value, "SmallVector holds trivially copyable elements only");
  static_assert(N > 0, "SmallVector needs inline room for at least one element");

 public:
  typedef T value_type;
  typedef T* iterator;
  typedef const T* const_iterator;

  // The inline room is raw bytes, not T[N]: a T with default member initializers (Corner's
  // null face) would otherwise be written N times for every star built, before any use.
  // data_ always points at the elements (the inline room or the heap), so an access is one
  // load, not a choice between the two.
  SmallVector() : data_(Inline()) {}
  SmallVector(const SmallVector& o) : data_(Inline()) { Assign(o.begin(), o.end()); }
  SmallVector(SmallVector&& o) noexcept : data_(Inline()) { Steal(o); }
  SmallVector& operator=(const SmallVector& o) {
    if (this != &o) {
      size_ = 0;
      Assign(o.begin(), o.end());
    }
    return *this;
  }
  SmallVector& operator=(SmallVector&& o) noexcept {
    if (this != &o) {
      Free();
      Steal(o);
    }
    return *this;
  }
  ~SmallVector() { Free(); }

  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }
  T& operator[](size_t i) { return data_[i]; }
  const T& operator[](size_t i) const { return data_[i]; }
  T& front() { return data_[0]; }
  const T& front() const { return data_[0]; }
  T& back() { return data_[size_ - 1]; }
  const T& back() const { return data_[size_ - 1]; }
  size_t capacity() const { return capacity_; }

  void reserve(size_t n) {
    if (n <= capacity_) return;
    T* p = static_cast<T*>(::operator new(n * sizeof(T)));
    if (size_) std::memcpy(static_cast<void*>(p), data_, size_ * sizeof(T));
    if (OnHeap()) ::operator delete(data_);
    data_ = p;
    capacity_ = n;
  }
  void push_back(const T& x) {
    if (size_ == capacity_) {
      const T copy = x;  // x may live in this vector
      reserve(2 * capacity_);
      data_[size_++] = copy;
      return;
    }
    data_[size_++] = x;
  }
  void clear() { size_ = 0; }
  void resize(size_t n, const T& x = T()) {
    reserve(n);
    for (size_t i = size_; i < n; ++i) data_[i] = x;
    size_ = n;
  }
  /// Removes [first, last), like std::vector::erase.
  T* erase(T* first, T* last) {
    std::copy(last, end(), first);
    size_ -= size_t(last - first);
    return first;
  }
  T* erase(T* pos) { return erase(pos, pos + 1); }

 private:
  T* Inline() { return reinterpret_cast<T*>(inline_); }
  bool OnHeap() const { return data_ != reinterpret_cast<const T*>(inline_); }
  void Assign(const T* b, const T* e) {
    reserve(size_t(e - b));
    if (e != b) std::memcpy(static_cast<void*>(data_), b, size_t(e - b) * sizeof(T));
    size_ = size_t(e - b);
  }
  /// Precondition: this holds no heap block (constructed, or just freed).
  void Steal(SmallVector& o) {
    if (o.OnHeap()) {
      data_ = o.data_, capacity_ = o.capacity_, size_ = o.size_;
      o.data_ = o.Inline(), o.capacity_ = N, o.size_ = 0;
    } else {
      Assign(o.begin(), o.end());
      o.size_ = 0;
    }
  }
  void Free() {
    if (OnHeap()) ::operator delete(data_);
    data_ = Inline();
    capacity_ = N;
    size_ = 0;
  }

  alignas(T) unsigned char inline_[N * sizeof(T)];
  T* data_;
  size_t size_ = 0, capacity_ = N;
};

}  // namespace irregular
}  // namespace vcg_ext
