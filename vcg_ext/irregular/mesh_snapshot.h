// filter_irregular: a compact copy of a whole mesh's state, to give the mesh back bit for bit
// after a run of many edits (the automatic reduction's whole-run undo, reduction_state.h).
//
// It saves what EditJournal (journal.h) saves of an element, and restores it the same way:
// per vertex its position, VF adjacency and flags (colour, quality and texture coordinate if
// the mesh has them); per face its vertices, FF and VF adjacency, flags and normal (wedge
// texture coordinates, colour and quality if the mesh has them); and the vector sizes and the
// vn / fn counts. The journal, built for a few hundred records per edit, spends 104 bytes per
// face record (indices as size_t / long, growth by doubling): as an undo point for a
// million-face input it held ~300 MB. Here indices are 32-bit, the arrays are sized exactly
// once, attributes the mesh lacks cost nothing, and what the saved faces give back is not
// stored: per face 16 bytes (its vertices and flags), per vertex its position and flags.
// - FF: the face across an edge is the one in the VF list of the edge's end that runs the
//   edge the other way (on a consistently oriented manifold, every edge; a border edge points
//   to its own face).
// - VF: the lists vcg's rebuild (UpdateTopology::VertexFace) makes from the saved faces, which
//   is what a run starts from (the filters build VF so, and the edits are undone before a
//   second snapshot).
// - Face normals: the saved vertices' triangle normal, normalized or not (the rule that gives
//   back more of the mesh's faces; MeshLab's loaders and vcg's PerFaceNormalized normalize,
//   PerVertexNormalizedPerFace does not).
// Elements where these do not give the saved value (deleted faces, non-manifold or
// inconsistently oriented edges, VF lists edited since the rebuild, normals of another rule)
// keep theirs in lists of exceptions. At 1.2M faces of MeshLab's CMeshO (double coordinates
// and normals) this is 19 MB of faces instead of 67 (0.9.31 stored VF and the normal per face).
//
// Preconditions: the mesh has FF and VF adjacency (as every edit of the project needs), its
// live faces have their three vertices, fewer than 2^31 elements. Restore() then leaves every
// saved field as Take() saw it, the vectors at their sizes then, and nothing else changed
// (elements added since are truncated).
// Costs: O(V + F) memory, O(V + F * valence) time per Take / Restore, nothing per edit.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/topology.h>

namespace vcg_ext {
namespace irregular {

template <class MeshType>
class CompactSnapshot {
 public:
  typedef typename MeshType::FaceType FaceType;
  typedef typename MeshType::VertexType VertexType;
  typedef typename MeshType::CoordType CoordType;

  bool Empty() const { return !taken_; }

  /// Saves the whole mesh (replacing any earlier snapshot).
  void Take(const MeshType& m) {
    Clear();
    taken_ = true;
    nv_ = m.vert.size();
    nf_ = m.face.size();
    vn_ = m.vn;
    fn_ = m.fn;
    pos_.reserve(nv_);
    vertFlags_.reserve(nv_);
    for (const VertexType& v : m.vert) {
      pos_.push_back(v.cP());
      vertFlags_.push_back(v.cFlags());
    }
    face_.reserve(nf_);
    for (const FaceType& f : m.face) {
      FaceState s;
      for (int z = 0; z < 3; ++z) s.v[z] = f.cV(z) ? int32_t(vcg::tri::Index(m, f.cV(z))) : -1;
      s.flags = f.cFlags();
      face_.push_back(s);
    }
    TakeVF(m);
    TakeNormals(m);
    // FF where the VF lists do not give it back
    for (size_t i = 0; i < nf_; ++i) {
      FaceType* f = const_cast<FaceType*>(&m.face[i]);
      bool same = !f->IsD();
      for (int z = 0; z < 3 && same; ++z) {
        const Across a = AcrossEdge(f, z);
        same = a.f == f->cFFp(z) && a.z == f->cFFi(z);
      }
      if (same) continue;
      FFException e;
      e.face = int32_t(i);
      for (int z = 0; z < 3; ++z) e.ff[z] = FaceIndex(m, f->cFFp(z)), e.ffi[z] = char(f->cFFi(z));
      ffExceptions_.push_back(e);
    }
    ffExceptions_.shrink_to_fit();
    TakeAttributes(m);
  }

  /// Faces whose FF is stored (see the header): 0 for a consistently oriented manifold mesh
  /// without deleted faces.
  size_t StoredFF() const { return ffExceptions_.size(); }

  /// Stored exceptions (see the header): 0 of each for a compacted, consistently oriented
  /// manifold mesh whose VF lists are vcg's rebuild and whose normals follow one rule.
  size_t StoredVF() const { return vertVF_.size() + faceVF_.size(); }
  size_t StoredNormals() const { return normals_.size(); }

  /// Gives the mesh back as Take() saw it (see the header); the snapshot stays.
  void Restore(MeshType& m) const {
    if (!taken_) return;
    // Elements added since are cut off (truncating never reallocates); a vector that became
    // shorter (a compaction) grows back first.
    if (m.vert.size() != nv_) m.vert.resize(nv_);
    if (m.face.size() != nf_) m.face.resize(nf_);
    for (size_t i = 0; i < nv_; ++i) {
      m.vert[i].P() = pos_[i];
      m.vert[i].Flags() = vertFlags_[i];
    }
    for (size_t i = 0; i < nf_; ++i) {
      FaceType& f = m.face[i];
      const FaceState& s = face_[i];
      for (int z = 0; z < 3; ++z) f.V(z) = s.v[z] < 0 ? nullptr : &m.vert[size_t(s.v[z])];
      f.Flags() = s.flags;
    }
    // VF by vcg's rebuild (TakeVF predicted it), then the exceptions
    vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
    for (const VertexVF& e : vertVF_) {
      m.vert[size_t(e.vertex)].VFp() = Face(m, e.vf);
      m.vert[size_t(e.vertex)].VFi() = e.vfi;
    }
    for (const FaceVF& e : faceVF_)
      for (int z = 0; z < 3; ++z) {
        m.face[size_t(e.face)].VFp(z) = Face(m, e.vf[z]);
        m.face[size_t(e.face)].VFi(z) = e.vfi[z];
      }
    // normals by the snapshot's rule, then the exceptions
    for (size_t i = 0; i < nf_; ++i)
      if (!m.face[i].IsD()) m.face[i].N() = RuleNormal(m.face[i], normalizedRule_);
    for (const NormalException& e : normals_) m.face[size_t(e.face)].N() = e.n;
    // FF from the restored faces and VF lists, as Take() found it there; then the exceptions
    for (size_t i = 0; i < nf_; ++i) {
      FaceType* f = &m.face[i];
      if (f->IsD()) continue;
      for (int z = 0; z < 3; ++z) {
        const Across a = AcrossEdge(f, z);
        f->FFp(z) = a.f;
        f->FFi(z) = a.z;
      }
    }
    for (const FFException& e : ffExceptions_)
      for (int z = 0; z < 3; ++z) {
        m.face[size_t(e.face)].FFp(z) = Face(m, e.ff[z]);
        m.face[size_t(e.face)].FFi(z) = e.ffi[z];
      }
    RestoreAttributes(m);
    m.vn = vn_;
    m.fn = fn_;
  }

  /// Forgets the snapshot and gives its memory back.
  void Clear() {
    taken_ = false;
    std::vector<CoordType>().swap(pos_);
    std::vector<int>().swap(vertFlags_);
    std::vector<FaceState>().swap(face_);
    std::vector<FFException>().swap(ffExceptions_);
    std::vector<VertexVF>().swap(vertVF_);
    std::vector<FaceVF>().swap(faceVF_);
    std::vector<NormalException>().swap(normals_);
    std::vector<typename VertexType::ColorType>().swap(vertColor_);
    std::vector<typename VertexType::QualityType>().swap(vertQuality_);
    std::vector<typename VertexType::TexCoordType>().swap(vertTex_);
    std::vector<WedgeTex>().swap(wedgeTex_);
    std::vector<typename FaceType::ColorType>().swap(faceColor_);
    std::vector<typename FaceType::QualityType>().swap(faceQuality_);
  }

  /// Bytes held (capacities), for the memory accounting of tests and benchmarks.
  size_t Bytes() const {
    return pos_.capacity() * sizeof(CoordType) + vertFlags_.capacity() * sizeof(int) +
           face_.capacity() * sizeof(FaceState) + ffExceptions_.capacity() * sizeof(FFException) +
           vertVF_.capacity() * sizeof(VertexVF) + faceVF_.capacity() * sizeof(FaceVF) +
           normals_.capacity() * sizeof(NormalException) +
           vertColor_.capacity() * sizeof(vertColor_[0]) + vertQuality_.capacity() * sizeof(vertQuality_[0]) +
           vertTex_.capacity() * sizeof(vertTex_[0]) + wedgeTex_.capacity() * sizeof(WedgeTex) +
           faceColor_.capacity() * sizeof(faceColor_[0]) + faceQuality_.capacity() * sizeof(faceQuality_[0]);
  }

 private:
  typedef typename FaceType::NormalType NormalType;
  struct FaceState {
    int32_t v[3];
    int flags;
  };
  struct VertexVF {
    int32_t vertex, vf;
    char vfi;
  };
  struct FaceVF {
    int32_t face, vf[3];
    char vfi[3];
  };
  struct NormalException {
    int32_t face;
    NormalType n;
  };
  struct FFException {
    int32_t face;
    int32_t ff[3];
    char ffi[3];
  };
  struct Across {
    FaceType* f;
    int z;
  };

  /// The face across edge z of f (from V(z) to V(z+1)) by the VF list of V(z+1): the other
  /// face g whose corner j there is followed by V(z), i.e. whose edge j runs the edge the other
  /// way (g, j); none: (f, z), a border edge. O(valence).
  static Across AcrossEdge(FaceType* f, int z) {
    VertexType* a = f->V(z);
    VertexType* b = f->V((z + 1) % 3);
    if (a == nullptr || b == nullptr) return Across{f, z};
    for (vcg::face::VFIterator<FaceType> it(b); !it.End(); ++it)
      if (it.F() != f && it.F()->V((it.I() + 1) % 3) == a) return Across{it.F(), it.I()};
    return Across{f, z};
  }
  struct WedgeTex {
    typename FaceType::TexCoordType t[3];
  };

  /// VF where vcg's rebuild (UpdateTopology::VertexFace: every vertex's list emptied, then
  /// each live face, in order, put at the head of its corners' lists) does not give it back:
  /// every deleted face (the rebuild skips them), and whatever the edits of an earlier run left
  /// in another order. The rebuild is simulated on indices: per vertex the head of its list.
  void TakeVF(const MeshType& m) {
    std::vector<int32_t> head(nv_, -1);
    std::vector<char> headZ(nv_, 0);
    for (size_t i = 0; i < nf_; ++i) {
      const FaceType& f = m.face[i];
      bool same = !f.IsD();
      if (same)
        for (int z = 0; z < 3; ++z) {
          const size_t v = size_t(face_[i].v[z]);
          same = same && FaceIndex(m, f.cVFp(z)) == head[v] && f.cVFi(z) == headZ[v];
          head[v] = int32_t(i);
          headZ[v] = char(z);
        }
      if (same) continue;
      FaceVF e;
      e.face = int32_t(i);
      for (int z = 0; z < 3; ++z) e.vf[z] = FaceIndex(m, f.cVFp(z)), e.vfi[z] = char(f.cVFi(z));
      faceVF_.push_back(e);
    }
    for (size_t i = 0; i < nv_; ++i) {
      const VertexType& v = m.vert[i];
      if (FaceIndex(m, v.cVFp()) == head[i] && v.cVFi() == headZ[i]) continue;
      vertVF_.push_back(VertexVF{int32_t(i), FaceIndex(m, v.cVFp()), char(v.cVFi())});
    }
    vertVF_.shrink_to_fit();
    faceVF_.shrink_to_fit();
  }

  /// The normal a rule gives face f from its vertices: vcg's TriangleNormal, normalized as
  /// vcg's PerFaceNormalized does (normalized) or not.
  static NormalType RuleNormal(const FaceType& f, bool normalized) {
    NormalType n = NormalType::Construct(vcg::TriangleNormal(f));
    if (normalized) n.Normalize();
    return n;
  }
  static bool SameBits(const NormalType& a, const NormalType& b) {
    return std::memcmp(&a, &b, sizeof(NormalType)) == 0;
  }

  /// The rule that gives back more live faces' normals, and the faces it does not give back
  /// (every deleted face: Restore computes none for them).
  void TakeNormals(const MeshType& m) {
    size_t plain = 0, unit = 0;
    for (const FaceType& f : m.face) {
      if (f.IsD()) continue;
      NormalType n = RuleNormal(f, false);
      plain += SameBits(f.cN(), n);
      unit += SameBits(f.cN(), n.Normalize());
    }
    normalizedRule_ = unit >= plain;
    for (size_t i = 0; i < nf_; ++i) {
      const FaceType& f = m.face[i];
      if (!f.IsD() && SameBits(f.cN(), RuleNormal(f, normalizedRule_))) continue;
      normals_.push_back(NormalException{int32_t(i), f.cN()});
    }
    normals_.shrink_to_fit();
  }

  static int32_t FaceIndex(const MeshType& m, const FaceType* f) {
    return f ? int32_t(vcg::tri::Index(m, f)) : -1;
  }
  static FaceType* Face(MeshType& m, int32_t i) { return i < 0 ? nullptr : &m.face[size_t(i)]; }

  // The attributes the journal keeps, by the same run-time checks (journal.h), each in an
  // array of its own that stays empty when the mesh lacks it.
  void TakeAttributes(const MeshType& m) {
    if (vcg::tri::HasPerVertexColor(m)) {
      vertColor_.reserve(nv_);
      for (const VertexType& v : m.vert) vertColor_.push_back(v.cC());
    }
    if (vcg::tri::HasPerVertexQuality(m)) {
      vertQuality_.reserve(nv_);
      for (const VertexType& v : m.vert) vertQuality_.push_back(v.cQ());
    }
    if (vcg::tri::HasPerVertexTexCoord(m)) {
      vertTex_.reserve(nv_);
      for (const VertexType& v : m.vert) vertTex_.push_back(v.cT());
    }
    if (vcg::tri::HasPerWedgeTexCoord(m)) {
      wedgeTex_.reserve(nf_);
      for (const FaceType& f : m.face) wedgeTex_.push_back(WedgeTex{{f.cWT(0), f.cWT(1), f.cWT(2)}});
    }
    if (vcg::tri::HasPerFaceColor(m)) {
      faceColor_.reserve(nf_);
      for (const FaceType& f : m.face) faceColor_.push_back(f.cC());
    }
    if (vcg::tri::HasPerFaceQuality(m)) {
      faceQuality_.reserve(nf_);
      for (const FaceType& f : m.face) faceQuality_.push_back(f.cQ());
    }
  }
  void RestoreAttributes(MeshType& m) const {
    for (size_t i = 0; i < vertColor_.size(); ++i) m.vert[i].C() = vertColor_[i];
    for (size_t i = 0; i < vertQuality_.size(); ++i) m.vert[i].Q() = vertQuality_[i];
    for (size_t i = 0; i < vertTex_.size(); ++i) m.vert[i].T() = vertTex_[i];
    for (size_t i = 0; i < wedgeTex_.size(); ++i)
      for (int z = 0; z < 3; ++z) m.face[i].WT(z) = wedgeTex_[i].t[z];
    for (size_t i = 0; i < faceColor_.size(); ++i) m.face[i].C() = faceColor_[i];
    for (size_t i = 0; i < faceQuality_.size(); ++i) m.face[i].Q() = faceQuality_[i];
  }

  bool taken_ = false;
  size_t nv_ = 0, nf_ = 0;
  int vn_ = 0, fn_ = 0;
  bool normalizedRule_ = true;  ///< the normals' rule (TakeNormals)
  std::vector<CoordType> pos_;
  std::vector<int> vertFlags_;
  std::vector<FaceState> face_;
  std::vector<FFException> ffExceptions_;  ///< faces whose FF the VF lists do not give back
  std::vector<VertexVF> vertVF_;           ///< vertices whose VF the rebuild does not give back
  std::vector<FaceVF> faceVF_;             ///< faces whose VF the rebuild does not give back
  std::vector<NormalException> normals_;   ///< faces whose normal the rule does not give back
  std::vector<typename VertexType::ColorType> vertColor_;
  std::vector<typename VertexType::QualityType> vertQuality_;
  std::vector<typename VertexType::TexCoordType> vertTex_;
  std::vector<WedgeTex> wedgeTex_;
  std::vector<typename FaceType::ColorType> faceColor_;
  std::vector<typename FaceType::QualityType> faceQuality_;
};

}  // namespace irregular
}  // namespace vcg_ext
