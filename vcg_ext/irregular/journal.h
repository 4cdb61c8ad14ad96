// filter_irregular: an undo journal for local mesh edits ("all or nothing").
//
// Every primitive edit first saves the state of the face or vertex it touches; RollbackTo()
// restores saved states newest first and truncates elements added since the checkpoint, so a
// partly applied sequence of operations leaves the mesh exactly as it was, FF and VF adjacency
// included. Costs O(touched elements): nothing here walks the whole mesh.
//
// Elements are recorded by index, not pointer, because adding elements may reallocate the
// vertex and face vectors (vcg's Allocator then fixes the mesh's own pointers, not ours).
#pragma once

#include <cstddef>
#include <vector>

#include <vcg/complex/complex.h>

namespace vcg_ext {
namespace irregular {

template <class MeshType>
class EditJournal {
 public:
  typedef typename MeshType::FaceType FaceType;
  typedef typename MeshType::VertexType VertexType;
  typedef typename MeshType::CoordType CoordType;

  /// A point in the journal to roll back to.
  struct Checkpoint {
    size_t faceLog = 0, vertLog = 0, faces = 0, verts = 0;
    int fn = 0, vn = 0;
  };

  explicit EditJournal(MeshType& m) : m_(m) {}

  Checkpoint Mark() const {
    Checkpoint c;
    c.faceLog = faceLog_.size();
    c.vertLog = vertLog_.size();
    c.faces = m_.face.size();
    c.verts = m_.vert.size();
    c.fn = m_.fn;
    c.vn = m_.vn;
    return c;
  }

  /// Saves face f (vertex refs, FF, VF, flags, normal) before it is changed.
  void SaveFace(FaceType* f) {
    FaceRecord r;
    r.idx = Idx(f);
    for (int z = 0; z < 3; ++z) {
      r.v[z] = f->V(z) ? long(vcg::tri::Index(m_, f->V(z))) : -1;
      r.ff[z] = f->cFFp(z) ? long(vcg::tri::Index(m_, f->cFFp(z))) : -1;
      r.ffi[z] = f->cFFi(z);
      r.vf[z] = f->cVFp(z) ? long(vcg::tri::Index(m_, f->cVFp(z))) : -1;
      r.vfi[z] = f->cVFi(z);
    }
    r.flags = f->Flags();
    r.n = f->N();
    faceLog_.push_back(r);
  }

  /// Saves vertex v (position, VF, flags) before it is changed.
  void SaveVertex(VertexType* v) {
    VertexRecord r;
    r.idx = vcg::tri::Index(m_, v);
    r.p = v->P();
    r.vf = v->cVFp() ? long(vcg::tri::Index(m_, v->cVFp())) : -1;
    r.vfi = v->cVFi();
    r.flags = v->Flags();
    vertLog_.push_back(r);
  }

  /// Restores the mesh to checkpoint c and forgets everything logged after it.
  void RollbackTo(const Checkpoint& c) {
    for (size_t k = faceLog_.size(); k-- > c.faceLog;) Restore(faceLog_[k]);
    for (size_t k = vertLog_.size(); k-- > c.vertLog;) Restore(vertLog_[k]);
    faceLog_.resize(c.faceLog);
    vertLog_.resize(c.vertLog);
    // Truncating never reallocates, so every pointer into the kept part stays valid.
    if (m_.face.size() > c.faces) m_.face.resize(c.faces);
    if (m_.vert.size() > c.verts) m_.vert.resize(c.verts);
    m_.fn = c.fn;
    m_.vn = c.vn;
  }

  /// Forgets the log up to now (the edits become permanent for this journal).
  void Commit() {
    faceLog_.clear();
    vertLog_.clear();
  }

  size_t LoggedFaces() const { return faceLog_.size(); }
  size_t LoggedVertices() const { return vertLog_.size(); }

 private:
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
  std::vector<FaceRecord> faceLog_;
  std::vector<VertexRecord> vertLog_;
};

}  // namespace irregular
}  // namespace vcg_ext
