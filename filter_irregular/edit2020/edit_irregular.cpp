// filter_irregular: "Irregular Vertices: Edit" for MeshLab 2020.09 (see edit_irregular.h).
#include "edit_irregular.h"

#include "edit_shared/tool_icon.h"

EditIrregular::EditIrregular()
    : tool_([this](const std::string& s) { Log(GLLogStream::FILTER, s); }) {}

bool EditIrregular::StartEdit(MeshModel& m, GLArea* gla, MLSceneGLSharedDataContext* cont) {
  return tool_.Start(m, gla, cont);
}

void EditIrregular::EndEdit(MeshModel& m, GLArea* gla, MLSceneGLSharedDataContext*) { tool_.End(m, gla); }

EditIrregularFactory::EditIrregularFactory() {
  edit_ = new QAction(filter_irregular::ToolIcon(), filter_irregular::IrregularEditTool::Name(), this);
  edit_->setCheckable(true);
  actionList_ << edit_;
}

MeshEditInterface* EditIrregularFactory::getMeshEditInterface(QAction* a) {
  return a == edit_ ? new EditIrregular() : nullptr;
}
