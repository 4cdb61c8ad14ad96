// filter_irregular: what a filter is, independently of the MeshLab API that hosts it.
//
// Every filter of the plugin is described once, in filter_catalog.cpp, by a FilterSpec: its
// menu name (also its name in .mlx scripts), its pymeshlab name, its help, its MeshLab
// category, its parameters (types, defaults, ranges, help) and the function that applies it.
// The two MeshLab adapters (meshlab2020/ for MeshFilterInterface, meshlab2025/ for the 2022+
// FilterPlugin) only translate: parameters to and from RichParameterList, the log, progress,
// the mesh's optional components, and the outcome (a refusal becomes a message box, an
// MLException / PyMeshLabException, or meshlabserver's exit status 255).
//
// Nothing here depends on Qt or on MeshLab beyond the mesh type CMeshO, whose header each
// adapter provides (mesh_type.h).
#pragma once

#include <array>
#include <cstdarg>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <vcg/space/point3.h>

class CMeshO;

namespace filter_irregular {

/// MeshLab's filter classes (menu categories); both APIs use these bit values.
enum FilterClassBits : unsigned {
  kSelection = 0x00001,
  kRemeshing = 0x00004,
  kFaceColoring = 0x00008,
  kSmoothing = 0x00080,
  kQuality = 0x00100,
  kMeasure = 0x10000,
};

enum class ParamType {
  Bool,
  Int,
  Float,
  Enum,        ///< an index into enumValues; pymeshlab takes the value's text
  Percentage,  ///< an absolute length in [0, bounding-box diagonal]; RichAbsPerc / RichPercentage
  Point3,      ///< a position; RichPoint3f / RichPosition
};

/// One parameter. Its name is the one .mlx scripts use; pymeshlab lowercases it.
struct ParamSpec {
  std::string name;
  ParamType type = ParamType::Int;
  double defaultValue = 0;  ///< Bool: 0/1; Enum: index; Percentage: absolute value
  std::string label;        ///< the dialog's label
  std::string help;         ///< the tooltip and the documentation
  std::vector<std::string> enumValues;
  /// Accepted range for Int and Float (inclusive); outside it the filter refuses with a
  /// message naming the parameter. Percentage: always [0, diagonal].
  double minValue = -1e30, maxValue = 1e30;
};

/// Parameter values, by name, as the adapter read them from MeshLab.
class ParamValues {
 public:
  void Set(const std::string& name, double v) { numbers_[name] = v; }
  void SetPoint(const std::string& name, const vcg::Point3d& p) { points_[name] = p; }
  bool Bool(const std::string& name) const { return Number(name) != 0; }
  int Int(const std::string& name) const { return int(Number(name)); }
  int Enum(const std::string& name) const { return int(Number(name)); }
  double Float(const std::string& name) const { return Number(name); }
  vcg::Point3d Point(const std::string& name) const;
  double Number(const std::string& name) const;

 private:
  std::map<std::string, double> numbers_;
  std::map<std::string, vcg::Point3d> points_;
};

/// A value a filter returns: pymeshlab gets them as a dict (numbers, bools and numpy vectors;
/// it drops strings, so reasons are documented integer codes); meshlabserver's log lists them.
struct OutputValue {
  enum Kind { Int, Float, Bool, Vector } kind = Int;
  double number = 0;
  std::vector<double> vector;
};

/// What applying a filter gave: success with output values, or a refusal with the reason.
/// A refused filter has left the mesh exactly as it was.
struct FilterOutcome {
  bool ok = true;
  std::string reason;
  std::vector<std::pair<std::string, OutputValue>> values;

  static FilterOutcome Refuse(std::string why) {
    FilterOutcome o;
    o.ok = false;
    o.reason = std::move(why);
    return o;
  }
  void SetInt(const std::string& key, long long v);
  void SetFloat(const std::string& key, double v);
  void SetBool(const std::string& key, bool v);
  void SetVector(const std::string& key, std::vector<double> v);
  const OutputValue* Find(const std::string& key) const;
};

/// Optional per-element components of MeshLab's mesh a filter needs enabled.
enum Component : unsigned {
  kVertColor = 1,
  kVertQuality = 2,
  kVertMark = 4,
  kFaceMark = 8,
  kFaceFlag = 16,
  kFaceColor = 32,
  kFaceQuality = 64,
};

enum class LogLevel { Info, Warning };

/// What a filter can ask of its host. Implemented by each adapter.
class FilterContext {
 public:
  virtual ~FilterContext() = default;
  /// The current mesh, with FF and VF adjacency up to date.
  virtual CMeshO& Mesh() = 0;
  /// Enables optional components (colour, quality, marks) so MeshLab knows about them.
  virtual void Require(unsigned components) = 0;
  virtual void Log(LogLevel level, const std::string& line) = 0;
  /// vcg's progress callback, or null.
  virtual bool (*Progress())(const int, const char*) = 0;
  /// A new, empty mesh layer in the document, named `label`, for filters that write a second
  /// mesh (the Pattern filter's panels). Null when the host cannot add layers.
  virtual CMeshO* NewLayer(const std::string& label) {
    (void)label;
    return nullptr;
  }

  void Logf(const char* fmt, ...) __attribute__((format(printf, 2, 3)));
  void Warnf(const char* fmt, ...) __attribute__((format(printf, 2, 3)));
};

/// printf into a std::string.
std::string Format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string FormatV(const char* fmt, va_list ap);

/// One filter, complete.
struct FilterSpec {
  int id = 0;
  std::string name;        ///< menu entry and .mlx name: "Irregular Vertices: Analyze"
  std::string pythonName;  ///< pymeshlab: ms.compute_irregular_vertices_analysis(...)
  std::string info;        ///< help text (HTML)
  unsigned classes = 0;    ///< FilterClassBits: the menus it appears in
  bool changesConnectivity = true;  ///< false: only colours, quality and selection change
  std::vector<ParamSpec> params;
  std::function<FilterOutcome(FilterContext&, const ParamValues&)> apply;
};

/// All filters of the plugin, in menu order.
const std::vector<FilterSpec>& Catalog();
const FilterSpec* FindFilter(int id);

/// Checks every parameter against its range; applies the filter; catches the unexpected so
/// the host never sees an exception other than a refusal. The single entry point both
/// adapters call.
FilterOutcome ApplyFilter(const FilterSpec& spec, FilterContext& ctx, const ParamValues& values);

}  // namespace filter_irregular
