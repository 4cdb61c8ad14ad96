// filter_irregular: the MeshLab 2020.09 adapter (MeshFilterInterface, Debian bookworm's MeshLab
// and meshlabserver). It only translates the catalog (core/filter_catalog.cpp) to MeshLab.
#pragma once

#include <common/interfaces.h>

class FilterIrregularPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  FilterIrregularPlugin();
  QString pluginName() const override;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction* a) override;
  FILTER_ARITY filterArity(QAction*) const override { return SINGLE_MESH; }
  int getRequirements(QAction* a) override;
  int getPreConditions(QAction* a) const override;
  int postCondition(QAction* a) const override;
  void initParameterSet(QAction* a, MeshModel& m, RichParameterList& par) override;
  bool applyFilter(QAction* a, MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb) override;
};
