// filter_irregular: the toolbar icon of "Irregular Vertices: Edit", painted in code (no resource
// file): a blue 5 and an orange 7 (the legend's colours) joined by an edge, and an arrow.
#pragma once

#include <QCoreApplication>
#include <QGuiApplication>
#include <QIcon>
#include <QPainter>
#include <QPixmap>

namespace filter_irregular {

inline QIcon ToolIcon() {
  // pixmaps need a GUI application; a host without one (a console loader) gets no icon
  if (!qobject_cast<QGuiApplication*>(QCoreApplication::instance())) return QIcon();
  QPixmap pm(32, 32);
  pm.fill(Qt::transparent);
  QPainter p(&pm);
  p.setRenderHint(QPainter::Antialiasing);
  p.setPen(QPen(QColor(60, 60, 60), 2));
  p.drawLine(9, 20, 21, 20);
  p.setPen(QPen(QColor(230, 190, 0), 3));
  p.drawLine(15, 12, 15, 3);
  p.drawLine(15, 3, 11, 8);
  p.drawLine(15, 3, 19, 8);
  p.setPen(Qt::NoPen);
  p.setBrush(QColor(40, 80, 230));
  p.drawEllipse(QPoint(8, 20), 6, 6);
  p.setBrush(QColor(245, 140, 20));
  p.drawEllipse(QPoint(23, 20), 6, 6);
  return QIcon(pm);
}

}  // namespace filter_irregular
