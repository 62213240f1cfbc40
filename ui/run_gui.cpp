#include "ui/run_gui.h"

#include "ui/main_window.h"

#include <QApplication>
#include <QStringList>

namespace bladeaxis::ui {

// `bladeaxis FILE` opens FILE: a job file (*.json) or a program.
int runGui(int argc, char** argv) {
    QApplication application(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("BladeAxis"));
    QApplication::setApplicationName(QStringLiteral("BladeAxis"));
    MainWindow window;
    window.show();
    const QStringList arguments = QApplication::arguments().mid(1);
    if (!arguments.isEmpty()) {
        const QString& file = arguments.front();
        if (file.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)) {
            window.openJob(file);
        } else {
            window.runProgram(file);
        }
    }
    return QApplication::exec();
}

} // namespace bladeaxis::ui
