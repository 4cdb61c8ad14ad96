// filter_irregular: the filters' ids and apply functions (one file each under core/), listed
// with their names and parameters in filter_catalog.cpp.
#pragma once

#include "filter_spec.h"

namespace filter_irregular {

/// Filter ids: stable, they are the QAction ids of both adapters.
enum FilterId {
  kAnalyze,
  kAtomic,
  kRelax,
  kReduce,
  kAggregate,
  kMovePair,
  kCancelTriple,
  kCancelQuadruple,
  kGenerate,
  kAutomaticReduction,
  kBoundary,  // appended: ids above keep their values
  kPattern,
};

FilterOutcome ApplyAnalyze(FilterContext& ctx, const ParamValues& par);             // filter_analyze.cpp
FilterOutcome ApplyAtomic(FilterContext& ctx, const ParamValues& par);              // filter_atomic.cpp
FilterOutcome ApplyRelax(FilterContext& ctx, const ParamValues& par);               // filter_relax.cpp
FilterOutcome ApplyReduce(FilterContext& ctx, const ParamValues& par);              // filter_composite.cpp
FilterOutcome ApplyAggregate(FilterContext& ctx, const ParamValues& par);           // filter_composite.cpp
FilterOutcome ApplyMovePair(FilterContext& ctx, const ParamValues& par);            // filter_composite.cpp
FilterOutcome ApplyCancelTriple(FilterContext& ctx, const ParamValues& par);        // filter_composite.cpp
FilterOutcome ApplyCancelQuadruple(FilterContext& ctx, const ParamValues& par);     // filter_composite.cpp
FilterOutcome ApplyGenerate(FilterContext& ctx, const ParamValues& par);            // filter_composite.cpp
FilterOutcome ApplyAutomaticReduction(FilterContext& ctx, const ParamValues& par);  // filter_automatic_reduction.cpp
FilterOutcome ApplyBoundary(FilterContext& ctx, const ParamValues& par);            // filter_boundary.cpp
FilterOutcome ApplyPattern(FilterContext& ctx, const ParamValues& par);             // filter_pattern.cpp

}  // namespace filter_irregular
