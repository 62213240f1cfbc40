#include "ui/main_window.h"

#include "ui/job_thread.h"
#include "ui/profile_plots.h"
#include "ui/s_theta_editor.h"
#include "ui/toolpath_view.h"

#include <QAction>
#include <QApplication>
#include <QDoubleSpinBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QKeySequence>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPalette>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSlider>
#include <QSplitter>
#include <QStatusBar>
#include <QStyleFactory>
#include <QTabWidget>
#include <QTableWidget>
#include <QToolBar>
#include <QVBoxLayout>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

namespace bladeaxis::ui {
namespace {

constexpr int kMaxRecentFiles = 8;
const char* const kRecentKey = "recentFiles";

QString layerStatusText(const scheduling::LayerResult& layer) {
    QStringList names;
    for (const scheduling::LayerStatus status : layer.flags) {
        names << QString::fromUtf8(scheduling::toString(status));
    }
    return names.isEmpty() ? QStringLiteral("Ok") : names.join(QStringLiteral(", "));
}

QTableWidgetItem* numberItem(double value, int decimals) {
    auto* item = new QTableWidgetItem(QString::number(value, 'f', decimals));
    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    return item;
}

} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(QStringLiteral("BladeAxis"));
    setAcceptDrops(true);
    m_layers = new QTableWidget(0, 5, this);
    m_layers->setHorizontalHeaderLabels({tr("Layer"), tr("Status"), tr("Samples"),
                                         tr("Min clearance [mrad]"), tr("Peak θ'' [rad/mm²]")});
    m_layers->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_layers->setSelectionMode(QAbstractItemView::SingleSelection);
    m_layers->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_layers->horizontalHeader()->setStretchLastSection(true);
    m_layers->setToolTip(tr("Layers of the re-scheduled toolpath; selecting one selects it "
                            "in every view"));
    connect(m_layers, &QTableWidget::itemSelectionChanged, this,
            [this] { emit layerSelected(selectedLayer()); });
    m_editor = new SThetaEditor(this);
    connect(this, &MainWindow::layerSelected, this, &MainWindow::showSelectedLayer);
    auto* splitter = new QSplitter(this);
    splitter->addWidget(m_layers);
    m_plots = new ProfilePlots(this);
    auto* tabs = new QTabWidget(this);
    tabs->addTab(m_editor, tr("S-θ editor"));
    tabs->addTab(m_plots, tr("Axis motion"));
    auto* view3dPage = new QWidget(this);
    auto* view3dLayout = new QVBoxLayout(view3dPage);
    m_view3d = new ToolpathView(view3dPage);
    m_toolSlider = new QSlider(Qt::Horizontal, view3dPage);
    m_toolSlider->setToolTip(tr("Scrub along the toolpath: shows the tool at that point"));
    m_toolSlider->setEnabled(false);
    connect(m_toolSlider, &QSlider::valueChanged, this,
            [this](int sample) { m_view3d->showToolAt(static_cast<std::size_t>(sample)); });
    view3dLayout->addWidget(m_view3d, 1);
    view3dLayout->addWidget(m_toolSlider);
    tabs->addTab(view3dPage, tr("3D view"));
    splitter->addWidget(tabs);
    splitter->setStretchFactor(1, 2);
    setCentralWidget(splitter);
    buildActions();
    buildStatusBar();
    resize(1000, 700);
}

MainWindow::~MainWindow() {
    if (m_thread != nullptr) {
        m_thread->requestCancel();
        m_thread->wait();
    }
}

void MainWindow::buildActions() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = file->addAction(tr("&Open program…"), this, &MainWindow::openProgramDialog);
    open->setShortcut(QKeySequence::Open);
    open->setToolTip(tr("Open an NC program (G-code) or CL data (APT/CLSF) and re-schedule it"));
    QAction* machine = file->addAction(tr("Open &machine…"), this, &MainWindow::openMachineDialog);
    machine->setShortcut(QKeySequence(tr("Ctrl+M")));
    machine->setToolTip(tr("Machine file (JSON); default: the built-in blade machine"));
    QAction* demo = file->addAction(tr("Run &demo"), this, &MainWindow::runDemo);
    demo->setShortcut(QKeySequence(tr("Ctrl+D")));
    demo->setToolTip(tr("Re-schedule the built-in demo blade program"));
    QAction* exportAction =
        file->addAction(tr("&Export program…"), this, &MainWindow::exportProgramDialog);
    exportAction->setShortcut(QKeySequence(tr("Ctrl+E")));
    exportAction->setToolTip(tr("Write the re-scheduled program (refused if a check failed)"));
    m_recentMenu = file->addMenu(tr("&Recent programs"));
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
    rebuildRecentMenu();

    QMenu* view = menuBar()->addMenu(tr("&View"));
    QAction* dark = view->addAction(tr("&Dark palette"));
    dark->setCheckable(true);
    dark->setShortcut(QKeySequence(tr("Ctrl+Shift+D")));
    connect(dark, &QAction::toggled, this, &MainWindow::setDarkPalette);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = m_editor->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    edit->addAction(undo);
    QAction* redo = m_editor->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(redo);

    QToolBar* bar = addToolBar(tr("Job"));
    bar->addAction(open);
    bar->addAction(demo);
    bar->addWidget(new QLabel(tr(" Tool radius: "), bar));
    m_toolRadius = new QDoubleSpinBox(bar);
    m_toolRadius->setRange(0.0, 100.0);
    m_toolRadius->setDecimals(3);
    m_toolRadius->setSuffix(tr(" mm"));
    m_toolRadius->setSpecialValueText(tr("from file"));
    m_toolRadius->setToolTip(tr("Ball radius R; 'from file' uses the radius the CL file states"));
    bar->addWidget(m_toolRadius);
    m_machineLabel = new QLabel(tr(" Machine: built-in"), bar);
    bar->addWidget(m_machineLabel);
}

void MainWindow::buildStatusBar() {
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 1000);
    m_progress->setMaximumWidth(220);
    m_progress->setVisible(false);
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setToolTip(tr("Stop the running job"));
    m_cancel->setVisible(false);
    connect(m_cancel, &QPushButton::clicked, this, [this] {
        if (m_thread != nullptr) {
            m_thread->requestCancel();
        }
    });
    statusBar()->addPermanentWidget(m_progress);
    statusBar()->addPermanentWidget(m_cancel);
    statusBar()->showMessage(tr("Open a program (Ctrl+O) or run the demo (Ctrl+D)"));
}

void MainWindow::runDemo() {
    job::JobSpec spec;
    spec.demo = true;
    startJob(std::move(spec));
}

void MainWindow::runProgram(const QString& programPath) {
    job::JobSpec spec;
    spec.program = programPath.toStdString();
    rememberRecent(programPath);
    startJob(std::move(spec));
}

void MainWindow::setMachineFile(const QString& machinePath) {
    m_machinePath = machinePath;
    m_machineLabel->setText(tr(" Machine: %1").arg(QFileInfo(machinePath).fileName()));
}

void MainWindow::startJob(job::JobSpec spec) {
    if (m_thread != nullptr) {
        statusBar()->showMessage(tr("A job is already running"), 3000);
        return;
    }
    if (!m_machinePath.isEmpty()) {
        spec.machineFile = m_machinePath.toStdString();
    }
    if (m_toolRadius->value() > 0.0) {
        spec.toolRadius = m_toolRadius->value();
    }
    m_spec = spec;
    m_thread = new JobThread(std::move(spec), this);
    connect(m_thread, &JobThread::progressed, this, [this](double fraction, const QString& stage) {
        m_progress->setValue(static_cast<int>(std::lround(fraction * 1000.0)));
        statusBar()->showMessage(tr("Running: %1").arg(stage));
    });
    connect(m_thread, &QThread::finished, this, &MainWindow::onJobFinished);
    m_progress->setValue(0);
    m_progress->setVisible(true);
    m_cancel->setVisible(true);
    m_thread->start();
}

void MainWindow::onJobFinished() {
    Result<job::JobResult> outcome = m_thread->takeResult();
    m_thread->deleteLater();
    m_thread = nullptr;
    m_progress->setVisible(false);
    m_cancel->setVisible(false);
    if (!outcome) {
        statusBar()->showMessage(tr("Job failed"));
        if (outcome.error().code != ErrorCode::Cancelled) {
            QMessageBox::warning(this, tr("BladeAxis"),
                                 QString::fromStdString(outcome.error().toString()));
        }
        emit jobFinished(false);
        return;
    }
    m_result = std::move(*outcome);
    showLayers();
    m_plots->setProfiles(m_result->original,
                         m_result->rescheduled
                             ? std::optional<analysis::AxisProfile>(m_result->rescheduled->profile)
                             : std::nullopt);
    if (m_result->rescheduled) {
        m_view3d->setToolRadius(m_result->toolRadius.value_or(0.0));
        m_view3d->setSchedule(m_result->rescheduled->schedule);
        const auto samples = static_cast<int>(m_result->rescheduled->schedule.newTips.size());
        m_toolSlider->setRange(0, std::max(samples - 1, 0));
        m_toolSlider->setEnabled(samples > 0);
    }
    statusBar()->showMessage(tr("Done in %1 s").arg(m_result->seconds, 0, 'f', 2));
    emit jobFinished(true);
}

void MainWindow::showLayers() {
    m_layers->setRowCount(0);
    if (!m_result || !m_result->rescheduled) {
        return;
    }
    const auto& layers = m_result->rescheduled->schedule.layers;
    m_layers->setRowCount(static_cast<int>(layers.size()));
    for (std::size_t index = 0; index < layers.size(); ++index) {
        const auto& layer = layers[index];
        const int row = static_cast<int>(index);
        m_layers->setItem(row, 0, numberItem(static_cast<double>(index), 0));
        m_layers->setItem(row, 1, new QTableWidgetItem(layerStatusText(layer)));
        m_layers->setItem(row, 2, numberItem(static_cast<double>(layer.s.size()), 0));
        m_layers->setItem(row, 3, numberItem(layer.minClearance * 1000.0, 2));
        m_layers->setItem(row, 4, numberItem(layer.peakSecondDerivative, 4));
    }
}

void MainWindow::showSelectedLayer(int layer) {
    m_view3d->setSelectedLayer(layer);
    if (!m_result || !m_result->rescheduled || layer < 0) {
        m_editor->clearLayer();
        return;
    }
    const auto& layers = m_result->rescheduled->schedule.layers;
    if (static_cast<std::size_t>(layer) < layers.size()) {
        m_editor->setLayer(layers[static_cast<std::size_t>(layer)], m_spec.parameters);
    }
}

int MainWindow::selectedLayer() const {
    const QList<QTableWidgetItem*> items = m_layers->selectedItems();
    return items.isEmpty() ? -1 : items.front()->row();
}

void MainWindow::selectLayer(int layer) {
    if (layer >= 0 && layer < m_layers->rowCount()) {
        m_layers->selectRow(layer);
    }
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (event->mimeData()->hasUrls()) {
        event->acceptProposedAction();
    }
}

void MainWindow::dropEvent(QDropEvent* event) {
    const QList<QUrl> urls = event->mimeData()->urls();
    if (!urls.isEmpty() && urls.front().isLocalFile()) {
        const QString path = urls.front().toLocalFile();
        if (path.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)) {
            setMachineFile(path);
        } else {
            runProgram(path);
        }
    }
}

void MainWindow::openProgramDialog() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open program"), QString(),
        tr("Programs (*.nc *.ngc *.gcode *.tap *.cl *.apt *.cls);;All files (*)"));
    if (!path.isEmpty()) {
        runProgram(path);
    }
}

void MainWindow::openMachineDialog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open machine"), QString(),
                                                      tr("Machine files (*.json)"));
    if (!path.isEmpty()) {
        setMachineFile(path);
    }
}

Status MainWindow::exportProgram(const QString& path) {
    if (!m_result || !m_result->rescheduled) {
        return makeError(ErrorCode::InvalidArgument, "no re-scheduled program to export yet");
    }
    job::JobSpec spec = m_spec;
    spec.outputProgram = path.toStdString();
    spec.outputDir.clear();
    return job::writeJobOutputs(spec, *m_result);
}

void MainWindow::exportProgramDialog() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export program"));
    if (path.isEmpty()) {
        return;
    }
    const Status written = exportProgram(path);
    if (!written) {
        QMessageBox::warning(this, tr("Export refused"),
                             QString::fromStdString(written.error().toString()));
        return;
    }
    // Editor changes are a preview until they are applied to the whole job.
    statusBar()->showMessage(
        tr("Exported %1 (the job's schedule; editor changes not applied)").arg(path));
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
        m_recentMenu->addAction(path, this, [this, path] { runProgram(path); });
    }
    m_recentMenu->setEnabled(!recent.isEmpty());
}

} // namespace bladeaxis::ui
