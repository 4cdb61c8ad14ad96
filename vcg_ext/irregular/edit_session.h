// filter_irregular: the logic of the interactive edit tool (paper sec. 9: "select a vertex pair
// and one of six movement directions ... interleaved with local and global relaxation").
// The MeshLab edit plugins (2020.09 and 2025.07) are thin views over this class: they pass the
// clicked surface point, key presses and a projection in, and draw Directions() and Message().
// No Qt, no OpenGL.
//
// What a session holds, and what it costs:
//  * The original surface, frozen when the session starts (surface_projector.h): relaxation
//    after every step projects on it (sec. 8), so many steps do not drift the shape.
//    O(F log F) once, at construction.
//  * A picking grid (pick_grid.h): a hash of the vertex positions in cells of the pick radius,
//    built on the first pick (O(V) once) and refreshed after every step and undo on the
//    vertices the step can touch (Touched()), so a click costs O(vertices near the click).
//  * An undo stack: each step or cancellation runs on its own MeshEditor, whose journal
//    (journal.h) is that step's undo entry; Undo rolls the newest one back, restoring positions,
//    connectivity, attributes and the picked pair bit for bit. Beyond opt.undoDepth entries the
//    oldest journal is dropped (its edit becomes permanent), so memory stays bounded. Redo
//    replays an undone action on the bit-identical state it ran on.
//  * A compact mesh: MeshLab's renderer reads vert[0..vn) and face[0..fn), so after every
//    Step, Cancel*, Undo and Redo the mesh has no deleted element (vert.size() == vn,
//    face.size() == fn), provided it had none at the start. A step that deletes elements (a
//    collapse) moves the last live vertices / faces into the holes and truncates the vectors,
//    inside the step's journal (Compact: O(deleted * valence), the holes found among the
//    elements the step saved, never by a scan); Undo grows the vectors back (journal.h), bit
//    for bit, so the undo history survives. Moved elements change index: the pair follows,
//    Touched() lists the filled and the truncated slots, the picking grid re-bins them.
//  * Spare capacity in m.vert / m.face (Reserve), so that a split in a step never makes vcg's
//    Allocator reallocate and re-point every face (O(F)) in the middle of a key press.
//
// The dry run of a step. Directions() tries each of the six moves on the mesh itself through a
// journal checkpoint and rolls it back (the mechanism that makes every refused operation all or
// nothing, journal.h): the verdict is Step(k)'s by construction - same code, same state - and
// the arrow ends where the lead really lands, after relaxation. A scratch-copy prediction
// (CompositePredictor::PredictMovePair) copies 13 and then 26 rings around the pair for each
// direction and is exact only when two region sizes agree; the trial costs one step, which is
// cheaper and never disagrees. Between two calls of the public API the mesh is always as the
// last Step / Undo left it. Directions() are cached until the mesh or the pair changes;
// Direction(k) computes one, for a GUI that spreads the trials over idle ticks.
// An accepted trial also keeps what it did (EditJournal::Replay, captured before the rollback),
// so Step(k) on a known arrow applies that instead of running the move again: the step a user
// sees costs O(touched), and the transport is paid once, in the arrow's trial.
// Cost (bench/bench_edit_session.cpp, 1M-face torus): see the README's benchmark table. A pair
// far apart moves by the sec. 7.1.1 pipeline of composite_ops.h, whose trial costs 1-50 ms (its
// transport: atomic moves with relaxation and, where the path is blocked, Detour's search up
// to 5 moves deep; not O(mesh)); an adjacent 5-7 pair's trial is a fraction of a millisecond.
//
// Direction k is the Move Pair filter's `direction` parameter (filter_composite.cpp passes it
// unchanged to CompositeOperations::MovePair): for an adjacent 5-7 pair the atomic move k of
// atomic_ops.h (0..5 counter-clockwise around the v5 from the v7, fig. 6); for any other pair
// the lead moves toward its neighbour k counted counter-clockwise from its neighbour of
// smallest index (sec. 7.1.1, fig. 10). The GUI never needs to know which: it draws the arrow
// from `from` to `to` and maps arrow keys and drags through DirectionToward. Messages number
// the directions 1..6 (k + 1), like the keys 1-6 of the tool.
//
// Preconditions: FF and VF adjacency up to date on a manifold, consistently oriented mesh
// (as for MeshEditor); the mesh is edited only through this session while it lives.
#pragma once

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <unordered_set>
#include <vector>

#include <vcg/space/point2.h>

#include "composite_ops.h"
#include "composite_prediction.h"
#include "pick_grid.h"
#include "relaxation.h"
#include "result.h"
#include "separatrix.h"
#include "surface_projector.h"
#include "topology.h"

namespace vcg_ext {
namespace irregular {

struct EditSessionOptions {
  bool relax = true;         ///< local relaxation of the touched region after every step (sec. 8)
  int relaxIterations = 3;   ///< sweeps of that relaxation
  int undoDepth = 200;       ///< steps kept for Undo (at least 100, the issue's floor)
  double pickRadius = 0;     ///< picking radius in model units; 0: 1.5 mean edge lengths
  int partnerHops = 50;      ///< how far (in edges) a partner is searched from the lead
  int cancelHops = 12;       ///< how far (in edges) a third / fourth vertex is searched for a cancellation
};

/// One of the six movement directions of the picked pair (atomic_ops.h convention k = 0..5).
template <class CoordType>
struct EditDirection {
  int k = 0;
  bool accepted = false;  ///< the dry run says the step would be done
  std::string reason;     ///< why not, when refused
  CoordType from, to;     ///< the moved vertex now, and where it would be after the step
                          ///< (after relaxation); to == from when refused
  int lead = -1, partner = -1;  ///< where the lead / the partner would end (accepted only)
};

template <class MeshType>
class EditSession {
 public:
  typedef typename MeshType::CoordType CoordType;
  typedef MeshEditor<MeshType> Editor;
  typedef CompositeOperations<MeshType> Ops;

  /// Freezes the original surface (O(F log F)); picking structures are built on the first pick.
  explicit EditSession(MeshType& m, EditSessionOptions opt = EditSessionOptions())
      : m_(m), opt_(opt), original_(m), grid_(m) {
    opt_.undoDepth = std::max(1, opt_.undoDepth);
    Reserve();
  }

  // --- picking
  /// Picks the irregular vertex nearest to `surfacePoint` (within the pick radius) and its
  /// nearest irregular partner as the pair. Refused, with the pair unchanged, when the nearest
  /// vertex is regular, on the boundary, or there is no vertex within the radius.
  Result PickAt(const CoordType& surfacePoint) {
    EnsureGrid();
    const double r = PickRadius();
    int nearest = -1, nearestIrregular = -1;
    double dn = 0, di = 0;
    grid_.ForEachNear(surfacePoint, r, [&](int v, double d) {
      if (!Live(v)) return;
      if (nearest < 0 || d < dn || (d == dn && v < nearest)) nearest = v, dn = d;
      if (Pickable(v).ok && (nearestIrregular < 0 || d < di || (d == di && v < nearestIrregular)))
        nearestIrregular = v, di = d;
    });
    if (nearestIrregular >= 0) return PickVertex(nearestIrregular);
    if (nearest >= 0) return Say(Pickable(nearest));
    return Say(Result::Fail(Str("no vertex within ", r, " of the click (the pick radius): click on the mesh, next to an "
                                "irregular vertex")));
  }
  /// Picks vertex v as the lead, and its nearest irregular partner (fewest edges, then nearest
  /// in space, then smallest index; at most opt.partnerHops edges away).
  Result PickVertex(int v) {
    Result ok = Pickable(v);
    if (!ok) return Say(ok);
    Invalidate();
    lead_ = v;
    partner_ = NearestPartner(v);
    if (partner_ < 0)
      return Say(Result::Ok(), Str("vertex ", v, " (valence ", Valence(v), ") picked; no irregular vertex within ",
                                   opt_.partnerHops, " edges to pair it with: click its partner"));
    return Say(Result::Ok(), Str("pair picked: vertex ", lead_, " (valence ", Valence(lead_), ") leads, vertex ", partner_,
                                 " (valence ", Valence(partner_), ") follows"));
  }
  /// Makes v the partner of the current lead (a second click).
  Result PickPartner(int v) {
    if (lead_ < 0) return Say(Result::Fail("pick the lead first: click an irregular vertex"));
    if (v == lead_) return Say(Result::Fail(Str("vertex ", v, " is already the lead: click another irregular vertex")));
    Result ok = Pickable(v);
    if (!ok) return Say(ok);
    Invalidate();
    partner_ = v;
    return Say(Result::Ok(), Str("pair picked: vertex ", lead_, " (valence ", Valence(lead_), ") leads, vertex ", partner_,
                                 " (valence ", Valence(partner_), ") follows"));
  }
  /// The pair from the current vertex selection: two selected vertices (the lower valence
  /// leads, then the smaller index), or one (PickVertex). O(V): one pass per user request.
  Result PickFromSelection() {
    std::vector<int> sel;
    for (size_t i = 0; i < m_.vert.size(); ++i)
      if (!m_.vert[i].IsD() && m_.vert[i].IsS()) sel.push_back(int(i));
    if (sel.size() == 1) return PickVertex(sel[0]);
    if (sel.size() != 2)
      return Say(Result::Fail(Str("select one or two irregular vertices to pick a pair (", sel.size(), " are selected)")));
    for (int v : sel) {
      Result ok = Pickable(v);
      if (!ok) return Say(ok);
    }
    if (Valence(sel[1]) < Valence(sel[0])) std::swap(sel[0], sel[1]);
    Invalidate();
    lead_ = sel[0];
    partner_ = -1;
    return PickPartner(sel[1]);
  }
  bool HasPair() const { return lead_ >= 0 && partner_ >= 0; }
  int Lead() const { return lead_; }
  int Partner() const { return partner_; }
  /// Forgets the pair (the mesh and the undo stack stay).
  void ClearPair() {
    Invalidate();
    lead_ = partner_ = -1;
  }

  // --- directions and steps
  /// The six directions with their dry-run verdicts (empty without a pair). Cached until the
  /// mesh or the pair changes; computing them costs six trial steps (see the header).
  std::vector<EditDirection<CoordType>> Directions() {
    if (!HasPair()) return {};
    for (int k = 0; k < 6; ++k) Direction(k);
    return dirs_;
  }
  /// Direction k alone (0..5), its dry run cached like Directions(): a GUI can spread the six
  /// trials over idle ticks when one step is expensive (a pair far apart, sec. 7.1.1).
  /// Without a pair, or for k outside 0..5: refused, with the reason.
  EditDirection<CoordType> Direction(int k) {
    if (!HasPair() || k < 0 || k > 5) {
      EditDirection<CoordType> d;
      d.k = k;
      d.reason = HasPair() ? Str("direction ", k + 1, " does not exist: the directions are 1 to 6") : NoPair().reason;
      return d;
    }
    if (dirs_.size() != 6) dirs_.assign(6, EditDirection<CoordType>()), known_.assign(6, 0), trials_.resize(6);
    if (!known_[size_t(k)]) dirs_[size_t(k)] = Trial(k, trials_[size_t(k)]), known_[size_t(k)] = 1;
    return dirs_[size_t(k)];
  }
  /// True when direction k's trial ran on the current state (Direction(k) returns at once).
  bool DirectionKnown(int k) const {
    return HasPair() && k >= 0 && k < 6 && known_.size() == 6 && known_[size_t(k)] != 0;
  }
  /// True when Directions() would return without running a trial.
  bool DirectionsKnown() const { return HasPair() && known_.size() == 6 && std::count(known_.begin(), known_.end(), 1) == 6; }
  /// The accepted direction whose drawn arrow (projected by `project`) is closest in angle to
  /// the screen vector `screen` (arrow keys, mouse drag); -1 if none (no pair, nothing
  /// accepted, a zero screen vector). Ties: the smaller k.
  int DirectionToward(const std::function<vcg::Point2d(const CoordType&)>& project, vcg::Point2d screen) {
    if (screen.Norm() == 0) return -1;
    int best = -1;
    double bestAngle = 0;
    for (const auto& d : Directions()) {
      if (!d.accepted) continue;
      const vcg::Point2d a = project(d.to) - project(d.from);
      if (a.Norm() == 0) continue;
      const double c = std::max(-1.0, std::min(1.0, (a * screen) / (a.Norm() * screen.Norm())));
      const double angle = std::acos(c);
      if (best < 0 || angle < bestAngle) best = d.k, bestAngle = angle;
    }
    return best;
  }
  /// The accepted direction whose step brings the lead nearest to `target` (mouse drag toward
  /// a surface point); -1 when no step brings it closer.
  int DirectionTowardPoint(const CoordType& target) {
    int best = -1;
    double bestD = 0;
    for (const auto& d : Directions()) {
      if (!d.accepted) continue;
      const double now = (d.from - target).Norm(), after = (d.to - target).Norm();
      if (after < now && (best < 0 || after < bestD)) best = d.k, bestD = after;
    }
    return best;
  }
  /// One step toward a surface point (DirectionTowardPoint); refused when none gets closer.
  Result StepToward(const CoordType& target) {
    if (!HasPair()) return Say(NoPair());
    const int k = DirectionTowardPoint(target);
    if (k < 0) return Say(Result::Fail("no accepted step brings the pair closer to the cursor"));
    return Step(k);
  }
  /// One step of the pair in direction k, then local relaxation; one undo entry. The pair
  /// follows the moved vertices. Refused, with the mesh bit-identical, with Message() saying why.
  ///
  /// When the arrow of direction k is known (Directions() or Direction(k) ran on this state),
  /// its trial is not computed again: the trial's refusal is the answer, and an accepted
  /// trial's captured result (EditJournal::Replay: the final state of every element it
  /// changed) is applied, O(touched), bit-identical to running the move again on the same
  /// state (the operations are deterministic; tested). A key press on a drawn arrow therefore
  /// costs no transport, however far apart the pair is.
  Result Step(int k) {
    if (!HasPair()) return Say(NoPair());
    if (k < 0 || k > 5) return Say(Result::Fail(Str("direction ", k + 1, " does not exist: the directions are 1 to 6")));
    const bool known = known_.size() == 6 && known_[size_t(k)];
    if (known && !dirs_[size_t(k)].accepted)
      return Say(Result::Fail(Str("direction ", k + 1, " refused: ", dirs_[size_t(k)].reason)));
    Entry e = Begin();
    std::vector<int> before = PairRegion(lead_, partner_);
    const int l0 = lead_, p0 = partner_;
    std::vector<int> compacted;
    if (known && trials_[size_t(k)].replay.Empty() == false && e.ed->journal().Apply(trials_[size_t(k)].replay)) {
      lead_ = dirs_[size_t(k)].lead;
      partner_ = dirs_[size_t(k)].partner;
      compacted = trials_[size_t(k)].compacted;
    } else {
      CompositeOutcome o = Ops(*e.ed, &original_, CompositeOpt()).MovePair(lead_, partner_, k, 1);
      if (!o) return Say(Result::Fail(Str("direction ", k + 1, " refused: ", o.result.reason)));
      Compaction c = Compact(*e.ed, e.start);
      lead_ = c.Where(o.lead);
      partner_ = c.Where(o.partner);
      compacted = c.touched;
    }
    e.action = Action::Step, e.k = k;
    std::vector<int> after = PairRegion(lead_, partner_);
    after.insert(after.end(), compacted.begin(), compacted.end());
    Push(std::move(e), before, after);
    return Say(Result::Ok(), Str("moved the pair in direction ", k + 1, ": vertex ", l0, " -> ", lead_, ", vertex ", p0,
                                 " -> ", partner_));
  }
  /// Cancels the triple the pair forms with a nearby third irregular vertex (5-5-7 or 5-7-7,
  /// sec. 7.2): the candidates are tried nearest first (fewest edges from the pair), each by
  /// its dry run (CompositePredictor) before the real cancellation. One undo entry. After it
  /// the survivor leads, paired with its nearest partner.
  Result CancelTriple() {
    if (!HasPair()) return Say(NoPair());
    std::vector<int> near = NearbyIrregular(4);
    std::string why;
    for (int c : near) {
      std::vector<int> t{lead_, partner_, c};
      if (!ValencesAre(t, {5, 5, 7}) && !ValencesAre(t, {5, 7, 7})) continue;
      Result r = TryCancel(t, false);
      if (r) return r;
      if (why.empty()) why = Str(" (with vertex ", c, ": ", r.reason, ")");
    }
    return Say(Result::Fail(Str("no irregular vertex within ", opt_.cancelHops, " edges of the pair forms a 5-5-7 or 5-7-7 "
                                "triple with it that can be cancelled", why)));
  }
  /// Cancels the quadruple (5-5-7-7, sec. 7.3) the pair forms with two nearby irregular
  /// vertices, tried like CancelTriple. One undo entry; afterwards no pair is picked.
  Result CancelQuadruple() {
    if (!HasPair()) return Say(NoPair());
    std::vector<int> near = NearbyIrregular(6);
    std::string why;
    for (size_t a = 0; a < near.size(); ++a)
      for (size_t b = a + 1; b < near.size(); ++b) {
        std::vector<int> q{lead_, partner_, near[a], near[b]};
        if (!ValencesAre(q, {5, 5, 7, 7})) continue;
        Result r = TryCancel(q, true);
        if (r) return r;
        if (why.empty()) why = Str(" (with vertices ", near[a], " and ", near[b], ": ", r.reason, ")");
      }
    return Say(Result::Fail(Str("no two irregular vertices within ", opt_.cancelHops, " edges of the pair form a 5-5-7-7 "
                                "quadruple with it that can be cancelled", why)));
  }
  /// Undoes the last step (or cancellation); false when there is nothing to undo.
  bool Undo() {
    if (undo_.empty()) {
      Say(Result::Fail("nothing to undo"));
      return false;
    }
    Entry& e = undo_.back();
    e.ed->RollbackTo(e.start);
    lead_ = e.lead;
    partner_ = e.partner;
    touched_ = e.touched;
    redo_.push_back(Redoable{e.action, e.k, e.lead, e.partner});
    undo_.pop_back();
    Invalidate();
    grid_.Refresh(touched_);
    Say(Result::Ok(), Str("undone (", undo_.size(), " more steps can be undone)"));
    return true;
  }
  int UndoDepth() const { return int(undo_.size()); }
  /// Redoes the last undone step or cancellation (the mesh is bit-identical to the state it
  /// ran on, so running it again gives the same result); false when there is none, or when
  /// the pair was picked again or another edit came in between (those forget the redo list).
  bool Redo() {
    if (redo_.empty() || redo_.back().lead != lead_ || redo_.back().partner != partner_) {
      redo_.clear();
      Say(Result::Fail("nothing to redo"));
      return false;
    }
    const Redoable r = redo_.back();
    redo_.pop_back();
    std::vector<Redoable> rest;
    rest.swap(redo_);
    Result done = r.action == Action::Step ? Step(r.k) : r.action == Action::Triple ? CancelTriple() : CancelQuadruple();
    if (done) redo_.swap(rest);
    return done.ok;
  }
  int RedoDepth() const { return int(redo_.size()); }
  /// The last refusal or success message, for the viewport and the log.
  const std::string& Message() const { return message_; }
  /// The vertices the last step, cancellation or undo may have changed (positions, valences;
  /// created vertices included; the slots the compaction filled, the truncated ones - past
  /// the end of m.vert after a step, back after its undo - and the corners of moved faces),
  /// for the GUI's partial re-upload and the picking grid.
  const std::vector<int>& Touched() const { return touched_; }
  /// The pick radius in model units (opt.pickRadius, or 1.5 mean edge lengths).
  double PickRadius() {
    if (opt_.pickRadius > 0) return opt_.pickRadius;
    EnsureGrid();
    return 1.5 * grid_.MeanEdge();
  }
  const SurfaceProjector& Original() const { return original_; }

 private:
  /// One undo entry: the journal of one step, and the pair before it.
  /// What an entry did, to redo it: a step in direction k, or a cancellation.
  enum class Action { Step, Triple, Quadruple };
  struct Entry {
    Action action = Action::Step;
    int k = -1;
    std::unique_ptr<Editor> ed;
    typename Editor::Checkpoint start;
    int lead = -1, partner = -1;
    std::vector<int> touched;
  };

  Result Say(Result r, const std::string& okText = std::string()) {
    message_ = r ? okText : r.reason;
    return r.ok ? Result::Ok() : r;
  }
  static Result NoPair() { return Result::Fail("no pair is picked: click an irregular vertex (and, optionally, its partner)"); }

  bool Live(int v) const {
    return v >= 0 && size_t(v) < m_.vert.size() && !m_.vert[size_t(v)].IsD() && m_.vert[size_t(v)].cVFp() != nullptr;
  }
  int Valence(int v) { return StarOf<MeshType>(&m_.vert[size_t(v)]).Valence(); }
  /// Ok if v can be picked: a live, interior, irregular vertex; else the reason, for the user.
  Result Pickable(int v) {
    if (!Live(v)) return Result::Fail(Str("vertex ", v, " is not a vertex of the mesh"));
    VertexStar<MeshType> s = StarOf<MeshType>(&m_.vert[size_t(v)]);
    if (s.boundary)
      return Result::Fail(Str("vertex ", v, " lies on the boundary (valence ", s.Valence(),
                              "): the edit tool moves interior irregular vertices"));
    if (s.Valence() == RegularValenceOf(s))
      return Result::Fail(Str("vertex ", v, " is regular (valence ", s.Valence(), "): click an irregular vertex"));
    return Result::Ok();
  }

  void EnsureGrid() {
    if (!grid_.Built()) grid_.Build(opt_.pickRadius);
  }
  void Invalidate() {
    known_.assign(6, 0);
    for (auto& t : trials_) t = TrialResult();  // the captured results belong to the old state
  }

  CompositeOptions CompositeOpt() const {
    CompositeOptions co;
    co.relax = opt_.relax;
    co.relaxIterations = opt_.relaxIterations;
    return co;
  }

  /// Breadth-first rings around `seeds`; calls visit(v, ring) for every vertex reached beyond
  /// the seeds, up to `hops` rings, and stops after the first ring where visit returned true.
  template <class Visit>
  void Rings(const std::vector<int>& seeds, int hops, Visit visit) {
    std::unordered_set<int> seen(seeds.begin(), seeds.end());
    std::vector<int> frontier(seeds);
    for (int r = 1; r <= hops && !frontier.empty(); ++r) {
      std::vector<int> next;
      bool stop = false;
      for (int v : frontier)
        for (auto n : StarOf<MeshType>(&m_.vert[size_t(v)]).neighbors) {
          const int ni = int(vcg::tri::Index(m_, n));
          if (seen.insert(ni).second) next.push_back(ni);
        }
      std::sort(next.begin(), next.end());
      for (int v : next) stop = visit(v, r) || stop;
      if (stop) return;
      frontier.swap(next);
    }
  }

  /// The irregular interior vertex nearest to v: fewest edges, then nearest in space, then
  /// smallest index. -1 if none within opt.partnerHops edges.
  int NearestPartner(int v) {
    int best = -1;
    double bd = 0;
    const CoordType p = m_.vert[size_t(v)].P();
    Rings({v}, opt_.partnerHops, [&](int w, int) {
      if (!Pickable(w).ok) return false;
      const double d = (m_.vert[size_t(w)].P() - p).Norm();
      if (best < 0 || d < bd || (d == bd && w < best)) best = w, bd = d;
      return true;
    });
    return best;
  }

  /// Up to `count` irregular interior vertices near the pair, fewest edges first (then the
  /// smaller index), within opt.cancelHops edges.
  std::vector<int> NearbyIrregular(size_t count) {
    std::vector<int> out;
    Rings({lead_, partner_}, opt_.cancelHops, [&](int w, int) {
      if (out.size() < count && Pickable(w).ok) out.push_back(w);
      return out.size() >= count;
    });
    return out;
  }

  bool ValencesAre(const std::vector<int>& vs, std::vector<int> want) {
    std::vector<int> d;
    for (int v : vs) d.push_back(Valence(v));
    std::sort(d.begin(), d.end());
    return d == want;
  }

  /// The vertices a step of the pair (a, b) can change: the pair, the connecting path the
  /// transport follows (separatrix.h; sec. 7.1.1), and 3 rings around them (relaxation moves
  /// the 2-ring of every atomic step). O(L) vertices.
  std::vector<int> PairRegion(int a, int b) {
    std::vector<int> seeds{a, b};
    if (!Live(a) || !Live(b)) {
      seeds.clear();
      for (int v : {a, b})
        if (Live(v)) seeds.push_back(v);
    } else if (a != b && StarOf<MeshType>(&m_.vert[size_t(a)]).IndexOf(&m_.vert[size_t(b)]) < 0) {
      SeparatrixTracer<MeshType> tracer(m_);
      ConnectingPath c = ConnectByDeepening(tracer, m_, a, b, CompositeOpt().maxTransportSteps);
      if (c) {
        std::vector<int> cv = c.Vertices();
        seeds.insert(seeds.end(), cv.begin(), cv.end());
      }
    }
    return KRing(m_, seeds, 3);
  }

  Entry Begin() {
    Reserve();
    Entry e;
    e.ed.reset(new Editor(m_));
    e.start = e.ed->Mark();
    e.lead = lead_;
    e.partner = partner_;
    return e;
  }
  /// Records a done edit as one undo entry; drops (commits) the oldest beyond the depth.
  void Push(Entry e, const std::vector<int>& before, const std::vector<int>& after) {
    const int n0 = int(e.start.verts);
    touched_ = before;
    touched_.insert(touched_.end(), after.begin(), after.end());
    for (int i = n0; i < int(m_.vert.size()); ++i) touched_.push_back(i);  // created vertices
    std::sort(touched_.begin(), touched_.end());
    touched_.erase(std::unique(touched_.begin(), touched_.end()), touched_.end());
    e.touched = touched_;
    redo_.clear();
    undo_.push_back(std::move(e));
    while (int(undo_.size()) > opt_.undoDepth) undo_.pop_front();
    Invalidate();
    grid_.Refresh(touched_);
  }

  /// What Compact did: the vertices moved into holes (old index -> new index) and the vertices
  /// whose slot or faces changed (for Touched() and the picking grid).
  struct Compaction {
    std::vector<std::pair<int, int>> moved;
    std::vector<int> touched;
    int Where(int v) const {
      for (const auto& p : moved)
        if (p.first == v) return p.second;
      return v;
    }
  };

  /// Leaves the mesh without deleted elements (m.vert.size() == vn, m.face.size() == fn),
  /// journaled in `ed` so that rolling back to `cp` restores the vectors bit for bit (journal.h
  /// grows them back). Precondition: the mesh had no deleted element at `cp`. The holes are
  /// found among the elements the edit saved or created since `cp` (a deleted element was
  /// saved before its deletion), never by a pass over the mesh; each hole below the end gets
  /// the last live element: a vertex's faces are re-pointed through its VF list (O(valence)),
  /// a face's three FF neighbours and the VF lists of its three vertices are fixed
  /// (O(valence)); deleted elements at the end are truncated (which never reallocates).
  /// Cost O(touched * valence).
  Compaction Compact(Editor& ed, const typename Editor::Checkpoint& cp) {
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;
    auto& j = ed.journal();
    Compaction out;
    // --- vertices
    std::vector<size_t> holes = j.VerticesSavedSince(cp);
    for (size_t i = cp.verts; i < m_.vert.size(); ++i) holes.push_back(i);
    Holes(holes, m_.vert);
    auto dropDeletedTail = [&](auto& vec, auto save) {
      while (!vec.empty() && vec.back().IsD()) {
        save(&vec.back());
        vec.resize(vec.size() - 1);
      }
    };
    auto saveV = [&](VertexType* v) { j.SaveWholeVertex(v); };
    auto saveF = [&](FaceType* f) { j.SaveWholeFace(f); };
    for (size_t i : holes) {
      dropDeletedTail(m_.vert, saveV);
      if (i >= m_.vert.size()) break;
      const size_t last = m_.vert.size() - 1;
      VertexType& to = m_.vert[i];
      VertexType& from = m_.vert[last];
      j.SaveWholeVertex(&to);
      j.SaveWholeVertex(&from);
      for (vcg::face::VFIterator<FaceType> it(&from); !it.End(); ++it) {
        j.SaveFace(it.F());
        it.F()->V(it.I()) = &to;
      }
      to.ImportData(from);
      to.P() = from.P();
      to.Flags() = from.Flags();
      to.VFp() = from.VFp();
      to.VFi() = from.VFi();
      m_.vert.resize(last);
      out.moved.push_back({int(last), int(i)});
      out.touched.push_back(int(i));
      out.touched.push_back(int(last));  // gone now, back after an undo: the grid re-bins both
    }
    dropDeletedTail(m_.vert, saveV);
    // --- faces
    holes = j.FacesSavedSince(cp);
    for (size_t i = cp.faces; i < m_.face.size(); ++i) holes.push_back(i);
    Holes(holes, m_.face);
    for (size_t i : holes) {
      dropDeletedTail(m_.face, saveF);
      if (i >= m_.face.size()) break;
      const size_t last = m_.face.size() - 1;
      FaceType* to = &m_.face[i];
      FaceType* from = &m_.face[last];
      j.SaveWholeFace(to);
      j.SaveWholeFace(from);
      for (int z = 0; z < 3; ++z) {
        FaceType* nb = from->FFp(z);
        if (nb != nullptr && nb != from) {
          j.SaveFace(nb);
          nb->FFp(from->FFi(z)) = to;
        }
        // the VF list of vertex z: its head, or the entry of the face before `from`
        VertexType* v = from->V(z);
        if (v->VFp() == from) {
          j.SaveVertex(v);
          v->VFp() = to;
        } else {
          FaceType* g = v->VFp();
          int gi = v->VFi();
          while (g != nullptr && g != from) {
            if (g->VFp(gi) == from) {
              j.SaveFace(g);
              g->VFp(gi) = to;
              break;
            }
            FaceType* next = g->VFp(gi);
            gi = g->VFi(gi);
            g = next;
          }
        }
        out.touched.push_back(int(vcg::tri::Index(m_, v)));
      }
      to->ImportData(*from);
      to->Flags() = from->Flags();
      for (int z = 0; z < 3; ++z) {
        to->V(z) = from->V(z);
        to->FFp(z) = from->FFp(z) == from ? to : from->FFp(z);
        to->FFi(z) = from->FFi(z);
        to->VFp(z) = from->VFp(z);
        to->VFi(z) = from->VFi(z);
      }
      m_.face.resize(last);
    }
    dropDeletedTail(m_.face, saveF);
    assert(m_.vert.size() == size_t(m_.vn) && m_.face.size() == size_t(m_.fn));
    return out;
  }
  /// Keeps the deleted elements of `cand` (indices into vec), sorted, without repetitions.
  template <class Vec>
  static void Holes(std::vector<size_t>& cand, const Vec& vec) {
    cand.erase(std::remove_if(cand.begin(), cand.end(), [&](size_t i) { return i >= vec.size() || !vec[i].IsD(); }),
               cand.end());
    std::sort(cand.begin(), cand.end());
    cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  }

  /// Keeps spare capacity in m.vert and m.face, so that a split during a step never
  /// reallocates them: vcg's Allocator would then walk every face to fix its pointers, O(F) in
  /// the middle of a step. When fewer than 1024 vertices (2048 faces) are spare, the vectors
  /// grow by max(4096, size / 8) through the Allocator (which fixes the pointers once) and the
  /// added elements are truncated again by a journal rollback: the mesh is as it was, with
  /// room. The only O(mesh) work of a session after its start, once per thousands of
  /// created vertices.
  void Reserve() {
    const bool vert = m_.vert.capacity() - m_.vert.size() < 1024, face = m_.face.capacity() - m_.face.size() < 2048;
    if (!vert && !face) return;
    EditJournal<MeshType> j(m_);
    const typename EditJournal<MeshType>::Checkpoint cp = j.Mark();
    const size_t hv = std::max<size_t>(4096, m_.vert.size() / 8), hf = std::max<size_t>(8192, m_.face.size() / 8);
    if (vert) vcg::tri::Allocator<MeshType>::AddVertices(m_, hv);
    if (face) vcg::tri::Allocator<MeshType>::AddFaces(m_, hf);
    j.RollbackTo(cp);
  }

  /// What an accepted trial did, to do it again in Step without recomputing it.
  struct TrialResult {
    typename EditJournal<MeshType>::Replay replay;  ///< the final state of what it changed
    std::vector<int> compacted;                      ///< Compaction::touched
  };

  /// Direction k tried on the mesh and rolled back (see the header); an accepted one's result
  /// is captured into `keep` (its replay).
  EditDirection<CoordType> Trial(int k, TrialResult& keep) {
    EditDirection<CoordType> d;
    d.k = k;
    d.from = d.to = m_.vert[size_t(lead_)].P();
    Reserve();
    Editor ed(m_);
    const typename Editor::Checkpoint cp = ed.Mark();
    CompositeOutcome o = Ops(ed, &original_, CompositeOpt()).MovePair(lead_, partner_, k, 1);
    d.accepted = o.result.ok;
    if (o) {
      // compacted like Step, so that lead / partner are the indices Step will give
      Compaction c = Compact(ed, cp);
      d.lead = c.Where(o.lead);
      d.partner = c.Where(o.partner);
      d.to = m_.vert[size_t(d.lead)].P();
      keep.replay = ed.journal().CaptureSince(cp);
      keep.compacted = c.touched;
      ed.RollbackTo(cp);
    } else {
      d.reason = o.result.reason;
    }
    return d;
  }

  /// The cancellation of `group` (triple or quadruple): dry run, then the real one as one undo
  /// entry. Refused (mesh unchanged) if either says no.
  Result TryCancel(const std::vector<int>& group, bool quadruple) {
    CompositePredictor<MeshType> pr(m_, &original_, CompositeOpt());
    CompositePrediction p = quadruple ? pr.PredictCancelQuadruple(group) : pr.PredictCancelTriple(group);
    if (!p) return p.result;
    std::vector<int> before;
    for (size_t i = 0; i < group.size(); ++i)
      for (size_t j = i + 1; j < group.size(); ++j) {
        std::vector<int> r = PairRegion(group[i], group[j]);
        before.insert(before.end(), r.begin(), r.end());
      }
    Entry e = Begin();
    e.action = quadruple ? Action::Quadruple : Action::Triple;
    Ops co(*e.ed, &original_, CompositeOpt());
    CompositeOutcome o = quadruple ? co.CancelQuadruple(group) : co.CancelTriple(group);
    if (!o) return o.result;
    Compaction c = Compact(*e.ed, e.start);
    const int survivor = c.Where(o.survivor);
    std::vector<int> after(c.touched);
    if (!quadruple && Live(survivor)) {
      std::vector<int> r = KRing(m_, {survivor}, 3);
      after.insert(after.end(), r.begin(), r.end());
    }
    Push(std::move(e), before, after);
    std::string what = quadruple ? "quadruple" : "triple";
    std::string ids = Str(group[0], ", ", group[1], ", ", group[2]) + (quadruple ? Str(", ", group[3]) : std::string());
    if (quadruple || !Live(survivor)) {
      lead_ = partner_ = -1;
      return Say(Result::Ok(), Str("cancelled the ", what, " (", ids, ")"));
    }
    lead_ = survivor;
    partner_ = NearestPartner(lead_);
    return Say(Result::Ok(), Str("cancelled the triple (", ids, "): vertex ", lead_, " (valence ", Valence(lead_),
                                 ") is left", partner_ >= 0 ? Str(", paired with vertex ", partner_) : std::string()));
  }

  MeshType& m_;
  EditSessionOptions opt_;
  SurfaceProjector original_;
  PickGrid<MeshType> grid_;
  int lead_ = -1, partner_ = -1;
  std::string message_;
  std::deque<Entry> undo_;
  struct Redoable {
    Action action;
    int k, lead, partner;
  };
  std::vector<Redoable> redo_;
  std::vector<int> touched_;
  std::vector<EditDirection<CoordType>> dirs_;
  std::vector<char> known_ = std::vector<char>(6, 0);  ///< dirs_[k] holds the current state's trial
  std::vector<TrialResult> trials_ = std::vector<TrialResult>(6);  ///< and trials_[k] its result, if accepted
};

}  // namespace irregular
}  // namespace vcg_ext
