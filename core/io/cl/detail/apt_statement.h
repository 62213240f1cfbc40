#pragma once
// Splitting APT / CLSF text into statements: `$` continuation joins physical lines, `$$`
// starts a comment. Shared by the reader and the rewriter so both see the same fields at the
// same byte offsets of the source text.

#include "core/base/error.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace bladeaxis::io::cl::detail {

// One physical line's contribution to a statement.
struct Segment {
    std::size_t joinedBegin = 0; // offset of the piece in Statement::body
    std::size_t textBegin = 0;   // offset of the piece in the source text
    std::size_t lineBegin = 0;   // offset of the piece's line in the source text (for columns)
    int line = 0;                // 1-based
};

// A logical statement. For the usual single-line statement `body` views the source text
// directly; continued statements are joined into `storage`.
struct Statement {
    std::string_view body;
    std::string storage;
    std::vector<Segment> segments;
    std::size_t textBegin = 0; // start of the statement's first line in the source text

    int firstLine() const { return segments.empty() ? 0 : segments.front().line; }
    std::size_t segmentIndex(std::size_t joinedPos) const;
    // 1-based line and column of a body offset.
    SourceLocation locate(std::size_t joinedPos, std::string_view file) const;
    // Source-text offset of a body offset (a position inside one segment).
    std::size_t textOffset(std::size_t joinedPos) const;
};

enum class ScanStatus { Statement, End, Unterminated };

class StatementScanner {
  public:
    // Starts at `begin`, which must be the start of a line numbered `line`.
    explicit StatementScanner(std::string_view text, std::size_t begin = 0, int line = 1);

    // Fills `out` with the next non-empty statement. On Unterminated, errorLine/errorColumn
    // point at the `$` whose continuation never came.
    ScanStatus next(Statement& out);

    int errorLine() const { return m_errorLine; }
    int errorColumn() const { return m_errorColumn; }

  private:
    std::string_view m_text;
    std::size_t m_pos;
    int m_line;
    int m_errorLine = 0;
    int m_errorColumn = 0;
};

// A comma-separated argument, trimmed, with its offset in the statement body.
struct Field {
    std::string_view text;
    std::size_t pos = 0;
};

// "WORD/arg, arg" or "WORD free text". The word is the leading run up to a blank or '/'.
struct ParsedStatement {
    std::string_view word;
    std::size_t wordPos = 0;
    bool hasSlash = false;
    std::size_t argsPos = 0; // body offset just after '/' (or after the word)
    std::vector<Field> fields;
};

// Reuses `out.fields` to avoid allocating per statement.
void parseStatement(std::string_view body, ParsedStatement& out);

bool equalsIgnoreCase(std::string_view a, std::string_view b);

// The first byte that cannot occur in a CL text file (NUL, control characters other than
// blanks and line ends), or npos.
std::size_t findBinaryByte(std::string_view text);

} // namespace bladeaxis::io::cl::detail
