// filter_irregular: automatic reduction of the number of irregular vertices, built only from
// the paper's operations (Li et al., sec. 6.2, 6.3, 7).
//
// What a designer of the paper does by hand, as a deterministic greedy loop:
//   1. type change (sec. 6.3): every vertex of valence <= 4 or >= 8 is split into v5 / v7;
//   2. local cancellation: wherever a single flip or collapse removes irregular vertices (an
//      adjacent 5-5-7 / 5-7-7 triple becomes one v5 / v7, an adjacent 5-5-7-7 quadruple
//      disappears: the atomic removals of sec. 6.2), it is applied;
//   3. transport (sec. 7.1, 7.2): an adjacent 5-7 pair is moved by pair steps toward the
//      nearest other irregular vertices, within a travel bound, until a removal applies there;
//      a transport that meets nothing to cancel is undone;
//   4. steps 2-3 repeat with a growing travel distance; a final global relaxation (sec. 8)
//      evens out the triangles.
// Every edit is followed by local relaxation of its neighbourhood and is undone when it would
// leave a triangle worse than the angle bound (this is what keeps the irregular vertices the
// surface needs: a v5 on an ear tip cannot be cancelled without squeezing the triangles there)
// or leave the input surface by more than the Hausdorff budget.
//
// Preconditions: a manifold, consistently oriented triangle mesh with FF and VF adjacency up to
// date (see mesh_checks.h). Boundary vertices are never edited. Postconditions: the mesh is a
// valid 2-manifold with the same topology; on interruption (progress callback returns false)
// the mesh is exactly as it was.
#pragma once

#include <algorithm>
#include <chrono>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <vcg/space/distance3.h>

#include "composite_ops.h"
#include "quality.h"
#include "sample_grid.h"

namespace vcg_ext {
namespace irregular {

struct ReductionOptions {
  int targetCount = 0;                  ///< stop once this many irregular vertices remain (0: as few as possible)
  double hausdorffBudgetPercent = 0.5;  ///< an edit whose faces leave the input surface by more (percent of its
                                        ///< bounding-box diagonal) is undone
  int maxTravel = 12;                   ///< most pair steps a 5-7 pair is transported to meet a partner
  double minAngleDeg = 30;              ///< an edit is undone if, after local relaxation, a triangle around it has
                                        ///< a smaller angle than this (unless one already had before the edit)
 int glideTravel = 30;                 ///< most steps a pair glides straight on looking for a partner
  int maxSweeps = 12;                   ///< passes over the irregular vertices
  double minSweepGainPercent = 1;       ///< stop when a pass removes no more than this share
  int targetsPerPair = 4;               ///< nearest irregular vertices a pair tries to reach, per round
  std::vector<char> frozen;             ///< per vertex index, 1: never touched by an edit (protected selection);
                                        ///< vertices created later are free
  int localRelaxIterations = 3;         ///< sweeps of local relaxation of the 2-ring after each step
  RelaxMode finalRelax = RelaxMode::Local;  ///< final relaxation of the whole mesh: local sweeps, or a global
                                            ///< solve (eq. 5) followed by local sweeps
  int globalRelaxRounds = 3;            ///< solve-and-project rounds of the final global relaxation
  int finalLocalSweeps = 5;             ///< local sweeps over the whole mesh at the end (0: none)
  double sharpEdgeDeg = 25;             ///< input edges sharper than this are sampled for the Hausdorff check
  double hausdorffSamplesPerEdge = 0;   ///< input samples per edited edge length for the Hausdorff check besides
                                        ///< its sharp edges (0: sharp edges only); 2 is stricter and ~3x slower
  double timeLimitSeconds = std::numeric_limits<double>::infinity();  ///< stop editing (keeping what was
                                        ///< done) after this long; the default: no limit (results then do
                                        ///< not depend on the machine's speed)
  std::function<bool(int, const char*)> progress;  ///< (percent, stage); returning false interrupts and rolls back
};

struct ReductionReport {
  Result result = Result::Fail("not run");
  std::map<int, int> histogramBefore, histogramAfter;  ///< interior valence -> count
  int irregularBefore = 0, irregularAfter = 0;
  int typeSplits = 0;         ///< vertices of valence <= 4 or >= 8 reduced to 5/7
  int localCancellations = 0; ///< atomic removals applied where they were
  int transports = 0;         ///< pair transports that ended in a cancellation
  int glides = 0;             ///< pairs that glided straight on into a cancellation
  int pairSteps = 0;          ///< pair steps of those transports
  int splitAbsorptions = 0;   ///< stretched dislocations split into two pairs that were both cancelled
  int undone = 0;             ///< edits undone (angle, Hausdorff or fold)
  bool globalRelaxUndone = false;  ///< the final global solve lowered the smallest angle and was undone
  bool finalSweepsUndone = false;  ///< the final local sweeps overshot the Hausdorff budget and were undone
  bool timeLimitReached = false;
  bool interrupted = false;
  double hausdorffPercent = 0;  ///< symmetric distance of the result to the input (HausdorffPercent)
  int budgetRetries = 0;        ///< reruns with a tighter per-edit budget after overshooting
  bool allUndone = false;       ///< even the retries overshot: the mesh was given back unchanged
  double seconds = 0;
  explicit operator bool() const { return result.ok; }
};

template <class MeshType>
class AutomaticReduction {
 public:
  typedef MeshEditor<MeshType> Editor;
  typedef typename MeshType::CoordType CoordType;
  typedef typename MeshType::FaceType FaceType;

  /// original: the input surface (edits are projected on it and measured against it).
  AutomaticReduction(MeshType& m, const SurfaceProjector& original, ReductionOptions opt = ReductionOptions())
      : m_(m), original_(original), opt_(std::move(opt)), ed_(m), comp_(ed_, &original, Quiet()), ops_(comp_.atomic()) {
    // The per-edit check samples the input side on its sharp edges (and, if asked, at
    // hausdorffSamplesPerEdge points per edge elsewhere): between samples the true distance
    // can be higher, so a tenth of the budget is kept back; Run() measures the result and
    // redoes the run if it still overshoots.
    budget_ = 0.9 * opt_.hausdorffBudgetPercent / 100.0 * double(original.Diagonal());
    BuildInputSamples(samplesPerEdge_ = opt_.hausdorffSamplesPerEdge);
  }

  /// Runs the reduction. Postcondition on success: the symmetric Hausdorff distance of the
  /// result to the input, as measured by HausdorffPercent (quality.h), is within the budget
  /// (the per-edit checks sample; a final measurement verifies, and a run that overshoots is
  /// redone with a tighter per-edit budget, at worst undone whole).
  ReductionReport Run() {
    ReductionReport rep;
    t0_ = std::chrono::steady_clock::now();
    TakeSnapshot();
    Histogram(rep.histogramBefore, rep.irregularBefore);
    for (int attempt = 0;; ++attempt) {
      ReductionReport r;
      r.histogramBefore = rep.histogramBefore;
      r.irregularBefore = rep.irregularBefore;
      r.budgetRetries = attempt;
      Edit(r);
      if (r.interrupted) {
        RestoreSnapshot();
        r.result = Result::Fail("interrupted: the mesh is unchanged");
        return r;
      }
      r.hausdorffPercent = HausdorffPercent(m_, original_);
      // the independent check of the tests samples more densely than HausdorffPercent: keep
      // a small margin below the budget
      const bool within = r.hausdorffPercent <= kVerifyMargin * opt_.hausdorffBudgetPercent;
      if (within || attempt == kMaxBudgetRetries) {
        rep = r;
        if (!within) {
          // even the tightest retry overshoots: give the input back unchanged
          RestoreSnapshot();
          rep.allUndone = true;
          rep.hausdorffPercent = HausdorffPercent(m_, original_);
        }
        break;
      }
      // Over the budget: start again with the per-edit check stricter: the input sampled all
      // over (not only on sharp edges), and the per-edit budget lowered in proportion to the
      // overshoot (gently: where the input is curved, the mesh before the edits may already
      // use most of the budget, and a much lower one would forbid every edit there).
      RestoreSnapshot();
      TakeSnapshot();
      budget_ *= std::max(0.5, std::min(0.95, kVerifyMargin * opt_.hausdorffBudgetPercent / r.hausdorffPercent));
      if (samplesPerEdge_ < 2) BuildInputSamples(samplesPerEdge_ = 2);
      epoch_ = 0;
      editedAt_.clear();
      failedAt_.clear();
      globalKept_ = sweepsKept_ = true;
    }
    ed_.Commit();
    snapshot_.Commit();
    vcg::tri::Allocator<MeshType>::CompactEveryVector(m_);
    vcg::tri::UpdateTopology<MeshType>::FaceFace(m_);
    vcg::tri::UpdateTopology<MeshType>::VertexFace(m_);
    Histogram(rep.histogramAfter, rep.irregularAfter);
    rep.globalRelaxUndone = !globalKept_;
    rep.finalSweepsUndone = !sweepsKept_;
    rep.seconds = Elapsed();
    rep.result = Result::Ok();
    return rep;
  }

 private:
  static constexpr double kVerifyMargin = 0.97;  ///< final distance must be under this share of the budget
  static constexpr int kMaxBudgetRetries = 2;     ///< reruns with a tighter per-edit budget

  /// One pass of the whole pipeline (type change, sweeps, final relaxation) into rep.
  void Edit(ReductionReport& rep) {
    StartCount();
    bool go = Stage(rep, 0, "Splitting high and low valences") && ReduceTypes(rep);
    // Growing travel: cheap local cancellations everywhere first, so the long transports only
    // run for what is left.
    // Sweeps: local removals only until they stop paying, then with transports, until a
    // sweep removes nothing (or a small share) more.
    for (int sweep = 0, travel = 0; go && sweep < opt_.maxSweeps; ++sweep) {
      const int before = irregular_;
      go = Stage(rep, 10 + 70 * sweep / opt_.maxSweeps, "Cancelling triples and quadruples") && Sweep(rep, travel);
      if (!go || Done()) break;
      const int removed = before - irregular_;
      if (removed * 100 <= before * opt_.minSweepGainPercent) {
        if (travel > 0) break;
        travel = opt_.maxTravel;
      }
    }
    if (rep.interrupted) return;
    // the final relaxation runs even when the time limit stopped the editing
    if (!opt_.progress || opt_.progress(90, "Relaxing")) FinalRelax();
    else rep.interrupted = true;
  }

  /// Input samples for the input-to-edited side of the Hausdorff check: the input's face
  /// centroids and vertices thinned to perEdge per edited edge length (none if 0), plus
  /// everything on its sharp edges (creases, tips), where an edit cuts corners. Oriented by
  /// their face.
  void BuildInputSamples(double perEdge) {
    const double h = MeanEdgeLength(m_);
    std::vector<vcg::Point3f> samples, normals;
    SharpEdgeSamples(original_.Mesh(), opt_.sharpEdgeDeg, samples, normals);
    if (perEdge > 0) ThinnedSurfaceSamples(original_.Mesh(), h / perEdge, samples, normals);
    originalSamples_.Build(std::move(samples), std::move(normals), h);
  }

  /// Ends and midpoints of the edges of m whose dihedral angle exceeds angleDeg, with the
  /// normal of each face along the edge. O(F log F).
  static void SharpEdgeSamples(const SurfaceProjector::PMesh& m, double angleDeg, std::vector<vcg::Point3f>& pts,
                               std::vector<vcg::Point3f>& nrm) {
    std::map<std::pair<const void*, const void*>, std::vector<size_t>> edgeFaces;
    for (size_t i = 0; i < m.face.size(); ++i)
      for (int z = 0; z < 3; ++z) {
        const void* a = m.face[i].cV(z);
        const void* b = m.face[i].cV((z + 1) % 3);
        edgeFaces[a < b ? std::make_pair(a, b) : std::make_pair(b, a)].push_back(i);
      }
    const double c = std::cos(angleDeg * M_PI / 180.0);
    for (auto& kv : edgeFaces) {
      const auto& fs = kv.second;
      // boundary and non-manifold edges are features too
      bool sharp = fs.size() != 2 || double(m.face[fs[0]].cN().dot(m.face[fs[1]].cN())) < c;
      if (!sharp) continue;
      const auto* a = static_cast<const SurfaceProjector::PMesh::VertexType*>(kv.first.first);
      const auto* b = static_cast<const SurfaceProjector::PMesh::VertexType*>(kv.first.second);
      for (size_t f : fs)
        for (const vcg::Point3f& p : {a->cP(), b->cP(), vcg::Point3f((a->cP() + b->cP()) / 2.f)}) {
          pts.push_back(p);
          nrm.push_back(m.face[f].cN());
        }
    }
  }

  /// Face centroids and corners of m, at most one per cell of a grid of the given spacing.
  static void ThinnedSurfaceSamples(const SurfaceProjector::PMesh& m, double spacing, std::vector<vcg::Point3f>& pts,
                                    std::vector<vcg::Point3f>& nrm) {
    std::unordered_map<uint64_t, char> taken;
    auto cell = [&](const vcg::Point3f& p) {
      auto c = [&](float x) { return uint64_t(int64_t(std::floor(x / spacing)) & 0x1FFFFF); };
      return (c(p[0]) << 42) | (c(p[1]) << 21) | c(p[2]);
    };
    for (auto& f : m.face)
      for (const vcg::Point3f& p : {vcg::Point3f((f.cP(0) + f.cP(1) + f.cP(2)) / 3.f), f.cP(0), f.cP(1), f.cP(2)})
        if (taken.emplace(cell(p), 1).second) {
          pts.push_back(p);
          nrm.push_back(f.cN());
        }
  }

  static double MeanEdgeLength(const MeshType& m) {
    double sum = 0;
    long n = 0;
    for (auto& f : m.face)
      if (!f.IsD())
        for (int z = 0; z < 3; ++z, ++n) sum += double((f.cP(z) - f.cP((z + 1) % 3)).Norm());
    return n ? sum / double(n) : 1;
  }

  static CompositeOptions Quiet() {
    CompositeOptions o;
    o.relax = true;
    return o;
  }

  double Elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }

  /// Reports progress; false (and rep.interrupted) if the caller asked to stop.
  bool Stage(ReductionReport& rep, int pct, const char* what) {
    if (opt_.progress && !opt_.progress(std::min(99, pct), what)) {
      rep.interrupted = true;
      return false;
    }
    if (Elapsed() > opt_.timeLimitSeconds) {
      rep.timeLimitReached = true;
      return false;
    }
    return true;
  }

  bool Done() const { return opt_.targetCount > 0 && irregular_ <= opt_.targetCount; }

  /// The running count of interior irregular vertices: one O(V) pass per run, then kept up
  /// to date from the vertices each accepted edit touched (UpdateCount).
  void StartCount() {
    isIrregular_.assign(m_.vert.size(), 0);
    irregular_ = 0;
    for (size_t i = 0; i < m_.vert.size(); ++i) irregular_ += isIrregular_[i] = IsInteriorIrregular(int(i));
  }

  /// After an accepted edit: valences change only at the vertices an edit touched and their
  /// neighbours (a collapse re-points the faces around the vertex it removes, all in the ring
  /// of the survivor). O(touched).
  void UpdateCount(const std::vector<int>& touched) {
    std::vector<int> live;
    for (int t : touched)
      if (ed_.IsLive(t)) live.push_back(t);
    std::vector<int> around = KRing(m_, live, 1);
    around.insert(around.end(), touched.begin(), touched.end());
    if (isIrregular_.size() < m_.vert.size()) isIrregular_.resize(m_.vert.size(), 0);
    for (int x : around) {
      if (x < 0 || size_t(x) >= isIrregular_.size()) continue;
      const char now = IsInteriorIrregular(x);
      irregular_ += int(now) - int(isIrregular_[size_t(x)]);
      isIrregular_[size_t(x)] = now;
    }
  }

  /// The whole-run undo (interruption, Hausdorff overshoot): every vertex and face of the
  /// input saved once, O(V + F) memory whatever the number of edits, while the editor's own
  /// journal is committed after every accepted edit and so holds one edit at a time.
  void TakeSnapshot() {
    snapshot_.Commit();
    snapshotMark_ = snapshot_.Mark();
    for (auto& f : m_.face) snapshot_.SaveFace(&f);
    for (auto& v : m_.vert) snapshot_.SaveVertex(&v);
  }
  void RestoreSnapshot() {
    ed_.Commit();  // what an interrupted edit logged is overwritten below
    snapshot_.RollbackTo(snapshotMark_);
  }

  void Histogram(std::map<int, int>& h, int& irregular) {
    h.clear();
    irregular = 0;
    for (size_t i = 0; i < m_.vert.size(); ++i) {
      if (!ed_.IsLive(int(i)) || ed_.IsBoundary(int(i))) continue;
      const int d = ed_.Valence(int(i));
      ++h[d];
      irregular += d != 6;
    }
  }

  bool IsInteriorIrregular(int v) { return ed_.IsLive(v) && !ed_.IsBoundary(v) && ed_.Valence(v) != 6; }
  bool Frozen(int v) const { return v >= 0 && size_t(v) < opt_.frozen.size() && opt_.frozen[size_t(v)]; }

  // ------------------------------------------------------------ 1. type change (sec. 6.3)
  bool ReduceTypes(ReductionReport& rep) {
    for (size_t i = 0; i < m_.vert.size(); ++i) {
      const int v = int(i);
      if (!IsInteriorIrregular(v) || Frozen(v)) continue;
      const int d = ed_.Valence(v);
      if (d == 5 || d == 7) continue;
      // the split relaxes the 2-ring of the vertices it touches, all within v's 2-ring
      std::vector<int> around = KRing(m_, {v}, 2);
      Guard g(*this, around);
      CompositeOutcome o = comp_.ReduceTo57(v);
      if (o) around.insert(around.end(), o.irregular.begin(), o.irregular.end());
      if (o && g.Accept(around)) ++rep.typeSplits;
      else ++rep.undone;
    }
    return true;
  }

  // ------------------------------------------------------------ 2-3. cancellation sweep
  /// One pass over the irregular vertices: local cancellations; with travel > 0 also pair
  /// transports of up to `travel` steps. False if interrupted or out of time.
  bool Sweep(ReductionReport& rep, int travel) {
    const size_t n = m_.vert.size();
    for (size_t i = 0; i < n && i < m_.vert.size(); ++i) {
      const int v = int(i);
      if ((i & 1023) == 0 && !Stage(rep, int(10 + 70 * i / n / std::max(1, opt_.maxTravel) * std::max(1, travel)),
                                    travel == 0 ? "Cancelling adjacent triples and quadruples"
                                                : "Moving pairs to cancel them"))
        return false;
      if ((i & 255) == 0 && Done()) return true;
      if (!IsInteriorIrregular(v) || Frozen(v)) continue;
      if (CancelAround(rep, v)) continue;
      if (travel == 0 || UnchangedSinceFailure(v, travel)) continue;
      if (ed_.Valence(v) == 5 && Transport(rep, v, travel)) continue;
      if (Isolated(v) && SplitAndAbsorb(rep, v, std::max(2, travel))) continue;
      Stamp(failedAt_, v, epoch_);
    }
    return true;
  }

  /// Count-reducing test for FindAndApply: the operation removes 2 or 4 irregular vertices
  /// among those it touches, leaves only valences 5-7, and touches no frozen vertex. These
  /// are exactly the atomic removals of sec. 6.2 (triple into one vertex, quadruple).
  bool Reduces(const std::map<int, int>& before, const std::map<int, int>& after) const {
    int irrBefore = 0, irrAfter = 0;
    for (auto& kv : before) {
      if (Frozen(kv.first)) return false;
      if (kv.second != 6 && std::find(exclude_.begin(), exclude_.end(), kv.first) != exclude_.end()) return false;
      irrBefore += kv.second != 6;
    }
    for (auto& kv : after) {
      if (kv.second == 0) continue;
      if (kv.second < 5 || kv.second > 7) return false;
      irrAfter += kv.second != 6;
    }
    return irrAfter <= irrBefore - 2 && irrAfter <= maxSurvivors_;
  }

  /// Applies a removal around v if one exists and keeps it if the result is good enough.
  bool CancelAround(ReductionReport& rep, int v) {
    Guard g(*this, {v});
    AtomicOutcome o = ops_.FindAndApply(
        {v}, [&](const std::map<int, int>& b, const std::map<int, int>& a) { return Reduces(b, a); },
        "cancellation", false);
    if (!o) return false;
    std::vector<int> touched = Changed(o);
    Relax(touched);
    if (!g.Accept(touched)) {
      ++rep.undone;
      return false;
    }
    ++rep.localCancellations;
    return true;
  }

  /// Transports a 5-7 pair containing v5 toward the nearest irregular vertices (graph
  /// distance <= travel), one pair step at a time, until a removal applies next to it.
  bool Transport(ReductionReport& rep, int v5, int travel) {
    for (auto* nb : ed_.Star(v5).neighbors) {
      const int w = ed_.Index(nb);
      if (ed_.Valence(w) == 7 && !Frozen(w)) return Transport(rep, v5, w, travel);
    }
    return false;
  }

  /// Transports the adjacent 5-7 pair (v5, v7) to a cancellation: toward the nearest
  /// irregular vertices first, then gliding straight on. True if a removal happened; the
  /// vertices it changed are added to *touchedOut.
  bool Transport(ReductionReport& rep, int v5, int v7, int travel, std::vector<int>* touchedOut = nullptr) {
    std::vector<int> targets = NearestIrregular({v5, v7}, travel, opt_.targetsPerPair);
    for (int t : targets) {
      const CoordType goal = ed_.V(t)->P();
      if (TryMove(rep, v5, v7, [&](int a, int b) { return StepCloser(a, b, goal); }, travel + 2, rep.transports,
                  touchedOut))
        return true;
    }
    // No irregular vertex nearby takes the pair: let it glide straight on (repeating the same
    // pair move parallel-transports it, sec. 6.2) until it meets one that does. This is what
    // empties the walls of 5-7 pairs between differently oriented regular patches.
    for (int dir : {1, 4, 0, 5, 2, 3})
      if (TryMove(rep, v5, v7, [&](int a, int b) { return ops_.MovePair57(a, b, dir); }, opt_.glideTravel,
                  rep.glides, touchedOut))
        return true;
    return false;
  }

  typedef std::function<AtomicOutcome(int, int)> PairStep;

  /// Moves the pair with `step` until a removal applies next to it, and keeps the result if
  /// it is good enough (Guard). A failed transport is the common case and the expensive one (a
  /// relaxation per step), so a topology-only probe (no relaxation, no fold check, undone)
  /// first finds whether and after how many steps a removal happens.
  bool TryMove(ReductionReport& rep, int v5, int v7, const PairStep& step, int maxSteps, int& successes,
               std::vector<int>* touchedOut) {
    int reach = -1;
    {
      auto cp = ed_.Mark();
      const bool folds = ed_.geometry().checkFolds;
      ed_.geometry().checkFolds = false;
      std::vector<int> scratch;
      reach = MoveUntilRemoval(v5, v7, step, maxSteps, false, scratch);
      ed_.geometry().checkFolds = folds;
      ed_.RollbackTo(cp);
    }
    if (reach < 0) return false;
    Guard g(*this, {v5, v7});
    std::vector<int> touched{v5, v7};
    const int steps = MoveUntilRemoval(v5, v7, step, reach + 2, true, touched);
    if (steps >= 0 && g.Accept(touched)) {
      if (touchedOut) touchedOut->insert(touchedOut->end(), touched.begin(), touched.end());
      ++successes;
      rep.pairSteps += steps;
      return true;
    }
    if (steps >= 0) ++rep.undone;
    g.Undo();
    return false;
  }

  /// Steps the pair (a, b) with `step` until a removal (sec. 6.2) applies next to it; when no
  /// step is possible, one more step in any direction may set the removal up. Returns the
  /// number of pair steps taken, or -1 if no removal happened (the caller undoes).
  int MoveUntilRemoval(int a, int b, const PairStep& step, int maxSteps, bool relax, std::vector<int>& touched) {
    for (int s = 0; s < maxSteps; ++s) {
      auto cp = ed_.Mark();
      AtomicOutcome o = step(a, b);
      bool ok = bool(o);
      for (auto& kv : o.changes) ok = ok && !Frozen(kv.first);
      if (!ok) {
        ed_.RollbackTo(cp);
        return StepAndCancel(a, b, touched, relax) ? s + 1 : -1;
      }
      a = o.irregular[0];
      b = o.irregular[1];
      Record(o, touched);
      if (relax) Relax({a, b});
      if (RemovalAt({a, b}, touched, relax)) return s + 1;
    }
    return -1;
  }

  bool Isolated(int v) {
    for (auto* nb : ed_.Star(v).neighbors)
      if (ed_.Valence(ed_.Index(nb)) != 6) return false;
    return true;
  }

  /// An isolated v5 / v7 and an isolated vertex w of the other type a few edges away form a
  /// stretched dislocation that no single pair move can carry. v steps toward w with 5-7
  /// pair generation (sec. 6.2), and each generated pair is transported away until it cancels
  /// elsewhere (sec. 7.2); once v is next to w the two form an adjacent 5-7 pair, which is
  /// transported to a cancellation in turn. Kept only if that last cancellation happens (net:
  /// two irregular vertices fewer), otherwise undone.
  bool SplitAndAbsorb(ReductionReport& rep, int v, int radius) {
    const int dv = ed_.Valence(v);
    std::vector<int> near = NearestIrregular({v}, radius, 1, dv == 5 ? 7 : 5);
    if (near.empty()) return false;
    const int w = near[0];
    const ReductionReport saved = rep;
    Guard g(*this, {v, w});
    std::vector<int> touched{v, w};
    int cur = v;
    for (int hop = 0; hop <= radius && !ed_.Adjacent(cur, w); ++hop) {
      std::unordered_map<int, int> dist = Distances(w, radius + 1);
      const int here = dist.count(cur) ? dist[cur] : radius + 2;
      const int d = ed_.Valence(cur);
      int next = -1;
      for (int k = 0; k < d && next < 0; ++k) {
        // the neighbour the vertex moves to must be closer to w
        const int to = ops_.NeighbourFrom(cur, -1, d == 5 ? k : k + 1);
        if (to < 0 || !dist.count(to) || dist[to] >= here) continue;
        auto cp = ed_.Mark();
        const size_t mark = touched.size();
        AtomicOutcome gen = ops_.MoveWithPairGeneration(cur, k);
        if (!gen) continue;
        Relax(Record(gen, touched));
        const int moved = gen.irregular[0];
        int p5 = gen.irregular[1], p7 = gen.irregular[2];
        if (ed_.Valence(p5) != 5) std::swap(p5, p7);
        // a removal of the generated pair against the moved vertex would only undo the step
        exclude_ = {moved, w};
        const bool away = Transport(rep, p5, p7, opt_.maxTravel, &touched);
        exclude_.clear();
        if (away) {
          next = moved;
        } else {
          touched.resize(mark);
          ed_.RollbackTo(cp);
        }
      }
      if (next < 0) break;
      cur = next;
    }
    if (ed_.IsLive(cur) && ed_.IsLive(w) && ed_.Adjacent(cur, w) && ed_.Valence(cur) + ed_.Valence(w) == 12) {
      const int a5 = ed_.Valence(cur) == 5 ? cur : w, a7 = a5 == cur ? w : cur;
      if (Transport(rep, a5, a7, opt_.maxTravel, &touched) && g.Accept(touched)) {
        ++rep.splitAbsorptions;
        return true;
      }
    }
    rep = saved;
    g.Undo();
    return false;
  }

  /// Graph distances from v, up to radius.
  std::unordered_map<int, int> Distances(int v, int radius) {
    std::unordered_map<int, int> dist{{v, 0}};
    std::vector<int> frontier{v};
    for (int r = 1; r <= radius; ++r) {
      std::vector<int> next;
      for (int x : frontier)
        for (auto* nb : ed_.Star(x).neighbors) {
          const int y = ed_.Index(nb);
          if (dist.emplace(y, r).second) next.push_back(y);
        }
      frontier.swap(next);
    }
    return dist;
  }

  static void Stamp(std::vector<long>& at, int v, long when) {
    if (v < 0) return;
    if (size_t(v) >= at.size()) at.resize(size_t(v) + 1, -1);
    at[size_t(v)] = when;
  }
  static long StampOf(const std::vector<long>& at, int v) { return size_t(v) < at.size() ? at[size_t(v)] : -1; }

  /// True if a transport from v already failed and nothing within `radius` edges has been
  /// edited since: trying again would fail the same way (the search is deterministic).
  bool UnchangedSinceFailure(int v, int radius) {
    const long failed = StampOf(failedAt_, v);
    if (failed < 0) return false;
    for (int x : KRing(m_, {v}, radius))
      if (StampOf(editedAt_, x) > failed) return false;
    return true;
  }

  /// The vertices an atomic operation changed and that still exist. The ones it deleted go
  /// to removed_, for the running count.
  std::vector<int> Changed(const AtomicOutcome& o) {
    std::vector<int> c;
    for (auto& kv : o.changes)
      (kv.second != 0 ? c : removed_).push_back(kv.first);
    return c;
  }

  /// Appends what o changed to touched; returns it too.
  std::vector<int> Record(const AtomicOutcome& o, std::vector<int>& touched) {
    std::vector<int> c = Changed(o);
    touched.insert(touched.end(), c.begin(), c.end());
    return c;
  }

  /// Applies a removal (sec. 6.2) involving one of the vertices, if one exists; adds what it
  /// changed to touched and relaxes there.
  bool RemovalAt(const std::vector<int>& vs, std::vector<int>& touched, bool relax = true) {
    for (int x : vs) {
      if (!ed_.IsLive(x)) continue;
      AtomicOutcome c = ops_.FindAndApply(
          {x}, [&](const std::map<int, int>& bf, const std::map<int, int>& af) { return Reduces(bf, af); },
          "cancellation", false);
      if (!c) continue;
      std::vector<int> changed = Record(c, touched);
      if (relax) Relax(changed);
      return true;
    }
    return false;
  }

  /// One pair step, in the first of the six directions after which a removal applies.
  bool StepAndCancel(int v5, int v7, std::vector<int>& touched, bool relax = true) {
    for (int dir = 0; dir < 6; ++dir) {
      auto cp = ed_.Mark();
      const size_t mark = touched.size();
      AtomicOutcome o = ops_.MovePair57(v5, v7, dir);
      bool ok = bool(o);
      if (ok)
        for (auto& kv : o.changes) ok = ok && !Frozen(kv.first);
      if (ok) {
        Record(o, touched);
        if (RemovalAt({o.irregular[0], o.irregular[1]}, touched, relax)) return true;
      }
      touched.resize(mark);
      ed_.RollbackTo(cp);
    }
    return false;
  }

  /// The pair step (one of the six of sec. 6.2) after which the pair's midpoint is closest to
  /// `goal`, if it gets closer; refused steps (blocked, folds, frozen) are skipped; ties go
  /// to the lowest direction. The dry runs (PredictMovePair57) rule out blocked and frozen
  /// steps and bound each step's distance from below without editing: a flip moves no
  /// vertex, a collapse leaves its survivor at one of three known places (graph_ops.h
  /// Collapse); only a split's new positions need the step applied. A step is applied (and
  /// rolled back) only if its bound can still beat the best so far, so the choice is the
  /// one trying all six would make, at usually two or three applications instead of seven.
  AtomicOutcome StepCloser(int v5, int v7, CoordType goal) {
    auto mid = [&](int a, int b) { return (ed_.V(a)->P() + ed_.V(b)->P()) / 2; };
    auto dist = [&](const CoordType& p) { return double((p - goal).Norm()); };
    double best = dist(mid(v5, v7));
    int bestDir = -1;
    struct Bound {
      double d;
      int dir;
      bool operator<(const Bound& o) const { return d < o.d || (d == o.d && dir < o.dir); }
    };
    std::vector<Bound> bounds;
    for (int dir = 0; dir < 6; ++dir) {
      AtomicPrediction pr = ops_.PredictMovePair57(v5, v7, dir);
      bool ok = bool(pr);
      for (auto& kv : pr.changes) ok = ok && !Frozen(kv.first);
      if (!ok) continue;
      double lb = 0;  // a split moves the pair: apply it to know
      if (pr.steps.size() == 1 && pr.steps[0].kind == GraphStep::kFlip) {
        lb = dist(mid(pr.pair5, pr.pair7));
      } else if (pr.steps.size() == 1 && pr.steps[0].kind == GraphStep::kCollapse) {
        // collapse x into the survivor (pair7): it ends at the midpoint, or its own or x's place
        const CoordType px = ed_.V(pr.steps[0].x)->P(), ps = ed_.V(pr.steps[0].y)->P(), p5 = ed_.V(pr.pair5)->P();
        lb = std::min({dist((p5 + (px + ps) / 2) / 2), dist((p5 + ps) / 2), dist((p5 + px) / 2)});
      }
      // a margin for rounding: the bound must never exceed the distance after the real step
      bounds.push_back({lb * (1 - 1e-9) - 1e-12, dir});
    }
    std::sort(bounds.begin(), bounds.end());
    for (const Bound& b : bounds) {
      if (b.d > best || (bestDir >= 0 && b.d == best && b.dir > bestDir)) break;
      auto cp = ed_.Mark();
      AtomicOutcome o = ops_.MovePair57(v5, v7, b.dir);
      if (o) {
        const double d = dist(mid(o.irregular[0], o.irregular[1]));
        if (d < best || (d == best && bestDir >= 0 && b.dir < bestDir)) best = d, bestDir = b.dir;
      }
      ed_.RollbackTo(cp);
    }
    if (bestDir < 0) return AtomicOutcome();
    return ops_.MovePair57(v5, v7, bestDir);
  }

  /// Irregular vertices (not in `from`) within `radius` edges of `from`, nearest first.
  std::vector<int> NearestIrregular(const std::vector<int>& from, int radius, int count, int valence = 0) {
    std::unordered_map<int, int> dist;
    std::queue<int> q;
    for (int v : from) dist[v] = 0, q.push(v);
    std::vector<int> found;
    while (!q.empty() && int(found.size()) < count) {
      const int v = q.front();
      q.pop();
      if (dist[v] >= radius) continue;
      VertexStar<MeshType> s = ed_.Star(v);
      std::vector<int> next;
      for (auto* nb : s.neighbors) next.push_back(ed_.Index(nb));
      std::sort(next.begin(), next.end());  // deterministic order
      for (int w : next) {
        if (dist.count(w)) continue;
        dist[w] = dist[v] + 1;
        q.push(w);
        if (IsInteriorIrregular(w) && !Frozen(w) && (valence == 0 || ed_.Valence(w) == valence) &&
            int(found.size()) < count)
          found.push_back(w);
      }
    }
    return found;
  }

  // ------------------------------------------------------------ geometry
  void Relax(const std::vector<int>& seeds) {
    std::vector<int> live;
    for (int v : seeds)
      if (ed_.IsLive(v)) live.push_back(v);
    if (live.empty()) return;
    std::vector<int> ring = KRing(m_, live, 2), movable;
    for (int v : ring)
      if (!Frozen(v)) movable.push_back(v);
    for (int v : movable) {
      ed_.journal().SaveVertex(ed_.V(v));
      for (auto& c : ed_.Star(v).corners) ed_.journal().SaveFace(c.f);
    }
    RelaxOptions ro;
    ro.iterations = opt_.localRelaxIterations;
    LocalRelax(m_, movable, &original_, ro);
  }

  /// Smallest angle (degrees) of the faces around the 2-ring of the seeds.
  double MinAngleAround(const std::vector<int>& seeds) {
    std::vector<int> live;
    for (int v : seeds)
      if (ed_.IsLive(v)) live.push_back(v);
    double mn = 180;
    for (int v : KRing(m_, live, 2))
      for (auto& c : ed_.Star(v).corners) mn = std::min(mn, MinAngle(c.f));
    return mn;
  }

  static double MinAngle(const FaceType* f) {
    double mn = 180;
    for (int z = 0; z < 3; ++z) {
      auto a = f->cP((z + 1) % 3) - f->cP(z), b = f->cP((z + 2) % 3) - f->cP(z);
      const double la = a.Norm(), lb = b.Norm();
      const double c = la > 0 && lb > 0 ? double(a.dot(b)) / (la * lb) : 1;
      mn = std::min(mn, std::acos(std::max(-1.0, std::min(1.0, c))) * 180 / M_PI);
    }
    return mn;
  }

  /// Local symmetric Hausdorff distance between the edited faces around the seeds and the
  /// input surface: (a) the faces' edge midpoints and centroids to the input (their vertices
  /// lie on it after projection), and (b) the input's samples on sharp edges (see the
  /// constructor) over each edited star to the edited faces of one more ring (so a sample
  /// near the border still finds its closest edited face). (b) is what catches a crease or a
  /// tip cut off by an edit.
  double DeviationAround(const std::vector<int>& seeds) {
    std::vector<int> live;
    for (int v : seeds)
      if (ed_.IsLive(v)) live.push_back(v);
    // the local relaxation after an edit moves its 2-ring, which changes the faces up to there
    const std::vector<int> region = KRing(m_, live, 2);
    std::vector<const FaceType*> changed, all;
    std::unordered_set<const FaceType*> seen;
    for (int v : region)
      for (auto& c : ed_.Star(v).corners)
        if (seen.insert(c.f).second) changed.push_back(c.f);
    // (a) each changed face's centroid and edge midpoints (an edge shared by two changed faces
    // once) against the input. Only "above the budget or not" matters to the caller, so a
    // query looks no farther than just past the budget, and the first excess ends the check.
    const float reach = float(1.01 * budget_) + 1e-12f;
    double mx = 0;
    auto probe = [&](const CoordType& p) {
      float d = 0;
      original_.Closest(vcg::Point3f::Construct(p), &d, nullptr, reach);
      mx = std::max(mx, double(d));
      return mx <= budget_;
    };
    for (const FaceType* f : changed) {
      if (!probe(CoordType((f->cP(0) + f->cP(1) + f->cP(2)) / 3))) return mx;
      for (int z = 0; z < 3; ++z) {
        const FaceType* g = f->cFFp(z);
        if (g != f && g < f && seen.count(g)) continue;  // that edge is probed from g
        if (!probe(CoordType((f->cP(z) + f->cP((z + 1) % 3)) / 2))) return mx;
      }
    }
    // (b) the input samples near the changed faces against the edited surface there. The
    // faces are hashed on a grid so each sample is compared with the faces around it only:
    // O(region) for any edit size. Faces of one more ring are included so a sample by the
    // border finds its true closest face; only samples closest to a changed face count, and
    // only on the same side (a thin part's other sheet is not this edit's business).
    all = changed;
    for (int v : KRing(m_, region, 1))
      for (auto& c : ed_.Star(v).corners)
        if (seen.insert(c.f).second) all.push_back(c.f);
    const float cellSize = float(std::max(2 * budget_, 1e-12));
    auto key = [&](int64_t x, int64_t y, int64_t z) {
      return (uint64_t(x & 0x1FFFFF) << 42) | (uint64_t(y & 0x1FFFFF) << 21) | uint64_t(z & 0x1FFFFF);
    };
    auto cellOf = [&](float x) { return int64_t(std::floor(x / cellSize)); };
    std::unordered_map<uint64_t, std::vector<int>> faceCells;
    std::vector<vcg::Triangle3<float>> tri;
    for (size_t k = 0; k < all.size(); ++k) {
      const FaceType* f = all[k];
      tri.emplace_back(vcg::Point3f::Construct(f->cP(0)), vcg::Point3f::Construct(f->cP(1)),
                       vcg::Point3f::Construct(f->cP(2)));
      vcg::Box3<float> b;
      for (int z = 0; z < 3; ++z) b.Add(tri.back().P(z));
      for (int64_t x = cellOf(b.min[0]); x <= cellOf(b.max[0]); ++x)
        for (int64_t y = cellOf(b.min[1]); y <= cellOf(b.max[1]); ++y)
          for (int64_t z = cellOf(b.min[2]); z <= cellOf(b.max[2]); ++z) faceCells[key(x, y, z)].push_back(int(k));
    }
    std::unordered_set<int> probed;
    for (size_t k = 0; k < changed.size(); ++k) {
      vcg::Box3<float> b;
      for (int z = 0; z < 3; ++z) b.Add(tri[k].P(z));
      // a sample off the edited surface (a cut crease) lies outside the face's box: widen it;
      // deviations grow edit by edit, so catching them below twice the budget suffices
      b.Offset(float(2 * budget_));
      for (int i : originalSamples_.InBox(b)) {
        if (!probed.insert(i).second) continue;
        const vcg::Point3f& p = originalSamples_.Point(i);
        float best = std::numeric_limits<float>::max();
        int bestFace = -1;
        // faces within 2 * budget of p are in p's cell or the 26 around it
        for (int64_t x = cellOf(p[0]) - 1; x <= cellOf(p[0]) + 1; ++x)
          for (int64_t y = cellOf(p[1]) - 1; y <= cellOf(p[1]) + 1; ++y)
            for (int64_t z = cellOf(p[2]) - 1; z <= cellOf(p[2]) + 1; ++z) {
              auto it = faceCells.find(key(x, y, z));
              if (it == faceCells.end()) continue;
              for (int t : it->second) {
                float d;
                vcg::Point3f q;
                vcg::TrianglePointDistance(tri[size_t(t)], p, d, q);
                if (d < best) best = d, bestFace = t;
              }
            }
        if (bestFace < 0) {
          // nothing within two budgets among the edited faces around: either the sample
          // belongs elsewhere (another part of the surface) or the edit moved away from it
          continue;
        }
        if (size_t(bestFace) >= changed.size()) continue;  // closest to an unchanged face
        const vcg::Triangle3<float>& t = tri[size_t(bestFace)];
        if (originalSamples_.Normal(i).dot((t.P(1) - t.P(0)) ^ (t.P(2) - t.P(0))) <= 0) continue;
        mx = std::max(mx, double(best));
      }
    }
    return mx;
  }

  /// Guards one edit: remembers the checkpoint and the angle quality before; Accept() keeps
  /// the edit if the neighbourhood is still good (angle bound, Hausdorff budget), otherwise
  /// rolls back.
  struct Guard {
    AutomaticReduction& r;
    typename Editor::Checkpoint cp;
    double angleBefore;
    Guard(AutomaticReduction& ar, const std::vector<int>& around)
        : r(ar), cp(ar.ed_.Mark()), angleBefore(ar.MinAngleAround(around)) {
      ++r.guardDepth_;
    }
    ~Guard() {
      if (--r.guardDepth_ == 0) r.removed_.clear();
    }
    Guard(const Guard&) = delete;
    Guard& operator=(const Guard&) = delete;
    bool Accept(const std::vector<int>& touched) {
      // A protected vertex next to a changed one would see one of its faces change (a
      // collapse or split re-points the faces around the vertex it removes or splits).
      if (!r.opt_.frozen.empty()) {
        std::vector<int> live;
        for (int t : touched)
          if (r.ed_.IsLive(t)) live.push_back(t);
        for (int x : KRing(r.m_, live, 1))
          if (r.Frozen(x)) {
            Undo();
            return false;
          }
      }
      const double after = r.MinAngleAround(touched);
      if (after < std::min(r.opt_.minAngleDeg, angleBefore) || r.DeviationAround(touched) > r.budget_) {
        Undo();
        return false;
      }
      ++r.epoch_;
      for (int t : touched) Stamp(r.editedAt_, t, r.epoch_);
      if (r.guardDepth_ == 1) {
        // outermost edit kept: count it and forget its undo log (memory O(one edit))
        r.UpdateCount(touched);
        r.UpdateCount(r.removed_);
        r.ed_.Commit();
      }
      return true;
    }
    void Undo() { r.ed_.RollbackTo(cp); }
  };

  /// The final relaxation of everything not frozen: global (eq. 5) if asked, kept only if it
  /// does not lower the smallest angle (the global solve equalizes lengths and angles on
  /// average and can squeeze a few triangles next to the remaining irregular vertices), then
  /// local sweeps, which never lower the smallest angle around a vertex.
  void FinalRelax() {
    std::vector<int> all;
    for (size_t i = 0; i < m_.vert.size(); ++i)
      if (ed_.IsLive(int(i)) && !Frozen(int(i))) all.push_back(int(i));
    if (opt_.finalRelax == RelaxMode::Global) {
      const double before = MeasureShape(m_).minAngleDeg;
      std::vector<CoordType> saved;
      for (int v : all) saved.push_back(ed_.V(v)->P());
      RelaxOptions go;
      go.mode = RelaxMode::Global;
      go.iterations = opt_.globalRelaxRounds;
      irregular::Relax(m_, all, &original_, go);
      if (MeasureShape(m_).minAngleDeg < before) {
        for (size_t i = 0; i < all.size(); ++i) ed_.V(all[i])->P() = saved[i];
        globalKept_ = false;
      }
    }
    std::vector<CoordType> beforeSweeps;
    for (int v : all) beforeSweeps.push_back(ed_.V(v)->P());
    RelaxOptions lo;
    lo.iterations = opt_.finalLocalSweeps;
    LocalRelax(m_, all, &original_, lo);
    for (auto& f : m_.face)
      if (!f.IsD()) f.N() = vcg::TriangleNormal(f).Normalize();
    // The sweeps are not checked vertex by vertex against the Hausdorff budget (sharp creases
    // get rounded a little): measure once and keep the edited positions if they overshoot.
    if (opt_.finalLocalSweeps > 0 && HausdorffPercent(m_, original_) > opt_.hausdorffBudgetPercent) {
      for (size_t i = 0; i < all.size(); ++i) ed_.V(all[i])->P() = beforeSweeps[i];
      for (auto& f : m_.face)
        if (!f.IsD()) f.N() = vcg::TriangleNormal(f).Normalize();
      sweepsKept_ = false;
    }
  }

  MeshType& m_;
  const SurfaceProjector& original_;
  ReductionOptions opt_;
  Editor ed_;
  CompositeOperations<MeshType> comp_;
  AtomicOperations<MeshType>& ops_;
  double budget_ = 0;          ///< per-edit Hausdorff budget (absolute), tightened by retries
  double samplesPerEdge_ = 0;  ///< input samples per edge length besides sharp edges, raised by retries
  SampleGrid originalSamples_;  ///< the input's vertices and face centroids, for DeviationAround()
  bool globalKept_ = true;
  bool sweepsKept_ = true;
  long epoch_ = 0;                       ///< accepted edits so far
  std::vector<long> editedAt_, failedAt_;  ///< per vertex: epoch of its last accepted edit / failed attempt
  std::vector<int> exclude_;  ///< Reduces(): irregular vertices a removal must not involve
  int maxSurvivors_ = 1 << 20;  ///< Reduces(): most irregular vertices a removal may leave
  std::chrono::steady_clock::time_point t0_;
  EditJournal<MeshType> snapshot_{m_};  ///< the input, for the whole-run undo (TakeSnapshot)
  typename EditJournal<MeshType>::Checkpoint snapshotMark_;
  int guardDepth_ = 0;                  ///< Guards alive (nested edits); the outermost commits
  std::vector<char> isIrregular_;       ///< per vertex: counted in irregular_
  int irregular_ = 0;                   ///< interior irregular vertices now (running count)
  std::vector<int> removed_;            ///< vertices deleted by the edits of the current Guard
};

}  // namespace irregular
}  // namespace vcg_ext
