// A read-only window probe for the MeshLab GUI tests (tests/meshlab/gui_support.py).
//
// LD_PRELOAD'ed into a MeshLab GUI (2020.09 on the host, 2025.07 in the sid chroot). Every
// 250 ms it writes, to the file named by $QD_GUI_PROBE (atomically: a temporary file renamed),
// a JSON list of the visible top-level windows (menus included): title, Qt class, geometry, and
// the text, Qt class, check state and screen centre of every visible label, button, line edit,
// combo box and menu entry in them.
// The tests read what the dialogs really show (parameter labels, the pymeshlab name, an error
// box's message) and where a button is; all input still goes through X (xdotool).
// Built by the tests with g++ against the host's Qt (bookworm's 5.15.8; it loads into sid's
// 5.15.19 as well); uses no moc.
#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QTimer>
#include <QWidget>
#include <cstdio>

namespace {

QJsonObject describe(const QWidget* w, const QString& text) {
  const QPoint centre = w->mapToGlobal(w->rect().center());
  QJsonObject item{{"class", w->metaObject()->className()},
                   {"text", text},
                   {"x", centre.x()},
                   {"y", centre.y()}};
  if (const auto* button = qobject_cast<const QAbstractButton*>(w); button && button->isCheckable())
    item["checked"] = button->isChecked();
  return item;
}

QString shownText(const QWidget* w) {
  if (const auto* label = qobject_cast<const QLabel*>(w)) return label->text();
  if (const auto* button = qobject_cast<const QAbstractButton*>(w)) return button->text();
  if (const auto* edit = qobject_cast<const QLineEdit*>(w)) return edit->text();
  if (const auto* combo = qobject_cast<const QComboBox*>(w)) return combo->currentText();
  return {};
}

// The entries of a menu or menu bar (QActions are not widgets), with their screen centres.
template <class Menu>
void appendActions(const Menu* menu, QJsonArray& widgets) {
  for (const QAction* action : menu->actions()) {
    if (!action->isVisible() || action->isSeparator()) continue;
    const QRect r = menu->actionGeometry(const_cast<QAction*>(action));
    if (r.isEmpty()) continue;
    const QPoint centre = menu->mapToGlobal(r.center());
    widgets.append(QJsonObject{{"class", "QAction"},
                               {"text", action->text()},
                               {"x", centre.x()},
                               {"y", centre.y()},
                               {"enabled", action->isEnabled()},
                               {"submenu", action->menu() != nullptr}});
  }
}

void appendMenus(const QWidget* w, QJsonArray& widgets) {
  if (const auto* menu = qobject_cast<const QMenu*>(w)) appendActions(menu, widgets);
  if (const auto* bar = qobject_cast<const QMenuBar*>(w)) appendActions(bar, widgets);
}

void snapshot() {
  const QString path = qEnvironmentVariable("QD_GUI_PROBE");
  if (path.isEmpty()) return;
  QJsonArray windows;
  for (const QWidget* top : QApplication::topLevelWidgets()) {
    if (!top->isVisible()) continue;
    QJsonArray widgets;
    appendMenus(top, widgets);
    for (const QWidget* w : top->findChildren<QWidget*>()) {
      if (!w->isVisible()) continue;
      appendMenus(w, widgets);
      const QString text = shownText(w);
      const bool checkable = qobject_cast<const QAbstractButton*>(w) != nullptr;
      if (!text.isEmpty() || checkable) widgets.append(describe(w, text));
    }
    const QRect frame = top->frameGeometry();
    windows.append(QJsonObject{{"title", top->windowTitle()},
                               {"class", top->metaObject()->className()},
                               {"x", frame.x()},
                               {"y", frame.y()},
                               {"width", frame.width()},
                               {"height", frame.height()},
                               {"widgets", widgets}});
  }
  QFile out(path + ".tmp");
  if (!out.open(QIODevice::WriteOnly | QIODevice::Truncate)) return;
  out.write(QJsonDocument(windows).toJson(QJsonDocument::Compact));
  out.close();
  std::rename(QFile::encodeName(path + ".tmp").constData(), QFile::encodeName(path).constData());
}

// Called while QApplication is being constructed: the timer starts once its event loop runs.
void start() {
  QMetaObject::invokeMethod(
      qApp,
      [] {
        auto* timer = new QTimer(qApp);
        QObject::connect(timer, &QTimer::timeout, snapshot);
        timer->start(250);
      },
      Qt::QueuedConnection);
}

}  // namespace

Q_COREAPP_STARTUP_FUNCTION(start)
