// filter_irregular: "Irregular Vertices: Atomic Operation": one graph or atomic operation of
// sec. 6.1-6.2 on the selected vertices (vcg_ext/irregular/atomic_ops.h, graph_ops.h).
#include <algorithm>
#include <memory>

#include "filter_common.h"
#include "filters.h"

#include <vcg_ext/irregular/atomic_ops.h>
#include <vcg_ext/irregular/impossibility.h>
#include <vcg_ext/irregular/relaxation.h>

namespace irr = vcg_ext::irregular;

namespace filter_irregular {

FilterOutcome ApplyAtomic(FilterContext& ctx, const ParamValues& par) {
  CMeshO& m = ctx.Mesh();
  const std::string defect = InputDefect(m);
  if (!defect.empty()) return FilterOutcome::Refuse(defect);
  const int op = par.Enum("operation");
  const int dir = par.Int("direction");
  const bool relax = par.Bool("relax");
  std::vector<int> sel = SelectedVertices(m);
  const irr::TopologySummary before = SummaryOf(m);
  std::unique_ptr<irr::SurfaceProjector> projector;
  if (relax) projector.reset(new irr::SurfaceProjector(m));
  irr::MeshEditor<CMeshO> ed(m);
  irr::AtomicOperations<CMeshO> ops(ed);
  auto valences = [&](const std::vector<int>& vs) {
    std::vector<int> d;
    for (int v : vs) d.push_back(ed.Valence(v));
    std::sort(d.begin(), d.end());
    return d;
  };
  std::string wrongCount;
  auto need = [&](size_t n, const char* what) -> bool {
    if (sel.size() == n) return true;
    static const char* words[] = {"no", "one", "two", "three", "four"};
    wrongCount = Format("%s needs exactly %zu selected vertices (%s); %zu are selected.", what, n, words[n], sel.size());
    return false;
  };
  // A graph operation (flip, collapse, split) states no valence changes of its own: they all
  // lie in the selection's 1-ring (plus a split's new vertex), measured before and after.
  const bool graphOp = op >= 6;
  std::vector<std::pair<int, int>> ringBefore;
  if (graphOp)
    for (int v : irr::KRing(m, sel, 1)) ringBefore.emplace_back(v, ed.Valence(v));
  int created = -1;
  irr::AtomicOutcome out;
  switch (op) {
    case 0: {  // 5-7 pair move
      if (sel.size() == 1 && (ed.Valence(sel[0]) == 5 || ed.Valence(sel[0]) == 7))
        return FilterOutcome::Refuse(irr::ImpossibilityCheck<CMeshO>(m).SingleVertexMove(sel[0]).message);
      if (!need(2, "A 5-7 pair move")) return FilterOutcome::Refuse(wrongCount);
      int a = sel[0], b = sel[1];
      if (ed.Valence(a) == 7) std::swap(a, b);
      out = ops.MovePair57(a, b, dir);
      break;
    }
    case 1:
      if (!need(1, "A move with 5-7 pair generation")) return FilterOutcome::Refuse(wrongCount);
      out = ops.MoveWithPairGeneration(sel[0], dir);
      break;
    case 2:
      if (sel.size() == 2 && valences(sel) == std::vector<int>{5, 7})
        return FilterOutcome::Refuse(irr::ImpossibilityCheck<CMeshO>(m).PairCancellation(sel[0], sel[1]).message);
      if (!need(3, "A triple cancellation")) return FilterOutcome::Refuse(wrongCount);
      out = ops.MoveWithPairRemoval(sel);
      break;
    case 3:
    case 4:
      if (!need(1, "A 5-5-7-7 generation")) return FilterOutcome::Refuse(wrongCount);
      out = ops.GenerateQuadruple(sel[0], dir, op == 4);
      break;
    case 5:
      if (sel.size() == 2 && valences(sel) == std::vector<int>{5, 7})
        return FilterOutcome::Refuse(irr::ImpossibilityCheck<CMeshO>(m).PairCancellation(sel[0], sel[1]).message);
      if (!need(4, "A 5-5-7-7 removal")) return FilterOutcome::Refuse(wrongCount);
      out = ops.RemoveQuadruple(sel);
      break;
    case 6:
      if (!need(2, "An edge flip")) return FilterOutcome::Refuse(wrongCount);
      out.result = ed.Flip(sel[0], sel[1]);
      out.description = Format("flip edge (%d, %d)", sel[0], sel[1]);
      break;
    case 7:
      if (!need(2, "An edge collapse")) return FilterOutcome::Refuse(wrongCount);
      out.result = ed.Collapse(sel[1], sel[0]);
      out.description = Format("collapse vertex %d into %d", sel[1], sel[0]);
      break;
    case 8: {
      if (!need(3, "A vertex split")) return FilterOutcome::Refuse(wrongCount);
      // the split vertex is the one adjacent to the other two
      std::vector<int> centre;
      for (int i = 0; i < 3; ++i)
        if (ed.Adjacent(sel[i], sel[(i + 1) % 3]) && ed.Adjacent(sel[i], sel[(i + 2) % 3])) centre.push_back(i);
      if (centre.size() != 1)
        return FilterOutcome::Refuse(centre.empty()
                                         ? "A vertex split needs a vertex and two of its neighbours."
                                         : "Ambiguous vertex split: the three selected vertices form a triangle; select "
                                           "two neighbours of the split vertex that are not adjacent to each other.");
      const int c = centre[0];
      out.result = ed.Split(sel[c], sel[(c + 1) % 3], sel[(c + 2) % 3], &created);
      out.description =
          Format("split vertex %d along edges to %d and %d", sel[c], sel[(c + 1) % 3], sel[(c + 2) % 3]);
      break;
    }
    default: return FilterOutcome::Refuse("Unknown operation.");
  }
  if (!out.result) return FilterOutcome::Refuse(out.result.reason);
  if (graphOp) {
    for (auto& vd : ringBefore) {
      const int now = ed.IsLive(vd.first) ? ed.Valence(vd.first) : 0;  // deleted: 0, as AtomicOutcome
      if (now != vd.second) out.changes[vd.first] = now;
    }
    if (created >= 0) out.changes[created] = ed.Valence(created);
    for (auto& kv : out.changes)
      if (kv.second > 0 && kv.second != (ed.IsBoundary(kv.first) ? 4 : 6)) out.irregular.push_back(kv.first);
  }
  // Re-select what the operation produced (irregular vertices it reports, or the touched ones).
  std::vector<int> keep = out.irregular;
  if (keep.empty())
    for (int v : sel)
      if (ed.IsLive(v)) keep.push_back(v);
  for (auto& v : m.vert) v.ClearS();
  for (int v : keep)
    if (ed.IsLive(v)) m.vert[size_t(v)].SetS();
  int relaxed = 0;
  if (relax) {
    std::vector<int> seeds;
    for (auto& kv : out.changes)
      if (ed.IsLive(kv.first)) seeds.push_back(kv.first);
    irr::RelaxOptions ro;
    ro.iterations = 5;
    const std::vector<int> ring = irr::KRing(m, seeds, 2);
    relaxed = int(ring.size());
    irr::LocalRelax(m, ring, projector.get(), ro);
  }
  std::string changes;
  for (auto& kv : out.changes) changes += Format(" %d:%d", kv.first, kv.second);
  FinishEdit(m);
  ctx.Logf("Atomic operation: %s", out.description.c_str());
  if (!changes.empty()) ctx.Logf("Valence after, by vertex index before compaction:%s", changes.c_str());
  const bool colorize = par.Bool("colorize");
  const irr::TopologySummary after = PaintAndLog(ctx, colorize, 0, 0, colorize);
  FilterOutcome result;
  AddSummaryValues(result, before, "_before");
  AddSummaryValues(result, after, "_after");
  result.SetInt("changed_vertices", (long long)out.changes.size());
  result.SetInt("relaxed_vertices", relaxed);
  result.SetInt("selected", (long long)SelectedVertices(m).size());
  return result;
}

}  // namespace filter_irregular
