// filter_irregular: an append-only sequence of records in fixed-size chunks (the undo
// journal's logs, journal.h).
//
// Why not std::vector: a journal grows by one record at a time during an edit and is cut back
// or forgotten when the edit ends. A vector doubles, so at the moment it grows the old and the
// new block are both resident (1.5x-3x the records), and the freed blocks stay in glibc's heap:
// once one large block has been freed, glibc raises its mmap threshold and serves the next large
// blocks from the heap, whose freed middle is never given back. On a reduction of bunny00
// subdivided once (300K faces) the heap then held 28 MB freed after two sweeps (issue 14's memory
// target). Here records never move once written, growing costs one chunk, and chunks are mapped
// from the system directly (POSIX mmap; elsewhere operator new) and unmapped when released, so
// what an edit's journal held goes back to the system when the edit ends.
//
// Preconditions: T is copy constructible. Costs: PushBack O(1) (a chunk every kChunkBytes),
// operator[] O(1), TruncateTo O(records dropped), ReleaseBeyond O(chunks).
#pragma once

#include <cassert>
#include <cstddef>
#include <new>
#include <utility>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/mman.h>
#define FI_CHUNKED_LOG_MMAP 1
#endif

namespace vcg_ext {
namespace irregular {

template <class T>
class ChunkedLog {
 public:
  /// Bytes a chunk spans: a few thousand records (a face record is about 100 bytes).
  static constexpr size_t kChunkBytes = size_t(1) << 20;
  static constexpr size_t kPerChunk = kChunkBytes / sizeof(T) > 0 ? kChunkBytes / sizeof(T) : 1;

  ChunkedLog() = default;
  ChunkedLog(const ChunkedLog&) = delete;
  ChunkedLog& operator=(const ChunkedLog&) = delete;
  ~ChunkedLog() {
    TruncateTo(0);
    ReleaseBeyond(0);
  }

  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

  void push_back(const T& x) {
    const size_t c = size_ / kPerChunk;
    if (c == chunks_.size()) chunks_.push_back(Allocate());
    new (chunks_[c] + size_ % kPerChunk) T(x);
    ++size_;
  }
  T& back() {
    assert(size_ > 0);
    return (*this)[size_ - 1];
  }
  const T& back() const {
    assert(size_ > 0);
    return (*this)[size_ - 1];
  }
  T& operator[](size_t i) { return chunks_[i / kPerChunk][i % kPerChunk]; }
  const T& operator[](size_t i) const { return chunks_[i / kPerChunk][i % kPerChunk]; }

  /// Drops the records from n on (n <= size()); the chunks stay for the next records.
  void TruncateTo(size_t n) {
    assert(n <= size_);
    for (size_t i = n; i < size_; ++i) (*this)[i].~T();
    size_ = n;
  }
  void clear() { TruncateTo(0); }

  /// Gives back every chunk that records beyond the first max(size(), keep) do not need.
  void ReleaseBeyond(size_t keep) {
    const size_t need = ChunksFor(keep > size_ ? keep : size_);
    if (chunks_.size() <= need) return;
    while (chunks_.size() > need) {
      Free(chunks_.back());
      chunks_.pop_back();
    }
    std::vector<T*>(chunks_).swap(chunks_);  // the pointers' room too
  }

  /// Bytes held (chunks allocated), for memory accounting.
  size_t Bytes() const { return chunks_.size() * kChunkBytes + chunks_.capacity() * sizeof(T*); }

 private:
  static size_t ChunksFor(size_t n) { return (n + kPerChunk - 1) / kPerChunk; }

  static T* Allocate() {
#ifdef FI_CHUNKED_LOG_MMAP
    void* p = mmap(nullptr, kChunkBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    return static_cast<T*>(p);
#else
    return static_cast<T*>(::operator new(kChunkBytes));
#endif
  }
  static void Free(T* p) {
#ifdef FI_CHUNKED_LOG_MMAP
    munmap(static_cast<void*>(p), kChunkBytes);
#else
    ::operator delete(static_cast<void*>(p));
#endif
  }

  std::vector<T*> chunks_;
  size_t size_ = 0;
};

}  // namespace irregular
}  // namespace vcg_ext
