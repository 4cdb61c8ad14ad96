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
#include <type_traits>

namespace vcg_ext {
namespace irregular {

template <class T, size_t N>
class SmallVector {
  static_assert(std::is_trivially_copyable<T>::value, "SmallVector holds trivially copyable elements only");

 public:
  typedef T value_type;
  typedef T* iterator;
  typedef const T* const_iterator;

  SmallVector() = default;
  SmallVector(const SmallVector& o) { Assign(o.begin(), o.end()); }
  SmallVector(SmallVector&& o) noexcept { Steal(o); }
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
  T* data() { return heap_ ? heap_ : inline_; }
  const T* data() const { return heap_ ? heap_ : inline_; }
  T* begin() { return data(); }
  T* end() { return data() + size_; }
  const T* begin() const { return data(); }
  const T* end() const { return data() + size_; }
  T& operator[](size_t i) { return data()[i]; }
  const T& operator[](size_t i) const { return data()[i]; }
  T& front() { return data()[0]; }
  const T& front() const { return data()[0]; }
  T& back() { return data()[size_ - 1]; }
  const T& back() const { return data()[size_ - 1]; }

  void reserve(size_t n) {
    if (n <= Capacity()) return;
    T* p = new T[n];
    if (size_) std::memcpy(static_cast<void*>(p), data(), size_ * sizeof(T));
    delete[] heap_;
    heap_ = p;
    capacity_ = n;
  }
  void push_back(const T& x) {
    if (size_ == Capacity()) {
      const T copy = x;  // x may live in this vector
      reserve(2 * Capacity());
      data()[size_++] = copy;
      return;
    }
    data()[size_++] = x;
  }
  void clear() { size_ = 0; }
  void resize(size_t n, const T& x = T()) {
    reserve(n);
    for (size_t i = size_; i < n; ++i) data()[i] = x;
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
  size_t Capacity() const { return heap_ ? capacity_ : N; }
  void Assign(const T* b, const T* e) {
    reserve(size_t(e - b));
    if (e != b) std::memcpy(static_cast<void*>(data()), b, size_t(e - b) * sizeof(T));
    size_ = size_t(e - b);
  }
  void Steal(SmallVector& o) {
    if (o.heap_) {
      heap_ = o.heap_, capacity_ = o.capacity_, size_ = o.size_;
      o.heap_ = nullptr, o.capacity_ = 0, o.size_ = 0;
    } else {
      heap_ = nullptr, capacity_ = 0;
      Assign(o.begin(), o.end());
      o.size_ = 0;
    }
  }
  void Free() {
    delete[] heap_;
    heap_ = nullptr;
    capacity_ = 0;
    size_ = 0;
  }

  T inline_[N];
  T* heap_ = nullptr;
  size_t size_ = 0, capacity_ = 0;
};

}  // namespace irregular
}  // namespace vcg_ext
