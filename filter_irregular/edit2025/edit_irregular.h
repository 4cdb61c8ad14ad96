// filter_irregular: "Irregular Vertices: Edit" for MeshLab 2025.07 (EditTool and the EditPlugin
// factory). Forwards every call to the shared tool (edit_shared/irregular_edit_tool.h).
#pragma once

#include <QAction>
#include <QObject>
#include <common/plugins/interfaces/edit_plugin.h>

#include "edit_shared/irregular_edit_tool.h"

class EditIrregular : public EditTool {
 public:
  EditIrregular();
  static const QString info() { return filter_irregular::IrregularEditTool::Info(); }

  bool startEdit(MeshModel& m, GLArea* gla, MLSceneGLSharedDataContext* cont) override;
  void endEdit(MeshModel& m, GLArea* gla, MLSceneGLSharedDataContext* cont) override;
  void decorate(MeshModel& m, GLArea* gla, QPainter* p) override { tool_.Decorate(m, gla, p); }
  void decorate(MeshModel&, GLArea*) override {}
  void mousePressEvent(QMouseEvent* e, MeshModel& m, GLArea* gla) override { tool_.MousePress(e, m, gla); }
  void mouseMoveEvent(QMouseEvent* e, MeshModel& m, GLArea* gla) override { tool_.MouseMove(e, m, gla); }
  void mouseReleaseEvent(QMouseEvent* e, MeshModel& m, GLArea* gla) override { tool_.MouseRelease(e, m, gla); }
  void keyPressEvent(QKeyEvent* e, MeshModel& m, GLArea* gla) override { tool_.KeyPress(e, m, gla); }

 private:
  filter_irregular::IrregularEditTool tool_;
};

class EditIrregularFactory : public QObject, public EditPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(EDIT_PLUGIN_IID)
  Q_INTERFACES(EditPlugin)

 public:
  EditIrregularFactory();
  QString pluginName() const override { return "EditIrregular"; }
  EditTool* getEditTool(const QAction* a) override;
  QString getEditToolDescription(const QAction*) override { return EditIrregular::info(); }

 private:
  QAction* edit_ = nullptr;
};
