#include "ui/nc_listing.h"

#include "core/io/program.h"

#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPaintEvent>
#include <QPainter>
#include <QPlainTextDocumentLayout>
#include <QPlainTextEdit>
#include <QTabBar>
#include <QTextBlock>
#include <QTextDocument>
#include <QTextLayout>
#include <QVBoxLayout>
#include <algorithm>
#include <map>

namespace bladeaxis::ui {

namespace {

// Behind each changed word, and behind the highlighted block; translucent so that a changed
// word stays marked on the highlighted block and both read in the dark palette too.
const QColor kChangedWord(255, 170, 0, 120);
const QColor kCurrentLine(70, 130, 230, 70);

constexpr int kOriginalTab = 0;
constexpr int kRescheduledTab = 1;

bool separatesWords(QChar c) {
    return c.isSpace() || c == QLatin1Char(',') || c == QLatin1Char('/');
}

struct Word {
    QString key; // leading letters (or "#" for none) and occurrence: "X@0", "#@2"
    int start = 0;
    int length = 0;
};

std::vector<Word> wordsOf(const QString& line) {
    std::vector<Word> words;
    std::map<QString, int> seen;
    const auto n = static_cast<int>(line.size());
    for (int i = 0; i < n;) {
        while (i < n && separatesWords(line[i])) {
            ++i;
        }
        const int start = i;
        while (i < n && !separatesWords(line[i])) {
            ++i;
        }
        if (i == start) {
            continue;
        }
        int letters = start;
        while (letters < i && line[letters].isLetter()) {
            ++letters;
        }
        QString key =
            letters > start ? line.mid(start, letters - start).toUpper() : QStringLiteral("#");
        key += QLatin1Char('@') + QString::number(seen[key]++);
        words.push_back({std::move(key), start, i - start});
    }
    return words;
}

// Offsets of the starts of the lines of `text` (line k + 1 starts at starts[k]).
std::vector<std::size_t> lineStarts(const std::string& text) {
    std::vector<std::size_t> starts{0};
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\n' && i + 1 < text.size()) {
            starts.push_back(i + 1);
        }
    }
    return starts;
}

std::string_view lineOf(const std::string& text, const std::vector<std::size_t>& starts, int line) {
    if (line < 1 || static_cast<std::size_t>(line) > starts.size()) {
        return {};
    }
    const std::size_t begin = starts[static_cast<std::size_t>(line) - 1];
    std::size_t end = static_cast<std::size_t>(line) < starts.size()
                          ? starts[static_cast<std::size_t>(line)]
                          : text.size();
    while (end > begin && (text[end - 1] == '\n' || text[end - 1] == '\r')) {
        --end;
    }
    return std::string_view(text).substr(begin, end - begin);
}

// The line of each record of `text` read back as a program of the input's format; empty when
// it does not read (it did when the job verified it).
std::vector<int> recordLinesOf(const std::string& text, const job::JobResult& result) {
    std::vector<int> lines;
    const auto collect = [&lines](std::size_t, std::span<const toolpath::ClRecord> records) {
        for (const toolpath::ClRecord& record : records) {
            lines.push_back(record.line);
        }
        return Status{};
    };
    const auto count = io::streamProgramRecords(text, "re-scheduled", result.program.format(),
                                                result.machine, result.program.options, collect);
    return count ? lines : std::vector<int>{};
}

} // namespace

// The QPlainTextEdit of the listing: paints the highlighted block and, in the re-scheduled
// program, the changed words of the visible blocks only, under the text.
class ListingEdit final : public QPlainTextEdit {
  public:
    ListingEdit(NcListing& owner, QWidget* parent) : QPlainTextEdit(parent), m_owner(owner) {}

  protected:
    void paintEvent(QPaintEvent* event) override {
        {
            QPainter painter(viewport());
            paintUnderText(painter, event->rect());
        }
        QPlainTextEdit::paintEvent(event);
    }

  private:
    // Walks the visible blocks as QPlainTextEdit's own painting does, each block below the
    // one before: the highlighted block and the changed words of each line.
    void paintUnderText(QPainter& painter, const QRect& area) const {
        const bool words = m_owner.shownProgram() == NcListing::Program::Rescheduled;
        const QTextBlock current = textCursor().block();
        QPointF offset = contentOffset();
        for (QTextBlock block = firstVisibleBlock(); block.isValid() && offset.y() <= area.bottom();
             block = block.next()) {
            const QRectF geometry = blockBoundingRect(block).translated(offset);
            offset.ry() += geometry.height();
            if (block == current) {
                painter.fillRect(QRectF(0, geometry.top(), viewport()->width(), geometry.height()),
                                 kCurrentLine);
            }
            if (words) {
                paintChangedWords(painter, block, geometry.topLeft());
            }
        }
    }

    void paintChangedWords(QPainter& painter, const QTextBlock& block, QPointF origin) const {
        const int line = block.blockNumber() + 1;
        if (!m_owner.lineChanged(line)) {
            return;
        }
        const int originalLine = m_owner.m_originalLineOf[static_cast<std::size_t>(line) - 1];
        const std::string_view original =
            m_owner.lineText(NcListing::Program::Original, originalLine);
        const QString originalText =
            QString::fromUtf8(original.data(), static_cast<qsizetype>(original.size()));
        for (const auto& [start, length] :
             NcListing::changedWordSpans(originalText, block.text())) {
            paintSpan(painter, block, origin, start, length);
        }
    }

    static void paintSpan(QPainter& painter, const QTextBlock& block, QPointF origin, int start,
                          int length) {
        const QTextLine textLine = block.layout()->lineForTextPosition(start);
        if (!textLine.isValid()) {
            return;
        }
        const qreal left = textLine.cursorToX(start);
        const qreal right = textLine.cursorToX(start + length);
        painter.fillRect(
            QRectF(left, textLine.y(), right - left, textLine.height()).translated(origin),
            kChangedWord);
    }

    NcListing& m_owner;
};

NcListing::Source NcListing::sourceOf(const job::JobResult& result, std::string originalText) {
    Source source;
    source.originalText = std::move(originalText);
    const auto& records = result.program.path().records;
    source.originalLines.reserve(records.size());
    for (const toolpath::ClRecord& record : records) {
        source.originalLines.push_back(record.line);
    }
    if (!result.rescheduled) {
        return source;
    }
    auto written = result.rescheduled->writtenText();
    if (!written) {
        return source;
    }
    source.rescheduledText = std::move(*written);
    // The G-code rewrite edits words inside their lines and never adds or removes one
    // (core/io/nc/gcode_writer.h), so its records keep their lines; the APT rewrite may add a
    // MULTAX/ON line, so other formats are read back for theirs.
    source.rescheduledLines = result.program.format() == io::ProgramFormat::Gcode
                                  ? source.originalLines
                                  : recordLinesOf(source.rescheduledText, result);
    if (source.rescheduledLines.size() != records.size()) {
        source.rescheduledLines.clear();
        source.rescheduledText.clear();
    }
    return source;
}

std::vector<std::pair<int, int>> NcListing::changedWordSpans(const QString& original,
                                                             const QString& rescheduled) {
    std::map<QString, QStringView> before;
    for (const Word& word : wordsOf(original)) {
        before.emplace(word.key, QStringView(original).mid(word.start, word.length));
    }
    std::vector<std::pair<int, int>> spans;
    for (const Word& word : wordsOf(rescheduled)) {
        const auto it = before.find(word.key);
        if (it == before.end() ||
            it->second != QStringView(rescheduled).mid(word.start, word.length)) {
            spans.emplace_back(word.start, word.length);
        }
    }
    return spans;
}

NcListing::NcListing(QWidget* parent) : QWidget(parent) {
    m_tabs = new QTabBar(this);
    m_tabs->setObjectName(QStringLiteral("listingProgramTabs"));
    m_tabs->addTab(tr("Original"));
    m_tabs->addTab(tr("Re-scheduled"));
    m_tabs->setToolTip(tr("The program as read, or as Export writes it with the changed words "
                          "marked"));
    m_changedLabel = new QLabel(this);
    m_changedLabel->setObjectName(QStringLiteral("listingChangedBlocks"));
    m_edit = new ListingEdit(*this, this);
    m_edit->setObjectName(QStringLiteral("listingText"));
    m_edit->setReadOnly(true);
    // Read-only text keeps a cursor the arrow keys move, block by block.
    m_edit->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
    m_edit->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_edit->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    auto* top = new QHBoxLayout;
    top->addWidget(m_tabs);
    top->addWidget(m_changedLabel, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(top);
    layout->addWidget(m_edit, 1);
    connect(m_tabs, &QTabBar::currentChanged, this, [this](int tab) {
        showProgram(tab == kRescheduledTab ? Program::Rescheduled : Program::Original);
    });
    connect(m_edit, &QPlainTextEdit::cursorPositionChanged, this, &NcListing::onCursorMoved);
    clear();
}

NcListing::~NcListing() = default;

void NcListing::clear() {
    setSource({});
}

void NcListing::setSource(Source source) {
    const std::optional<std::size_t> selected = currentRecord();
    m_selecting = true; // the documents change under the cursor: nothing was selected
    m_source = std::move(source);
    m_originalStarts = lineStarts(m_source.originalText);
    m_rescheduledStarts = lineStarts(m_source.rescheduledText);
    countChangedBlocks();
    m_edit->setDocument(nullptr); // an empty document of its own until a program is shown
    for (QTextDocument*& document : m_documents) {
        delete std::exchange(document, nullptr);
    }
    {
        const QSignalBlocker block(m_tabs); // a disabled current tab is not the engineer's choice
        m_tabs->setTabEnabled(kRescheduledTab, hasRescheduled());
    }
    updateChangedLabel();
    m_selecting = false;
    display(m_preferred);
    if (selected) {
        selectRecord(*selected);
    }
}

void NcListing::countChangedBlocks() {
    m_changedBlocks = 0;
    m_originalLineOf.clear();
    if (!hasRescheduled()) {
        return;
    }
    m_originalLineOf.assign(m_rescheduledStarts.size(), 0);
    const std::size_t records = m_source.originalLines.size();
    for (std::size_t i = 0; i < records; ++i) {
        const int line = m_source.rescheduledLines[i];
        if (line < 1 || static_cast<std::size_t>(line) > m_originalLineOf.size()) {
            continue;
        }
        m_originalLineOf[static_cast<std::size_t>(line) - 1] = m_source.originalLines[i];
        if (lineChanged(line)) {
            ++m_changedBlocks;
        }
    }
}

void NcListing::updateChangedLabel() {
    const QLocale locale;
    m_changedLabel->setText(
        hasRescheduled()
            ? tr("%1 of %2 blocks changed")
                  .arg(locale.toString(static_cast<qulonglong>(m_changedBlocks)),
                       locale.toString(static_cast<qulonglong>(m_source.originalLines.size())))
            : QString());
    m_changedLabel->setToolTip(tr("Blocks whose A, B or X Y Z words the re-scheduling changed; "
                                  "the changed words are marked in the re-scheduled program"));
}

bool NcListing::lineChanged(int line) const {
    if (line < 1 || static_cast<std::size_t>(line) > m_originalLineOf.size()) {
        return false;
    }
    const int original = m_originalLineOf[static_cast<std::size_t>(line) - 1];
    return original > 0 &&
           lineText(Program::Original, original) != lineText(Program::Rescheduled, line);
}

std::string_view NcListing::lineText(Program program, int line) const {
    return program == Program::Original
               ? lineOf(m_source.originalText, m_originalStarts, line)
               : lineOf(m_source.rescheduledText, m_rescheduledStarts, line);
}

const std::vector<int>& NcListing::shownLines() const {
    return m_shown == Program::Original ? m_source.originalLines : m_source.rescheduledLines;
}

QTextDocument* NcListing::documentOf(Program program) {
    QTextDocument*& document = m_documents[program == Program::Original ? 0 : 1];
    if (document == nullptr) {
        document = new QTextDocument(this);
        document->setDocumentLayout(new QPlainTextDocumentLayout(document));
        document->setUndoRedoEnabled(false); // read-only: no undo history of the whole text
        document->setDefaultFont(m_edit->font());
        const std::string& text =
            program == Program::Original ? m_source.originalText : m_source.rescheduledText;
        document->setPlainText(QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size())));
    }
    return document;
}

void NcListing::showProgram(Program program) {
    m_preferred = program;
    display(program);
}

void NcListing::display(Program program) {
    if (program == Program::Rescheduled && !hasRescheduled()) {
        program = Program::Original;
    }
    if (m_edit->document() == m_documents[program == Program::Original ? 0 : 1]) {
        return; // shown already
    }
    const std::optional<std::size_t> selected = currentRecord();
    m_shown = program;
    {
        const QSignalBlocker block(m_tabs);
        m_tabs->setCurrentIndex(program == Program::Original ? kOriginalTab : kRescheduledTab);
    }
    m_selecting = true;
    m_edit->setDocument(documentOf(program));
    m_selecting = false;
    if (selected) {
        selectRecord(*selected);
    }
}

int NcListing::lineOfRecord(std::size_t record) const {
    const std::vector<int>& lines = shownLines();
    return record < lines.size() ? lines[record] : 0;
}

void NcListing::selectRecord(std::size_t record) {
    const int line = lineOfRecord(record);
    if (line < 1 || line > m_edit->document()->blockCount()) {
        return;
    }
    // A block off screen comes to the middle, with its neighbours on both sides; one on
    // screen stays where it is.
    const bool visible = isLineVisible(line);
    m_selecting = true;
    m_edit->setTextCursor(QTextCursor(m_edit->document()->findBlockByNumber(line - 1)));
    if (!visible) {
        m_edit->centerCursor();
    }
    m_selecting = false;
    m_edit->viewport()->update();
}

std::optional<std::size_t> NcListing::currentRecord() const {
    const int line = currentLine();
    const std::vector<int>& lines = shownLines();
    // Records are read in the order of their lines.
    const auto it = std::lower_bound(lines.begin(), lines.end(), line);
    if (line < 1 || it == lines.end() || *it != line) {
        return std::nullopt;
    }
    return static_cast<std::size_t>(it - lines.begin());
}

int NcListing::currentLine() const {
    return m_edit->document()->isEmpty() ? 0 : m_edit->textCursor().blockNumber() + 1;
}

bool NcListing::isLineVisible(int line) const {
    const QTextBlock block = m_edit->document()->findBlockByNumber(line - 1);
    if (!block.isValid() || !m_edit->isVisible()) {
        return false;
    }
    return m_edit->viewport()->rect().contains(m_edit->cursorRect(QTextCursor(block)));
}

QPlainTextEdit* NcListing::editor() const {
    return m_edit;
}

void NcListing::onCursorMoved() {
    m_edit->viewport()->update(); // the highlighted block moved
    if (m_selecting) {
        return;
    }
    if (const std::optional<std::size_t> record = currentRecord()) {
        emit recordSelected(*record);
    }
}

} // namespace bladeaxis::ui
