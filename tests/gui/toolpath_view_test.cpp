// The 3D view on the demo job's display scene: the blade and toolpath fill the frame, the
// colourings, view presets, glyph toggles and the layer section each change what is drawn.

#include "core/job/display_scene.h"
#include "core/job/job.h"
#include "tests/gui/image_checks.h"
#include "ui/toolpath_view.h"

#include <QImage>
#include <QTest>

namespace {

using bladeaxis::ui::ToolpathView;

using bladeaxis::gui_test::pixelsNear;
using bladeaxis::gui_test::shareDifferentFrom;

const bladeaxis::job::JobResult& demoResult() {
    static const bladeaxis::job::JobResult result = bladeaxis::gui_test::runDemoJob(false);
    return result;
}

// Pixels that differ between two frames of the same size.
std::size_t changedPixels(const QImage& a, const QImage& b) {
    std::size_t changed = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            changed += a.pixel(x, y) != b.pixel(x, y) ? 1U : 0U;
        }
    }
    return changed;
}

bool save(const QImage& image, const char* name) {
    return image.save(QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/") + QLatin1String(name));
}

} // namespace

class ToolpathViewTest final : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() {
        m_scene = bladeaxis::job::buildDisplayScene(demoResult());
        QVERIFY(!m_scene.empty());
        m_view.resize(800, 600);
        m_view.showScene(m_scene);
    }

    void init() {
        m_view.setColouring(ToolpathView::Colouring::Layer);
        m_view.setOriginalAxesVisible(true);
        m_view.setRescheduledAxesVisible(true);
        m_view.setSelectedLayer(-1);
        m_view.resetView();
    }

    void bladeAndToolpathFillTheFrameAndAreSavedAsPng() {
        const QImage frame = m_view.renderFrame();
        QVERIFY(save(frame, "toolpath_view.png"));
        QVERIFY(QImage(QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/toolpath_view.png")).size() ==
                frame.size());
        const double share = shareDifferentFrom(frame, frame.pixel(frame.width() / 2, 2));
        qInfo("3D view: %.1f %% of the pixels show the blade and the toolpath (%zu triangles, "
              "%zu drawn points)",
              100.0 * share, m_scene.surface.triangles.size(), m_scene.tips.size());
        QVERIFY(share > 0.05);
    }

    void colouringBySpeedDiffersFromColouringByLayer() {
        const QImage byLayer = m_view.renderFrame();
        m_view.setColouring(ToolpathView::Colouring::ASpeed);
        const QImage bySpeed = m_view.renderFrame();
        m_view.setColouring(ToolpathView::Colouring::OriginalASpeed);
        const QImage byOriginalSpeed = m_view.renderFrame();
        QVERIFY(save(bySpeed, "toolpath_view_speed.png"));
        QVERIFY(save(byOriginalSpeed, "toolpath_view_original_speed.png"));
        QVERIFY(changedPixels(byLayer, bySpeed) > 1000);
        QVERIFY(changedPixels(bySpeed, byOriginalSpeed) > 100);
    }

    void viewPresetsChangeTheFrame() {
        std::vector<QImage> frames;
        for (void (ToolpathView::*preset)() :
             {&ToolpathView::viewFront, &ToolpathView::viewTop, &ToolpathView::viewSide,
              &ToolpathView::viewIsometric}) {
            (m_view.*preset)();
            frames.push_back(m_view.renderFrame());
        }
        QVERIFY(save(frames[2], "toolpath_view_side.png"));
        for (std::size_t i = 0; i < frames.size(); ++i) {
            for (std::size_t j = i + 1; j < frames.size(); ++j) {
                QVERIFY2(changedPixels(frames[i], frames[j]) > 5000,
                         qPrintable(QStringLiteral("presets %1 and %2").arg(i).arg(j)));
            }
        }
        // After a rotating drag, reset returns to the isometric frame.
        QTest::mousePress(&m_view, Qt::LeftButton, {}, QPoint(400, 300));
        QTest::mouseMove(&m_view, QPoint(450, 320));
        QTest::mouseRelease(&m_view, Qt::LeftButton, {}, QPoint(450, 320));
        QVERIFY(changedPixels(m_view.renderFrame(), frames[3]) > 5000);
        m_view.resetView();
        QCOMPARE(changedPixels(m_view.renderFrame(), frames[3]), std::size_t{0});
    }

    void togglingEitherGlyphSetChangesTheFrame() {
        const QImage both = m_view.renderFrame();
        m_view.setOriginalAxesVisible(false);
        const QImage rescheduledOnly = m_view.renderFrame();
        m_view.setRescheduledAxesVisible(false);
        const QImage none = m_view.renderFrame();
        m_view.setOriginalAxesVisible(true);
        const QImage originalOnly = m_view.renderFrame();
        QVERIFY(changedPixels(both, rescheduledOnly) > 200);
        QVERIFY(changedPixels(rescheduledOnly, none) > 200);
        QVERIFY(changedPixels(none, originalOnly) > 200);
    }

    void selectedLayerShowsItsSectionInYellow() {
        const QColor yellow(255, 235, 51);
        m_view.setOriginalAxesVisible(false);
        m_view.setRescheduledAxesVisible(false);
        const QImage before = m_view.renderFrame();
        m_view.setSelectedLayer(static_cast<int>(m_scene.layers.size() / 2));
        const QImage selected = m_view.renderFrame();
        QVERIFY(save(selected, "toolpath_view_layer.png"));
        QVERIFY(pixelsNear(selected, yellow, 30) > 200 + pixelsNear(before, yellow, 30));
    }

    void reconstructedBladeRendersWithoutCad() {
        bladeaxis::job::DisplaySceneInput input;
        const auto& result = demoResult();
        input.pass =
            std::span(result.program.path().records).subspan(result.pass.first, result.pass.count);
        input.toolRadius = *result.toolRadius;
        input.schedule = &result.rescheduled->schedule;
        const auto scene = bladeaxis::job::buildDisplayScene(input);
        QCOMPARE(scene.surfaceSource, bladeaxis::job::SurfaceSource::Reconstructed);
        ToolpathView view;
        view.resize(800, 600);
        view.showScene(scene);
        const QImage frame = view.renderFrame();
        QVERIFY(save(frame, "toolpath_view_reconstructed.png"));
        QVERIFY(shareDifferentFrom(frame, frame.pixel(frame.width() / 2, 2)) > 0.05);
    }

  private:
    bladeaxis::job::DisplayScene m_scene;
    ToolpathView m_view;
};

QTEST_MAIN(ToolpathViewTest)
#include "toolpath_view_test.moc"
