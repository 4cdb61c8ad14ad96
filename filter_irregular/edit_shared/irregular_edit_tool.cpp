// filter_irregular: the Qt/OpenGL side of "Irregular Vertices: Edit" (see irregular_edit_tool.h).
#include "irregular_edit_tool.h"

#include <algorithm>
#include <cmath>

#if FI_MESHLAB_API == 2025
#include <common/plugins/interfaces/edit_plugin.h>
#else
#include <common/interfaces.h>
#endif
#include <meshlab/glarea.h>

#include <QFontMetrics>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QElapsedTimer>
#include <QPainter>
#include <QTimer>

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <wrap/gl/pick.h>
#include <wrap/gl/picking.h>
#include <wrap/qt/device_to_logical.h>
#include <wrap/qt/gl_label.h>

#include <vcg_ext/irregular/edit_session.h>
#include <vcg_ext/irregular/legend.h>
#include <vcg_ext/irregular/mesh_checks.h>
#include <vcg_ext/irregular/topology.h>

namespace irr = vcg_ext::irregular;

namespace filter_irregular {

namespace {
const char* kTool = "Irregular Vertices: Edit";
/// A drag steps once the cursor is this far (pixels) from the moved vertex on screen.
const double kDragPixels = 12.0;
/// Arrows are drawn at least this long (pixels) so that short edges stay readable.
const double kMinArrowPixels = 40.0;
/// The arrows' trials a frame may run (ms of wall time; at least one trial per frame).
const qint64 kArrowBudgetMs = 10;
}  // namespace

struct IrregularEditTool::View {
  Eigen::Matrix<Scalarm, 4, 4> M;  ///< projection * modelview (with the mesh's Tr)
  Scalarm viewport[4];
  bool valid = false;
};

IrregularEditTool::IrregularEditTool(std::function<void(const std::string&)> log)
    : log_(std::move(log)), view_(new View) {}

IrregularEditTool::~IrregularEditTool() = default;

QString IrregularEditTool::Info() {
  return "Move the irregular vertices of a triangle mesh interactively (paper sec. 9): click near an "
         "irregular vertex to pick it with its nearest partner (Shift+click: another partner), then "
         "keys 1-6 or the arrow keys move the pair one step, a drag moves it toward the cursor, "
         "T / Q cancel a triple / quadruple, Ctrl+Z undoes a step. Starts from the selection when "
         "exactly two vertices are selected.";
}

bool IrregularEditTool::Start(MeshModel& m, GLArea* gla, MLSceneGLSharedDataContext* cont) {
  cont_ = cont;
  CMeshO& cm = m.cm;
  if (cm.fn == 0) {
    log_(std::string(kTool) + ": the mesh has no faces");
    return false;
  }
  // The session keeps vertex indices: start from a compact mesh with fresh adjacency.
  vcg::tri::Allocator<CMeshO>::CompactEveryVector(cm);
  m.updateDataMask(MeshModel::MM_FACEFACETOPO | MeshModel::MM_VERTFACETOPO);
  vcg::tri::UpdateTopology<CMeshO>::FaceFace(cm);
  vcg::tri::UpdateTopology<CMeshO>::VertexFace(cm);
  message_.clear();
  messageIsError_ = false;
  // EditSession's precondition: a manifold, consistently oriented triangle mesh (the filters
  // check the same). A mesh that fails gets no session: the tool only says why.
  irr::Result fit = irr::DiagnoseInput(cm).Verdict();
  if (!fit) {
    Report(false, "this mesh cannot be edited: " + fit.reason);
    if (gla) gla->update();
    return true;  // stays active to show the reason (MeshLab drops lines logged before paintGL)
  }
  session_.reset(new Session(cm));
  pressed_ = dragging_ = pickPending_ = false;
  int selected = 0;
  for (auto& v : cm.vert)
    if (!v.IsD() && v.IsS()) ++selected;
  if (selected == 2) {
    irr::Result r = session_->PickFromSelection();
    Report(bool(r), r ? "pair picked from the selection: vertices " + std::to_string(session_->Lead()) + " and " +
                            std::to_string(session_->Partner())
                      : "the selection is not a pair: " + r.reason);
    arrowsAnnounced_ = false;
  } else {
    message_ = "click near an irregular vertex to pick a pair";
  }
  RefreshIrregular(m);
  if (gla) gla->setCursor(Qt::CrossCursor);
  if (gla) gla->update();
  return true;
}

void IrregularEditTool::End(MeshModel& m, GLArea* gla) {
  if (!session_) return;
  session_.reset();
  // Steps may leave deleted elements behind (collapses); MeshLab expects a compact mesh.
  vcg::tri::Allocator<CMeshO>::CompactEveryVector(m.cm);
  vcg::tri::UpdateTopology<CMeshO>::FaceFace(m.cm);
  vcg::tri::UpdateTopology<CMeshO>::VertexFace(m.cm);
  MeshChanged(m, gla);
  equivalent_.clear();
  irregularCount_ = 0;
}

void IrregularEditTool::Report(bool ok, const std::string& what) {
  message_ = what;
  messageIsError_ = !ok;
  // MeshLab hands the edit tool its log only in paintGL (GLArea sets it before Decorate):
  // the line is written by the next Decorate, which every request triggers.
  pendingLog_.push_back(std::string(kTool) + ": " + what);
}

void IrregularEditTool::RefreshIrregular(MeshModel& m) {
  // O(n), once per use of the tool (Start); steps refresh locally (RefreshAround).
  irr::ValenceField<CMeshO> vf = irr::ComputeValences(m.cm);
  equivalent_.assign(m.cm.vert.size(), -1);
  irregularCount_ = 0;
  for (size_t i = 0; i < m.cm.vert.size(); ++i)
    if (!m.cm.vert[i].IsD() && vf.referenced[i]) {
      equivalent_[i] = vf.Equivalent(i);
      irregularCount_ += vf.IsIrregular(i);
    }
}

void IrregularEditTool::RefreshAround(MeshModel& m, const std::vector<int>& touched) {
  // What a step can change: the valence and position of the touched vertices (created ones
  // included), hence the normals of their faces and of those faces' vertices. O(touched).
  // The session keeps the mesh compact (EditSession::Compact): a step that deletes elements
  // moves the last ones into the holes and truncates, an undo grows the vectors back; the
  // moved and the truncated vertices are among the touched ones.
  CMeshO& cm = m.cm;
  for (size_t i = cm.vert.size(); i < equivalent_.size(); ++i)  // truncated by the step
    irregularCount_ -= (equivalent_[i] >= 0 && equivalent_[i] != 6);
  equivalent_.resize(cm.vert.size(), -1);
  std::vector<CMeshO::FacePointer> faces;
  for (int v : touched) {
    if (v < 0 || size_t(v) >= cm.vert.size()) continue;
    CMeshO::VertexType& vert = cm.vert[size_t(v)];
    int e = -1;
    if (!vert.IsD() && vert.cVFp() != nullptr) {
      irr::VertexStar<CMeshO> star = irr::StarOf<CMeshO>(&vert);
      e = irr::EquivalentValence(star.Valence(), irr::RegularValenceOf(star));
      for (auto& c : star.corners) faces.push_back(c.f);
      cm.bbox.Add(vert.P());
    }
    irregularCount_ += (e >= 0 && e != 6) - (equivalent_[size_t(v)] >= 0 && equivalent_[size_t(v)] != 6);
    equivalent_[size_t(v)] = e;
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  std::vector<CMeshO::VertexPointer> corners;
  for (auto f : faces) {
    f->N() = vcg::TriangleNormal(*f).Normalize();
    for (int z = 0; z < 3; ++z) corners.push_back(f->V(z));
  }
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  for (auto v : corners) {  // area-weighted, as vcg's PerVertexNormalized
    CMeshO::CoordType n(0, 0, 0);
    for (vcg::face::VFIterator<CMeshO::FaceType> vfi(v); !vfi.End(); ++vfi) n += vcg::TriangleNormal(*vfi.F());
    v->N() = n.Normalize();
  }
}

bool IrregularEditTool::CompactIfNeeded(MeshModel& m) {
  CMeshO& cm = m.cm;
  if (size_t(cm.vn) == cm.vert.size() && size_t(cm.fn) == cm.face.size()) return false;
  // MeshLab's renderer (vcg's buffer manager) reads face[0..fn) and vert[0..vn): a mesh with
  // deleted elements crashes it. The session keeps the mesh compact after every step, cancel,
  // undo and redo (EditSession::Compact, journaled, so the undo history survives); this is a
  // guarded fallback only, should an operation ever leave deleted elements: the mesh is
  // compacted, the session restarts on it with the pair remapped, and the undo history so
  // far is lost (reported).
  const int lead = session_->Lead(), partner = session_->Partner();
  vcg::tri::Allocator<CMeshO>::PointerUpdater<CMeshO::VertexPointer> pu;
  vcg::tri::Allocator<CMeshO>::CompactVertexVector(cm, pu);
  vcg::tri::Allocator<CMeshO>::CompactFaceVector(cm);
  vcg::tri::UpdateTopology<CMeshO>::FaceFace(cm);
  vcg::tri::UpdateTopology<CMeshO>::VertexFace(cm);
  auto remap = [&pu](int v) { return v >= 0 && size_t(v) < pu.remap.size() && pu.remap[size_t(v)] < pu.remap.size()
                                         ? int(pu.remap[size_t(v)]) : -1; };
  const int nl = pu.remap.empty() ? lead : remap(lead), np = pu.remap.empty() ? partner : remap(partner);
  session_.reset(new Session(cm));
  if (nl >= 0 && session_->PickVertex(nl) && np >= 0) session_->PickPartner(np);
  pendingLog_.push_back(std::string(kTool) + ": unexpected: the operation left deleted mesh elements; the mesh was "
                        "compacted for MeshLab's renderer, which clears the undo history (please report this)");
  return true;
}

void IrregularEditTool::MeshChanged(MeshModel& m, GLArea* gla) {
  if (session_ && CompactIfNeeded(m)) {
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFaceNormalized(m.cm);
    vcg::tri::UpdateBounding<CMeshO>::Box(m.cm);
    RefreshIrregular(m);
  } else if (session_) {
    RefreshAround(m, session_->Touched());
  } else {  // End: after the compaction
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFaceNormalized(m.cm);
    vcg::tri::UpdateBounding<CMeshO>::Box(m.cm);
  }
  if (cont_) {
    MLRenderingData::RendAtts atts;
    atts[MLRenderingData::ATT_NAMES::ATT_VERTPOSITION] = true;
    atts[MLRenderingData::ATT_NAMES::ATT_VERTNORMAL] = true;
    atts[MLRenderingData::ATT_NAMES::ATT_FACENORMAL] = true;
    atts[MLRenderingData::ATT_NAMES::ATT_VERTCOLOR] = true;
    atts[MLRenderingData::ATT_NAMES::ATT_FACECOLOR] = true;
    atts[MLRenderingData::ATT_NAMES::ATT_VERTTEXTURE] = true;
    atts[MLRenderingData::ATT_NAMES::ATT_WEDGETEXTURE] = true;
    cont_->meshAttributesUpdated(m.id(), true, atts);  // connectivity changed: rebuild
    cont_->manageBuffers(m.id());
  }
  if (gla) gla->updateAllSiblingsGLAreas();
}

bool IrregularEditTool::Project(const CMeshO::CoordType& p, double& x, double& y) const {
  if (!view_->valid) return false;
  CMeshO::CoordType s = vcg::GLPickTri<CMeshO>::glProject(view_->M, view_->viewport, p);
  x = s[0];
  y = s[1];
  return std::isfinite(x) && std::isfinite(y);
}

void IrregularEditTool::StepToward(double sx, double sy, MeshModel& m, GLArea* gla) {
  if (!session_ || !session_->HasPair()) {
    Report(false, "no pair picked: click near an irregular vertex first");
    return;
  }
  if (!view_->valid) return;
  auto project = [this](const CMeshO::CoordType& p) {
    double x = 0, y = 0;
    Project(p, x, y);
    return vcg::Point2d(x, y);
  };
  int k = session_->DirectionToward(project, vcg::Point2d(sx, sy));
  if (k < 0) {
    Report(false, "no accepted direction toward there" +
                      (session_->Message().empty() ? std::string() : ": " + session_->Message()));
    return;
  }
  DoStep(k, m, gla);
}

void IrregularEditTool::DoStep(int k, MeshModel& m, GLArea* gla) {
  irr::Result r = session_->Step(k);
  const std::string dir = "step in direction " + std::to_string(k + 1);
  if (r) {
    const std::string msg = session_->Message();
    Report(true, dir + " done: " + msg);
    arrowsAnnounced_ = false;
    MeshChanged(m, gla);
  } else {  // EditSession's reason may name the direction already
    const std::string again = "direction " + std::to_string(k + 1) + " refused: ";
    const bool named = r.reason.compare(0, again.size(), again) == 0;
    Report(false, dir + " refused: " + (named ? r.reason.substr(again.size()) : r.reason));
  }
}

void IrregularEditTool::ComputeArrows(GLArea* gla) {
  if (!session_->HasPair()) return;
  if (!session_->DirectionsKnown()) {
    // One trial at least, then more while the frame's budget lasts; the rest in the next
    // frames, so a pair far apart (a trial of up to tens of ms) never freezes the viewer.
    QElapsedTimer clock;
    clock.start();
    int ran = 0;
    for (int k = 0; k < 6; ++k)
      if (!session_->DirectionKnown(k) && (ran == 0 || clock.elapsed() < kArrowBudgetMs)) {
        session_->Direction(k);
        ++ran;
      }
    if (!session_->DirectionsKnown() && gla) QTimer::singleShot(0, gla, [gla]() { gla->update(); });
  }
  if (session_->DirectionsKnown() && !arrowsAnnounced_) {
    arrowsAnnounced_ = true;
    const std::string a = AcceptedText();
    if (!messageIsError_) message_ += "; " + a;
    pendingLog_.push_back(std::string(kTool) + ": arrows: " + a);
  }
}

std::string IrregularEditTool::AcceptedText() {
  std::string keys;
  for (const auto& d : session_->Directions())
    if (d.accepted) keys += (keys.empty() ? "" : " ") + std::to_string(d.k + 1);
  return "accepted next: " + (keys.empty() ? std::string("none") : keys);
}

void IrregularEditTool::MousePress(QMouseEvent* e, MeshModel&, GLArea* gla) {
  if (e->button() != Qt::LeftButton) return;
  const vcg::Point2f at = QTLogicalToOpenGL(gla, e->pos());
  pressAt_ = QPoint(int(at.X()), int(at.Y()));
  pressed_ = true;
  dragging_ = false;
}

void IrregularEditTool::MouseMove(QMouseEvent* e, MeshModel& m, GLArea* gla) {
  if (!pressed_ || !session_ || !session_->HasPair()) return;
  const vcg::Point2f at = QTLogicalToOpenGL(gla, e->pos());
  if (!dragging_ && std::hypot(at.X() - pressAt_.x(), at.Y() - pressAt_.y()) < 6) return;
  dragging_ = true;
  // One step per mouse event, greedily: the accepted direction that brings the pair's
  // midpoint nearest to the cursor on screen, and only if it gets nearer by a pixel. The
  // strict decrease keeps a drag from oscillating (the lead and its partner swap roles
  // between steps, so "the direction nearest in angle" can undo the previous step).
  const std::vector<irr::EditDirection<CMeshO::CoordType>> dirs = session_->Directions();
  const CMeshO& cm = m.cm;
  auto pos = [&cm](int v, const CMeshO::CoordType& fallback) {
    return v >= 0 && size_t(v) < cm.vert.size() && !cm.vert[size_t(v)].IsD() ? cm.vert[size_t(v)].cP() : fallback;
  };
  auto distance = [&](const CMeshO::CoordType& p) {
    double x = 0, y = 0;
    return Project(p, x, y) ? std::hypot(at.X() - x, at.Y() - y) : 1e30;
  };
  const CMeshO::CoordType now = (pos(session_->Lead(), {}) + pos(session_->Partner(), {})) / 2;
  const double d0 = distance(now);
  if (d0 < kDragPixels) return;
  int best = -1;
  double bestD = d0 - 1.0;
  for (const auto& d : dirs) {
    if (!d.accepted) continue;
    const double d1 = distance((pos(d.lead, d.to) + pos(d.partner, d.to)) / 2);
    if (d1 < bestD) best = d.k, bestD = d1;
  }
  if (best >= 0) DoStep(best, m, gla);
}

void IrregularEditTool::MouseRelease(QMouseEvent* e, MeshModel&, GLArea* gla) {
  if (e->button() != Qt::LeftButton) return;
  if (pressed_ && !dragging_) {
    // a click: pick in the next Decorate, where the depth buffer of the frame is available
    const vcg::Point2f at = QTLogicalToOpenGL(gla, e->pos());
    pickAt_ = QPoint(int(at.X()), int(at.Y()));
    pickPending_ = true;
    pickPartner_ = (e->modifiers() & Qt::ShiftModifier) != 0;
  }
  pressed_ = dragging_ = false;
  gla->update();
}

void IrregularEditTool::KeyPress(QKeyEvent* e, MeshModel& m, GLArea* gla) {
  if (!session_) return;
  const int key = e->key();
  const bool ctrl = (e->modifiers() & Qt::ControlModifier) != 0;
  if ((key == Qt::Key_Y && ctrl) || (key == Qt::Key_Z && ctrl && (e->modifiers() & Qt::ShiftModifier))) {
    e->accept();
    const bool redone = session_->Redo();
    const std::string msg = redone ? "redone: " + session_->Message()
                                   : session_->Message().empty() ? std::string("nothing to redo") : session_->Message();
    Report(redone, msg);
    arrowsAnnounced_ = arrowsAnnounced_ && !redone;
    if (redone) MeshChanged(m, gla);
  } else if (key == Qt::Key_Z && ctrl) {
    e->accept();
    const bool undone = session_->Undo();
    const std::string msg = session_->Message().empty() ? std::string(undone ? "undone" : "nothing to undo")
                                                        : session_->Message();
    Report(undone, msg);
    arrowsAnnounced_ = arrowsAnnounced_ && !undone;
    if (undone) MeshChanged(m, gla);
  } else if (key >= Qt::Key_1 && key <= Qt::Key_6) {
    e->accept();
    const int k = key - Qt::Key_1;
    if (!session_->HasPair()) {
      Report(false, "no pair picked: click near an irregular vertex first");
    } else {
      DoStep(k, m, gla);
    }
  } else if (key == Qt::Key_Left || key == Qt::Key_Right || key == Qt::Key_Up || key == Qt::Key_Down) {
    e->accept();
    // GL window coordinates: y points up
    const double sx = key == Qt::Key_Left ? -1 : key == Qt::Key_Right ? 1 : 0;
    const double sy = key == Qt::Key_Down ? -1 : key == Qt::Key_Up ? 1 : 0;
    StepToward(sx, sy, m, gla);
  } else if (key == Qt::Key_T || key == Qt::Key_Q) {
    e->accept();
    const bool triple = key == Qt::Key_T;
    irr::Result r = triple ? session_->CancelTriple() : session_->CancelQuadruple();
    const std::string what = triple ? "triple" : "quadruple";
    Report(bool(r), r ? what + " cancelled" : what + " not cancelled: " + r.reason);
    arrowsAnnounced_ = arrowsAnnounced_ && !r;
    if (r) MeshChanged(m, gla);
  } else {
    return;
  }
  gla->update();
}

void IrregularEditTool::Decorate(MeshModel& m, GLArea* gla, QPainter* p) {
  for (const std::string& line : pendingLog_) log_(line);
  pendingLog_.clear();
  if (!session_) {  // no session: the reason, if any
    if (p && !message_.empty())
      vcg::glLabel::render2D(p, vcg::glLabel::TOP_LEFT, 0, QString("%1: %2").arg(kTool).arg(QString::fromStdString(message_)),
                             vcg::glLabel::Mode(vcg::Color4b(255, 90, 70, 255)));
    return;
  }
  CMeshO& cm = m.cm;
  glPushMatrix();
  vcg::glMultMatrix(cm.Tr);
  vcg::GLPickTri<CMeshO>::glGetMatrixAndViewport(view_->M, view_->viewport);
  view_->valid = true;

  if (pickPending_) {
    pickPending_ = false;
    CMeshO::CoordType surface;
    if (!vcg::Pick(pickAt_.x(), pickAt_.y(), surface)) {
      Report(false, "nothing under the cursor");
    } else if (pickPartner_ && session_->Lead() >= 0) {
      // Shift+click: the vertex nearest to the clicked surface point becomes the partner
      int best = -1;
      double bestD = 0;
      for (size_t i = 0; i < cm.vert.size(); ++i) {
        if (cm.vert[i].IsD()) continue;
        const double d = vcg::SquaredDistance(cm.vert[i].P(), surface);
        if (best < 0 || d < bestD) best = int(i), bestD = d;
      }
      irr::Result r = session_->PickPartner(best);
      Report(bool(r), r ? "partner " + std::to_string(best) + " picked" : "partner not picked: " + r.reason);
      arrowsAnnounced_ = arrowsAnnounced_ && !r;
    } else {
      irr::Result r = session_->PickAt(surface);
      Report(bool(r), r ? "pair picked: vertices " + std::to_string(session_->Lead()) + " and " +
                              std::to_string(session_->Partner())
                        : "no pair picked: " + r.reason);
      arrowsAnnounced_ = arrowsAnnounced_ && !r;
    }
  }

  glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT | GL_POINT_BIT | GL_LINE_BIT | GL_DEPTH_BUFFER_BIT |
               GL_VIEWPORT_BIT);
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);
  glEnable(GL_POINT_SMOOTH);
  // over the mesh: a depth test, pulled slightly toward the eye so the points win over
  // their own faces and stay hidden behind the far side of the model
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthRange(0.0, 0.9995);
  glPointSize(7.0f);
  glBegin(GL_POINTS);
  for (size_t i = 0; i < equivalent_.size() && i < cm.vert.size(); ++i) {
    if (equivalent_[i] < 0 || equivalent_[i] == 6 || cm.vert[i].IsD()) continue;
    vcg::glColor(irr::LegendColor(equivalent_[i]));
    vcg::glVertex(cm.vert[i].P());
  }
  glEnd();

  // the pair: a white ring under the legend colour, drawn on top of everything
  glDisable(GL_DEPTH_TEST);
  const int pair[2] = {session_->Lead(), session_->Partner()};
  for (int v : pair) {
    if (v < 0 || size_t(v) >= cm.vert.size() || cm.vert[size_t(v)].IsD()) continue;
    glPointSize(16.0f);
    glColor3ub(255, 255, 255);
    glBegin(GL_POINTS);
    vcg::glVertex(cm.vert[size_t(v)].P());
    glEnd();
    glPointSize(10.0f);
    glColor3ub(20, 20, 20);
    glBegin(GL_POINTS);
    vcg::glVertex(cm.vert[size_t(v)].P());
    glEnd();
  }
  glPopAttrib();
  glPopMatrix();

  // the accepted directions, as arrows in screen space with their key numbers: those whose
  // trial has run (ComputeArrows runs the others over the next frames)
  ComputeArrows(gla);
  std::vector<irr::EditDirection<CMeshO::CoordType>> dirs;
  for (int k = 0; k < 6; ++k)
    if (session_->DirectionKnown(k)) dirs.push_back(session_->Direction(k));
  struct Arrow {
    double x0, y0, x1, y1;
    int k;
  };
  std::vector<Arrow> arrows;
  for (const auto& d : dirs) {
    if (!d.accepted) continue;
    Arrow a;
    a.k = d.k;
    if (!Project(d.from, a.x0, a.y0) || !Project(d.to, a.x1, a.y1)) continue;
    double dx = a.x1 - a.x0, dy = a.y1 - a.y0, len = std::hypot(dx, dy);
    if (len < 1e-6) continue;
    if (len < kMinArrowPixels) a.x1 = a.x0 + dx / len * kMinArrowPixels, a.y1 = a.y0 + dy / len * kMinArrowPixels;
    arrows.push_back(a);
  }
  glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT | GL_LINE_BIT | GL_TRANSFORM_BIT);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_TEXTURE_2D);
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glOrtho(view_->viewport[0], view_->viewport[0] + view_->viewport[2], view_->viewport[1],
          view_->viewport[1] + view_->viewport[3], -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  glLineWidth(3.0f);
  glColor3ub(255, 230, 0);
  glBegin(GL_LINES);
  for (const Arrow& a : arrows) {
    const double dx = a.x1 - a.x0, dy = a.y1 - a.y0, len = std::hypot(dx, dy);
    const double ux = dx / len, uy = dy / len, head = std::min(10.0, 0.4 * len);
    glVertex2d(a.x0, a.y0);
    glVertex2d(a.x1, a.y1);
    glVertex2d(a.x1, a.y1);
    glVertex2d(a.x1 - head * (ux + 0.5 * uy), a.y1 - head * (uy - 0.5 * ux));
    glVertex2d(a.x1, a.y1);
    glVertex2d(a.x1 - head * (ux - 0.5 * uy), a.y1 - head * (uy + 0.5 * ux));
  }
  glEnd();
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  glPopAttrib();

  if (p) {
    // text with a one-pixel dark shadow, readable over the light mesh and the dark background
    auto label = [p](vcg::Point2f at, const QString& text, vcg::glLabel::Mode mode) {
      vcg::glLabel::Mode shadow = mode;
      shadow.color = vcg::Color4b(0, 0, 0, 255);
      vcg::glLabel::render2D(p, vcg::Point2f(at.X() + 1, at.Y() - 1), text, shadow);
      vcg::glLabel::render2D(p, at, text, mode);
    };
    GLint vp[4];
    glGetIntegerv(GL_VIEWPORT, vp);
    const float lineStep = 18.f;
    auto line = [&](int i, const QString& text, vcg::glLabel::Mode mode) {
      label(vcg::Point2f(6.f, float(vp[3]) - 16.f - lineStep * float(i)), text, mode);
    };
    vcg::glLabel::Mode keyMode(vcg::Color4b(255, 230, 0, 255));
    keyMode.qFont.setPixelSize(15);
    keyMode.qFont.setBold(true);
    for (const Arrow& a : arrows) {
      const double dx = a.x1 - a.x0, dy = a.y1 - a.y0, len = std::hypot(dx, dy);
      label(vcg::Point2f(float(a.x1 + dx / len * 10 - 4), float(a.y1 + dy / len * 10 - 6)), QString::number(a.k + 1),
            keyMode);
    }
    vcg::glLabel::Mode textMode(messageIsError_ ? vcg::Color4b(255, 90, 70, 255) : vcg::Color4b(240, 240, 240, 255));
    textMode.qFont.setPixelSize(14);
    line(0,
         QString("%1: %2 irregular vertices%3").arg(kTool).arg(irregularCount_)
             .arg(session_->HasPair() ? QString(", pair %1-%2").arg(session_->Lead()).arg(session_->Partner()) : QString()),
         vcg::glLabel::Mode(vcg::Color4b(240, 240, 240, 255)));
    line(1,
         "keys 1-6 / arrows: step   drag: move toward cursor   T / Q: cancel triple / quadruple   Ctrl+Z / Ctrl+Y: "
         "undo / redo   Shift+click: partner   Esc: navigate",
         vcg::glLabel::Mode(vcg::Color4b(210, 210, 210, 255)));
    if (!message_.empty()) {  // word-wrapped to the viewport's width
      const QFontMetrics fm(textMode.qFont);
      const int width = std::max(200, int(vp[2]) - 20);
      QString rest = QString::fromStdString(message_), current;
      int row = 2;
      for (const QString& word : rest.split(' ')) {
        const QString next = current.isEmpty() ? word : current + ' ' + word;
        if (!current.isEmpty() && fm.horizontalAdvance(next) > width) {
          line(row++, current, textMode);
          current = word;
        } else {
          current = next;
        }
      }
      if (!current.isEmpty()) line(row, current, textMode);
    }
  }
  for (const std::string& line : pendingLog_) log_(line);  // the pick's line
  pendingLog_.clear();
}

}  // namespace filter_irregular
