// filter_irregular: the edit guard of the automatic reduction (automatic_reduction.h). Every
// edit is relaxed locally (RelaxAround) and kept only if, around it:
//   * no triangle has an angle under the bound (unless one already had before the edit): this
//     is what keeps the irregular vertices the surface needs (a v5 on an ear tip cannot be
//     cancelled without squeezing the triangles there); a triangle with a vertex on a crease
//     line has a bound lower by opt.creaseAngleSlackDeg, as relaxation never moves that vertex;
//   * the faces stay within the Hausdorff budget of the input surface, both ways
//     (DeviationAround: the edited faces to the input, and the input's samples (sampling:
//     its sharp edges, optionally its whole surface thinned) to the edited faces); the
//     samples on crease lines (crease_lines.h: at least opt.creaseMinEdges connected edges
//     sharper than opt.creaseDeg) are held to the much smaller crease budget, so that an
//     edit cannot cut a crease;
//   * no protected (frozen) vertex sees one of its faces change.
// The angle allowance (ReductionOptions::angleAllowancePercent, default 0.8% of the triangles):
// an edit that fails the angle bound may still pass if its angles stay at or above
// angleFloorDeg (a triangle at a crease line keeps its own bound) and the mesh's count of
// triangles under the bound stays within the allowance. Callers with an angle repair (routes,
// aggregations) ask for it only once the repair failed (GuardedEdit::VerdictWithinAllowance).
// The count (UnderBound) is kept per face slot: a flag per slot says "under the bound" as of
// the last committed edit. The faces an edit in progress may have changed (the 2-rings gathered
// before it and at each verdict, nested edits included: the dirty set) are compared with their
// flags when a verdict needs the count (one that fails the bound: O(the faces dirty so far in
// the outermost edit), so a transport of L steps judged at each step costs O(L^2) face checks
// at worst), and their flags are refreshed when the outermost edit is kept. Recount (one O(F)
// pass, once per sweep) makes it exact again where a change went past those faces (the final
// polish, the boundary stage's relaxation between steps).
// GuardedEdit is the scope of one edit: it remembers the journal checkpoint and the angle
// before, and Accept() keeps or rolls back. Costs O(the edit's 2-ring) per check.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>
#include <vector>
#include <utility>

#include <vcg/space/distance3.h>

#include "crease_line_edges.h"
#include "graph_ops.h"
#include "reduction_options.h"
#include "reduction_state.h"
#include "relaxation.h"
#include "sample_grid.h"
#include "surface_projector.h"

namespace vcg_ext {
namespace irregular {

/// Why the guard refused an edit.
enum class GuardVerdict { Kept = 0, Frozen = 1, Angle = 2, Hausdorff = 3, Boundary = 4 };

template <class MeshType>
class GuardedEdit;

template <class MeshType>
class EditGuard {
 public:
  typedef MeshEditor<MeshType> Editor;
  typedef typename MeshType::CoordType CoordType;
  typedef typename MeshType::FaceType FaceType;

  /// The per-edit check samples the input side on its sharp edges (and, if asked, at
  /// hausdorffSamplesPerEdge points per edge elsewhere): between samples the true distance can
  /// be higher, so a tenth of the budget is kept back; the driver measures the result and
  /// redoes the run if it still overshoots (Tighten).
  /// crease: per vertex index, 1 = never moved by RelaxAround (null: none). inputCrease: per
  /// vertex index of the input (the projector's mesh), 1 on the crease lines the run keeps sharp;
  /// only those lines' samples get the crease budget (null: every crease line's,
  /// CreaseLineEdgesOfSoup). Both outlive the guard.
  EditGuard(MeshType& m, const SurfaceProjector& original, const ReductionOptions& opt, Editor& ed,
            ReductionState<MeshType>& state, const std::vector<char>* crease = nullptr,
            const std::vector<char>* inputCrease = nullptr)
      : m_(m), original_(original), opt_(opt), ed_(ed), state_(state), crease_(crease), inputCrease_(inputCrease) {
    if (!inputCrease_) {
      ownInputCrease_ = LineVertices(CreaseLineEdgesOfSoup(original.Mesh(), opt_.creaseDeg, opt_.creaseMinEdges,
                                                           opt_.creaseStraightShare),
                                     original.Mesh().vert.size());
      inputCrease_ = &ownInputCrease_;
    }
    budget_ = 0.9 * opt_.hausdorffBudgetPercent / 100.0 * double(original.Diagonal());
    creaseBudget_ = opt_.creaseBudgetPercent / 100.0 * double(original.Diagonal());
    boundCos_ = std::cos(opt_.minAngleDeg * M_PI / 180);
    BuildInputSamples(samplesPerEdge_ = opt_.hausdorffSamplesPerEdge);
  }

  /// Stricter per-edit checks for a retry: the budget scaled by `factor`, and the input
  /// sampled all over (2 per edge length) if it was not already.
  void Tighten(double factor) {
    budget_ *= factor;
    if (samplesPerEdge_ < 2) BuildInputSamples(samplesPerEdge_ = 2);
  }

  double Budget() const { return budget_; }
  /// Input samples that a witness showed harmless (Deviation), over the guard's life: for the
  /// tests, which check that the shortcut is taken.
  size_t WitnessHits() const { return witnessHits_; }
  /// Drops every witness, seeds included: the next checks search, as a guard without
  /// witnesses would (the tests compare the two verdicts).
  void ForgetWitnesses() { std::fill(sampleWitness_.begin(), sampleWitness_.end(), -1); }
  Editor& ed() { return ed_; }
  const ReductionOptions& options() const { return opt_; }
  ReductionState<MeshType>& state() { return state_; }

  /// The verdict on an edit that touched `touched`, given the smallest angle around it before.
  /// allowance: false judges by the angle bound alone, as without an allowance (a caller that
  /// can still repair the angles first: GuardedEdit::RepairAngles); forceAllowance: the edit
  /// must pass the allowance's test (floor and count) even where it keeps the bound "no worse
  /// than before" (after a repair that required the minimum itself).
  GuardVerdict Judge(const std::vector<int>& touched, double angleBefore, bool allowance = true,
                     bool forceAllowance = false) {
    // A protected vertex next to a changed one would see one of its faces change (a collapse
    // or split re-points the faces around the vertex it removes or splits).
    if (!opt_.frozen.empty()) {
      const std::vector<int> live = LiveOf(touched);
      for (int x : KRing(m_, live, 1))
        if (state_.Frozen(x)) return GuardVerdict::Frozen;
    }
    // More boundary irregular vertices than the input had (by the corner rule): the edit
    // moved curvature into a regular stretch of boundary without cancelling any there.
    if (state_.BoundaryIrregular() + state_.BoundaryDelta(touched) > state_.BoundaryLimit())
      return GuardVerdict::Boundary;
    // the angle check and the distance check look at the same region and faces: gathered once
    std::vector<int>& region = region_;
    std::vector<const FaceType*>& changed = changed_;
    GatherChanged(touched, region, changed);
    double atCrease = 180;
    const double elsewhere = MinAngleOf(changed, &atCrease);
    if (allowance_ > 0) MarkDirty(changed);
    if (forceAllowance || elsewhere < std::min(opt_.minAngleDeg, angleBefore) ||
        atCrease < std::min(opt_.minAngleDeg - opt_.creaseAngleSlackDeg, angleBefore)) {
      // the allowance: a floor instead of the bound, while the mesh's count allows; not at a
      // crease line, whose vertices no relaxation moves, so no later sweep can lift a thin
      // triangle there (fandisk at 20K, the allowance asked before the repair: 191 irregular
      // vertices left with the floor there too, 0.95%, smallest angle 16 degrees; 148 without,
      // 24.5 degrees)
      const double floor = std::min(opt_.angleFloorDeg, opt_.minAngleDeg);
      const bool allowed = allowance && allowance_ > 0 && elsewhere >= std::min(floor, angleBefore) &&
                           atCrease >= std::min(opt_.minAngleDeg - opt_.creaseAngleSlackDeg, angleBefore) &&
                           underBound_ + DirtyChange() <= allowance_;
      if (!allowed) return GuardVerdict::Angle;
    }
    double crease = 0;
    if (Deviation(region, changed, &crease, false) > budget_ || crease > creaseBudget_) return GuardVerdict::Hausdorff;
    return GuardVerdict::Kept;
  }

  /// The mesh's triangles with an angle under minAngleDeg as of the last committed edit (exact
  /// up to changes made outside guarded edits since the last Recount).
  long UnderBound() const { return underBound_; }
  /// How many the allowance lets there be (0: no allowance).
  long Allowance() const { return allowance_; }
  /// Counts the triangles under the bound over the whole mesh, sets every slot's flag, and the
  /// allowance from the live face count: one O(F) pass, for the driver between sweeps, never
  /// per edit.
  void Recount() {
    long n = 0, faces = 0;
    underFlag_.assign(m_.face.size(), 0);
    for (size_t i = 0; i < m_.face.size(); ++i) {
      const FaceType& f = m_.face[i];
      if (f.IsD()) continue;
      ++faces;
      n += underFlag_[i] = UnderTheBound(f);
    }
    ForgetDirty();
    underBound_ = n;
    allowance_ = opt_.angleAllowancePercent > 0 ? long(opt_.angleAllowancePercent / 100 * double(faces)) : 0;
  }

  /// Local relaxation (sec. 8) of the 2-ring of the seeds, journaled so the guard can undo it.
  /// Boundary vertices stay, unless slideAlong is given: then those whose corner is nearly
  /// straight slide along it (LocalRelax, RelaxOptions::boundaryCurve), for edits on the
  /// boundary.
  void RelaxAround(const std::vector<int>& seeds, const BoundaryCurve* slideAlong = nullptr) {
    const bool gathered = Gathered(seeds);
    const std::vector<int> live = gathered ? std::vector<int>() : LiveOf(seeds);
    if (gathered ? region_.empty() : live.empty()) return;
    std::vector<int> ring = gathered ? region_ : KRing(m_, live, 2), movable;
    for (int v : ring)
      if (!state_.Frozen(v)) movable.push_back(v);
    // each face once (0.9.19; a face has three vertices in the ring): nothing changes between
    // the saves, so one record restores it as three would. The gathered faces are those, in
    // the same order, when every vertex of the ring moves.
    if (gathered && movable.size() == ring.size()) {
      for (int v : movable) ed_.journal().SaveVertex(ed_.V(v));
      for (const FaceType* f : changed_) ed_.journal().SaveFace(const_cast<FaceType*>(f));
    } else {
      relaxFaceSeen_.Begin(m_.face.size());
      for (int v : movable) {
        ed_.journal().SaveVertex(ed_.V(v));
        for (auto& c : ed_.Star(v).corners)
          if (relaxFaceSeen_.Insert(size_t(c.f - &m_.face[0]))) ed_.journal().SaveFace(c.f);
      }
    }
    RelaxOptions ro;
    ro.iterations = opt_.localRelaxIterations;
    ro.boundaryCurve = slideAlong;
    LocalRelax(m_, movable, &original_, ro, crease_);  // crease vertices stay: moving them rounds the crease
  }

  /// Does an edge around the 2-ring of the seeds join faces whose normals differ by more than
  /// maxTurnDeg (a triangle turned over)? For edits made without the per-step fold check.
  bool FoldsAround(const std::vector<int>& seeds, double maxTurnDeg = 120) {
    const double c = std::cos(maxTurnDeg * M_PI / 180.0);
    auto folds = [&](const FaceType* f) {
      const CoordType n0 = vcg::TriangleNormal(*f);
      for (int z = 0; z < 3; ++z) {
        const FaceType* g = f->cFFp(z);
        if (g == f) continue;
        const CoordType n1 = vcg::TriangleNormal(*g);
        const double d = double(n0.Norm()) * double(n1.Norm());
        if (d == 0 || double(n0.dot(n1)) / d < c) return true;
      }
      return false;
    };
    if (Gathered(seeds)) {  // the same faces, each once
      for (const FaceType* f : changed_)
        if (folds(f)) return true;
      return false;
    }
    for (int v : KRing(m_, LiveOf(seeds), 2))
      for (auto& cr : ed_.Star(v).corners)
        if (folds(cr.f)) return true;
    return false;
  }

  /// While one of these lives, the caller promises not to change the mesh's topology (only
  /// positions: relaxation, angle repair): the 2-ring of a set of seeds and its faces
  /// (GatherChanged) are then gathered once and reused by every question about the same seeds
  /// (CutsCrease, RelaxAround, FoldsAround, Judge, ...). A transport's route asked them four
  /// to six times in a row, each a walk of the ring and of every star in it.
  class SameTopology {
   public:
    explicit SameTopology(EditGuard& g) : g_(g) { g_.memo_ = Memo{true, false, {}}; }
    ~SameTopology() { g_.memo_ = Memo(); }
    SameTopology(const SameTopology&) = delete;
    SameTopology& operator=(const SameTopology&) = delete;

   private:
    EditGuard& g_;
  };
  /// Is the gathering of these seeds at hand (within a SameTopology, gathered since)?
  bool Gathered(const std::vector<int>& seeds) const { return memo_.active && memo_.valid && memo_.seeds == seeds; }

  /// Smallest angle (degrees) of the faces around the 2-ring of the seeds. With atCrease, the
  /// faces with a vertex on a crease line count there instead (*atCrease: their smallest angle,
  /// left as it was when there is none).
  /// Each face once (GatherChanged), and the largest corner cosine turned into an angle once
  /// per side: acos is decreasing and correctly rounded, so this is the smallest of the faces'
  /// MinAngle, to the bit, at one acos per call instead of one per face and star it lies in.
  double MinAngleAround(const std::vector<int>& seeds, double* atCrease = nullptr) {
    GatherChanged(seeds, region_, changed_);
    return MinAngleOf(changed_, atCrease);
  }

  /// MinAngleAround(seeds) (no crease split), and in *sharp the vertices of the faces around
  /// the 2-ring of the seeds with an angle under `deg` (sorted, each once): one gather of the
  /// region for both, as the angle repair rounds of a refused route need both.
  double MinAngleAndSharpCorners(const std::vector<int>& seeds, double deg, std::vector<int>* sharp) {
    GatherChanged(seeds, region_, changed_);
    sharp->clear();
    const double c = std::cos(deg * M_PI / 180);
    double maxCos = -2;
    for (const FaceType* f : changed_) {
      const double fc = relax_detail::MaxCornerCos(f);
      maxCos = std::max(maxCos, fc);
      if (fc > c)
        for (int z = 0; z < 3; ++z) sharp->push_back(ed_.Index(f->cV(z)));
    }
    std::sort(sharp->begin(), sharp->end());
    sharp->erase(std::unique(sharp->begin(), sharp->end()), sharp->end());
    return maxCos > -2 ? std::min(180.0, AngleOfCos(maxCos)) : 180;
  }

  /// How many faces around the 2-ring of the seeds (each once) have an angle under `deg`.
  int CountBelowAround(const std::vector<int>& seeds, double deg) {
    GatherChanged(seeds, region_, changed_);
    int n = 0;
    for (const FaceType* f : changed_) n += MinAngle(f) < deg;
    return n;
  }

  /// The dirty set (see the header) starts empty: the outermost guarded edit ended.
  /// Committed: its faces' flags are refreshed and the count moves by their change.
  void EndDirty(bool committed) {
    if (committed) underBound_ += DirtyChange(true);
    ForgetDirty();
  }
  /// Adds the faces to the dirty set (see the header).
  void MarkDirty(const std::vector<const FaceType*>& faces) {
    if (dirtyMark_.size() < m_.face.size()) dirtyMark_.resize(m_.face.size(), 0);
    for (const FaceType* f : faces) {
      const size_t i = size_t(f - &m_.face[0]);
      if (!dirtyMark_[i]) dirtyMark_[i] = 1, dirty_.push_back(int(i));
    }
  }

  /// MinAngleAround(touched, atCrease) right after Judge(touched) passed it, with nothing
  /// edited since: the faces that verdict gathered, without gathering them again.
  double MinAngleOfJudged(double* atCrease) const { return MinAngleOf(changed_, atCrease); }

  /// Has f a vertex on one of the input's crease lines (vertices created since are not)?
  bool OnCreaseLine(const FaceType* f) const {
    if (!crease_) return false;
    for (int z = 0; z < 3; ++z) {
      const size_t i = size_t(f->cV(z) - &m_.vert[0]);
      if (i < crease_->size() && (*crease_)[i]) return true;
    }
    return false;
  }

  /// Smallest angle of f in degrees (0 with a zero-length edge): one acos per face
  /// (relaxation.h relax_detail::MaxCornerCos).
  static double MinAngle(const FaceType* f) { return AngleOfCos(relax_detail::MaxCornerCos(f)); }
  /// The angle in degrees whose cosine is c (clamped to [-1, 1]).
  static double AngleOfCos(double c) { return std::acos(std::max(-1.0, std::min(1.0, c))) * 180 / M_PI; }

  /// Local symmetric Hausdorff distance between the edited faces around the seeds and the
  /// input surface: (a) the faces' edge midpoints and centroids to the input (their vertices
  /// lie on it after projection), and (b) the input's samples on sharp edges (see the
  /// constructor) over each edited star to the edited faces of one more ring (so a sample
  /// near the border still finds its closest edited face). (b) is what catches a crease or a
  /// tip cut off by an edit. Only "above the budget or not" matters, so (a) stops at the
  /// first excess. *crease: the largest deviation of (b)'s samples on creases.
  double DeviationAround(const std::vector<int>& seeds, double* crease) {
    GatherChanged(seeds, region_, changed_);
    return Deviation(region_, changed_, crease, false);
  }

  /// Does the edit around the seeds leave a sample of the input's crease lines farther than
  /// the crease budget from the edited faces ((b) of DeviationAround, crease samples only)?
  /// For an edit not yet relaxed: a cut crease stays cut, as relaxation never moves crease
  /// vertices and projects the others back onto the input on their own side. fandisk at 20K:
  /// of 3916 transport routes this flagged before their relaxation, 6 passed the guard after
  /// it (1792 were refused for the crease budget, 2062 for angles, 56 folded); of the 4784 it
  /// did not flag, 19 were refused for the distance. Cheap: no query at all when no crease
  /// sample lies near the edit.
  bool CutsCrease(const std::vector<int>& seeds) {
    double crease = 0;
    GatherChanged(seeds, region_, changed_);
    Deviation(region_, changed_, &crease, true);
    return crease > creaseBudget_;
  }

 private:
  /// The part of the mesh an edit around the seeds changes: the local relaxation after an edit
  /// moves its 2-ring (region: the 2-ring of the live seeds), which changes the faces around it
  /// (changed: each once, in the order the stars give them; faceSeen_ holds them).
  /// region and changed are always region_ and changed_ (the memo of SameTopology holds them).
  void GatherChanged(const std::vector<int>& seeds, std::vector<int>& region, std::vector<const FaceType*>& changed) {
    if (Gathered(seeds)) {
      // Deviation adds faces to faceSeen_: it is refilled with the gathered faces alone
      faceSeen_.Begin(m_.face.size());
      for (const FaceType* f : changed) faceSeen_.Insert(size_t(f - &m_.face[0]));
      return;
    }
    region = KRing(m_, LiveOf(seeds), 2);
    changed.clear();
    faceSeen_.Begin(m_.face.size());
    for (int v : region)
      for (auto& c : ed_.Star(v).corners)
        if (faceSeen_.Insert(size_t(c.f - &m_.face[0]))) changed.push_back(c.f);
    if (memo_.active) {
      memo_.valid = true;
      memo_.seeds = seeds;
    }
  }

  /// Smallest angle (degrees) of the faces; with atCrease, those with a vertex on a crease
  /// line count there instead (see MinAngleAround).
  double MinAngleOf(const std::vector<const FaceType*>& faces, double* atCrease) const {
    double maxCos = -2, maxCosCrease = -2;  // -2: no face seen
    for (const FaceType* f : faces) {
      double& into = atCrease && OnCreaseLine(f) ? maxCosCrease : maxCos;
      into = std::max(into, relax_detail::MaxCornerCos(f));
    }
    if (atCrease && maxCosCrease > -2) *atCrease = std::min(*atCrease, AngleOfCos(maxCosCrease));
    return maxCos > -2 ? std::min(180.0, AngleOfCos(maxCos)) : 180;
  }

  /// DeviationAround over what GatherChanged gave (faceSeen_ as it left it); creaseOnly: (b)
  /// only, over the crease samples only (CutsCrease).
  double Deviation(const std::vector<int>& region, const std::vector<const FaceType*>& changed, double* crease,
                   bool creaseOnly) {
    std::vector<const FaceType*>& all = scratch_.all;  // buffers reused from edit to edit
    all.clear();
    auto seenInsert = [&](const FaceType* f) { return faceSeen_.Insert(size_t(f - &m_.face[0])); };
    // (a) each changed face's centroid and edge midpoints (an edge shared by two changed faces
    // once) against the input; a query looks no farther than just past the budget
    const float reach = float(1.01 * budget_) + 1e-12f;
    double mx = 0;
    // Consecutive probes lie on one face or its neighbour: the input face found closest for
    // the last one usually keeps the next within the budget, and then the search is skipped
    // (as OneSidedHausdorff does, quality.h). The verdict is the same: the true distance is at
    // most that face's, and the radius is the largest float not above the budget. Such a
    // probe leaves mx as it is, which the callers never see beyond "above the budget or not".
    float within = float(budget_);
    if (double(within) > budget_) within = std::nextafter(within, 0.f);
    // Failing that, the input faces relaxation last projected the probe's corners onto
    // (SurfaceProjector::VertexHint): a centroid or midpoint of corners on the input surface
    // lies within the surface's bulge of them, and most probes then need no search (callgrind,
    // native bench, bunny00 at 20K: this check's instructions 4.82 G -> 2.80 G, the same verdicts).
    const proj_detail::PFace* hint = nullptr;
    auto probe = [&](const CoordType& p, const FaceType* around, int z0, int z1) {
      const vcg::Point3f q = vcg::Point3f::Construct(p);
      size_t corners[3];
      for (int z = z0; z <= z1; ++z) corners[z - z0] = size_t(around->cV(z % 3) - &m_.vert[0]);
      if (original_.NearHints(hint, q, within, corners, size_t(z1 - z0 + 1))) return true;
      float d = 0;
      const proj_detail::PFace* f = nullptr;
      original_.ClosestFrom(hint, q, &d, nullptr, reach, &f);
      if (f != nullptr) hint = f;
      mx = std::max(mx, double(d));
      return mx <= budget_;
    };
    for (size_t k = 0; k < changed.size() && !creaseOnly; ++k) {
      const FaceType* f = changed[k];
      if (!probe(CoordType((f->cP(0) + f->cP(1) + f->cP(2)) / 3), f, 0, 2)) return mx;
      for (int z = 0; z < 3; ++z) {
        const FaceType* g = f->cFFp(z);
        if (g != f && g < f && faceSeen_.Contains(size_t(g - &m_.face[0]))) continue;  // probed from g
        if (!probe(CoordType((f->cP(z) + f->cP((z + 1) % 3)) / 2), f, z, z + 1)) return mx;
      }
    }
    // (b) the input samples near the changed faces against the edited surface there. Most
    // edits have none near them (samples sit on sharp edges): look them up first, and build
    // the face hash below only when there is one. A sample off the edited surface (a cut
    // crease) lies outside its face's box: the boxes are widened; deviations grow edit by
    // edit, so catching them below twice the budget suffices.
    // One grid query over the union of the faces' widened boxes, then each sample found kept
    // if it lies in one of them: the same samples as a query per face, at one query per edit.
    std::vector<int>& near = scratch_.near;
    near.clear();
    {
      std::vector<vcg::Box3<float>>& faceBoxes = scratch_.faceBoxes;
      faceBoxes.clear();
      vcg::Box3<float> all;
      for (const FaceType* f : changed) {
        vcg::Box3<float> b;
        for (int z = 0; z < 3; ++z) b.Add(vcg::Point3f::Construct(f->cP(z)));
        b.Offset(float(2 * budget_));
        faceBoxes.push_back(b);
        all.Add(b);
      }
      originalSamples_.InBox(all, scratch_.inBox);
      for (int i : scratch_.inBox) {
        if (creaseOnly && originalSamples_.Tag(i) == 0) continue;
        for (const vcg::Box3<float>& b : faceBoxes)
          if (b.IsIn(originalSamples_.Point(i))) {
            near.push_back(i);
            break;
          }
      }
    }
    // A sample that a face of the mesh showed harmless before (sampleWitness_) usually still
    // is: if that face, wherever it is, is still within the sample's bound (and faces its
    // side), the sample is within it of the edited surface, so harmless (the search below
    // asks only for some face within the bound). Two gains (0.9.21):
    //   * edits that keep failing in one place test the same samples again and again: when
    //     every sample near the edit has such a witness, the face hash below is not built;
    //   * the search sees only the faces around the edit: a sample on a sharp edge of a thin
    //     part whose own face lies outside them was closest to an edited face across the part
    //     (one of the sharp edge's face normals faces it) and refused the edit, although its
    //     own face lies within its bound. Its witness passes it, as the whole mesh would.
    //     Native bench at 20K: the bull 623 -> 531 left, the camel 324 -> 208, armadillo
    //     186 -> 144; 2200 -> 1725 refusals for the distance on the bull.
    {
      size_t k = 0;
      for (int i : near)
        if (!Witnessed(i)) near[k++] = i;
      witnessHits_ += near.size() - k;
      near.resize(k);
    }
    if (near.empty()) return mx;
    // The faces are hashed on a grid so each sample is compared with the faces around it
    // only: O(region) for any edit size. Faces of one more ring are included so a sample by the
    // border finds its true closest face; only samples closest to a changed face count, and
    // only on the same side (a thin part's other sheet is not this edit's business).
    all = changed;
    for (int v : KRing(m_, region, 1))
      for (auto& c : ed_.Star(v).corners)
        if (seenInsert(c.f)) all.push_back(c.f);
    const float cellSize = float(std::max(2 * budget_, 1e-12));
    auto key = [&](int64_t x, int64_t y, int64_t z) {
      return (uint64_t(x & 0x1FFFFF) << 42) | (uint64_t(y & 0x1FFFFF) << 21) | uint64_t(z & 0x1FFFFF);
    };
    auto cellOf = [&](float x) { return int64_t(std::floor(x / cellSize)); };
    // (cell key, face) pairs sorted by key then face: each cell's faces in increasing face
    // order, as a hash map of per-cell vectors filled face by face would hold them, without
    // a heap allocation per cell (the buffer is reused from edit to edit)
    std::vector<std::pair<uint64_t, int>>& faceCells = scratch_.faceCells;
    faceCells.clear();
    std::vector<vcg::Triangle3<float>>& tri = scratch_.tri;
    std::vector<vcg::Box3<float>>& boxes = scratch_.boxes;
    tri.clear();
    boxes.clear();
    for (size_t k = 0; k < all.size(); ++k) {
      const FaceType* f = all[k];
      tri.emplace_back(vcg::Point3f::Construct(f->cP(0)), vcg::Point3f::Construct(f->cP(1)),
                       vcg::Point3f::Construct(f->cP(2)));
      vcg::Box3<float> b;
      for (int z = 0; z < 3; ++z) b.Add(tri.back().P(z));
      boxes.push_back(b);
      for (int64_t x = cellOf(b.min[0]); x <= cellOf(b.max[0]); ++x)
        for (int64_t y = cellOf(b.min[1]); y <= cellOf(b.max[1]); ++y)
          for (int64_t z = cellOf(b.min[2]); z <= cellOf(b.max[2]); ++z) faceCells.emplace_back(key(x, y, z), int(k));
    }
    std::sort(faceCells.begin(), faceCells.end());
    // A face spans several cells: measured once per sample (lastSample); and not at all when
    // its box is already farther than the closest face so far (the distance to a triangle is
    // at least the distance to its box; the margin covers rounding), which cannot change the
    // closest face found.
    std::vector<int>& lastSample = scratch_.lastSample;
    lastSample.assign(all.size(), -1);
    auto boxDistance = [&](const vcg::Box3<float>& b, const vcg::Point3f& p) {
      float d2 = 0;
      for (int a = 0; a < 3; ++a) {
        const float e = std::max({b.min[a] - p[a], 0.f, p[a] - b.max[a]});
        d2 += e * e;
      }
      return std::sqrt(d2);
    };
    // Only "above the budget or not" matters: a sample with any face within its bound (the
    // budget; on a crease also the crease budget) cannot be farther than that from its
    // closest face, whichever that is, so it is harmless and its search stops there. The face
    // that showed the last sample harmless is tried first (consecutive samples are close):
    // on meshes with many sharp edges (thin parts) most samples then cost one distance.
    int sampleHint = -1;
    auto harmless = [&](int t, const vcg::Point3f& p, float bound) {
      float d;
      vcg::Point3f q;
      vcg::TrianglePointDistance(tri[size_t(t)], p, d, q);
      return d <= bound;
    };
    // A sample counts only if its closest face is a changed one on its side (below): one
    // facing away from every changed face (the other sheet of a thin part) cannot count.
    std::vector<vcg::Point3f>& changedNormals = scratch_.changedNormals;
    changedNormals.clear();
    for (size_t k = 0; k < changed.size(); ++k) {
      const vcg::Triangle3<float>& t = tri[k];
      changedNormals.push_back((t.P(1) - t.P(0)) ^ (t.P(2) - t.P(0)));
    }
    auto facesSome = [&](const vcg::Point3f& n) {
      for (const vcg::Point3f& fn : changedNormals)
        if (n.dot(fn) > 0) return true;
      return false;
    };
    for (int i : near) {
      const vcg::Point3f& p = originalSamples_.Point(i);
      const bool onCrease = originalSamples_.Tag(i) != 0;
      const float bound = SampleBound(i);
      if (sampleHint >= 0 && harmless(sampleHint, p, bound)) {
        sampleWitness_[size_t(i)] = int(all[size_t(sampleHint)] - &m_.face[0]);
        continue;
      }
      if (!originalSamples_.AnyNormal(i, facesSome)) continue;
      float best = std::numeric_limits<float>::max();
      int bestFace = -1;
      bool done = false;
      // faces within 2 * budget of p are in p's cell or the 26 around it
      for (int64_t x = cellOf(p[0]) - 1; x <= cellOf(p[0]) + 1 && !done; ++x)
        for (int64_t y = cellOf(p[1]) - 1; y <= cellOf(p[1]) + 1 && !done; ++y)
          for (int64_t z = cellOf(p[2]) - 1; z <= cellOf(p[2]) + 1 && !done; ++z) {
            const uint64_t cell = key(x, y, z);
            auto it = std::lower_bound(faceCells.begin(), faceCells.end(), std::make_pair(cell, -1));
            for (; it != faceCells.end() && it->first == cell; ++it) {
              const int t = it->second;
              if (lastSample[size_t(t)] == i) continue;
              lastSample[size_t(t)] = i;
              if (boxDistance(boxes[size_t(t)], p) > best * (1 + 1e-4f)) continue;
              float d;
              vcg::Point3f q;
              vcg::TrianglePointDistance(tri[size_t(t)], p, d, q);
              if (d <= bound) {
                sampleHint = t;
                sampleWitness_[size_t(i)] = int(all[size_t(t)] - &m_.face[0]);
                done = true;
                break;
              }
              if (d < best) best = d, bestFace = t;
            }
          }
      if (done) continue;
      // nothing within two budgets among the edited faces around: either the sample belongs
      // elsewhere (another part of the surface) or the edit moved away from it
      if (bestFace < 0) continue;
      if (size_t(bestFace) >= changed.size()) continue;  // closest to an unchanged face
      const vcg::Point3f& bestNormal = changedNormals[size_t(bestFace)];
      if (!Faces(i, bestNormal)) continue;
      // It was not harmless, so it is beyond its bound: the verdict is known
      mx = std::max(mx, double(best));
      if (onCrease) *crease = std::max(*crease, double(best));
      return mx;
    }
    return mx;
  }

  /// The bound of input sample i: the budget, on a crease line the crease budget if smaller.
  float SampleBound(int i) const {
    return float(originalSamples_.Tag(i) != 0 ? std::min(budget_, creaseBudget_) : budget_);
  }

  /// Does a face of normal n face input sample i's side (one of its normals within 90 degrees)?
  bool Faces(int i, const vcg::Point3f& n) const {
    return originalSamples_.AnyNormal(i, [&](const vcg::Point3f& sn) { return sn.dot(n) > 0; });
  }

  /// Is input sample i within its bound of the live face that last showed it harmless?
  bool Witnessed(int i) const {
    const int w = sampleWitness_[size_t(i)];
    if (w < 0 || size_t(w) >= m_.face.size() || m_.face[size_t(w)].IsD()) return false;
    const FaceType& f = m_.face[size_t(w)];
    const vcg::Triangle3<float> t(vcg::Point3f::Construct(f.cP(0)), vcg::Point3f::Construct(f.cP(1)),
                                  vcg::Point3f::Construct(f.cP(2)));
    const vcg::Point3f n = (t.P(1) - t.P(0)) ^ (t.P(2) - t.P(0));
    if (!Faces(i, n)) return false;
    float d;
    vcg::Point3f q;
    vcg::TrianglePointDistance(t, originalSamples_.Point(i), d, q);
    return d <= SampleBound(i);
  }

  /// The seeds an edit has not deleted (a collapse removes vertices that stay in `touched`).
  std::vector<int> LiveOf(const std::vector<int>& seeds) const {
    std::vector<int> live;
    for (int v : seeds)
      if (ed_.IsLive(v)) live.push_back(v);
    return live;
  }

  /// Input samples for the input-to-edited side of the Hausdorff check: the input's face
  /// centroids and vertices thinned to perEdge per edited edge length (none if 0), plus
  /// everything on its sharp edges (creases, tips), where an edit cuts corners. Oriented by
  /// their face.
  void BuildInputSamples(double perEdge) {
    const double h = MeanEdgeLength(m_);
    std::vector<vcg::Point3f> samples, normals;
    std::vector<char> onCrease;  // per sample: on a crease line (opt.creaseDeg)
    std::vector<int> source;     // per sample: the input's face it lies on
    SharpEdgeSamples(original_.Mesh(), opt_.sharpEdgeDeg, opt_.creaseDeg, *inputCrease_, samples, normals, onCrease,
                     &source);
    if (perEdge > 0) ThinnedSurfaceSamples(original_.Mesh(), h / perEdge, samples, normals, &source);
    onCrease.resize(samples.size(), 0);
    // a sample is a point and a face's normal: the points repeat (a vertex once per sharp edge
    // and face around it), and the grid merges them (sample_grid.h); the tag keeps crease
    // samples apart (their bound is the crease budget)
    std::vector<int> merged;
    originalSamples_.Build(samples, normals, h, onCrease, &merged);
    SeedWitnesses(source, merged);
  }

  /// Every sample's first witness: the face of the mesh it was taken from, when the mesh is
  /// still the input (the projector's faces are the mesh's live faces, in order). A sample
  /// lies on that face, so the first edit near it needs no search either, and the search's
  /// false refusals on thin parts (see Deviation) are avoided from the first edit on. A seed
  /// is only a candidate: Witnessed measures it as it measures any witness, so a mesh that
  /// is not the input (remeshed first, or edited before a retry's resampling) only loses the
  /// shortcut. O(faces + samples), once per sampling.
  void SeedWitnesses(const std::vector<int>& source, const std::vector<int>& merged) {
    sampleWitness_.assign(originalSamples_.Size(), -1);
    std::vector<int> live;  // the input's face k is the mesh's face live[k]
    live.reserve(original_.Mesh().face.size());
    for (size_t i = 0; i < m_.face.size(); ++i)
      if (!m_.face[i].IsD()) live.push_back(int(i));
    if (live.size() != original_.Mesh().face.size()) return;
    for (size_t k = 0; k < source.size() && k < merged.size(); ++k) {
      int& w = sampleWitness_[size_t(merged[k])];
      if (w < 0) w = live[size_t(source[k])];
    }
  }

  /// Ends and midpoints of the edges of m whose dihedral angle exceeds angleDeg, with the
  /// normal of each face along the edge; onCrease[i]: sample i lies on a crease line (an
  /// interior edge sharper than creaseDeg whose two ends lineVertex flags: a line's edge, as an
  /// edge that sharp joining two lines' vertices makes them one line; none when creaseDeg is 0);
  /// source (if given): the face of each. O(F log F).
  static void SharpEdgeSamples(const SurfaceProjector::PMesh& m, double angleDeg, double creaseDeg,
                               const std::vector<char>& lineVertex, std::vector<vcg::Point3f>& pts,
                               std::vector<vcg::Point3f>& nrm, std::vector<char>& onCrease,
                               std::vector<int>* source = nullptr) {
    // One flat array of half-edges sorted by (edge, face), not a map of vectors: the same
    // samples in the same order (the map's pointer keys ordered the vertices by index), and
    // 12 bytes per half-edge instead of a node and a vector per edge (at 1.2M faces the map
    // was a 190 MiB transient, part of the run's memory peak).
    struct HalfEdge {
      uint32_t a, b, f;  // vertex indices a < b, face index
    };
    std::vector<HalfEdge> he;
    he.reserve(3 * m.face.size());
    for (size_t i = 0; i < m.face.size(); ++i)
      for (int z = 0; z < 3; ++z) {
        uint32_t a = uint32_t(vcg::tri::Index(m, m.face[i].cV(z)));
        uint32_t b = uint32_t(vcg::tri::Index(m, m.face[i].cV((z + 1) % 3)));
        if (a > b) std::swap(a, b);
        he.push_back({a, b, uint32_t(i)});
      }
    std::sort(he.begin(), he.end(), [](const HalfEdge& x, const HalfEdge& y) {
      return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.f < y.f;
    });
    const double c = std::cos(angleDeg * M_PI / 180.0), cc = std::cos(creaseDeg * M_PI / 180.0);
    for (size_t i = 0, j = 0; i < he.size(); i = j) {
      for (j = i + 1; j < he.size() && he[j].a == he[i].a && he[j].b == he[i].b; ++j) {
      }
      // boundary and non-manifold edges are features too
      const double dot = j - i != 2 ? 1.0 : double(m.face[he[i].f].cN().dot(m.face[he[i + 1].f].cN()));
      const bool sharpCrease = creaseDeg > 0 && j - i == 2 && dot < cc;
      const bool crease =
          sharpCrease && he[i].b < lineVertex.size() && lineVertex[he[i].a] && lineVertex[he[i].b];
      const bool sharp = j - i != 2 || dot < c;
      if (!sharp) continue;
      const auto& a = m.vert[he[i].a];
      const auto& b = m.vert[he[i].b];
      for (size_t k = i; k < j; ++k)
        for (const vcg::Point3f& p : {a.cP(), b.cP(), vcg::Point3f((a.cP() + b.cP()) / 2.f)}) {
          pts.push_back(p);
          nrm.push_back(m.face[he[k].f].cN());
          onCrease.push_back(crease);
          if (source) source->push_back(int(he[k].f));
        }
    }
  }

  /// Face centroids and corners of m, at most one per cell of a grid of the given spacing;
  /// source (if given): the face of each.
  static void ThinnedSurfaceSamples(const SurfaceProjector::PMesh& m, double spacing, std::vector<vcg::Point3f>& pts,
                                    std::vector<vcg::Point3f>& nrm, std::vector<int>* source = nullptr) {
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
          if (source) source->push_back(int(&f - &m.face[0]));
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

  MeshType& m_;
  const SurfaceProjector& original_;
  const ReductionOptions& opt_;
  Editor& ed_;
  ReductionState<MeshType>& state_;
  const std::vector<char>* crease_;  ///< vertices RelaxAround never moves (the input's crease lines)
  const std::vector<char>* inputCrease_;  ///< the input's crease lines kept sharp, by its vertex index
  std::vector<char> ownInputCrease_;      ///< ... all of them, when the guard was given none
  double budget_ = 0;           ///< per-edit Hausdorff budget (absolute), tightened by retries
  double creaseBudget_ = 0;     ///< per-edit budget of the crease samples (absolute)
  double samplesPerEdge_ = 0;   ///< input samples per edge length besides sharp edges, raised by retries
  SampleGrid originalSamples_;  ///< the input's samples, for DeviationAround()
  StampSet faceSeen_;           ///< GatherChanged's set of the faces it gathered (and Deviation's after it)
  StampSet relaxFaceSeen_;      ///< RelaxAround: the faces it journaled
  std::vector<int> region_;     ///< GatherChanged's region, reused from call to call
  std::vector<const FaceType*> changed_;  ///< ... and its faces
  /// SameTopology's memo: region_ and changed_ are the gathering of `seeds` (valid), reusable
  /// while the topology does not change (active).
  struct Memo {
    bool active = false, valid = false;
    std::vector<int> seeds;
  } memo_;
  /// Deviation's buffers, kept so an edit's check allocates nothing once they have grown.
  struct DeviationScratch {
    std::vector<std::pair<uint64_t, int>> faceCells;  ///< all's faces by grid cell
    std::vector<vcg::Point3f> changedNormals;          ///< the changed faces' normals
    std::vector<const FaceType*> all;        ///< the changed faces and one more ring
    std::vector<int> near, inBox;            ///< input samples near the changed faces; a grid query's
    std::vector<vcg::Box3<float>> faceBoxes; ///< the changed faces' widened boxes
    std::vector<vcg::Triangle3<float>> tri;  ///< all's triangles ...
    std::vector<vcg::Box3<float>> boxes;     ///< ... and their boxes
    std::vector<int> lastSample;             ///< per face of all: the last sample measured against it
  } scratch_;
  friend class GuardedEdit<MeshType>;
  std::vector<int> sampleWitness_;  ///< per input sample: the face (index) that last showed it harmless, or -1
  // the angle allowance (see the header)
  long underBound_ = 0;             ///< triangles under minAngleDeg, committed (the sum of underFlag_)
  long allowance_ = 0;              ///< the most the allowance lets there be (0: none)
  double boundCos_ = 1;             ///< cos(minAngleDeg): a face is under the bound if its largest corner cosine is above
  std::vector<char> underFlag_;     ///< per face slot: under the bound as of the last commit
  std::vector<int> dirty_;          ///< face slots an edit in progress may have changed
  std::vector<char> dirtyMark_;     ///< per face slot: in dirty_

  /// How the dirty faces' count under the bound differs from their flags (a dead slot counts
  /// as not under); refresh: the flags take the current state.
  long DirtyChange(bool refresh = false) {
    if (underFlag_.size() < m_.face.size()) underFlag_.resize(m_.face.size(), 0);
    long d = 0;
    for (int i : dirty_) {
      const FaceType& f = m_.face[size_t(i)];
      const char now = !f.IsD() && UnderTheBound(f);
      d += now - underFlag_[size_t(i)];
      if (refresh) underFlag_[size_t(i)] = now;
    }
    return d;
  }
  /// Has f an angle under minAngleDeg (its largest corner cosine over the bound's)?
  bool UnderTheBound(const FaceType& f) const {
    return relax_detail::MaxCornerCos(&f) > boundCos_;
  }
  void ForgetDirty() {
    for (int i : dirty_) dirtyMark_[size_t(i)] = 0;
    dirty_.clear();
  }
  size_t witnessHits_ = 0;          ///< samples a witness showed harmless (WitnessHits)
};

/// The scope of one guarded edit: remembers the checkpoint and the angle quality before;
/// Accept() keeps the edit if the guard passes it, otherwise rolls back and records the
/// refusal (by reason in the report, by subject vertex in the state). Edits nest; the
/// outermost kept one commits the journal (ReductionState::Kept).
template <class MeshType>
class GuardedEdit {
 public:
  /// around: where the edit will happen (the angle before is measured on its 2-ring);
  /// subjects: the irregular vertices it tries to cancel or move (default: around).
  GuardedEdit(EditGuard<MeshType>& guard, ReductionReport& rep, const std::vector<int>& around,
              const std::vector<int>* subjects = nullptr)
      : g_(guard), rep_(rep), cp_(guard.ed().Mark()),
        angleBefore_(guard.MinAngleAround(around)), subjects_(subjects ? *subjects : around) {
    g_.state().EnterEdit();
    if (g_.Allowance() > 0) g_.MarkDirty(g_.changed_);  // the faces around it before it
    outermost_ = g_.state().Depth() == 1;
  }
  ~GuardedEdit() {
    // the outermost edit ends: kept (Keep refreshed the flags already) or not (rolled back, or
    // left to the caller's own mark: the dirty faces are back as their flags say)
    if (outermost_ && !kept_) g_.EndDirty(false);
    g_.state().LeaveEdit();
  }
  GuardedEdit(const GuardedEdit&) = delete;
  GuardedEdit& operator=(const GuardedEdit&) = delete;

  /// Keeps the edit (true) or undoes it (false).
  bool Accept(const std::vector<int>& touched) {
    if (!Judge(touched)) return false;
    Keep(touched);
    return true;
  }
  /// The guard's verdict alone. A refusal undoes the edit and records it; a pass commits
  /// nothing yet, so a caller with checks of its own (boundary_reduction.h) can still roll
  /// back to a mark taken before this edit began, and calls Keep only when it keeps the edit.
  bool Judge(const std::vector<int>& touched) {
    const GuardVerdict v = Verdict(touched);
    if (v == GuardVerdict::Kept) return true;
    Refuse(v);
    return false;
  }
  /// The guard's verdict, without undoing or recording anything: for a caller that has
  /// another way to try when it fails (then Refuse, or Keep).
  /// allowance: false for a verdict by the angle bound alone (see EditGuard::Judge).
  GuardVerdict Verdict(const std::vector<int>& touched, bool allowance = true) {
    return g_.Judge(touched, angleBefore_, allowance);
  }
  /// After an angle repair failed (RepairAngles gave Angle): the verdict under the angle
  /// allowance (floor and count required), or Angle when the run has no allowance.
  GuardVerdict VerdictWithinAllowance(const std::vector<int>& touched) {
    return g_.Allowance() > 0 ? g_.Judge(touched, angleBefore_, true, true) : GuardVerdict::Angle;
  }
  /// Undoes the edit and records the refusal `v` (not Kept): the report's count by reason,
  /// the subjects' undone count (leftover reasons) and the region's effort bound.
  void Refuse(GuardVerdict v) {
    Undo();
    (v == GuardVerdict::Frozen     ? rep_.undoneFrozen
     : v == GuardVerdict::Angle    ? rep_.undoneAngle
     : v == GuardVerdict::Boundary ? rep_.undoneBoundary
                                   : rep_.undoneHausdorff)++;
    g_.state().Undone(subjects_);
    g_.state().Refused(v == GuardVerdict::Frozen     ? Refusal::Frozen
                       : v == GuardVerdict::Angle    ? Refusal::Angle
                       : v == GuardVerdict::Boundary ? Refusal::Boundary
                                                     : Refusal::Hausdorff);
  }
  /// The edit is kept: stamps, running count, and (outermost edit) the journal's commit.
  /// The outermost also commits the count of triangles under the angle bound (the allowance).
  void Keep(const std::vector<int>& touched) {
    g_.state().Kept(touched);
    if (outermost_) {
      g_.EndDirty(true);
      kept_ = true;
    }
  }
  void Undo() { g_.ed().RollbackTo(cp_); }
  /// The smallest angle around the edit before it began (the guard's bound where it is under
  /// the minimum angle).
  double AngleBefore() const { return angleBefore_; }
  /// Angle repair, for an edit the guard refused for triangles under the minimum angle (a
  /// transport's route, pair_transport.h; an aggregation, leftover_aggregation.h): relax again
  /// around its sharp corners (their 2-ring), up to `rounds` times, while the smallest angle
  /// is at most `slack` under `bound` and has risen in one of the last two rounds (a repair that
  /// works lifts it round after round; one that does not often lowers it). The relaxed vertices
  /// join `touched`. clearMinimum: a Kept verdict still needs every judged angle at the minimum
  /// itself (crease faces keep their slack), not only "no worse than before". The rounds are
  /// judged by the angle bound alone (no allowance): the caller asks for the allowance only
  /// once the repair failed, so that it is not spent on triangles a repair lifts (bunny00 at
  /// 80K: 64 irregular vertices left when the allowance passed routes before any repair, 1138
  /// triangles under 30 degrees before the final polish). Returns the last verdict (Angle if
  /// no round was tried). Undoes nothing: the caller keeps or undoes.
  GuardVerdict RepairAngles(std::vector<int>& touched, int rounds, double bound, double slack, bool clearMinimum) {
    const double minimum = g_.options().minAngleDeg;
    GuardVerdict verdict = GuardVerdict::Angle;
    std::vector<int> sharp;
    double last = -1;  // the smallest angle before the previous round
    int stalled = 0;   // rounds in a row that did not raise it
    for (int r = 0; r < rounds && verdict == GuardVerdict::Angle; ++r) {
      const double now = g_.MinAngleAndSharpCorners(touched, minimum, &sharp);
      if (now < bound - slack) break;
      stalled = r > 0 && now <= last ? stalled + 1 : 0;
      if (stalled == 2) break;
      last = now;
      g_.RelaxAround(sharp);
      touched.insert(touched.end(), sharp.begin(), sharp.end());
      verdict = Verdict(touched, false);
      double atCrease = 180;
      if (clearMinimum && verdict == GuardVerdict::Kept && g_.MinAngleOfJudged(&atCrease) < minimum)
        verdict = GuardVerdict::Angle;
    }
    return verdict;
  }

 private:
  EditGuard<MeshType>& g_;
  ReductionReport& rep_;
  typename MeshEditor<MeshType>::Checkpoint cp_;
  double angleBefore_;
  std::vector<int> subjects_;
  bool outermost_ = false;  ///< not nested in another guarded edit
  bool kept_ = false;       ///< Keep was called (outermost: the allowance's count is committed)
};

}  // namespace irregular
}  // namespace vcg_ext
