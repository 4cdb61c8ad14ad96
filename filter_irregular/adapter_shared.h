// filter_irregular: the translation both MeshLab adapters share, where MeshLab 2020.09 and
// 2025.07 spell things the same way (RichParameterList getters, MeshModel's MM_* masks,
// vcg's progress callback). Included by meshlab2020/ and meshlab2025/ only.
#pragma once

#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include <QString>
#include <QStringList>

#include "core/filter_spec.h"
#include "core/mesh_type.h"

namespace filter_irregular {

/// Reads every parameter the spec lists from MeshLab's list (same getters in both APIs).
template <class RichParameterListT>
ParamValues ReadParams(const FilterSpec& spec, const RichParameterListT& par) {
  ParamValues v;
  for (const ParamSpec& p : spec.params) {
    const QString name = QString::fromStdString(p.name);
    switch (p.type) {
      case ParamType::Bool: v.Set(p.name, par.getBool(name) ? 1 : 0); break;
      case ParamType::Int: v.Set(p.name, par.getInt(name)); break;
      case ParamType::Float: v.Set(p.name, par.getFloat(name)); break;
      case ParamType::Enum: v.Set(p.name, par.getEnum(name)); break;
      case ParamType::Percentage: v.Set(p.name, par.getAbsPerc(name)); break;
      case ParamType::Point3: {
        const auto q = par.getPoint3m(name);
        v.SetPoint(p.name, vcg::Point3d(q[0], q[1], q[2]));
        break;
      }
    }
  }
  return v;
}

/// Adds the spec's parameters to MeshLab's list. Bool, Int, Float and Enum parameters have the
/// same classes in both APIs; lengths and points do not, so the adapter passes their makers:
/// percentage(name, default, max, label, help) and point(name, label, help).
template <class RichParameterListT, class MakePercentage, class MakePoint>
void AddParams(const FilterSpec& spec, double diagonal, RichParameterListT& par, MakePercentage percentage,
               MakePoint point) {
  for (const ParamSpec& p : spec.params) {
    const QString name = QString::fromStdString(p.name), label = QString::fromStdString(p.label),
                  help = QString::fromStdString(p.help);
    switch (p.type) {
      case ParamType::Bool: par.addParam(RichBool(name, p.defaultValue != 0, label, help)); break;
      case ParamType::Int: par.addParam(RichInt(name, int(p.defaultValue), label, help)); break;
      case ParamType::Float: par.addParam(RichFloat(name, Scalarm(p.defaultValue), label, help)); break;
      case ParamType::Enum: {
        QStringList values;
        for (const std::string& s : p.enumValues) values << QString::fromStdString(s);
        par.addParam(RichEnum(name, int(p.defaultValue), values, label, help));
        break;
      }
      case ParamType::Percentage: par.addParam(percentage(name, p.defaultValue, diagonal, label, help)); break;
      case ParamType::Point3: par.addParam(point(name, label, help)); break;
    }
  }
}

/// MeshModel's data mask for the components a filter asks for (same MM_* in both APIs).
template <class MeshModelT>
int DataMaskOf(unsigned components) {
  int mask = 0;
  if (components & kVertColor) mask |= MeshModelT::MM_VERTCOLOR;
  if (components & kVertQuality) mask |= MeshModelT::MM_VERTQUALITY;
  if (components & kVertMark) mask |= MeshModelT::MM_VERTMARK;
  if (components & kFaceMark) mask |= MeshModelT::MM_FACEMARK;
  if (components & kFaceFlag) mask |= MeshModelT::MM_FACEFLAG;
  if (components & kFaceColor) mask |= MeshModelT::MM_FACECOLOR;
  if (components & kFaceQuality) mask |= MeshModelT::MM_FACEQUALITY;
  return mask;
}

/// What changes, for MeshLab's render buffers (postCondition). A filter that edits
/// connectivity changes geometry and topology, and rewrites the attributes the edits carry by
/// interpolation (vcg_ext/irregular/attribute_transfer.h): wedge and vertex texture
/// coordinates, face and vertex colour and quality. They are declared updated, so MeshLab
/// refreshes them; they are not dropped: the filter needs none of them (DataMaskOf asks only
/// for what it writes) and carries whichever the mesh has. Not MM_ALL, which would also
/// claim the camera, the transform and wedge normals and colours (CMeshO has none) and, in
/// MeshLab's words, "could add unwanted data to the layer".
template <class MeshModelT>
int PostConditionOf(const FilterSpec& spec) {
  if (!spec.changesConnectivity)
    return MeshModelT::MM_VERTCOLOR | MeshModelT::MM_VERTQUALITY | MeshModelT::MM_VERTFLAGSELECT;
  return MeshModelT::MM_GEOMETRY_AND_TOPOLOGY_CHANGE | MeshModelT::MM_VERTCOLOR | MeshModelT::MM_VERTQUALITY |
         MeshModelT::MM_VERTTEXCOORD | MeshModelT::MM_FACECOLOR | MeshModelT::MM_FACEQUALITY |
         MeshModelT::MM_WEDGTEXCOORD | MeshModelT::MM_VERTFLAGSELECT | MeshModelT::MM_FACEFLAGSELECT;
}

/// MeshLab's standard update after a filter wrote a mesh's coordinates: bounding box, face
/// and vertex normals (MeshModel::updateBoxAndNormals in 2025.07, UpdateBoxAndNormals in 2020.09).
template <class MeshModelT>
auto UpdateBoxAndNormalsOf(MeshModelT& mm, int) -> decltype(mm.updateBoxAndNormals(), void()) {
  mm.updateBoxAndNormals();
}
template <class MeshModelT>
void UpdateBoxAndNormalsOf(MeshModelT& mm, long) {
  mm.UpdateBoxAndNormals();
}

/// Removes a layer from the document: delMesh(MeshModel*) in 2020.09, delMesh(id) in 2025.07.
template <class MeshDocumentT, class MeshModelT>
auto DeleteLayerOf(MeshDocumentT& md, MeshModelT* mm, int) -> decltype(md.delMesh(mm), void()) {
  md.delMesh(mm);
}
template <class MeshDocumentT, class MeshModelT>
void DeleteLayerOf(MeshDocumentT& md, MeshModelT* mm, long) {
  md.delMesh(mm->id());
}

/// The FilterContext of a MeshModel; logging goes through the adapter's logger. NewLayer adds
/// a layer to the document the way MeshLab's own filters do (filter_meshing's "Unrolled Mesh",
/// filter_create): MeshDocument::addNewMesh("", label), here without making it current, so
/// the filter's mesh stays the current one (pymeshlab's MeshSet lists the layer after it);
/// with per-face colour enabled. Finish() then updates each new layer's box and normals (as
/// those filters call updateBoxAndNormals after filling it), or, when the filter refused,
/// deletes the new layers, so a refusal leaves the document as it was.
template <class MeshModelT, class MeshDocumentT = void>
class MeshModelContext : public FilterContext {
 public:
  MeshModelContext(MeshModelT& mm, vcg::CallBackPos* cb, std::function<void(LogLevel, const std::string&)> logger,
                   MeshDocumentT* md = nullptr)
      : mm_(mm), cb_(cb), logger_(std::move(logger)), md_(md) {}
  CMeshO& Mesh() override { return mm_.cm; }
  void Require(unsigned components) override { mm_.updateDataMask(DataMaskOf<MeshModelT>(components)); }
  void Log(LogLevel level, const std::string& line) override { logger_(level, line); }
  bool (*Progress())(const int, const char*) override { return cb_; }
  CMeshO* NewLayer(const std::string& label) override {
    if constexpr (std::is_void_v<MeshDocumentT>) {
      (void)label;
      return nullptr;
    } else {
      if (md_ == nullptr) return nullptr;
      MeshModelT* layer = md_->addNewMesh("", QString::fromStdString(label), false);
      if (layer == nullptr) return nullptr;
      layer->updateDataMask(MeshModelT::MM_FACECOLOR);
      layers_.push_back(layer);
      return &layer->cm;
    }
  }
  /// After the filter: update the new layers (ok) or remove them (refused).
  void Finish(bool ok) {
    if constexpr (!std::is_void_v<MeshDocumentT>) {
      for (MeshModelT* layer : layers_) {
        if (ok)
          UpdateBoxAndNormalsOf(*layer, 0);
        else
          DeleteLayerOf(*md_, layer, 0);
      }
    }
    (void)ok;
    layers_.clear();
  }

 private:
  MeshModelT& mm_;
  vcg::CallBackPos* cb_;
  std::function<void(LogLevel, const std::string&)> logger_;
  MeshDocumentT* md_;
  std::vector<MeshModelT*> layers_;
};

inline std::string OutputValuesText(const FilterOutcome& out);

/// Applies the filter to the document's current mesh, as both adapters do: the context, the
/// parameters, and the log lines "Irregular Vertices: refused: <reason>" (meshlabserver never
/// prints a filter's error message, so the reason must be in the log) or
/// "Irregular Vertices: returned: <values>". The adapter turns a refusal into its API's error.
template <class MeshDocumentT, class RichParameterListT>
FilterOutcome ApplyToDocument(const FilterSpec& spec, MeshDocumentT& md, const RichParameterListT& par,
                              vcg::CallBackPos* cb, const std::function<void(LogLevel, const std::string&)>& log) {
  auto* mm = md.mm();
  FilterOutcome out;
  if (mm == nullptr) {
    out = FilterOutcome::Refuse("There is no current mesh.");
  } else {
    MeshModelContext<std::remove_pointer_t<decltype(mm)>, MeshDocumentT> ctx(*mm, cb, log, &md);
    out = ApplyFilter(spec, ctx, ReadParams(spec, par));
    ctx.Finish(out.ok);
  }
  if (!out.ok)
    log(LogLevel::Warning, "Irregular Vertices: refused: " + out.reason);
  else
    log(LogLevel::Info, "Irregular Vertices: returned: " + OutputValuesText(out));
  return out;
}

/// "key=value key=[a b c] ..." for the log (meshlabserver users read the output values there).
inline std::string OutputValuesText(const FilterOutcome& out) {
  std::string s;
  for (auto& kv : out.values) {
    s += (s.empty() ? "" : " ") + kv.first + "=";
    const OutputValue& v = kv.second;
    switch (v.kind) {
      case OutputValue::Int: s += Format("%lld", (long long)v.number); break;
      case OutputValue::Bool: s += v.number != 0 ? "true" : "false"; break;
      case OutputValue::Float: s += Format("%.6g", v.number); break;
      case OutputValue::Vector: {
        s += "[";
        for (size_t i = 0; i < v.vector.size(); ++i) s += Format(i ? " %.6g" : "%.6g", v.vector[i]);
        s += "]";
        break;
      }
    }
  }
  return s;
}

}  // namespace filter_irregular
