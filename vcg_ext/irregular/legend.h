// filter_irregular: the one colour legend every filter uses, and valence-based selection.
//
// Colours follow the paper's figures (v5 blue, v7 orange, v8 red) and extend them:
//   v3 or less  purple   (150,  40, 190)
//   v4          cyan     (  0, 175, 200)
//   v5          blue     ( 40,  80, 230)
//   v6          grey     (200, 200, 200)   regular
//   v7          orange   (245, 140,  20)
//   v8          red      (215,  30,  30)
//   v9 or more  dark red (110,   0,  20)
// A boundary vertex is coloured by its equivalent interior valence (valence + 2), so a
// regular boundary vertex (valence 4) is grey and a boundary vertex of valence 3 is blue.
#pragma once

#include <vcg/complex/complex.h>

#include "topology.h"

namespace vcg_ext {
namespace irregular {

inline vcg::Color4b LegendColor(int equivalentValence) {
  if (equivalentValence <= 3) return vcg::Color4b(150, 40, 190, 255);
  switch (equivalentValence) {
    case 4: return vcg::Color4b(0, 175, 200, 255);
    case 5: return vcg::Color4b(40, 80, 230, 255);
    case 6: return vcg::Color4b(200, 200, 200, 255);
    case 7: return vcg::Color4b(245, 140, 20, 255);
    case 8: return vcg::Color4b(215, 30, 30, 255);
    default: return vcg::Color4b(110, 0, 20, 255);
  }
}

/// Writes the valence into vertex quality and, if colorize, the legend colour into vertex
/// colour, for every live referenced vertex. Unreferenced vertices are left alone.
template <class MeshType>
void PaintValences(MeshType& m, const ValenceField<MeshType>& vf, bool colorize, bool writeQuality = true) {
  for (size_t i = 0; i < m.vert.size(); ++i) {
    if (m.vert[i].IsD() || !vf.referenced[i]) continue;
    if (writeQuality) m.vert[i].Q() = typename MeshType::VertexType::QualityType(vf.valence[i]);
    if (colorize) m.vert[i].C() = LegendColor(vf.Equivalent(i));
  }
}

enum class IrregularSelection { None = 0, AllIrregular = 1, OnlyValence = 2 };

/// Replaces the vertex selection with every irregular vertex, or with the vertices whose
/// equivalent valence equals `valence`; mode None leaves the selection alone.
/// Returns the number of selected vertices.
template <class MeshType>
int SelectByValence(MeshType& m, const ValenceField<MeshType>& vf, IrregularSelection mode, int valence) {
  int n = 0;
  if (mode == IrregularSelection::None) {
    for (size_t i = 0; i < m.vert.size(); ++i) n += !m.vert[i].IsD() && m.vert[i].IsS();
    return n;
  }
  for (size_t i = 0; i < m.vert.size(); ++i) {
    if (m.vert[i].IsD()) continue;
    bool sel = false;
    if (vf.referenced[i]) {
      if (mode == IrregularSelection::AllIrregular) sel = vf.IsIrregular(i);
      if (mode == IrregularSelection::OnlyValence) sel = vf.Equivalent(i) == valence;
    }
    if (sel) {
      m.vert[i].SetS();
      ++n;
    } else {
      m.vert[i].ClearS();
    }
  }
  return n;
}

}  // namespace irregular
}  // namespace vcg_ext
