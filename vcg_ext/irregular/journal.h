// filter_irregular: an undo journal for local mesh edits ("all or nothing").
//
// Every primitive edit first saves the state of the face or vertex it touches; RollbackTo()
// restores saved states newest first and truncates elements added since the checkpoint, so a
// partly applied sequence of operations leaves the mesh exactly as it was, FF and VF adjacency
// included. Costs O(touched elements): nothing here walks the whole mesh.
//
// An edit may also move elements into the holes of deleted ones and truncate the vectors
// (the edit session's compaction): SaveWholeFace / SaveWholeVertex keep a copy of the whole
// element as well, restored in its chronological place, and RollbackTo grows the vectors back
// (within their capacity) before restoring, so the vectors end exactly as at the checkpoint.
//
// Elements are recorded by index, not pointer, because adding elements may reallocate the
// vertex and face vectors (vcg's Allocator then fixes the mesh's own pointers, not ours).
//
// The logs are chunked (chunked_log.h): a long edit's records never move as the log grows, and
// the memory they held goes back to the system at the commit (issue 14's memory target).
//
// Attributes (attribute_transfer.h): when the mesh has them, a saved face also keeps its wedge
// texture coordinates, colour and quality, and a saved vertex its colour, quality and texture
// coordinate, in separate logs, so a mesh without them pays nothing (vcglib's HasPer...
// checks: compile-time for static components, run-time for optional ones).
#pragma once

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <cstring>
#include <vector>

#include <vcg/complex/complex.h>

#include "chunked_log.h"

namespace vcg_ext {
namespace irregular {

template <class MeshType>
class EditJournal {
 public:
  typedef typename MeshType::FaceType FaceType;
  typedef typename MeshType::VertexType VertexType;
  typedef typename MeshType::CoordType CoordType;

 private:
  // The records (declared first: Replay holds them).
  struct FaceRecord {
    size_t idx;
    long v[3], ff[3], vf[3];
    char ffi[3], vfi[3];
    int flags;
    CoordType n;
  };
  struct VertexRecord {
    size_t idx;
    CoordType p;
    long vf;
    int vfi;
    int flags;
  };

  struct FaceAttrRecord {
    size_t idx;
    typename FaceType::TexCoordType wt[3];
    typename FaceType::ColorType c;
    typename FaceType::QualityType q;
  };
  struct VertexAttrRecord {
    size_t idx;
    typename VertexType::ColorType c;
    typename VertexType::QualityType q;
    typename VertexType::TexCoordType t;
  };
  /// A whole element, saved when the regular log held `stamp` records (it is newer than
  /// those and older than the following ones).
  struct WholeFace {
    size_t stamp, idx;
    FaceType f;
  };
  struct WholeVertex {
    size_t stamp, idx;
    VertexType v;
  };
  template <class T>
  using Vector = std::vector<T>;
  /// The six logs of records: what the journal keeps since its last commit (Seq = ChunkedLog),
  /// and what a Replay carries (Seq = std::vector).
  template <template <class> class Seq>
  struct LogsOf {
    Seq<FaceRecord> face;
    Seq<VertexRecord> vert;
    Seq<FaceAttrRecord> faceAttr;
    Seq<VertexAttrRecord> vertAttr;
    Seq<WholeFace> faceWhole;
    Seq<WholeVertex> vertWhole;
    /// Calls fn on each of the six vectors.
    template <class Fn>
    void ForEach(Fn fn) {
      fn(face), fn(vert), fn(faceAttr), fn(vertAttr), fn(faceWhole), fn(vertWhole);
    }
    template <class Fn>
    void ForEach(Fn fn) const {
      fn(face), fn(vert), fn(faceAttr), fn(vertAttr), fn(faceWhole), fn(vertWhole);
    }
  };

 public:

  /// A point in the journal to roll back to.
  struct Checkpoint {
    size_t faceLog = 0, vertLog = 0, faces = 0, verts = 0;
    size_t faceAttrLog = 0, vertAttrLog = 0;
    size_t faceWhole = 0, vertWhole = 0;
    int fn = 0, vn = 0;
  };

  explicit EditJournal(MeshType& m) : m_(m) {}

  Checkpoint Mark() const {
    Checkpoint c;
    c.faceLog = log_.face.size();
    c.vertLog = log_.vert.size();
    c.faceAttrLog = log_.faceAttr.size();
    c.vertAttrLog = log_.vertAttr.size();
    c.faceWhole = log_.faceWhole.size();
    c.vertWhole = log_.vertWhole.size();
    c.faces = m_.face.size();
    c.verts = m_.vert.size();
    c.fn = m_.fn;
    c.vn = m_.vn;
    return c;
  }

  /// Saves face f (vertex refs, FF, VF, flags, normal; wedge texture coordinates, colour and
  /// quality if the mesh has them) before it is changed.
  void SaveFace(FaceType* f) {
    log_.face.push_back(RecordOf(f));
    SaveFaceAttributes(log_.face.back().idx, *f);
  }

  /// Saves vertex v (position, VF, flags; colour, quality and texture coordinate if the mesh
  /// has them) before it is changed.
  void SaveVertex(VertexType* v) {
    log_.vert.push_back(RecordOf(v));
    SaveVertexAttributes(log_.vert.back().idx, *v);
  }

  /// Saves face f like SaveFace, plus a copy of the whole element (every static component,
  /// whatever the journal knows of), for an edit that overwrites or truncates the slot
  /// (compaction, edit_session.h). Rollback restores the copy in its chronological place.
  void SaveWholeFace(FaceType* f) {
    SaveFace(f);
    log_.faceWhole.push_back(WholeFace{log_.face.size(), log_.face.back().idx, *f});
  }
  /// The same for vertex v.
  void SaveWholeVertex(VertexType* v) {
    SaveVertex(v);
    log_.vertWhole.push_back(WholeVertex{log_.vert.size(), log_.vert.back().idx, *v});
  }

  /// The indices of the faces / vertices saved since checkpoint c (with repetitions), e.g. to
  /// find the elements an edit deleted without a pass over the mesh. O(logged).
  std::vector<size_t> FacesSavedSince(const Checkpoint& c) const {
    std::vector<size_t> out;
    for (size_t k = c.faceLog; k < log_.face.size(); ++k) out.push_back(log_.face[k].idx);
    return out;
  }
  std::vector<size_t> VerticesSavedSince(const Checkpoint& c) const {
    std::vector<size_t> out;
    for (size_t k = c.vertLog; k < log_.vert.size(); ++k) out.push_back(log_.vert[k].idx);
    return out;
  }

  /// What an edit made of the mesh since a checkpoint: the final state of every element it
  /// saved or created, and the final sizes. Captured after a trial (edit_session.h: the dry run
  /// of an arrow) and applied later to the same state, it does that edit again without
  /// recomputing it. Only valid on a mesh bit-identical to the one at the checkpoint.
  struct Replay {
    size_t faces0 = 0, verts0 = 0;  ///< the vectors' sizes at the checkpoint (checked by Apply)
    size_t faces = 0, verts = 0;    ///< and after the edit
    int fn = 0, vn = 0;
    LogsOf<Vector> logs;  ///< the final state of each element (regular and whole records; stamps unused)
    bool Empty() const { return logs.face.empty() && logs.vert.empty() && faces == faces0 && verts == verts0; }
  };

  /// The state now of every element saved since c or created since c (those still inside the
  /// vectors), and the sizes. O(logged).
  Replay CaptureSince(const Checkpoint& c) const {
    Replay r;
    r.faces0 = c.faces, r.verts0 = c.verts;
    r.faces = m_.face.size(), r.verts = m_.vert.size();
    r.fn = m_.fn, r.vn = m_.vn;
    for (size_t i : Changed(FacesSavedSince(c), c.faces, m_.face.size())) {
      const FaceType* f = &m_.face[i];
      r.logs.face.push_back(RecordOf(f));
      r.logs.faceWhole.push_back(WholeFace{0, i, *f});
      if (HasFaceAttributes()) r.logs.faceAttr.push_back(AttributesOf(i, *f));
    }
    for (size_t i : Changed(VerticesSavedSince(c), c.verts, m_.vert.size())) {
      const VertexType* v = &m_.vert[i];
      r.logs.vert.push_back(RecordOf(v));
      r.logs.vertWhole.push_back(WholeVertex{0, i, *v});
      if (HasVertexAttributes()) r.logs.vertAttr.push_back(AttributesOf(i, *v));
    }
    return r;
  }

  /// Does the captured edit again, journaled like any edit (RollbackTo a mark taken before
  /// undoes it). Precondition: the mesh is bit-identical to the one the capture started from
  /// (sizes checked: false, and nothing done, when they differ), and the vectors' capacity
  /// holds the final sizes (growing never reallocates). O(captured).
  bool Apply(const Replay& r) {
    if (m_.face.size() != r.faces0 || m_.vert.size() != r.verts0) return false;
    assert(r.faces <= m_.face.capacity() && r.verts <= m_.vert.capacity());
    // save what is overwritten and what is truncated, for the rollback
    for (const auto& w : r.logs.faceWhole)
      if (w.idx < m_.face.size()) SaveWholeFace(&m_.face[w.idx]);
    for (size_t i = r.faces; i < m_.face.size(); ++i) SaveWholeFace(&m_.face[i]);
    for (const auto& w : r.logs.vertWhole)
      if (w.idx < m_.vert.size()) SaveWholeVertex(&m_.vert[w.idx]);
    for (size_t i = r.verts; i < m_.vert.size(); ++i) SaveWholeVertex(&m_.vert[i]);
    m_.face.resize(r.faces);
    m_.vert.resize(r.verts);
    // whole copies first, then the records (the adjacency, which may be optional components
    // outside the element's bytes), then the attributes: the order of RollbackTo
    for (const auto& w : r.logs.faceWhole) RestoreWhole(w);
    for (const auto& w : r.logs.vertWhole) RestoreWhole(w);
    for (const auto& x : r.logs.face) Restore(x);
    for (const auto& x : r.logs.vert) Restore(x);
    for (const auto& x : r.logs.faceAttr) Restore(x);
    for (const auto& x : r.logs.vertAttr) Restore(x);
    m_.fn = r.fn;
    m_.vn = r.vn;
    return true;
  }

  /// Restores the mesh to checkpoint c and forgets everything logged after it.
  /// The vectors may be shorter than at c (an edit truncated them after moving elements into
  /// holes): they grow back first, within their capacity (asserted: growing never reallocates,
  /// so every pointer stays valid), then the records are restored newest first.
  void RollbackTo(const Checkpoint& c) {
    GrowBack(m_.face, c.faces, c.faceLog, log_.face);
    GrowBack(m_.vert, c.verts, c.vertLog, log_.vert);
    RestoreInterleaved(log_.face, c.faceLog, log_.faceWhole, c.faceWhole);
    RestoreInterleaved(log_.vert, c.vertLog, log_.vertWhole, c.vertWhole);
    for (size_t k = log_.faceAttr.size(); k-- > c.faceAttrLog;) Restore(log_.faceAttr[k]);
    for (size_t k = log_.vertAttr.size(); k-- > c.vertAttrLog;) Restore(log_.vertAttr[k]);
    log_.face.TruncateTo(c.faceLog);
    log_.vert.TruncateTo(c.vertLog);
    log_.faceAttr.TruncateTo(c.faceAttrLog);
    log_.vertAttr.TruncateTo(c.vertAttrLog);
    log_.faceWhole.TruncateTo(c.faceWhole);
    log_.vertWhole.TruncateTo(c.vertWhole);
    // Truncating never reallocates, so every pointer into the kept part stays valid.
    if (m_.face.size() > c.faces) m_.face.resize(c.faces);
    if (m_.vert.size() > c.verts) m_.vert.resize(c.verts);
    m_.fn = c.fn;
    m_.vn = c.vn;
  }

  /// Forgets the log up to now (the edits become permanent for this journal). A log that held
  /// more than kRetainedRecords (one long edit) gives all its chunks back to the system, so
  /// what a journal holds between edits is bounded (RetainedBytesLimit), not by the longest
  /// edit so far; a shorter one keeps its chunk for the next edit (no allocation per edit).
  void Commit() {
    log_.ForEach([](auto& log) { Forget(log); });
  }

  size_t LoggedFaces() const { return log_.face.size(); }
  size_t LoggedVertices() const { return log_.vert.size(); }
  /// Bytes the logs hold (their chunks, mapped address space: only the pages written are
  /// resident), for memory accounting.
  size_t Bytes() const {
    size_t bytes = 0;
    log_.ForEach([&](const auto& log) { bytes += log.Bytes(); });
    return bytes;
  }
  /// Records a log may have held for its chunk to be kept after a Commit (a few edits' worth).
  static constexpr size_t kRetainedRecords = 4096;
  /// The most Bytes() can be right after a Commit: a chunk per log, and its pointer.
  static constexpr size_t RetainedBytesLimit() { return 6 * (ChunkedLog<FaceRecord>::kChunkBytes + sizeof(void*)); }

 private:
  template <class Log>
  static void Forget(Log& log) {
    const bool longEdit = log.size() > kRetainedRecords;
    log.clear();
    log.ReleaseBeyond(longEdit ? 0 : std::min(kRetainedRecords, log.kPerChunk));  // at most one chunk
  }

  /// Grows `vec` back to the size the records since `from` and the checkpoint size `size` need
  /// (never beyond its capacity: no reallocation, pointers stay valid).
  template <class Vec, class Log>
  static void GrowBack(Vec& vec, size_t size, size_t from, const Log& log) {
    size_t need = size;
    for (size_t k = from; k < log.size(); ++k) need = std::max(need, log[k].idx + 1);
    if (need <= vec.size()) return;
    assert(need <= vec.capacity());
    vec.resize(need);
  }
  /// Restores `log` from its end down to `from`, and the whole copies since `wholeFrom` each
  /// in its chronological place, newest first, so every element ends as it was at the
  /// checkpoint.
  template <class Log, class Whole>
  void RestoreInterleaved(const Log& log, size_t from, const Whole& whole, size_t wholeFrom) {
    size_t w = whole.size();
    for (size_t k = log.size(); k-- > from;) {
      for (; w > wholeFrom && whole[w - 1].stamp > k; --w) RestoreWhole(whole[w - 1]);
      Restore(log[k]);
    }
    for (; w > wholeFrom; --w) RestoreWhole(whole[w - 1]);
  }
  // Byte copies, not operator=: vcg's elements with optional components (CMeshO's) assert in
  // operator= ("never copy an element that has OCF stuff"; a Debug build aborts). The bytes
  // are what the copy holds; the optional data lives in the vector_ocf and comes back through
  // the attribute and adjacency records restored next to it.
  void RestoreWhole(const WholeFace& r) { CopyBytes(m_.face[r.idx], r.f); }
  void RestoreWhole(const WholeVertex& r) { CopyBytes(m_.vert[r.idx], r.v); }
  template <class T>
  static void CopyBytes(T& to, const T& from) {
    std::memcpy(static_cast<void*>(&to), static_cast<const void*>(&from), sizeof(T));
  }

  /// The indices in `saved` (with repetitions) and in [from, size), below `size`, sorted.
  static std::vector<size_t> Changed(std::vector<size_t> saved, size_t from, size_t size) {
    for (size_t i = from; i < size; ++i) saved.push_back(i);
    saved.erase(std::remove_if(saved.begin(), saved.end(), [size](size_t i) { return i >= size; }), saved.end());
    std::sort(saved.begin(), saved.end());
    saved.erase(std::unique(saved.begin(), saved.end()), saved.end());
    return saved;
  }

  FaceRecord RecordOf(const FaceType* f) const {
    FaceRecord r;
    r.idx = Idx(f);
    for (int z = 0; z < 3; ++z) {
      r.v[z] = f->cV(z) ? long(vcg::tri::Index(m_, f->cV(z))) : -1;
      r.ff[z] = f->cFFp(z) ? long(vcg::tri::Index(m_, f->cFFp(z))) : -1;
      r.ffi[z] = f->cFFi(z);
      r.vf[z] = f->cVFp(z) ? long(vcg::tri::Index(m_, f->cVFp(z))) : -1;
      r.vfi[z] = f->cVFi(z);
    }
    r.flags = f->cFlags();
    r.n = f->cN();
    return r;
  }
  VertexRecord RecordOf(const VertexType* v) const {
    VertexRecord r;
    r.idx = vcg::tri::Index(m_, v);
    r.p = v->cP();
    r.vf = v->cVFp() ? long(vcg::tri::Index(m_, v->cVFp())) : -1;
    r.vfi = v->cVFi();
    r.flags = v->cFlags();
    return r;
  }

  bool WedgeTex() const { return vcg::tri::HasPerWedgeTexCoord(m_); }
  bool FaceColor() const { return vcg::tri::HasPerFaceColor(m_); }
  bool FaceQuality() const { return vcg::tri::HasPerFaceQuality(m_); }
  bool VertColor() const { return vcg::tri::HasPerVertexColor(m_); }
  bool VertQuality() const { return vcg::tri::HasPerVertexQuality(m_); }
  bool VertTex() const { return vcg::tri::HasPerVertexTexCoord(m_); }

  bool HasFaceAttributes() const { return WedgeTex() || FaceColor() || FaceQuality(); }
  bool HasVertexAttributes() const { return VertColor() || VertQuality() || VertTex(); }
  FaceAttrRecord AttributesOf(size_t idx, const FaceType& f) const {
    FaceAttrRecord r{};
    r.idx = idx;
    if (WedgeTex())
      for (int z = 0; z < 3; ++z) r.wt[z] = f.cWT(z);
    if (FaceColor()) r.c = f.cC();
    if (FaceQuality()) r.q = f.cQ();
    return r;
  }
  VertexAttrRecord AttributesOf(size_t idx, const VertexType& v) const {
    VertexAttrRecord r{};
    r.idx = idx;
    if (VertColor()) r.c = v.cC();
    if (VertQuality()) r.q = v.cQ();
    if (VertTex()) r.t = v.cT();
    return r;
  }
  void SaveFaceAttributes(size_t idx, FaceType& f) {
    if (HasFaceAttributes()) log_.faceAttr.push_back(AttributesOf(idx, f));
  }
  void SaveVertexAttributes(size_t idx, VertexType& v) {
    if (HasVertexAttributes()) log_.vertAttr.push_back(AttributesOf(idx, v));
  }
  void Restore(const FaceAttrRecord& r) {
    FaceType& f = m_.face[r.idx];
    if (WedgeTex())
      for (int z = 0; z < 3; ++z) f.WT(z) = r.wt[z];
    if (FaceColor()) f.C() = r.c;
    if (FaceQuality()) f.Q() = r.q;
  }
  void Restore(const VertexAttrRecord& r) {
    VertexType& v = m_.vert[r.idx];
    if (VertColor()) v.C() = r.c;
    if (VertQuality()) v.Q() = r.q;
    if (VertTex()) v.T() = r.t;
  }

  size_t Idx(const FaceType* f) const { return vcg::tri::Index(m_, f); }
  FaceType* F(long i) { return i < 0 ? nullptr : &m_.face[size_t(i)]; }
  VertexType* V(long i) { return i < 0 ? nullptr : &m_.vert[size_t(i)]; }

  void Restore(const FaceRecord& r) {
    FaceType& f = m_.face[r.idx];
    for (int z = 0; z < 3; ++z) {
      f.V(z) = V(r.v[z]);
      f.FFp(z) = F(r.ff[z]);
      f.FFi(z) = r.ffi[z];
      f.VFp(z) = F(r.vf[z]);
      f.VFi(z) = r.vfi[z];
    }
    f.Flags() = r.flags;
    f.N() = r.n;
  }
  void Restore(const VertexRecord& r) {
    VertexType& v = m_.vert[r.idx];
    v.P() = r.p;
    v.VFp() = F(r.vf);
    v.VFi() = r.vfi;
    v.Flags() = r.flags;
  }

  MeshType& m_;
  LogsOf<ChunkedLog> log_;
};

}  // namespace irregular
}  // namespace vcg_ext
