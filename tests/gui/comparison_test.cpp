// The comparison in the GUI on the demo job run through core: the table shows one row per
// method with the numbers of the batch report's own writer (compare.json), the fairness rule's
// settings on hover and Ctrl+C as CSV; the plots draw every method, hide one on request, and
// still draw a job without a comparison.

#include "core/job/job.h"
#include "core/report/compare_report.h"
#include "tests/gui/image_checks.h"
#include "ui/comparison_table.h"
#include "ui/profile_plots.h"

#include <nlohmann/json.hpp>

#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QImage>
#include <QMouseEvent>
#include <QTest>
#include <QToolTip>
#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <string>

namespace {

using bladeaxis::gui_test::distinctColours;
using bladeaxis::gui_test::pixelsNear;
using bladeaxis::ui::ComparisonTable;
using bladeaxis::ui::ProfilePlots;

// Antialiasing blends the line edges: per channel, this close counts as the line colour.
constexpr int kLineTolerance = 8;

// A key the report may leave out (T2 without a time-optimal result): null when absent.
nlohmann::json optionalField(const nlohmann::json& object, const char* key) {
    return object.contains(key) ? object.at(key) : nlohmann::json();
}

bool sameNumber(double expected, double actual) {
    return std::abs(expected - actual) <= 1e-12 * std::max(1.0, std::abs(expected));
}

QImage grabbed(QWidget& widget, const char* file) {
    const QImage image = widget.grab().toImage();
    image.save(QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/") + QLatin1String(file));
    return image;
}

QPalette darkPalette() {
    QPalette palette;
    palette.setColor(QPalette::Window, QColor(45, 45, 48));
    palette.setColor(QPalette::Base, QColor(30, 30, 32));
    palette.setColor(QPalette::Text, QColor(220, 220, 220));
    palette.setColor(QPalette::WindowText, QColor(220, 220, 220));
    return palette;
}

} // namespace

class ComparisonTest final : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() {
        m_result = bladeaxis::gui_test::runDemoJob(true);
        QVERIFY(m_result->comparison.has_value());
        QVERIFY(m_result->rescheduled.has_value());
        QVERIFY(comparison().find("quaternion") != nullptr);
        QVERIFY(comparison().find("optimal-qp") != nullptr);
    }

    void tableShowsOneRowPerMethodWithTheReportsNumbers() {
        ComparisonTable table;
        table.setComparison(comparison());
        const nlohmann::json report = bladeaxis::report::compareJson(comparison());
        const auto& methods = report["methods"];
        QCOMPARE(static_cast<std::size_t>(table.rowCount()), methods.size());
        for (int row = 0; row < table.rowCount(); ++row) {
            const auto& method = methods[static_cast<std::size_t>(row)];
            QCOMPARE(table.item(row, 0)->text().toStdString(), method["method"].get<std::string>());
            for (const char* axis : {"X", "Y", "Z", "A"}) {
                const auto& figures = method["axes"][axis];
                checkCell(table, row, QString(axis) + "_peak_velocity",
                          figures[axis[0] == 'A' ? "peak_velocity_deg_s" : "peak_velocity_mm_s"]);
                checkCell(table, row, QString(axis) + "_peak_acceleration",
                          figures[axis[0] == 'A' ? "peak_acceleration_deg_s2"
                                                 : "peak_acceleration_mm_s2"]);
            }
            const auto& a = method["axes"]["A"];
            checkCell(table, row, "A_velocity_reduction_vs_original",
                      a["velocity_reduction_vs_original"]);
            checkCell(table, row, "A_acceleration_reduction_vs_original",
                      a["acceleration_reduction_vs_original"]);
            checkCell(table, row, "A_velocity_reduction_vs_reference",
                      optionalField(a, "velocity_reduction_vs_best_quaternion_setting"));
            checkCell(table, row, "A_acceleration_reduction_vs_reference",
                      optionalField(a, "acceleration_reduction_vs_best_quaternion_setting"));
            checkCell(table, row, "a_reversals", method["a_reversals"]);
            checkCell(table, row, "t1_s", method["t1_s"]);
            checkCell(table, row, "t1_gain_vs_original", method["t1_gain_vs_original"]);
            checkCell(table, row, "t2_s", optionalField(method, "t2_s"));
            checkCell(table, row, "t2_gain_vs_original",
                      optionalField(method, "t2_gain_vs_original"));
            checkCell(table, row, "min_clearance_deg", method["channel"]["min_clearance_deg"]);
            checkCell(table, row, "compute_ms",
                      1000.0 * method["timing"]["compute_s"].get<double>());
        }
    }

    void tableShowsTheGapToTheOptimum() {
        ComparisonTable table;
        table.setComparison(comparison());
        const nlohmann::json report = bladeaxis::report::compareJson(comparison());
        const auto& methods = report["methods"];
        double optimumEnergy = 0.0;
        for (const auto& method : methods) {
            if (method["method"] == "optimal-qp") {
                optimumEnergy = method["channel"]["theta_dd_energy_deg2_mm3"].get<double>();
            }
        }
        QVERIFY(optimumEnergy > 0.0);
        for (int row = 0; row < table.rowCount(); ++row) {
            const double energy =
                methods[static_cast<std::size_t>(row)]["channel"]["theta_dd_energy_deg2_mm3"]
                    .get<double>();
            checkCell(table, row, "theta_dd_energy_ratio_to_optimal_qp", energy / optimumEnergy);
        }
    }

    void bestValueOfAColumnIsMarked() {
        ComparisonTable table;
        table.setComparison(comparison());
        const nlohmann::json report = bladeaxis::report::compareJson(comparison());
        const auto& methods = report["methods"];
        auto rowOfExtreme = [&](auto valueOf, bool lowest) {
            std::size_t best = 0;
            for (std::size_t i = 1; i < methods.size(); ++i) {
                const double value = valueOf(methods[i]), current = valueOf(methods[best]);
                best = (lowest ? value < current : value > current) ? i : best;
            }
            return static_cast<int>(best);
        };
        const int lowestAcceleration = rowOfExtreme(
            [](const auto& m) {
                return m["axes"]["A"]["peak_acceleration_deg_s2"].template get<double>();
            },
            true);
        const int widestClearance = rowOfExtreme(
            [](const auto& m) { return m["channel"]["min_clearance_deg"].template get<double>(); },
            false);
        const int acceleration = table.columnOf(QStringLiteral("A_peak_acceleration"));
        const int clearance = table.columnOf(QStringLiteral("min_clearance_deg"));
        for (int row = 0; row < table.rowCount(); ++row) {
            QCOMPARE(table.item(row, acceleration)->font().bold(), row == lowestAcceleration);
        }
        QVERIFY(table.item(widestClearance, clearance)->font().bold());
        QVERIFY(!table.item(0, table.columnOf(QStringLiteral("compute_ms")))->font().bold());
    }

    void quaternionRowNamesTheFairnessRulesSettings() {
        ComparisonTable table;
        table.setComparison(comparison());
        int row = 0;
        while (row < table.rowCount() && table.item(row, 0)->text() != "quaternion") {
            ++row;
        }
        QVERIFY(row < table.rowCount());
        const QString tooltip = table.item(row, 0)->toolTip();
        QVERIFY(!comparison().quaternionFairness.empty());
        for (const auto& entry : comparison().quaternionFairness) {
            QVERIFY2(tooltip.contains(QString::fromStdString(entry.setting)), qPrintable(tooltip));
        }
        // Each reduction against the quaternion baseline names the setting it is measured
        // against: the best one for that metric.
        const auto& fairness = comparison().quaternionFairness;
        const auto best = std::find_if(fairness.begin(), fairness.end(), [](const auto& entry) {
            return entry.metric == "A peak acceleration";
        });
        QVERIFY(best != fairness.end());
        const int column = table.columnOf(QStringLiteral("A_acceleration_reduction_vs_reference"));
        QVERIFY(column >= 0);
        QVERIFY(table.item(0, column)->toolTip().contains(QString::fromStdString(best->setting)));
    }

    void ctrlCCopiesTheTableAsCsv() {
        ComparisonTable table;
        table.setComparison(comparison());
        table.show();
        table.resize(1400, 260);
        table.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&table));
        QVERIFY(distinctColours(grabbed(table, "comparison_table.png")) > 10);
        table.setFocus();
        QApplication::clipboard()->clear();
        QTest::keySequence(&table, QKeySequence::Copy);
        const QStringList lines =
            QApplication::clipboard()->text().split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), table.rowCount() + 1);
        QVERIFY(lines[1].startsWith(QStringLiteral("original,")));

        table.setRangeSelected(QTableWidgetSelectionRange(1, 0, 2, 1), true);
        const QStringList selected = table.toCsv().split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(selected.size(), 3); // header and the two selected rows
        QCOMPARE(selected[0].count(QLatin1Char(',')), 1);
    }

    void clearEmptiesTheTable() {
        ComparisonTable table;
        table.setComparison(comparison());
        QVERIFY(table.rowCount() > 0);
        table.clear();
        QCOMPARE(table.rowCount(), 0);
        QCOMPARE(table.columnOf(QStringLiteral("t1_s")), -1);
    }

    void plotsDrawEveryMethodAndHideOne() {
        ProfilePlots plots;
        plots.resize(1000, 700);
        plots.setComparison(comparison());
        // By default the original and the exported program; every method on demand.
        for (const auto& method : comparison().methods) {
            const QString name = QString::fromStdString(method.method);
            QCOMPARE(plots.isMethodVisible(name),
                     name == QStringLiteral("original") || name == QStringLiteral("stheta-best"));
            plots.setMethodVisible(name, true);
        }
        plots.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plots));
        QCOMPARE(static_cast<std::size_t>(plots.methods().size()), comparison().methods.size());
        const QImage all = grabbed(plots, "comparison_plots.png");
        QVERIFY(distinctColours(all) > 10);
        for (const auto& method : comparison().methods) {
            if (method.method != "original") { // the original is drawn in the text colour
                const QColor colour =
                    ProfilePlots::methodColour(QString::fromStdString(method.method), false);
                QVERIFY2(pixelsNear(all, colour, kLineTolerance) > 100, method.method.c_str());
            }
        }

        // Hiding a method through its legend checkbox removes its curves (its legend icon
        // keeps the colour) and rescales.
        const QColor best = ProfilePlots::methodColour(QStringLiteral("stheta-best"), false);
        QCheckBox* box = plots.findChild<QCheckBox*>(QStringLiteral("legend_stheta-best"));
        QVERIFY(box != nullptr);
        box->click();
        QVERIFY(!plots.isMethodVisible(QStringLiteral("stheta-best")));
        const QImage hidden = grabbed(plots, "comparison_plots_hidden.png");
        QVERIFY(hidden != all);
        QVERIFY(pixelsNear(hidden, best, kLineTolerance) * 4 <
                pixelsNear(all, best, kLineTolerance));

        // The hover readout lists the visible methods only, each at the hovered time.
        const QString readout = plots.valuesAt(1.0, ProfilePlots::AVelocity);
        QVERIFY(!readout.contains(QStringLiteral("stheta-best:")));
        QVERIFY2(readout.contains(QStringLiteral("optimal-qp:")), qPrintable(readout));
        QVERIFY(readout.contains(QStringLiteral("deg/s")));

        // The public setter does the same and ticks the box again.
        plots.setMethodVisible(QStringLiteral("stheta-best"), true);
        QVERIFY(box->isChecked());
        QCOMPARE(grabbed(plots, "comparison_plots_shown.png"), all);

        // Hovering a plot marks the time in every plot and shows the readout.
        QWidget* canvas = plots.childAt(plots.width() / 4, plots.height() / 2);
        QVERIFY(canvas != nullptr);
        const QPointF inside(canvas->width() / 4.0, canvas->height() / 2.0);
        QMouseEvent move(QEvent::MouseMove, inside, canvas->mapToGlobal(inside), Qt::NoButton,
                         Qt::NoButton, Qt::NoModifier);
        QApplication::sendEvent(canvas, &move);
        QVERIFY(grabbed(plots, "comparison_plots_hover.png") != all);
        QVERIFY2(QToolTip::text().contains(QStringLiteral("stheta-best:")),
                 qPrintable(QToolTip::text()));
    }

    // On a table-B machine the titles and the log switch name the table B, the head A and the
    // linear axes as the program does; the default is the roles' own letters.
    void plotsNameTheAxesByTheProgramsLetters() {
        ProfilePlots plots;
        QCOMPARE(plots.quantityTitle(ProfilePlots::AVelocity),
                 QStringLiteral("A velocity [deg/s]"));
        auto* box = plots.findChild<QCheckBox*>(QStringLiteral("accelerationLogScale"));
        QVERIFY(box != nullptr);
        QCOMPARE(box->text(), QStringLiteral("log |A acc.|"));
        plots.setAxisLetters({'Y', 'X', 'Z', 'B', 'A'}); // role X Y Z A B -> program letter
        QCOMPARE(plots.quantityTitle(ProfilePlots::APosition), QStringLiteral("B position [deg]"));
        QCOMPARE(plots.quantityTitle(ProfilePlots::XVelocity), QStringLiteral("Y velocity [mm/s]"));
        QCOMPARE(plots.logAccelerationTitle(),
                 QStringLiteral("|B acceleration| [deg/s²], log scale"));
        QCOMPARE(box->text(), QStringLiteral("log |B acc.|"));
    }

    void plotsFitANarrowWindow() {
        ProfilePlots plots;
        plots.setComparison(comparison());
        // Six methods in the legend must not widen the plots: the legend scrolls instead.
        QVERIFY(plots.minimumSizeHint().width() <= 400);
        plots.resize(400, 900);
        plots.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plots));
        QVERIFY(distinctColours(grabbed(plots, "comparison_plots_narrow.png")) > 10);
    }

    void plotsFollowADarkPalette() {
        ProfilePlots plots;
        plots.resize(1000, 700);
        plots.setPalette(darkPalette());
        plots.setComparison(comparison());
        plots.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plots));
        const QImage image = grabbed(plots, "comparison_plots_dark.png");
        QVERIFY(distinctColours(image) > 10);
        const QColor corner = QColor::fromRgb(image.pixel(image.width() - 2, image.height() - 2));
        QVERIFY(corner.lightness() < 128);
        const QColor best = ProfilePlots::methodColour(QStringLiteral("stheta-best"), true);
        QVERIFY(pixelsNear(image, best, kLineTolerance) > 100);
    }

    void plotsWithoutAComparisonShowTheJobsBeforeAndAfter() {
        ProfilePlots plots;
        plots.resize(800, 600);
        plots.setProfiles(m_result->original, m_result->rescheduled->profile);
        plots.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plots));
        QCOMPARE(plots.methods(),
                 QStringList({QStringLiteral("original"), QStringLiteral("re-scheduled")}));
        const QImage image = grabbed(plots, "before_after_plots.png");
        QVERIFY(distinctColours(image) > 10);

        // A curve added by name replaces the one of that name, or joins the others.
        plots.addProfile(QStringLiteral("re-scheduled"), m_result->original);
        QCOMPARE(plots.methods().size(), 2);
        plots.addProfile(QStringLiteral("edited"), m_result->rescheduled->profile);
        QCOMPARE(plots.methods().back(), QStringLiteral("edited"));
        QCOMPARE(plots.methods().size(), 3);
        plots.clear();
        QVERIFY(plots.methods().isEmpty());
    }

  private:
    const bladeaxis::compare::Comparison& comparison() const { return *m_result->comparison; }

    static void checkCell(const ComparisonTable& table, int row, const QString& key,
                          const nlohmann::json& expected) {
        const int column = table.columnOf(key);
        QVERIFY2(column >= 0, qPrintable(key));
        const QVariant value = table.item(row, column)->data(ComparisonTable::kValueRole);
        if (expected.is_null()) { // the report has no figure: neither has the table
            QVERIFY2(!value.isValid(), qPrintable(key));
            return;
        }
        QVERIFY2(value.isValid(), qPrintable(key));
        QVERIFY2(sameNumber(expected.get<double>(), value.toDouble()),
                 qPrintable(QStringLiteral("%1 row %2: report %3, table %4")
                                .arg(key)
                                .arg(row)
                                .arg(expected.get<double>(), 0, 'g', 17)
                                .arg(value.toDouble(), 0, 'g', 17)));
    }

    std::optional<bladeaxis::job::JobResult> m_result;
};

QTEST_MAIN(ComparisonTest)
#include "comparison_test.moc"
