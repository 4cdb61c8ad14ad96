// filter_irregular: the logic of the interactive edit tool (paper sec. 9: "select a vertex pair
// and one of six movement directions ... interleaved with local and global relaxation").
// SKELETON: the contract the GUI plugins code against; the implementation is being written
// (issue 16). No Qt, no OpenGL: the GUI passes positions and a projection in.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <vcg/space/point2.h>

#include "result.h"

namespace vcg_ext {
namespace irregular {

struct EditSessionOptions {
  bool relax = true;         ///< local relaxation of the touched region after every step (sec. 8)
  int relaxIterations = 3;   ///< sweeps of that relaxation
  int undoDepth = 200;       ///< steps kept for Undo (at least 100, the issue's floor)
  double pickRadius = 0;     ///< picking radius in model units; 0: 1.5 mean edge lengths
};

/// One of the six movement directions of the picked pair (atomic_ops.h convention k = 0..5).
template <class CoordType>
struct EditDirection {
  int k = 0;
  bool accepted = false;  ///< the dry run says the step would be done
  std::string reason;     ///< why not, when refused
  CoordType from, to;     ///< the moved vertex now, and where it would be after the step
};

template <class MeshType>
class EditSession {
 public:
  typedef typename MeshType::CoordType CoordType;

  explicit EditSession(MeshType& m, EditSessionOptions opt = EditSessionOptions()) : m_(m), opt_(opt) {}

  // --- picking
  /// Picks the irregular vertex nearest to `surfacePoint` (within the pick radius) and its
  /// nearest irregular partner as the pair.
  Result PickAt(const CoordType& surfacePoint) { (void)surfacePoint; return NotYet(); }
  /// Picks vertex v as the lead, and its nearest irregular partner.
  Result PickVertex(int v) { (void)v; return NotYet(); }
  /// Makes v the partner of the current lead (a second click).
  Result PickPartner(int v) { (void)v; return NotYet(); }
  /// The pair from the current vertex selection (exactly two selected vertices, or one).
  Result PickFromSelection() { return NotYet(); }
  bool HasPair() const { return lead_ >= 0 && partner_ >= 0; }
  int Lead() const { return lead_; }
  int Partner() const { return partner_; }

  // --- directions and steps
  /// The six directions with their dry-run verdicts (empty without a pair).
  std::vector<EditDirection<CoordType>> Directions() { return {}; }
  /// The accepted direction whose drawn arrow (projected by `project`) is closest in angle to
  /// the screen vector `screen` (arrow keys, mouse drag); -1 if none.
  int DirectionToward(const std::function<vcg::Point2d(const CoordType&)>& project, vcg::Point2d screen) {
    (void)project; (void)screen; return -1;
  }
  /// One step of the pair in direction k, then local relaxation; one undo entry.
  Result Step(int k) { (void)k; return NotYet(); }
  /// Cancels the triple / quadruple the pair is part of, when the paper's conditions hold.
  Result CancelTriple() { return NotYet(); }
  Result CancelQuadruple() { return NotYet(); }
  /// Undoes the last step (or cancellation); false when there is nothing to undo.
  bool Undo() { return false; }
  int UndoDepth() const { return 0; }
  /// The last refusal or success message, for the viewport and the log.
  const std::string& Message() const { return message_; }

 private:
  Result NotYet() { return Result::Fail("the edit tool is not implemented yet"); }
  MeshType& m_;
  EditSessionOptions opt_;
  int lead_ = -1, partner_ = -1;
  std::string message_;
};

}  // namespace irregular
}  // namespace vcg_ext
