#include "core/io/cl/detail/apt_statement.h"

#include <algorithm>
#include <cctype>

namespace bladeaxis::io::cl::detail {
namespace {

bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

std::string_view trim(std::string_view text, std::size_t& offset) {
    std::size_t begin = 0;
    while (begin < text.size() && isBlank(text[begin])) {
        ++begin;
    }
    std::size_t end = text.size();
    while (end > begin && isBlank(text[end - 1])) {
        --end;
    }
    offset += begin;
    return text.substr(begin, end - begin);
}

// One physical line: [begin, contentEnd) without the line ending, next line at `next`.
struct PhysicalLine {
    std::size_t begin = 0;
    std::size_t pieceEnd = 0; // content end after removing a `$$` comment and a trailing `$`
    std::size_t dollar = 0;   // offset of the continuation `$` when continued
    std::size_t next = 0;
    bool continued = false;
    bool blank = false;
};

PhysicalLine readLine(std::string_view text, std::size_t begin) {
    PhysicalLine line;
    line.begin = begin;
    std::size_t newline = text.find('\n', begin);
    std::size_t end = newline == std::string_view::npos ? text.size() : newline;
    line.next = newline == std::string_view::npos ? text.size() : newline + 1;
    std::string_view content = text.substr(begin, end - begin);
    // `$$` comments run to the end of the line; they may follow a continuation `$`.
    if (std::size_t comment = content.find("$$"); comment != std::string_view::npos) {
        content = content.substr(0, comment);
    }
    while (!content.empty() && isBlank(content.back())) {
        content.remove_suffix(1);
    }
    if (!content.empty() && content.back() == '$') {
        line.continued = true;
        content.remove_suffix(1);
        line.dollar = begin + content.size();
    }
    line.pieceEnd = begin + content.size();
    line.blank = !line.continued && std::all_of(content.begin(), content.end(), isBlank);
    return line;
}

} // namespace

std::size_t Statement::segmentIndex(std::size_t joinedPos) const {
    std::size_t index = 0;
    while (index + 1 < segments.size() && segments[index + 1].joinedBegin <= joinedPos) {
        ++index;
    }
    return index;
}

SourceLocation Statement::locate(std::size_t joinedPos, std::string_view file) const {
    if (segments.empty()) {
        return SourceLocation{std::string(file), 0, 0};
    }
    const Segment& segment = segments[segmentIndex(joinedPos)];
    std::size_t column = segment.textBegin - segment.lineBegin + (joinedPos - segment.joinedBegin);
    return SourceLocation{std::string(file), segment.line, static_cast<int>(column + 1)};
}

std::size_t Statement::textOffset(std::size_t joinedPos) const {
    const Segment& segment = segments[segmentIndex(joinedPos)];
    return segment.textBegin + (joinedPos - segment.joinedBegin);
}

StatementScanner::StatementScanner(std::string_view text, std::size_t begin, int line)
    : m_text(text), m_pos(begin), m_line(line) {}

ScanStatus StatementScanner::next(Statement& out) {
    out.segments.clear();
    out.storage.clear();
    out.body = {};
    PhysicalLine last;
    std::size_t joined = 0;
    while (m_pos < m_text.size()) {
        PhysicalLine line = readLine(m_text, m_pos);
        const int lineNumber = m_line;
        m_pos = line.next;
        ++m_line;
        if (line.blank) {
            continue; // blank and comment-only lines, also inside a continuation
        }
        if (out.segments.empty()) {
            out.textBegin = line.begin;
        }
        // Single-line statements (nearly all) are viewed in place; pieces are copied only
        // once a continuation makes the statement span lines.
        if (out.segments.size() == 1) {
            const Segment& first = out.segments.front();
            out.storage.assign(m_text.substr(first.textBegin, joined));
        }
        const std::size_t piece = line.pieceEnd - line.begin;
        out.segments.push_back(Segment{joined, line.begin, line.begin, lineNumber});
        if (out.segments.size() > 1) {
            out.storage.append(m_text.substr(line.begin, piece));
        }
        joined += piece;
        last = line;
        if (!line.continued) {
            break;
        }
    }
    if (out.segments.empty()) {
        return ScanStatus::End;
    }
    if (last.continued) {
        m_errorLine = out.segments.back().line;
        m_errorColumn = static_cast<int>(last.dollar - last.begin + 1);
        return ScanStatus::Unterminated;
    }
    if (out.segments.size() == 1) {
        const Segment& only = out.segments.front();
        out.body = m_text.substr(only.textBegin, joined);
    } else {
        out.body = out.storage;
    }
    return ScanStatus::Statement;
}

void parseStatement(std::string_view body, ParsedStatement& out) {
    out.fields.clear();
    out.hasSlash = false;
    std::size_t pos = 0;
    while (pos < body.size() && isBlank(body[pos])) {
        ++pos;
    }
    out.wordPos = pos;
    std::size_t wordEnd = pos;
    while (wordEnd < body.size() && !isBlank(body[wordEnd]) && body[wordEnd] != '/' &&
           body[wordEnd] != ',') {
        ++wordEnd;
    }
    out.word = body.substr(pos, wordEnd - pos);
    std::size_t after = wordEnd;
    while (after < body.size() && isBlank(body[after])) {
        ++after;
    }
    if (after >= body.size() || body[after] != '/') {
        out.argsPos = wordEnd;
        return;
    }
    out.hasSlash = true;
    out.argsPos = after + 1;
    std::string_view args = body.substr(out.argsPos);
    std::size_t offset = 0;
    std::size_t probe = 0;
    while (true) {
        std::size_t comma = args.find(',', probe);
        std::size_t end = comma == std::string_view::npos ? args.size() : comma;
        std::size_t fieldPos = out.argsPos + offset;
        std::string_view text = trim(args.substr(offset, end - offset), fieldPos);
        out.fields.push_back(Field{text, fieldPos});
        if (comma == std::string_view::npos) {
            break;
        }
        offset = comma + 1;
        probe = offset;
    }
    if (out.fields.size() == 1 && out.fields.front().text.empty()) {
        out.fields.clear(); // "WORD/" with nothing after it
    }
}

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::toupper(static_cast<unsigned char>(x)) ==
                      std::toupper(static_cast<unsigned char>(y));
           });
}

std::size_t findBinaryByte(std::string_view text) {
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if ((byte < 0x20 && byte != '\t' && byte != '\n' && byte != '\r' && byte != '\f' &&
             byte != '\v') ||
            byte == 0x7F) {
            return i;
        }
    }
    return std::string_view::npos;
}

} // namespace bladeaxis::io::cl::detail
