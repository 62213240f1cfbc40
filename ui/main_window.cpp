#include "ui/main_window.h"

#include "core/base/units.h"
#include "core/job/demo_program.h"
#include "core/job/tool_radius.h"
#include "ui/comparison_summary.h"
#include "ui/comparison_table.h"
#include "ui/job_settings_panel.h"
#include "ui/job_thread.h"
#include "ui/layer_settings_panel.h"
#include "ui/profile_plots.h"
#include "ui/review_dashboard.h"
#include "ui/s_theta_editor.h"
#include "ui/section_view.h"
#include "ui/toolpath_view.h"

#include <QCloseEvent>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFont>
#include <QFrame>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSlider>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>
#include <cmath>
#include <utility>

namespace bladeaxis::ui {
namespace {

enum LayerColumn {
    kLayerColumn,
    kStatusColumn,
    kEditColumn,
    kReversalsBefore,
    kReversalsAfter,
    kPeakABefore,
    kPeakAAfter,
    kClearanceColumn,
    kPeakThetaColumn,
    kLayerColumns
};

QString layerStatusText(const scheduling::LayerResult& layer) {
    QStringList names;
    for (const scheduling::LayerStatus status : layer.flags) {
        names << QString::fromUtf8(scheduling::toString(status));
    }
    return names.isEmpty() ? QStringLiteral("ok") : names.join(QStringLiteral(", "));
}

QString editText(const scheduling::LayerOverride* change) {
    if (change == nullptr) {
        return {};
    }
    const bool settings =
        change->preset || change->marginRad || change->epsilonRule || change->leadFraction;
    if (settings && !change->keyPoints.empty()) {
        return QObject::tr("settings, key points");
    }
    return settings ? QObject::tr("settings") : QObject::tr("key points");
}

const QColor kBetter(20, 130, 60);
const QColor kWorse(200, 40, 40);
constexpr double kNoticeableChange = 0.01; // 1 %: below this a re-run's figure did not move
constexpr double kMuchWorse = 2.0;         // x2: an edit that made the layer much worse

// A number as a person reads it in the desktop's language: thousands grouped ("1,408,372"),
// right-aligned; the value itself kept for sorting and tests.
QTableWidgetItem* numberItem(double value, int decimals) {
    auto* item = new QTableWidgetItem(QLocale().toString(value, 'f', decimals));
    item->setData(Qt::UserRole, value);
    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    return item;
}

// The time span (s, on the re-scheduled motion's time axis) of the samples of pass records
// first..last; nullopt when none of them was analysed.
std::optional<std::pair<double, double>> layerTimeSpan(const analysis::AxisProfile& profile,
                                                       std::size_t first, std::size_t last) {
    const auto& records = profile.sampleRecord;
    const auto begin = std::lower_bound(records.begin(), records.end(), first);
    const auto end = std::upper_bound(records.begin(), records.end(), last);
    if (begin >= end) {
        return std::nullopt;
    }
    return std::pair{profile.timeAt(static_cast<std::size_t>(begin - records.begin())),
                     profile.timeAt(static_cast<std::size_t>(end - records.begin()) - 1)};
}

// One undo step of the job: a layer's override before and after, and the key points the editor
// shows at once for each (the job re-runs with the override in the background).
class LayerEditCommand final : public QUndoCommand {
  public:
    LayerEditCommand(MainWindow& window, std::size_t layer,
                     std::optional<scheduling::LayerOverride> before,
                     std::optional<scheduling::LayerOverride> after,
                     std::vector<Vec2> beforePreview, std::vector<Vec2> afterPreview,
                     const QString& text)
        : QUndoCommand(text), m_window(window), m_layer(layer), m_before(std::move(before)),
          m_after(std::move(after)), m_beforePreview(std::move(beforePreview)),
          m_afterPreview(std::move(afterPreview)) {}
    void undo() override { m_window.setLayerOverride(m_layer, m_before, m_beforePreview); }
    void redo() override { m_window.setLayerOverride(m_layer, m_after, m_afterPreview); }

  private:
    MainWindow& m_window;
    std::size_t m_layer;
    std::optional<scheduling::LayerOverride> m_before, m_after;
    std::vector<Vec2> m_beforePreview, m_afterPreview;
};

} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    updateTitle();
    connect(&m_undo, &QUndoStack::cleanChanged, this,
            [this](bool clean) { setWindowModified(!clean); });
    setAcceptDrops(true);
    m_layers = new QTableWidget(0, kLayerColumns, this);
    setLayerHeaders(m_tableLetter);
    m_layers->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_layers->setSelectionMode(QAbstractItemView::SingleSelection);
    m_layers->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_layers->horizontalHeader()->setStretchLastSection(true);
    m_layers->verticalHeader()->setVisible(false);
    connect(m_layers, &QTableWidget::itemSelectionChanged, this,
            [this] { emit layerSelected(selectedLayer()); });
    connect(this, &MainWindow::layerSelected, this, &MainWindow::showSelectedLayer);

    auto* tabs = new QTabWidget(this);
    m_tabs = tabs;
    tabs->setObjectName(QStringLiteral("pages"));
    tabs->addTab(buildReviewPage(), tr("Review"));
    tabs->addTab(buildEditorPage(), tr("S-θ editor"));
    m_plots = new ProfilePlots(this);
    tabs->addTab(m_plots, tr("Axis motion"));
    tabs->addTab(buildComparisonPage(), tr("Comparison"));
    tabs->addTab(build3dPage(), tr("3D view"));
    auto* splitter = new QSplitter(this);
    splitter->addWidget(m_layers);
    splitter->addWidget(tabs);
    splitter->setStretchFactor(1, 2);
    splitter->setSizes({420, 780});
    // A given radius that contradicts the program is said above everything, not in a tooltip:
    // the program sent to the machine depends on it.
    m_radiusBanner = new QFrame(this);
    m_radiusBanner->setObjectName(QStringLiteral("radiusConflictBanner"));
    m_radiusBanner->setStyleSheet(
        QStringLiteral("#radiusConflictBanner { background: #fbd3d3; border: 1px solid #c62828; }"
                       "#radiusConflictBanner QLabel { color: #8e0000; font-weight: bold; }"));
    auto* bannerRow = new QHBoxLayout(m_radiusBanner);
    m_radiusBannerText = new QLabel(m_radiusBanner);
    m_radiusBannerText->setWordWrap(true);
    auto* useProgram = new QPushButton(tr("Use the program's radius"), m_radiusBanner);
    useProgram->setObjectName(QStringLiteral("useProgramRadius"));
    connect(useProgram, &QPushButton::clicked, this, &MainWindow::useProgramToolRadius);
    auto* keepGiven = new QPushButton(tr("Keep the given radius"), m_radiusBanner);
    keepGiven->setObjectName(QStringLiteral("keepGivenRadius"));
    connect(keepGiven, &QPushButton::clicked, this, &MainWindow::confirmGivenToolRadius);
    bannerRow->addWidget(m_radiusBannerText, 1);
    bannerRow->addWidget(useProgram);
    bannerRow->addWidget(keepGiven);
    m_radiusBanner->setVisible(false);
    auto* central = new QWidget(this);
    auto* centralLayout = new QVBoxLayout(central);
    centralLayout->setContentsMargins(0, 0, 0, 0);
    centralLayout->addWidget(m_radiusBanner);
    centralLayout->addWidget(splitter, 1);
    setCentralWidget(central);

    m_undo.setUndoLimit(500);
    buildJobSettingsDock();
    buildListingDock();
    buildFileMenu();
    buildEditMenu();
    buildViewMenu();
    buildHelpMenu();
    buildToolBar();
    buildStatusBar();
    resize(1200, 780);
    restoreSettings();
}

void MainWindow::setLayerHeaders(QChar table) {
    // Two-line headers (name over unit) keep the columns narrow enough for the before/after
    // figures to fit beside the editor without scrolling.
    m_layers->setHorizontalHeaderLabels(
        {tr("Layer"), tr("Status"), tr("Edited"), tr("Rev.\nbefore"), tr("Rev.\nafter"),
         tr("Peak %1 acc.\nbefore [°/s²]").arg(table), tr("Peak %1 acc.\nafter [°/s²]").arg(table),
         tr("Min clearance\n[°]"), tr("Peak θ''\n[°/mm²]")});
    const QStringList headerTips{
        tr("Layer number, 0 first in feed order"),
        tr("ok, or what the engine found: pinched, monotone infeasible (original kept), ..."),
        tr("What you changed in this layer: settings, key points"),
        tr("%1 reversals in the layer, original program").arg(table),
        tr("%1 reversals in the layer, re-scheduled program (0 is the aim)").arg(table),
        tr("Peak %1 acceleration in the layer at the programmed feed, original program").arg(table),
        tr("Peak %1 acceleration in the layer, re-scheduled; green lower, red higher than before")
            .arg(table),
        tr("Smallest distance of the new orientation from the edge of the channel where the shank "
           "touches the blade: the margin (3° by default) where the schedule runs along the "
           "hull, less only where the layer is pinched"),
        tr("Sharpest bend of the new θ(S); lower is smoother")};
    for (int column = 0; column < kLayerColumns; ++column) {
        m_layers->horizontalHeaderItem(column)->setToolTip(headerTips[column]);
    }
    m_layers->setToolTip(tr("Layers of the re-scheduled toolpath: status, %1 reversals and peak "
                            "%1 acceleration before and after; selecting one selects it "
                            "everywhere")
                             .arg(table));
}

void MainWindow::showAxisLetters(const kinematics::MachineModel& machine) {
    std::array<char, 5> letters{};
    for (kinematics::AxisId axis : kinematics::kAllAxes) {
        letters[static_cast<std::size_t>(axis)] = machine.letter(axis);
    }
    m_plots->setAxisLetters(letters);
    m_tableLetter = QLatin1Char(machine.letter(kinematics::AxisId::A));
    setLayerHeaders(m_tableLetter);
    const std::array<std::pair<QString, QString>, 2> texts{
        std::pair{tr("Colour: &%1 speed").arg(m_tableLetter), tr("%1 speed").arg(m_tableLetter)},
        std::pair{tr("Colour: %1 speed (&original)").arg(m_tableLetter),
                  tr("%1 speed (original)").arg(m_tableLetter)}};
    for (std::size_t i = 0; i < texts.size(); ++i) {
        m_speedColourings[i]->setText(texts[i].first);
        m_speedColourings[i]->setIconText(texts[i].second);
    }
}

MainWindow::~MainWindow() {
    if (m_thread != nullptr) {
        m_thread->requestCancel();
        m_thread->wait();
    }
}

QWidget* MainWindow::buildEditorPage() {
    auto* page = new QWidget(this);
    auto* layout = new QVBoxLayout(page);
    layout->setContentsMargins(0, 0, 0, 0);
    m_layerSettings = new LayerSettingsPanel(page);
    connect(m_layerSettings, &LayerSettingsPanel::settingsChanged, this,
            &MainWindow::onLayerSettingsChanged);
    connect(m_layerSettings, &LayerSettingsPanel::resetRequested, this, &MainWindow::onLayerReset);
    auto* split = new QSplitter(Qt::Horizontal, page);
    m_editor = new SThetaEditor(split);
    connect(m_editor, &SThetaEditor::keyPointsEdited, this, &MainWindow::onKeyPointsEdited);
    m_section = new SectionView(split);
    m_section->setToolTip(tr("The layer in its section plane: blade section, ball-centre path, "
                             "original (orange) and re-scheduled (blue) tool axes"));
    split->addWidget(m_editor);
    split->addWidget(m_section);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    layout->addWidget(m_layerSettings);
    layout->addWidget(split, 1);
    return page;
}

QWidget* MainWindow::build3dPage() {
    auto* page = new QWidget(this);
    auto* layout = new QVBoxLayout(page);
    m_view3dBar = new QToolBar(page);
    m_view3dBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    layout->addWidget(m_view3dBar);
    m_view3d = new ToolpathView(page);
    m_toolSlider = new QSlider(Qt::Horizontal, page);
    m_toolSlider->setToolTip(tr("Scrub along the toolpath: shows the tool (ball and shank) there"));
    m_toolSlider->setEnabled(false);
    connect(m_toolSlider, &QSlider::valueChanged, this,
            [this](int record) { showPassRecord(static_cast<std::size_t>(record)); });
    // Where the tool is, as the engineer reads it: program line, time and A.
    auto* readout = new QLabel(page);
    readout->setMinimumWidth(readout->fontMetrics().horizontalAdvance(
        QStringLiteral("line 0000000 · t = 00000.00 s · A = −0000.0°")));
    connect(m_view3d, &ToolpathView::positionReadoutChanged, readout, &QLabel::setText);
    // A click on the toolpath selects the point's layer and moves the tool there.
    connect(m_view3d, &ToolpathView::pointPicked, this, [this](std::size_t passIndex) {
        if (m_result) {
            selectRecord(m_result->pass.first + passIndex);
        }
    });
    auto* sliderRow = new QHBoxLayout;
    sliderRow->addWidget(m_toolSlider, 1);
    sliderRow->addWidget(readout);
    layout->addWidget(m_view3d, 1);
    layout->addLayout(sliderRow);
    return page;
}

void MainWindow::buildStatusBar() {
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 1000);
    m_progress->setMaximumWidth(220);
    m_progress->setVisible(false);
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setToolTip(tr("Stop the running job (Esc)"));
    m_cancel->setShortcut(QKeySequence(Qt::Key_Escape));
    m_cancel->setVisible(false);
    connect(m_cancel, &QPushButton::clicked, this, &MainWindow::cancelJob);
    statusBar()->addPermanentWidget(m_progress);
    statusBar()->addPermanentWidget(m_cancel);
    statusBar()->showMessage(tr("Open a program (Ctrl+O) or run the demo (Ctrl+D)"));
}

void MainWindow::runDemo() {
    if (m_thread != nullptr) { // refused before anything of the job on screen changes
        statusBar()->showMessage(tr("A job is already running"), 3000);
        return;
    }
    job::JobSpec spec;
    spec.demo = true;
    spec = m_jobSettings->applyTo(std::move(spec));
    spec.read.angleUnit.reset(); // the unit belongs to a program, the tolerances to the desk
    m_undo.clear();
    detachBladeCad();
    startJob(std::move(spec), false, RadiusChoice{});
}

void MainWindow::runProgram(const QString& programPath) {
    if (m_thread != nullptr) {
        statusBar()->showMessage(tr("A job is already running"), 3000);
        return;
    }
    job::JobSpec spec;
    spec.program = programPath.toStdString();
    spec = m_jobSettings->applyTo(std::move(spec));
    spec.read.angleUnit.reset();   // the unit belongs to a program, the tolerances to the desk
    m_pendingRecent = programPath; // a file that does not read is not worth recalling
    m_undo.clear();
    detachBladeCad();
    startJob(std::move(spec), false, RadiusChoice{});
}

void MainWindow::updateTitle() {
    if (!m_result) {
        setWindowTitle(QStringLiteral("BladeAxis"));
        return;
    }
    const QString name =
        m_spec.demo ? QString::fromLatin1(job::kDemoProgramName)
                    : QFileInfo(QString::fromStdString(m_spec.program.string())).fileName();
    setWindowTitle(tr("%1[*] - BladeAxis").arg(name));
    setWindowModified(!m_undo.isClean());
}

bool MainWindow::needsToolRadius(const Error& error) {
    return error.code == ErrorCode::InvalidArgument &&
           error.message.find("ball radius") != std::string::npos &&
           error.message.find("--tool-radius") != std::string::npos;
}

// Pre-filled with the radius this program states (none when it is asked for) and never with a
// value typed for another program: 0 until the engineer types one.
void MainWindow::askToolRadiusAndRetry(job::JobSpec spec, const QString& program) {
    QInputDialog dialog(this);
    dialog.setWindowTitle(tr("Ball radius"));
    dialog.setLabelText(
        tr("%1 does not state the ball radius of its cutter.\nBall radius R [mm] "
           "for this program:")
            .arg(QFileInfo(QString::fromStdString(spec.program.string())).fileName()));
    dialog.setInputMode(QInputDialog::DoubleInput);
    dialog.setDoubleRange(0.0, 500.0);
    dialog.setDoubleDecimals(3);
    dialog.setDoubleValue(spec.toolRadius.value_or(0.0));
    if (dialog.exec() != QDialog::Accepted || !(dialog.doubleValue() > 0.0)) {
        statusBar()->showMessage(tr("No ball radius given: the program was not run"));
        return;
    }
    spec.toolRadius = dialog.doubleValue();
    m_pendingRecent = program;
    startJob(std::move(spec), false, RadiusChoice{RadiusOrigin::Asked, false});
}

void MainWindow::detachBladeCad() {
    if (m_result && !m_cadPath.isEmpty()) {
        statusBar()->showMessage(
            tr("Blade CAD %1 detached: it belonged to the previous program").arg(m_cadPath), 8000);
        m_cadPath.clear();
        m_cadPlacement = {};
        showBladeCad();
    }
}

void MainWindow::cancelJob() {
    if (m_thread != nullptr) {
        m_thread->requestCancel();
    }
}

void MainWindow::startJob(job::JobSpec spec, bool reapply, std::optional<RadiusChoice> radius) {
    if (m_thread != nullptr) {
        statusBar()->showMessage(tr("A job is already running"), 3000);
        return;
    }
    if (!reapply) {
        if (!m_machinePath.isEmpty() && spec.machineFile.empty()) {
            spec.machineFile = m_machinePath.toStdString();
        }
        // The radius is the spec's alone: a value typed for the program on screen is not
        // carried to another one (rerunWithToolRadius puts it in the spec of the same program).
        // CAD loaded before any program was shown is the first program's.
        if (!m_result && !m_cadPath.isEmpty() && spec.cad.file.empty() && !spec.demo) {
            spec.cad.file = m_cadPath.toStdString();
            spec.cad.placement = m_cadPlacement;
        }
        spec.compare = m_compareAction->isChecked();
        spec.compareOptimum = m_optimumAction->isChecked();
        m_specBeforeJob = std::exchange(m_spec, spec);
        m_radiusBeforeJob = m_radius;
        if (radius) {
            m_radius = *radius;
        }
        m_lastAttempt = spec;
        m_lastAttemptRadius = m_radius;
        m_lastAttemptFailed = false;
        m_jobSettings->showSpec(spec);
        showBladeCad();
    }
    // Edits do not change the comparison (its methods schedule the preset's own layers): a
    // re-run for an edit keeps the comparison it has and skips that work.
    if (reapply) {
        spec.compare = false;
    }
    m_keepSelection = selectedLayer();
    m_threadIsReapply = reapply;
    m_thread = new JobThread(std::move(spec), this);
    const quint64 generation = ++m_jobGeneration;
    connect(m_thread, &JobThread::progressed, this,
            [this, reapply](double fraction, const QString& stage) {
                m_progress->setValue(static_cast<int>(std::lround(fraction * 1000.0)));
                // A re-run for an edit repeats every stage of the job; the user asked for one
                // thing, which the message names first.
                statusBar()->showMessage(reapply ? tr("Applying the layer edits: %1").arg(stage)
                                                 : tr("Running: %1").arg(stage));
            });
    // A job stopped by stopRunningJob was handled already: its late signal is not the next job's.
    connect(m_thread, &QThread::finished, this, [this, generation] {
        if (generation == m_jobGeneration && m_thread != nullptr) {
            onJobFinished();
        }
    });
    if (!reapply) { // a new program is shown in 3D as soon as it is read
        connect(m_thread, &JobThread::originalReady, this, [this] {
            if (m_thread != nullptr) {
                m_view3d->showScene(m_thread->takeOriginalScene());
            }
        });
    }
    m_progress->setValue(0);
    m_progress->setVisible(true);
    m_cancel->setVisible(true);
    m_thread->start();
}

void MainWindow::onJobFinished() {
    Result<job::JobResult> outcome = m_thread->takeResult();
    job::DisplayScene scene = m_thread->takeScene();
    std::string programText = m_thread->takeProgramText();
    const bool reapply = m_threadIsReapply;
    m_thread->deleteLater();
    m_thread = nullptr;
    m_progress->setVisible(false);
    m_cancel->setVisible(false);
    const QString pendingRecent = std::exchange(m_pendingRecent, QString());
    if (!outcome) {
        const bool cancelled = outcome.error().code == ErrorCode::Cancelled;
        // What the command line asks for with --tool-radius, the window asks for below.
        const bool askRadius = !reapply && needsToolRadius(outcome.error());
        statusBar()->showMessage(cancelled ? tr("Cancelled") : tr("Job failed"));
        job::JobSpec failed = m_spec;
        if (!reapply) {
            // The 3D view showed the new program as soon as it was read; everything else still
            // holds the previous result, so the view and the job settings go back to it (an
            // export after this writes the result shown).
            m_spec = m_specBeforeJob;
            m_radius = m_radiusBeforeJob;
            if (m_result) {
                m_view3d->showScene(m_scene);
                m_cadPath = QString::fromStdString(m_spec.cad.file.string());
                m_cadPlacement = m_spec.cad.placement;
            }
            // A machine file that does not load is not kept for the next program.
            if (outcome.error().code == ErrorCode::MachineFile && !m_machinePath.isEmpty() &&
                failed.machineFile == m_machinePath.toStdString()) {
                const QString restored = QString::fromStdString(m_spec.machineFile.string());
                if (!setMachineFile(restored == m_machinePath ? QString() : restored)) {
                    static_cast<void>(setMachineFile(QString()));
                }
            }
            showToolRadius();
            showBladeCad();
        }
        if (!reapply) {
            // A failed program stays in the Job settings, to be run again with other settings.
            m_lastAttemptFailed = !cancelled;
            if (cancelled) {
                m_jobSettings->showSpec(m_spec);
            }
        }
        if (!cancelled && !askRadius) {
            showJobError(outcome.error());
        }
        m_editor->setPending({});
        emit jobFinished(false);
        if (askRadius) {
            askToolRadiusAndRetry(std::move(failed), pendingRecent);
        }
        return;
    }
    if (!pendingRecent.isEmpty() && !reapply) {
        rememberRecent(pendingRecent);
    }
    if (reapply && m_result && m_result->comparison && !outcome->comparison) {
        outcome->comparison = std::move(m_result->comparison);
        // The comparison was computed before the edit: the edited schedule becomes its row.
        if (auto status = job::appendEditedMethod(*outcome, m_spec); !status) {
            statusBar()->showMessage(tr("The edited schedule is not in the comparison: %1")
                                         .arg(QString::fromStdString(status.error().message)));
        }
    }
    m_result = std::move(*outcome);
    showListing(std::move(programText), !reapply);
    showResult(std::move(scene));
    if (!reapply) {
        m_cadPath = QString::fromStdString(m_spec.cad.file.string());
        m_cadPlacement = m_spec.cad.placement;
    }
    showToolRadius();
    showBladeCad();
    updateExportActions();
    updateTitle();
    const QString cycleTimes = QString::fromStdString(job::cycleTimeStatus(*m_result));
    QStringList warnings;
    for (const std::string& warning : m_result->warnings) {
        warnings << QString::fromStdString(warning);
    }
    statusBar()->showMessage(
        (reapply ? tr("Layer edits applied in %1 s").arg(m_result->seconds, 0, 'f', 2)
                 : tr("Done in %1 s").arg(m_result->seconds, 0, 'f', 2)) +
        tr("; cycle time: %1").arg(cycleTimes) +
        (warnings.isEmpty() ? QString()
                            : tr("; %n warning(s) on the Review page", nullptr,
                                 static_cast<int>(warnings.size()))));
    statusBar()->setToolTip(warnings.isEmpty() ? QString()
                                               : tr("%n warning(s), listed on the Review page:\n",
                                                    nullptr, static_cast<int>(warnings.size())) +
                                                     warnings.join(QLatin1Char('\n')));
    if (m_reapplyQueued) {
        m_reapplyQueued = false;
        reapplyEdits();
    }
    emit jobFinished(true);
}

void MainWindow::showResult(job::DisplayScene scene) {
    m_scene = std::move(scene);
    showAxisLetters(m_result->machine);
    showReview(!m_threadIsReapply);
    showLayers();
    m_plots->setMachineLimits(m_result->machine);
    if (m_result->comparison) {
        const QString exported = exportedMethod();
        m_plots->setComparison(*m_result->comparison, exported);
        m_comparison->setComparison(*m_result->comparison);
        m_comparison->setExportedMethod(exported);
        m_comparisonSummary->setComparison(*m_result->comparison, exported,
                                           m_result->machine.controller.planner);
    } else {
        m_comparisonSummary->clear();
        m_plots->setProfiles(m_result->original, m_result->rescheduled
                                                     ? std::optional(m_result->rescheduled->profile)
                                                     : std::nullopt);
        m_comparison->clear();
    }
    m_view3d->showScene(m_scene);
    m_view3d->setToolRadius(m_result->toolRadius.value_or(0.0));
    m_view3d->setTimeline(*m_result);
    const auto records = static_cast<int>(m_result->pass.count);
    m_toolSlider->setRange(0, std::max(records - 1, 0));
    m_toolSlider->setEnabled(records > 0);
    const int row = m_keepSelection >= 0 && m_keepSelection < m_layers->rowCount() ? m_keepSelection
                    : m_layers->rowCount() > 0                                     ? 0
                                                                                   : -1;
    if (row >= 0) {
        selectLayer(row);
        showSelectedLayer(row); // also when the row was already selected
    }
}

void MainWindow::showLayers() {
    const QSignalBlocker block(m_layers);
    m_layers->setRowCount(0);
    if (!m_result || !m_result->rescheduled) {
        return;
    }
    const std::vector<report::LayerMotion> motion = job::layerMotionOf(*m_result);
    const std::vector<report::LayerMotion> before = std::exchange(m_layerMotion, motion);
    const bool compare = m_threadIsReapply && before.size() == motion.size();
    m_layers->setRowCount(static_cast<int>(motion.size()));
    for (int row = 0; row < m_layers->rowCount(); ++row) {
        const auto index = static_cast<std::size_t>(row);
        showLayerRow(row, motion[index]);
        if (compare) {
            explainLayerChange(row, motion[index], before[index]);
        }
    }
    m_layers->resizeColumnsToContents();
}

void MainWindow::showLayerRow(int row, const report::LayerMotion& m) {
    const auto& layer = m_result->rescheduled->schedule.layers[static_cast<std::size_t>(row)];
    m_layers->setItem(row, kLayerColumn, numberItem(row, 0));
    auto* status = new QTableWidgetItem(layerStatusText(layer));
    if (scheduling::isFlagged(layer)) {
        status->setForeground(QColor(200, 110, 0));
    }
    m_layers->setItem(row, kStatusColumn, status);
    m_layers->setItem(row, kEditColumn,
                      new QTableWidgetItem(editText(overrideOf(static_cast<std::size_t>(row)))));
    m_layers->setItem(row, kReversalsBefore, numberItem(m.reversalsBefore, 0));
    m_layers->setItem(row, kReversalsAfter, numberItem(m.reversalsAfter, 0));
    m_layers->setItem(row, kPeakABefore, numberItem(units::radToDeg(m.peakAccelerationBefore), 0));
    auto* after = numberItem(units::radToDeg(m.peakAccelerationAfter), 0);
    // Before -> after at a glance: lower is what the re-scheduling is for.
    after->setForeground(m.peakAccelerationAfter <= m.peakAccelerationBefore ? kBetter : kWorse);
    m_layers->setItem(row, kPeakAAfter, after);
    m_layers->setItem(row, kClearanceColumn, numberItem(units::radToDeg(layer.minClearance), 3));
    m_layers->setItem(row, kPeakThetaColumn,
                      numberItem(units::radToDeg(layer.peakSecondDerivative), 4));
}

void MainWindow::explainLayerChange(int row, const report::LayerMotion& now,
                                    const report::LayerMotion& before) {
    const double ratio = now.peakAccelerationAfter / std::max(before.peakAccelerationAfter, 1e-12);
    if (std::abs(ratio - 1.0) < kNoticeableChange) {
        return;
    }
    const auto layer = static_cast<std::size_t>(row);
    QString why;
    if (overrideOf(layer) != nullptr) {
        why = tr("This layer's edit changed its peak %1 acceleration").arg(m_tableLetter);
    } else {
        const bool previousEdited = layer > 0 && overrideOf(layer - 1) != nullptr;
        const bool nextEdited = overrideOf(layer + 1) != nullptr;
        why = nextEdited ? tr("Changed although not edited: layer %1's edit moved the junction "
                              "this layer ends at")
                               .arg(row + 1)
              : previousEdited ? tr("Changed although not edited: layer %1's edit moved the "
                                    "junction this layer starts at")
                                     .arg(row - 1)
                               : tr("Changed with the last edit of another layer");
    }
    QTableWidgetItem* item = m_layers->item(row, kPeakAAfter);
    const QString change =
        ratio >= 1.0
            ? tr("%1× the peak before the last edit").arg(QLocale().toString(ratio, 'f', 1))
            : tr("%1 % lower than before the last edit")
                  .arg(QLocale().toString(100.0 * (1.0 - ratio), 'f', 0));
    item->setToolTip(why + QStringLiteral(": ") + change);
    item->setText(item->text() + (ratio >= 1.0 ? QStringLiteral(" ▲") : QStringLiteral(" ▼")));
    if (ratio >= kMuchWorse) { // an edit that made a layer much worse must not go unseen
        item->setBackground(QColor(255, 205, 205));
        item->setForeground(QColor(150, 0, 0));
    }
}

void MainWindow::showSelectedLayer(int layer) {
    m_view3d->setSelectedLayer(layer);
    if (!m_result || !m_result->rescheduled || layer < 0 ||
        static_cast<std::size_t>(layer) >= m_result->rescheduled->schedule.layers.size()) {
        m_editor->clearLayer();
        m_plots->setHighlightedSpan(std::nullopt, {});
        m_layerSettings->clearLayer();
        m_section->clearLayer();
        return;
    }
    const auto index = static_cast<std::size_t>(layer);
    const scheduling::LayerOverride* change = overrideOf(index);
    const scheduling::ScheduleParameters parameters =
        change != nullptr ? scheduling::layerParameters(m_spec.parameters, *change)
                          : m_spec.parameters;
    const auto& scheduled = m_result->rescheduled->schedule.layers[index];
    showLayerInListing(scheduled.first, scheduled.last);
    m_editor->setLayer(scheduled, parameters, index);
    m_plots->setHighlightedSpan(
        layerTimeSpan(m_result->rescheduled->profile, scheduled.first, scheduled.last),
        tr("layer %1").arg(layer));
    m_layerSettings->setLayer(layer, change, m_spec.parameters);
    m_section->setLayer(m_scene, layer);
    if (editsPending()) {
        m_editor->setPending(tr("Applying the layer edits…"));
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

// --- Layer edits ----------------------------------------------------------------------------

const scheduling::LayerOverride* MainWindow::overrideOf(std::size_t layer) const {
    return scheduling::findOverride(m_spec.layerEdits, layer);
}

void MainWindow::setLayerOverride(std::size_t layer,
                                  const std::optional<scheduling::LayerOverride>& change,
                                  const std::vector<Vec2>& preview) {
    auto& edits = m_spec.layerEdits;
    std::erase_if(edits, [layer](const auto& edit) { return edit.layer == layer; });
    if (change) {
        const auto at =
            std::ranges::lower_bound(edits, layer, {}, &scheduling::LayerOverride::layer);
        edits.insert(at, *change);
    }
    if (static_cast<int>(layer) == selectedLayer() && !preview.empty()) {
        m_editor->applyVertices(preview);
    }
    if (static_cast<int>(layer) < m_layers->rowCount()) {
        m_layers->setItem(static_cast<int>(layer), kEditColumn,
                          new QTableWidgetItem(editText(overrideOf(layer))));
    }
    requestReapply();
}

void MainWindow::pushLayerEdit(std::size_t layer, std::optional<scheduling::LayerOverride> after,
                               std::vector<Vec2> beforePreview, std::vector<Vec2> afterPreview,
                               const QString& description) {
    const scheduling::LayerOverride* current = overrideOf(layer);
    std::optional<scheduling::LayerOverride> before =
        current != nullptr ? std::optional(*current) : std::nullopt;
    if (before == after) {
        return;
    }
    m_undo.push(new LayerEditCommand(*this, layer, std::move(before), std::move(after),
                                     std::move(beforePreview), std::move(afterPreview),
                                     tr("%1 (layer %2)").arg(description).arg(layer)));
}

void MainWindow::onKeyPointsEdited(const std::vector<Vec2>& before, const std::vector<Vec2>& after,
                                   const QString& description) {
    const int layer = selectedLayer();
    if (layer < 0) {
        return;
    }
    const auto index = static_cast<std::size_t>(layer);
    scheduling::LayerOverride change;
    if (const scheduling::LayerOverride* current = overrideOf(index)) {
        change = *current;
    }
    change.layer = index;
    change.keyPoints = after;
    pushLayerEdit(index, change, before, after, description);
}

// New settings re-schedule the layer from scratch: its key-point edit, made in the old hull,
// is dropped (undo brings it back).
void MainWindow::onLayerSettingsChanged(int layer,
                                        const std::optional<scheduling::LayerOverride>& settings) {
    if (layer >= 0) {
        pushLayerEdit(static_cast<std::size_t>(layer), settings, {}, {},
                      tr("Change layer settings"));
    }
}

void MainWindow::onLayerReset(int layer) {
    if (layer >= 0) {
        pushLayerEdit(static_cast<std::size_t>(layer), std::nullopt, {}, {}, tr("Reset layer"));
    }
}

void MainWindow::requestReapply() {
    if (m_reapplyQueued) {
        return;
    }
    m_reapplyQueued = true;
    m_editor->setPending(tr("Applying the layer edits…"));
    // Coalesces the steps of one user action (and a burst of undos) into one re-run.
    QTimer::singleShot(0, this, [this] {
        if (m_thread == nullptr && m_reapplyQueued) {
            m_reapplyQueued = false;
            reapplyEdits();
        }
    });
}

void MainWindow::reapplyEdits() {
    if (!m_result) {
        return;
    }
    startJob(m_spec, true);
}

Status MainWindow::refuseWhilePending() const {
    if (!m_result || !m_result->rescheduled) {
        return makeError(ErrorCode::InvalidArgument, "no re-scheduled program to export yet");
    }
    if (editsPending()) {
        return makeError(ErrorCode::InvalidArgument,
                         "the job is still running with the latest edits; export when it is done");
    }
    return {};
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!confirmDiscardEdits()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    QMainWindow::closeEvent(event);
}

} // namespace bladeaxis::ui
