// filter_irregular: geometry replacement (paper Fig. 1 middle and right, Fig. 14d): every
// pattern region becomes a panel in a new mesh.
// SKELETON: the contract only; the implementation is being written (issue 15).
#pragma once

#include <string>
#include <vector>

#include "pattern_result.h"

namespace vcg_ext {
namespace irregular {

struct PanelOptions {
  double inset = 0.15;    ///< inset of each panel's outline, as a fraction of the mean edge length
  double extrude = 0.25;  ///< extrusion along the normal, as a fraction of the mean edge length (0: flat)
};

struct PanelReport {
  bool ok = true;
  std::string reason;
  int panels = 0;
  std::vector<int> panelSidesHistogram;  ///< [s] = panels whose outline has s sides
};

/// Writes into `out` (cleared first) one panel per region of `labels` over `m`. `m` is only read.
template <class MeshType>
PanelReport BuildPanels(const MeshType& m, const PatternLabels& labels, const PanelOptions& opt, MeshType& out) {
  (void)m; (void)labels; (void)opt; (void)out;
  PanelReport r;
  r.ok = false;
  r.reason = "panels: not implemented yet";
  return r;
}

}  // namespace irregular
}  // namespace vcg_ext
