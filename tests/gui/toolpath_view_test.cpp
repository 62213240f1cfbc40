// The 3D view on the demo job's display scene: the blade and toolpath fill the frame, the
// colourings, view presets, glyph toggles and the layer section each change what is drawn; the
// view stays readable (re-scheduled axes only, thinned, a legend for every colour, the selected
// layer in a colour of its own), reads out where the tool is and picks a clicked point; and in
// the main window at 1366x768 every action of its tool bar can be reached.

#include "core/job/display_scene.h"
#include "core/job/job.h"
#include "tests/gui/image_checks.h"
#include "ui/main_window.h"
#include "ui/toolpath_view.h"

#include <QAction>
#include <QCoreApplication>
#include <QImage>
#include <QLabel>
#include <QMenu>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTest>
#include <QToolBar>
#include <QToolButton>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <set>

namespace {

using bladeaxis::ui::ToolpathView;

using bladeaxis::gui_test::pixelsNear;
using bladeaxis::gui_test::shareDifferentFrom;

constexpr int kJobTimeoutMs = 240'000;
// Drawn unlit, so their pixels carry exactly these colours (antialiasing aside).
const QColor kOriginalAxisColour(255, 153, 51);
const QColor kRescheduledAxisColour(77, 230, 255);

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

// The frame without its legend band: where the blade and the toolpath are drawn.
QImage sceneOf(ToolpathView& view) {
    return view.renderFrame().copy(view.sceneArea());
}

bool containsEntryStartingWith(const QStringList& entries, const QString& start) {
    return std::ranges::any_of(entries,
                               [&](const QString& entry) { return entry.startsWith(start); });
}

// The time of pass record `record` in the re-scheduled motion, as the axis-motion plots show it.
double secondsAt(const bladeaxis::analysis::AxisProfile& profile, std::size_t record) {
    const auto& samples = profile.sampleRecord;
    const auto after = std::upper_bound(samples.begin(), samples.end(), record);
    return profile.timeAt(
        static_cast<std::size_t>(std::max<std::ptrdiff_t>(after - samples.begin() - 1, 0)));
}

// A number of the readout: its typographic minus read as '-'.
double readoutNumber(QString text) {
    return text.replace(QChar(0x2212), QLatin1Char('-')).toDouble();
}

// Makes the main window's tab titled `title` current and returns its page.
QWidget* showTab(bladeaxis::ui::MainWindow& window, const QString& title) {
    for (QTabWidget* tabs : window.findChildren<QTabWidget*>()) {
        for (int index = 0; index < tabs->count(); ++index) {
            if (tabs->tabText(index) == title) {
                tabs->setCurrentIndex(index);
                QCoreApplication::processEvents();
                return tabs->widget(index);
            }
        }
    }
    return nullptr;
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

    // Every test starts from the view as a user first sees it.
    void init() {
        m_view.setColouring(ToolpathView::Colouring::Layer);
        m_view.setOriginalAxesVisible(false);
        m_view.setRescheduledAxesVisible(true);
        m_view.setSurfaceVisible(true);
        m_view.setAxisDensity(ToolpathView::kDefaultMaxAxes);
        m_view.setSelectedLayer(-1);
        m_view.showToolAt(std::numeric_limits<std::size_t>::max()); // hides the tool
        m_view.resetView();
    }

    void bladeAndToolpathFillTheFrameAndAreSavedAsPng() {
        const QImage frame = m_view.renderFrame();
        QVERIFY(save(frame, "toolpath_view.png"));
        QVERIFY(QImage(QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/toolpath_view.png")).size() ==
                frame.size());
        const QImage scene = frame.copy(m_view.sceneArea()); // without the legend band
        const double share = shareDifferentFrom(scene, scene.pixel(scene.width() / 2, 2));
        qInfo("3D view: %.1f %% of the scene area shows the blade and the toolpath (%zu "
              "triangles, %zu drawn points)",
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
        m_view.setOriginalAxesVisible(true);
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

    void byDefaultOnlyRescheduledAxesAreDrawnAndAtMostTheDensityOfThem() {
        ToolpathView view;
        view.resize(800, 600);
        view.showScene(m_scene);
        QVERIFY(!view.originalAxesVisible());
        QVERIFY(view.rescheduledAxesVisible());
        QCOMPARE(view.axisDensity(), ToolpathView::kDefaultMaxAxes);
        QCOMPARE(view.axisDensityBox()->value(), ToolpathView::kDefaultMaxAxes);
        const std::size_t drawn = view.drawnAxisCount();
        const auto cap = static_cast<std::size_t>(ToolpathView::kDefaultMaxAxes);
        qInfo("%zu re-scheduled axes drawn, one every %zu of %zu records", drawn, view.axisStride(),
              m_scene.passRecords);
        QVERIFY(drawn > 0);
        QVERIFY(drawn <= cap);
        QCOMPARE(view.axisStride(), (m_scene.passRecords + cap - 1) / cap);
        const QImage scene = sceneOf(view);
        QVERIFY(save(scene, "toolpath_view_default_axes.png"));
        QCOMPARE(pixelsNear(scene, kOriginalAxisColour, 10), std::size_t{0});
        QVERIFY(pixelsNear(scene, kRescheduledAxisColour, 10) > 100);
    }

    void changingTheDensityChangesTheNumberOfAxesDrawn() {
        const std::size_t byDefault = m_view.drawnAxisCount();
        const QImage defaultFrame = m_view.renderFrame();
        m_view.setAxisDensity(100);
        const std::size_t fewer = m_view.drawnAxisCount();
        QVERIFY(fewer > 0 && fewer <= 100);
        QVERIFY(fewer < byDefault);
        QCOMPARE(m_view.axisDensityBox()->value(), 100);
        QVERIFY(changedPixels(defaultFrame, m_view.renderFrame()) > 200);
        // The control in the view's strip does the same.
        m_view.axisDensityBox()->setValue(1000);
        QCOMPARE(m_view.axisDensity(), 1000);
        QVERIFY(m_view.drawnAxisCount() > byDefault);
        QVERIFY(m_view.drawnAxisCount() <= 1000);
        // Both sets are thinned alike.
        m_view.setOriginalAxesVisible(true);
        QCOMPARE(m_view.drawnAxisCount() % 2, std::size_t{0});
        QVERIFY(m_view.drawnAxisCount() <= 2000);
    }

    void legendNamesEveryColourDrawnAndAddsTheOriginalAxesWhenShown() {
        QStringList entries = m_view.legendEntries();
        QVERIFY2(containsEntryStartingWith(entries, "toolpath"), qPrintable(entries.join('|')));
        QVERIFY(containsEntryStartingWith(entries, "re-scheduled tool axes"));
        QVERIFY(containsEntryStartingWith(entries, "blade: "));
        QVERIFY(!containsEntryStartingWith(entries, "original tool axes"));
        QVERIFY(!containsEntryStartingWith(entries, "tool: "));

        m_view.setOriginalAxesVisible(true);
        entries = m_view.legendEntries();
        QVERIFY2(containsEntryStartingWith(entries, "original tool axes"),
                 qPrintable(entries.join('|')));
        QVERIFY(pixelsNear(sceneOf(m_view), kOriginalAxisColour, 10) > 100);

        const auto middle = static_cast<int>(m_scene.layers.size() / 2);
        m_view.setSelectedLayer(middle);
        m_view.showToolAt(m_scene.passRecords / 2);
        entries = m_view.legendEntries();
        QVERIFY2(entries.contains(QStringLiteral("layer %1 (selected)").arg(middle)),
                 qPrintable(entries.join('|')));
        QVERIFY(entries.contains(QStringLiteral("other layers")));
        // The thick yellow line is the section of the blade the layer's S-θ editor works in.
        QVERIFY(containsEntryStartingWith(entries,
                                          QStringLiteral("blade section at layer %1").arg(middle)));
        QVERIFY(containsEntryStartingWith(entries, "tool: ball R"));

        // Every line colour the legend names is drawn (the lit blade and tool are shaded).
        const QImage frame = m_view.renderFrame();
        QVERIFY(save(frame, "toolpath_view_legend.png"));
        const QImage scene = frame.copy(m_view.sceneArea());
        for (const ToolpathView::LegendEntry& entry : m_view.legend()) {
            using Swatch = ToolpathView::LegendEntry::Swatch;
            if (entry.swatch == Swatch::Line || entry.swatch == Swatch::ThickLine) {
                QVERIFY2(pixelsNear(scene, entry.colour, 10) > 20, qPrintable(entry.text));
            }
        }
    }

    void legendDoesNotCoverTheBlade() {
        const QRect area = m_view.sceneArea();
        const QImage frame = m_view.renderFrame();
        QVERIFY(area.width() >= frame.width() / 2);
        // The frame's scene area is fitted to the part: its border rows and columns are empty.
        const QRgb background = frame.pixel(2, 2);
        for (int y = 0; y < frame.height(); ++y) {
            QCOMPARE(frame.pixel(area.right() - 1, y), background);
        }
    }

    void selectingALayerGivesItAColourNoOtherLayerUses() {
        std::set<QRgb> palette;
        for (std::size_t i = 0; i < m_scene.tips.size(); ++i) {
            palette.insert(m_view.pathColourAt(i).rgb());
        }
        const QImage before = sceneOf(m_view);
        const std::size_t target = m_scene.layers.size() / 2;
        m_view.setSelectedLayer(static_cast<int>(target));
        std::set<QRgb> selected, others;
        for (std::size_t i = 0; i < m_scene.tips.size(); ++i) {
            (m_scene.layer[i] == target ? selected : others).insert(m_view.pathColourAt(i).rgb());
        }
        QCOMPARE(selected.size(), std::size_t{1});
        const QRgb highlight = *selected.begin();
        QVERIFY(!others.contains(highlight));
        QVERIFY(!palette.contains(highlight)); // not a colour of the unselected palette either
        const ToolpathView::LegendEntry first = m_view.legend().front();
        QCOMPARE(first.text, QStringLiteral("layer %1 (selected)").arg(target));
        QCOMPARE(first.colour.rgb(), highlight);
        // On screen: the highlight appears only with the selection.
        const QImage after = sceneOf(m_view);
        QVERIFY(save(after, "toolpath_view_selected_layer.png"));
        QCOMPARE(pixelsNear(before, QColor(highlight), 10), std::size_t{0});
        QVERIFY(pixelsNear(after, QColor(highlight), 10) > 100);
    }

    void readoutShowsTheLineTimeAndAOfThePosition() {
        const auto& result = demoResult();
        m_view.setTimeline(result);
        QSignalSpy changed(&m_view, &ToolpathView::positionReadoutChanged);
        const std::size_t record = result.pass.count / 3;
        m_view.showToolAt(record);
        const QString readout = m_view.positionReadout();
        QCOMPARE(changed.count(), 1);
        QCOMPARE(changed.front().front().toString(), readout);
        QCOMPARE(m_view.positionReadout(record), readout);

        static const QRegularExpression format(
            QStringLiteral("^line (\\d+) · t = ([0-9.]+) s · A = ([−0-9.]+)°$"));
        const QRegularExpressionMatch match = format.match(readout);
        QVERIFY2(match.hasMatch(), qPrintable(readout));
        const auto& records = result.program.path().records;
        QCOMPARE(match.captured(1).toInt(), records[result.pass.first + record].line);
        const double seconds = secondsAt(result.rescheduled->profile, record);
        QVERIFY2(std::abs(readoutNumber(match.captured(2)) - seconds) <= 0.005,
                 qPrintable(readout));
        const double aDegrees =
            (*result.rescheduled->axes)[record].a * 180.0 / 3.14159265358979323846;
        QVERIFY2(std::abs(readoutNumber(match.captured(3)) - aDegrees) <= 0.05,
                 qPrintable(readout));

        // Hiding the tool (a new scene) empties it.
        m_view.showScene(m_scene);
        QVERIFY(m_view.positionReadout().isEmpty());
        QCOMPARE(changed.back().front().toString(), QString());
    }

    void clickOnAToolpathPointPicksItsRecord() {
        m_view.viewFront(); // looking along +y: the point of least y is in front of everything
        const QRect area = m_view.sceneArea();
        std::vector<QPointF> shown(m_scene.tips.size());
        for (std::size_t i = 0; i < shown.size(); ++i) {
            shown[i] = *m_view.widgetPositionOf(m_scene.record[i]);
        }
        std::vector<std::size_t> order;
        for (std::size_t i = 0; i < shown.size(); ++i) {
            order.push_back(i);
        }
        std::ranges::sort(order, {}, [&](std::size_t i) { return m_scene.tips[i].y(); });
        // The frontmost point whose neighbours on screen are far enough for the click's
        // rounding to a whole pixel not to matter.
        const auto standsClear = [&](std::size_t i) {
            return area.contains(shown[i].toPoint()) &&
                   std::ranges::none_of(order, [&](std::size_t j) {
                       return j != i && QLineF(shown[i], shown[j]).length() < 4.0;
                   });
        };
        const auto target = std::ranges::find_if(order, standsClear);
        QVERIFY(target != order.end());
        const std::size_t record = m_scene.record[*target];
        const QPoint at = shown[*target].toPoint();

        QSignalSpy picked(&m_view, &ToolpathView::pointPicked);
        QTest::mouseClick(&m_view, Qt::LeftButton, {}, at);
        QCOMPARE(picked.count(), 1);
        QCOMPARE(picked.front().front().value<std::size_t>(), record);

        // A drag from the same point rotates the view and picks nothing.
        QTest::mousePress(&m_view, Qt::LeftButton, {}, at);
        QTest::mouseMove(&m_view, at + QPoint(40, 10));
        QTest::mouseRelease(&m_view, Qt::LeftButton, {}, at + QPoint(40, 10));
        QCOMPARE(picked.count(), 1);
    }

    void colourBarIsInDegreesPerSecond() {
        QVERIFY(m_view.colourBarTitle().isEmpty()); // by layer: no colour bar
        for (const auto colouring :
             {ToolpathView::Colouring::ASpeed, ToolpathView::Colouring::OriginalASpeed}) {
            m_view.setColouring(colouring);
            const QString title = m_view.colourBarTitle();
            QVERIFY2(title.contains("deg/s") && !title.contains("rad"), qPrintable(title));
            QCOMPARE(m_view.legendEntries().front(), title);
        }
    }

    // The main window as a laptop shows it: the 3D view's bar shows every action (or, when it
    // overflows, its » menu holds the rest), and the original axes start hidden there too.
    void everyActionOfTheThreeDToolBarIsReachableAt1366x768() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear(); // no window geometry of an earlier run
        bladeaxis::ui::MainWindow window;
        window.resize(1366, 768);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QWidget* page = showTab(window, QStringLiteral("3D view"));
        QVERIFY(page != nullptr);
        auto* bar = page->findChild<QToolBar*>();
        QVERIFY(bar != nullptr);
        QTRY_VERIFY(bar->isVisible());
        QMenu* overflow = nullptr;
        for (auto* button : bar->findChildren<QToolButton*>()) {
            if (button->objectName() == QLatin1String("qt_toolbar_ext_button") &&
                button->isVisible()) {
                overflow = button->menu();
            }
        }
        qInfo("3D tool bar %d px wide, needs %d px", bar->width(), bar->sizeHint().width());
        for (QAction* action : bar->actions()) {
            if (action->isSeparator()) {
                continue;
            }
            const QWidget* button = bar->widgetForAction(action);
            const bool shown = button != nullptr && button->isVisible();
            const bool inMenu = overflow != nullptr && !overflow->actions().isEmpty() &&
                                overflow->actions().contains(action);
            QVERIFY2(shown || inMenu, qPrintable(action->text()));
            if (action->text() == QLatin1String("&Original axes")) {
                QVERIFY(!action->isChecked());
            }
        }
        QVERIFY(!window.view3d()->originalAxesVisible());
    }

    // In the main window a picked point selects its layer, moves the tool slider there and the
    // readout beside the slider says where it is.
    void pickInTheMainWindowSelectsTheLayerAndMovesTheTool() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        bladeaxis::ui::MainWindow window;
        window.resize(1366, 768);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QSignalSpy finished(&window, &bladeaxis::ui::MainWindow::jobFinished);
        window.runDemo();
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.front().front().toBool(), true);
        QVERIFY(showTab(window, QStringLiteral("3D view")) != nullptr);
        ToolpathView* view = window.view3d();
        const auto& scene = view->scene();
        const std::size_t layer = scene.layers.size() - 2;
        const std::size_t record =
            (scene.layers[layer].firstRecord + scene.layers[layer].lastRecord) / 2;
        emit view->pointPicked(record);
        QCOMPARE(window.selectedLayer(), static_cast<int>(layer));
        QCOMPARE(view->selectedLayer(), static_cast<int>(layer));
        QCOMPARE(window.toolSlider()->value(), static_cast<int>(record));
        QVERIFY(view->toolVisible());
        const QString readout = view->positionReadout();
        QVERIFY(readout.startsWith(QStringLiteral("line ")));
        const auto labels = window.findChildren<QLabel*>();
        QVERIFY(std::ranges::any_of(labels, [&](const QLabel* label) {
            return label->isVisible() && label->text() == readout;
        }));
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
