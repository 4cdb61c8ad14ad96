// filter_irregular: the result of an operation that can be refused.
#pragma once
#include <sstream>
#include <string>
#include <type_traits>
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

namespace str_detail {
// Text and integers are appended directly; anything else (floating point, chars, points) is
// printed by an ostream, so every argument reads exactly as `o << arg` prints it. Why: the
// descriptions and refusals of predictions are built for every candidate an edit considers,
// and an ostringstream per text cost about 4% of Automatic Reduction's time.
inline void Append(std::string& s, const std::string& x) { s += x; }
inline void Append(std::string& s, const char* x) { s += x; }
template <size_t N>
void Append(std::string& s, const char (&x)[N]) {
  s += static_cast<const char*>(x);
}
template <class T>
typename std::enable_if<std::is_integral<T>::value && !std::is_same<T, char>::value &&
                        !std::is_same<T, signed char>::value && !std::is_same<T, unsigned char>::value>::type
Append(std::string& s, T x) {
  if (std::is_same<T, bool>::value) s += x ? '1' : '0';  // as an ostream without boolalpha
  else s += std::to_string(x);
}
template <class T>
typename std::enable_if<!std::is_integral<T>::value || std::is_same<T, char>::value ||
                        std::is_same<T, signed char>::value || std::is_same<T, unsigned char>::value>::type
Append(std::string& s, const T& x) {
  std::ostringstream o;
  o << x;
  s += o.str();
}
}  // namespace str_detail

/// Concatenates its arguments as an ostream would print them: the refusal texts' builder
/// ("vertices ", v5, " and ", v7, " are not adjacent").
template <class... Args>
std::string Str(const Args&... args) {
  std::string s;
  using expand = int[];
  (void)expand{0, (str_detail::Append(s, args), 0)...};
  return s;
}

}  // namespace irregular
}  // namespace vcg_ext
