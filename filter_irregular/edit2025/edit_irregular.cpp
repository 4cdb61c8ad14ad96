// filter_irregular: "Irregular Vertices: Edit" for MeshLab 2025.07 (see edit_irregular.h).
#include "edit_irregular.h"

#include "edit_shared/tool_icon.h"

EditIrregular::EditIrregular()
    : tool_([this](const std::string& s) { log(GLLogStream::FILTER, s); }) {}

bool EditIrregular::startEdit(MeshModel& m, GLArea* gla, MLSceneGLSharedDataContext* cont) {
  return tool_.Start(m, gla, cont);
}

void EditIrregular::endEdit(MeshModel& m, GLArea* gla, MLSceneGLSharedDataContext*) { tool_.End(m, gla); }

EditIrregularFactory::EditIrregularFactory() {
  edit_ = new QAction(filter_irregular::ToolIcon(), filter_irregular::IrregularEditTool::Name(), this);
  edit_->setCheckable(true);
  actionList.push_back(edit_);
}

EditTool* EditIrregularFactory::getEditTool(const QAction* a) {
  return a == edit_ ? new EditIrregular() : nullptr;
}
