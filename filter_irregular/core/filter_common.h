// filter_irregular: helpers every filter's apply function shares (selection, finishing an
// edit, the colour legend and the topology summary with its output values).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "filter_spec.h"
#include "mesh_type.h"

#include <vcg_ext/irregular/topology.h>

namespace vcg_ext {
namespace irregular {
class SurfaceProjector;
class BoundaryCurve;
}  // namespace irregular
}  // namespace vcg_ext

namespace filter_irregular {

/// Indices of the selected live vertices, ascending.
std::vector<int> SelectedVertices(CMeshO& m);

/// After a connectivity edit: drop deleted elements, rebuild adjacency once, update normals
/// and bounding box (MeshLab's convention after a topology change).
void FinishEdit(CMeshO& m);

/// The input check every filter starts with: refuses non-manifold, polygonal, degenerate,
/// duplicated-vertex or unreferenced-vertex meshes, naming the MeshLab filter that repairs
/// each defect. Empty string: the mesh is fine.
std::string InputDefect(CMeshO& m);

/// Paints the legend (colorize) and writes valence into quality (writeQuality), replaces the
/// selection (selectMode: 0 keeps it, 1 all irregular, 2 only `selectValence`), logs the
/// topology summary and returns it. Output values: see AddSummaryValues.
vcg_ext::irregular::TopologySummary PaintAndLog(FilterContext& ctx, bool colorize, int selectMode, int selectValence,
                                                bool writeQuality, int* selected = nullptr);

/// Output values of a summary, with a suffix ("" for Analyze, "_before" / "_after" for the
/// editing filters): irregular, boundary_irregular (the boundary vertices among them, by the
/// boundary valence rule of topology.h), v3 (equivalent valence 3 or less), v4, v5, v7, v8,
/// v9 (9 or more), and
/// valence_histogram (a vector: entry k counts interior vertices of valence k; boundary
/// vertices in boundary_valence_histogram, without suffix variants).
void AddSummaryValues(FilterOutcome& out, const vcg_ext::irregular::TopologySummary& s, const std::string& suffix);

/// Summary of the mesh as it is (no painting, no log).
vcg_ext::irregular::TopologySummary SummaryOf(CMeshO& m);

/// " v5:12 v7:10" from a valence histogram.
std::string HistogramText(const std::map<int, int>& h);

/// The shape measures line ("Before: min angle ...").
void LogShape(FilterContext& ctx, const char* when, CMeshO& m);

/// The relaxation after an edit (sec. 8): the surface and its boundary frozen as they were
/// before the filter, then local relaxation of the 2-ring around the edited vertices,
/// projected onto that surface, boundary vertices sliding along that boundary (corners
/// fixed), texture coordinates re-sampled where the vertices moved to
/// (attribute_transfer.h). Disabled: freezes nothing and relaxes nothing.
class EditRelaxation {
 public:
  EditRelaxation(CMeshO& m, bool enabled);  ///< O(F) when enabled: call before editing
  ~EditRelaxation();
  /// The frozen surface (null when disabled), for operations that relax step by step.
  const vcg_ext::irregular::SurfaceProjector* Surface() const;
  /// Relaxes the 2-ring around the live vertices of `seeds`; returns its size (0 when
  /// disabled). O(ring).
  int Around(const std::vector<int>& seeds, int iterations = 5);

 private:
  struct Frozen;
  CMeshO& m_;
  std::unique_ptr<Frozen> frozen_;
};

}  // namespace filter_irregular
