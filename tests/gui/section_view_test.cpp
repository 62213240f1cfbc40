// The section view on the demo job: the selected layer's blade section, ball-centre path and
// both sets of tool axes are drawn; another layer draws differently; no layer draws nothing.

#include "core/job/display_scene.h"
#include "core/job/job.h"
#include "tests/gui/image_checks.h"
#include "ui/section_view.h"

#include <QImage>
#include <QPalette>
#include <QTest>
#include <set>

namespace {

using bladeaxis::gui_test::distinctColours;
using bladeaxis::gui_test::pixelsNear;

bladeaxis::job::DisplayScene demoScene() {
    return bladeaxis::job::buildDisplayScene(bladeaxis::gui_test::runDemoJob(false));
}

// The section is filled with this colour (section_view.cpp), the axes are orange and blue.
const QColor kSectionFill(200, 205, 215);
const QColor kOriginal(235, 140, 40);
const QColor kRescheduled(30, 160, 220);

} // namespace

class SectionViewTest final : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() {
        m_scene = demoScene();
        QVERIFY(m_scene.layers.size() >= 3);
        m_view.resize(600, 500);
    }

    void withoutALayerTheViewAsksForOne() {
        m_view.clearLayer();
        const QImage image = m_view.grab().toImage();
        QCOMPARE(pixelsNear(image, kSectionFill, 0), std::size_t{0});
    }

    void selectedLayerShowsItsSectionCentresAndBothAxes() {
        const int layer = static_cast<int>(m_scene.layers.size() / 2);
        m_view.setLayer(m_scene, layer);
        QCOMPARE(m_view.layer(), layer);
        const QImage image = m_view.grab().toImage();
        QVERIFY(image.save(QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/section_view.png")));
        QVERIFY(distinctColours(image) > 20);
        const double sectionShare = static_cast<double>(pixelsNear(image, kSectionFill, 0)) /
                                    static_cast<double>(image.width() * image.height());
        qInfo("section view: the blade section fills %.1f %% of the view", 100.0 * sectionShare);
        QVERIFY(sectionShare > 0.02);
        QVERIFY(pixelsNear(image, kOriginal, 0) > 50);
        QVERIFY(pixelsNear(image, kRescheduled, 0) > 50);
    }

    void toolAxesStayInsideThePaneOnEveryLayer() {
        m_view.resize(360, 300); // narrow: long axes would run past the edge
        for (int layer = 0; layer < static_cast<int>(m_scene.layers.size()); ++layer) {
            m_view.setLayer(m_scene, layer);
            const QImage image = m_view.grab().toImage();
            QImage border = image.copy();
            // Only the outermost 3 pixels: nothing of the axes may be drawn there.
            for (int y = 3; y < border.height() - 3; ++y) {
                for (int x = 3; x < border.width() - 3; ++x) {
                    border.setPixelColor(x, y, Qt::black);
                }
            }
            QCOMPARE(pixelsNear(border, kOriginal, 0), std::size_t{0});
            QCOMPARE(pixelsNear(border, kRescheduled, 0), std::size_t{0});
        }
        m_view.resize(600, 500);
    }

    void theDarkPaletteGivesADarkPane() {
        QPalette dark = m_view.palette();
        dark.setColor(QPalette::Base, QColor(30, 30, 34));
        dark.setColor(QPalette::Text, QColor(230, 230, 230));
        m_view.setPalette(dark);
        m_view.setLayer(m_scene, 1);
        const QImage image = m_view.grab().toImage();
        QVERIFY(image.pixelColor(image.width() / 2, image.height() - 2).lightness() < 80);
        m_view.setPalette(QPalette());
    }

    void anotherLayerDrawsDifferently() {
        m_view.setLayer(m_scene, 1);
        const QImage first = m_view.grab().toImage();
        m_view.setLayer(m_scene, static_cast<int>(m_scene.layers.size()) - 2);
        const QImage other = m_view.grab().toImage();
        QVERIFY(first != other);
    }

    void layerOutsideTheSceneClearsTheView() {
        m_view.setLayer(m_scene, static_cast<int>(m_scene.layers.size()));
        QCOMPARE(m_view.layer(), -1);
        QCOMPARE(pixelsNear(m_view.grab().toImage(), kSectionFill, 0), std::size_t{0});
    }

  private:
    bladeaxis::job::DisplayScene m_scene;
    bladeaxis::ui::SectionView m_view;
};

QTEST_MAIN(SectionViewTest)
#include "section_view_test.moc"
