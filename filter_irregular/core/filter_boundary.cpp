// filter_irregular: "Irregular Vertices: Boundary Operation": the boundary operations of
// vcg_ext/irregular/boundary_ops.h on the selected vertices (absorb an interior v5/v7 or a 5-7
// pair into the boundary, move a boundary v3 along it, generate a 5-7 pair from it, move a
// boundary 5-7 pair along it, generate two boundary pairs).
#include <algorithm>
#include <memory>

#include "filter_common.h"
#include "filters.h"

#include <vcg_ext/irregular/boundary_ops.h>
#include <vcg_ext/irregular/relaxation.h>

namespace irr = vcg_ext::irregular;

namespace filter_irregular {

FilterOutcome ApplyBoundary(FilterContext& ctx, const ParamValues& par) {
  CMeshO& m = ctx.Mesh();
  const std::string defect = InputDefect(m);
  if (!defect.empty()) return FilterOutcome::Refuse(defect);
  const int op = par.Enum("operation");
  const int side = par.Enum("side");
  const bool relax = par.Bool("relax");
  const std::vector<int> sel = SelectedVertices(m);
  const irr::TopologySummary before = SummaryOf(m);
  if (before.boundaryLoops == 0) return FilterOutcome::Refuse("The mesh has no boundary: there is nothing to absorb into.");
  EditRelaxation relaxation(m, relax);  // before editing: freezes the surface as it was
  irr::MeshEditor<CMeshO> ed(m);
  irr::BoundaryOperations<CMeshO> ops(ed);
  irr::BoundaryOutcome out;
  switch (op) {
    case 0:  // absorb
      if (sel.size() == 1) {
        out = ops.Absorb(sel[0]);
      } else if (sel.size() == 2) {
        out = ops.AbsorbPair(sel[0], sel[1]);
      } else {
        return FilterOutcome::Refuse(Format("Absorbing into the boundary needs one selected interior v5 or v7, or the "
                                            "two vertices of a 5-7 pair; %zu are selected.",
                                            sel.size()));
      }
      break;
    case 1:
      if (sel.size() != 1)
        return FilterOutcome::Refuse(Format("Moving along the boundary needs exactly one selected boundary vertex of "
                                            "valence 3; %zu are selected.",
                                            sel.size()));
      out = ops.MoveAlongBoundary(sel[0], side);
      break;
    case 2:
      if (sel.size() != 1)
        return FilterOutcome::Refuse(Format("Generating a pair from the boundary needs exactly one selected boundary "
                                            "vertex of valence 4; %zu are selected.",
                                            sel.size()));
      out = ops.GeneratePair(sel[0], side);
      break;
    case 3:
    case 4: {
      irr::BoundaryPairOutcome po;
      if (op == 3) {
        if (sel.size() != 2)
          return FilterOutcome::Refuse(Format("Moving a boundary 5-7 pair needs its two boundary vertices (valences 3 "
                                              "and 5, joined by a boundary edge) selected; %zu are selected.",
                                              sel.size()));
        po = ops.MoveBoundaryPair(sel[0], sel[1],
                                  par.Enum("pairDirection") == 0 ? irr::BoundaryPairDirection::TowardThree
                                                                 : irr::BoundaryPairDirection::TowardFive,
                                  par.Int("steps"));
      } else {
        if (sel.size() != 1)
          return FilterOutcome::Refuse(Format("Generating two boundary pairs needs exactly one selected boundary "
                                              "vertex of valence 4; %zu are selected.",
                                              sel.size()));
        po = ops.GenerateBoundaryPairs(sel[0]);
      }
      out.result = po.result;
      out.description = po.description;
      out.changes = po.changes;
      break;
    }
    default: return FilterOutcome::Refuse("Unknown operation.");
  }
  if (!out) return FilterOutcome::Refuse(out.result.reason);
  // Select what is irregular among the touched vertices.
  for (auto& v : m.vert) v.ClearS();
  int relaxed = 0;
  std::vector<int> touched;
  for (auto& kv : out.changes)
    if (ed.IsLive(kv.first)) touched.push_back(kv.first);
  for (int v : touched) {
    irr::VertexStar<CMeshO> st = ed.Star(v);
    if (st.Valence() != irr::RegularValenceOf(st)) m.vert[size_t(v)].SetS();
  }
  if (relax && !touched.empty()) {
    relaxed = relaxation.Around(touched);
  }
  FinishEdit(m);
  ctx.Logf("Boundary operation: %s", out.description.c_str());
  const bool colorize = par.Bool("colorize");
  const irr::TopologySummary after = PaintAndLog(ctx, colorize, 0, 0, colorize);
  FilterOutcome result;
  AddSummaryValues(result, before, "_before");
  AddSummaryValues(result, after, "_after");
  result.SetInt("changed_vertices", (long long)out.changes.size());
  result.SetInt("relaxed_vertices", relaxed);
  result.SetInt("interior_irregular_before", before.irregular - before.boundaryIrregular);
  result.SetInt("interior_irregular_after", after.irregular - after.boundaryIrregular);
  result.SetInt("selected", (long long)SelectedVertices(m).size());
  return result;
}

}  // namespace filter_irregular
