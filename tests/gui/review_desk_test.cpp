// Issue 38, the review desk, read from the window's state: the Review page comes first after a
// job and shows the batch's figures (the same numbers as `--batch --json`, each cycle time
// beside its model), every warning with its place, and every gouge or collision point, whose
// export waits for the engineer's acknowledgement; error dialogs name the window's controls
// (Job settings) instead of command-line options, and those controls fix the program; the plots
// show the original and the exported program with the machine's limits, others on demand, and a
// log acceleration that does not turn a smooth schedule into spikes; the comparison's compact
// view groups its numbers, keeps the method column and states a recommendation.

#include "app/batch/batch_runner.h"
#include "core/base/units.h"
#include "ui/comparison_summary.h"
#include "ui/comparison_table.h"
#include "ui/job_settings_panel.h"
#include "ui/main_window.h"
#include "ui/profile_plots.h"
#include "ui/review_dashboard.h"
#include "ui/window_wording.h"

#include <nlohmann/json.hpp>

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>
#include <QTimer>
#include <QWheelEvent>
#include <cmath>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>

namespace {

constexpr int kJobTimeoutMs = 240'000;
const QString kOut = QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/review_desk");

using bladeaxis::ui::ReviewDashboard;

// Answers the modal dialogs that open while it lives, remembering their text.
class DialogAnswerer {
  public:
    DialogAnswerer() {
        QObject::connect(&m_timer, &QTimer::timeout, [this] {
            if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
                m_texts << box->text();
                box->accept();
            }
        });
        m_timer.start(50);
    }
    const QStringList& texts() const { return m_texts; }

  private:
    QTimer m_timer;
    QStringList m_texts;
};

bool near(double a, double b) {
    return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)});
}

QString jobFileFor(const QString& name, const QString& program) {
    const QString path = kOut + QLatin1Char('/') + name + QStringLiteral(".bladeaxis.json");
    std::ofstream(path.toStdString()) << R"({"schema": "bladeaxis-job/1", "program": ")"
                                      << program.toStdString() << R"(", "tool_radius_mm": 8})";
    return path;
}

} // namespace

class ReviewDeskTest final : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QDir().mkpath(kOut);
        m_window = std::make_unique<bladeaxis::ui::MainWindow>();
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        m_window->runDemo();
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.front().front().toBool(), true);
        std::ostringstream out, err;
        QCOMPARE(bladeaxis::app::runBatchCommandLine(
                     {"bladeaxis", "--batch", "--demo", "--json", "--quiet"}, out, err),
                 0);
        m_batch = nlohmann::json::parse(out.str());
    }

    void theReviewPageComesFirstAfterAJob() {
        QVERIFY(m_window->jobSettingsDock()->isHidden()); // until wanted
        QCOMPARE(m_window->pages()->tabText(0), QStringLiteral("Review"));
        QCOMPARE(m_window->pages()->currentWidget(), static_cast<QWidget*>(m_window->dashboard()));
        QVERIFY(m_window->dashboard()->headline()->text().contains(QStringLiteral("→ 0")));
    }

    // Every figure is the batch's, before and after, and each cycle time names its model in the
    // words of report.json.
    void theReviewPageShowsTheBatchsFiguresBesideTheirModels() {
        const ReviewDashboard& board = *m_window->dashboard();
        const auto value = [&](const char* key, int column) {
            const int row = board.rowOf(QString::fromLatin1(key));
            const QTableWidgetItem* item = row >= 0 ? board.figures()->item(row, column) : nullptr;
            return item != nullptr ? item->data(ReviewDashboard::kValueRole).toDouble() : NAN;
        };
        const auto text = [&](const char* key, int column) {
            const int row = board.rowOf(QString::fromLatin1(key));
            const QTableWidgetItem* item = row >= 0 ? board.figures()->item(row, column) : nullptr;
            return item != nullptr ? item->text() : QString();
        };
        const nlohmann::json& before = m_batch["original"];
        const nlohmann::json& after = m_batch["rescheduled"]["analysis"];
        QCOMPARE(value("reversals", ReviewDashboard::kOriginal),
                 before["a_reversals"].get<double>());
        QCOMPARE(value("reversals", ReviewDashboard::kRescheduled),
                 after["a_reversals"].get<double>());
        const std::pair<const char*, const char*> peaks[] = {
            {"peak_velocity", "peak_velocity_deg_s"},
            {"peak_acceleration", "peak_acceleration_deg_s2"}};
        for (const auto& [key, json] : peaks) {
            QVERIFY2(near(value(key, ReviewDashboard::kOriginal),
                          before["axes"]["A"][json].get<double>()),
                     key);
            QVERIFY2(near(value(key, ReviewDashboard::kRescheduled),
                          after["axes"]["A"][json].get<double>()),
                     key);
        }
        const std::pair<const char*, const char*> times[] = {
            {"t1", "constant_feed"}, {"t2", "look_ahead"}, {"block_time", "block_by_block"}};
        for (const auto& [key, json] : times) {
            QVERIFY2(near(value(key, ReviewDashboard::kOriginal),
                          before["cycle_times"][json]["time_s"].get<double>()),
                     key);
            QVERIFY2(near(value(key, ReviewDashboard::kRescheduled),
                          after["cycle_times"][json]["time_s"].get<double>()),
                     key);
            const QString model =
                QString::fromStdString(before["cycle_times"][json]["model"].get<std::string>());
            QVERIFY2(text(key, ReviewDashboard::kModel).contains(model),
                     qPrintable(text(key, ReviewDashboard::kModel)));
        }
        QVERIFY(text("t2", ReviewDashboard::kModel).startsWith(QStringLiteral("look-ahead")));
        QVERIFY(
            text("block_time", ReviewDashboard::kModel).contains(QStringLiteral("LinuxCNC 2.9")));
        QVERIFY(text("t1", ReviewDashboard::kModel).startsWith(QStringLiteral("constant feed")));
        QVERIFY(text("limiting_axis", ReviewDashboard::kOriginal)
                    .contains(QString::fromStdString(
                        before["constant_feed_time"]["binding_axis"].get<std::string>())));
        const nlohmann::json& checks = m_batch["rescheduled"]["checks"];
        QVERIFY(near(value("channel_clearance", ReviewDashboard::kRescheduled),
                     checks["min_channel_clearance_deg"].get<double>()));
        QVERIFY(near(value("ball_centres", ReviewDashboard::kRescheduled),
                     1000.0 * checks["max_centre_deviation_mm"].get<double>()));
        QCOMPARE(text("ball_centres", ReviewDashboard::kChange), QStringLiteral("kept"));
        QCOMPARE(value("gouges_collisions", ReviewDashboard::kRescheduled),
                 m_batch["clearance"]["rescheduled"]["issues"].get<double>());
        // Numbers a person reads: thousands grouped.
        QVERIFY2(text("peak_acceleration", ReviewDashboard::kOriginal).contains(QLatin1Char(',')),
                 qPrintable(text("peak_acceleration", ReviewDashboard::kOriginal)));
        QCOMPARE(board.warnings()->rowCount(), static_cast<int>(m_batch["warnings"].size()));
    }

    // Only the original and the exported program by default, the exported marked; the others
    // on demand; the machine's limits as lines.
    void thePlotsShowTheOriginalAndTheExportedWithTheMachinesLimits() {
        bladeaxis::ui::ProfilePlots& plots = *m_window->plots();
        QCOMPARE(plots.exportedMethod(), QStringLiteral("stheta-best"));
        QVERIFY(plots.isMethodVisible(QStringLiteral("original")));
        QVERIFY(plots.isMethodVisible(QStringLiteral("stheta-best")));
        for (const QString& other :
             {QStringLiteral("quaternion"), QStringLiteral("stheta-faithful")}) {
            QVERIFY2(plots.methods().contains(other), qPrintable(other));
            QVERIFY2(!plots.isMethodVisible(other), qPrintable(other));
        }
        auto* exported = plots.findChild<QCheckBox*>(QStringLiteral("legend_stheta-best"));
        QVERIFY(exported != nullptr);
        QVERIFY(exported->font().bold());
        QVERIFY(exported->text().contains(QStringLiteral("exported")));
        auto* quaternion = plots.findChild<QCheckBox*>(QStringLiteral("legend_quaternion"));
        QVERIFY(quaternion != nullptr && !quaternion->isChecked());
        quaternion->click();
        QVERIFY(plots.isMethodVisible(QStringLiteral("quaternion")));
        quaternion->click();
        QVERIFY(!plots.isMethodVisible(QStringLiteral("quaternion")));

        const auto& limits = m_window->result()->machine.limit(bladeaxis::kinematics::AxisId::A);
        QVERIFY(plots.limitOf(bladeaxis::ui::ProfilePlots::AAcceleration).has_value());
        QVERIFY(near(*plots.limitOf(bladeaxis::ui::ProfilePlots::AAcceleration),
                     bladeaxis::units::radToDeg(limits.acceleration)));
        QVERIFY(near(*plots.limitOf(bladeaxis::ui::ProfilePlots::AVelocity),
                     bladeaxis::units::radToDeg(limits.velocity)));
    }

    // The log plot draws |a|'s upper envelope per pixel column above a floor four decades under
    // the highest peak shown: the smooth schedule is a band, not a comb of one-column dips.
    void theLogAccelerationDoesNotMakeASmoothScheduleSpiky() {
        bladeaxis::ui::ProfilePlots& plots = *m_window->plots();
        QVERIFY(plots.accelerationLogScale());
        const double peak = bladeaxis::units::radToDeg(
            m_window->result()->original.axis(bladeaxis::kinematics::AxisId::A).peakAcceleration);
        QVERIFY(plots.accelerationLogFloor() >= peak * 1e-4 * 0.999);
        const int columns = 500;
        const std::vector<double> envelope =
            plots.logAccelerationEnvelope(QStringLiteral("stheta-best"), columns);
        QVERIFY(envelope.size() > 100);
        int dips = 0; // a column more than a decade below both neighbours
        for (std::size_t i = 1; i + 1 < envelope.size(); ++i) {
            dips += envelope[i] < envelope[i - 1] - 1.0 && envelope[i] < envelope[i + 1] - 1.0;
        }
        QVERIFY2(dips * 100 < static_cast<int>(envelope.size()), qPrintable(QString::number(dips)));
    }

    // The wheel zooms the time axis about the mouse, a drag pans it, Fit shows it all again.
    void thePlotsZoomPanAndFit() {
        bladeaxis::ui::ProfilePlots& plots = *m_window->plots();
        m_window->pages()->setCurrentWidget(&plots);
        QTest::qWait(50);
        QVERIFY(!plots.timeWindow().has_value());
        auto* fit = plots.findChild<QPushButton*>(QStringLiteral("fitPlots"));
        QVERIFY(fit != nullptr);
        QWidget* canvas = plots.childAt(plots.width() / 4, plots.height() / 2);
        QVERIFY(canvas != nullptr);
        // The middle of the first plot, in one column or two.
        const QPointF inside(canvas->width() / 4.0, canvas->height() / 12.0);
        QWheelEvent wheel(inside, canvas->mapToGlobal(inside), QPoint(), QPoint(0, 120),
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(canvas, &wheel);
        QVERIFY(plots.timeWindow().has_value());
        const auto zoomed = *plots.timeWindow();
        QTest::mousePress(canvas, Qt::LeftButton, Qt::NoModifier, inside.toPoint());
        QMouseEvent drag(QEvent::MouseMove, inside + QPointF(-40, 0),
                         canvas->mapToGlobal(inside + QPointF(-40, 0)), Qt::NoButton,
                         Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(canvas, &drag);
        QTest::mouseRelease(canvas, Qt::LeftButton, Qt::NoModifier,
                            (inside + QPointF(-40, 0)).toPoint());
        QVERIFY(plots.timeWindow()->first > zoomed.first);
        QVERIFY(std::abs((plots.timeWindow()->second - plots.timeWindow()->first) -
                         (zoomed.second - zoomed.first)) < 1e-9);
        fit->click();
        QVERIFY(!plots.timeWindow().has_value());
    }

    void theCompactComparisonGroupsNumbersKeepsTheMethodsAndRecommends() {
        const bladeaxis::ui::ComparisonSummary& summary = *m_window->comparisonSummary();
        const auto& methods = m_window->result()->comparison->methods;
        QCOMPARE(summary.table()->rowCount(), static_cast<int>(methods.size()));
        QVERIFY(!summary.table()->verticalHeader()->isHidden()); // the frozen method names
        const int accel = summary.columnOf(QStringLiteral("peak_acceleration"));
        for (int row = 0; row < summary.table()->rowCount(); ++row) {
            const auto& method = methods[static_cast<std::size_t>(row)];
            QCOMPARE(summary.table()->verticalHeaderItem(row)->text(),
                     QString::fromStdString(method.method));
            const double peak = bladeaxis::units::radToDeg(
                method.profile.axis(bladeaxis::kinematics::AxisId::A).peakAcceleration);
            QTableWidgetItem* cell = summary.table()->item(row, accel);
            QVERIFY(
                near(cell->data(bladeaxis::ui::ComparisonSummary::kValueRole).toDouble(), peak));
            if (peak >= 1000.0) {
                QVERIFY2(cell->text().contains(QLatin1Char(',')), qPrintable(cell->text()));
            }
            const int t1 = summary.columnOf(QStringLiteral("t1"));
            QVERIFY(near(summary.table()->item(row, t1)->data(Qt::UserRole).toDouble(),
                         method.t1.time));
        }
        // On the demo: the S-θ presets differ by under 5 % in T2, so the smoother best wins; the
        // optimum is a reference, not recommended.
        QCOMPARE(summary.recommendedMethod(), QStringLiteral("stheta-best"));
        QVERIFY(summary.recommendation()->text().contains(QStringLiteral("Export writes it.")));
        QVERIFY(summary.recommendation()->text().contains(QStringLiteral("optimal-qp")));
        QVERIFY(summary.rowOf(summary.recommendedMethod()) > 0);
        QVERIFY2(summary.recommendation()->text().contains(QStringLiteral("Recommended: ") +
                                                           summary.recommendedMethod()),
                 qPrintable(summary.recommendation()->text()));
        // The full table on demand.
        QVERIFY(m_window->comparisonTable()->isHidden());
        auto* full = m_window->findChild<QPushButton*>(QStringLiteral("showFullComparison"));
        QVERIFY(full != nullptr);
        full->click();
        QVERIFY(!m_window->comparisonTable()->isHidden());
        QCOMPARE(m_window->comparisonTable()->rowCount(), static_cast<int>(methods.size()));
        full->click();
    }

    void theCoreAdviceIsWordedForTheWindow() {
        using bladeaxis::ui::windowWording;
        const QString radians = windowWording(QStringLiteral(
            "If the A and B words are in radians, give --angle-unit rad; check that"));
        QVERIFY(!radians.contains(QStringLiteral("--")));
        QVERIFY(radians.contains(QStringLiteral("\"radians\" under \"Angle unit\" in the Job "
                                                "settings panel")));
        QVERIFY(
            !windowWording(QStringLiteral("nothing was written (use --force to write it anyway)"))
                 .contains(QStringLiteral("--force")));
        QCOMPARE(windowWording(QStringLiteral("no advice here")), QStringLiteral("no advice here"));
    }

    // Every gouge or collision point of the output is a row (layer, point 1-based, line,
    // depth); export waits for the tick, and a new result clears it.
    void everyClearancePointIsListedAndTheTickBelongsToOneResult() {
        bladeaxis::job::JobResult result = *m_window->result();
        QVERIFY(result.cadCheck && result.cadCheck->rescheduled); // the demo's own surface
        auto& report = *result.cadCheck->rescheduled;
        QVERIFY(report.layers.size() > 2);
        const std::size_t inSecondLayer = report.layers[1].first + 1;
        report.issues = {{.record = 0, .line = 7, .depth = 0.25},
                         {.record = inSecondLayer,
                          .line = 40,
                          .kind = bladeaxis::cad::ClearanceKind::ShankCollision,
                          .depth = 0.5}};
        ReviewDashboard board;
        board.setResult(result);
        QTableWidget& list = *board.clearanceIssues();
        QCOMPARE(board.clearanceIssueCount(), 2);
        const auto value = [&](int row, int column) {
            return list.item(row, column)->data(ReviewDashboard::kValueRole).toDouble();
        };
        QCOMPARE(value(0, ReviewDashboard::kIssueLayer), 0.0);
        QCOMPARE(value(0, ReviewDashboard::kIssuePoint), 1.0);
        QCOMPARE(value(1, ReviewDashboard::kIssueLayer), 1.0);
        QCOMPARE(value(1, ReviewDashboard::kIssuePoint), static_cast<double>(inSecondLayer + 1));
        QCOMPARE(value(1, ReviewDashboard::kIssueLine), 40.0);
        QCOMPARE(value(1, ReviewDashboard::kIssueDepth), 0.5);
        QVERIFY(!list.isHidden() && !board.acknowledgeBox()->isHidden());
        QVERIFY(!board.clearanceAcknowledged());
        board.acknowledgeBox()->click();
        QVERIFY(board.clearanceAcknowledged());
        board.setResult(result); // a re-run: the engineer looks again
        QVERIFY(!board.clearanceAcknowledged());
        result.cadCheck->rescheduled->issues.clear();
        board.setResult(result);
        QVERIFY(board.clearanceAcknowledged()); // nothing to acknowledge
        QVERIFY(board.acknowledgeBox()->isHidden());
    }

    // Each warning's place: the program line it names, the layer, or both; double-clicking a
    // warning that names a layer selects it.
    void everyWarningIsListedWithItsLineOrLayer() {
        bladeaxis::job::JobResult result = *m_window->result();
        result.warnings = {"blade.nc:120: a block beyond the travel of X",
                           "layer 3: no monotone path, the original orientation is kept",
                           "the file ends without M30"};
        ReviewDashboard board;
        board.setResult(result);
        QTableWidget& list = *board.warnings();
        QCOMPARE(list.rowCount(), 3);
        QCOMPARE(list.item(0, ReviewDashboard::kWarningWhere)->text(), QStringLiteral("line 120"));
        QCOMPARE(list.item(1, ReviewDashboard::kWarningWhere)->text(), QStringLiteral("layer 3"));
        QCOMPARE(list.item(2, ReviewDashboard::kWarningWhere)->text(), QStringLiteral("—"));
        QSignalSpy requested(&board, &ReviewDashboard::layerRequested);
        emit list.cellDoubleClicked(1, ReviewDashboard::kWarningText);
        QCOMPARE(requested.size(), 1);
        QCOMPARE(requested.front().front().toInt(), 3);
    }

    // A pass whose B wanders by 0.05 deg is refused naming the window's B tolerance, not
    // --b-tolerance-deg; the Job settings' B tolerance runs it, with the batch's warning listed
    // on the Review page with its line.
    void aBNoiseRefusalNamesTheBToleranceAndTheControlRunsIt() {
        const QString job =
            jobFileFor(QStringLiteral("b_noise"),
                       QStringLiteral(BLADEAXIS_TEST_DATA_DIR "/awkward/b_noise_large.nc"));
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        DialogAnswerer answerer;
        QVERIFY(m_window->openJob(job).has_value());
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.back().front().toBool(), false);
        QTRY_VERIFY(!answerer.texts().isEmpty());
        const QString shown = answerer.texts().join(QLatin1Char('\n'));
        QVERIFY2(!shown.contains(QStringLiteral("--b-tolerance-deg")), qPrintable(shown));
        QVERIFY2(shown.contains(QStringLiteral("\"B tolerance\" in the Job settings panel")),
                 qPrintable(shown));

        // The dock, hidden until wanted, is shown with the message that names it.
        bladeaxis::ui::JobSettingsPanel& settings = *m_window->jobSettings();
        QVERIFY(m_window->jobSettingsDock()->isVisibleTo(m_window.get()));
        settings.bToleranceBox()->setValue(0.1);
        QVERIFY(settings.applyButton()->isEnabled());
        settings.applyButton()->click();
        QVERIFY(m_window->isRunning());
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.back().front().toBool(), true);
        QVERIFY(m_window->spec().program.string().find("b_noise_large.nc") != std::string::npos);
        QVERIFY(near(bladeaxis::units::radToDeg(m_window->spec().check.tiltToleranceRad), 0.1));
        // Its warnings, every one, each with the line it names.
        const auto& warnings = m_window->result()->warnings;
        QVERIFY(!warnings.empty());
        QTableWidget& list = *m_window->dashboard()->warnings();
        QCOMPARE(list.rowCount(), static_cast<int>(warnings.size()));
        for (int row = 0; row < list.rowCount(); ++row) {
            QCOMPARE(list.item(row, ReviewDashboard::kWarningText)->text(),
                     bladeaxis::ui::windowWording(
                         QString::fromStdString(warnings[static_cast<std::size_t>(row)])));
        }
        // The B warning names the program (no line): its place is the file.
        QVERIFY(list.findItems(QStringLiteral("b_noise_large.nc"), Qt::MatchExactly).size() == 1);
        QVERIFY(m_window->statusBar()->toolTip().contains(QString::fromStdString(warnings.back())));
        const QString message = m_window->statusBar()->currentMessage();
        QVERIFY2(message.contains(QStringLiteral(" on the Review page")), qPrintable(message));
    }

    // Rotary words in radians read as degrees: the refusal names the Angle unit of the window,
    // and choosing radians there runs the program.
    void aRadiansRefusalNamesTheAngleUnitAndTheControlRunsIt() {
        const QString job =
            jobFileFor(QStringLiteral("radians"),
                       QStringLiteral(BLADEAXIS_TEST_DATA_DIR "/awkward/radians_2rev.nc"));
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        DialogAnswerer answerer;
        QVERIFY(m_window->openJob(job).has_value());
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.back().front().toBool(), false);
        QTRY_VERIFY(!answerer.texts().isEmpty());
        const QString shown = answerer.texts().join(QLatin1Char('\n'));
        QVERIFY2(!shown.contains(QStringLiteral("--angle-unit")), qPrintable(shown));
        QVERIFY2(shown.contains(QStringLiteral("\"radians\" under \"Angle unit\"")),
                 qPrintable(shown));
        QComboBox& unit = *m_window->jobSettings()->angleUnitBox();
        unit.setCurrentIndex(unit.findText(QStringLiteral("radians")));
        m_window->jobSettings()->applyButton()->click();
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.back().front().toBool(), true);
        QVERIFY(m_window->spec().program.string().find("radians_2rev.nc") != std::string::npos);
        QVERIFY(m_window->result()->rescheduled.has_value());
    }

    // The tolerances and the preset stay for the next program opened; the angle unit, a
    // property of one program, starts at "from the file" again.
    void theNextProgramKeepsTheTolerancesButNotTheAngleUnit() {
        bladeaxis::ui::JobSettingsPanel& settings = *m_window->jobSettings();
        QCOMPARE(settings.angleUnitBox()->currentText(), QStringLiteral("radians"));
        settings.bToleranceBox()->setValue(0.05);
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        m_window->runDemo();
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.back().front().toBool(), true);
        QVERIFY(near(bladeaxis::units::radToDeg(m_window->spec().check.tiltToleranceRad), 0.05));
        QVERIFY(!m_window->spec().read.angleUnit.has_value());
        QCOMPARE(settings.angleUnitBox()->currentText(), QStringLiteral("from the file"));
        QVERIFY(!settings.applyButton()->isEnabled());
    }

  private:
    std::unique_ptr<bladeaxis::ui::MainWindow> m_window;
    nlohmann::json m_batch;
};

QTEST_MAIN(ReviewDeskTest)
#include "review_desk_test.moc"
