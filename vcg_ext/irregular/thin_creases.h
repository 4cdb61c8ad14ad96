// filter_irregular: the crease lines that are the rim of a thin part, which the automatic
// reduction does not protect (issue 14: "creases stay sharp", and "thin parts").
//
// A crease line (crease_lines.h) is kept sharp by the reduction: its vertices never move, and
// an edit that cuts it is refused. That is right for a design crease (fandisk's). But the rim
// of a thin flap (a lion's ear: two sheets a few edge lengths apart, folded over in one or two
// edges) is as sharp and as straight, and protecting it freezes the irregular vertices its
// thin part needs next to it: on the lion at 20K, 65 of its 143 interior leftovers lay within
// two edges of a sharp edge (18 of 86 with no crease lines). Such a rim is no feature of the
// design but of the thin part, which keeps its shape through the Hausdorff budget anyway.
//
// A line is a thin part's rim when at least `minShare` of its edges are thin: behind one of
// the edge's two faces (against its normal), within `thinEdges` mean edge lengths of the edge's
// midpoint, lies a vertex of the edited mesh whose normal faces the other way
// (LeftoverAnalysis::ThicknessAt). The test reads the edited mesh only, so the lines of the
// mesh being edited (whose vertices relaxation keeps still) and those of the input the edit
// guard measures against (whose samples get the crease budget) are judged alike, even when the
// two are different meshes (the filter's remeshing first).
//
// Cost: once per run, O(F) (with FF adjacency) or O(F log F) (without: half-edges sorted) to
// find the lines, O(V) for the union-find over their ends, and per line edge two ball queries
// of thinEdges edge lengths in a grid of the edited mesh's vertices, built only when a line
// exists.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include <vcg/space/point3.h>

#include "crease_lines.h"
#include "leftover_reasons.h"

namespace vcg_ext {
namespace irregular {

/// An edge of a crease line: its ends (vertex indices of its mesh), its midpoint and the unit
/// normals of its two faces.
struct CreaseLineEdge {
  uint32_t a, b;
  vcg::Point3d mid, nA, nB;
};

namespace thin_detail {

template <class FaceType>
vcg::Point3d UnitNormal(const FaceType& f) {
  vcg::Point3d n = vcg::Point3d::Construct(vcg::TriangleNormal(f));
  const double l = n.Norm();
  return l > 0 ? n / l : n;
}

/// The candidates (interior edges sharper than angleDeg) with their faces, kept when their set
/// is a crease line (CreaseLineEdges).
template <class MeshType>
std::vector<CreaseLineEdge> KeepLines(const MeshType& m, std::vector<CreaseLineEdge> sharp, int minEdges,
                                      double minStraightShare) {
  std::vector<std::pair<uint32_t, uint32_t>> ends;
  ends.reserve(sharp.size());
  for (const CreaseLineEdge& e : sharp) ends.push_back({e.a, e.b});
  const std::vector<char> keep = CreaseLineEdges(
      ends, m.vert.size(), minEdges, [&m](uint32_t i) { return m.vert[i].cP(); }, minStraightShare);
  std::vector<CreaseLineEdge> lines;
  for (size_t i = 0; i < sharp.size(); ++i)
    if (keep[i]) lines.push_back(sharp[i]);
  return lines;
}

}  // namespace thin_detail

/// The crease-line edges of a mesh with FF adjacency (the rule of CreaseLineVertices,
/// relaxation.h: edges sharper than angleDeg in sets of minEdges that run as lines). O(F + E log E).
template <class MeshType>
std::vector<CreaseLineEdge> CreaseLineEdgesOf(MeshType& m, double angleDeg, int minEdges, double minStraightShare) {
  std::vector<CreaseLineEdge> sharp;
  if (angleDeg <= 0) return sharp;
  const double c = std::cos(angleDeg * M_PI / 180.0);
  for (auto& f : m.face) {
    if (f.IsD()) continue;
    for (int z = 0; z < 3; ++z) {
      auto* g = f.FFp(z);
      if (g == &f || g < &f) continue;  // each interior edge once
      // the sharpness test exactly as CreaseLineVertices computes it (the same lines, to the bit)
      if (!(double(vcg::TriangleNormal(f).Normalize().dot(vcg::TriangleNormal(*g).Normalize())) < c)) continue;
      const vcg::Point3d nf = thin_detail::UnitNormal(f), ng = thin_detail::UnitNormal(*g);
      const uint32_t a = uint32_t(vcg::tri::Index(m, f.V(z))), b = uint32_t(vcg::tri::Index(m, f.V((z + 1) % 3)));
      sharp.push_back({a, b, (vcg::Point3d::Construct(f.cP(z)) + vcg::Point3d::Construct(f.cP((z + 1) % 3))) / 2, nf, ng});
    }
  }
  return thin_detail::KeepLines(m, std::move(sharp), minEdges, minStraightShare);
}

/// The same for a mesh without adjacency but with unit face normals (the edit guard's copy of
/// the input, SurfaceProjector::Mesh): its half-edges sorted by their ends; sharpness from the
/// stored normals, as the guard's SharpEdgeSamples computes it. Vertex indices are the mesh's.
/// O(F log F).
template <class MeshType>
std::vector<CreaseLineEdge> CreaseLineEdgesOfSoup(const MeshType& m, double angleDeg, int minEdges,
                                                  double minStraightShare) {
  std::vector<CreaseLineEdge> sharp;
  if (angleDeg <= 0) return sharp;
  struct HalfEdge {
    uint32_t a, b, f;
  };
  std::vector<HalfEdge> he;
  he.reserve(3 * m.face.size());
  for (size_t i = 0; i < m.face.size(); ++i) {
    if (m.face[i].IsD()) continue;
    for (int z = 0; z < 3; ++z) {
      uint32_t a = uint32_t(vcg::tri::Index(m, m.face[i].cV(z))), b = uint32_t(vcg::tri::Index(m, m.face[i].cV((z + 1) % 3)));
      if (a > b) std::swap(a, b);
      he.push_back({a, b, uint32_t(i)});
    }
  }
  std::sort(he.begin(), he.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.f < y.f;
  });
  const double c = std::cos(angleDeg * M_PI / 180.0);
  for (size_t i = 0, j = 0; i < he.size(); i = j) {
    for (j = i + 1; j < he.size() && he[j].a == he[i].a && he[j].b == he[i].b; ++j) {
    }
    if (j - i != 2) continue;  // boundary or non-manifold
    if (!(double(m.face[he[i].f].cN().dot(m.face[he[i + 1].f].cN())) < c)) continue;
    const vcg::Point3d nf = thin_detail::UnitNormal(m.face[he[i].f]), ng = thin_detail::UnitNormal(m.face[he[i + 1].f]);
    const vcg::Point3d mid = (vcg::Point3d::Construct(m.vert[he[i].a].cP()) + vcg::Point3d::Construct(m.vert[he[i].b].cP())) / 2;
    sharp.push_back({he[i].a, he[i].b, mid, nf, ng});
  }
  return thin_detail::KeepLines(m, std::move(sharp), minEdges, minStraightShare);
}

/// Judges edges for thinness against one mesh (the edited one): its vertex grid is built once,
/// on the first question. h: the mesh's mean edge length.
template <class MeshType>
class ThinRimProbe {
 public:
  ThinRimProbe(MeshType& m, double thinEdges) : analysis_(m, Options(thinEdges)), thinEdges_(thinEdges) {
    double sum = 0;
    long n = 0;
    for (auto& f : m.face)
      if (!f.IsD())
        for (int z = 0; z < 3; ++z, ++n) sum += double((f.cP(z) - f.cP((z + 1) % 3)).Norm());
    h_ = n ? sum / double(n) : 0;
  }

  /// Is the part thinner than thinEdges mean edge lengths behind either face of e?
  bool Thin(const CreaseLineEdge& e) {
    typedef typename MeshType::CoordType C;
    const C p = C::Construct(e.mid);
    return analysis_.ThicknessAt(p, C::Construct(e.nA), h_) < thinEdges_ ||
           analysis_.ThicknessAt(p, C::Construct(e.nB), h_) < thinEdges_;
  }

 private:
  static LeftoverOptions Options(double thinEdges) {
    LeftoverOptions o;
    o.thinEdges = thinEdges;
    return o;
  }
  LeftoverAnalysis<MeshType> analysis_;
  double thinEdges_;
  double h_ = 0;
};

/// Removes from `lines` (the crease-line edges of a mesh of nVerts vertices) every line (a
/// connected set of them) at least minShare of whose edges the probe finds thin. Returns the
/// number of lines removed. Postcondition: no line left is a thin part's rim.
template <class Probe>
int DropThinLines(std::vector<CreaseLineEdge>& lines, size_t nVerts, Probe& probe, double minShare = 0.5) {
  if (lines.empty()) return 0;
  VertexSets sets(nVerts);
  auto find = [&](uint32_t x) { return sets.Find(x); };
  for (const CreaseLineEdge& e : lines) sets.Join(e.a, e.b);
  std::vector<int> edges(nVerts, 0), thin(nVerts, 0);
  for (const CreaseLineEdge& e : lines) {
    const uint32_t r = find(e.a);
    ++edges[r];
    thin[r] += probe.Thin(e) ? 1 : 0;
  }
  int dropped = 0;
  std::vector<char> drop(nVerts, 0);
  for (size_t r = 0; r < nVerts; ++r)
    if (edges[r] > 0 && double(thin[r]) >= minShare * double(edges[r])) drop[r] = 1, ++dropped;
  lines.erase(std::remove_if(lines.begin(), lines.end(), [&](const CreaseLineEdge& e) { return drop[find(e.a)] != 0; }),
              lines.end());
  return dropped;
}

/// Per vertex of a mesh of nVerts vertices, 1 on one of the lines.
inline std::vector<char> LineVertices(const std::vector<CreaseLineEdge>& lines, size_t nVerts) {
  std::vector<char> flags(nVerts, 0);
  for (const CreaseLineEdge& e : lines) flags[e.a] = flags[e.b] = 1;
  return flags;
}

}  // namespace irregular
}  // namespace vcg_ext
