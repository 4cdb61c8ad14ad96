// filter_irregular: "Irregular Vertices: Analyze": the legend, the selection, the topology
// summary (log and output values).
#include "filter_common.h"
#include "filters.h"

namespace filter_irregular {

FilterOutcome ApplyAnalyze(FilterContext& ctx, const ParamValues& par) {
  CMeshO& m = ctx.Mesh();
  const std::string defect = InputDefect(m);
  if (!defect.empty()) return FilterOutcome::Refuse(defect);
  int selected = 0;
  vcg_ext::irregular::TopologySummary s =
      PaintAndLog(ctx, par.Bool("colorize"), par.Enum("select"), par.Int("valence"), true, &selected);
  FilterOutcome out;
  out.SetInt("vertices", s.vertices);
  out.SetInt("edges", s.edges);
  out.SetInt("faces", s.faces);
  AddSummaryValues(out, s, "");
  out.SetFloat("irregular_percent", s.vertices ? 100.0 * s.irregular / s.vertices : 0.0);
  int top = 0;
  for (auto& kv : s.boundaryHistogram) top = std::max(top, kv.first);
  std::vector<double> boundary(size_t(top) + 1, 0.0);
  for (auto& kv : s.boundaryHistogram) boundary[size_t(kv.first)] = kv.second;
  out.SetVector("boundary_valence_histogram", boundary);
  out.SetInt("boundary_corners", s.boundaryCorners);
  out.SetInt("euler_characteristic", s.eulerCharacteristic);
  out.SetInt("genus", s.genus);
  out.SetInt("boundary_loops", s.boundaryLoops);
  out.SetInt("components", s.components);
  out.SetInt("gauss_bonnet_sum", s.gaussBonnetSum);
  out.SetBool("gauss_bonnet_holds", s.GaussBonnetHolds());
  out.SetInt("selected", par.Enum("select") != 0 ? selected : int(SelectedVertices(m).size()));
  return out;
}

}  // namespace filter_irregular
