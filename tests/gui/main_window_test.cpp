// The main window on the demo job: the layer list shows the result's layers, selection is
// published, key-point and settings edits become undoable job edits that re-run the job, the
// exports equal the batch front end's, and screenshots are not blank.

#include "app/batch/batch_runner.h"
#include "core/base/version.h"
#include "core/io/program.h"
#include "core/job/job_file.h"
#include "tests/gui/image_checks.h"
#include "ui/axis_ticks.h"
#include "ui/comparison_table.h"
#include "ui/layer_settings_panel.h"
#include "ui/main_window.h"
#include "ui/profile_plots.h"
#include "ui/review_dashboard.h"
#include "ui/s_theta_editor.h"
#include "ui/section_view.h"
#include "ui/toolpath_view.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QInputDialog>
#include <QMenu>
#include <QMessageBox>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>
#include <QTimer>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr int kJobTimeoutMs = 240'000;

std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace

class MainWindowTest final : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // settings of the test, not the user's
        m_window = std::make_unique<bladeaxis::ui::MainWindow>();
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        m_window->runDemo();
        QVERIFY(m_window->isRunning());
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.front().front().toBool(), true);
    }

    void layerListShowsEveryLayerOfTheResult() {
        QVERIFY(m_window->result().has_value());
        QVERIFY(m_window->result()->rescheduled.has_value());
        const auto layerCount = m_window->result()->rescheduled->schedule.layers.size();
        QVERIFY(layerCount > 0);
        QCOMPARE(static_cast<std::size_t>(m_window->layerTable()->rowCount()), layerCount);
    }

    void theStatusBarNamesTheControllerModelOfEachCycleTime() {
        const QString message = m_window->statusBar()->currentMessage();
        QVERIFY2(message.contains(QStringLiteral("block-by-block")), qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("look-ahead T2")), qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("(this machine)")), qPrintable(message));
        const auto& result = *m_window->result();
        const QString before = QString::number(result.blockByBlock.time, 'f', 1);
        QVERIFY2(message.contains(before), qPrintable(message));
    }

    void aboutBoxShowsTheVersionAndRevisionOfVersionOutput() {
        auto* about = m_window->findChild<QAction*>(QStringLiteral("aboutAction"));
        QVERIFY(about != nullptr);
        QString shown;
        QTimer::singleShot(200, [&shown] {
            for (QWidget* widget : QApplication::topLevelWidgets()) {
                if (auto* box = qobject_cast<QMessageBox*>(widget); box && box->isVisible()) {
                    shown = box->text();
                    box->accept();
                }
            }
        });
        about->trigger(); // modal: returns once the box is closed
        const auto version = bladeaxis::projectVersion();
        const auto revision = bladeaxis::projectRevision();
        QVERIFY2(shown.contains(QString::fromUtf8(version.data(), qsizetype(version.size()))),
                 qPrintable(shown));
        QVERIFY2(shown.contains(QString::fromUtf8(revision.data(), qsizetype(revision.size()))),
                 qPrintable(shown));
    }

    void selectingALayerPublishesIt() {
        QSignalSpy selected(m_window.get(), &bladeaxis::ui::MainWindow::layerSelected);
        const int target = m_window->layerTable()->rowCount() / 2;
        m_window->selectLayer(target);
        QCOMPARE(m_window->selectedLayer(), target);
        QVERIFY(!selected.isEmpty());
        QCOMPARE(selected.back().front().toInt(), target);
    }

    void layerListShowsReversalsBeforeAndNoneAfter() {
        const QTableWidget* table = m_window->layerTable();
        const int before = headerColumn(table, "Rev. before");
        const int after = headerColumn(table, "Rev. after");
        QVERIFY(before >= 0 && after >= 0);
        int reversalsBefore = 0;
        for (int row = 0; row < table->rowCount(); ++row) {
            reversalsBefore += table->item(row, before)->text().toInt();
            QCOMPARE(table->item(row, after)->text().toInt(), 0);
        }
        QVERIFY(reversalsBefore > 0);
    }

    void layerTableShowsDegreesWherePeopleReadAngles() {
        const QTableWidget* table = m_window->layerTable();
        QStringList headers;
        for (int column = 0; column < table->columnCount(); ++column) {
            headers << table->horizontalHeaderItem(column)->text();
        }
        const QString all = headers.join('|');
        QVERIFY2(!all.contains("mrad") && !all.contains("rad/mm"), qPrintable(all));
        QVERIFY2(all.contains(QString::fromUtf8("Min clearance\n[°]")), qPrintable(all));
        const int clearance = headerColumn(table, "Min clearance");
        const auto& layer = m_window->result()->rescheduled->schedule.layers.front();
        QCOMPARE(table->item(0, clearance)->data(Qt::UserRole).toDouble(),
                 layer.minClearance * 180.0 / 3.14159265358979323846);
    }

    void comparisonRunsWithTheJobAndFillsTheTable() {
        QVERIFY(m_window->result()->comparison.has_value());
        QCOMPARE(static_cast<std::size_t>(m_window->comparisonTable()->rowCount()),
                 m_window->result()->comparison->methods.size());
    }

    void exportedProgramIsByteIdenticalToTheBatchExport() {
        const std::string gui = BLADEAXIS_GUI_OUTPUT_DIR "/gui_demo.nc";
        const std::string batch = BLADEAXIS_GUI_OUTPUT_DIR "/batch_demo.nc";
        std::remove(gui.c_str());
        std::remove(batch.c_str());
        const bladeaxis::Status written = m_window->exportProgram(QString::fromStdString(gui));
        QVERIFY2(written.has_value(), written ? "" : written.error().toString().c_str());
        std::ostringstream out, err;
        const int exitCode = bladeaxis::app::runBatchCommandLine(
            {"bladeaxis", "--batch", "--demo", "--quiet", "-o", batch}, out, err);
        QVERIFY2(exitCode == 0, err.str().c_str());
        const std::string guiBytes = fileBytes(gui);
        QVERIFY(!guiBytes.empty());
        QVERIFY(guiBytes == fileBytes(batch));
        m_unedited = guiBytes;
    }

    void clDataAndReportExport() {
        const QString cl = QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/gui_demo.cl");
        const bladeaxis::Status written = m_window->exportClData(cl);
        QVERIFY2(written.has_value(), written ? "" : written.error().toString().c_str());
        const std::string text = fileBytes(cl.toStdString());
        QVERIFY(text.starts_with("PARTNO"));
        const QString folder = QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/gui_report");
        QDir(folder).removeRecursively();
        const bladeaxis::Status report = m_window->exportReport(folder);
        QVERIFY2(report.has_value(), report ? "" : report.error().toString().c_str());
        for (const char* file : {"report.json", "layers.csv", "axes.csv", "report.html"}) {
            QVERIFY2(QFileInfo::exists(folder + "/" + file), file);
        }
    }

    void draggingAKeyPointEditsTheJobUndoablyAndBatchRerunsIt() {
        const int target = layerWithInteriorKeyPoint();
        if (target < 0) {
            QSKIP("the demo has no layer with an interior key point");
        }
        m_window->selectLayer(target);
        bladeaxis::ui::SThetaEditor* editor = m_window->editor();
        QVERIFY(editor->layer().has_value());
        const std::vector<double> before = editor->layer()->theta;
        QVERIFY(dragFirstInteriorKeyPoint(*editor, before));
        const auto& edited = *editor->layer();
        const double direction = edited.theta.back() >= edited.theta.front() ? 1.0 : -1.0;
        for (std::size_t i = 0; i < edited.theta.size(); ++i) {
            QVERIFY(edited.theta[i] >= edited.thetaMin[i] - 1e-9);
            QVERIFY(edited.theta[i] <= edited.thetaMax[i] + 1e-9);
            if (i > 0) {
                QVERIFY((edited.theta[i] - edited.theta[i - 1]) * direction >= -1e-9);
            }
        }
        QCOMPARE(m_window->undoStack()->count(), 1);
        const std::vector<double> after = edited.theta;
        const std::vector<bladeaxis::Vec2> afterKeys = edited.polyline;

        // The job re-runs with the edit: its program changes, and the batch front end running
        // the saved job writes the same bytes.
        QVERIFY(waitForEdits());
        const auto& layer = m_window->result()->rescheduled->schedule.layers[target];
        QVERIFY(layer.polyline == afterKeys);
        QVERIFY(m_window->plots()->methods().contains(QStringLiteral("edited")));
        // The comparison has the edited program as a row, marked as what Export writes.
        const bladeaxis::ui::ComparisonTable* comparison = m_window->comparisonTable();
        QVERIFY(comparison->exportedRow() >= 0);
        QCOMPARE(comparison->item(comparison->exportedRow(), 0)->text(), QStringLiteral("edited"));
        QVERIFY(m_window->result()->rescheduled->schedule.check.reversals == 0);
        QCOMPARE(m_window->selectedLayer(), target);
        const std::string gui = BLADEAXIS_GUI_OUTPUT_DIR "/gui_edited.nc";
        const std::string batch = BLADEAXIS_GUI_OUTPUT_DIR "/batch_edited.nc";
        const QString jobFile =
            QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/edited_job.bladeaxis.json");
        std::remove(batch.c_str());
        QVERIFY(m_window->exportProgram(QString::fromStdString(gui)).has_value());
        QVERIFY(m_window->saveJob(jobFile).has_value());
        std::ostringstream out, err;
        const int exitCode = bladeaxis::app::runBatchCommandLine(
            {"bladeaxis", "--batch", "--quiet", "--job", jobFile.toStdString(), "-o", batch}, out,
            err);
        QVERIFY2(exitCode == 0, err.str().c_str());
        const std::string guiBytes = fileBytes(gui);
        QVERIFY(guiBytes != m_unedited);
        QVERIFY(guiBytes == fileBytes(batch));
        // Re-read the exported program: every record of the input is there.
        auto machine = bladeaxis::job::loadMachine(m_window->spec());
        QVERIFY(machine.has_value());
        auto reread = bladeaxis::io::loadProgram(gui, *machine);
        QVERIFY2(reread.has_value(), reread ? "" : reread.error().toString().c_str());
        QCOMPARE(reread->path().records.size(), m_window->result()->program.path().records.size());

        // Undo shows the old curve at once and re-runs to the unedited program; redo again.
        m_window->undoStack()->undo();
        QVERIFY(editor->layer()->theta == before);
        QVERIFY(waitForEdits());
        QVERIFY(m_window->spec().layerEdits.empty());
        QVERIFY(m_window->result()->rescheduled->programText == m_unedited);
        QVERIFY(!m_window->plots()->methods().contains(QStringLiteral("edited")));
        QCOMPARE(comparison->item(comparison->exportedRow(), 0)->text(),
                 QStringLiteral("stheta-best"));
        m_window->undoStack()->redo();
        QVERIFY(editor->layer()->theta == after);
        QVERIFY(waitForEdits());
        QVERIFY(m_window->result()->rescheduled->programText == guiBytes);
        m_window->undoStack()->undo();
        QVERIFY(waitForEdits());
    }

    void layerSettingsReScheduleTheLayerAndUndo() {
        const int target = m_window->layerTable()->rowCount() / 2;
        m_window->selectLayer(target);
        const auto loBefore = m_window->result()->rescheduled->schedule.layers[target].lo;
        QDoubleSpinBox* margin = m_window->layerSettings()->marginBox();
        margin->setValue(0.5);
        emit margin->editingFinished();
        QVERIFY(waitForEdits());
        QCOMPARE(m_window->spec().layerEdits.size(), std::size_t{1});
        QVERIFY(m_window->spec().layerEdits.front().marginRad.has_value());
        QVERIFY(m_window->result()->rescheduled->schedule.layers[target].lo != loBefore);
        const int edited = headerColumn(m_window->layerTable(), "Edited");
        QCOMPARE(m_window->layerTable()->item(target, edited)->text(), QStringLiteral("settings"));
        // Each peak that moved with the edit says why: the layer's own edit, or the junction a
        // neighbour shares with it.
        const int peakAfter = headerColumn(m_window->layerTable(), "Peak A acc. after");
        int explained = 0;
        for (int row = 0; row < m_window->layerTable()->rowCount(); ++row) {
            const QString why = m_window->layerTable()->item(row, peakAfter)->toolTip();
            if (why.isEmpty()) {
                continue;
            }
            ++explained;
            if (row == target) {
                QVERIFY2(why.startsWith(QStringLiteral("This layer's edit")), qPrintable(why));
            } else if (std::abs(row - target) == 1) {
                QVERIFY2(why.contains(QStringLiteral("junction")), qPrintable(why));
            }
        }
        QVERIFY(explained > 0);
        m_window->undoStack()->undo();
        QVERIFY(waitForEdits());
        QVERIFY(m_window->spec().layerEdits.empty());
        QVERIFY(m_window->result()->rescheduled->schedule.layers[target].lo == loBefore);
    }

    // A saved job with a program and its blade CAD: the clearance check runs, and the 3D view
    // and the section view show the CAD's surface and sections.
    void jobWithBladeCadShowsTheCadSurface() {
        const QString folder = QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/gui_report");
        QVERIFY(QFileInfo::exists(folder + "/demo_blade.step")); // from clDataAndReportExport
        const QString jobFile = folder + "/cad_job.json";
        std::ofstream(jobFile.toStdString())
            << R"({"schema": "bladeaxis-job/1", "program": "demo_blade.nc", "tool_radius_mm": )"
            << *m_window->result()->toolRadius << R"(, "cad": "demo_blade.step"})";
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        QVERIFY(m_window->openJob(jobFile).has_value());
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.front().front().toBool(), true);
        QVERIFY(m_window->result()->cadCheck.has_value());
        const auto& scene = m_window->view3d()->scene();
        QCOMPARE(scene.surfaceSource, bladeaxis::job::SurfaceSource::Cad);
        QVERIFY(!scene.surface.triangles.empty());
        const int layer = m_window->selectedLayer();
        QVERIFY(layer >= 0);
        QVERIFY(!scene.layers[static_cast<std::size_t>(layer)].section.empty());
        QCOMPARE(m_window->sectionView()->layer(), layer);
        const QImage image = m_window->grab().toImage();
        QVERIFY(image.save(QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/main_window_cad.png")));
    }

    void accelerationIsOnALogScaleAndTheSelectedLayerIsTinted() {
        bladeaxis::ui::ProfilePlots* plots = m_window->plots();
        QVERIFY(plots->accelerationLogScale());
        auto* box = plots->findChild<QCheckBox*>(QStringLiteral("accelerationLogScale"));
        QVERIFY(box != nullptr && box->isChecked());
        const int target = m_window->layerTable()->rowCount() / 2;
        m_window->selectLayer(target);
        const auto span = plots->highlightedSpan();
        QVERIFY(span.has_value());
        QVERIFY(span->first < span->second);
        QVERIFY(span->second <= m_window->result()->rescheduled->profile.times().back() + 1e-9);
        QCOMPARE(plots->highlightedSpanLabel(), QStringLiteral("layer %1").arg(target));
        box->setChecked(false);
        QVERIFY(!plots->accelerationLogScale());
        box->setChecked(true);
    }

    void theSThetaLegendAndARefusalStayOutsideTheData() {
        const int target = layerWithInteriorKeyPoint();
        if (target < 0) {
            QSKIP("the demo has no layer with an interior key point");
        }
        m_window->selectLayer(target);
        bladeaxis::ui::SThetaEditor* editor = m_window->editor();
        QVERIFY(editor->plotArea().top() >= editor->legendHeight());
        const QRectF plotBefore = editor->plotArea();
        // A key point pulled far outside the channel is refused; the whole reason is shown in
        // its own strip above the plot, kept while no message shows, so the plot stays put.
        std::vector<bladeaxis::Vec2> vertices = editor->layer()->polyline;
        vertices[1].y() += 50.0;
        QVERIFY(!editor->applyVertices(vertices));
        QVERIFY(!editor->refusal().isEmpty());
        QCOMPARE(editor->plotArea(), plotBefore);
        // It names the layer as the table does, the key point 1-based and the amount in degrees
        // with two decimals.
        const QString message = editor->message();
        QVERIFY2(message.startsWith(QStringLiteral("Layer %1 refused: ").arg(target)),
                 qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("key point 2")), qPrintable(message)); // moved
        QVERIFY2(!message.contains(QStringLiteral("key point 0")), qPrintable(message));
        QVERIFY2(QRegularExpression(QStringLiteral("\\d+\\.\\d\\d deg")).match(message).hasMatch(),
                 qPrintable(message));
        const QRectF strip = editor->messageRect();
        QVERIFY(!strip.isEmpty());
        QVERIFY(strip.top() >= editor->legendHeight());
        QVERIFY(editor->plotArea().top() >= strip.bottom());
        const QFontMetricsF metrics(editor->font());
        const QRectF needed = metrics.boundingRect(strip, Qt::TextWordWrap, editor->refusal());
        QVERIFY(strip.height() >= needed.height());
        QVERIFY(!editor->readoutAt(editor->plotArea().center()).isEmpty());
        m_window->selectLayer(target == 0 ? 1 : 0); // leaves the refused preview
    }

    void clickingTheSThetaPlotTakesTheFocusFromASettingsBox() {
        m_window->activateWindow(); // focus exists only in the active window
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
        m_window->selectLayer(0);
        QDoubleSpinBox* margin = m_window->layerSettings()->marginBox();
        margin->setFocus();
        QTRY_VERIFY(margin->hasFocus());
        bladeaxis::ui::SThetaEditor* editor = m_window->editor();
        QTest::mouseClick(editor, Qt::LeftButton, {}, editor->plotArea().center().toPoint());
        QTRY_VERIFY(editor->hasFocus()); // so Ctrl+Z reaches the job's undo, not the box
    }

    void everyLayerColumnExplainsItselfInPlainWords() {
        const QTableWidget* table = m_window->layerTable();
        for (int column = 0; column < table->columnCount(); ++column) {
            const QString tip = table->horizontalHeaderItem(column)->toolTip();
            QVERIFY2(!tip.isEmpty(), qPrintable(table->horizontalHeaderItem(column)->text()));
            QVERIFY2(!tip.contains(QChar(0x00A7)), qPrintable(tip)); // no "§" numbers
        }
    }

    void theMachineMenuOffersTheShippedMachinesAndReRunsOnAChoice() {
        QMenu* menu = nullptr;
        for (QMenu* candidate : m_window->findChildren<QMenu*>()) {
            menu = candidate->title() == QStringLiteral("Mac&hine") ? candidate : menu;
        }
        QVERIFY(menu != nullptr);
        // The menu is rebuilt each time it opens, so its actions are looked up every time.
        const auto find = [menu](bool builtIn) -> QAction* {
            emit menu->aboutToShow();
            for (QAction* action : menu->actions()) {
                const bool isBuiltIn = action->isCheckable() && action->data().toString().isEmpty();
                if (builtIn ? isBuiltIn
                            : action->text().contains(QStringLiteral("blade_ab.json"))) {
                    return action;
                }
            }
            return nullptr;
        };
        for (const bool builtIn : {false, true}) {
            QAction* choice = find(builtIn);
            QVERIFY(choice != nullptr);
            QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
            choice->trigger();
            QVERIFY(finished.wait(kJobTimeoutMs));
            QCOMPARE(finished.front().front().toBool(), true);
            QCOMPARE(m_window->result()->machine.sourceFile.empty(), builtIn);
        }
    }

    void roundTicksReadZeroFiftyHundred() {
        const std::vector<double> ticks = bladeaxis::ui::niceTicks(44.0, 266.0, 5);
        QCOMPARE(ticks, (std::vector<double>{50.0, 100.0, 150.0, 200.0, 250.0}));
        QCOMPARE(bladeaxis::ui::niceTicks(-0.3, 0.3, 4), (std::vector<double>{-0.2, 0.0, 0.2}));
    }

    void aNewToolRadiusInTheToolBarReRunsTheJob() {
        QDoubleSpinBox* radius = m_window->toolRadiusBox();
        QVERIFY(m_window->result()->toolRadius.has_value());
        const double used = *m_window->result()->toolRadius;
        const double other = used == 7.5 ? 6.5 : 7.5;
        for (const double value : {other, used}) { // there, and back by the tool bar alone
            QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
            radius->setValue(value);
            emit radius->editingFinished();
            QVERIFY(m_window->isRunning());
            QVERIFY(finished.wait(kJobTimeoutMs));
            QCOMPARE(finished.front().front().toBool(), true);
            QVERIFY(m_window->result()->toolRadius.has_value());
            QCOMPARE(*m_window->result()->toolRadius, value);
        }
    }

    void screenshotOfTheMainWindowIsNotBlank() {
        const QImage image = m_window->grab().toImage();
        QVERIFY(image.save(QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/main_window.png")));
        QVERIFY(bladeaxis::gui_test::distinctColours(image) > 10);
    }

    void beforeAfterPlotsAndDarkPaletteRender() {
        bladeaxis::ui::ProfilePlots* plots = m_window->plots();
        plots->resize(800, 600);
        const QImage light = plots->grab().toImage();
        QVERIFY(light.save(QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/axis_motion.png")));
        QVERIFY(bladeaxis::gui_test::distinctColours(light) > 10);
        m_window->setDarkPalette(true);
        const QImage dark = m_window->grab().toImage();
        QVERIFY(dark.save(QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/main_window_dark.png")));
        QVERIFY(bladeaxis::gui_test::distinctColours(dark) > 10);
        m_window->setDarkPalette(false);
    }

    void threeDViewShowsTheToolpath() {
        bladeaxis::ui::ToolpathView* view = m_window->view3d();
        view->resize(800, 600);
        const QImage image = view->renderFrame();
        QVERIFY(image.save(QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/view3d.png")));
        const QRgb background = image.pixel(0, 0);
        std::size_t covered = 0;
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                covered += image.pixel(x, y) != background ? 1U : 0U;
            }
        }
        const double share =
            static_cast<double>(covered) / static_cast<double>(image.width() * image.height());
        qInfo("3D view: %.1f %% of the pixels show the toolpath", 100.0 * share);
        QVERIFY(share > 0.02);

        // A left drag rotates the camera: the next frame differs.
        QTest::mousePress(view, Qt::LeftButton, {}, QPoint(400, 300));
        QTest::mouseMove(view, QPoint(430, 310));
        QTest::mouseMove(view, QPoint(480, 320));
        QTest::mouseRelease(view, Qt::LeftButton, {}, QPoint(480, 320));
        const QImage rotated = view->renderFrame();
        QVERIFY(rotated != image);

        // Scrubbing shows the tool: the frame changes again.
        QSlider* slider = m_window->toolSlider();
        QVERIFY(slider->isEnabled());
        slider->setValue(slider->maximum() / 2);
        const QImage withTool = view->renderFrame();
        QVERIFY(withTool.save(QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/view3d_tool.png")));
        QVERIFY(withTool != rotated);
    }

    // The demo blade moved 0.3 mm into the tool: the export is refused naming where and pointing
    // to the Review page, which lists every point (layer, point 1-based, line, depth); once the
    // engineer ticks the acknowledgement there, Export writes it, as --force does in batch.
    // Last: it leaves another job in the window.
    void gougingExportIsRefusedWithWhereAndCanBeForced() {
        const QString folder = QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/gui_report");
        QVERIFY(QFileInfo::exists(folder + "/demo_blade.step")); // from clDataAndReportExport
        const QString jobFile = folder + "/gouging_job.json";
        std::ofstream(jobFile.toStdString())
            << R"({"schema": "bladeaxis-job/1", "program": "demo_blade.nc", "tool_radius_mm": 8,)"
            << R"( "cad": "demo_blade.step", "cad_translate_mm": [0, 0, 0.3]})";
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        const bladeaxis::Status opened = m_window->openJob(jobFile);
        QVERIFY2(opened.has_value(), opened ? "" : opened.error().toString().c_str());
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.front().front().toBool(), true);
        const QString output = folder + "/gouging.nc";
        QFile::remove(output);
        const bladeaxis::Status refused = m_window->exportProgram(output);
        QVERIFY(!refused.has_value());
        const std::string message = refused.error().toString();
        QVERIFY2(message.find("demo_blade.nc:") != std::string::npos, message.c_str());
        QVERIFY2(message.find("the input program already gouges there") != std::string::npos,
                 message.c_str());
        QVERIFY(!QFileInfo::exists(output));

        // The window's way: the refusal names the Review page's acknowledgement, not --force,
        // and shows the page, where every point is listed.
        QString shown;
        QTimer closer;
        connect(&closer, &QTimer::timeout, [&] {
            if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
                shown = box->text();
                box->accept();
            }
        });
        closer.start(50);
        m_window->exportProgramTo(output);
        QVERIFY2(shown.contains(QStringLiteral(": gouge ")), qPrintable(shown));
        QVERIFY2(!shown.contains(QStringLiteral("--force")), qPrintable(shown));
        QVERIFY2(shown.contains(QStringLiteral("on the Review tab")), qPrintable(shown));
        QVERIFY(!QFileInfo::exists(output));
        bladeaxis::ui::ReviewDashboard& board = *m_window->dashboard();
        QCOMPARE(m_window->pages()->currentWidget(), static_cast<QWidget*>(&board));
        const auto& issues = m_window->result()->cadCheck->rescheduled->issues;
        QCOMPARE(board.clearanceIssueCount(), static_cast<int>(issues.size()));
        for (int row = 0; row < board.clearanceIssueCount(); ++row) {
            const auto& issue = issues[static_cast<std::size_t>(row)];
            const auto cell = [&](int column) {
                return board.clearanceIssues()->item(row, column)->data(Qt::UserRole).toDouble();
            };
            QCOMPARE(cell(bladeaxis::ui::ReviewDashboard::kIssuePoint),
                     static_cast<double>(issue.record + 1)); // 1-based
            QCOMPARE(cell(bladeaxis::ui::ReviewDashboard::kIssueLine),
                     static_cast<double>(issue.line));
            QCOMPARE(cell(bladeaxis::ui::ReviewDashboard::kIssueDepth), issue.depth);
            QVERIFY(cell(bladeaxis::ui::ReviewDashboard::kIssueLayer) >= 0.0);
        }
        QVERIFY(!board.clearanceAcknowledged());
        QVERIFY(board.acknowledgeBox()->isVisibleTo(m_window.get()));
        board.acknowledgeBox()->click();
        QVERIFY(board.clearanceAcknowledged());
        shown.clear();
        m_window->exportProgramTo(output);
        closer.stop();
        QVERIFY2(shown.isEmpty(), qPrintable(shown));
        QVERIFY(QFileInfo::exists(output));
    }

    void exportIsOfferedOnlyWithAResultAndSuggestsTheInputsName() {
        bladeaxis::ui::MainWindow fresh;
        QVERIFY(!fresh.exportProgramAction()->isEnabled());
        QVERIFY(!fresh.exportClAction()->isEnabled());
        QVERIFY(!fresh.exportReportAction()->isEnabled());
        QVERIFY(fresh.suggestedExportPath().isEmpty());
        QVERIFY(m_window->exportProgramAction()->isEnabled());
        QVERIFY(m_window->exportReportAction()->isEnabled());
        QVERIFY2(m_window->suggestedExportPath().endsWith("demo_blade_rescheduled.nc"),
                 qPrintable(m_window->suggestedExportPath()));
        QVERIFY(m_window->exportFilter().startsWith("G-code ("));
    }

    void aProgramThatDoesNotReadStaysOutOfRecentFiles() {
        const QString missing = QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/no_such_program.nc");
        const auto passBefore = m_window->result()->pass.count;
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        closeMessageBoxesWhileWaiting(); // the error box of the failed job
        m_window->runProgram(missing);
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.front().front().toBool(), false);
        QVERIFY(!QSettings().value("recentFiles").toStringList().contains(missing));
        QCOMPARE(m_window->result()->pass.count, passBefore);
    }

    void cancellingAJobSaysSoAndShowsThePreviousResultAgain() {
        const auto shownBefore = m_window->view3d()->scene().passRecords;
        const std::filesystem::path programBefore = m_window->spec().program;
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        // A long program, so that the job still runs when it is cancelled.
        const std::string longProgram = BLADEAXIS_GUI_OUTPUT_DIR "/long_for_cancel.nc";
        std::ostringstream out, err;
        QCOMPARE(
            bladeaxis::app::runBatchCommandLine({"bladeaxis", "--batch", "--generate", longProgram,
                                                 "--revolutions", "30", "--pitch", "0.5", "-q"},
                                                out, err),
            0);
        m_window->runProgram(QString::fromStdString(longProgram));
        // Cancel once the new program is on screen (the 3D view shows it as soon as it reads).
        QTRY_VERIFY_WITH_TIMEOUT(m_window->view3d()->scene().passRecords != shownBefore ||
                                     !m_window->isRunning(),
                                 kJobTimeoutMs);
        QVERIFY2(m_window->isRunning(), "the job finished before it could be cancelled");
        m_window->cancelJob();
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.front().front().toBool(), false);
        QCOMPARE(m_window->statusBar()->currentMessage(), QStringLiteral("Cancelled"));
        QCOMPARE(m_window->view3d()->scene().passRecords, shownBefore);
        QVERIFY2(m_window->spec().program == programBefore, "exports use the result's job");
    }

    void theTitleNamesTheProgramAndMarksUnsavedEdits() {
        const QString name =
            QFileInfo(QString::fromStdString(m_window->spec().program.string())).fileName();
        QVERIFY2(m_window->windowTitle().startsWith(name + "[*]"),
                 qPrintable(m_window->windowTitle()));
        m_window->undoStack()->resetClean(); // as after an edit not saved in a job file
        QVERIFY(m_window->isWindowModified());
        const QString job = QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/title_job.json");
        QVERIFY(m_window->saveJob(job).has_value());
        QVERIFY(!m_window->isWindowModified());
    }

    void aProgramWithoutItsBallRadiusAsksForItInTheWindow() {
        auto* timer = new QTimer(this);
        connect(timer, &QTimer::timeout, this, [timer] {
            if (auto* dialog = qobject_cast<QInputDialog*>(QApplication::activeModalWidget())) {
                dialog->setDoubleValue(8.0);
                dialog->accept();
                timer->stop();
            }
        });
        timer->start(50);
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        m_window->runProgram(
            QStringLiteral(BLADEAXIS_TEST_DATA_DIR "/programs/naca_weak_3rev_no_radius.nc"));
        QTRY_VERIFY_WITH_TIMEOUT(finished.size() >= 2, kJobTimeoutMs);
        timer->deleteLater();
        QCOMPARE(finished.at(0).front().toBool(), false); // the run that found no radius
        QCOMPARE(finished.at(1).front().toBool(), true);  // and the run with the one given
        QVERIFY(m_window->result()->toolRadius.has_value());
        QCOMPARE(*m_window->result()->toolRadius, 8.0);
        QVERIFY(m_window->windowTitle().startsWith("naca_weak_3rev_no_radius.nc"));
    }

    void aHeidenhainProgramIsExportedAsAHeidenhainProgram() {
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        m_window->runProgram(QStringLiteral(BLADEAXIS_TEST_DATA_DIR "/dialects/naca_weak_3rev.h"));
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.front().front().toBool(), true);
        QCOMPARE(*m_window->result()->toolRadius, 8.0);
        QVERIFY2(m_window->exportFilter().startsWith("Heidenhain programs (*.h)"),
                 qPrintable(m_window->exportFilter()));
        QVERIFY(m_window->suggestedExportPath().endsWith("naca_weak_3rev_rescheduled.h"));
        const QString output = QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/heidenhain_export.h");
        m_window->exportProgramTo(output);
        QFile written(output);
        QVERIFY(written.open(QIODevice::ReadOnly));
        const QByteArray text = written.readAll();
        QVERIFY(text.startsWith("0 BEGIN PGM NACA_WEAK_3REV MM\n"));
        QVERIFY(text.contains("\n9 L M126\n"));
    }

    void aJobShowsWhereItWouldWriteAndWritesNothingUntilExport() {
        const QDir folder(QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/job_outputs"));
        QVERIFY(folder.mkpath("."));
        const QString output = folder.filePath("blade_out.h");
        QFile::remove(output);
        const QString job = folder.filePath("job.json");
        QFile file(job);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QStringLiteral("{\"schema\": \"bladeaxis-job/1\", \"program\": \"%1\", "
                                  "\"output_program\": \"blade_out.h\"}")
                       .arg(BLADEAXIS_TEST_DATA_DIR "/dialects/naca_weak_3rev.h")
                       .toUtf8());
        file.close();
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        QVERIFY(m_window->openJob(job).has_value());
        const QString message = m_window->jobOpenedMessage(job);
        QVERIFY2(message.contains("nothing is written until you export") &&
                     message.contains(output),
                 qPrintable(message));
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.front().front().toBool(), true);
        QCOMPARE(m_window->suggestedExportPath(), output);
        QVERIFY(!QFileInfo::exists(output));
    }

  private:
    static int headerColumn(const QTableWidget* table, const char* prefix) {
        for (int column = 0; column < table->columnCount(); ++column) {
            // Headers are on two lines (name over unit); the prefix is matched on one.
            QString header = table->horizontalHeaderItem(column)->text();
            if (header.replace(QLatin1Char('\n'), QLatin1Char(' '))
                    .startsWith(QLatin1String(prefix))) {
                return column;
            }
        }
        return -1;
    }

    int layerWithInteriorKeyPoint() const {
        const auto& layers = m_window->result()->rescheduled->schedule.layers;
        for (std::size_t i = 0; i < layers.size(); ++i) {
            if (layers[i].polyline.size() >= 3) {
                return static_cast<int>(i);
            }
        }
        return -1;
    }

    // The hull may be tight on one side: small drags up and down until one is accepted.
    static bool dragFirstInteriorKeyPoint(bladeaxis::ui::SThetaEditor& editor,
                                          const std::vector<double>& before) {
        for (const int dy : {6, -6, 3, -3, 12, -12}) {
            const QPoint start = editor.vertexPosition(1).toPoint();
            QTest::mousePress(&editor, Qt::LeftButton, {}, start);
            QTest::mouseMove(&editor, start + QPoint(0, dy / 2));
            QTest::mouseMove(&editor, start + QPoint(0, dy));
            QTest::mouseRelease(&editor, Qt::LeftButton, {}, start + QPoint(0, dy));
            if (editor.layer()->theta != before) {
                return true;
            }
        }
        return false;
    }

    // Accepts any message box that opens in the next seconds (a failed job reports its error
    // in one, modal to the window).
    static void closeMessageBoxesWhileWaiting() {
        auto* timer = new QTimer(qApp);
        QObject::connect(timer, &QTimer::timeout, [] {
            for (QWidget* widget : QApplication::topLevelWidgets()) {
                if (auto* box = qobject_cast<QMessageBox*>(widget); box && box->isVisible()) {
                    box->accept();
                }
            }
        });
        timer->start(50);
        QTimer::singleShot(30'000, timer, &QObject::deleteLater);
    }

    // Waits until the job has re-run with the latest edits.
    bool waitForEdits() {
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        while (m_window->editsPending()) {
            if (!finished.wait(kJobTimeoutMs)) {
                return false;
            }
        }
        return true;
    }

    std::unique_ptr<bladeaxis::ui::MainWindow> m_window;
    std::string m_unedited; // the exported program without edits
};

QTEST_MAIN(MainWindowTest)
#include "main_window_test.moc"
