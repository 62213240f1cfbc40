#include "ui/run_gui.h"

#include "ui/main_window.h"

#include <QApplication>

namespace bladeaxis::ui {

int runGui(int argc, char** argv) {
    QApplication application(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("BladeAxis"));
    QApplication::setApplicationName(QStringLiteral("BladeAxis"));
    MainWindow window;
    window.show();
    return QApplication::exec();
}

} // namespace bladeaxis::ui
