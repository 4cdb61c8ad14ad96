// filter_irregular: "Irregular Vertices: Relax": local or global relaxation (sec. 8,
// vcg_ext/irregular/relaxation.h) projected onto the mesh as it was before the filter.
#include <algorithm>

#include "filter_common.h"
#include "filters.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>

#include <vcg_ext/irregular/attribute_transfer.h>
#include <vcg_ext/irregular/quality.h>
#include <vcg_ext/irregular/relaxation.h>

namespace irr = vcg_ext::irregular;

namespace filter_irregular {

namespace {
void AddShapeValues(FilterOutcome& out, const irr::ShapeMeasures& s, const char* suffix) {
  out.SetFloat(std::string("min_angle") + suffix, s.minAngleDeg);
  out.SetFloat(std::string("mean_min_angle") + suffix, s.meanMinAngleDeg);
  out.SetFloat(std::string("percent_below_30") + suffix, 100.0 * s.shareBelow30);
  out.SetFloat(std::string("edge_length_spread") + suffix, s.edgeLengthSpread);
}
}  // namespace

FilterOutcome ApplyRelax(FilterContext& ctx, const ParamValues& par) {
  CMeshO& m = ctx.Mesh();
  const std::string defect = InputDefect(m);
  if (!defect.empty()) return FilterOutcome::Refuse(defect);
  irr::RelaxOptions ro;
  ro.mode = irr::RelaxMode(par.Enum("mode"));
  ro.iterations = par.Int("iterations");
  ro.reproject = par.Bool("reproject");
  ro.featureAngleDeg = float(par.Float("featureAngle"));
  std::vector<int> region;
  const int which = par.Enum("region");
  if (which == 1) region = SelectedVertices(m);
  if (which == 2) {
    irr::ValenceField<CMeshO> vf = irr::ComputeValences(m);
    std::vector<int> seeds;
    for (size_t i = 0; i < m.vert.size(); ++i)
      if (!m.vert[i].IsD() && vf.IsIrregular(i)) seeds.push_back(int(i));
    region = irr::KRing(m, seeds, 2);
  }
  if (which == 0 || (which == 1 && region.empty()))
    for (size_t i = 0; i < m.vert.size(); ++i)
      if (!m.vert[i].IsD()) region.push_back(int(i));
  irr::SurfaceProjector original(m);
  // Both modes slide boundary vertices along the boundary as it was (corners stay).
  irr::BoundaryCurve boundary(m);
  ro.boundaryCurve = &boundary;
  std::vector<char> crease = irr::CreaseVertices(m, ro.featureAngleDeg);
  const irr::ShapeMeasures before = irr::MeasureShape(m);
  // eq. 5 over the terms the free vertices reach (the rest of the mesh's eq. 5 is a constant)
  const irr::RelaxMeasures energyBefore = irr::MeasureRelaxRegion(m, region, ro, &crease);
  LogShape(ctx, "Before", m);
  // Progress: one sweep at a time so the bar moves.
  irr::RelaxOptions one = ro;
  one.iterations = 1;
  irr::RelaxReport total;
  auto cb = ctx.Progress();
  for (int it = 0; it < ro.iterations; ++it) {
    if (cb) cb(100 * it / std::max(1, ro.iterations), "Relaxing...");
    // per sweep, so that no vertex leaves the star its texture coordinates are sampled from
    irr::AttributeResampler<CMeshO> texture(m, region);
    irr::RelaxReport r = irr::Relax(m, region, ro.reproject ? &original : nullptr, one, &crease);
    texture.Resample();
    total.vertices = r.vertices;
    total.moved += r.moved;
    total.rejected += r.rejected;
    total.seconds += r.seconds;
    total.solveSeconds += r.solveSeconds;
    // Global: a round that found no step lowering eq. 5 without hurting a triangle converged;
    // the next would solve the same problem again.
    if (ro.mode == irr::RelaxMode::Global && r.moved == 0) break;
  }
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  const irr::ShapeMeasures after = irr::MeasureShape(m);
  const irr::RelaxMeasures energyAfter = irr::MeasureRelaxRegion(m, region, ro, &crease);
  LogShape(ctx, "After", m);
  ctx.Logf("Energy of eq. 5 (1-ring target lengths) over the relaxed region: %.6g -> %.6g", energyBefore.energy,
           energyAfter.energy);
  ctx.Logf("Relaxed %d vertices (%s, %d iterations): %d moves, %d refused (would fold), %.3f s (solver %.3f s)",
           total.vertices, ro.mode == irr::RelaxMode::Global ? "global" : "local", ro.iterations, total.moved,
           total.rejected, total.seconds, total.solveSeconds);
  const double hausdorff = irr::HausdorffPercent(m, original);
  ctx.Logf("Hausdorff distance to the input: %.4f%% of the bounding box diagonal", hausdorff);
  FilterOutcome out;
  AddShapeValues(out, before, "_before");
  AddShapeValues(out, after, "_after");
  out.SetInt("relaxed_vertices", total.vertices);
  out.SetInt("moves", total.moved);
  out.SetInt("refused_moves", total.rejected);
  out.SetFloat("hausdorff_percent", hausdorff);
  out.SetFloat("energy_before", energyBefore.energy);
  out.SetFloat("energy_after", energyAfter.energy);
  out.SetFloat("seconds", total.seconds);
  return out;
}

}  // namespace filter_irregular
