// The screenshots of docs/user-guide.md, taken from the real window on the demo job so that they
// never go stale: the whole window, the S-theta editor page, the axis-motion plots and the 3D
// view. They are written to BLADEAXIS_GUI_OUTPUT_DIR/user-guide/ on every run and, with
// BLADEAXIS_UPDATE_SCREENSHOTS=1, over docs/images/ as well. The guide and this test stay in
// step: every images/gui-*.png the guide shows is one this test takes, and the other way round.

#include "tests/gui/image_checks.h"
#include "ui/main_window.h"
#include "ui/toolpath_view.h"

#include <QCoreApplication>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QImage>
#include <QPainter>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>
#include <algorithm>
#include <array>
#include <iterator>
#include <memory>
#include <set>

namespace {

constexpr int kJobTimeoutMs = 240'000;
// A common laptop screen: what a CAM engineer is likely to see, and small enough as a PNG.
constexpr QSize kWindowSize(1366, 768);
// A widget that painted nothing is one or two colours (background, frame); anything drawn with
// antialiased text and curves has far more.
constexpr std::size_t kMinimumColours = 16;

// The screenshots this test takes, by file name; docs/user-guide.md must show exactly these.
constexpr std::array<const char*, 7> kScreenshots = {
    "gui-main-window.png", "gui-review.png",  "gui-s-theta-editor.png", "gui-axis-plots.png",
    "gui-comparison.png",  "gui-3d-view.png", "gui-nc-listing.png"};

QString outputFolder() {
    return QStringLiteral(BLADEAXIS_GUI_OUTPUT_DIR "/user-guide");
}

QString docsImagesFolder() {
    return QStringLiteral(BLADEAXIS_SOURCE_DIR "/docs/images");
}

// Rewriting the committed images is a deliberate act, never a side effect of running the tests.
bool updateCommittedScreenshots() {
    return qEnvironmentVariable("BLADEAXIS_UPDATE_SCREENSHOTS") == QLatin1String("1");
}

// Every images/gui-*.png the guide links, by file name.
std::set<QString> screenshotsReferencedByTheGuide(const QString& guideText) {
    static const QRegularExpression reference(
        QStringLiteral(R"(images/(gui-[A-Za-z0-9_.-]+\.png))"));
    std::set<QString> names;
    for (auto match = reference.globalMatch(guideText); match.hasNext();) {
        names.insert(match.next().captured(1));
    }
    return names;
}

QString joined(const std::set<QString>& names) {
    return QStringList(names.begin(), names.end()).join(QStringLiteral(", "));
}

} // namespace

class UserGuideScreenshotsTest final : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() {
        // The test's own settings, emptied: a dark palette, machine file or tool radius left by
        // an earlier run would otherwise change the pictures.
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        QVERIFY(QDir().mkpath(outputFolder()));
        m_window = std::make_unique<bladeaxis::ui::MainWindow>();
        m_window->resize(kWindowSize);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        QCOMPARE(m_window->size(), kWindowSize);
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        m_window->runDemo();
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.front().front().toBool(), true);
        // A middle layer is an intermediate one (flat at both ends, docs/method.md §3.2), the
        // case the guide explains; the first layer has a free start.
        const int middle = m_window->layerTable()->rowCount() / 2;
        m_window->selectLayer(middle);
        settle();
        QCOMPARE(m_window->selectedLayer(), middle);
    }

    void savesTheWholeWindowAfterTheDemoJob() {
        showTab(QStringLiteral("S-θ editor"));
        saveScreenshot("gui-main-window.png", m_window->grab().toImage());
    }

    // The first page after a job: the batch's figures with their models, warnings, clearance.
    void savesTheReviewPage() {
        QWidget* page = showTab(QStringLiteral("Review"));
        QVERIFY(page != nullptr);
        saveScreenshot("gui-review.png", page->grab().toImage());
    }

    // The compact comparison with its recommendation (the full table folded away).
    void savesTheComparisonPage() {
        QWidget* page = showTab(QStringLiteral("Comparison"));
        QVERIFY(page != nullptr);
        saveScreenshot("gui-comparison.png", page->grab().toImage());
    }

    void savesTheSThetaEditorPageOfAMiddleLayer() {
        QWidget* page = showTab(QStringLiteral("S-θ editor"));
        QVERIFY(page != nullptr);
        saveScreenshot("gui-s-theta-editor.png", page->grab().toImage());
    }

    void savesTheAxisPlotsOfEveryComparedMethod() {
        QWidget* page = showTab(QStringLiteral("Axis motion"));
        QVERIFY(page != nullptr);
        saveScreenshot("gui-axis-plots.png", page->grab().toImage());
    }

    // The page with its tool bar and slider; the slider halfway so the tool is drawn too.
    void savesTheThreeDViewWithTheToolHalfwayAlongThePath() {
        QWidget* page = showTab(QStringLiteral("3D view"));
        QVERIFY(page != nullptr);
        QSlider* slider = m_window->toolSlider();
        QVERIFY(slider->isEnabled());
        slider->setValue(slider->maximum() / 2);
        settle();
        saveScreenshot("gui-3d-view.png", grabWithThreeDFrame(*page, *m_window->view3d()));
    }

    // The listing at a block of the pass, the re-scheduled program's changed words marked.
    void savesTheNcListingAtABlockOfThePass() {
        const auto& result = *m_window->result();
        m_window->selectRecord(result.pass.first + result.pass.count / 2);
        settle();
        saveScreenshot("gui-nc-listing.png", m_window->listingDock()->grab().toImage());
    }

    void theGuideShowsExactlyTheScreenshotsThisTestSaves() {
        QFile guide(QStringLiteral(BLADEAXIS_SOURCE_DIR "/docs/user-guide.md"));
        QVERIFY2(guide.open(QIODevice::ReadOnly), qPrintable(guide.fileName()));
        const std::set<QString> referenced =
            screenshotsReferencedByTheGuide(QString::fromUtf8(guide.readAll()));
        const std::set<QString> taken(kScreenshots.begin(), kScreenshots.end());
        std::set<QString> notTaken, notShown;
        std::ranges::set_difference(referenced, taken, std::inserter(notTaken, notTaken.end()));
        std::ranges::set_difference(taken, referenced, std::inserter(notShown, notShown.end()));
        QVERIFY2(notTaken.empty(),
                 qPrintable("docs/user-guide.md shows images no test takes: " + joined(notTaken)));
        QVERIFY2(notShown.empty(),
                 qPrintable("screenshots docs/user-guide.md does not show: " + joined(notShown)));
        QCOMPARE(m_saved, taken); // every screenshot was taken in this run
    }

  private:
    // Lets the tab switch, layouts and repaints happen before a grab.
    static void settle() {
        QCoreApplication::processEvents();
        QTest::qWait(100);
    }

    // Makes the tab titled `title` current and returns its page (nullptr when there is none).
    QWidget* showTab(const QString& title) {
        for (QTabWidget* tabs : m_window->findChildren<QTabWidget*>()) {
            for (int index = 0; index < tabs->count(); ++index) {
                if (tabs->tabText(index) == title) {
                    tabs->setCurrentIndex(index);
                    settle();
                    return tabs->widget(index);
                }
            }
        }
        return nullptr;
    }

    // The page as grab() renders it, with the 3D view's own frame painted over the view: the
    // frame's background pixels carry alpha 0 in an RGBX image, which the screen ignores but a
    // grab into a pixmap keeps, so a plain grab shows the background as transparent (white in
    // most viewers) with the overlay text unreadable on it.
    static QImage grabWithThreeDFrame(QWidget& page, bladeaxis::ui::ToolpathView& view) {
        QImage image = page.grab().toImage().convertToFormat(QImage::Format_RGB32);
        QPainter painter(&image);
        painter.drawImage(view.mapTo(&page, QPoint(0, 0)),
                          view.renderFrame().convertToFormat(QImage::Format_RGB32));
        return image;
    }

    // Opaque RGB: smaller PNGs, and a part left transparent by mistake shows up black.
    void saveScreenshot(const char* name, const QImage& grabbed) {
        const QImage image = grabbed.convertToFormat(QImage::Format_RGB32);
        const std::size_t colours = bladeaxis::gui_test::distinctColours(image, 2);
        QVERIFY2(colours >= kMinimumColours,
                 qPrintable(QStringLiteral("%1 looks blank: %2 colours").arg(name).arg(colours)));
        const QString fileName = QString::fromLatin1(name);
        QVERIFY(image.save(QDir(outputFolder()).filePath(fileName)));
        if (updateCommittedScreenshots()) {
            QVERIFY(image.save(QDir(docsImagesFolder()).filePath(fileName)));
        }
        m_saved.insert(fileName);
    }

    std::unique_ptr<bladeaxis::ui::MainWindow> m_window;
    std::set<QString> m_saved;
};

QTEST_MAIN(UserGuideScreenshotsTest)
#include "user_guide_screenshots_test.moc"
