// filter_irregular: stripe and zebra patterns (paper sec. 10, Figs. 1 and 13).
// SKELETON: the contract only; the implementation is being written (issue 15).
#pragma once

#include "pattern_result.h"

namespace vcg_ext {
namespace irregular {

struct StripeOptions {
  int seedFace = -1;      ///< face where the direction is picked; -1: from seedVertex, else face 0
  int seedVertex = -1;    ///< alternative seed: a selected vertex (its first incident face)
  int direction = 0;      ///< which of the seed face's three edges gives the lattice direction (0..2)
  int period = 2;         ///< stripes alternate every `period` strips (2: A B A B ...)
};

/// Stripes: triangle strips between consecutive straight edge lines of one lattice direction,
/// carried from the seed. Fills faceRegion, regionKind (StripeA/StripeB/Cell/Conflict) and the
/// measures (strips, width histogram, cells, conflict faces). Reads the mesh only.
template <class MeshType>
PatternLabels ComputeStripes(const MeshType& m, const StripeOptions& opt) {
  (void)m; (void)opt;
  return PatternLabels::Fail("stripe pattern: not implemented yet");
}

/// Zebra (Fig. 13): stripes whose direction follows the lattice through the singularities.
template <class MeshType>
PatternLabels ComputeZebra(const MeshType& m, const StripeOptions& opt) {
  (void)m; (void)opt;
  return PatternLabels::Fail("zebra pattern: not implemented yet");
}

}  // namespace irregular
}  // namespace vcg_ext
