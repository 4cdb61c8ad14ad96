// filter_irregular: the MeshLab 2025.07 adapter (the FilterPlugin API of MeshLab 2022 and later;
// MeshLab's GUI and pymeshlab 2025.7). It only translates the catalog (core/filter_catalog.cpp).
#pragma once

#include <QObject>
#include <common/plugins/interfaces/filter_plugin.h>

class FilterIrregularPlugin : public QObject, public FilterPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
  Q_INTERFACES(FilterPlugin)

 public:
  FilterIrregularPlugin();
  QString pluginName() const override;
  QString filterName(ActionIDType filter) const override;
  QString pythonFilterName(ActionIDType filter) const override;
  QString filterInfo(ActionIDType filter) const override;
  FilterClass getClass(const QAction* a) const override;
  FilterArity filterArity(const QAction*) const override { return SINGLE_MESH; }
  int getRequirements(const QAction* a) override;
  int getPreConditions(const QAction* a) const override;
  int postCondition(const QAction* a) const override;
  RichParameterList initParameterList(const QAction* a, const MeshModel& m) override;
  std::map<std::string, QVariant> applyFilter(const QAction* a, const RichParameterList& par, MeshDocument& md,
                                              unsigned int& postConditionMask, vcg::CallBackPos* cb) override;
};
