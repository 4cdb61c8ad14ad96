// filter_irregular: the interactive edit tool "Irregular Vertices: Edit" (issue 16; the paper's
// sec. 9 interface: pick a 5-7 pair, move it in one of six directions with local relaxation).
//
// This class is the Qt/OpenGL side shared by both MeshLab generations: it draws (irregular
// vertices in the legend's colours, the pair, the accepted directions as arrows, the last
// message), turns mouse and keys into requests, and tells MeshLab the mesh changed. Every
// decision (which vertex is picked, which direction a screen vector means, whether a step is
// done, undo) is vcg_ext/irregular/edit_session.h's; nothing here edits the mesh directly.
// The two thin adapters (edit2020/, edit2025/) forward MeshLab's calls here; this file is
// compiled once per generation against that generation's headers.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <QPoint>
#include <QString>

#include "core/mesh_type.h"

class MeshModel;
class GLArea;
class MLSceneGLSharedDataContext;
class QPainter;
class QMouseEvent;
class QKeyEvent;

namespace vcg_ext {
namespace irregular {
template <class MeshType>
class EditSession;
}
}  // namespace vcg_ext

namespace filter_irregular {

class IrregularEditTool {
 public:
  /// `log` writes one line into MeshLab's log (the adapters pass their Log/log).
  explicit IrregularEditTool(std::function<void(const std::string&)> log);
  ~IrregularEditTool();

  static QString Name() { return "Irregular Vertices: Edit"; }
  static QString Info();

  /// Prepares the mesh (compact, FF/VF adjacency), opens the session and, when the current
  /// vertex selection holds exactly two vertices, picks that pair.
  bool Start(MeshModel& m, GLArea* gla, MLSceneGLSharedDataContext* cont);
  /// Closes the session (its undo history with it) and compacts the mesh.
  void End(MeshModel& m, GLArea* gla);
  /// Called inside paintGL: does a pending pick (needs the depth buffer), caches the
  /// projection for keys and drags, draws the overlay.
  void Decorate(MeshModel& m, GLArea* gla, QPainter* p);
  void MousePress(QMouseEvent* e, MeshModel& m, GLArea* gla);
  void MouseMove(QMouseEvent* e, MeshModel& m, GLArea* gla);
  void MouseRelease(QMouseEvent* e, MeshModel& m, GLArea* gla);
  void KeyPress(QKeyEvent* e, MeshModel& m, GLArea* gla);

 private:
  typedef vcg_ext::irregular::EditSession<CMeshO> Session;
  struct View;  // the projection cached by the last Decorate

  void Report(bool ok, const std::string& what);
  /// After a step, a cancellation or an undo: normals, bbox and valences around the touched
  /// vertices (EditSession::Touched), and MeshLab's buffers (positions and connectivity).
  void MeshChanged(MeshModel& m, GLArea* gla);
  /// Fallback only (the session keeps the mesh compact itself): compacts the mesh if an
  /// operation left deleted elements (MeshLab's renderer needs a compact mesh) and restarts
  /// the session on it with the pair remapped, losing the undo history; true if it did.
  bool CompactIfNeeded(MeshModel& m);
  /// The equivalent valence of every vertex (O(n): at Start).
  void RefreshIrregular(MeshModel& m);
  /// The same for the touched vertices, with the normals of their faces. O(touched).
  void RefreshAround(MeshModel& m, const std::vector<int>& touched);
  /// The accepted direction nearest to the screen vector (sx, sy) (GL window coordinates).
  void StepToward(double sx, double sy, MeshModel& m, GLArea* gla);
  /// Step(k), its message, and MeshChanged when done.
  void DoStep(int k, MeshModel& m, GLArea* gla);
  /// Runs the trials of the arrows not known yet (EditSession::Direction), for at most about
  /// kArrowBudgetMs per frame and at least one, and asks for another frame while some are
  /// missing; once all six are known, appends "accepted next: ..." to the message and logs it.
  void ComputeArrows(GLArea* gla);
  /// "accepted next: 1 3 4 6": the keys whose step the dry run accepts (the drawn arrows).
  /// Precondition: all six directions known.
  std::string AcceptedText();
  bool Project(const CMeshO::CoordType& p, double& x, double& y) const;

  std::function<void(const std::string&)> log_;
  std::unique_ptr<Session> session_;
  std::unique_ptr<View> view_;
  MLSceneGLSharedDataContext* cont_ = nullptr;
  std::vector<int> equivalent_;  ///< equivalent valence per vertex (legend colour; 6 regular, -1 none)
  int irregularCount_ = 0;
  std::string message_;                   ///< drawn in the viewport
  std::vector<std::string> pendingLog_;   ///< lines for MeshLab's log, written by Decorate
  bool messageIsError_ = false;
  bool arrowsAnnounced_ = false;  ///< the current state's "accepted next" line was logged
  // mouse: a click (press + release without moving) picks, a drag steps toward the cursor
  bool pressed_ = false, dragging_ = false, pickPending_ = false, pickPartner_ = false;
  QPoint pressAt_, pickAt_;  ///< GL window coordinates (y up, device pixels)
};

}  // namespace filter_irregular
