#include "core/io/table/point_table.h"

#include "core/base/number_io.h"
#include "core/base/tolerances.h"
#include "core/base/units.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

namespace bladeaxis::io::table {

namespace {

constexpr std::array<std::string_view, 6> kRequired{"x", "y", "z", "i", "j", "k"};
constexpr int kMaxErrors = 20;
// Digits for a number whose column writes no fixed decimals ("12", "1e-3").
constexpr int kFreeDecimals = 9;

struct Token {
    std::string_view text;
    std::size_t offset = 0; // in the line
};

struct Line {
    std::string_view text; // without its line end
    std::size_t begin = 0; // offset in the file
    int number = 0;        // 1-based
};

// Calls `visit` for every line of the text (CR LF or LF ends, a last line without one).
template <class Visit>
void forEachLine(std::string_view text, Visit&& visit) {
    std::size_t begin = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
    int number = 0;
    while (begin < text.size()) {
        const std::size_t newline = text.find('\n', begin);
        const std::size_t end = newline == std::string_view::npos ? text.size() : newline;
        std::size_t contentEnd = end;
        if (contentEnd > begin && text[contentEnd - 1] == '\r') {
            --contentEnd;
        }
        if (!visit(Line{text.substr(begin, contentEnd - begin), begin, ++number})) {
            return;
        }
        begin = end + 1;
    }
}

bool isSeparator(char c) {
    return c == ',' || c == ';' || c == ' ' || c == '\t';
}

// Fields separated by commas, semicolons or runs of blanks, trimmed.
std::vector<Token> split(std::string_view line) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) {
            ++i;
        }
        if (i < line.size() && (line[i] == ',' || line[i] == ';')) {
            ++i; // an empty field between two separators is an error for the caller to see
            continue;
        }
        const std::size_t start = i;
        while (i < line.size() && !isSeparator(line[i])) {
            ++i;
        }
        if (i > start) {
            tokens.push_back({line.substr(start, i - start), start});
        }
    }
    return tokens;
}

bool isCommentOrBlank(std::string_view line) {
    const std::size_t first = line.find_first_not_of(" \t");
    return first == std::string_view::npos || line[first] == '#';
}

bool allNumbers(const std::vector<Token>& tokens) {
    return !tokens.empty() && std::all_of(tokens.begin(), tokens.end(), [](const Token& token) {
        return parseNumber(token.text).has_value();
    });
}

std::string lower(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

class TableReader {
  public:
    TableReader(std::string_view text, std::string_view file, const ReadOptions& options)
        : m_text(text), m_file(file), m_options(options) {}

    Result<TableProgram> run();

  private:
    bool readLine(const Line& line);
    std::vector<std::string> optionColumns() const;
    bool setColumns(const std::vector<std::string>& names, const Line& line);
    void readRecord(const std::vector<Token>& tokens, const Line& line);
    void fail(const Line& line, std::size_t column, std::string message) {
        if (static_cast<int>(m_errors.size()) < kMaxErrors) {
            m_errors.push_back(
                Error{ErrorCode::Parse,
                      std::move(message),
                      {std::string(m_file), line.number, static_cast<int>(column) + 1},
                      {}});
        }
    }

    std::string_view m_text;
    std::string_view m_file;
    ReadOptions m_options;
    TableProgram m_program;
    std::vector<Error> m_errors;
    std::optional<std::vector<std::string>> m_columns;
    std::array<std::size_t, 6> m_index{}; // column of x y z i j k
    std::optional<std::size_t> m_feedIndex;
    bool m_reportedMissingFeed = false;
};

bool TableReader::setColumns(const std::vector<std::string>& names, const Line& line) {
    m_columns = names;
    for (std::size_t c = 0; c < kRequired.size(); ++c) {
        const auto found = std::find(names.begin(), names.end(), kRequired[c]);
        if (found == names.end()) {
            fail(line, 0,
                 "the table's columns (" + std::to_string(names.size()) + ") do not include '" +
                     std::string(kRequired[c]) +
                     "': expected x, y, z (tool tip, mm) and i, j, k (tool axis), in any order");
            return false;
        }
        m_index[c] = static_cast<std::size_t>(found - names.begin());
    }
    const auto feed = std::find(names.begin(), names.end(), "f");
    if (feed != names.end()) {
        m_feedIndex = static_cast<std::size_t>(feed - names.begin());
    }
    return true;
}

void TableReader::readRecord(const std::vector<Token>& tokens, const Line& line) {
    if (tokens.size() != m_columns->size()) {
        fail(line, tokens.empty() ? 0 : tokens.front().offset,
             "expected " + std::to_string(m_columns->size()) + " numbers, got " +
                 std::to_string(tokens.size()));
        return;
    }
    std::vector<double> values;
    for (const Token& token : tokens) {
        const auto value = parseNumber(token.text);
        if (!value || !std::isfinite(*value)) {
            fail(line, token.offset,
                 "expected a finite number, got '" + std::string(token.text) + "'");
            return;
        }
        values.push_back(*value);
    }
    toolpath::ClRecord record;
    record.tip = Vec3(values[m_index[0]], values[m_index[1]], values[m_index[2]]);
    const Vec3 axis(values[m_index[3]], values[m_index[4]], values[m_index[5]]);
    if (!(axis.norm() > tol::kZeroVector)) {
        fail(line, tokens[m_index[3]].offset, "the tool axis (i, j, k) has zero length");
        return;
    }
    record.axis = axis.normalized();
    record.line = line.number;
    if (m_feedIndex && values[*m_feedIndex] > 0.0) {
        record.feed = units::perMinuteToPerSecond(values[*m_feedIndex]);
    } else if (m_options.feedMmPerS) {
        record.feed = *m_options.feedMmPerS;
    } else if (!m_reportedMissingFeed) {
        m_reportedMissingFeed = true;
        fail(line, 0,
             "the table states no feed: give --feed (mm/min, job key feed_mm_min) or "
             "add an f column (mm/min)");
        return;
    }
    TableRecordSource source;
    source.lineBegin = line.begin;
    for (std::size_t c = 0; c < 6; ++c) {
        source.begin[c] = static_cast<std::uint32_t>(tokens[m_index[c]].offset);
        source.length[c] = static_cast<std::uint16_t>(tokens[m_index[c]].text.size());
    }
    m_program.path.records.push_back(record);
    m_program.sources.push_back(source);
}

std::vector<std::string> TableReader::optionColumns() const {
    std::vector<std::string> names;
    for (const Token& token : split(*m_options.tableColumns)) {
        names.push_back(lower(token.text));
    }
    return names;
}

bool TableReader::readLine(const Line& line) {
    if (isCommentOrBlank(line.text)) {
        return true;
    }
    const std::vector<Token> tokens = split(line.text);
    if (!m_columns) {
        // --columns names the columns also where the file has a header line: it is how a
        // header this reader does not know ("nx ny nz") is read.
        if (m_options.tableColumns) {
            if (!setColumns(optionColumns(), line)) {
                return false;
            }
            if (!allNumbers(tokens)) {
                m_program.path.warnings.push_back(
                    std::string(m_file) + ":" + std::to_string(line.number) +
                    ": the header line is replaced by --columns " + *m_options.tableColumns);
                return true;
            }
        } else if (!allNumbers(tokens)) {
            std::vector<std::string> names;
            for (const Token& token : tokens) {
                names.push_back(lower(token.text));
            }
            return setColumns(names, line);
        } else if (tokens.size() == 6) {
            setColumns({"x", "y", "z", "i", "j", "k"}, line);
        } else {
            fail(line, 0,
                 "a table without a header line has " + std::to_string(tokens.size()) +
                     " numbers per line: name the columns with --columns (e.g. x,y,z,i,j,k,f) "
                     "or a header line");
            return false;
        }
    }
    readRecord(tokens, line);
    return static_cast<int>(m_errors.size()) < kMaxErrors;
}

Result<TableProgram> TableReader::run() {
    m_program.text = std::string(m_text);
    m_program.path.sourceFile = std::string(m_file);
    m_program.path.format = toolpath::SourceFormat::Table;
    forEachLine(m_text, [this](const Line& line) { return readLine(line); });
    if (!m_errors.empty()) {
        Error first = std::move(m_errors.front());
        first.more.assign(std::make_move_iterator(m_errors.begin() + 1),
                          std::make_move_iterator(m_errors.end()));
        return std::unexpected(first);
    }
    if (m_program.path.records.empty()) {
        return makeError(ErrorCode::Parse, "no data line: expected lines of x y z i j k numbers",
                         {std::string(m_file), 1, 1});
    }
    return std::move(m_program);
}

// Decimals of a written number: "12.500" -> 3; none for "12", "5." and "1e-3".
std::optional<int> fixedDecimals(std::string_view token) {
    const std::size_t dot = token.find('.');
    if (token.find_first_of("eE") != std::string_view::npos || dot == std::string_view::npos ||
        dot + 1 == token.size()) {
        return std::nullopt;
    }
    return static_cast<int>(token.size() - dot - 1);
}

std::string formatLike(std::string_view old, double value) {
    const auto decimals = fixedDecimals(old);
    return decimals ? formatFixed(value, *decimals) : formatTrimmed(value, kFreeDecimals);
}

} // namespace

Result<TableProgram> parsePointTable(std::string_view text, std::string_view fileName,
                                     const ReadOptions& options) {
    return TableReader(text, fileName, options).run();
}

Result<std::string> rewritePointTable(const TableProgram& program,
                                      std::span<const toolpath::ClRecord> records) {
    if (records.size() != program.sources.size()) {
        return makeError(ErrorCode::InvalidArgument,
                         "rewritePointTable: " + std::to_string(records.size()) + " records for " +
                             std::to_string(program.sources.size()) + " table lines");
    }
    std::string out;
    out.reserve(program.text.size() + program.text.size() / 16);
    std::size_t cursor = 0;
    for (std::size_t r = 0; r < records.size(); ++r) {
        const Vec3 axis = records[r].axis.normalized();
        if (!isFinite(records[r].tip) || !isFinite(axis)) {
            return makeError(ErrorCode::InvalidArgument,
                             "rewritePointTable: record " + std::to_string(r) + " is not finite");
        }
        const std::array<double, 6> values{records[r].tip.x(), records[r].tip.y(),
                                           records[r].tip.z(), axis.x(),
                                           axis.y(),           axis.z()};
        const TableRecordSource& source = program.sources[r];
        // Columns may be in any order ("i j k x y z"): copy them in the order they are written.
        std::array<std::size_t, 6> order{0, 1, 2, 3, 4, 5};
        std::sort(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) { return source.begin[a] < source.begin[b]; });
        for (const std::size_t c : order) {
            const std::size_t begin = source.lineBegin + source.begin[c];
            const std::string_view old(program.text.data() + begin, source.length[c]);
            const double oldValue = parseNumber(old).value_or(0.0);
            const std::string text = formatLike(old, values[c]);
            if (text == formatLike(old, oldValue)) {
                continue;
            }
            out.append(program.text, cursor, begin - cursor);
            out.append(text);
            cursor = begin + old.size();
        }
    }
    out.append(program.text, cursor);
    return out;
}

bool looksLikePointTable(std::string_view text) {
    int dataLines = 0;
    int headerLines = 0;
    bool table = true;
    forEachLine(text.substr(0, std::min<std::size_t>(text.size(), 1 << 16)), [&](const Line& line) {
        if (isCommentOrBlank(line.text)) {
            return true;
        }
        const auto tokens = split(line.text);
        if (allNumbers(tokens) && tokens.size() >= 3) {
            ++dataLines;
        } else if (dataLines == 0 && headerLines == 0) {
            ++headerLines;
        } else {
            table = false;
        }
        return table && dataLines < 5;
    });
    return table && dataLines > 0;
}

} // namespace bladeaxis::io::table
