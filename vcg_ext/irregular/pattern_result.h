// filter_irregular: what a surface pattern is (paper sec. 9-10, Figs. 1, 12-14): pattern ids on
// faces, computed from the triangulation's own structure, and the measures a designer compares.
//
// Every pattern (stripe_pattern.h, star_pattern.h, circle_pattern.h) fills a PatternLabels; the
// panels (pattern_panels.h) and the Pattern filter only read it. A region is a set of faces
// with one pattern id; its kind says what it is. Conflict regions are where the pattern cannot
// be made consistent (around irregular vertices, odd cycles of strips): their size is what the
// irregular vertices cost the design.
#pragma once

#include <string>
#include <vector>

namespace vcg_ext {
namespace irregular {

enum class RegionKind {
  StripeA = 0,     ///< a strip of the stripe/zebra pattern, first colour of the alternation
  StripeB = 1,     ///< a strip, second colour
  Cell = 2,        ///< a cell between strips, or a lattice cell (hexagon, pentagon, ...)
  Star = 3,        ///< a star seeded at a vertex
  Circle = 4,      ///< a circle (ring of faces) of the circle pattern
  Conflict = 5,    ///< faces where the pattern is inconsistent (degenerate region)
  Background = 6,  ///< faces no pattern element covers
};

inline const char* RegionKindName(RegionKind k) {
  switch (k) {
    case RegionKind::StripeA: return "stripe A";
    case RegionKind::StripeB: return "stripe B";
    case RegionKind::Cell: return "cell";
    case RegionKind::Star: return "star";
    case RegionKind::Circle: return "circle";
    case RegionKind::Conflict: return "conflict";
    case RegionKind::Background: return "background";
  }
  return "?";
}

/// The measures of sec. 10's comparison (Fig. 1: strips of width one and two, the shapes
/// between strips), logged and returned by the Pattern filter. Zero where a pattern does not
/// define them.
struct PatternMeasures {
  int strips = 0;                       ///< number of strip regions
  std::vector<int> stripWidthHistogram; ///< [w] = number of strips of width w (index 0 unused)
  int cells = 0;                        ///< number of Cell regions
  int nonHexagonalCells = 0;            ///< cells whose polygon does not have 6 sides
  std::vector<int> cellSidesHistogram;  ///< [s] = number of cells whose polygon has s sides
  int conflictRegions = 0;              ///< connected Conflict regions
  int conflictFaces = 0;                ///< faces in Conflict regions (degenerate regions)
  int starSeeds = 0;                    ///< stars: seeds used
  int isolatedStarSeeds = 0;            ///< stars: seeds with no other irregular vertex within the radius
  int circles = 0;                      ///< circles: closed rings of faces
};

/// The pattern: a region id per face (index = face index in m.face; -1 for deleted faces),
/// the kind of each region, and the measures. Region ids are dense: 0 .. regionKind.size()-1.
struct PatternLabels {
  bool ok = true;
  std::string reason;  ///< why the pattern could not be made (bad seed, empty mesh, ...)
  std::vector<int> faceRegion;
  std::vector<RegionKind> regionKind;
  PatternMeasures measures;

  static PatternLabels Fail(std::string why) {
    PatternLabels p;
    p.ok = false;
    p.reason = std::move(why);
    return p;
  }
};

}  // namespace irregular
}  // namespace vcg_ext
