// The main window's menus, tool bar, files (open, save, export, recent), settings and palette.
#include "core/base/file_io.h"
#include "core/base/version.h"
#include "core/job/demo_program.h"
#include "core/job/job_file.h"
#include "core/job/tool_radius.h"
#include "core/kinematics/machine_file.h"
#include "ui/blade_placement_dialog.h"
#include "ui/comparison_table.h"
#include "ui/job_thread.h"
#include "ui/main_window.h"
#include "ui/profile_plots.h"
#include "ui/review_dashboard.h"
#include "ui/s_theta_editor.h"
#include "ui/toolpath_view.h"
#include "ui/window_wording.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCoreApplication>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QKeySequence>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPalette>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QStyleFactory>
#include <QToolBar>
#include <filesystem>
#include <vtkVersion.h>

namespace bladeaxis::ui {
namespace {

constexpr int kMaxRecentFiles = 8;
const char* const kRecentKey = "recentFiles";
const char* const kDarkKey = "view/dark";
const char* const kCompareKey = "job/compare";
const char* const kOptimumKey = "job/optimum";
const char* const kMachineKey = "job/machine";
// Earlier versions remembered the tool bar's radius across programs and sessions; it is removed.
const char* const kObsoleteToolRadiusKey = "job/toolRadius";
constexpr const char* kJobSuffix = ".bladeaxis.json";

QAction* menuAction(QMenu* menu, const QString& text, const QKeySequence& shortcut,
                    const QString& tip) {
    QAction* action = menu->addAction(text);
    action->setShortcut(shortcut);
    action->setToolTip(tip);
    action->setStatusTip(tip);
    return action;
}

} // namespace

void MainWindow::buildFileMenu() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    connect(menuAction(file, tr("&Open program…"), QKeySequence::Open,
                       tr("Open an NC program (G-code) or CL data (APT/CLSF) and re-schedule it")),
            &QAction::triggered, this, &MainWindow::openProgramDialog);
    connect(menuAction(file, tr("Open &machine…"), QKeySequence(tr("Ctrl+M")),
                       tr("Machine file (JSON); default: the built-in blade machine")),
            &QAction::triggered, this, &MainWindow::openMachineDialog);
    m_machineMenu = file->addMenu(tr("Mac&hine"));
    connect(m_machineMenu, &QMenu::aboutToShow, this, &MainWindow::fillMachineMenu);
    connect(menuAction(file, tr("Open blade &CAD…"), QKeySequence(tr("Ctrl+B")),
                       tr("Blade CAD (STEP/IGES) for the clearance check, the sections and the "
                          "3D surface of the next program")),
            &QAction::triggered, this, &MainWindow::openCadDialog);
    m_clearCad = menuAction(file, tr("C&lear blade CAD"), QKeySequence(),
                            tr("Detach the blade CAD from the program on screen and re-run it "
                               "without"));
    m_clearCad->setEnabled(false);
    connect(m_clearCad, &QAction::triggered, this, &MainWindow::clearBladeCad);
    connect(menuAction(file, tr("Run &demo"), QKeySequence(tr("Ctrl+D")),
                       tr("Re-schedule the built-in demo blade program")),
            &QAction::triggered, this, [this] {
                if (readyForNewJob()) {
                    runDemo();
                }
            });
    m_recentMenu = file->addMenu(tr("&Recent programs"));
    file->addSeparator();
    connect(menuAction(file, tr("Open &job…"), QKeySequence(tr("Ctrl+J")),
                       tr("Open a saved job (program, machine, parameters and layer edits)")),
            &QAction::triggered, this, &MainWindow::openJobDialog);
    m_saveJob =
        menuAction(file, tr("&Save job…"), QKeySequence::Save,
                   tr("Save the job with its layer edits as *.bladeaxis.json; `bladeaxis --batch "
                      "--job` reruns it"));
    connect(m_saveJob, &QAction::triggered, this, &MainWindow::saveJobDialog);
    file->addSeparator();
    m_exportProgram = menuAction(file, tr("&Export program…"), QKeySequence(tr("Ctrl+E")),
                                 tr("Write the re-scheduled program (refused if a check failed)"));
    connect(m_exportProgram, &QAction::triggered, this, &MainWindow::exportProgramDialog);
    m_exportCl = menuAction(file, tr("Export &CL data…"), QKeySequence(tr("Ctrl+Shift+E")),
                            tr("Write the re-scheduled toolpath as APT CL data"));
    connect(m_exportCl, &QAction::triggered, this, &MainWindow::exportClDialog);
    m_exportReport = menuAction(file, tr("Export &report…"), QKeySequence(tr("Ctrl+R")),
                                tr("Write report.json, axes.csv, layers.csv and, with a "
                                   "comparison, report.html into a folder"));
    connect(m_exportReport, &QAction::triggered, this, &MainWindow::exportReportDialog);
    updateExportActions();
    file->addSeparator();
    connect(menuAction(file, tr("&Quit"), QKeySequence::Quit, tr("Close BladeAxis")),
            &QAction::triggered, this, &QWidget::close);
    rebuildRecentMenu();
}

void MainWindow::buildEditMenu() {
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = m_undo.createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    edit->addAction(undo);
    QAction* redo = m_undo.createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(redo);
    edit->addSeparator();
    m_compareAction = edit->addAction(tr("&Compare methods"));
    m_compareAction->setCheckable(true);
    m_compareAction->setChecked(true);
    m_compareAction->setToolTip(tr("Also run quaternion interpolation, both S-θ presets and the "
                                   "optimum on the same ball centres (next job)"));
    m_optimumAction = edit->addAction(tr("Compare with the &optimum"));
    m_optimumAction->setCheckable(true);
    m_optimumAction->setChecked(true);
    m_optimumAction->setToolTip(tr("Include optimal-qp and optimal-lp in the comparison (slow on "
                                   "large programs)"));
}

void MainWindow::buildViewMenu() {
    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addAction(m_jobSettingsDock->toggleViewAction());
    view->addAction(m_listingDock->toggleViewAction());
    view->addSeparator();
    m_darkAction = view->addAction(tr("&Dark palette"));
    m_darkAction->setCheckable(true);
    m_darkAction->setShortcut(QKeySequence(tr("Ctrl+Shift+D")));
    connect(m_darkAction, &QAction::toggled, this, [this](bool dark) {
        setDarkPalette(dark);
        QSettings().setValue(kDarkKey, dark);
    });
    view->addSeparator();
    auto* colouring = new QActionGroup(this);
    // The 3D view's bar shows shorter names (icon texts) than the menu, so that every action
    // fits it in a 1366 px wide window; "Colour:" is said once, in front of the colourings.
    m_view3dBar->addWidget(new QLabel(tr(" Colour: "), m_view3dBar));
    const std::tuple<QString, QString, ToolpathView::Colouring> colourings[] = {
        {tr("Colour: &layer"), tr("layer"), ToolpathView::Colouring::Layer},
        {tr("Colour: &A speed"), tr("A speed"), ToolpathView::Colouring::ASpeed},
        {tr("Colour: A speed (&original)"), tr("A speed (original)"),
         ToolpathView::Colouring::OriginalASpeed}};
    for (const auto& [text, barText, mode] : colourings) {
        QAction* action = view->addAction(text);
        action->setIconText(barText);
        action->setCheckable(true);
        action->setChecked(mode == ToolpathView::Colouring::Layer);
        if (mode != ToolpathView::Colouring::Layer) { // renamed for a table-B machine's letter
            m_speedColourings[mode == ToolpathView::Colouring::ASpeed ? 0 : 1] = action;
        }
        colouring->addAction(action);
        m_view3dBar->addAction(action);
        connect(action, &QAction::triggered, this,
                [this, value = mode] { m_view3d->setColouring(value); });
    }
    m_view3dBar->addSeparator();
    view->addSeparator();
    const std::pair<QString, void (ToolpathView::*)(bool)> toggles[] = {
        {tr("&Blade"), &ToolpathView::setSurfaceVisible},
        {tr("&Original axes"), &ToolpathView::setOriginalAxesVisible},
        {tr("Re-&scheduled axes"), &ToolpathView::setRescheduledAxesVisible}};
    for (const auto& [text, setter] : toggles) {
        QAction* action = view->addAction(text);
        action->setCheckable(true);
        // As the view starts: the original axes only on demand (they hide the blade).
        action->setChecked(setter != &ToolpathView::setOriginalAxesVisible);
        m_view3dBar->addAction(action);
        connect(action, &QAction::toggled, m_view3d, setter);
    }
    m_view3dBar->addSeparator();
    view->addSeparator();
    const std::tuple<QString, QString, QString, void (ToolpathView::*)()> presets[] = {
        {tr("&Front"), tr("Front"), tr("1"), &ToolpathView::viewFront},
        {tr("&Top"), tr("Top"), tr("2"), &ToolpathView::viewTop},
        {tr("Along the rotary a&xis"), tr("Along X"), tr("3"), &ToolpathView::viewSide},
        {tr("&Isometric"), tr("Isometric"), tr("4"), &ToolpathView::viewIsometric},
        {tr("&Fit"), tr("Fit"), tr("F"), &ToolpathView::fitView}};
    for (const auto& [text, barText, key, slot] : presets) {
        QAction* action =
            menuAction(view, text, QKeySequence(key),
                       tr("3D view preset: %1").arg(QString(text).remove(QLatin1Char('&'))));
        action->setIconText(barText);
        m_view3dBar->addAction(action);
        connect(action, &QAction::triggered, m_view3d, slot);
    }
}

void MainWindow::buildHelpMenu() {
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* about = help->addAction(tr("&About BladeAxis"));
    about->setObjectName(QStringLiteral("aboutAction"));
    connect(about, &QAction::triggered, this,
            [this] { QMessageBox::about(this, tr("About BladeAxis"), aboutText()); });
}

// The same version and revision as `bladeaxis --version` and report.json's bladeaxis_version.
QString aboutText() {
    return QObject::tr("<h3>BladeAxis %1</h3><p>Revision %2</p>"
                       "<p>Re-schedules the tool orientation of four-axis helical blade "
                       "toolpaths so the rotary A axis turns monotonically and smoothly, "
                       "keeping the ball-centre path.</p><p>Built with Qt %3 (running %4), "
                       "VTK %5.</p>")
        .arg(QString::fromUtf8(projectVersion().data(), qsizetype(projectVersion().size())),
             QString::fromUtf8(projectRevision().data(), qsizetype(projectRevision().size())),
             QStringLiteral(QT_VERSION_STR), QString::fromLatin1(qVersion()),
             QString::fromLatin1(vtkVersion::GetVTKVersion()));
}

void MainWindow::buildToolBar() {
    QToolBar* bar = addToolBar(tr("Job"));
    bar->setObjectName(QStringLiteral("jobToolBar"));
    for (QAction* action : menuBar()->actions().front()->menu()->actions()) {
        if (action->text() == tr("&Open program…") || action->text() == tr("Run &demo") ||
            action->text() == tr("&Export program…")) {
            bar->addAction(action);
        }
    }
    bar->addSeparator();
    bar->addWidget(new QLabel(tr(" Tool radius: "), bar));
    m_toolRadius = new QDoubleSpinBox(bar);
    m_toolRadius->setRange(0.0, 100.0);
    m_toolRadius->setDecimals(3);
    m_toolRadius->setSuffix(tr(" mm"));
    m_toolRadius->setSpecialValueText(tr("from file"));
    m_toolRadius->setToolTip(tr("Ball radius R of the program on screen; 'from file' uses the "
                                "radius the program states. Not carried to the next program."));
    m_toolRadius->setEnabled(false); // a radius belongs to a program: none before one is shown
    // Once typed (not at every keystroke), a new radius re-runs the job on screen.
    connect(m_toolRadius, &QDoubleSpinBox::editingFinished, this, [this] {
        const std::optional<double> shown =
            m_toolRadius->value() > 0.0 ? std::optional(m_toolRadius->value()) : std::nullopt;
        if (m_result && m_thread == nullptr && shown != m_spec.toolRadius) {
            rerunWithToolRadius();
        }
    });
    bar->addWidget(m_toolRadius);
    m_radiusSource = new QLabel(bar);
    m_radiusSource->setObjectName(QStringLiteral("toolRadiusSource"));
    m_radiusSource->setToolTip(tr("Where the ball radius of the job on screen comes from"));
    bar->addWidget(m_radiusSource);
    m_machineLabel = new QLabel(tr(" Machine: built-in"), bar);
    bar->addWidget(m_machineLabel);
    m_cadLabel = new QLabel(tr("  Blade CAD: none"), bar);
    m_cadLabel->setToolTip(tr("Without CAD the blade is reconstructed from the toolpath's "
                              "contact points and no clearance check runs (the demo has its "
                              "own surface)"));
    bar->addWidget(m_cadLabel);
}

void MainWindow::restoreSettings() {
    QSettings settings;
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    m_compareAction->setChecked(settings.value(kCompareKey, true).toBool());
    connect(m_compareAction, &QAction::toggled, this,
            [](bool on) { QSettings().setValue(kCompareKey, on); });
    m_optimumAction->setChecked(settings.value(kOptimumKey, true).toBool());
    connect(m_optimumAction, &QAction::toggled, this,
            [](bool on) { QSettings().setValue(kOptimumKey, on); });
    settings.remove(kObsoleteToolRadiusKey);
    const QString machine = settings.value(kMachineKey).toString();
    if (!machine.isEmpty() && !setMachineFile(machine)) {
        settings.remove(kMachineKey); // a machine file that no longer loads is not used
    }
    m_darkAction->setChecked(settings.value(kDarkKey, false).toBool());
}

// The machine files BladeAxis ships: installed beside the program (../share/bladeaxis/machines)
// or, in a build tree, the source's resources/machines.
QStringList shippedMachineFiles() {
    QStringList files;
    for (const QString& folder :
         {QCoreApplication::applicationDirPath() + QStringLiteral("/../share/bladeaxis/machines"),
          QStringLiteral(BLADEAXIS_RESOURCES_DIR "/machines")}) {
        const QDir dir(folder);
        for (const QString& name :
             dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
            const QString path = QFileInfo(dir.filePath(name)).canonicalFilePath();
            if (!files.contains(path)) {
                files << path;
            }
        }
    }
    return files;
}

// The built-in machine, the shipped machine files by their names, and the file in use: a click
// chooses one and re-runs the job shown.
void MainWindow::fillMachineMenu() {
    m_machineMenu->clear();
    auto* group = new QActionGroup(m_machineMenu);
    const auto add = [this, group](const QString& text, const QString& path) {
        QAction* action = m_machineMenu->addAction(text);
        action->setCheckable(true);
        action->setChecked(path == m_machinePath);
        action->setData(path);
        action->setToolTip(path.isEmpty() ? tr("The built-in blade machine") : path);
        group->addAction(action);
        connect(action, &QAction::triggered, this, [this, path] {
            if (const Status set = setMachineFile(path); !set) {
                reportOutcome(set, QString(), tr("Machine file not loaded"));
                return;
            }
            rerunWithMachine();
        });
    };
    add(tr("Built-in blade machine"), QString());
    QStringList files = shippedMachineFiles();
    if (!m_machinePath.isEmpty() && !files.contains(m_machinePath)) {
        files << m_machinePath;
    }
    for (const QString& path : files) {
        const auto machine = kinematics::loadMachineFile(path.toStdString());
        const QString name =
            machine ? QString::fromStdString(machine->name) : QFileInfo(path).fileName();
        add(tr("%1 (%2)").arg(name, QFileInfo(path).fileName()), path);
    }
    m_machineMenu->addSeparator();
    m_machineMenu->addAction(tr("Other file…"), this, &MainWindow::openMachineDialog);
}

Status MainWindow::setMachineFile(const QString& machinePath) {
    if (!machinePath.isEmpty()) {
        if (auto machine = kinematics::loadMachineFile(machinePath.toStdString()); !machine) {
            return std::unexpected(machine.error());
        }
    }
    m_machinePath = machinePath;
    m_machineLabel->setText(machinePath.isEmpty()
                                ? tr(" Machine: built-in")
                                : tr(" Machine: %1").arg(QFileInfo(machinePath).fileName()));
    QSettings().setValue(kMachineKey, machinePath);
    return {};
}

void MainWindow::setBladeCad(const QString& cadPath, const cad::AxisRotationPlacement& placement) {
    if (m_thread != nullptr) {
        statusBar()->showMessage(
            tr("A job is running: load or clear the blade CAD when it is done"), 5000);
        return;
    }
    const bool changed = cadPath != m_cadPath ||
                         placement.rotationXyz != m_cadPlacement.rotationXyz ||
                         placement.translation != m_cadPlacement.translation;
    m_cadPath = cadPath;
    m_cadPlacement = cadPath.isEmpty() ? cad::AxisRotationPlacement{} : placement;
    showBladeCad();
    if (!m_result || !changed) {
        return; // no program on screen: the next program opened uses it
    }
    // The program on screen is checked against it (or without it) at once.
    job::JobSpec spec = m_spec;
    spec.cad.file = m_cadPath.toStdString();
    spec.cad.placement = m_cadPlacement;
    rerunWith(std::move(spec), cadPath.isEmpty()
                                   ? tr("Blade CAD cleared: re-running without it…")
                                   : tr("Checking the program against %1…").arg(cadPath));
}

void MainWindow::showBladeCad() {
    m_cadLabel->setText(m_cadPath.isEmpty()
                            ? tr("  Blade CAD: none")
                            : tr("  Blade CAD: %1").arg(QFileInfo(m_cadPath).fileName()));
    if (m_clearCad != nullptr) {
        m_clearCad->setEnabled(!m_cadPath.isEmpty());
    }
}

void MainWindow::openCadDialog() {
    if (m_thread != nullptr) {
        statusBar()->showMessage(tr("A job is running: load the blade CAD when it is done"), 5000);
        return;
    }
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open blade CAD"), QString(),
                                     tr("CAD (*.step *.stp *.iges *.igs);;All files (*)"));
    if (path.isEmpty()) {
        return;
    }
    BladePlacementDialog dialog(m_cadPlacement, this);
    if (dialog.exec() != QDialog::Accepted) {
        return;
    }
    setBladeCad(path, dialog.placement());
    if (!m_result) {
        statusBar()->showMessage(tr("Blade CAD %1 is used by the next program you open").arg(path),
                                 8000);
    }
}

Status MainWindow::openJob(const QString& jobPath) {
    if (m_thread != nullptr) {
        return makeError(ErrorCode::InvalidArgument, "a job is already running");
    }
    job::JobSpec spec;
    if (Status read = job::readJobFile(jobPath.toStdString(), spec); !read) {
        return read;
    }
    m_undo.clear();
    if (!spec.cad.file.empty()) { // the job's own CAD
        m_cadPath.clear();
    }
    detachBladeCad();
    const RadiusOrigin origin = spec.toolRadius ? RadiusOrigin::JobFile : RadiusOrigin::Program;
    startJob(std::move(spec), false, RadiusChoice{origin, false});
    return {};
}

// A job file may name outputs; the window writes none of them until the engineer exports,
// and says so with the paths, so nobody is surprised where a job received from someone writes.
QString MainWindow::jobOpenedMessage(const QString& jobPath) const {
    QStringList outputs;
    for (const std::filesystem::path& output :
         {m_spec.outputProgram, m_spec.outputCl, m_spec.outputDir}) {
        if (!output.empty()) {
            outputs << QString::fromStdString(std::filesystem::absolute(output).string());
        }
    }
    if (outputs.isEmpty()) {
        return tr("Running %1").arg(jobPath);
    }
    return tr("Running %1; nothing is written until you export (the job names %2)")
        .arg(jobPath, outputs.join(QStringLiteral(", ")));
}

QString MainWindow::jobFilePath(const QString& path) {
    if (path.endsWith(QLatin1String(kJobSuffix), Qt::CaseInsensitive)) {
        return path;
    }
    QString base = path;
    if (base.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)) {
        base.chop(5);
    }
    return base + QLatin1String(kJobSuffix);
}

Status MainWindow::saveJob(const QString& jobPath) {
    if (!m_result) {
        return makeError(ErrorCode::InvalidArgument, "no job to save: open a program first");
    }
    const std::filesystem::path path = jobFilePath(jobPath).toStdString();
    const std::filesystem::path folder = std::filesystem::absolute(path).parent_path();
    Status written = writeFileAtomically(path, job::jobJsonText(m_spec, folder));
    if (written) {
        m_undo.setClean(); // the edits are in the job file now
    }
    return written;
}

bool MainWindow::confirmDiscardEdits() {
    if (m_undo.isClean()) {
        return true;
    }
    const auto answer = QMessageBox::question(
        this, tr("BladeAxis"),
        tr("The layer edits of this job are not saved. Save them in a job file?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save) {
        saveJobDialog();
        return m_undo.isClean();
    }
    return answer == QMessageBox::Discard;
}

bool MainWindow::readyForNewJob() {
    if (!confirmDiscardEdits()) {
        return false;
    }
    if (m_thread == nullptr) {
        return true;
    }
    QMessageBox box(QMessageBox::Question, tr("BladeAxis"),
                    tr("A job is running. Cancel it and go on?"), QMessageBox::NoButton, this);
    QPushButton* cancelJobButton =
        box.addButton(tr("Cancel the running job"), QMessageBox::AcceptRole);
    QPushButton* keep = box.addButton(tr("Keep it running"), QMessageBox::RejectRole);
    box.setDefaultButton(keep);
    box.exec();
    if (box.clickedButton() != cancelJobButton) {
        statusBar()->showMessage(tr("The running job goes on; nothing was changed"), 5000);
        return false;
    }
    stopRunningJob();
    return m_thread == nullptr;
}

void MainWindow::stopRunningJob() {
    if (m_thread == nullptr) {
        return;
    }
    m_thread->requestCancel();
    m_thread->wait();
    onJobFinished(); // now, not when the signal arrives: the caller starts the next job
}

Status MainWindow::exportProgram(const QString& path) {
    if (Status pending = refuseWhilePending(); !pending) {
        return pending;
    }
    if (radiusConflictUnresolved()) {
        return makeError(ErrorCode::InvalidArgument,
                         m_radiusBannerText->text().toStdString() +
                             ": use the program's radius or keep the given one first");
    }
    job::JobSpec spec = m_spec;
    // Forced only by the engineer's tick under the points listed, never by their absence.
    spec.cad.force = m_dashboard->clearanceIssueCount() > 0 && m_dashboard->clearanceAcknowledged();
    spec.outputProgram = path.toStdString();
    spec.outputCl.clear();
    spec.outputDir.clear();
    return job::writeJobOutputs(spec, *m_result);
}

Status MainWindow::exportClData(const QString& path) {
    if (Status pending = refuseWhilePending(); !pending) {
        return pending;
    }
    if (radiusConflictUnresolved()) {
        return makeError(ErrorCode::InvalidArgument,
                         m_radiusBannerText->text().toStdString() +
                             ": use the program's radius or keep the given one first");
    }
    job::JobSpec spec = m_spec;
    // Forced only by the engineer's tick under the points listed, never by their absence.
    spec.cad.force = m_dashboard->clearanceIssueCount() > 0 && m_dashboard->clearanceAcknowledged();
    spec.outputProgram.clear();
    spec.outputCl = path.toStdString();
    spec.outputDir.clear();
    return job::writeJobOutputs(spec, *m_result);
}

Status MainWindow::exportReport(const QString& folder) {
    if (Status pending = refuseWhilePending(); !pending) {
        return pending;
    }
    job::JobSpec spec = m_spec;
    spec.outputProgram.clear();
    spec.outputCl.clear();
    spec.outputDir = folder.toStdString();
    return job::writeJobOutputs(spec, *m_result);
}

void MainWindow::reportOutcome(const Status& status, const QString& done,
                               const QString& refusedTitle) {
    if (!status) {
        showRefusalSource(status);
        QMessageBox::warning(this, refusedTitle, windowWording(status.error()));
        statusBar()->showMessage(refusedTitle, 5000);
        return;
    }
    statusBar()->showMessage(done, 8000);
}

void MainWindow::exportProgramTo(const QString& path) {
    if (!resolveRadiusConflictForExport()) {
        return;
    }
    reportOutcome(exportProgram(path), tr("Exported %1").arg(path), tr("Export refused"));
}

void MainWindow::exportClDataTo(const QString& path) {
    if (!resolveRadiusConflictForExport()) {
        return;
    }
    reportOutcome(exportClData(path), tr("Exported %1").arg(path), tr("Export refused"));
}

void MainWindow::updateExportActions() {
    const bool rescheduled = m_result && m_result->rescheduled;
    for (QAction* action : {m_exportProgram, m_exportCl}) {
        if (action != nullptr) {
            action->setEnabled(rescheduled);
        }
    }
    if (m_exportReport != nullptr) {
        m_exportReport->setEnabled(m_result.has_value());
    }
    if (m_saveJob != nullptr) {
        m_saveJob->setEnabled(m_result.has_value());
    }
}

bool MainWindow::radiusConflictUnresolved() const {
    return m_result && !m_radius.conflictConfirmed &&
           job::toolRadiusDisagrees(m_spec.toolRadius, m_result->program.path().toolRadius);
}

void MainWindow::showToolRadius() {
    {
        const QSignalBlocker block(m_toolRadius);
        m_toolRadius->setValue(m_spec.toolRadius.value_or(0.0));
    }
    m_toolRadius->setEnabled(m_result.has_value());
    QString source;
    QString style;
    const std::optional<double> stated =
        m_result ? m_result->program.path().toolRadius : std::nullopt;
    const QString statement =
        m_result ? QString::fromStdString(job::statedRadiusSource(m_result->program)) : QString();
    if (m_spec.toolRadius) {
        switch (m_radius.origin) {
        case RadiusOrigin::Typed:
        case RadiusOrigin::Program:
            source = tr("typed");
            break;
        case RadiusOrigin::Asked:
            source = tr("typed when asked");
            break;
        case RadiusOrigin::JobFile:
            source = tr("from the job file");
            break;
        }
    } else if (m_result && m_spec.demo) {
        source = tr("from the demo's generator");
    } else if (m_result && stated) {
        source = tr("from the program (%1)").arg(statement);
    }
    const bool conflict = m_result && job::toolRadiusDisagrees(m_spec.toolRadius, stated);
    if (conflict) {
        const QString radii = tr("%1 mm %2, but the program states %3 mm (%4)")
                                  .arg(QLocale().toString(*m_spec.toolRadius, 'g', 6), source,
                                       QLocale().toString(*stated, 'g', 6), statement);
        source = m_radius.conflictConfirmed ? tr("%1, kept over the program's %2 mm")
                                                  .arg(source, QLocale().toString(*stated, 'g', 6))
                                            : tr("%1: conflicts with the program's %2 mm")
                                                  .arg(source, QLocale().toString(*stated, 'g', 6));
        style = m_radius.conflictConfirmed ? QStringLiteral("color: #b35c00; font-weight: bold;")
                                           : QStringLiteral("color: #c62828; font-weight: bold;");
        m_radiusBannerText->setText(tr("Tool radius conflict: %1. Export is blocked until you "
                                       "choose.")
                                        .arg(radii));
    }
    m_radiusSource->setText(source.isEmpty() ? QString() : QStringLiteral(" ") + source + " ");
    m_radiusSource->setStyleSheet(style);
    m_radiusBanner->setVisible(conflict && !m_radius.conflictConfirmed);
}

void MainWindow::useProgramToolRadius() {
    if (!m_result || m_thread != nullptr) {
        return;
    }
    job::JobSpec spec = m_spec;
    spec.toolRadius.reset();
    rerunWith(std::move(spec), tr("Re-running with the program's tool radius…"),
              RadiusChoice{RadiusOrigin::Program, false});
}

void MainWindow::confirmGivenToolRadius() {
    m_radius.conflictConfirmed = true;
    showToolRadius();
}

bool MainWindow::resolveRadiusConflictForExport() {
    if (!radiusConflictUnresolved() || !refuseWhilePending()) {
        return true; // the export itself says why it is refused, if it is
    }
    const double stated = *m_result->program.path().toolRadius;
    QMessageBox box(QMessageBox::Warning, tr("Tool radius conflict"),
                    m_radiusBannerText->text() + "\n\n" +
                        tr("The exported program keeps the program's own tool statement; its "
                           "tip points are computed with the radius the job used (%1 mm).")
                            .arg(QLocale().toString(*m_spec.toolRadius, 'g', 6)),
                    QMessageBox::NoButton, this);
    QPushButton* useProgram =
        box.addButton(tr("Use the program's %1 mm").arg(QLocale().toString(stated, 'g', 6)),
                      QMessageBox::AcceptRole);
    QPushButton* keep =
        box.addButton(tr("Export with %1 mm").arg(QLocale().toString(*m_spec.toolRadius, 'g', 6)),
                      QMessageBox::DestructiveRole);
    box.setDefaultButton(box.addButton(QMessageBox::Cancel));
    box.exec();
    if (box.clickedButton() == keep) {
        confirmGivenToolRadius();
        return true;
    }
    if (box.clickedButton() == useProgram) {
        useProgramToolRadius();
        statusBar()->showMessage(
            tr("Re-running with the program's tool radius: export again when it is done"));
        return false;
    }
    statusBar()->showMessage(tr("Export cancelled"), 5000);
    return false;
}

QString MainWindow::suggestedExportPath() const {
    if (!m_result) {
        return {};
    }
    if (!m_spec.outputProgram
             .empty()) { // the job file names it: offer that, never write it unasked
        return QString::fromStdString(std::filesystem::absolute(m_spec.outputProgram).string());
    }
    const QFileInfo input(QString::fromStdString(m_spec.demo ? std::string(job::kDemoProgramName)
                                                             : m_spec.program.string()));
    const QString suffix = input.suffix().isEmpty() ? QString() : "." + input.suffix();
    const QString folder = m_spec.demo ? QDir::currentPath() : input.absolutePath();
    return QDir(folder).filePath(input.completeBaseName() + "_rescheduled" + suffix);
}

QString MainWindow::exportFilter() const {
    const QString all = tr("All files (*)");
    if (!m_result) {
        return all;
    }
    switch (m_result->program.format()) {
    case io::ProgramFormat::Gcode:
        switch (std::get<io::nc::GcodeProgram>(m_result->program.document).dialect) {
        case io::NcDialect::Sinumerik:
            return tr("Sinumerik programs (*.mpf *.spf)") + ";;" + all;
        case io::NcDialect::Heidenhain:
            return tr("Heidenhain programs (*.h)") + ";;" + all;
        case io::NcDialect::Iso:
            break;
        }
        return tr("G-code (*.nc *.ngc *.tap *.iso *.txt)") + ";;" + all;
    case io::ProgramFormat::Apt:
        return tr("CL data (*.cl *.cls *.apt *.aptsource)") + ";;" + all;
    case io::ProgramFormat::Table:
        return tr("Point tables (*.csv *.txt *.xyz)") + ";;" + all;
    }
    return all;
}

void MainWindow::exportProgramDialog() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export program"),
                                                      suggestedExportPath(), exportFilter());
    if (!path.isEmpty()) {
        exportProgramTo(path);
    }
}

void MainWindow::exportClDialog() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export CL data"), QString(),
                                                      tr("CL data (*.cl *.apt)"));
    if (!path.isEmpty()) {
        exportClDataTo(path);
    }
}

void MainWindow::exportReportDialog() {
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Export report into"));
    if (!folder.isEmpty()) {
        reportOutcome(exportReport(folder), tr("Report written to %1").arg(folder),
                      tr("Report not written"));
    }
}

void MainWindow::openJobDialog() {
    if (!readyForNewJob()) {
        return;
    }
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open job"), QString(), tr("Job files (*.json)"));
    if (!path.isEmpty()) {
        reportOutcome(openJob(path), jobOpenedMessage(path), tr("Job not opened"));
    }
}

void MainWindow::saveJobDialog() {
    if (!m_result) {
        return;
    }
    const QString path = QFileDialog::getSaveFileName(this, tr("Save job"), QString(),
                                                      tr("Job files (*.bladeaxis.json)"));
    if (!path.isEmpty()) {
        reportOutcome(saveJob(path), tr("Saved %1").arg(jobFilePath(path)), tr("Job not saved"));
    }
}

void MainWindow::openProgramDialog() {
    if (!readyForNewJob()) {
        return;
    }
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open program"), QString(),
        tr("Programs (*.nc *.ngc *.gcode *.tap *.iso *.mpf *.spf *.h *.cl *.apt *.cls);;"
           "All files (*)"));
    if (!path.isEmpty()) {
        runProgram(path);
    }
}

void MainWindow::openMachineDialog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open machine"), QString(),
                                                      tr("Machine files (*.json)"));
    if (path.isEmpty()) {
        return;
    }
    if (const Status set = setMachineFile(path); !set) {
        reportOutcome(set, QString(), tr("Machine file not loaded"));
        return;
    }
    rerunWithMachine();
}

// The job on screen again with one input changed, so the change is seen at once rather than
// with the next program. Layer edits are kept.
void MainWindow::rerunWith(job::JobSpec spec, const QString& message,
                           std::optional<RadiusChoice> radius) {
    if (!m_result || m_thread != nullptr) {
        return;
    }
    statusBar()->showMessage(message);
    startJob(std::move(spec), false, radius);
}

// The radius typed is this program's: it goes into the spec of the program on screen only.
void MainWindow::rerunWithToolRadius() {
    job::JobSpec spec = m_spec;
    spec.toolRadius =
        m_toolRadius->value() > 0.0 ? std::optional(m_toolRadius->value()) : std::nullopt;
    rerunWith(std::move(spec), tr("Re-running with the new tool radius…"),
              RadiusChoice{spec.toolRadius ? RadiusOrigin::Typed : RadiusOrigin::Program, false});
}

void MainWindow::rerunWithMachine() {
    job::JobSpec spec = m_spec;
    spec.machineFile = m_machinePath.toStdString();
    rerunWith(std::move(spec), tr("Re-running on the chosen machine…"));
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (event->mimeData()->hasUrls()) {
        event->acceptProposedAction();
    }
}

// A dropped program runs; a dropped JSON file is a job when it says so, else a machine file.
void MainWindow::dropEvent(QDropEvent* event) {
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.isEmpty() || !urls.front().isLocalFile()) {
        return;
    }
    const QString path = urls.front().toLocalFile();
    if (!path.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)) {
        if (readyForNewJob()) {
            runProgram(path);
        }
        return;
    }
    QFile file(path);
    const bool isJob = file.open(QIODevice::ReadOnly) && file.read(4096).contains("bladeaxis-job");
    if (isJob) {
        if (readyForNewJob()) {
            reportOutcome(openJob(path), jobOpenedMessage(path), tr("Job not opened"));
        }
    } else if (const Status set = setMachineFile(path); !set) {
        reportOutcome(set, QString(), tr("Machine file not loaded"));
    }
}

void MainWindow::setDarkPalette(bool dark) {
    QApplication::setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
    if (!dark) {
        QApplication::setPalette(QApplication::style()->standardPalette());
        return;
    }
    QPalette palette;
    palette.setColor(QPalette::Window, QColor(45, 45, 48));
    palette.setColor(QPalette::WindowText, QColor(220, 220, 220));
    palette.setColor(QPalette::Base, QColor(30, 30, 32));
    palette.setColor(QPalette::AlternateBase, QColor(45, 45, 48));
    palette.setColor(QPalette::Text, QColor(220, 220, 220));
    palette.setColor(QPalette::Button, QColor(55, 55, 58));
    palette.setColor(QPalette::ButtonText, QColor(220, 220, 220));
    palette.setColor(QPalette::Highlight, QColor(42, 130, 218));
    palette.setColor(QPalette::HighlightedText, Qt::white);
    palette.setColor(QPalette::ToolTipBase, QColor(55, 55, 58));
    palette.setColor(QPalette::ToolTipText, QColor(220, 220, 220));
    QApplication::setPalette(palette);
}

void MainWindow::rememberRecent(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value(kRecentKey).toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecentFiles) {
        recent.removeLast();
    }
    settings.setValue(kRecentKey, recent);
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
    m_recentMenu->clear();
    const QStringList recent = QSettings().value(kRecentKey).toStringList();
    for (const QString& path : recent) {
        m_recentMenu->addAction(path, this, [this, path] {
            if (readyForNewJob()) {
                runProgram(path);
            }
        });
    }
    m_recentMenu->setEnabled(!recent.isEmpty());
}

} // namespace bladeaxis::ui
