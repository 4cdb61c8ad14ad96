// filter_irregular: MeshLab 2020.09 adapter. Parameters become RichParameters (RichAbsPerc for
// lengths, RichPoint3f for points); a refusal sets errorMessage (the GUI's message box) and
// logs the reason (meshlabserver prints the log but not errorMessage, and exits with 255); the
// output values are logged on one line ("Irregular Vertices: returned: key=value ...").
#include "filter_irregular_plugin.h"

#include "../adapter_shared.h"
#include "../core/filter_spec.h"

namespace fi = filter_irregular;

FilterIrregularPlugin::FilterIrregularPlugin() {
  for (const fi::FilterSpec& f : fi::Catalog()) typeList << f.id;
  for (FilterIDType t : types()) actionList << new QAction(filterName(t), this);
}

QString FilterIrregularPlugin::pluginName() const { return "FilterIrregular"; }

QString FilterIrregularPlugin::filterName(FilterIDType id) const {
  const fi::FilterSpec* f = fi::FindFilter(id);
  return f ? QString::fromStdString(f->name) : QString();
}

QString FilterIrregularPlugin::filterInfo(FilterIDType id) const {
  const fi::FilterSpec* f = fi::FindFilter(id);
  return f ? QString::fromStdString(f->info) : QString();
}

MeshFilterInterface::FilterClass FilterIrregularPlugin::getClass(QAction* a) {
  return FilterClass(fi::FindFilter(ID(a))->classes);
}

int FilterIrregularPlugin::getRequirements(QAction*) {
  return MeshModel::MM_FACEFACETOPO | MeshModel::MM_VERTFACETOPO;
}

int FilterIrregularPlugin::getPreConditions(QAction*) const { return MeshModel::MM_FACENUMBER; }

int FilterIrregularPlugin::postCondition(QAction* a) const {
  return fi::PostConditionOf<MeshModel>(*fi::FindFilter(ID(a)));
}

void FilterIrregularPlugin::initParameterSet(QAction* a, MeshModel& m, RichParameterList& par) {
  fi::AddParams(
      *fi::FindFilter(ID(a)), m.cm.bbox.Diag(), par,
      [](const QString& name, double def, double max, const QString& label, const QString& help) {
        return RichAbsPerc(name, float(def), 0.f, float(max), label, help);
      },
      [](const QString& name, const QString& label, const QString& help) {
        return RichPoint3f(name, Point3m(0, 0, 0), label, help);
      });
}

bool FilterIrregularPlugin::applyFilter(QAction* a, MeshDocument& md, const RichParameterList& par,
                                        vcg::CallBackPos* cb) {
  const fi::FilterOutcome out =
      fi::ApplyToDocument(*fi::FindFilter(ID(a)), md, par, cb, [this](fi::LogLevel level, const std::string& line) {
        Log(level == fi::LogLevel::Warning ? GLLogStream::WARNING : GLLogStream::FILTER, "%s", line.c_str());
      });
  if (!out.ok) errorMessage = QString::fromStdString(out.reason);
  return out.ok;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterIrregularPlugin)
