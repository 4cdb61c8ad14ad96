// filter_irregular: the host-independent pieces of filter_spec.h (values, formatting, the
// checked entry point).
#include "filter_spec.h"

#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>

#include "mesh_type.h"

namespace filter_irregular {

double ParamValues::Number(const std::string& name) const {
  auto it = numbers_.find(name);
  if (it == numbers_.end()) throw std::logic_error("filter_irregular: parameter '" + name + "' was not passed");
  return it->second;
}

vcg::Point3d ParamValues::Point(const std::string& name) const {
  auto it = points_.find(name);
  if (it == points_.end()) throw std::logic_error("filter_irregular: parameter '" + name + "' was not passed");
  return it->second;
}

void FilterOutcome::SetInt(const std::string& key, long long v) {
  OutputValue o;
  o.kind = OutputValue::Int;
  o.number = double(v);
  values.emplace_back(key, o);
}
void FilterOutcome::SetFloat(const std::string& key, double v) {
  OutputValue o;
  o.kind = OutputValue::Float;
  o.number = v;
  values.emplace_back(key, o);
}
void FilterOutcome::SetBool(const std::string& key, bool v) {
  OutputValue o;
  o.kind = OutputValue::Bool;
  o.number = v ? 1 : 0;
  values.emplace_back(key, o);
}
void FilterOutcome::SetVector(const std::string& key, std::vector<double> v) {
  OutputValue o;
  o.kind = OutputValue::Vector;
  o.vector = std::move(v);
  values.emplace_back(key, o);
}
const OutputValue* FilterOutcome::Find(const std::string& key) const {
  for (auto& kv : values)
    if (kv.first == key) return &kv.second;
  return nullptr;
}

std::string FormatV(const char* fmt, va_list ap) {
  va_list copy;
  va_copy(copy, ap);
  const int n = std::vsnprintf(nullptr, 0, fmt, copy);
  va_end(copy);
  std::string s(size_t(std::max(n, 0)), '\0');
  if (n > 0) std::vsnprintf(&s[0], size_t(n) + 1, fmt, ap);
  return s;
}

std::string Format(const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  std::string s = FormatV(fmt, ap);
  va_end(ap);
  return s;
}

void FilterContext::Logf(const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  Log(LogLevel::Info, FormatV(fmt, ap));
  va_end(ap);
}

void FilterContext::Warnf(const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  Log(LogLevel::Warning, FormatV(fmt, ap));
  va_end(ap);
}

const FilterSpec* FindFilter(int id) {
  for (const FilterSpec& f : Catalog())
    if (f.id == id) return &f;
  return nullptr;
}

namespace {
/// The value as a person would write it: integers without decimals.
std::string Shown(double v) {
  if (v == std::floor(v) && std::fabs(v) < 1e15) return Format("%lld", (long long)v);
  return Format("%g", v);
}
}  // namespace

FilterOutcome ApplyFilter(const FilterSpec& spec, FilterContext& ctx, const ParamValues& values) {
  try {
    for (const ParamSpec& p : spec.params) {
      if (p.type == ParamType::Point3) {
        const vcg::Point3d q = values.Point(p.name);
        if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
          return FilterOutcome::Refuse(Format("Parameter '%s' (%s) is not a finite point.", p.name.c_str(), p.label.c_str()));
        continue;
      }
      const double v = values.Number(p.name);
      if (!std::isfinite(v))
        return FilterOutcome::Refuse(Format("Parameter '%s' (%s) is not a finite number.", p.name.c_str(), p.label.c_str()));
      if (p.type == ParamType::Enum && (v < 0 || v >= double(p.enumValues.size())))
        return FilterOutcome::Refuse(Format("Parameter '%s' (%s) must be one of %zu choices; got index %s.", p.name.c_str(),
                                            p.label.c_str(), p.enumValues.size(), Shown(v).c_str()));
      if ((p.type == ParamType::Int || p.type == ParamType::Float) && (v < p.minValue || v > p.maxValue))
        return FilterOutcome::Refuse(Format("Parameter '%s' (%s) must be between %s and %s; got %s.", p.name.c_str(),
                                            p.label.c_str(), Shown(p.minValue).c_str(), Shown(p.maxValue).c_str(),
                                            Shown(v).c_str()));
      if (p.type == ParamType::Percentage) {
        const double diag = ctx.Mesh().bbox.Diag();
        if (v < 0 || v > diag * (1 + 1e-6))
          return FilterOutcome::Refuse(Format("Parameter '%s' (%s) must be between 0 and the bounding-box diagonal "
                                              "(%g); got %g.",
                                              p.name.c_str(), p.label.c_str(), diag, v));
      }
    }
    return spec.apply(ctx, values);
  } catch (const std::bad_alloc&) {
    return FilterOutcome::Refuse("Out of memory while applying '" + spec.name + "'.");
  } catch (const std::exception& e) {
    return FilterOutcome::Refuse("Internal error in '" + spec.name + "': " + e.what() + " (please report it).");
  }
}

}  // namespace filter_irregular
