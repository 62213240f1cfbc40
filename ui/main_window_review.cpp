// The main window's review desk (issue 38): the Review page shown first after a job, the Job
// settings dock the error dialogs point to, and the dialogs' window wording.

#include "ui/comparison_summary.h"
#include "ui/comparison_table.h"
#include "ui/job_settings_panel.h"
#include "ui/main_window.h"
#include "ui/review_dashboard.h"
#include "ui/window_wording.h"

#include <QCheckBox>
#include <QDockWidget>
#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>
#include <QTabWidget>
#include <QVBoxLayout>

namespace bladeaxis::ui {

QWidget* MainWindow::buildReviewPage() {
    m_dashboard = new ReviewDashboard(this);
    // Selecting the row selects the layer everywhere (layerSelected).
    connect(m_dashboard, &ReviewDashboard::layerRequested, this, &MainWindow::selectLayer);
    connect(m_dashboard, &ReviewDashboard::acknowledgementChanged, this, [this](bool ticked) {
        statusBar()->showMessage(
            ticked ? tr("Export will write the program although the tool gouges or collides at "
                        "the %1 points listed on the Review page")
                         .arg(m_dashboard->clearanceIssueCount())
                   : tr("Export refuses the program while the tool gouges or collides"),
            8000);
    });
    return m_dashboard;
}

QWidget* MainWindow::buildComparisonPage() {
    auto* page = new QWidget(this);
    m_comparisonSummary = new ComparisonSummary(page);
    m_comparison = new ComparisonTable(page);
    m_comparison->setVisible(false);
    auto* full = new QPushButton(tr("Full table"), page);
    full->setObjectName(QStringLiteral("showFullComparison"));
    full->setCheckable(true);
    full->setToolTip(tr("Every column of the comparison, as report.html prints it (Ctrl+C copies "
                        "it as CSV)"));
    connect(full, &QPushButton::toggled, m_comparison, &QWidget::setVisible);
    auto* layout = new QVBoxLayout(page);
    layout->addWidget(m_comparisonSummary, 1);
    layout->addWidget(full, 0, Qt::AlignLeft);
    layout->addWidget(m_comparison, 2);
    return page;
}

QString MainWindow::exportedMethod() const {
    if (!m_spec.layerEdits.empty()) {
        return QString::fromUtf8(job::kEditedMethod);
    }
    return m_spec.presetName == "faithful" ? QStringLiteral("stheta-faithful")
                                           : QStringLiteral("stheta-best");
}

void MainWindow::buildJobSettingsDock() {
    m_jobSettingsDock = new QDockWidget(QString::fromUtf8(controls::kJobSettings), this);
    m_jobSettingsDock->setObjectName(QStringLiteral("jobSettingsDock"));
    m_jobSettings = new JobSettingsPanel(m_jobSettingsDock);
    m_jobSettingsDock->setWidget(m_jobSettings);
    addDockWidget(Qt::RightDockWidgetArea, m_jobSettingsDock);
    // Out of the way until wanted: View > Job settings, or an error dialog that names it.
    m_jobSettingsDock->hide();
    m_jobSettingsDock->toggleViewAction()->setObjectName(QStringLiteral("showJobSettings"));
    connect(m_jobSettings, &JobSettingsPanel::applyRequested, this, &MainWindow::applyJobSettings);
}

void MainWindow::applyJobSettings() {
    if (m_thread != nullptr) {
        statusBar()->showMessage(tr("A job is already running"), 3000);
        return;
    }
    if (m_lastAttemptFailed) {
        job::JobSpec spec = m_jobSettings->applyTo(m_lastAttempt);
        if (!spec.demo) {
            m_pendingRecent = QString::fromStdString(spec.program.string());
        }
        statusBar()->showMessage(
            tr("Running %1 again with the job settings…")
                .arg(spec.demo ? tr("the demo") : QFileInfo(m_pendingRecent).fileName()));
        m_undo.clear(); // the edits on screen belong to the program shown, not this one
        startJob(std::move(spec), false, m_lastAttemptRadius);
        return;
    }
    if (!m_result) {
        statusBar()->showMessage(tr("The settings apply to the next program opened"), 5000);
        return;
    }
    rerunWith(m_jobSettings->applyTo(m_spec), tr("Re-running with the job settings…"));
}

void MainWindow::showReview(bool newProgram) {
    m_dashboard->setResult(*m_result);
    if (newProgram) { // the review comes first; a re-run for an edit keeps the page in use
        m_tabs->setCurrentWidget(m_dashboard);
    }
}

void MainWindow::showJobError(const Error& error) {
    const QString message = windowWording(error);
    if (message.contains(QString::fromUtf8(controls::kJobSettings))) {
        m_jobSettingsDock->show(); // the control the message names, at hand
        m_jobSettingsDock->raise();
    }
    QMessageBox::warning(this, tr("BladeAxis"), message);
}

void MainWindow::showRefusalSource(const Status& status) {
    if (!status && status.error().code == ErrorCode::CheckFailed &&
        !m_dashboard->clearanceAcknowledged()) {
        m_tabs->setCurrentWidget(m_dashboard);
        m_dashboard->acknowledgeBox()->setFocus();
    }
}

} // namespace bladeaxis::ui
