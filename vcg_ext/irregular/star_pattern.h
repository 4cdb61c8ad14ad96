// filter_irregular: the star pattern seeded at v5 vertices (paper sec. 10, Fig. 12).
// SKELETON: the contract only; the implementation is being written (issue 15).
#pragma once

#include <vector>

#include "pattern_result.h"

namespace vcg_ext {
namespace irregular {

struct StarOptions {
  std::vector<int> seeds;  ///< seed vertex indices; empty: every interior v5
  int radius = 3;          ///< star radius in rings (edges) around the seed
};

/// Stars around the seeds. Reports starSeeds and isolatedStarSeeds (no other irregular vertex
/// within `radius` rings). Reads the mesh only.
template <class MeshType>
PatternLabels ComputeStars(const MeshType& m, const StarOptions& opt) {
  (void)m; (void)opt;
  return PatternLabels::Fail("star pattern: not implemented yet");
}

}  // namespace irregular
}  // namespace vcg_ext
