// filter_irregular: MeshLab 2025.07 adapter. Parameters become RichParameters (RichPercentage
// for lengths, RichPosition for points); a refusal throws MLException (a message box in the
// GUI, pymeshlab.PyMeshLabException in Python) after logging the reason; the output values are
// returned as the filter's map (a dict in pymeshlab: ints, floats, bools and numpy vectors).
#include "filter_irregular_plugin.h"

#include <common/mlexception.h>

#include "../adapter_shared.h"
#include "../core/filter_spec.h"

namespace fi = filter_irregular;

FilterIrregularPlugin::FilterIrregularPlugin() {
  for (const fi::FilterSpec& f : fi::Catalog()) typeList.push_back(f.id);
  for (ActionIDType t : types()) actionList.push_back(new QAction(filterName(t), this));
}

QString FilterIrregularPlugin::pluginName() const { return "FilterIrregular"; }

QString FilterIrregularPlugin::filterName(ActionIDType id) const {
  const fi::FilterSpec* f = fi::FindFilter(int(id));
  return f ? QString::fromStdString(f->name) : QString();
}

QString FilterIrregularPlugin::pythonFilterName(ActionIDType id) const {
  const fi::FilterSpec* f = fi::FindFilter(int(id));
  return f ? QString::fromStdString(f->pythonName) : QString();
}

QString FilterIrregularPlugin::filterInfo(ActionIDType id) const {
  const fi::FilterSpec* f = fi::FindFilter(int(id));
  return f ? QString::fromStdString(f->info) : QString();
}

FilterPlugin::FilterClass FilterIrregularPlugin::getClass(const QAction* a) const {
  return FilterClass(fi::FindFilter(int(ID(a)))->classes);
}

int FilterIrregularPlugin::getRequirements(const QAction*) {
  return MeshModel::MM_FACEFACETOPO | MeshModel::MM_VERTFACETOPO;
}

int FilterIrregularPlugin::getPreConditions(const QAction*) const { return MeshModel::MM_FACENUMBER; }

int FilterIrregularPlugin::postCondition(const QAction* a) const {
  return fi::PostConditionOf<MeshModel>(*fi::FindFilter(int(ID(a))));
}

RichParameterList FilterIrregularPlugin::initParameterList(const QAction* a, const MeshModel& m) {
  RichParameterList par;
  fi::AddParams(
      *fi::FindFilter(int(ID(a))), m.cm.bbox.Diag(), par,
      [](const QString& name, double def, double max, const QString& label, const QString& help) {
        return RichPercentage(name, Scalarm(def), 0, Scalarm(max), label, help);
      },
      [](const QString& name, const QString& label, const QString& help) {
        return RichPosition(name, Point3m(0, 0, 0), label, help);
      });
  return par;
}

std::map<std::string, QVariant> FilterIrregularPlugin::applyFilter(const QAction* a, const RichParameterList& par,
                                                                   MeshDocument& md, unsigned int& postConditionMask,
                                                                   vcg::CallBackPos* cb) {
  const fi::FilterSpec& spec = *fi::FindFilter(int(ID(a)));
  const fi::FilterOutcome out =
      fi::ApplyToDocument(spec, md, par, cb, [this](fi::LogLevel level, const std::string& line) {
        log(level == fi::LogLevel::Warning ? GLLogStream::WARNING : GLLogStream::FILTER, line);
      });
  if (!out.ok) throw MLException(QString::fromStdString(out.reason));
  postConditionMask = fi::PostConditionOf<MeshModel>(spec);
  std::map<std::string, QVariant> values;
  for (auto& kv : out.values) {
    const fi::OutputValue& v = kv.second;
    switch (v.kind) {
      case fi::OutputValue::Int: values[kv.first] = QVariant(int(v.number)); break;
      case fi::OutputValue::Float: values[kv.first] = QVariant(double(v.number)); break;
      case fi::OutputValue::Bool: values[kv.first] = QVariant(v.number != 0); break;
      case fi::OutputValue::Vector: {
        Eigen::VectorXd e(Eigen::Index(v.vector.size()));
        for (size_t i = 0; i < v.vector.size(); ++i) e[Eigen::Index(i)] = v.vector[i];
        values[kv.first] = QVariant::fromValue(e);
        break;
      }
    }
  }
  return values;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterIrregularPlugin)
