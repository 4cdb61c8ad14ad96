// filter_irregular: the slots of deleted vertices and faces, given to the elements later splits
// create (issue 14's memory target).
//
// Why: vcglib's Allocator appends every new element and a collapse only flags its elements
// deleted, so a long run of edits grows the vectors by the dead slots it leaves: bunny00
// subdivided once, reduced, went from 150,818 vertex slots to 212,417, with the faces and their
// optional adjacency alongside (tens of MB at a million faces). With the pool on, a split takes a
// dead slot before it appends.
//
// Only the slots of committed edits are reused (Harvest, at the journal's commit): a slot freed
// by the edit in progress could still be brought back by its rollback. Taking a slot saves the
// whole dead element in the journal first (SaveWholeVertex / SaveWholeFace), so a rollback gives
// it back bit for bit, and the pool remembers what it gave since each checkpoint, so a rollback
// puts the slots back in the same order. Which slot the k-th new vertex will get is known in
// advance (NextVertex), so dry runs name created vertices as the real edit will.
//
// Preconditions: the pool belongs to one MeshEditor (graph_ops.h), which calls Harvest before
// every commit of its journal, RollbackTo after every rollback, and Clear when the mesh is
// replaced from outside (a snapshot restored). Costs: Take O(1) plus the element's copy,
// RollbackTo O(slots taken since), Harvest O(logged log logged): nothing walks the mesh.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <vector>

#include <vcg/complex/complex.h>

#include "journal.h"

namespace vcg_ext {
namespace irregular {

template <class MeshType>
class SlotPool {
 public:
  typedef EditJournal<MeshType> Journal;
  typedef typename Journal::Checkpoint Checkpoint;

  /// Off (the default): every new element is appended, as vcglib does. On: dead slots first.
  /// vertexReusable(i), if set, is asked once for each dead vertex slot at its harvest: false
  /// keeps the slot out of the pool (e.g. a vertex whose per-index state must survive a
  /// whole-mesh restore); the caller may also forget its own state for the slot there.
  void Enable(bool on, std::function<bool(int)> vertexReusable = nullptr) {
    on_ = on;
    vertexReusable_ = std::move(vertexReusable);
    Clear();
  }

  /// Forgets every pooled slot (they stay deleted in the mesh, appended past as before).
  void Clear() {
    verts_.clear();
    faces_.clear();
    takenVerts_.clear();
    takenFaces_.clear();
  }

  /// Index the k-th vertex created from now will get (k = 0: the next one).
  int NextVertex(const MeshType& m, int k) const {
    // the pool stays empty while off (Harvest adds nothing then)
    if (size_t(k) < verts_.size()) return verts_[verts_.size() - 1 - size_t(k)];
    return int(m.vert.size() + size_t(k) - verts_.size());
  }

  /// Slots for nv new vertices and nf new faces, their indices in v[0..nv) and f[0..nf):
  /// pooled slots first (each saved whole in the journal, its flags cleared and counted live),
  /// then appended ones (vcglib's Allocator, which may move the vectors: take pointers after).
  /// The caller sets every field it needs (a pooled slot keeps a dead element's old values).
  void Take(MeshType& m, Journal& j, int nv, int nf, int* v, int* f) {
    // pooled slots first; an appended one is marked -1 - (its rank among the appended)
    auto fromPool = [&](std::vector<int>& pool, std::vector<Taken>& taken, auto logged, auto save, auto& vec,
                        int& live, int n, int* out) {
      int appended = 0;
      for (int k = 0; k < n; ++k) {
        if (pool.empty()) {
          out[k] = -1 - appended++;
          continue;
        }
        const int i = pool.back();
        pool.pop_back();
        taken.push_back(Taken{i, logged()});
        save(&vec[size_t(i)]);
        vec[size_t(i)].Flags() = 0;
        ++live;
        out[k] = i;
      }
      return appended;
    };
    const int appendV = fromPool(verts_, takenVerts_, [&] { return j.LoggedVertices(); }, [&](auto* x) { j.SaveWholeVertex(x); },
                                 m.vert, m.vn, nv, v);
    const int appendF = fromPool(faces_, takenFaces_, [&] { return j.LoggedFaces(); }, [&](auto* x) { j.SaveWholeFace(x); },
                                 m.face, m.fn, nf, f);
    const int v0 = int(m.vert.size()), f0 = int(m.face.size());
    if (appendV) vcg::tri::Allocator<MeshType>::AddVertices(m, size_t(appendV));
    if (appendF) vcg::tri::Allocator<MeshType>::AddFaces(m, size_t(appendF));
    for (int k = 0; k < nv; ++k)
      if (v[k] < 0) v[k] = v0 + (-1 - v[k]);
    for (int k = 0; k < nf; ++k)
      if (f[k] < 0) f[k] = f0 + (-1 - f[k]);
  }

  /// After the journal rolled back to c: the slots taken since c go back, in their order.
  void RollbackTo(const Checkpoint& c) {
    while (!takenVerts_.empty() && takenVerts_.back().logged >= c.vertLog) {
      verts_.push_back(takenVerts_.back().slot);
      takenVerts_.pop_back();
    }
    while (!takenFaces_.empty() && takenFaces_.back().logged >= c.faceLog) {
      faces_.push_back(takenFaces_.back().slot);
      takenFaces_.pop_back();
    }
  }

  /// Before the journal commits: the elements the committed edits deleted (each was saved in
  /// the journal before its deletion) join the pool, pushed in increasing index order (a stack:
  /// the newest harvest's largest index is taken first). Forgets what was taken (a commit
  /// cannot be rolled back).
  void Harvest(const MeshType& m, const Journal& j) {
    takenVerts_.clear();
    takenFaces_.clear();
    if (!on_) return;
    // the dead ones first, then sorted and unique: the same list as sorting every logged index
    // (most are live faces and vertices, logged many times), at a fraction of the sort
    auto dead = [](const std::vector<size_t>& idx, const auto& vec) {
      std::vector<int> out;
      for (size_t i : idx)
        if (i < vec.size() && vec[i].IsD()) out.push_back(int(i));
      std::sort(out.begin(), out.end());
      out.erase(std::unique(out.begin(), out.end()), out.end());
      return out;
    };
    const Checkpoint all;  // the log since the last commit
    for (int i : dead(j.VerticesSavedSince(all), m.vert))
      if (!vertexReusable_ || vertexReusable_(i)) verts_.push_back(i);
    for (int i : dead(j.FacesSavedSince(all), m.face)) faces_.push_back(i);
  }

  size_t PooledVertices() const { return verts_.size(); }
  size_t PooledFaces() const { return faces_.size(); }

 private:
  struct Taken {
    int slot;
    size_t logged;  ///< the journal's log length when it was taken
  };
  bool on_ = false;
  std::function<bool(int)> vertexReusable_;
  std::vector<int> verts_, faces_;           ///< pooled slots (a stack)
  std::vector<Taken> takenVerts_, takenFaces_;  ///< taken since the last commit, oldest first
};

}  // namespace irregular
}  // namespace vcg_ext
