// filter_irregular: "Irregular Vertices: Pattern": the paper's application (sec. 9-10, Figs. 1,
// 12-14): pattern ids on faces (stripes, zebra, stars, circles) written as face colour and face
// quality, the measures a designer compares before and after editing, and optionally the panels
// (geometry replacement) in a new layer.
#include <algorithm>

#include "filter_common.h"
#include "filters.h"

#include <vcg_ext/irregular/circle_pattern.h>
#include <vcg_ext/irregular/pattern_panels.h>
#include <vcg_ext/irregular/star_pattern.h>
#include <vcg_ext/irregular/stripe_pattern.h>

namespace filter_irregular {

namespace irr = vcg_ext::irregular;

namespace {

enum PatternChoice { kStripes = 0, kZebra = 1, kStars = 2, kCircles = 3 };

/// The colour of a region: a hue per kind, four shades by region id so that neighbouring
/// regions of one kind differ; conflicts in a loud magenta.
vcg::Color4b RegionColor(irr::RegionKind k, int region) {
  static const unsigned char shade[4] = {255, 205, 160, 120};
  const int s = shade[region & 3];
  auto scaled = [&](int r, int g, int b) {
    return vcg::Color4b((unsigned char)(r * s / 255), (unsigned char)(g * s / 255), (unsigned char)(b * s / 255), 255);
  };
  switch (k) {
    case irr::RegionKind::StripeA: return scaled(40, 70, 190);    // blue
    case irr::RegionKind::StripeB: return scaled(245, 215, 110);  // sand
    case irr::RegionKind::Cell: return scaled(90, 190, 90);       // green
    case irr::RegionKind::Star: return scaled(235, 120, 30);      // orange
    case irr::RegionKind::Circle: return scaled(60, 180, 200);    // teal
    case irr::RegionKind::Conflict: return vcg::Color4b(255, 0, 255, 255);
    case irr::RegionKind::Background: return vcg::Color4b(170, 170, 170, 255);
  }
  return vcg::Color4b(0, 0, 0, 255);
}

std::vector<double> AsVector(const std::vector<int>& h) { return std::vector<double>(h.begin(), h.end()); }

std::string HistText(const std::vector<int>& h) {
  std::string s;
  for (size_t i = 0; i < h.size(); ++i)
    if (h[i]) s += Format(" %zu:%d", i, h[i]);
  return s.empty() ? " none" : s;
}

}  // namespace

FilterOutcome ApplyPattern(FilterContext& ctx, const ParamValues& par) {
  CMeshO& m = ctx.Mesh();
  const std::string defect = InputDefect(m);
  if (!defect.empty()) return FilterOutcome::Refuse(defect);
  const int choice = par.Enum("pattern");
  irr::PatternLabels labels;
  int seedFace = -1;
  if (choice == kStripes || choice == kZebra) {
    irr::StripeOptions opt;
    opt.direction = par.Int("direction");
    opt.period = par.Int("period");
    // the seed: the selected face, else the selected vertex, else face 0 (lowest index first)
    int selFaces = 0, selVerts = 0, firstFace = -1, firstVert = -1;
    for (size_t i = 0; i < m.face.size(); ++i)
      if (!m.face[i].IsD() && m.face[i].IsS() && selFaces++ == 0) firstFace = int(i);
    for (size_t i = 0; i < m.vert.size(); ++i)
      if (!m.vert[i].IsD() && m.vert[i].IsS() && selVerts++ == 0) firstVert = int(i);
    if (firstFace >= 0) {
      opt.seedFace = firstFace;
      ctx.Logf("Seed: the selected face %d%s", firstFace,
               selFaces > 1 ? Format(" (the first of %d selected faces)", selFaces).c_str() : "");
    } else if (firstVert >= 0) {
      opt.seedVertex = firstVert;
      ctx.Logf("Seed: the selected vertex %d%s (its first face)", firstVert,
               selVerts > 1 ? Format(", the first of %d selected vertices", selVerts).c_str() : "");
    } else {
      ctx.Logf("Seed: face 0 (no face or vertex selected)");
    }
    std::string why;
    seedFace = irr::StripeSeedFace(m, opt, &why);
    if (seedFace < 0) return FilterOutcome::Refuse("Cannot seed the pattern: " + why + ".");
    opt.seedFace = seedFace;
    labels = choice == kStripes ? irr::ComputeStripes(m, opt) : irr::ComputeZebra(m, opt);
  } else if (choice == kStars) {
    irr::StarOptions opt;
    opt.radius = par.Int("starRadius");
    opt.seeds = SelectedVertices(m);
    ctx.Logf(opt.seeds.empty() ? "Star seeds: every interior v5 (no vertex selected)"
                               : "Star seeds: the %zu selected vertices",
             opt.seeds.size());
    labels = irr::ComputeStars(m, opt);
  } else {
    irr::CircleOptions opt;
    opt.ringWidth = par.Int("ringWidth");
    labels = irr::ComputeCircles(m, opt);
  }
  if (!labels.ok) return FilterOutcome::Refuse("The pattern cannot be made: " + labels.reason + ".");
  if (labels.faceRegion.size() != m.face.size())
    return FilterOutcome::Refuse("Internal error: the pattern does not label every face (please report it).");

  irr::PanelReport panels;
  if (par.Bool("panels")) {
    CMeshO* layer = ctx.NewLayer("panels");
    if (layer == nullptr)
      return FilterOutcome::Refuse("Panels need a new layer, and this MeshLab cannot add one here; run again with "
                                   "'Panels' off.");
    irr::PanelOptions popt;
    popt.inset = par.Float("panelInset");
    popt.extrude = par.Float("panelExtrusion");
    // the colours m gets below (m is only painted once nothing can be refused any more)
    for (size_t r = 0; r < labels.regionKind.size(); ++r)
      popt.regionColors.push_back(RegionColor(labels.regionKind[r], int(r)));
    panels = irr::BuildPanels(m, labels, popt, *layer);
    if (!panels.ok) return FilterOutcome::Refuse("The panels cannot be made: " + panels.reason + ".");
  }

  // writes: face colour and quality only (no geometry, no connectivity)
  ctx.Require(kFaceColor | kFaceQuality);
  for (size_t i = 0; i < m.face.size(); ++i) {
    if (m.face[i].IsD()) continue;
    const int r = labels.faceRegion[i];
    const irr::RegionKind k = r >= 0 ? labels.regionKind[size_t(r)] : irr::RegionKind::Background;
    m.face[i].C() = RegionColor(k, r);
    m.face[i].Q() = r;
  }

  const irr::PatternMeasures& s = labels.measures;
  auto widthCount = [&](int lo, int hi) {
    int n = 0;
    for (size_t w = 0; w < s.stripWidthHistogram.size(); ++w)
      if (int(w) >= lo && int(w) <= hi) n += s.stripWidthHistogram[w];
    return n;
  };
  static const char* names[] = {"Stripes", "Zebra", "Stars", "Circles"};
  ctx.Logf("Pattern %s: %zu regions", names[choice], labels.regionKind.size());
  if (choice == kStripes || choice == kZebra) {
    ctx.Logf("Strips: %d; width histogram:%s", s.strips, HistText(s.stripWidthHistogram).c_str());
    ctx.Logf("Lattice cells: %d, %d not hexagonal; sides histogram:%s", s.cells, s.nonHexagonalCells,
             HistText(s.cellSidesHistogram).c_str());
    ctx.Logf("Conflict (degenerate) regions: %d, %d faces", s.conflictRegions, s.conflictFaces);
  }
  if (choice == kStars) ctx.Logf("Stars: %d seeds, %d isolated", s.starSeeds, s.isolatedStarSeeds);
  if (choice == kCircles) ctx.Logf("Circles: %d", s.circles);
  if (par.Bool("panels"))
    ctx.Logf("Panels: %d in the new layer 'panels'; sides histogram:%s", panels.panels,
             HistText(panels.panelSidesHistogram).c_str());

  FilterOutcome out;
  out.SetInt("regions", (long long)labels.regionKind.size());
  out.SetInt("seed_face", seedFace);
  out.SetInt("strips", s.strips);
  out.SetInt("strip_width_1", widthCount(1, 1));
  out.SetInt("strip_width_2", widthCount(2, 2));
  out.SetInt("strip_width_3_or_more", widthCount(3, 1 << 30));
  out.SetInt("cells", s.cells);
  out.SetInt("non_hexagonal_cells", s.nonHexagonalCells);
  out.SetInt("conflict_regions", s.conflictRegions);
  out.SetInt("conflict_faces", s.conflictFaces);
  out.SetInt("star_seeds", s.starSeeds);
  out.SetInt("isolated_star_seeds", s.isolatedStarSeeds);
  out.SetInt("circles", s.circles);
  out.SetInt("panels", panels.panels);
  // vectors last, the long one at the end: meshlabserver's log cuts lines at 4095 characters
  out.SetVector("cell_sides_histogram", AsVector(s.cellSidesHistogram));
  out.SetVector("panel_sides_histogram", AsVector(panels.panelSidesHistogram));
  out.SetVector("strip_width_histogram", AsVector(s.stripWidthHistogram));
  return out;
}

}  // namespace filter_irregular
