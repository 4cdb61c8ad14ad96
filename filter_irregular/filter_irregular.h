// filter_irregular: MeshLab 2020.09 filter plugin for editing irregular vertices
// (Li, Zhang, Kobayashi, Wonka, "Editing Operations for Irregular Vertices in Triangle Meshes").
// This is the thin adapter between MeshLab and the algorithms in vcg_ext/irregular/.
#pragma once

#include <common/interfaces.h>

class FilterIrregularPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  enum { FP_ANALYZE, FP_ATOMIC, FP_RELAX, FP_REDUCE, FP_AGGREGATE, FP_MOVE_PAIR, FP_CANCEL_TRIPLE, FP_CANCEL_QUADRUPLE, FP_GENERATE,
         FP_AUTO_REDUCE };

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

 private:
  bool analyze(MeshModel& mm, const RichParameterList& par);
  bool atomic(MeshModel& mm, const RichParameterList& par);
  bool relax(MeshModel& mm, const RichParameterList& par, vcg::CallBackPos* cb);
  void logShape(const char* when, CMeshO& m);
  bool composite(QAction* a, MeshModel& mm, const RichParameterList& par, vcg::CallBackPos* cb);
  // filter_automatic_reduction.cpp
  void initAutomaticReductionParameters(MeshModel& mm, RichParameterList& par);
  bool automaticReduction(MeshModel& mm, const RichParameterList& par, vcg::CallBackPos* cb);
  /// Refuses: the reason goes to the error message (GUI dialog) and to the log (meshlabserver
  /// prints the log but not the error message). Returns false for `return refuse(...)`.
  bool refuse(const QString& why);
  /// Recolours and writes valence to quality; logs the summary.
  /// Legend colours (colorize) and valence in vertex quality (writeQuality), the selection
  /// (selectMode: 0 keeps it), and the topology summary in the log.
  void paintAndLog(MeshModel& mm, bool colorize, int selectMode, int selectValence, bool logSummary,
                   bool writeQuality = true);
};
