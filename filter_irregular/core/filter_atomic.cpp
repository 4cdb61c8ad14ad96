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

namespace {

/// The vertex a single-vertex operation acts on, and the reference neighbour that names
/// direction 0: one selected vertex (reference: none, i.e. the projected +X axis), or two
/// adjacent ones, the vertex being the one of the valence the operation needs (5 or 7 for a
/// move, 6 for a generation) and the other the reference; if both have it, the lower index is
/// the vertex. Returns why the selection does not fit, or "".
std::string VertexAndReference(irr::MeshEditor<CMeshO>& ed, const std::vector<int>& sel, const char* what, bool move,
                               int& p, int& ref) {
  if (sel.size() == 1) {
    p = sel[0];
    ref = -1;
    return "";
  }
  if (sel.size() != 2)
    return Format("%s needs one selected vertex, or that vertex and one of its neighbours (the reference edge of "
                  "direction 0); %zu are selected.", what, sel.size());
  const int a = std::min(sel[0], sel[1]), b = std::max(sel[0], sel[1]);
  if (!ed.Adjacent(a, b))
    return Format("%s with two selected vertices needs them adjacent: the second one names the reference edge; "
                  "vertices %d and %d are not adjacent.", what, a, b);
  auto fits = [&](int v) {
    const int d = ed.Valence(v);
    return move ? (d == 5 || d == 7) : d == 6;
  };
  p = fits(a) || !fits(b) ? a : b;
  ref = p == a ? b : a;
  return "";
}

}  // namespace

FilterOutcome ApplyAtomic(FilterContext& ctx, const ParamValues& par) {
  CMeshO& m = ctx.Mesh();
  const std::string defect = InputDefect(m);
  if (!defect.empty()) return FilterOutcome::Refuse(defect);
  const int op = par.Enum("operation");
  const int dir = par.Int("direction");
  const bool relax = par.Bool("relax");
  const bool toward = par.Bool("towardPoint");
  const vcg::Point3d tp = par.Point("point");
  const CMeshO::CoordType target(tp[0], tp[1], tp[2]);
  std::vector<int> sel = SelectedVertices(m);
  const irr::TopologySummary before = SummaryOf(m);
  EditRelaxation relaxation(m, relax);  // before editing: freezes the surface as it was
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
  const bool graphOp = op >= 6 && op <= 8;
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
      int d = dir;
      if (toward) {
        d = ed.IsLive(a) && ed.IsLive(b) && ed.Valence(a) == 5 && ed.Valence(b) == 7 && ed.Adjacent(a, b)
                ? ops.PairDirectionToward(a, b, target)
                : 0;  // not a pair: MovePair57 says why
        if (d < 0) return FilterOutcome::Refuse("No move of this 5-7 pair is possible (every direction is blocked).");
      }
      out = ops.MovePair57(a, b, d);
      break;
    }
    case 1: {
      int p = -1, ref = -1;
      std::string why = VertexAndReference(ed, sel, "A move with 5-7 pair generation", true, p, ref);
      if (!why.empty()) return FilterOutcome::Refuse(why);
      const int sector = toward ? ops.SectorToward(p, target, ref) : dir;
      out = ops.MoveVertexWithPairGeneration(p, sector, ref, irr::AtomicVia(par.Enum("via")),
                                             irr::PairSide(par.Enum("pairSide")));
      break;
    }
    case 2:
      if (sel.size() == 2 && valences(sel) == std::vector<int>{5, 7})
        return FilterOutcome::Refuse(irr::ImpossibilityCheck<CMeshO>(m).PairCancellation(sel[0], sel[1]).message);
      if (!need(3, "A triple cancellation")) return FilterOutcome::Refuse(wrongCount);
      out = ops.MoveWithPairRemoval(sel);
      break;
    case 3:
    case 4:
    case 9: {
      int p = -1, ref = -1;
      std::string why = VertexAndReference(ed, sel, "A 5-5-7-7 generation", false, p, ref);
      if (!why.empty()) return FilterOutcome::Refuse(why);
      const int sector = toward ? ops.SectorToward(p, target, ref) : dir;
      typedef irr::AtomicOperations<CMeshO>::QuadrupleVia QV;
      out = ops.GenerateQuadrupleInSector(p, sector, op == 3 ? QV::Flip : op == 4 ? QV::Split : QV::CollapseSplit, ref);
      break;
    }
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
      if (kv.second > 0 && kv.second != irr::RegularValenceOf(ed.Star(kv.first))) out.irregular.push_back(kv.first);
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
    relaxed = relaxation.Around(seeds);
  }
  std::string changes;
  for (auto& kv : out.changes) changes += Format(" %d:%d", kv.first, kv.second);
  FinishEdit(m);
  ctx.Logf("Atomic operation: %s", out.description.c_str());
  if (out.moved >= 0 || out.pair5 >= 0)
    ctx.Logf("Moved vertex %d, 5-7 pair (v5 %d, v7 %d), by vertex index before compaction", out.moved, out.pair5,
             out.pair7);
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
