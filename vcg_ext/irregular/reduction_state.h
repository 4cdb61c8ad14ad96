// filter_irregular: the state of one automatic reduction run (automatic_reduction.h), apart
// from its settings (reduction_options.h): the running count of irregular vertices, when each
// vertex was last edited or failed, the edits the guard undid per vertex, and the one copy of
// the input that undoes a whole run. Everything here costs O(touched) per edit; only
// StartCount() and the snapshot are O(mesh), once per run.
//
// Memory: the snapshot is compact (mesh_snapshot.h: 16 bytes per face, a vertex its position
// and flags; VF, FF and normals rebuilt from them), and TakeSnapshot gives the mesh's vectors
// room for the run's new elements (ReserveRoom), so that a split does not double them
// (std::vector's growth: the old and the new vector resident at once, ~200 MB on a
// million-face CMeshO with its optional adjacency). The run ends with CompactKeepingAdjacency,
// which does not rebuild FF.
#pragma once

#include <algorithm>
#include <map>
#include <unordered_map>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <vcg/complex/algorithms/update/topology.h>

#include "atomic_ops.h"
#include "graph_ops.h"
#include "journal.h"
#include "mesh_snapshot.h"
#include "reduction_options.h"
#include "relaxation.h"

namespace vcg_ext {
namespace irregular {

/// Gives the pages of freed heap memory back to the system. glibc keeps what many small blocks
/// freed as resident memory (the edit guard's map of the input's edges, built and dropped by
/// its constructor, left ~170 MB resident on a million-face input); a whole-mesh allocation
/// that follows then adds to it instead of reusing it. Elsewhere: nothing. O(heap), once per run.
inline void ReleaseFreedMemory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

/// Makes the capacity of m.vert and m.face at least their size plus `spareVerts` /
/// `spareFaces`, fixing every pointer to a moved element (face -> vertex, FF, VF, edge ->
/// vertex, edge -> face), as vcg's Allocator does when it grows a vector, but to the size asked
/// instead of double. Nothing else changes (sizes, counts, attributes). O(V + F) when it moves
/// a vector, O(1) when the room is there already. Meshes with half-edges or tetrahedra are left
/// alone (their pointers are not fixed here): returns false then.
template <class MeshType>
bool ReserveRoom(MeshType& m, size_t spareVerts, size_t spareFaces) {
  if (!m.hedge.empty() || !m.tetra.empty()) return false;
  typedef typename MeshType::VertexType VertexType;
  typedef typename MeshType::FaceType FaceType;
  if (!m.vert.empty() && m.vert.capacity() < m.vert.size() + spareVerts) {
    const VertexType* oldBase = &m.vert[0];
    const VertexType* oldEnd = oldBase + m.vert.size();
    m.vert.reserve(m.vert.size() + spareVerts);
    VertexType* newBase = &m.vert[0];
    auto fix = [&](VertexType*& p) {
      if (p && p >= oldBase && p < oldEnd) p = newBase + (p - oldBase);
    };
    for (auto& f : m.face)
      for (int z = 0; z < 3; ++z) fix(f.V(z));
    for (auto& e : m.edge) fix(e.V(0)), fix(e.V(1));
  }
  if (!m.face.empty() && m.face.capacity() < m.face.size() + spareFaces) {
    const FaceType* oldBase = &m.face[0];
    const FaceType* oldEnd = oldBase + m.face.size();
    m.face.reserve(m.face.size() + spareFaces);
    FaceType* newBase = &m.face[0];
    auto fix = [&](FaceType*& p) {
      if (p && p >= oldBase && p < oldEnd) p = newBase + (p - oldBase);
    };
    const bool ff = vcg::tri::HasFFAdjacency(m);
    const bool vf = vcg::tri::HasPerFaceVFAdjacency(m) && vcg::tri::HasPerVertexVFAdjacency(m);
    for (auto& f : m.face)
      for (int z = 0; z < 3; ++z) {
        if (ff) fix(f.FFp(z));
        if (vf) fix(f.VFp(z));
      }
    if (vf)
      for (auto& v : m.vert) fix(v.VFp());
    if (vcg::tri::HasEFAdjacency(m))
      for (auto& e : m.edge) fix(e.EFp());
  }
  return true;
}

/// Removes the deleted vertices and faces, leaving the mesh as vcg's CompactEveryVector followed
/// by UpdateTopology::FaceFace and ::VertexFace leaves it, without FaceFace: that one sorts a
/// vector of 3F half-edges (32 bytes each, ~110 MiB at 1.2M faces: the end of a reduction's
/// peak). CompactEveryVector keeps the order of the live elements and re-points FF and VF
/// through its remap; on a manifold mesh an edge has one opposite face, so the FF it keeps is
/// the FF FaceFace would find (a border edge points to its own face in both). VertexFace
/// re-threads the VF lists in vcg's order (one pass, no allocation), so that what follows sees
/// the lists it saw before. Precondition: FF and VF valid on the live elements (every edit keeps
/// them so: mesh_checks.h), no live element pointing to a deleted one. O(V + F) time, O(V + F)
/// indices of memory (vcg's remaps).
template <class MeshType>
void CompactKeepingAdjacency(MeshType& m) {
  vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
  vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
}

template <class MeshType>
class ReductionState {
 public:
  typedef MeshEditor<MeshType> Editor;

  ReductionState(MeshType& m, Editor& ed, const ReductionOptions& opt) : m_(m), ed_(ed), opt_(opt) {}

  bool Frozen(int v) const { return v >= 0 && size_t(v) < opt_.frozen.size() && opt_.frozen[size_t(v)]; }
  bool IsInteriorIrregular(int v) {
    if (!ed_.IsLive(v)) return false;
    const int d = ed_.InteriorValence(v);
    return d >= 0 && d != 6;
  }
  /// A boundary vertex whose valence differs from its regular one by the corner rule (topology.h).
  bool IsBoundaryIrregular(int v) {
    if (!ed_.IsLive(v)) return false;
    VertexStar<MeshType> s = ed_.Star(v);
    return s.boundary && s.Valence() != RegularValenceOf(s);
  }

  // ------------------------------------------------------------ running count
  /// Interior irregular vertices now.
  int Irregular() const { return irregular_; }
  /// The target count (if any) is reached.
  bool Done() const { return opt_.targetCount > 0 && irregular_ <= opt_.targetCount; }

  /// One O(V) pass per run; afterwards UpdateCount keeps the count from the touched vertices.
  void StartCount() {
    isIrregular_.assign(m_.vert.size(), 0);
    isBoundaryIrregular_.assign(m_.vert.size(), 0);
    irregular_ = boundaryIrregular_ = 0;
    for (size_t i = 0; i < m_.vert.size(); ++i) {
      irregular_ += isIrregular_[i] = IsInteriorIrregular(int(i));
      boundaryIrregular_ += isBoundaryIrregular_[i] = IsBoundaryIrregular(int(i));
    }
    boundaryLimit_ = boundaryIrregular_;
  }

  /// Boundary irregular vertices now, and the most allowed: the input's count (issue 14: an
  /// edit may move curvature into the boundary, never add boundary irregular vertices).
  int BoundaryIrregular() const { return boundaryIrregular_; }
  int BoundaryLimit() const { return boundaryLimit_; }
  /// How the boundary irregular count would change if the edit that touched `touched` were
  /// kept now (same region as UpdateCount; boundary vertices move only where an edit touched
  /// them, relaxation keeps them fixed). O(touched).
  int BoundaryDelta(const std::vector<int>& touched) {
    int delta = 0;
    for (int x : ChangedRegion(touched)) {
      if (x < 0) continue;
      const char before = size_t(x) < isBoundaryIrregular_.size() ? isBoundaryIrregular_[size_t(x)] : 0;
      delta += int(IsBoundaryIrregular(x)) - int(before);
    }
    return delta;
  }

  /// After a kept edit: valences change only at the vertices an edit touched (those it
  /// deleted included) and their neighbours (a collapse re-points the faces around the vertex
  /// it removes, all in the ring of the survivor). O(touched).
  void UpdateCount(const std::vector<int>& touched) {
    if (isIrregular_.size() < m_.vert.size()) isIrregular_.resize(m_.vert.size(), 0);
    if (isBoundaryIrregular_.size() < m_.vert.size()) isBoundaryIrregular_.resize(m_.vert.size(), 0);
    for (int x : ChangedRegion(touched)) {
      if (x < 0 || size_t(x) >= isIrregular_.size()) continue;
      const char now = IsInteriorIrregular(x), nowB = IsBoundaryIrregular(x);
      irregular_ += int(now) - int(isIrregular_[size_t(x)]);
      isIrregular_[size_t(x)] = now;
      boundaryIrregular_ += int(nowB) - int(isBoundaryIrregular_[size_t(x)]);
      isBoundaryIrregular_[size_t(x)] = nowB;
    }
  }

  /// What UpdateCount(touched) would add to the interior irregular count, without changing
  /// anything. O(touched).
  int CountChange(const std::vector<int>& touched) {
    int d = 0;
    for (int x : ChangedRegion(touched)) {
      if (x < 0) continue;
      const int was = size_t(x) < isIrregular_.size() ? isIrregular_[size_t(x)] : 0;
      d += int(IsInteriorIrregular(x)) - was;
    }
    return d;
  }

  /// The touched vertices, their 1-ring and the vertices the current edit deleted (sorted,
  /// unique): where valences (and boundary corners) can have changed.
  std::vector<int> ChangedRegion(const std::vector<int>& touched) {
    std::vector<int> live;
    for (int t : touched)
      if (ed_.IsLive(t)) live.push_back(t);
    std::vector<int> around = KRing(m_, live, 1);
    around.insert(around.end(), touched.begin(), touched.end());
    around.insert(around.end(), removed_.begin(), removed_.end());
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    return around;
  }

  // ------------------------------------------------------------ what an edit touched
  /// The vertices an atomic operation changed and that still exist; the ones it deleted are
  /// remembered for UpdateCount until the outermost guarded edit ends.
  std::vector<int> Changed(const AtomicOutcome& o) {
    std::vector<int> c;
    for (auto& kv : o.changes) (kv.second != 0 ? c : removed_).push_back(kv.first);
    return c;
  }
  /// Appends what o changed to touched; returns it too.
  std::vector<int> Record(const AtomicOutcome& o, std::vector<int>& touched) {
    std::vector<int> c = Changed(o);
    touched.insert(touched.end(), c.begin(), c.end());
    return c;
  }

  // ------------------------------------------------------------ guarded edits (edit_guard.h)
  /// A guarded edit begins (they nest: a split-and-absorb contains transports).
  void EnterEdit() { ++depth_; }
  /// Guarded edits in progress (1: the outermost one).
  int Depth() const { return depth_; }
  /// It ends; the outermost one forgets the deleted vertices it collected.
  void LeaveEdit() {
    if (--depth_ == 0) removed_.clear();
  }
  /// A guarded edit was kept. The outermost one stamps its vertices (its touched list holds
  /// those of the edits kept inside it), updates the count and commits the editor's journal,
  /// so the journal holds one edit at a time. An inner one stamps nothing: the edit around it
  /// may still be undone, and a stamp left by an undone edit would make the repeated-failure
  /// and given-up checks (UnchangedSinceFailure, GivenUp) see a change where the mesh has
  /// none, and try again what fails the same way (the bull: 486 split-and-absorbs undone in
  /// its last three sweeps, 0.9.13).
  void Kept(const std::vector<int>& touched) {
    ++epoch_;
    if (depth_ == 1) {
      for (int t : touched) Stamp(editedAt_, t, epoch_);
      UpdateCount(touched);
      ed_.Commit();
    }
  }
  /// Vertex slot v is dead and will be reused (slot_pool.h): forget what the run kept of the
  /// vertex that was there, so the new one starts with none of it.
  void ForgetVertex(int v) {
    undoneAt_.erase(v);
    effort_.erase(v);
    if (size_t(v) < failedAt_.size()) failedAt_[size_t(v)] = -1;
    if (size_t(v) < triedAt_.size()) triedAt_[size_t(v)] = -1;
    if (size_t(v) < triedUnchanged_.size()) triedUnchanged_[size_t(v)] = 0;
    ForgetBall(v);
  }
  /// The guard undid an edit that tried to cancel or move `subjects`.
  void Undone(const std::vector<int>& subjects) {
    for (int v : subjects)
      if (v >= 0) ++undoneAt_[v];
  }
  /// Edits undone per vertex index (indices of the mesh during the run).
  const std::map<int, int>& UndoneAt() const { return undoneAt_; }

  // ------------------------------------------------------------ repeated failures
  /// Guarded edits kept so far, inner ones included (also those inside an edit undone later).
  long Epoch() const { return epoch_; }
  /// A transport from v failed now.
  void Failed(int v) {
    Stamp(failedAt_, v, epoch_);
    ForgetBall(v);
  }
  /// v's turn with the travel strategies kept nothing (tried now, or skipped as tried before
  /// and unchanged, or as given up): for the leftover reasons only (TriedUnchanged).
  void Tried(int v) { Stamp(triedAt_, v, epoch_); }
  /// True if a transport from v already failed and no edit kept since (an outermost one,
  /// Kept) touched a vertex within `radius` edges: trying again would fail the same way (the
  /// search is deterministic).
  ///
  /// The walk's vertices are kept (unchangedBall_) when it finds none: the next query for v
  /// with the same radius reads their stamps instead of walking the rings again (about 1800
  /// stars at the default travel; on the bull these walks were 2.7% of the run, 0.9.22). The
  /// same answer: while no kept edit touched a vertex of that ball, every edge among its
  /// vertices is still there and no new one joins them (an edit's touched vertices include,
  /// for each edge it adds or removes, a vertex the edge's ends were joined to), so the ball
  /// is the same. A touched one sends the query back to the walk.
  bool UnchangedSinceFailure(int v, int radius) {
    const long failed = StampOf(failedAt_, v);
    if (failed < 0) return false;
    auto stampedSince = [&](int x) { return StampOf(editedAt_, x) > failed; };
    auto cached = unchangedBall_.find(v);
    if (cached != unchangedBall_.end() && cached->second.radius == radius &&
        std::none_of(cached->second.ball.begin(), cached->second.ball.end(), stampedSince))
      return true;
    ForgetBall(v);
    std::vector<int> ball;
    if (AnyWithin(m_, v, radius, [&](int x) {
          ball.push_back(x);
          return stampedSince(x);
        }))
      return false;
    if (ballEntries_ + ball.size() <= kMaxBallEntries) {
      ballEntries_ += ball.size();
      // exact size: the walk's growth by doubling left up to half of it empty (at 1.2M faces
      // the cache's 4M entries held 24 MB, a twentieth of the run's peak)
      ball.shrink_to_fit();
      unchangedBall_[v] = UnchangedBall{radius, std::move(ball)};
    }
    return true;
  }

  // ------------------------------------------------------------ bounded effort per region
  /// v's turn in a sweep begins: refused edits now count against v's region.
  void BeginTurn(int v) { turn_ = v; }
  /// The turn ends: a region whose refusals reached the bound is given up (stamped now).
  void EndTurn() {
    if (turn_ >= 0 && opt_.maxRefusalsPerRegion > 0) {
      auto it = effort_.find(turn_);
      if (it != effort_.end() && it->second.refused >= opt_.maxRefusalsPerRegion && it->second.givenUpAt < 0)
        it->second.givenUpAt = epoch_;
    }
    turn_ = -1;
  }
  /// The current turn's region has had its bound of refused edits: try nothing more there.
  bool TurnExhausted() const {
    if (turn_ < 0 || opt_.maxRefusalsPerRegion <= 0) return false;
    auto it = effort_.find(turn_);
    return it != effort_.end() && it->second.refused >= opt_.maxRefusalsPerRegion;
  }
  /// An edit tried in the current turn was undone (outside a turn, e.g. type change or the
  /// boundary stage: not counted).
  void Refused(Refusal why) {
    if (turn_ < 0) return;
    Effort& e = effort_[turn_];
    ++e.refused;
    ++e.byReason[int(why)];
  }
  /// v's region was given up and no edit was kept within kRegionRings edges of v since:
  /// trying again would be refused the same way. If an edit was kept there, the region gets
  /// a fresh bound. O(region).
  bool GivenUp(int v) {
    auto it = effort_.find(v);
    if (it == effort_.end() || it->second.givenUpAt < 0) return false;
    const long givenUpAt = it->second.givenUpAt;
    if (AnyWithin(m_, v, kRegionRings, [&](int x) { return StampOf(editedAt_, x) > givenUpAt; })) {
      effort_.erase(it);
      return false;
    }
    return true;
  }
  /// The regions given up (run-time indices), with their refusals by reason; irregularAround
  /// and thickness are left for the caller.
  std::vector<GaveUpRegion> GaveUpRegions() const {
    std::vector<GaveUpRegion> out;
    for (auto& kv : effort_) {
      if (kv.second.givenUpAt < 0) continue;
      GaveUpRegion g;
      g.vertex = kv.first;
      g.refused = kv.second.refused;
      std::copy(kv.second.byReason, kv.second.byReason + kRefusalKinds, g.byReason);
      out.push_back(g);
    }
    return out;
  }

  // ------------------------------------------------------------ the whole-run undo
  /// Saves every vertex and face once (mesh_snapshot.h): O(V + F) memory whatever the number
  /// of edits. First gives the mesh's vectors room for as many elements more (at least 4096
  /// vertices and 8192 faces): the elements a run adds stay in the vectors (a collapse
  /// leaves a hole, a split appends), so that they do not double in the middle of the run, when
  /// the old and the new vector and the snapshot are all resident at once (ReserveRoom; it may
  /// move the elements: pointers into the mesh taken before are invalid after). The room costs
  /// address space, not resident memory, until elements fill it: reserving writes nothing there.
  /// An eighth was not enough: bunny00 subdivided once (301,632 faces, 19,715 irregular
  /// vertices) ends its run with 383,490 faces in the vector (+27%), and the face vector
  /// doubled in the transports: the run's peak. Half was not enough once the travel grew with
  /// the mesh (0.9.5): the same input filled 97% of it (219,268 of 226,227 vertex slots), and
  /// a run on four times as large an input (1.2M faces) had reached 3.7 times the memory of a
  /// load and save when it was stopped (0.9.6).
  void TakeSnapshot() {
    ReleaseFreedMemory();
    ReserveRoom(m_, std::max<size_t>(4096, m_.vert.size()), std::max<size_t>(8192, m_.face.size()));
    snapshot_.Take(m_);
  }
  /// Gives back the mesh as TakeSnapshot saw it, bit for bit, and forgets the snapshot.
  void RestoreSnapshot() {
    ed_.Commit();  // what an interrupted edit logged is overwritten below
    snapshot_.Restore(m_);
    snapshot_.Clear();
    ed_.slotPool().Clear();  // pooled slots may hold live vertices again
  }
  /// Forgets the snapshot and gives its memory back.
  void DropSnapshot() {
    snapshot_.Clear();
    ReleaseFreedMemory();
  }
  /// Bytes the snapshot holds (0 when none).
  size_t SnapshotBytes() const { return snapshot_.Bytes(); }

  /// Before the final measurement of a pass (automatic_reduction.h): gives back the per-vertex
  /// stamps of kept edits, failed attempts and turns (24 bytes a vertex), which only the sweeps
  /// read (keeping one byte a vertex of them for the leftover reasons),
  /// and the pages of freed heap memory (ReleaseFreedMemory), so that the measurement's grid is
  /// not added on top of memory the run no longer uses. A retry starts with Reset() anyway;
  /// the counts, the undone edits and the given-up regions stay for the report.
  void ReleaseSweepState() {
    // what the leftover reasons need of them, one byte a vertex: "no route" vs "untried"
    triedUnchanged_.assign(m_.vert.size(), 0);
    for (size_t v = 0; v < triedUnchanged_.size(); ++v) {
      const long tried = StampOf(triedAt_, int(v));
      triedUnchanged_[v] = tried >= 0 && tried >= StampOf(editedAt_, int(v));
    }
    std::vector<long>().swap(editedAt_);
    std::vector<long>().swap(triedAt_);
    std::vector<long>().swap(failedAt_);
    DropBalls();
    ReleaseFreedMemory();
  }

  /// Per vertex index, 1: it had a turn with the travel strategies that kept nothing (Tried)
  /// and no kept edit touched it since (set by ReleaseSweepState; the leftover reasons' `tried`).
  const std::vector<char>& TriedUnchanged() const { return triedUnchanged_; }

  /// Forgets the edit history (a retry starts from the restored input).
  void Reset() {
    epoch_ = 0;
    triedUnchanged_.clear();
    editedAt_.clear();
    failedAt_.clear();
    triedAt_.clear();
    DropBalls();
    undoneAt_.clear();
    removed_.clear();
    effort_.clear();
    turn_ = -1;
  }

 private:
  struct Effort {
    int refused = 0;                               ///< edits refused in the region's turns
    int byReason[kRefusalKinds] = {};
    long givenUpAt = -1;                           ///< epoch it was given up at (-1: not given up)
  };

  /// The vertices an UnchangedSinceFailure walk found none touched in, with its radius.
  struct UnchangedBall {
    int radius = 0;
    std::vector<int> ball;
  };
  /// Bound on the vertices kept in all balls together (16 MB): past it, queries walk.
  static constexpr size_t kMaxBallEntries = size_t(1) << 22;
  void DropBalls() {
    std::unordered_map<int, UnchangedBall>().swap(unchangedBall_);
    ballEntries_ = 0;
  }
  void ForgetBall(int v) {
    auto it = unchangedBall_.find(v);
    if (it == unchangedBall_.end()) return;
    ballEntries_ -= it->second.ball.size();
    unchangedBall_.erase(it);
  }

  static void Stamp(std::vector<long>& at, int v, long when) {
    if (v < 0) return;
    if (size_t(v) >= at.size()) at.resize(size_t(v) + 1, -1);
    at[size_t(v)] = when;
  }
  static long StampOf(const std::vector<long>& at, int v) { return size_t(v) < at.size() ? at[size_t(v)] : -1; }

  MeshType& m_;
  Editor& ed_;
  const ReductionOptions& opt_;
  CompactSnapshot<MeshType> snapshot_;  ///< the input, for the whole-run undo
  int depth_ = 0;                   ///< guarded edits in progress
  std::vector<char> isIrregular_;   ///< per vertex: counted in irregular_
  int irregular_ = 0;               ///< interior irregular vertices now
  std::vector<char> isBoundaryIrregular_;  ///< per vertex: counted in boundaryIrregular_
  int boundaryIrregular_ = 0;       ///< boundary irregular vertices now (corner rule)
  int boundaryLimit_ = 0;           ///< the input's boundary irregular count
  std::vector<int> removed_;        ///< vertices deleted by the current outermost edit
  long epoch_ = 0;                  ///< kept edits so far
  std::vector<long> editedAt_, failedAt_;  ///< per vertex: epoch of its last kept edit / failed attempt
  std::vector<long> triedAt_;              ///< per vertex: epoch of its last turn with travel that kept nothing
  std::vector<char> triedUnchanged_;       ///< see TriedUnchanged
  std::map<int, int> undoneAt_;     ///< per vertex: edits the guard undid
  std::map<int, Effort> effort_;    ///< per irregular vertex whose turns had refusals: the bounded effort
  std::unordered_map<int, UnchangedBall> unchangedBall_;  ///< per failed vertex (UnchangedSinceFailure)
  size_t ballEntries_ = 0;          ///< vertices in unchangedBall_
  int turn_ = -1;                   ///< the vertex whose turn it is (-1: none)
};

}  // namespace irregular
}  // namespace vcg_ext
