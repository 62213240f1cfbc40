#include "core/io/cl/apt_reader.h"

#include "core/base/file_io.h"
#include "core/base/number_io.h"
#include "core/base/tolerances.h"
#include "core/base/units.h"
#include "core/io/cl/detail/apt_statement.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>

namespace bladeaxis::io::cl {
namespace {

using detail::equalsIgnoreCase;
using detail::Field;
using detail::ParsedStatement;
using detail::ScanStatus;
using detail::Statement;
using detail::StatementScanner;

// A ball end's corner radius equals half its diameter within this (mm).
constexpr double kBallRadiusTolMm = 1e-6;
constexpr std::string_view kGotoFieldNames[] = {"GOTO/ x", "GOTO/ y", "GOTO/ z",
                                                "GOTO/ i", "GOTO/ j", "GOTO/ k"};

bool looksNonFinite(std::string_view token) {
    std::string lower(token);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return lower.find("nan") != std::string::npos || lower.find("inf") != std::string::npos;
}

// The modal state of the CL stream while reading.
struct ModalState {
    bool inches = false;
    std::optional<double> feed; // mm/s
    bool rapidNext = false;
    Vec3 axis = Vec3::UnitZ();
    bool multaxOn = false;
    std::uint32_t multaxEpoch = 0;
};

// APT source motion and circles: statements that move the tool along geometry BladeAxis does
// not evaluate. CL data from a CAM system's post has GOTOs only; these come from APT part
// programs or circle output.
constexpr std::string_view kUnfollowedMotion[] = {"GO",     "GOFWD", "GOLFT",  "GORGT",
                                                  "GOBACK", "GOUP",  "GODOWN", "INDIRV",
                                                  "INDIRP", "PSIS",  "CIRCLE", "GOCLER"};

class AptReader {
  public:
    AptReader(std::string_view text, std::string_view file, const ReadOptions& options)
        : m_text(text), m_file(file), m_defaultFeed(options.feedMmPerS) {}

    Result<AptProgram> run();

  private:
    void dispatch();
    void readGoto();
    void readFrom();
    void readDelta();
    void readMsys();
    void refuseMotion();
    std::optional<Vec3> readPointAndAxis(std::string_view word);
    bool takeFeed(toolpath::ClRecord& record);
    void addRecord(toolpath::ClRecord record, AptMotion motion, std::uint8_t numberCount);
    void readFedrat();
    void readUnits();
    void readCutter();
    void readTldata();
    void readMultax();
    void setTool(double diameter, std::optional<double> cornerRadius, std::size_t radiusPos);

    std::optional<double> number(const Field& field, std::string_view what);
    void fail(std::size_t bodyPos, std::string message);
    void warn(std::string message);
    double lengthScale() const { return m_state.inches ? units::kMmPerInch : 1.0; }
    Error collectErrors();

    std::string_view m_text;
    std::string_view m_file;
    AptProgram m_program;
    ModalState m_state;
    Statement m_statement;
    ParsedStatement m_parsed;
    std::vector<Error> m_errors;
    bool m_finished = false;
    bool m_pathEnded = false;
    bool m_lastWasEnd = false;           // the last statement so far is END (CATIA's last line)
    int m_lastStatementLine = 0;         // where a file without FINI stops
    std::optional<double> m_defaultFeed; // mm/s, for CL data without FEDRAT
    bool m_reportedMissingFeed = false;
    std::uint32_t m_frame = 0;     // index of the MSYS frame in force
    std::optional<Vec3> m_lastTip; // world, for GODLTA
};

void AptReader::fail(std::size_t bodyPos, std::string message) {
    if (m_errors.size() < static_cast<std::size_t>(kMaxReportedErrors)) {
        m_errors.push_back(
            Error{ErrorCode::Parse, std::move(message), m_statement.locate(bodyPos, m_file), {}});
    }
}

void AptReader::warn(std::string message) {
    m_program.path.warnings.push_back(std::string(m_file) + ":" +
                                      std::to_string(m_statement.firstLine()) + ": " + message);
}

std::optional<double> AptReader::number(const Field& field, std::string_view what) {
    std::optional<double> value = parseNumber(field.text);
    if (!value) {
        const std::string token(field.text);
        fail(field.pos,
             looksNonFinite(token)
                 ? std::string(what) + " is not a finite number: '" + token + "'"
                 : "expected a number for " + std::string(what) + ", got '" + token + "'");
    }
    return value;
}

void AptReader::dispatch() {
    const std::string_view word = m_parsed.word;
    m_lastWasEnd = equalsIgnoreCase(word, "END");
    if (equalsIgnoreCase(word, "GOTO")) {
        readGoto();
    } else if (equalsIgnoreCase(word, "FEDRAT")) {
        readFedrat();
    } else if (equalsIgnoreCase(word, "RAPID")) {
        m_state.rapidNext = true;
    } else if (equalsIgnoreCase(word, "MULTAX")) {
        readMultax();
    } else if (equalsIgnoreCase(word, "UNITS")) {
        readUnits();
    } else if (equalsIgnoreCase(word, "CUTTER")) {
        readCutter();
    } else if (equalsIgnoreCase(word, "TLDATA")) {
        readTldata();
    } else if (equalsIgnoreCase(word, "FINI")) {
        m_finished = true;
    } else if (equalsIgnoreCase(word, "END-OF-PATH")) {
        m_pathEnded = true; // NX CLSF ends each tool path so, and has no FINI
    } else if (equalsIgnoreCase(word, "FROM")) {
        readFrom();
    } else if (equalsIgnoreCase(word, "GODLTA")) {
        readDelta();
    } else if (equalsIgnoreCase(word, "MSYS")) {
        readMsys();
    } else if (std::any_of(
                   std::begin(kUnfollowedMotion), std::end(kUnfollowedMotion),
                   [&word](std::string_view motion) { return equalsIgnoreCase(word, motion); })) {
        refuseMotion();
    }
    // Everything else (PARTNO, PPRINT, LOADTL, SPINDL, COOLNT, TOOL PATH, PAINT, CUTCOM, END,
    // ...) does not move the tool: it stays in AptProgram::text and is otherwise ignored.
}

void AptReader::refuseMotion() {
    const std::string word(m_parsed.word);
    const bool circle = equalsIgnoreCase(word, "CIRCLE");
    fail(m_parsed.wordPos,
         circle ? "circular move (CIRCLE/): BladeAxis re-schedules linear CL data and would "
                  "take the arc for its chord; post the program with linear moves (GOTO only)"
                : word + ": APT part-program motion, not CL data; run the part program through "
                         "the APT processor and read the CL file it writes (GOTO statements)");
}

// x,y,z[,i,j,k] of GOTO/FROM in the frame in force, to world: the tip, and the unit axis
// (which also becomes the modal axis) when six numbers are given.
std::optional<Vec3> AptReader::readPointAndAxis(std::string_view word) {
    const auto& fields = m_parsed.fields;
    if (fields.size() != 3 && fields.size() != 6) {
        fail(m_parsed.argsPos, "expected 3 or 6 numbers after " + std::string(word) + "/, got " +
                                   std::to_string(fields.size()));
        return std::nullopt;
    }
    double values[6] = {};
    for (std::size_t i = 0; i < fields.size(); ++i) {
        std::optional<double> value = number(fields[i], kGotoFieldNames[i]);
        if (!value) {
            return std::nullopt;
        }
        values[i] = *value;
    }
    const AptFrame& frame = m_program.frames[m_frame];
    const Vec3 tip = frame.pointToWorld(Vec3(values[0], values[1], values[2]) * lengthScale());
    if (!isFinite(tip)) {
        fail(fields[0].pos, std::string(word) + "/ coordinates out of range");
        return std::nullopt;
    }
    if (fields.size() == 6) {
        Vec3 axis(values[3], values[4], values[5]);
        const double norm = axis.stableNorm();
        if (!std::isfinite(norm) || norm <= tol::kZeroVector) {
            fail(fields[3].pos, "tool axis (i,j,k) of " + std::string(word) + "/ has zero length");
            return std::nullopt;
        }
        m_state.axis = frame.rotation * (axis / norm);
    }
    return tip;
}

// The feed of a feed move: FEDRAT's, else the one given by the user; without either, one
// error for the whole file (every GOTO would repeat it).
bool AptReader::takeFeed(toolpath::ClRecord& record) {
    if (m_state.rapidNext) {
        record.motion = toolpath::MotionKind::Rapid;
        return true;
    }
    if (m_state.feed || m_defaultFeed) {
        record.feed = m_state.feed ? *m_state.feed : *m_defaultFeed;
        return true;
    }
    if (!m_reportedMissingFeed) {
        m_reportedMissingFeed = true;
        fail(m_parsed.wordPos, "GOTO before any FEDRAT: the file states no feed; give the feed "
                               "with --feed (mm/min, job key feed_mm_min) or add a FEDRAT");
    }
    return false;
}

void AptReader::addRecord(toolpath::ClRecord record, AptMotion motion, std::uint8_t numberCount) {
    record.line = m_statement.firstLine();
    m_state.rapidNext = false; // RAPID applies to the next motion only
    m_lastTip = record.tip;
    m_program.path.records.push_back(record);
    m_program.source.push_back(AptRecordSource{m_statement.textBegin, m_state.multaxEpoch,
                                               numberCount, m_state.multaxOn, m_state.inches,
                                               motion, m_frame});
}

void AptReader::readFrom() {
    const std::optional<Vec3> tip = readPointAndAxis("FROM");
    if (!tip) {
        return;
    }
    toolpath::ClRecord record;
    record.tip = *tip;
    record.axis = m_state.axis;
    record.motion = toolpath::MotionKind::Rapid; // where the tool starts, not a cut
    addRecord(record, AptMotion::From, static_cast<std::uint8_t>(m_parsed.fields.size()));
}

// GODLTA/dx,dy,dz moves by a vector of the frame in force; GODLTA/d along the tool axis.
void AptReader::readDelta() {
    const auto& fields = m_parsed.fields;
    if (fields.size() != 1 && fields.size() != 3) {
        fail(m_parsed.argsPos, "expected 1 (along the tool axis) or 3 numbers after GODLTA/, got " +
                                   std::to_string(fields.size()));
        return;
    }
    if (!m_lastTip) {
        fail(m_parsed.wordPos, "GODLTA before any GOTO or FROM: an incremental move needs a "
                               "start point");
        return;
    }
    Vec3 delta = Vec3::Zero();
    for (std::size_t i = 0; i < fields.size(); ++i) {
        std::optional<double> value = number(fields[i], "GODLTA/ increment");
        if (!value) {
            return;
        }
        delta[static_cast<Eigen::Index>(i)] = *value * lengthScale();
    }
    const Vec3 world = fields.size() == 1 ? Vec3(delta.x() * m_state.axis)
                                          : Vec3(m_program.frames[m_frame].rotation * delta);
    toolpath::ClRecord record;
    record.tip = *m_lastTip + world;
    record.axis = m_state.axis;
    if (!takeFeed(record)) {
        return;
    }
    addRecord(record, AptMotion::Delta, static_cast<std::uint8_t>(fields.size()));
}

// MSYS/x,y,z,xi,xj,xk,yi,yj,yk: the origin and the X and Y axes of the local system in the
// base frame (NX CLSF and ISO 4343); Z = X x Y. MSYS with no numbers returns to the base frame.
void AptReader::readMsys() {
    const auto& fields = m_parsed.fields;
    if (fields.empty()) {
        m_frame = 0;
        return;
    }
    if (fields.size() != 9) {
        fail(m_parsed.argsPos, "expected 9 numbers after MSYS/ (origin x,y,z, then the local X "
                               "and Y axes), got " +
                                   std::to_string(fields.size()));
        return;
    }
    double values[9] = {};
    for (std::size_t i = 0; i < 9; ++i) {
        std::optional<double> value = number(fields[i], "MSYS/");
        if (!value) {
            return;
        }
        values[i] = *value;
    }
    const Vec3 xAxis(values[3], values[4], values[5]);
    const Vec3 yAxis(values[6], values[7], values[8]);
    if (xAxis.norm() < tol::kZeroVector || yAxis.norm() < tol::kZeroVector ||
        std::abs(xAxis.normalized().dot(yAxis.normalized())) > 1e-6) {
        fail(fields[3].pos, "MSYS/ axes must be two non-zero perpendicular vectors");
        return;
    }
    AptFrame frame;
    frame.origin = Vec3(values[0], values[1], values[2]) * lengthScale();
    frame.rotation.col(0) = xAxis.normalized();
    frame.rotation.col(1) = yAxis.normalized();
    frame.rotation.col(2) = xAxis.normalized().cross(yAxis.normalized());
    m_program.frames.push_back(frame);
    m_frame = static_cast<std::uint32_t>(m_program.frames.size() - 1);
}

void AptReader::readGoto() {
    const std::optional<Vec3> tip = readPointAndAxis("GOTO");
    if (!tip) {
        return;
    }
    toolpath::ClRecord record;
    record.tip = *tip;
    record.axis = m_state.axis;
    if (!takeFeed(record)) {
        return;
    }
    addRecord(record, AptMotion::Goto, static_cast<std::uint8_t>(m_parsed.fields.size()));
}

void AptReader::readFedrat() {
    std::optional<double> value;
    double unitScale = lengthScale(); // a bare FEDRAT/f is per minute in the file's units
    for (const Field& field : m_parsed.fields) {
        if (equalsIgnoreCase(field.text, "MMPM")) {
            unitScale = 1.0;
        } else if (equalsIgnoreCase(field.text, "IPM")) {
            unitScale = units::kMmPerInch;
        } else if (equalsIgnoreCase(field.text, "MMPR") || equalsIgnoreCase(field.text, "IPR")) {
            fail(field.pos, "feed per revolution (" + std::string(field.text) +
                                ") is not supported; expected MMPM or IPM");
            return;
        } else if (value) {
            fail(field.pos, "expected one feed value in FEDRAT/, got a second one");
            return;
        } else if (!(value = number(field, "the FEDRAT/ feed"))) {
            return;
        }
    }
    if (!value) {
        fail(m_parsed.argsPos, "expected a feed value after FEDRAT/");
        return;
    }
    if (*value <= 0.0) {
        fail(m_parsed.argsPos, "feed must be positive, got " + formatShortest(*value));
        return;
    }
    m_state.feed = units::perMinuteToPerSecond(*value * unitScale);
}

void AptReader::readUnits() {
    const auto& fields = m_parsed.fields;
    if (fields.size() == 1 && equalsIgnoreCase(fields[0].text, "MM")) {
        m_state.inches = false;
    } else if (fields.size() == 1 && (equalsIgnoreCase(fields[0].text, "INCHES") ||
                                      equalsIgnoreCase(fields[0].text, "INCH"))) {
        m_state.inches = true;
    } else {
        fail(m_parsed.argsPos, "expected MM or INCHES after UNITS/");
    }
}

// A flat (corner radius 0) or bull-nose cutter gives no ball radius: it is recorded with its
// line, and the job refuses to re-orient it unless the job states a ball (see StatedCutter).
void AptReader::setTool(double diameter, std::optional<double> cornerRadius,
                        std::size_t radiusPos) {
    const double half = 0.5 * diameter * lengthScale();
    const std::optional<double> radius =
        cornerRadius ? std::optional(*cornerRadius * lengthScale()) : std::nullopt;
    if (radius && std::abs(*radius - half) > kBallRadiusTolMm) {
        if (!m_program.path.nonBallCutter) {
            std::string statement(m_statement.body);
            statement.erase(0, statement.find_first_not_of(" \t"));
            m_program.path.nonBallCutter = toolpath::StatedCutter{
                2.0 * half, *radius, m_statement.locate(radiusPos, m_file).line,
                statement.substr(0, statement.find_last_not_of(" \t\r") + 1)};
        }
        return;
    }
    m_program.path.toolRadius = radius ? *radius : half;
}

void AptReader::readCutter() {
    const auto& fields = m_parsed.fields;
    if (fields.empty()) {
        fail(m_parsed.argsPos, "expected a diameter after CUTTER/");
        return;
    }
    std::optional<double> diameter = number(fields[0], "the CUTTER/ diameter");
    if (!diameter) {
        return;
    }
    if (*diameter <= 0.0) {
        fail(fields[0].pos, "cutter diameter must be positive, got " + formatShortest(*diameter));
        return;
    }
    std::optional<double> radius;
    if (fields.size() >= 2 && !(radius = number(fields[1], "the CUTTER/ corner radius"))) {
        return;
    }
    setTool(*diameter, radius, fields.size() >= 2 ? fields[1].pos : fields[0].pos);
}

void AptReader::readTldata() {
    const auto& fields = m_parsed.fields;
    if (fields.empty() || !equalsIgnoreCase(fields[0].text, "MILL")) {
        warn("TLDATA other than TLDATA/MILL ignored");
        return;
    }
    if (fields.size() < 2) {
        fail(m_parsed.argsPos, "expected MILL,diameter,lower radius after TLDATA/");
        return;
    }
    std::optional<double> diameter = number(fields[1], "the TLDATA/ diameter");
    if (!diameter) {
        return;
    }
    if (*diameter <= 0.0) {
        fail(fields[1].pos, "tool diameter must be positive, got " + formatShortest(*diameter));
        return;
    }
    std::optional<double> radius;
    if (fields.size() >= 3 && !(radius = number(fields[2], "the TLDATA/ lower radius"))) {
        return;
    }
    setTool(*diameter, radius, fields.size() >= 3 ? fields[2].pos : fields[1].pos);
}

void AptReader::readMultax() {
    const auto& fields = m_parsed.fields;
    ++m_state.multaxEpoch;
    if (fields.empty() || equalsIgnoreCase(fields[0].text, "ON")) {
        m_state.multaxOn = true;
    } else if (equalsIgnoreCase(fields[0].text, "OFF")) {
        m_state.multaxOn = false;
    } else {
        fail(fields[0].pos,
             "expected ON or OFF after MULTAX/, got '" + std::string(fields[0].text) + "'");
    }
}

Error AptReader::collectErrors() {
    Error first = std::move(m_errors.front());
    first.more.assign(std::make_move_iterator(m_errors.begin() + 1),
                      std::make_move_iterator(m_errors.end()));
    return first;
}

SourceLocation locateOffset(std::string_view text, std::size_t offset, std::string_view file) {
    const std::string_view before = text.substr(0, offset);
    const auto line = std::count(before.begin(), before.end(), '\n') + 1;
    const std::size_t lineStart = before.rfind('\n');
    const std::size_t column =
        lineStart == std::string_view::npos ? offset + 1 : offset - lineStart;
    return SourceLocation{std::string(file), static_cast<int>(line), static_cast<int>(column)};
}

Result<AptProgram> AptReader::run() {
    if (m_text.empty()) {
        return makeError(ErrorCode::Parse, "empty file", SourceLocation{std::string(m_file), 1, 1});
    }
    if (std::size_t bad = detail::findBinaryByte(m_text); bad != std::string_view::npos) {
        return makeError(ErrorCode::Parse,
                         "binary data in a CL text file (byte " +
                             std::to_string(static_cast<unsigned char>(m_text[bad])) + ")",
                         locateOffset(m_text, bad, m_file));
    }
    m_program.path.sourceFile = std::string(m_file);
    m_program.path.format = toolpath::SourceFormat::Apt;
    m_program.text = std::string(m_text);
    const std::size_t firstNewline = m_text.find('\n');
    m_program.crlf = firstNewline != std::string_view::npos && firstNewline > 0 &&
                     m_text[firstNewline - 1] == '\r';
    // A UTF-8 byte order mark (some Windows editors add one) would hide the first major word.
    const std::size_t bom = m_text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
    StatementScanner scanner(m_text, bom);
    while (!m_finished && m_errors.size() < static_cast<std::size_t>(kMaxReportedErrors)) {
        const ScanStatus status = scanner.next(m_statement);
        if (status == ScanStatus::End) {
            break;
        }
        if (status == ScanStatus::Unterminated) {
            m_errors.push_back(Error{
                ErrorCode::Parse,
                "unterminated '$' continuation at the end of the file",
                SourceLocation{std::string(m_file), scanner.errorLine(), scanner.errorColumn()},
                {}});
            break;
        }
        m_lastStatementLine = m_statement.firstLine();
        detail::parseStatement(m_statement.body, m_parsed);
        dispatch();
    }
    if (!m_errors.empty()) {
        return std::unexpected(collectErrors());
    }
    if (m_program.path.records.empty()) {
        return makeError(ErrorCode::Parse, "no GOTO statement in the file",
                         SourceLocation{std::string(m_file), 1, 1});
    }
    // A file cut short still parses statement by statement. CATIA ends its files with END.
    if (!m_finished && !m_pathEnded && !m_lastWasEnd) {
        m_program.path.warnings.push_back(
            std::string(m_file) + ":" + std::to_string(m_lastStatementLine) +
            ": the file ends here, at its last statement, without FINI, END-OF-PATH or END: it "
            "may "
            "be truncated");
    }
    return std::move(m_program);
}

} // namespace

Result<AptProgram> parseApt(std::string_view text, std::string_view fileName,
                            const ReadOptions& options) {
    return AptReader(text, fileName, options).run();
}

Result<AptProgram> readAptFile(const std::filesystem::path& path, const ReadOptions& options) {
    Result<std::string> text = readTextFile(path);
    if (!text) {
        return std::unexpected(std::move(text.error()));
    }
    return parseApt(*text, path.string(), options);
}

} // namespace bladeaxis::io::cl
