// filter_irregular: the composite filters (sec. 6.3 and 7, vcg_ext/irregular/composite_ops.h):
// Reduce to Valence 5 and 7, Aggregate, Move Pair, Cancel Triple, Cancel Quadruple, Generate.
// They share one frame (RunComposite): input check, the relaxation frozen before the edit (EditRelaxation), all-or-nothing
// edit, re-selection of the resulting irregular vertices, legend, output values.
#include <algorithm>
#include <memory>

#include "filter_common.h"
#include "filters.h"

#include <vcg_ext/irregular/composite_ops.h>
#include <vcg_ext/irregular/impossibility.h>

namespace irr = vcg_ext::irregular;

namespace filter_irregular {

namespace {

typedef irr::CompositeOperations<CMeshO> Ops;

/// What a composite filter's body sees.
struct CompositeFrame {
  CMeshO& m;
  irr::MeshEditor<CMeshO>& ed;
  Ops& ops;
  const std::vector<int>& sel;
  FilterContext& ctx;
  FilterOutcome extra;  ///< output values of the body (besides the common ones)

  std::vector<int> Valences(const std::vector<int>& vs) const {
    std::vector<int> d;
    for (int v : vs) d.push_back(ed.Valence(v));
    std::sort(d.begin(), d.end());
    return d;
  }
  /// Two selected vertices of opposite curvature (valences adding up to 12: 5-7, 4-8, 3-9).
  bool IsOppositePair() const {
    if (sel.size() != 2) return false;
    const std::vector<int> d = Valences(sel);
    return d[0] + d[1] == 12 && d[0] != 6;
  }
  /// Theorem 5.5 decided on its condition (impossibility.h): the theorem, or the triple
  /// cancellation that a nearby third vertex makes possible.
  std::string PairCancellationAnswer() const {
    irr::ImpossibilityCheck<CMeshO> check(m);
    return check.PairCancellation(sel[0], sel[1]).message;
  }
  /// Empty if `n` vertices are selected, else the refusal.
  std::string NeedCount(size_t n, const char* what) const {
    if (sel.size() == n) return std::string();
    return Format("%s needs exactly %zu selected vertices; %zu are selected.", what, n, sel.size());
  }
};

irr::CompositeOutcome Refused(const std::string& why) {
  irr::CompositeOutcome o;
  o.result = irr::Result::Fail(why);
  return o;
}

template <class Body>
FilterOutcome RunComposite(FilterContext& ctx, const ParamValues& par, const char* what, Body body) {
  CMeshO& m = ctx.Mesh();
  const std::string defect = InputDefect(m);
  if (!defect.empty()) return FilterOutcome::Refuse(defect);
  std::vector<int> sel = SelectedVertices(m);
  const irr::TopologySummary before = SummaryOf(m);
  const bool relax = par.Bool("relax");
  EditRelaxation relaxation(m, relax);  // before editing: freezes the surface as it was
  irr::MeshEditor<CMeshO> ed(m);
  irr::CompositeOptions co;
  co.relax = relax;
  if (auto cb = ctx.Progress()) co.progress = [cb](int pct, const char* text) { cb(pct, text); };
  Ops ops(ed, relaxation.Surface(), co);
  CompositeFrame frame{m, ed, ops, sel, ctx, FilterOutcome()};
  irr::CompositeOutcome out = body(frame);
  if (!out.result) return FilterOutcome::Refuse(out.result.reason);
  // Select what the operation leaves irregular: a vertex one step made irregular may have been
  // made regular by a later one (Reduce reduces the ends of its own splits).
  for (auto& v : m.vert) v.ClearS();
  for (int v : out.irregular)
    if (ed.IsLive(v) && ed.Valence(v) != irr::RegularValenceOf(ed.Star(v))) m.vert[size_t(v)].SetS();
  FinishEdit(m);
  ctx.Logf("%s: %d atomic steps", what, out.atomicSteps);
  if (!out.log.empty() && out.atomicSteps <= 50) ctx.Logf("Steps:\n%s", out.log.c_str());
  const bool colorize = par.Bool("colorize");
  const irr::TopologySummary after = PaintAndLog(ctx, colorize, 0, 0, colorize);
  FilterOutcome result;
  AddSummaryValues(result, before, "_before");
  AddSummaryValues(result, after, "_after");
  result.SetInt("atomic_steps", out.atomicSteps);
  result.SetInt("selected", (long long)SelectedVertices(m).size());
  for (auto& kv : frame.extra.values) result.values.push_back(kv);
  return result;
}

}  // namespace

FilterOutcome ApplyReduce(FilterContext& ctx, const ParamValues& par) {
  const bool selectedOnly = par.Enum("scope") == 1;
  return RunComposite(ctx, par, "Irregular Vertices: Reduce to Valence 5 and 7", [&](CompositeFrame& f) {
    CMeshO& m = f.m;
    std::vector<int> todo;
    irr::ValenceField<CMeshO> vf = irr::ComputeValences(m);
    for (size_t i = 0; i < m.vert.size(); ++i) {
      if (m.vert[i].IsD() || !vf.referenced[i] || vf.boundary[i]) continue;
      if (vf.valence[i] >= 5 && vf.valence[i] <= 7) continue;
      if (selectedOnly && !m.vert[i].IsS()) continue;
      todo.push_back(int(i));
    }
    if (todo.empty()) return Refused("There is no interior vertex of valence other than 5, 6 and 7 to reduce.");
    irr::CompositeOutcome out;
    int reduced = 0, notReduced = 0;
    std::string failed;
    const size_t initial = todo.size();
    auto cb = f.ctx.Progress();
    for (size_t t = 0; t < todo.size(); ++t) {
      if (cb && t % 64 == 0) cb(int(100 * std::min(t, initial) / initial), "Reducing to valence 5 and 7");
      if (!f.ed.IsLive(todo[t])) continue;
      const int d = f.ed.Valence(todo[t]);
      if (d >= 5 && d <= 7) continue;
      // type_change.h: the vertex becomes v7s (v5s) only; no other irregular vertex changes,
      // unless no orientation allows it, then a neighbouring v5 (v7) may be absorbed
      irr::CompositeOutcome r = f.ops.ReduceTo57(todo[t]);
      if (r) {
        ++reduced;
        out.atomicSteps += r.atomicSteps;
        out.irregular.insert(out.irregular.end(), r.irregular.begin(), r.irregular.end());
      } else {
        if (notReduced < 10) failed += Format("%s%d: %s", failed.empty() ? "" : "; ", todo[t], r.result.reason.c_str());
        if (notReduced == 10) failed += "; ...";
        ++notReduced;
      }
      f.ed.Commit();
    }
    if (reduced == 0) return Refused("No vertex could be reduced. " + failed);
    f.ctx.Logf("Reduced %d vertices to valence 5 and 7 (%d asked)", reduced, int(initial));
    if (!failed.empty()) f.ctx.Warnf("Not reduced (kept as they were): %s", failed.c_str());
    f.extra.SetInt("reduced", reduced);
    f.extra.SetInt("not_reduced", notReduced);
    out.result = irr::Result::Ok();
    return out;
  });
}

FilterOutcome ApplyAggregate(FilterContext& ctx, const ParamValues& par) {
  return RunComposite(ctx, par, "Irregular Vertices: Aggregate",
                      [&](CompositeFrame& f) { return f.ops.Aggregate(f.sel); });
}

FilterOutcome ApplyMovePair(FilterContext& ctx, const ParamValues& par) {
  return RunComposite(ctx, par, "Irregular Vertices: Move Pair", [&](CompositeFrame& f) {
    if (f.sel.size() == 1) {  // Theorem 5.1 on its condition: the theorem, or a partner to pair with
      irr::ImpossibilityCheck<CMeshO> check(f.m);
      return Refused(check.SingleVertexMove(f.sel[0]).message);
    }
    const std::string count = f.NeedCount(2, "Moving a pair");
    if (!count.empty()) return Refused(count);
    int lead = f.sel[0], partner = f.sel[1];
    const int how = par.Enum("lead");
    const bool swap = (how == 0 && f.ed.Valence(lead) > f.ed.Valence(partner)) ||
                      (how == 1 && f.ed.Valence(lead) < f.ed.Valence(partner)) || how == 3;
    if (swap) std::swap(lead, partner);
    if (par.Bool("towardPoint")) {
      const int v5 = f.ed.Valence(lead) == 5 ? lead : partner, v7 = v5 == lead ? partner : lead;
      const vcg::Point3d p = par.Point("point");
      return f.ops.MovePair57Toward(v5, v7, CMeshO::CoordType(p[0], p[1], p[2]));
    }
    return f.ops.MovePair(lead, partner, par.Int("direction"), par.Int("steps"));
  });
}

FilterOutcome ApplyCancelTriple(FilterContext& ctx, const ParamValues& par) {
  return RunComposite(ctx, par, "Irregular Vertices: Cancel Triple", [&](CompositeFrame& f) {
    if (f.IsOppositePair()) return Refused(f.PairCancellationAnswer());
    const std::string count = f.NeedCount(3, "A triple cancellation");
    if (!count.empty()) return Refused(count);
    return f.ops.CancelTriple(f.sel);
  });
}

FilterOutcome ApplyCancelQuadruple(FilterContext& ctx, const ParamValues& par) {
  return RunComposite(ctx, par, "Irregular Vertices: Cancel Quadruple", [&](CompositeFrame& f) {
    if (f.IsOppositePair()) return Refused(f.PairCancellationAnswer());
    const std::string count = f.NeedCount(4, "A quadruple cancellation");
    if (!count.empty()) return Refused(count);
    return f.ops.CancelQuadruple(f.sel);
  });
}

FilterOutcome ApplyGenerate(FilterContext& ctx, const ParamValues& par) {
  return RunComposite(ctx, par, "Irregular Vertices: Generate", [&](CompositeFrame& f) {
    const std::string count = f.NeedCount(1, "Generation");
    if (!count.empty()) return Refused(count);
    const int dir = par.Int("direction"), spacing = par.Int("spacing");
    if (par.Enum("shape") == 1) {
      if (par.Enum("kind") == 0)
        return Refused("The parallelogram shape is for a quadruple (generate it from a regular vertex).");
      return f.ops.GenerateQuadrupleShape(f.sel[0], dir, par.Int("side1Direction"), par.Int("side1"),
                                          par.Int("side2Direction"), par.Int("side2"));
    }
    return par.Enum("kind") == 0 ? f.ops.GenerateTriple(f.sel[0], dir, spacing)
                                 : f.ops.GenerateQuadruple(f.sel[0], dir, spacing);
  });
}

}  // namespace filter_irregular
