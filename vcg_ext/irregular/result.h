// filter_irregular: the result of an operation that can be refused.
#pragma once
#include <sstream>
#include <string>
#include <utility>

namespace vcg_ext {
namespace irregular {

/// Success, or failure with a reason written for the user ("the edge (12, 40) lies on the
/// boundary"). Every operation of vcg_ext that can be refused returns one; a refused
/// operation leaves the mesh exactly as it was.
struct Result {
  bool ok = true;
  std::string reason;

  static Result Ok() { return Result(); }
  static Result Fail(std::string why) {
    Result r;
    r.ok = false;
    r.reason = std::move(why);
    return r;
  }
  explicit operator bool() const { return ok; }
};

/// Concatenates its arguments as an ostream would print them: the refusal texts' builder
/// ("vertices ", v5, " and ", v7, " are not adjacent").
template <class... Args>
std::string Str(const Args&... args) {
  std::ostringstream o;
  using expand = int[];
  (void)expand{0, ((o << args), 0)...};
  return o.str();
}

}  // namespace irregular
}  // namespace vcg_ext
