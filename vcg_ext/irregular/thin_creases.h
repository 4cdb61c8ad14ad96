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
// A line is a thin part's rim when at least `minShare` of its vertices have a neighbour off the
// line where the part is thinner than `thinEdges` mean edge lengths (LeftoverAnalysis::
// Thickness: a surface facing the other way that close behind it).
//
// Cost: once per run, O(V) for the line labels plus, per crease-line vertex, its neighbours'
// thickness queries (each a ball of thinEdges edge lengths in a grid of the mesh).
#pragma once

#include <vector>

#include "leftover_reasons.h"
#include "topology.h"

namespace vcg_ext {
namespace irregular {

/// Clears the flags of crease lines (connected sets of flagged vertices, by mesh edges) that are
/// a thin part's rim (header). Returns the number of lines cleared. Needs FF and VF adjacency.
/// Postcondition: every flag left set belongs to a line that is not a thin part's rim.
template <class MeshType>
int DropThinCreaseLines(MeshType& m, std::vector<char>& crease, double thinEdges, double minShare = 0.5) {
  if (thinEdges <= 0) return 0;
  const size_t n = std::min(crease.size(), m.vert.size());
  LeftoverOptions lo;
  lo.thinEdges = thinEdges;
  LeftoverAnalysis<MeshType> analysis(m, lo);
  std::vector<int> label(n, -1), stack, members;
  int dropped = 0;
  for (size_t s = 0; s < n; ++s) {
    if (!crease[s] || label[s] >= 0 || m.vert[s].IsD()) continue;
    // the line of s, by a walk over flagged neighbours
    members.clear();
    stack.assign(1, int(s));
    label[s] = int(s);
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      members.push_back(v);
      for (auto* w : StarOf<MeshType>(&m.vert[size_t(v)]).neighbors) {
        const size_t wi = size_t(vcg::tri::Index(m, w));
        if (wi < n && crease[wi] && label[wi] < 0) label[wi] = int(s), stack.push_back(int(wi));
      }
    }
    int thin = 0;
    for (int v : members) {
      for (auto* w : StarOf<MeshType>(&m.vert[size_t(v)]).neighbors) {
        const int wi = int(vcg::tri::Index(m, w));
        if (size_t(wi) < n && crease[size_t(wi)]) continue;  // on a line: its normal is the fold's
        if (analysis.Thickness(wi, StarOf<MeshType>(w)) < thinEdges) {
          ++thin;
          break;
        }
      }
    }
    if (double(thin) >= minShare * double(members.size())) {
      for (int v : members) crease[size_t(v)] = 0;
      ++dropped;
    }
  }
  return dropped;
}

}  // namespace irregular
}  // namespace vcg_ext
