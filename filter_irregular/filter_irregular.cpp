// filter_irregular: MeshLab adapter. Each filter translates parameters, calls vcg_ext, logs.
#include "filter_irregular.h"

#include <QString>
#include <QStringList>

#include <vcg/complex/algorithms/update/flag.h>
#include <vcg/complex/algorithms/update/selection.h>

#include <vcg_ext/irregular/legend.h>
#include <vcg_ext/irregular/mesh_checks.h>
#include <vcg_ext/irregular/topology.h>

namespace irr = vcg_ext::irregular;

FilterIrregularPlugin::FilterIrregularPlugin() {
  typeList << FP_ANALYZE;
  for (FilterIDType t : types()) actionList << new QAction(filterName(t), this);
}

QString FilterIrregularPlugin::pluginName() const { return "FilterIrregular"; }

QString FilterIrregularPlugin::filterName(FilterIDType id) const {
  switch (id) {
    case FP_ANALYZE: return "Irregular Vertices: Analyze";
    case FP_ATOMIC: return "Irregular Vertices: Atomic Operation";
  }
  return "";
}

QString FilterIrregularPlugin::filterInfo(FilterIDType id) const {
  switch (id) {
    case FP_ANALYZE:
      return "Colours vertices by valence (v3- purple, v4 cyan, v5 blue, v6 grey, v7 orange, v8 red, "
             "v9+ dark red; boundary vertices by valence + 2, so regular boundary vertices of valence 4 "
             "are grey), writes the valence into vertex quality, optionally selects irregular vertices, "
             "and logs the valence histogram, the irregular count, Euler characteristic, genus, "
             "boundary loops and whether the discrete Gauss-Bonnet identity "
             "sum(6 - valence) + sum_boundary(4 - valence) = 6 chi holds "
             "(Li et al., Editing Operations for Irregular Vertices in Triangle Meshes, eq. 2). "
             "Refuses non-manifold or polygonal meshes without changing them.";
    case FP_ATOMIC:
      return "Applies one atomic operation on irregular vertices.";
  }
  return "";
}

MeshFilterInterface::FilterClass FilterIrregularPlugin::getClass(QAction* a) {
  switch (ID(a)) {
    case FP_ANALYZE: return FilterClass(Quality | Measure | Selection);
    case FP_ATOMIC: return FilterClass(Remeshing | Selection);
  }
  return Generic;
}

int FilterIrregularPlugin::getRequirements(QAction*) {
  return MeshModel::MM_FACEFACETOPO | MeshModel::MM_VERTFACETOPO;
}

int FilterIrregularPlugin::getPreConditions(QAction*) const { return MeshModel::MM_FACENUMBER; }

int FilterIrregularPlugin::postCondition(QAction* a) const {
  switch (ID(a)) {
    case FP_ANALYZE:
      return MeshModel::MM_VERTCOLOR | MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTFLAGSELECT;
    default: return MeshModel::MM_ALL;
  }
}

void FilterIrregularPlugin::initParameterSet(QAction* a, MeshModel&, RichParameterList& par) {
  switch (ID(a)) {
    case FP_ANALYZE:
      par.addParam(RichEnum("select", 1, QStringList() << "None" << "All irregular" << "Only valence",
                            "Select vertices",
                            "Replace the vertex selection: None keeps it as it is; All irregular selects "
                            "every vertex of valence != 6 (boundary: != 4); Only valence selects the "
                            "vertices of the valence below (boundary vertices count as valence + 2)."));
      par.addParam(RichInt("valence", 5, "Valence to select",
                           "Used with 'Only valence': select the vertices of this (interior-equivalent) valence."));
      par.addParam(RichBool("colorize", true, "Colour by valence",
                            "Paint vertices with the plugin's valence legend (v5 blue, v7 orange, v8 red, ...)."));
      break;
  }
}

bool FilterIrregularPlugin::refuse(const QString& why) {
  errorMessage = why;
  Log(GLLogStream::WARNING, "Irregular Vertices: refused: %s", qUtf8Printable(why));
  return false;
}

void FilterIrregularPlugin::paintAndLog(MeshModel& mm, bool colorize, int selectMode, int selectValence,
                                        bool logSummary) {
  CMeshO& m = mm.cm;
  irr::ValenceField<CMeshO> vf = irr::ComputeValences(m);
  mm.updateDataMask(MeshModel::MM_VERTQUALITY | (colorize ? MeshModel::MM_VERTCOLOR : 0));
  irr::PaintValences(m, vf, colorize);
  const int selected = irr::SelectByValence(m, vf, irr::IrregularSelection(selectMode), selectValence);
  m.svn = selected;
  if (!logSummary) return;
  irr::TopologySummary s = irr::Summarize(m);
  QString hist;
  for (auto& kv : s.histogram) hist += QString(" v%1:%2").arg(kv.first).arg(kv.second);
  QString bhist;
  for (auto& kv : s.boundaryHistogram) bhist += QString(" v%1:%2").arg(kv.first).arg(kv.second);
  Log("Irregular vertices: %d of %d vertices (%.2f%%)", s.irregular, s.vertices,
      s.vertices ? 100.0 * s.irregular / s.vertices : 0.0);
  Log("Valence histogram (interior):%s", qUtf8Printable(hist));
  if (!s.boundaryHistogram.empty()) Log("Valence histogram (boundary, regular = 4):%s", qUtf8Printable(bhist));
  Log("Euler characteristic %d, genus %d, boundary loops %d, components %d (V %d, E %d, F %d)",
      s.eulerCharacteristic, s.genus, s.boundaryLoops, s.components, s.vertices, s.edges, s.faces);
  Log("Gauss-Bonnet (eq. 2): sum of valence defects %d, 6 x chi = %d: %s", s.gaussBonnetSum,
      6 * s.eulerCharacteristic, s.GaussBonnetHolds() ? "holds" : "FAILS");
  if (selectMode != 0) Log("Selected %d vertices", selected);
}

bool FilterIrregularPlugin::analyze(MeshModel& mm, const RichParameterList& par) {
  irr::InputReport rep = irr::DiagnoseInput(mm.cm);
  irr::Result ok = rep.Verdict();
  if (!ok) return refuse(QString::fromStdString(ok.reason));
  paintAndLog(mm, par.getBool("colorize"), par.getEnum("select"), par.getInt("valence"), true);
  return true;
}

bool FilterIrregularPlugin::atomic(MeshModel&, const RichParameterList&) {
  return refuse("not available");
}

bool FilterIrregularPlugin::applyFilter(QAction* a, MeshDocument& md, const RichParameterList& par,
                                        vcg::CallBackPos*) {
  MeshModel* mm = md.mm();
  if (mm == nullptr) return refuse("There is no current mesh.");
  switch (ID(a)) {
    case FP_ANALYZE: return analyze(*mm, par);
    case FP_ATOMIC: return atomic(*mm, par);
  }
  return refuse("Unknown filter.");
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterIrregularPlugin)
