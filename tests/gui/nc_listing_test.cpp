// Issue 38, the NC listing, read from the window's state: the original and the re-scheduled
// program's text in a dock, the changed words marked and the changed blocks counted; a block
// selected in the listing selects its record in the 3D view, the tool slider and the layer
// table, and a record selected there (or through the window) scrolls the listing to its block
// and highlights it. A listing of a large program stays quick to fill and to paint.

#include "app/batch/batch_runner.h"
#include "ui/main_window.h"
#include "ui/nc_listing.h"
#include "ui/profile_plots.h"
#include "ui/toolpath_view.h"

#include <QDockWidget>
#include <QElapsedTimer>
#include <QLabel>
#include <QListView>
#include <QScrollBar>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QTabBar>
#include <QTest>
#include <algorithm>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr int kJobTimeoutMs = 240'000;

using bladeaxis::ui::NcListing;

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::string line;
    for (const char c : text) {
        if (c == '\n') {
            lines.push_back(line);
            line.clear();
        } else if (c != '\r') {
            line += c;
        }
    }
    if (!line.empty()) {
        lines.push_back(line);
    }
    return lines;
}

// The text of the listing's current (highlighted) line.
QString currentBlockText(const NcListing& listing) {
    return listing.lineString(listing.currentLine());
}

} // namespace

class NcListingTest final : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        m_window = std::make_unique<bladeaxis::ui::MainWindow>();
        m_window->resize(1366, 768);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        m_window->runDemo();
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.front().front().toBool(), true);
        QVERIFY(m_window->result()->rescheduled.has_value());
    }

    // G-code words are matched by their letters (an inserted word is new), APT's numbers by
    // their position.
    void changedWordsAreTheWordsWhoseTextDiffers() {
        using Spans = std::vector<std::pair<int, int>>;
        QCOMPARE(NcListing::changedWordSpans(QStringLiteral("N10 G1 X1.5 Y2 Z3 A10.0 F500"),
                                             QStringLiteral("N10 G1 X1.5 Y2 Z3.1 A12.5 F500")),
                 (Spans{{15, 4}, {20, 5}}));
        QCOMPARE(NcListing::changedWordSpans(QStringLiteral("G1 X1 Y2"),
                                             QStringLiteral("G1 X1 Y2 A7.25")),
                 (Spans{{9, 5}}));
        QCOMPARE(NcListing::changedWordSpans(QStringLiteral("N20 A=DC(10.0) B5"),
                                             QStringLiteral("N20 A=DC(11.0) B5")),
                 (Spans{{4, 10}}));
        QCOMPARE(NcListing::changedWordSpans(QStringLiteral("GOTO/1.0,2.0,3.0"),
                                             QStringLiteral("GOTO/1.0,2.0,3.0,0.1,0.2,0.97")),
                 (Spans{{17, 3}, {21, 3}, {25, 4}}));
        QVERIFY(NcListing::changedWordSpans(QStringLiteral("(ball end R=4 mm)"),
                                            QStringLiteral("(ball end R=4 mm)"))
                    .empty());
    }

    // The dock shows the re-scheduled program; the count is the blocks whose line reads
    // differently, counted here from the job's two texts.
    void theListingShowsTheRescheduledProgramWithItsChangedBlocks() {
        const NcListing& listing = *m_window->listing();
        QVERIFY(m_window->listingDock()->isVisible());
        QCOMPARE(listing.shownProgram(), NcListing::Program::Rescheduled);
        const auto& result = *m_window->result();
        const std::vector<std::string> original = linesOf(result.programText());
        const std::vector<std::string> rescheduled = linesOf(result.rescheduled->programText);
        QCOMPARE(listing.lineCount(), static_cast<int>(rescheduled.size()));
        std::size_t changed = 0;
        for (const auto& record : result.program.path().records) {
            const auto line = static_cast<std::size_t>(record.line) - 1;
            changed += original[line] != rescheduled[line] ? 1 : 0;
        }
        QVERIFY(changed > result.pass.count / 2); // the demo's pass turns anew
        QCOMPARE(listing.changedBlockCount(), changed);
        QVERIFY(listing.changedLabel()->text().contains(QLocale().toString(changed)));
        // A changed block has its A word marked; a header line none.
        const auto& records = result.program.path().records;
        const auto& middle = records[result.pass.first + result.pass.count / 2];
        QVERIFY(listing.lineChanged(middle.line));
        const auto index = static_cast<std::size_t>(middle.line) - 1;
        const auto spans = NcListing::changedWordSpans(QString::fromStdString(original[index]),
                                                       QString::fromStdString(rescheduled[index]));
        QVERIFY(!spans.empty());
        const QString rescheduledLine = QString::fromStdString(rescheduled[index]);
        QVERIFY(std::ranges::any_of(spans, [&](const auto& span) {
            return rescheduledLine.at(span.first) == QLatin1Char('A');
        }));
        QVERIFY(!listing.lineChanged(1));
    }

    // The engineer puts the cursor on a block of the pass: the window, the 3D view, the tool
    // slider and the layer table select its record.
    void aBlockSelectedInTheListingSelectsItsRecordEverywhere() {
        const auto& result = *m_window->result();
        const std::size_t passIndex = result.pass.count / 3;
        const std::size_t record = result.pass.first + passIndex;
        const int line = result.program.path().records[record].line;
        QListView* view = m_window->listing()->view();
        view->setCurrentIndex(view->model()->index(line - 1, 0)); // as a click or the arrow keys
        QCOMPARE(m_window->listing()->currentLine(), line);
        QCOMPARE(m_window->selectedRecord(), std::optional<std::size_t>(record));
        QCOMPARE(m_window->toolSlider()->value(), static_cast<int>(passIndex));
        QVERIFY(m_window->view3d()->toolVisible());
        QVERIFY(
            m_window->view3d()->positionReadout().startsWith(QStringLiteral("line %1 ").arg(line)));
        QCOMPARE(m_window->selectedLayer(), m_window->view3d()->layerOfRecord(passIndex));
        QCOMPARE(m_window->view3d()->selectedLayer(), m_window->selectedLayer());
    }

    // Selected through the window, by a 3D pick or by the slider: the listing scrolls to the
    // record's block and highlights it.
    void aRecordSelectedElsewhereScrollsTheListingToItsBlock() {
        const auto& result = *m_window->result();
        const auto& records = result.program.path().records;
        const NcListing& listing = *m_window->listing();
        const auto expectShown = [&](std::size_t record) {
            QCOMPARE(listing.currentRecord(), std::optional<std::size_t>(record));
            QCOMPARE(listing.currentLine(), records[record].line);
            QVERIFY(listing.isLineVisible(records[record].line));
            QCOMPARE(currentBlockText(listing).toStdString(),
                     linesOf(result.rescheduled->programText)[records[record].line - 1]);
        };
        const std::size_t last = result.pass.first + result.pass.count - 1;
        m_window->selectRecord(last);
        expectShown(last);
        QCOMPARE(m_window->toolSlider()->value(), static_cast<int>(result.pass.count - 1));
        emit m_window->view3d()->pointPicked(10);
        expectShown(result.pass.first + 10);
        m_window->toolSlider()->setValue(static_cast<int>(result.pass.count / 2));
        expectShown(result.pass.first + result.pass.count / 2);
        QCOMPARE(m_window->selectedRecord(),
                 std::optional<std::size_t>(result.pass.first + result.pass.count / 2));
        // A block before the pass (approach) is only in the listing.
        m_window->selectRecord(0);
        expectShown(0);
    }

    // The plots mark the selected record's time on the exported program's time axis, and a
    // click on a plot selects the record at the time clicked.
    void thePlotsMarkTheSelectedRecordAndSelectTheOneClicked() {
        const auto& result = *m_window->result();
        const auto& profile = result.rescheduled->profile;
        const std::size_t sample = profile.sampleRecord.size() / 3;
        const std::size_t passIndex = profile.sampleRecord[sample];
        m_window->selectRecord(result.pass.first + passIndex);
        QVERIFY(m_window->plots()->markedTime().has_value());
        QCOMPARE(*m_window->plots()->markedTime(), profile.timeAt(sample));
        const std::size_t other = profile.sampleRecord.size() / 5;
        emit m_window->plots()->timeClicked(profile.timeAt(other) + 1e-9);
        const std::size_t clicked = result.pass.first + profile.sampleRecord[other];
        QCOMPARE(m_window->selectedRecord(), std::optional<std::size_t>(clicked));
        QCOMPARE(m_window->listing()->currentRecord(), std::optional<std::size_t>(clicked));
        QCOMPARE(m_window->toolSlider()->value(), static_cast<int>(profile.sampleRecord[other]));
    }

    // A layer row shows the layer's first block unless the block shown is one of its own.
    void aLayerRowShowsItsFirstBlock() {
        const auto& result = *m_window->result();
        const auto& layers = result.rescheduled->schedule.layers;
        QVERIFY(layers.size() > 3);
        m_window->selectLayer(1);
        m_window->selectLayer(2); // a change of row, whatever row was selected
        QCOMPARE(m_window->listing()->currentRecord(),
                 std::optional<std::size_t>(result.pass.first + layers[2].first));
        const std::size_t inside = result.pass.first + (layers[1].first + layers[1].last) / 2;
        m_window->selectRecord(inside);
        QCOMPARE(m_window->selectedLayer(), 1);
        QCOMPARE(m_window->listing()->currentRecord(), std::optional<std::size_t>(inside));
    }

    // The original program keeps the selected block; its words are not marked.
    void theToggleShowsTheOriginalAtTheSameRecord() {
        const auto& result = *m_window->result();
        NcListing& listing = *m_window->listing();
        const std::size_t record = result.pass.first + result.pass.count / 4;
        m_window->selectRecord(record);
        listing.programTabs()->setCurrentIndex(0);
        QCOMPARE(listing.shownProgram(), NcListing::Program::Original);
        QCOMPARE(listing.currentRecord(), std::optional<std::size_t>(record));
        QVERIFY(listing.isLineVisible(listing.currentLine()));
        const int line = result.program.path().records[record].line;
        QCOMPARE(currentBlockText(listing).toStdString(),
                 linesOf(result.programText())[static_cast<std::size_t>(line) - 1]);
        QCOMPARE(m_window->selectedRecord(), std::optional<std::size_t>(record)); // unmoved
        listing.programTabs()->setCurrentIndex(1);
        QCOMPARE(listing.shownProgram(), NcListing::Program::Rescheduled);
        QCOMPARE(listing.currentRecord(), std::optional<std::size_t>(record));
    }

    // A million blocks (a large shop program): filled, scrolled to the end and painted within
    // a few seconds on a loaded machine; the rows and their changed words are made for the
    // visible lines only, as they are painted.
    void aLargeListingStaysResponsive() {
        constexpr int kBlocks = 1'000'000;
        NcListing::Source source;
        source.originalText.reserve(kBlocks * 40);
        source.rescheduledText.reserve(kBlocks * 40);
        for (int i = 0; i < kBlocks; ++i) {
            const std::string head = "N" + std::to_string(10 * i) + " G1 X" +
                                     std::to_string(i % 97) + ".125 Y2.5 Z-3.75 A";
            source.originalText += head + std::to_string(i % 360) + ".0 B15.\n";
            source.rescheduledText += head + std::to_string((i + i % 7) % 360) + ".0 B15.\n";
            source.originalLines.push_back(i + 1);
            source.rescheduledLines.push_back(i + 1);
        }
        NcListing listing;
        listing.resize(700, 500);
        listing.show();
        QVERIFY(QTest::qWaitForWindowExposed(&listing));
        QElapsedTimer clock;
        clock.start();
        listing.setSource(std::move(source));
        QCoreApplication::processEvents();
        const qint64 fill = clock.restart();
        listing.selectRecord(kBlocks - 10);
        listing.view()->viewport()->repaint();
        const qint64 paint = clock.elapsed();
        QVERIFY(listing.isLineVisible(kBlocks - 9));
        QCOMPARE(listing.changedBlockCount(),
                 static_cast<std::size_t>(kBlocks - (kBlocks + 6) / 7));
        QVERIFY2(fill < 3000, qPrintable(QStringLiteral("filled in %1 ms").arg(fill)));
        QVERIFY2(paint < 300, qPrintable(QStringLiteral("painted in %1 ms").arg(paint)));
    }

    // CL data: the listing reads the rewritten program back for its records' lines (an APT
    // rewrite may add lines), so each block shown for a record is that record's GOTO. Last: it
    // replaces the window's job.
    void anAptProgramMapsItsRecordsToTheirGotoLines() {
        const std::string program = BLADEAXIS_GUI_OUTPUT_DIR "/listing_blade.apt";
        std::ostringstream out, err;
        QCOMPARE(
            bladeaxis::app::runBatchCommandLine(
                {"bladeaxis", "--batch", "--generate", program, "--format", "apt", "-q"}, out, err),
            0);
        QSignalSpy finished(m_window.get(), &bladeaxis::ui::MainWindow::jobFinished);
        m_window->runProgram(QString::fromStdString(program));
        QVERIFY(finished.wait(kJobTimeoutMs));
        QCOMPARE(finished.front().front().toBool(), true);
        const auto& result = *m_window->result();
        const NcListing& listing = *m_window->listing();
        QCOMPARE(listing.shownProgram(), NcListing::Program::Rescheduled);
        QVERIFY(listing.changedBlockCount() > result.pass.count / 2);
        const std::size_t record = result.pass.first + result.pass.count / 2;
        m_window->selectRecord(record);
        QCOMPARE(listing.currentRecord(), std::optional<std::size_t>(record));
        QVERIFY(currentBlockText(listing).startsWith(QStringLiteral("GOTO")));
        QVERIFY(listing.lineChanged(listing.currentLine()));
        QVERIFY(listing.isLineVisible(listing.currentLine()));
    }

    void cleanupTestCase() { m_window.reset(); }

  private:
    std::unique_ptr<bladeaxis::ui::MainWindow> m_window;
};

QTEST_MAIN(NcListingTest)
#include "nc_listing_test.moc"
