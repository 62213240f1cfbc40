#include "ui/nc_listing.h"

#include "core/io/program.h"

#include <QAbstractListModel>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QListView>
#include <QLocale>
#include <QPainter>
#include <QStyledItemDelegate>
#include <QTabBar>
#include <QVBoxLayout>
#include <algorithm>
#include <map>

namespace bladeaxis::ui {

namespace {

// Behind each changed word, and behind the highlighted line; translucent so that a changed
// word stays marked on the highlighted line and both read in the dark palette too.
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

// The length of the longest line, in characters of a fixed-pitch font (bytes: the words of a
// program are ASCII).
int widestLine(const std::string& text, const std::vector<std::size_t>& starts) {
    std::size_t widest = 0;
    for (std::size_t k = 0; k < starts.size(); ++k) {
        const std::size_t end = k + 1 < starts.size() ? starts[k + 1] : text.size();
        widest = std::max(widest, end - starts[k]);
    }
    return static_cast<int>(std::min<std::size_t>(widest, 4096));
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

// The shown program's lines as rows, made from the bytes when the view asks for them.
class ListingModel final : public QAbstractListModel {
  public:
    ListingModel(const NcListing& owner, QObject* parent)
        : QAbstractListModel(parent), m_owner(owner) {}

    int rowCount(const QModelIndex& parent = {}) const override {
        return parent.isValid() ? 0 : m_rows;
    }

    QVariant data(const QModelIndex& index, int role) const override {
        if (role != Qt::DisplayRole || !index.isValid()) {
            return {};
        }
        return m_owner.lineString(m_owner.shownProgram(), index.row() + 1);
    }

    // The shown program or its text changed: every row is new.
    void reset(int rows) {
        beginResetModel();
        m_rows = rows;
        endResetModel();
    }

  private:
    const NcListing& m_owner;
    int m_rows = 0;
};

// Paints a line: the current line's background, the changed words' (in the re-scheduled
// program), then the text, so that both backgrounds stay under the text.
class ListingDelegate final : public QStyledItemDelegate {
  public:
    ListingDelegate(const NcListing& owner, QObject* parent)
        : QStyledItemDelegate(parent), m_owner(owner) {}

    // Every row is as wide as the longest line (the list scrolls sideways to it).
    void setWidestLine(int characters) { m_widest = characters; }

    QSize sizeHint(const QStyleOptionViewItem& option, const QModelIndex&) const override {
        const QFontMetrics metrics(option.font);
        return {metrics.horizontalAdvance(QLatin1Char('0')) * m_widest + 2 * kMarginPx,
                metrics.height()};
    }

    void paint(QPainter* painter, const QStyleOptionViewItem& option,
               const QModelIndex& index) const override {
        const QString text = index.data().toString();
        const QFontMetricsF metrics(option.font);
        if (index.row() + 1 == m_owner.currentLine()) {
            painter->fillRect(option.rect, kCurrentLine);
        }
        const int line = index.row() + 1;
        if (m_owner.shownProgram() == NcListing::Program::Rescheduled &&
            m_owner.lineChanged(line)) {
            const QString original =
                m_owner.lineString(NcListing::Program::Original,
                                   m_owner.m_originalLineOf[static_cast<std::size_t>(line) - 1]);
            for (const auto& [start, length] : NcListing::changedWordSpans(original, text)) {
                const qreal left =
                    option.rect.left() + kMarginPx + metrics.horizontalAdvance(text.left(start));
                painter->fillRect(QRectF(left, option.rect.top(),
                                         metrics.horizontalAdvance(text.mid(start, length)),
                                         option.rect.height()),
                                  kChangedWord);
            }
        }
        painter->setFont(option.font);
        painter->setPen(option.palette.color(QPalette::Text));
        painter->drawText(option.rect.adjusted(kMarginPx, 0, 0, 0),
                          Qt::AlignLeft | Qt::AlignVCenter | Qt::TextExpandTabs, text);
    }

  private:
    static constexpr int kMarginPx = 4;
    const NcListing& m_owner;
    int m_widest = 80;
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
    m_model = new ListingModel(*this, this);
    m_delegate = new ListingDelegate(*this, this);
    m_view = new QListView(this);
    m_view->setObjectName(QStringLiteral("listingText"));
    m_view->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    // Every row the same height: the view places a million rows without measuring them.
    m_view->setUniformItemSizes(true);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    m_view->setModel(m_model);
    m_view->setItemDelegate(m_delegate);
    auto* top = new QHBoxLayout;
    top->addWidget(m_tabs);
    top->addWidget(m_changedLabel, 1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(top);
    layout->addWidget(m_view, 1);
    connect(m_tabs, &QTabBar::currentChanged, this, [this](int tab) {
        showProgram(tab == kRescheduledTab ? Program::Rescheduled : Program::Original);
    });
    connect(m_view->selectionModel(), &QItemSelectionModel::currentChanged, this,
            &NcListing::onCurrentLineChanged);
    clear();
}

NcListing::~NcListing() = default;

void NcListing::clear() {
    setSource({});
}

void NcListing::setSource(Source source) {
    const std::optional<std::size_t> selected = currentRecord();
    m_selecting = true; // the rows change under the current line: nothing was selected
    m_source = std::move(source);
    m_originalStarts = lineStarts(m_source.originalText);
    m_rescheduledStarts = lineStarts(m_source.rescheduledText);
    countChangedBlocks();
    {
        const QSignalBlocker block(m_tabs); // a disabled current tab is not the engineer's choice
        m_tabs->setTabEnabled(kRescheduledTab, hasRescheduled());
    }
    updateChangedLabel();
    m_selecting = false;
    display(m_preferred, true);
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

QString NcListing::lineString(Program program, int line) const {
    const std::string_view text = lineText(program, line);
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

QString NcListing::lineString(int line) const {
    return lineString(m_shown, line);
}

int NcListing::lineCount() const {
    return m_model->rowCount();
}

const std::vector<int>& NcListing::shownLines() const {
    return m_shown == Program::Original ? m_source.originalLines : m_source.rescheduledLines;
}

void NcListing::showProgram(Program program) {
    m_preferred = program;
    display(program, false);
}

void NcListing::display(Program program, bool newSource) {
    if (program == Program::Rescheduled && !hasRescheduled()) {
        program = Program::Original;
    }
    if (program == m_shown && !newSource) {
        return;
    }
    const std::optional<std::size_t> selected = newSource ? std::nullopt : currentRecord();
    m_shown = program;
    {
        const QSignalBlocker block(m_tabs);
        m_tabs->setCurrentIndex(program == Program::Original ? kOriginalTab : kRescheduledTab);
    }
    const std::string& text =
        program == Program::Original ? m_source.originalText : m_source.rescheduledText;
    const std::vector<std::size_t>& starts =
        program == Program::Original ? m_originalStarts : m_rescheduledStarts;
    m_delegate->setWidestLine(widestLine(text, starts));
    m_selecting = true;
    m_model->reset(text.empty() ? 0 : static_cast<int>(starts.size()));
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
    if (line < 1 || line > lineCount()) {
        return;
    }
    // A line off screen comes to the middle, with its neighbours on both sides; one on screen
    // stays where it is.
    const bool visible = isLineVisible(line);
    const QModelIndex index = m_model->index(line - 1);
    m_selecting = true;
    m_view->setCurrentIndex(index);
    m_view->scrollTo(index, visible ? QAbstractItemView::EnsureVisible
                                    : QAbstractItemView::PositionAtCenter);
    m_selecting = false;
    m_view->viewport()->update();
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
    const QModelIndex current = m_view->currentIndex();
    return current.isValid() ? current.row() + 1 : 0;
}

bool NcListing::isLineVisible(int line) const {
    if (line < 1 || line > lineCount() || !m_view->isVisible()) {
        return false;
    }
    const QRect row = m_view->visualRect(m_model->index(line - 1));
    const QRect area = m_view->viewport()->rect();
    return row.top() >= area.top() && row.bottom() <= area.bottom();
}

void NcListing::onCurrentLineChanged() {
    m_view->viewport()->update(); // the highlighted line moved
    if (m_selecting) {
        return;
    }
    if (const std::optional<std::size_t> record = currentRecord()) {
        emit recordSelected(*record);
    }
}

} // namespace bladeaxis::ui
