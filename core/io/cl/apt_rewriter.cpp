#include "core/base/file_io.h"
#include "core/base/number_io.h"
#include "core/base/tolerances.h"
#include "core/base/units.h"
#include "core/io/cl/apt_writer.h"
#include "core/io/cl/detail/apt_statement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace bladeaxis::io::cl {
namespace {

using detail::Field;
using detail::Statement;

// Digits used for numbers written without a fixed number of decimals ("10", "1e-3").
constexpr int kFreeTipDecimals = 6;
constexpr int kFreeAxisDecimals = 9;
// Appended i,j,k get at least this many decimals (more when x,y,z have more).
constexpr int kMinAppendedAxisDecimals = 6;

// How a number token was written, so a changed value is written the same way.
struct NumberStyle {
    bool fixed = false; // "12.500": fixed decimals; otherwise trimmed ("12", "5.", "1e-3")
    int decimals = 0;
};

NumberStyle styleOf(std::string_view token) {
    const std::size_t dot = token.find('.');
    if (token.find_first_of("eE") != std::string_view::npos || dot == std::string_view::npos ||
        dot + 1 == token.size()) {
        return {};
    }
    return {true, static_cast<int>(token.size() - dot - 1)};
}

std::string formatAs(NumberStyle style, double value, int freeDecimals) {
    return style.fixed ? formatFixed(value, style.decimals) : formatTrimmed(value, freeDecimals);
}

// Where one piece of a number token sits in the source text.
struct TokenPiece {
    std::size_t textBegin;
    std::size_t size;
};

class AptRewriter {
  public:
    AptRewriter(const AptProgram& program, std::span<const toolpath::ClRecord> records)
        : m_program(program), m_records(records) {}

    Result<std::string> run();

  private:
    Status validate() const;
    Status rewriteRecord(std::size_t index);
    Status rewriteDelta(std::size_t index, const std::vector<Field>& fields);
    void rewriteNumbers(const Vec3& values, double scale, const std::vector<Field>& fields);
    void rewriteTip(std::size_t index, const std::vector<Field>& fields);
    Vec3 localTip(std::size_t index) const;
    Vec3 localAxis(std::size_t index) const;
    void rewriteAxis(const Vec3& axis, const std::vector<Field>& fields);
    int appendedDecimals(const std::vector<Field>& fields) const;
    bool axisDiffers(const Vec3& axis, int decimals) const;
    void ensureMultax(std::size_t index);
    void appendAxis(const Vec3& axis, const std::vector<Field>& fields, int decimals);
    void replaceToken(const Field& field, std::string_view text);
    void emit(std::size_t begin, std::size_t end, std::string_view text);

    const AptProgram& m_program;
    std::span<const toolpath::ClRecord> m_records;
    std::string m_out;
    std::size_t m_cursor = 0; // source text up to here is already in m_out
    Statement m_statement;
    detail::ParsedStatement m_parsed;
    std::vector<TokenPiece> m_pieces;     // reused by replaceToken
    Vec3 m_effectiveAxis = Vec3::UnitZ(); // the axis a reader of m_out has at this point
    std::uint32_t m_effectiveFrame = 0;   // the MSYS frame m_effectiveAxis is written in
    bool m_insertedMultax = false;
    std::uint32_t m_insertedEpoch = 0;
};

Status AptRewriter::validate() const {
    if (m_records.size() != m_program.path.records.size() ||
        m_program.source.size() != m_program.path.records.size()) {
        return makeError(ErrorCode::InvalidArgument,
                         "rewriteApt: " + std::to_string(m_records.size()) + " records for " +
                             std::to_string(m_program.path.records.size()) + " GOTO statements");
    }
    for (std::size_t i = 0; i < m_records.size(); ++i) {
        const toolpath::ClRecord& record = m_records[i];
        const double norm = record.axis.stableNorm();
        if (!isFinite(record.tip) || !isFinite(record.axis) || !(norm > tol::kZeroVector)) {
            return makeError(
                ErrorCode::InvalidArgument,
                "rewriteApt: record " + std::to_string(i) +
                    " has a non-finite tip or a non-finite or zero axis",
                SourceLocation{m_program.path.sourceFile, m_program.path.records[i].line, 0});
        }
    }
    return {};
}

void AptRewriter::emit(std::size_t begin, std::size_t end, std::string_view text) {
    m_out.append(m_program.text, m_cursor, begin - m_cursor);
    m_out.append(text);
    m_cursor = end;
}

// A token split by a `$` continuation (CATIA breaks lines at column 72, inside numbers too)
// keeps its split: each piece but the last takes as many characters of the new text as it had,
// the last takes the rest and never ends up empty, because a continuation line left blank
// would join the next statement to this one. The lines keep their lengths when the new text
// is as long as the old.
void AptRewriter::replaceToken(const Field& field, std::string_view text) {
    const std::size_t begin = field.pos;
    const std::size_t end = field.pos + field.text.size();
    const auto& segments = m_statement.segments;
    std::vector<TokenPiece>& pieces = m_pieces;
    pieces.clear();
    for (std::size_t s = m_statement.segmentIndex(begin); s < segments.size(); ++s) {
        const std::size_t segEnd =
            s + 1 < segments.size() ? segments[s + 1].joinedBegin : m_statement.body.size();
        const std::size_t from = std::max(begin, segments[s].joinedBegin);
        const std::size_t to = std::min(end, segEnd);
        if (from >= end) {
            break;
        }
        if (from < to) {
            pieces.push_back(TokenPiece{m_statement.textOffset(from), to - from});
        }
    }
    std::size_t used = 0;
    for (std::size_t p = 0; p < pieces.size(); ++p) {
        const bool last = p + 1 == pieces.size();
        const std::size_t left = text.size() - used;
        const std::size_t take = last ? left : std::min(pieces[p].size, left > 0 ? left - 1 : 0);
        emit(pieces[p].textBegin, pieces[p].textBegin + pieces[p].size, text.substr(used, take));
        used += take;
    }
}

// The records are in the world frame; the file writes them in the MSYS frame in force.
Vec3 AptRewriter::localTip(std::size_t index) const {
    return m_program.frames[m_program.source[index].frame].pointToLocal(m_records[index].tip);
}

Vec3 AptRewriter::localAxis(std::size_t index) const {
    const AptFrame& frame = m_program.frames[m_program.source[index].frame];
    return frame.rotation.transpose() * m_records[index].axis.normalized();
}

// Three numbers (mm values written in the file's length unit), each changed only where its
// text in the file's own style changes.
void AptRewriter::rewriteNumbers(const Vec3& values, double scale,
                                 const std::vector<Field>& fields) {
    for (int c = 0; c < 3; ++c) {
        const Field& field = fields[static_cast<std::size_t>(c)];
        const NumberStyle style = styleOf(field.text);
        const double old = parseNumber(field.text).value_or(0.0);
        const std::string text = formatAs(style, values[c] / scale, kFreeTipDecimals);
        if (text != formatAs(style, old, kFreeTipDecimals)) {
            replaceToken(field, text);
        }
    }
}

void AptRewriter::rewriteTip(std::size_t index, const std::vector<Field>& fields) {
    const double scale = m_program.source[index].inches ? units::kMmPerInch : 1.0;
    rewriteNumbers(localTip(index), scale, fields);
}

// GODLTA/dx,dy,dz gets the increment from the previous written point to the new one, so the
// absolute positions are the records'. GODLTA/d moves along the tool axis and has only one
// number: a change of its end point cannot be written in that form.
Status AptRewriter::rewriteDelta(std::size_t index, const std::vector<Field>& fields) {
    const double scale = m_program.source[index].inches ? units::kMmPerInch : 1.0;
    const AptFrame& frame = m_program.frames[m_program.source[index].frame];
    const Vec3 delta =
        index > 0
            ? Vec3(frame.rotation.transpose() * (m_records[index].tip - m_records[index - 1].tip))
            : Vec3::Zero();
    if (fields.size() == 3) {
        rewriteNumbers(delta, scale, fields);
        return {};
    }
    const Vec3 oldDelta =
        index > 0 ? Vec3(m_program.path.records[index].tip - m_program.path.records[index - 1].tip)
                  : Vec3::Zero();
    const Vec3 newDelta =
        index > 0 ? Vec3(m_records[index].tip - m_records[index - 1].tip) : Vec3::Zero();
    if ((newDelta - oldDelta).norm() > tol::kRoundTripMm) {
        return makeError(
            ErrorCode::CheckFailed,
            "GODLTA/d (a move along the tool axis) would have to change, which its "
            "one number cannot say; post the move as GOTO or GODLTA/dx,dy,dz",
            SourceLocation{m_program.path.sourceFile, m_program.path.records[index].line, 0});
    }
    return {};
}

void AptRewriter::rewriteAxis(const Vec3& axis, const std::vector<Field>& fields) {
    std::array<NumberStyle, 3> styles;
    Vec3 old;
    for (int c = 0; c < 3; ++c) {
        const Field& field = fields[static_cast<std::size_t>(c + 3)];
        styles[static_cast<std::size_t>(c)] = styleOf(field.text);
        old[c] = parseNumber(field.text).value_or(0.0);
    }
    // The file may hold a non-unit axis ("0,0,2"): compare directions, not raw numbers.
    const Vec3 oldUnit = old.normalized();
    bool changed = false;
    for (int c = 0; c < 3; ++c) {
        const NumberStyle style = styles[static_cast<std::size_t>(c)];
        changed = changed || formatAs(style, axis[c], kFreeAxisDecimals) !=
                                 formatAs(style, oldUnit[c], kFreeAxisDecimals);
    }
    m_effectiveAxis = changed ? axis : oldUnit;
    if (!changed) {
        return;
    }
    const bool wasUnit = std::abs(old.norm() - 1.0) <= tol::kRoundTripMm;
    for (int c = 0; c < 3; ++c) {
        const NumberStyle style = styles[static_cast<std::size_t>(c)];
        const std::string text = formatAs(style, axis[c], kFreeAxisDecimals);
        if (!wasUnit || text != formatAs(style, old[c], kFreeAxisDecimals)) {
            replaceToken(fields[static_cast<std::size_t>(c + 3)], text);
        }
    }
}

int AptRewriter::appendedDecimals(const std::vector<Field>& fields) const {
    const NumberStyle zStyle = styleOf(fields[2].text);
    return std::max(kMinAppendedAxisDecimals, zStyle.fixed ? zStyle.decimals : 0);
}

bool AptRewriter::axisDiffers(const Vec3& axis, int decimals) const {
    for (int c = 0; c < 3; ++c) {
        if (formatFixed(axis[c], decimals) != formatFixed(m_effectiveAxis[c], decimals)) {
            return true;
        }
    }
    return false;
}

// i,j,k are only meaningful with MULTAX on: insert MULTAX/ON on its own line where it is off.
void AptRewriter::ensureMultax(std::size_t index) {
    const AptRecordSource& source = m_program.source[index];
    if (source.multaxOn || (m_insertedMultax && m_insertedEpoch == source.multaxEpoch)) {
        return;
    }
    const std::string_view eol = m_program.crlf ? "\r\n" : "\n";
    emit(source.textBegin, source.textBegin, std::string("MULTAX/ON").append(eol));
    m_insertedMultax = true;
    m_insertedEpoch = source.multaxEpoch;
}

void AptRewriter::appendAxis(const Vec3& axis, const std::vector<Field>& fields, int decimals) {
    const std::size_t zEnd = m_statement.textOffset(fields[2].pos + fields[2].text.size() - 1) + 1;
    emit(zEnd, zEnd,
         "," + formatFixed(axis.x(), decimals) + "," + formatFixed(axis.y(), decimals) + "," +
             formatFixed(axis.z(), decimals));
    m_effectiveAxis = axis;
}

Status AptRewriter::rewriteRecord(std::size_t index) {
    const AptRecordSource& source = m_program.source[index];
    detail::StatementScanner scanner(m_program.text, source.textBegin,
                                     m_program.path.records[index].line);
    if (scanner.next(m_statement) != detail::ScanStatus::Statement) {
        return makeError(ErrorCode::Internal, "rewriteApt: GOTO statement not found again");
    }
    detail::parseStatement(m_statement.body, m_parsed);
    const auto& fields = m_parsed.fields;
    const char* word = source.motion == AptMotion::Goto   ? "GOTO"
                       : source.motion == AptMotion::From ? "FROM"
                                                          : "GODLTA";
    if (!detail::equalsIgnoreCase(m_parsed.word, word) || fields.size() != source.numberCount) {
        return makeError(ErrorCode::Internal, "rewriteApt: program text and records disagree");
    }
    if (source.motion == AptMotion::Delta) {
        return rewriteDelta(index, fields);
    }
    if (source.frame != m_effectiveFrame) {
        // The modal axis stays the same world direction across an MSYS: seen from this frame.
        m_effectiveAxis = m_program.frames[source.frame].rotation.transpose() *
                          (m_program.frames[m_effectiveFrame].rotation * m_effectiveAxis);
        m_effectiveFrame = source.frame;
    }
    const Vec3 axis = localAxis(index);
    if (source.numberCount == 6) {
        rewriteTip(index, fields);
        rewriteAxis(axis, fields);
    } else {
        // Decide first: a MULTAX/ON line goes before the statement, ahead of its edits.
        const int decimals = appendedDecimals(fields);
        const bool append = axisDiffers(axis, decimals);
        if (append) {
            ensureMultax(index);
        }
        rewriteTip(index, fields);
        if (append) {
            appendAxis(axis, fields, decimals);
        }
    }
    return {};
}

Result<std::string> AptRewriter::run() {
    if (Status valid = validate(); !valid) {
        return std::unexpected(std::move(valid.error()));
    }
    m_out.reserve(m_program.text.size() + m_program.text.size() / 8);
    for (std::size_t i = 0; i < m_records.size(); ++i) {
        if (Status status = rewriteRecord(i); !status) {
            return std::unexpected(std::move(status.error()));
        }
    }
    m_out.append(m_program.text, m_cursor);
    return std::move(m_out);
}

} // namespace

Result<std::string> rewriteApt(const AptProgram& program,
                               std::span<const toolpath::ClRecord> newRecords) {
    return AptRewriter(program, newRecords).run();
}

Status writeAptFile(const std::filesystem::path& out, const AptProgram& program,
                    std::span<const toolpath::ClRecord> newRecords) {
    Result<std::string> text = rewriteApt(program, newRecords);
    if (!text) {
        return std::unexpected(std::move(text.error()));
    }
    const std::filesystem::path inputs[] = {std::filesystem::path(program.path.sourceFile)};
    return writeFileAtomically(out, *text, inputs);
}

} // namespace bladeaxis::io::cl
