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
// Cost: once per run, the lines (crease_line_edges.h), O(V) for the union-find over their ends,
// and per line edge at most two ball queries of thinEdges edge lengths in a grid of the edited
// mesh's vertices, built only when a line exists; a line's queries stop once its verdict is
// known (0.9.30; fandisk at 20K, one 1266-edge line kept: most of its edges are not probed).
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include <vcg/space/point3.h>

#include "crease_line_edges.h"
#include "leftover_reasons.h"

namespace vcg_ext {
namespace irregular {

/// Judges edges for thinness against one mesh (the edited one), in units of its mean edge
/// length: its vertex grid is built once, on the first question.
template <class MeshType>
class ThinRimProbe {
 public:
  ThinRimProbe(MeshType& m, double thinEdges) : analysis_(m, Options(thinEdges)), thinEdges_(thinEdges) {}

  /// Is the part thinner than thinEdges mean edge lengths behind either face of e?
  bool Thin(const CreaseLineEdge& e) {
    typedef typename MeshType::CoordType C;
    const C p = C::Construct(e.mid);
    const double h = analysis_.MeanEdgeLength();
    return analysis_.ThicknessAt(p, C::Construct(e.nA), h) < thinEdges_ ||
           analysis_.ThicknessAt(p, C::Construct(e.nB), h) < thinEdges_;
  }

 private:
  static LeftoverOptions Options(double thinEdges) {
    LeftoverOptions o;
    o.thinEdges = thinEdges;
    return o;
  }
  LeftoverAnalysis<MeshType> analysis_;
  double thinEdges_;
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
  std::vector<int> edges(nVerts, 0), probed(nVerts, 0), thin(nVerts, 0);
  for (const CreaseLineEdge& e : lines) ++edges[find(e.a)];
  // a line's probing stops once its verdict is known: enough thin edges to drop it, or too few
  // edges left to reach that share (the verdicts are those of probing every edge)
  auto decided = [&](uint32_t r) {
    const double need = minShare * double(edges[r]);
    return double(thin[r]) >= need || double(thin[r] + edges[r] - probed[r]) < need;
  };
  for (const CreaseLineEdge& e : lines) {
    const uint32_t r = find(e.a);
    if (decided(r)) continue;
    ++probed[r];
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

}  // namespace irregular
}  // namespace vcg_ext
