// filter_irregular: the circle pattern (paper sec. 10, Fig. 14).
// SKELETON: the contract only; the implementation is being written (issue 15).
#pragma once

#include "pattern_result.h"

namespace vcg_ext {
namespace irregular {

struct CircleOptions {
  int ringWidth = 1;  ///< rings of faces per circle band
};

/// Circles. Reports `circles` (closed rings). Reads the mesh only.
template <class MeshType>
PatternLabels ComputeCircles(const MeshType& m, const CircleOptions& opt) {
  (void)m; (void)opt;
  return PatternLabels::Fail("circle pattern: not implemented yet");
}

}  // namespace irregular
}  // namespace vcg_ext
