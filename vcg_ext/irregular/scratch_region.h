// filter_irregular: a scratch copy of the few rings around some vertices (issue 13, item 3),
// for dry runs that simulate an operation instead of applying it and rolling it back.
//
// ScratchRegion::Extract copies every face incident to the k-ring of the seed vertices into a
// small mesh of the same type and maps vertex ids both ways. The user's mesh is only read.
// Fidelity: the copy keeps the original's vertex and face order (so "the neighbour of smallest
// index" and every tie-break are the same), rebuilds FF there and, for every vertex whose
// whole star was copied, restores the original VF chain (the order stars are walked in); the
// optional (Ocf) components the user's mesh has enabled are enabled in the copy, attributes
// are copied. Vertices whose star was cut form the cut border, which looks like a mesh
// boundary to an operation: `guard` holds the vertices within `margin` rings of it, and
// GuardState / SameGuard tell whether a run changed anything there (then the run may differ
// from the real operation and the caller grows the region).
//
// Ids: scratch vertex i < n0 is the copy of user vertex orig[i - pad]; a vertex the run
// creates (i >= n0) would be appended to the user's mesh, so it maps to
// m.vert.size() + (i - n0). With pad > 0 the copy starts with `pad` deleted placeholder
// vertices, so every live scratch id is >= pad: a number >= pad in a message written by the
// run is a vertex id and BackText renames it to the user's id (numbers below pad - valences,
// step counts - are left alone). Cost: O(region + pad).
#pragma once

#include <algorithm>
#include <cctype>
#include <string>
#include <unordered_map>
#include <vector>

#include <vcg/complex/complex.h>

#include "relaxation.h"  // KRing
#include "topology.h"

namespace vcg_ext {
namespace irregular {

template <class MeshType>
class ScratchRegion {
 public:
  typedef typename MeshType::VertexType VertexType;
  typedef typename MeshType::FaceType FaceType;
  typedef typename MeshType::CoordType CoordType;

  MeshType mesh;                          ///< the copy
  std::vector<int> orig;                  ///< scratch vertex i (>= pad, < n0) -> user vertex orig[i - pad]
  std::unordered_map<int, int> toScratch; ///< user vertex -> scratch vertex
  std::vector<int> guard;                 ///< scratch vertices within `margin` rings of the cut border
  int pad = 0;                            ///< leading deleted placeholder vertices
  int n0 = 0;                             ///< scratch vertices right after Extract
  int userSize = 0;                       ///< the user's m.vert.size()

  /// Precondition: m has FF and VF up to date; seeds that are not live vertices are ignored.
  /// Copies the faces incident to the k-ring of the seeds (see header).
  void Extract(MeshType& m, const std::vector<int>& seeds, int k, int margin, int padding = 0) {
    userSize = int(m.vert.size());
    pad = padding;
    std::vector<int> live;
    for (int c : seeds)
      if (Live(m, c)) live.push_back(c);
    const std::vector<int> inner = KRing(m, live, k);
    std::vector<int> faces;
    for (int v : inner)
      for (auto& c : StarOf<MeshType>(&m.vert[size_t(v)]).corners) faces.push_back(int(vcg::tri::Index(m, c.f)));
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    std::vector<int> verts;
    for (int f : faces)
      for (int z = 0; z < 3; ++z) verts.push_back(int(vcg::tri::Index(m, m.face[size_t(f)].V(z))));
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    orig = verts;
    for (size_t i = 0; i < verts.size(); ++i) toScratch[verts[i]] = pad + int(i);
    std::unordered_map<int, int> faceTo;
    for (size_t j = 0; j < faces.size(); ++j) faceTo[faces[j]] = int(j);
    mesh.textures = m.textures;
    EnableLikeSource(m, mesh);
    if (pad > 0) {
      vcg::tri::Allocator<MeshType>::AddVertices(mesh, size_t(pad));
      for (int i = 0; i < pad; ++i) vcg::tri::Allocator<MeshType>::DeleteVertex(mesh, mesh.vert[size_t(i)]);
    }
    vcg::tri::Allocator<MeshType>::AddVertices(mesh, verts.size());
    vcg::tri::Allocator<MeshType>::AddFaces(mesh, faces.size());
    for (size_t i = 0; i < verts.size(); ++i) mesh.vert[size_t(pad) + i].ImportData(m.vert[size_t(verts[i])]);
    for (size_t j = 0; j < faces.size(); ++j) {
      FaceType& src = m.face[size_t(faces[j])];
      FaceType& dst = mesh.face[j];
      dst.ImportData(src);
      for (int z = 0; z < 3; ++z) dst.V(z) = &mesh.vert[size_t(toScratch[int(vcg::tri::Index(m, src.V(z)))])];
    }
    vcg::tri::UpdateTopology<MeshType>::FaceFace(mesh);
    vcg::tri::UpdateTopology<MeshType>::VertexFace(mesh);
    // Vertices whose whole star was copied keep the original VF chain; the others form the
    // cut border.
    std::vector<int> border;
    for (size_t i = 0; i < verts.size(); ++i) {
      VertexType& ov = m.vert[size_t(verts[i])];
      bool whole = true;
      for (auto& c : StarOf<MeshType>(&ov).corners) whole = whole && faceTo.count(int(vcg::tri::Index(m, c.f)));
      if (!whole) {
        border.push_back(pad + int(i));
        continue;
      }
      VertexType& sv = mesh.vert[size_t(pad) + i];
      sv.VFp() = &mesh.face[size_t(faceTo[int(vcg::tri::Index(m, ov.cVFp()))])];
      sv.VFi() = ov.cVFi();
      for (auto& c : StarOf<MeshType>(&ov).corners) {
        FaceType& of = *c.f;
        FaceType& sf = mesh.face[size_t(faceTo[int(vcg::tri::Index(m, &of))])];
        FaceType* nf = of.cVFp(c.z);
        sf.VFp(c.z) = nf ? &mesh.face[size_t(faceTo[int(vcg::tri::Index(m, nf))])] : nullptr;
        sf.VFi(c.z) = of.cVFi(c.z);
      }
    }
    guard = KRing(mesh, border, margin);
    n0 = int(mesh.vert.size());
  }

  /// user vertex -> scratch vertex, -1 if not copied (operations refuse it as dead)
  int ToScratch(int i) const {
    auto it = toScratch.find(i);
    return it == toScratch.end() ? -1 : it->second;
  }
  std::vector<int> ToScratch(const std::vector<int>& v) const {
    std::vector<int> r;
    for (int i : v) r.push_back(ToScratch(i));
    return r;
  }
  /// scratch vertex -> user vertex (created ones: the id they would get); -1 stays -1
  int Back(int i) const {
    if (i < 0) return -1;
    if (i < pad) return -1;
    if (i < n0) return orig[size_t(i - pad)];
    return userSize + (i - n0);
  }
  std::vector<int> Back(const std::vector<int>& v) const {
    std::vector<int> r;
    for (int i : v) r.push_back(Back(i));
    return r;
  }
  /// A message written by a run on the scratch, with every number >= pad (a vertex id, see
  /// header) renamed to the user's id. Only meaningful with pad > 0.
  std::string BackText(const std::string& s) const {
    if (pad <= 0) return s;
    std::string out;
    for (size_t i = 0; i < s.size();) {
      const bool digitStart = std::isdigit((unsigned char)s[i]) && (i == 0 || (!std::isalnum((unsigned char)s[i - 1]) &&
                                                                             s[i - 1] != '.' && s[i - 1] != '_'));
      if (!digitStart) {
        out += s[i++];
        continue;
      }
      size_t j = i;
      while (j < s.size() && std::isdigit((unsigned char)s[j])) ++j;
      const bool plainInt = j == s.size() || (s[j] != '.' || j + 1 == s.size() || !std::isdigit((unsigned char)s[j + 1]));
      const std::string tok = s.substr(i, j - i);
      if (plainInt && tok.size() < 10) {
        const long long x = std::stoll(tok);
        if (x >= pad && x < (long long)mesh.vert.size()) {
          out += std::to_string(Back(int(x)));
          i = j;
          continue;
        }
      }
      out += tok;
      i = j;
    }
    return out;
  }

  /// Positions, valences and deletions of the guard vertices, to tell whether a run reached
  /// the cut border.
  struct GuardState {
    std::vector<CoordType> p;
    std::vector<int> valence;
    std::vector<char> dead;
    bool operator==(const GuardState& o) const { return p == o.p && valence == o.valence && dead == o.dead; }
  };
  GuardState Guard() {
    GuardState g;
    for (int v : guard) {
      VertexType& x = mesh.vert[size_t(v)];
      g.p.push_back(x.P());
      g.dead.push_back(x.IsD() ? 1 : 0);
      g.valence.push_back(x.IsD() ? 0 : irregular::Valence<MeshType>(&x));
    }
    return g;
  }

  static bool Live(const MeshType& m, int i) {
    return i >= 0 && size_t(i) < m.vert.size() && !m.vert[size_t(i)].IsD() && m.vert[size_t(i)].cVFp();
  }

 private:
// Optional (Ocf) components, as in MeshLab's CMeshO: the scratch enables what the user's mesh
// has enabled, so adjacency exists and attributes are copied. No-ops for static components.
#define FI_MIRROR_OCF(Name)                                                                        \
  template <class C>                                                                               \
  static auto Mirror##Name(C& src, C& dst, int)->decltype(src.Is##Name##Enabled(), void()) {      \
    if (src.Is##Name##Enabled()) dst.Enable##Name();                                               \
  }                                                                                                \
  template <class C>                                                                               \
  static void Mirror##Name(C&, C&, long) {}
  FI_MIRROR_OCF(FFAdjacency)
  FI_MIRROR_OCF(VFAdjacency)
  FI_MIRROR_OCF(Mark)
  FI_MIRROR_OCF(TexCoord)
  FI_MIRROR_OCF(WedgeTexCoord)
  FI_MIRROR_OCF(Color)
  FI_MIRROR_OCF(Quality)
  FI_MIRROR_OCF(Normal)
#undef FI_MIRROR_OCF

  static void EnableLikeSource(MeshType& m, MeshType& s) {
    MirrorVFAdjacency(m.vert, s.vert, 0);
    MirrorMark(m.vert, s.vert, 0);
    MirrorTexCoord(m.vert, s.vert, 0);
    MirrorColor(m.vert, s.vert, 0);
    MirrorQuality(m.vert, s.vert, 0);
    MirrorNormal(m.vert, s.vert, 0);
    MirrorFFAdjacency(m.face, s.face, 0);
    MirrorVFAdjacency(m.face, s.face, 0);
    MirrorMark(m.face, s.face, 0);
    MirrorWedgeTexCoord(m.face, s.face, 0);
    MirrorColor(m.face, s.face, 0);
    MirrorQuality(m.face, s.face, 0);
    MirrorNormal(m.face, s.face, 0);
  }
};

}  // namespace irregular
}  // namespace vcg_ext
