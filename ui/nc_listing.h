#pragma once
// The NC listing of the review desk (issue 38): the program's text, the original or the
// re-scheduled one, with the words the re-scheduling changed marked and the number of changed
// blocks. A block (line) maps to the record it programs through the records' source lines, so
// the listing and the other views select the same point.
//
// Shop programs have up to a million lines: the texts are held once as bytes with the offsets
// of their lines, and a list view asks for the visible lines only; the changed words are found
// and painted for those lines as they are painted. (A QTextDocument of a million lines takes
// seconds and about 560 MB to fill, and a QSyntaxHighlighter formats every block of it.)

#include "core/job/job.h"

#include <QWidget>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

class QLabel;
class QListView;
class QTabBar;

namespace bladeaxis::ui {

class ListingModel;
class ListingDelegate;

class NcListing final : public QWidget {
    Q_OBJECT

  public:
    enum class Program { Original, Rescheduled };

    // What the listing shows: both texts and, per record of the program, its 1-based line in
    // each (records are read in the order of their lines, so both lists ascend).
    struct Source {
        std::string originalText;
        std::string rescheduledText; // empty without a re-scheduling
        std::vector<int> originalLines;
        std::vector<int> rescheduledLines; // empty without a re-scheduling
    };

    // The listing of a job: the input's text as read (the job releases its own copy once it has
    // rewritten the program) and the result's re-scheduled text and record lines.
    static Source sourceOf(const job::JobResult& result, std::string originalText);

    // The spans (start, length, in characters) of the words of `rescheduled` that differ from
    // `original`'s: a word is a run between blanks, commas and slashes; words starting with
    // letters are matched by their letters ("X", "A" of "A=DC(..)") and their occurrence, the
    // others (APT's numbers) by their position among them.
    static std::vector<std::pair<int, int>> changedWordSpans(const QString& original,
                                                             const QString& rescheduled);

    explicit NcListing(QWidget* parent = nullptr);
    ~NcListing() override;

    void setSource(Source source);
    void clear();
    bool hasRescheduled() const { return !m_source.rescheduledLines.empty(); }

    // Shows a program, keeping the selected record selected; the next job's listing shows the
    // same one (the original when the job has no re-scheduled program).
    void showProgram(Program program);
    Program shownProgram() const { return m_shown; }

    // Blocks (records) whose line reads differently in the re-scheduled program.
    std::size_t changedBlockCount() const { return m_changedBlocks; }
    // Whether line `line` (1-based) of the re-scheduled program differs from its original line.
    bool lineChanged(int line) const;

    // Makes record `record`'s line of the shown program current of the shown program, scrolled into
    // view and highlighted, without emitting recordSelected (the caller selected it).
    void selectRecord(std::size_t record);
    // The record of the highlighted line; none when that line programs no record.
    std::optional<std::size_t> currentRecord() const;
    // The highlighted (current) line, 1-based; 0 when none.
    int currentLine() const;
    int lineCount() const;
    // The text of line `line` (1-based) of the shown program.
    QString lineString(int line) const;
    // Whether the whole of line `line` of the shown program is inside the visible area.
    bool isLineVisible(int line) const;
    // The line of record `record` in the shown program; 0 when there is none.
    int lineOfRecord(std::size_t record) const;
    // The list of the shown program's lines, one row per line.
    QListView* view() const { return m_view; }
    QTabBar* programTabs() const { return m_tabs; }
    QLabel* changedLabel() const { return m_changedLabel; }

  signals:
    // The engineer made a line that programs record `record` current (click, arrow keys).
    void recordSelected(std::size_t record);

  private:
    const std::vector<int>& shownLines() const;
    // Shows `program`; `newSource`: its rows are new although it was shown.
    void display(Program program, bool newSource);
    void onCurrentLineChanged();
    void countChangedBlocks();
    void updateChangedLabel();

    Source m_source;
    // Per line of the re-scheduled program (index line - 1): the original line it rewrites, 0
    // when none (a line the rewrite inserted, or a line without a record).
    std::vector<int> m_originalLineOf;
    // Byte offset of each line's start in each text.
    std::vector<std::size_t> m_originalStarts, m_rescheduledStarts;
    std::size_t m_changedBlocks = 0;
    Program m_shown = Program::Original;
    Program m_preferred = Program::Rescheduled; // the engineer's choice of tab
    bool m_selecting = false; // selectRecord is moving the current line: no recordSelected
    QTabBar* m_tabs = nullptr;
    QLabel* m_changedLabel = nullptr;
    QListView* m_view = nullptr;
    ListingModel* m_model = nullptr;
    ListingDelegate* m_delegate = nullptr;

    friend class ListingModel;
    friend class ListingDelegate;
    std::string_view lineText(Program program, int line) const;
    QString lineString(Program program, int line) const;
};

} // namespace bladeaxis::ui
