// filter_irregular: helpers shared by the filters' apply functions (see filter_common.h).
#include "filter_common.h"

#include <algorithm>

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <vcg_ext/irregular/legend.h>
#include <vcg_ext/irregular/mesh_checks.h>
#include <vcg_ext/irregular/attribute_transfer.h>
#include <vcg_ext/irregular/quality.h>
#include <vcg_ext/irregular/relaxation.h>

namespace irr = vcg_ext::irregular;

namespace filter_irregular {

std::vector<int> SelectedVertices(CMeshO& m) {
  std::vector<int> s;
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD() && m.vert[i].IsS()) s.push_back(int(i));
  return s;
}

void FinishEdit(CMeshO& m) {
  vcg::tri::Allocator<CMeshO>::CompactEveryVector(m);
  vcg::tri::UpdateTopology<CMeshO>::FaceFace(m);
  vcg::tri::UpdateTopology<CMeshO>::VertexFace(m);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
}

std::string InputDefect(CMeshO& m) {
  // Attributes are not defects: texture coordinates, face and vertex colours and qualities
  // are carried through every edit (vcg_ext/irregular/attribute_transfer.h); what cannot be
  // carried (an edit across a texture seam or between two textures) is refused by that edit,
  // with the reason, not here for the whole mesh.
  irr::Result ok = irr::DiagnoseInput(m).Verdict();
  return ok ? std::string() : ok.reason;
}

std::string HistogramText(const std::map<int, int>& h) {
  std::string s;
  for (auto& kv : h) s += Format(" v%d:%d", kv.first, kv.second);
  return s;
}

irr::TopologySummary SummaryOf(CMeshO& m) { return irr::Summarize(m); }

void AddSummaryValues(FilterOutcome& out, const irr::TopologySummary& s, const std::string& suffix) {
  // Interior valence k counts as k; a boundary vertex as valence + 6 - its regular valence
  // (the boundary valence rule, topology.h), as in the legend, so "v5" means "one valence
  // short of regular" everywhere: valence 3 on a smooth stretch, 2 at a 120 degree corner.
  const std::map<int, int>& equivalent = s.equivalentHistogram;
  auto count = [&](int lo, int hi) {
    long long n = 0;
    for (auto& kv : equivalent)
      if (kv.first >= lo && kv.first <= hi) n += kv.second;
    return n;
  };
  out.SetInt("irregular" + suffix, s.irregular);
  out.SetInt("boundary_irregular" + suffix, s.boundaryIrregular);
  out.SetInt("v3" + suffix, count(0, 3));
  out.SetInt("v4" + suffix, count(4, 4));
  out.SetInt("v5" + suffix, count(5, 5));
  out.SetInt("v7" + suffix, count(7, 7));
  out.SetInt("v8" + suffix, count(8, 8));
  out.SetInt("v9" + suffix, count(9, 1 << 30));
  int top = 0;
  for (auto& kv : s.histogram) top = std::max(top, kv.first);
  std::vector<double> hist(size_t(top) + 1, 0.0);
  for (auto& kv : s.histogram) hist[size_t(kv.first)] = kv.second;
  out.SetVector("valence_histogram" + suffix, hist);
}

irr::TopologySummary PaintAndLog(FilterContext& ctx, bool colorize, int selectMode, int selectValence,
                                 bool writeQuality, int* selectedOut) {
  CMeshO& m = ctx.Mesh();
  irr::ValenceField<CMeshO> vf = irr::ComputeValences(m);
  ctx.Require((writeQuality ? kVertQuality : 0u) | (colorize ? kVertColor : 0u));
  irr::PaintValences(m, vf, colorize, writeQuality);
  const int selected = irr::SelectByValence(m, vf, irr::IrregularSelection(selectMode), selectValence);
  m.svn = selected;
  if (selectedOut) *selectedOut = selected;
  irr::TopologySummary s = irr::Summarize(m);
  ctx.Logf("Irregular vertices: %d of %d vertices (%.2f%%)", s.irregular, s.vertices,
           s.vertices ? 100.0 * s.irregular / s.vertices : 0.0);
  ctx.Logf("Valence histogram (interior):%s", HistogramText(s.histogram).c_str());
  if (!s.boundaryHistogram.empty()) {
    ctx.Logf("Valence histogram (boundary):%s", HistogramText(s.boundaryHistogram).c_str());
    ctx.Logf("Boundary: %d irregular vertices, %d corners (regular valence round(corner angle / 60) + 1: "
             "4 on a smooth stretch, 3 at 120 degrees)",
             s.boundaryIrregular, s.boundaryCorners);
  }
  ctx.Logf("Euler characteristic %d, genus %d, boundary loops %d, components %d (V %d, E %d, F %d)",
           s.eulerCharacteristic, s.genus, s.boundaryLoops, s.components, s.vertices, s.edges, s.faces);
  ctx.Logf("Gauss-Bonnet (eq. 2): sum of valence defects %d, 6 x chi = %d: %s", s.gaussBonnetSum,
           6 * s.eulerCharacteristic, s.GaussBonnetHolds() ? "holds" : "FAILS");
  if (selectMode != 0) ctx.Logf("Selected %d vertices", selected);
  return s;
}

void LogShape(FilterContext& ctx, const char* when, CMeshO& m) {
  irr::ShapeMeasures s = irr::MeasureShape(m);
  ctx.Logf("%s: min angle %.2f deg, mean min angle %.2f deg, %.2f%% of triangles under 30 deg, edge length spread %.3f",
           when, s.minAngleDeg, s.meanMinAngleDeg, 100.0 * s.shareBelow30, s.edgeLengthSpread);
}

struct EditRelaxation::Frozen {
  explicit Frozen(CMeshO& m) : surface(m), boundary(m) {}
  irr::SurfaceProjector surface;
  irr::BoundaryCurve boundary;
};

EditRelaxation::EditRelaxation(CMeshO& m, bool enabled) : m_(m) {
  if (enabled) frozen_.reset(new Frozen(m));
}

EditRelaxation::~EditRelaxation() = default;

const irr::SurfaceProjector* EditRelaxation::Surface() const { return frozen_ ? &frozen_->surface : nullptr; }

int EditRelaxation::Around(const std::vector<int>& seeds, int iterations) {
  if (!frozen_) return 0;
  std::vector<int> live;
  for (int v : seeds)
    if (v >= 0 && size_t(v) < m_.vert.size() && !m_.vert[size_t(v)].IsD()) live.push_back(v);
  if (live.empty()) return 0;
  irr::RelaxOptions ro;
  ro.iterations = iterations;
  ro.boundaryCurve = &frozen_->boundary;
  const std::vector<int> ring = irr::KRing(m_, live, 2);
  irr::AttributeResampler<CMeshO> texture(m_, ring);  // the texture stays where it was on the surface
  irr::LocalRelax(m_, ring, &frozen_->surface, ro);
  texture.Resample();
  return int(ring.size());
}

}  // namespace filter_irregular
