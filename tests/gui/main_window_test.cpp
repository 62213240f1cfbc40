// The main window on the demo job: the layer list shows the result's layers, selection is
// published, and a screenshot of the window is not blank.

#include "app/batch/batch_runner.h"
#include "ui/main_window.h"
#include "ui/profile_plots.h"
#include "ui/s_theta_editor.h"
#include "ui/toolpath_view.h"

#include <QImage>
#include <QSignalSpy>
#include <QSlider>
#include <QTableWidget>
#include <QTest>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr int kJobTimeoutMs = 240'000;

// Distinct colours in the image: a blank (unpainted) window has one or two.
std::size_t distinctColours(const QImage& image) {
    std::set<QRgb> colours;
    for (int y = 0; y < image.height(); y += 2) {
        for (int x = 0; x < image.width(); x += 2) {
            colours.insert(image.pixel(x, y));
        }
    }
    return colours.size();
}

std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace

class MainWindowTest final : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() {
        m_window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&m_window));
        QSignalSpy finished(&m_window, &bladeaxis::ui::MainWindow::jobFinished);
        m_window.runDemo();
        QVERIFY(m_window.isRunning());
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.front().front().toBool(), true);
    }

    void layerListShowsEveryLayerOfTheResult() {
        QVERIFY(m_window.result().has_value());
        QVERIFY(m_window.result()->rescheduled.has_value());
        const auto layerCount = m_window.result()->rescheduled->schedule.layers.size();
        QVERIFY(layerCount > 0);
        QCOMPARE(static_cast<std::size_t>(m_window.layerTable()->rowCount()), layerCount);
    }

    void selectingALayerPublishesIt() {
        QSignalSpy selected(&m_window, &bladeaxis::ui::MainWindow::layerSelected);
        const int target = m_window.layerTable()->rowCount() / 2;
        m_window.selectLayer(target);
        QCOMPARE(m_window.selectedLayer(), target);
        QVERIFY(!selected.isEmpty());
        QCOMPARE(selected.back().front().toInt(), target);
    }

    void draggingAKeyPointReSmoothsInsideTheChannelAndUndoes() {
        const auto& layers = m_window.result()->rescheduled->schedule.layers;
        int target = -1;
        for (std::size_t i = 0; i < layers.size() && target < 0; ++i) {
            if (layers[i].polyline.size() >= 3) {
                target = static_cast<int>(i);
            }
        }
        if (target < 0) {
            QSKIP("the demo has no layer with an interior key point");
        }
        m_window.selectLayer(target);
        bladeaxis::ui::SThetaEditor* editor = m_window.editor();
        QVERIFY(editor->layer().has_value());
        const std::vector<double> before = editor->layer()->theta;
        bool moved = false;
        // The hull may be tight on one side: try small drags up and down.
        for (const int dy : {6, -6, 3, -3, 12, -12}) {
            const QPoint start = editor->vertexPosition(1).toPoint();
            QTest::mousePress(editor, Qt::LeftButton, {}, start);
            QTest::mouseMove(editor, start + QPoint(0, dy / 2));
            QTest::mouseMove(editor, start + QPoint(0, dy));
            QTest::mouseRelease(editor, Qt::LeftButton, {}, start + QPoint(0, dy));
            if (editor->layer()->theta != before) {
                moved = true;
                break;
            }
        }
        QVERIFY(moved);
        const auto& edited = *editor->layer();
        const double direction = edited.theta.back() >= edited.theta.front() ? 1.0 : -1.0;
        for (std::size_t i = 0; i < edited.theta.size(); ++i) {
            QVERIFY(edited.theta[i] >= edited.thetaMin[i] - 1e-9);
            QVERIFY(edited.theta[i] <= edited.thetaMax[i] + 1e-9);
            if (i > 0) {
                QVERIFY((edited.theta[i] - edited.theta[i - 1]) * direction >= -1e-9);
            }
        }
        QCOMPARE(editor->undoStack()->count(), 1);
        const std::vector<double> after = edited.theta;
        editor->undoStack()->undo();
        QVERIFY(editor->layer()->theta == before);
        editor->undoStack()->redo();
        QVERIFY(editor->layer()->theta == after);
    }

    void exportedProgramIsByteIdenticalToTheBatchExport() {
        const std::string gui = BLADEAXIS_GUI_OUTPUT_DIR "/gui_demo.nc";
        const std::string batch = BLADEAXIS_GUI_OUTPUT_DIR "/batch_demo.nc";
        std::remove(gui.c_str());
        std::remove(batch.c_str());
        const bladeaxis::Status written = m_window.exportProgram(QString::fromStdString(gui));
        QVERIFY2(written.has_value(), written ? "" : written.error().toString().c_str());
        std::ostringstream out, err;
        const int exitCode = bladeaxis::app::runBatchCommandLine(
            {"bladeaxis", "--batch", "--demo", "--quiet", "-o", batch}, out, err);
        QVERIFY2(exitCode == 0, err.str().c_str());
        const std::string guiBytes = fileBytes(gui);
        QVERIFY(!guiBytes.empty());
        QVERIFY(guiBytes == fileBytes(batch));
    }

    void screenshotOfTheMainWindowIsNotBlank() {
        const QImage image = m_window.grab().toImage();
        QVERIFY(image.save(QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/main_window.png")));
        QVERIFY(distinctColours(image) > 10);
    }

    void beforeAfterPlotsAndDarkPaletteRender() {
        bladeaxis::ui::ProfilePlots* plots = m_window.plots();
        plots->resize(800, 600);
        const QImage light = plots->grab().toImage();
        QVERIFY(light.save(QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/axis_motion.png")));
        QVERIFY(distinctColours(light) > 10);
        m_window.setDarkPalette(true);
        const QImage dark = m_window.grab().toImage();
        QVERIFY(dark.save(QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/main_window_dark.png")));
        QVERIFY(distinctColours(dark) > 10);
        m_window.setDarkPalette(false);
    }

    void threeDViewShowsTheToolpath() {
        bladeaxis::ui::ToolpathView* view = m_window.view3d();
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
        QSlider* slider = m_window.toolSlider();
        QVERIFY(slider->isEnabled());
        slider->setValue(slider->maximum() / 2);
        const QImage withTool = view->renderFrame();
        QVERIFY(withTool.save(QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/view3d_tool.png")));
        QVERIFY(withTool != rotated);
    }

  private:
    bladeaxis::ui::MainWindow m_window;
};

QTEST_MAIN(MainWindowTest)
#include "main_window_test.moc"
