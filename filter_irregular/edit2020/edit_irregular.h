// filter_irregular: "Irregular Vertices: Edit" for MeshLab 2020.09 (MeshEditInterface and its
// factory). Forwards every call to the shared tool (edit_shared/irregular_edit_tool.h).
#pragma once

#include <QAction>
#include <QObject>
#include <common/interfaces.h>

#include "edit_shared/irregular_edit_tool.h"

class EditIrregular : public QObject, public MeshEditInterface {
  Q_OBJECT
  Q_INTERFACES(MeshEditInterface)

 public:
  EditIrregular();
  static const QString Info() { return filter_irregular::IrregularEditTool::Info(); }
  QString pluginName() const override { return "EditIrregular"; }

  bool StartEdit(MeshModel& m, GLArea* gla, MLSceneGLSharedDataContext* cont) override;
  void EndEdit(MeshModel& m, GLArea* gla, MLSceneGLSharedDataContext* cont) override;
  void Decorate(MeshModel& m, GLArea* gla, QPainter* p) override { tool_.Decorate(m, gla, p); }
  void Decorate(MeshModel&, GLArea*) override {}
  void mousePressEvent(QMouseEvent* e, MeshModel& m, GLArea* gla) override { tool_.MousePress(e, m, gla); }
  void mouseMoveEvent(QMouseEvent* e, MeshModel& m, GLArea* gla) override { tool_.MouseMove(e, m, gla); }
  void mouseReleaseEvent(QMouseEvent* e, MeshModel& m, GLArea* gla) override { tool_.MouseRelease(e, m, gla); }
  void keyPressEvent(QKeyEvent* e, MeshModel& m, GLArea* gla) override { tool_.KeyPress(e, m, gla); }

 private:
  filter_irregular::IrregularEditTool tool_;
};

class EditIrregularFactory : public QObject, public MeshEditInterfaceFactory {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_EDIT_INTERFACE_FACTORY_IID)
  Q_INTERFACES(MeshEditInterfaceFactory)

 public:
  EditIrregularFactory();
  QList<QAction*> actions() const override { return actionList_; }
  MeshEditInterface* getMeshEditInterface(QAction* a) override;
  QString getEditToolDescription(QAction*) override { return EditIrregular::Info(); }

 private:
  QList<QAction*> actionList_;
  QAction* edit_ = nullptr;
};
