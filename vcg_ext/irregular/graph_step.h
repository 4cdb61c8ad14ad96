// filter_irregular: one graph operation of sec. 6.1 as a step of a plan (atomic operations,
// type change): what a dry run predicts and what the real operation then executes.
#pragma once

#include <sstream>
#include <string>

namespace vcg_ext {
namespace irregular {

/// One graph operation of sec. 6.1.
///   Flip:     flip edge (x, y).
///   Collapse: collapse vertex x into y (x is deleted, y survives).
///   Split:    split vertex x along its edges to y and z; x keeps the edges from y to z
///             counter-clockwise, a new vertex takes the others (MeshEditor::Split(x, y, z)).
struct GraphStep {
  enum Kind { kFlip, kCollapse, kSplit };
  Kind kind = kFlip;
  int x = -1, y = -1, z = -1;
  int created = -1;  ///< Split, when the plan names it: the new vertex (m.vert.size() at that time)
  std::string Describe() const {
    std::ostringstream o;
    if (kind == kFlip) o << "flip edge (" << x << ", " << y << ")";
    else if (kind == kCollapse) o << "collapse vertex " << x << " into " << y;
    else o << "split vertex " << x << " along edges (" << x << ", " << y << ") and (" << x << ", " << z << ")";
    if (kind == kSplit && created >= 0) o << ": new vertex " << created;
    return o.str();
  }
  bool operator==(const GraphStep& s) const {
    return kind == s.kind && x == s.x && y == s.y && z == s.z && created == s.created;
  }
};

}  // namespace irregular
}  // namespace vcg_ext
