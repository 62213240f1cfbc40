#include "core/io/nc/gcode_reader.h"

#include "core/base/file_io.h"
#include "core/base/number_io.h"
#include "core/base/pages_mapped_ahead.h"
#include "core/io/nc/detail/block_scanner.h"
#include "core/io/nc/detail/error_list.h"
#include "core/io/nc/detail/modal_interpreter.h"
#include "core/io/nc/detail/tool_comment.h"
#include "core/io/nc/dialect.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>

namespace bladeaxis::io::nc {

namespace {

// A block that only ends the program again: a Heidenhain program's END PGM after its M30 (or M2
// on its last L block), or a repeated M30. It adds no motion and is still the one program's end.
bool onlyEndsTheProgram(const detail::ScannedBlock& block) {
    constexpr std::uint32_t kBlockNumber = 1U << ('N' - 'A');
    return block.programEnd && (block.present & ~kBlockNumber) == 0 && block.gCount == 0 &&
           block.subprogramWord == detail::kNoOffset;
}

// Record offsets are 32-bit to keep the per-record data small.
constexpr std::size_t kMaxTextBytes = kMaxProgramBytes;

Error parseErrorAt(std::string_view fileName, int line, std::string message) {
    return Error{ErrorCode::Parse, std::move(message), {std::string(fileName), line, 1}, {}};
}

// Counted in runs of at most 255 bytes, each into an 8-bit sum that cannot overflow, so that the
// compiler compares a vector of bytes at a time; std::count widens every byte to a 64-bit sum
// and took several times longer.
std::size_t countNewlines(std::string_view text) {
    constexpr std::size_t kRun = 255;
    std::size_t count = 0;
    for (std::size_t runBegin = 0; runBegin < text.size(); runBegin += kRun) {
        const std::size_t runEnd = std::min(text.size(), runBegin + kRun);
        std::uint8_t inRun = 0;
        for (std::size_t i = runBegin; i < runEnd; ++i) {
            inRun = static_cast<std::uint8_t>(inRun + (text[i] == '\n' ? 1 : 0));
        }
        count += inRun;
    }
    return count;
}

// Records and their sources are reserved for one per line, so that a million-block program does
// not pay for vector doubling (peak memory) or copies; so is the F of every record where the
// interpreter keeps one (an ISO program on a combined-axes control).
void reserveForLines(GcodeProgram& program, const kinematics::MachineModel& machine) {
    const std::size_t lines = countNewlines(program.text) + 1;
    program.path.records.reserve(lines);
    program.sources.reserve(lines);
    if (program.dialect == NcDialect::Iso &&
        machine.feedMeaning == kinematics::FeedMeaning::CombinedAxes) {
        program.programmedFeeds.reserve(lines);
    }
}

// A header comment that states the unit of the rotary words: "(ANGLES IN RADIANS)",
// "(ROTARY UNIT: DEG)", "; angular unit = degrees". It must name angles and a unit, so that
// "(B=5 deg, lead 15 deg)" or "(RADIUS 4)" declare nothing.
std::optional<AngleUnit> declaredAngleUnit(std::string_view line) {
    const std::size_t comment = line.find_first_of("(;");
    if (comment == std::string_view::npos) {
        return std::nullopt;
    }
    std::string lower(line.substr(comment));
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (char& c : lower) {
        c = std::isalpha(static_cast<unsigned char>(c)) ? c : ' ';
    }
    lower = " " + lower + " ";
    const auto has = [&lower](const char* word) {
        return lower.find(std::string(" ") + word + " ") != std::string::npos;
    };
    if (!(has("angle") || has("angles") || has("angular") || has("rotary"))) {
        return std::nullopt;
    }
    if (has("radians") || has("radian") || has("rad")) {
        return AngleUnit::Radians;
    }
    if (has("degrees") || has("degree") || has("deg")) {
        return AngleUnit::Degrees;
    }
    return std::nullopt;
}

std::size_t byteOrderMarkLength(std::string_view text) {
    return text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
}

struct StatedTool {
    detail::ToolComment tool;
    int line = 0;
    std::string text; // the comment line, as written
};

// The ball radius the header comments state (tools stated before the first move), converted to
// mm (`inch`: the first move is in inches). A flat or bull-nose cutter gives none and is
// recorded for the job to refuse (StatedCutter); ball radii that disagree give a warning, so
// the radius must be given.
void applyStatedTools(const std::vector<StatedTool>& tools, bool inch, GcodeProgram& program) {
    if (tools.empty() || program.path.toolRadius) { // a Heidenhain TOOL DEF states it exactly
        return;
    }
    const std::string& file = program.path.sourceFile;
    const double toMm = inch ? 25.4 : 1.0;
    for (const StatedTool& stated : tools) {
        if (!stated.tool.isBallEnd()) {
            program.path.nonBallCutter =
                toolpath::StatedCutter{stated.tool.diameter * toMm, stated.tool.cornerRadius * toMm,
                                       stated.line, stated.text};
            return;
        }
        if (stated.tool.cornerRadius != tools.front().tool.cornerRadius) {
            program.path.warnings.push_back(
                file + ":" + std::to_string(stated.line) + ": the header names ball radii " +
                formatShortest(tools.front().tool.cornerRadius) + " (line " +
                std::to_string(tools.front().line) + ") and " +
                formatShortest(stated.tool.cornerRadius) + ": neither is used");
            return;
        }
    }
    program.path.toolRadius = tools.front().tool.cornerRadius * toMm;
}

// Where the records the interpreter makes go: they stay in the program, or a streamed read
// hands them to its consumer in runs and clears them (with their sources and feeds).
class RecordOutlet {
  public:
    explicit RecordOutlet(const RecordChunkConsumer* consume,
                          const TextReadUpTo* readUpTo = nullptr, const ReadWatch* watch = nullptr)
        : m_consume(consume), m_readUpTo(readUpTo), m_watch(watch) {}

    void afterBlock(GcodeProgram& program) {
        if (!m_firstInch && !program.sources.empty()) {
            m_firstInch = (program.sources.front().flags & kInch) != 0;
        }
        if (m_consume != nullptr && program.path.records.size() >= kStreamChunkRecords) {
            handOn(program);
        }
    }

    // After each line: every kLinesPerLook lines the watch hears how far the read is (`read`
    // of `total` bytes) and may stop it.
    void lineRead(std::size_t read, std::size_t total) {
        if (m_watch == nullptr || ++m_linesSinceLook < kLinesPerLook) {
            return;
        }
        m_linesSinceLook = 0;
        if (m_watch->progress) {
            m_watch->progress(static_cast<double>(read) / static_cast<double>(total));
        }
        if (isCancelled(m_watch->cancel) && !m_stop) {
            m_stop = cancelledError();
        }
    }

    void handOn(GcodeProgram& program) {
        if (m_consume == nullptr || program.path.records.empty() || m_stop) {
            return;
        }
        if (Status taken = (*m_consume)(m_handedOn, program.path.records); !taken) {
            m_stop = std::move(taken.error());
            return;
        }
        m_handedOn += program.path.records.size();
        if (m_readUpTo != nullptr && *m_readUpTo && !program.sources.empty()) {
            (*m_readUpTo)(program.sources.back().lineBegin);
        }
        program.path.records.clear();
        program.sources.clear();
        program.programmedFeeds.clear();
    }

    bool firstRecordInInches() const { return m_firstInch.value_or(false); }
    // Why the consumer stopped the read, if it did.
    const std::optional<Error>& stop() const { return m_stop; }

  private:
    // About a millisecond of reading between two looks.
    static constexpr std::size_t kLinesPerLook = 4096;

    const RecordChunkConsumer* m_consume;
    const TextReadUpTo* m_readUpTo;
    const ReadWatch* m_watch;
    std::size_t m_linesSinceLook = 0;
    std::size_t m_handedOn = 0;
    std::optional<bool> m_firstInch;
    std::optional<Error> m_stop;
};

// Interprets every line of `text` (the program's own text, or the text a streamed read
// borrows) and returns the number of records made.
std::size_t interpretLines(GcodeProgram& program, std::string_view text,
                           const kinematics::MachineModel& machine, const ReadOptions& options,
                           detail::ErrorList& errors, RecordOutlet& outlet) {
    std::vector<StatedTool> statedTools;
    detail::ModalInterpreter interpreter(program, machine, errors, options.angleUnit);
    detail::ScannedBlock block;
    std::size_t begin = byteOrderMarkLength(text); // an editor's UTF-8 mark is not a word
    int lineNumber = 0;
    bool ended = false;
    int endLine = 0;
    while (begin < text.size() && !errors.full() && !outlet.stop()) {
        ++lineNumber;
        const void* newline = std::memchr(text.data() + begin, '\n', text.size() - begin);
        const std::size_t end =
            newline ? static_cast<std::size_t>(static_cast<const char*>(newline) - text.data())
                    : text.size();
        std::size_t contentEnd = end;
        if (contentEnd > begin && text[contentEnd - 1] == '\r') {
            --contentEnd;
        }
        const std::string_view line = text.substr(begin, contentEnd - begin);
        if (!interpreter.rotaryWordSeen() && program.dialect == NcDialect::Iso) {
            if (const auto unit = declaredAngleUnit(line)) {
                interpreter.noteDeclaredUnit(*unit, lineNumber);
            }
        }
        if (interpreter.recordCount() == 0) {
            if (const auto tool = detail::toolInComment(line)) {
                statedTools.push_back({*tool, lineNumber, std::string(line)});
            }
        }
        if (auto issue = detail::scanBlock(line, block, program.dialect)) {
            errors.add(lineNumber, static_cast<int>(issue->offset) + 1, std::move(issue->message));
        } else if (ended && block.hasWords && !onlyEndsTheProgram(block)) {
            // A subprogram body or a second program after M30: its moves are not this
            // program's, and reading them as motion would re-schedule them too.
            errors.add(lineNumber, 1,
                       "blocks after the program end (M2/M30 at line " + std::to_string(endLine) +
                           "): a subprogram or a second program; BladeAxis reads one flat "
                           "program, so have the post-processor expand subprograms and write "
                           "one program per file");
            break;
        } else {
            interpreter.apply(block, line, static_cast<std::uint32_t>(begin), lineNumber);
            outlet.afterBlock(program);
            if (block.programEnd && !ended) {
                ended = true;
                endLine = lineNumber;
            }
        }
        begin = end + 1;
        outlet.lineRead(std::min(begin, text.size()), text.size());
    }
    interpreter.finish();
    outlet.handOn(program);
    applyStatedTools(statedTools, outlet.firstRecordInInches(), program);
    // [A] A program cut short (a failed transfer, a full disk) still parses block by block;
    // without its M2/M30 the engineer must be told, since the re-scheduled copy would be as
    // short.
    if (!ended && errors.empty()) {
        program.path.warnings.push_back(
            SourceLocation{std::string(errors.fileName()), lineNumber, 0}.toString() +
            ": no program end (M2 or M30): the file may be truncated");
    }
    return interpreter.recordCount();
}

// The checks before the first line and the program's dialect; `text` is the whole program.
Status prepareProgram(std::string_view text, std::string_view fileName, const ReadOptions& options,
                      GcodeProgram& program) {
    if (text.size() > kMaxTextBytes) {
        return std::unexpected(programTooLarge(fileName));
    }
    if (text.empty()) {
        return std::unexpected(
            parseErrorAt(fileName, 1, "empty file: expected G-code blocks with G0/G1 moves"));
    }
    program.path.sourceFile = std::string(fileName);
    program.path.format = toolpath::SourceFormat::Gcode;
    if (options.dialect) {
        program.dialect = *options.dialect;
    } else {
        DetectedDialect detected = detectDialect(text, fileName);
        program.dialect = detected.dialect;
        if (detected.warning) {
            program.path.warnings.push_back(std::move(*detected.warning));
        }
    }
    if (program.dialect != NcDialect::Iso && options.angleUnit == AngleUnit::Radians) {
        return std::unexpected(parseErrorAt(fileName, 1,
                                            std::string("--angle-unit rad does not apply: a ") +
                                                toString(program.dialect) +
                                                " program states its rotary axes in degrees"));
    }
    return {};
}

// Interprets the prepared program's lines; the errors of the whole read, or none.
Status interpretProgram(GcodeProgram& program, std::string_view text, std::string_view fileName,
                        const kinematics::MachineModel& machine, const ReadOptions& options,
                        RecordOutlet& outlet) {
    detail::ErrorList errors(fileName, kMaxParseErrors);
    const std::size_t records = interpretLines(program, text, machine, options, errors, outlet);
    if (outlet.stop()) {
        return std::unexpected(*outlet.stop());
    }
    if (!errors.empty()) {
        return std::unexpected(errors.take());
    }
    if (records == 0) {
        return std::unexpected(parseErrorAt(
            fileName, 1, "no moves: expected G0/G1 blocks that program X, Y, Z and A"));
    }
    return {};
}

// The interpreter writes the records and their sources one line after another, a few hundred
// megabytes on a large program: their reserved pages are mapped on the other core meanwhile
// (PagesMappedAhead), so that the reading, which runs on one core, does not stop at each fresh
// page. The pages are those the records are reserved for: one per line.
Status readIntoReservation(GcodeProgram& program, std::string_view fileName,
                           const kinematics::MachineModel& machine, const ReadOptions& options,
                           RecordOutlet& outlet) {
    auto& records = program.path.records;
    const PagesMappedAhead ahead(
        {{records.data(), records.capacity() * sizeof(*records.data())},
         {program.sources.data(), program.sources.capacity() * sizeof(*program.sources.data())},
         {program.programmedFeeds.data(),
          program.programmedFeeds.capacity() * sizeof(*program.programmedFeeds.data())}});
    return interpretProgram(program, program.text, fileName, machine, options, outlet);
}

Result<GcodeProgram> parseOwnedText(std::string text, std::string_view fileName,
                                    const kinematics::MachineModel& machine,
                                    const ReadOptions& options, const ReadWatch& watch) {
    GcodeProgram program;
    if (Status ready = prepareProgram(text, fileName, options, program); !ready) {
        return std::unexpected(ready.error());
    }
    program.text = std::move(text);
    reserveForLines(program, machine);
    RecordOutlet keepAll(nullptr, nullptr, &watch);
    Status read = readIntoReservation(program, fileName, machine, options, keepAll);
    if (!read) {
        return std::unexpected(read.error());
    }
    // Shrinking copies the records, so it is done only when the reservation was mostly wasted
    // (comment-heavy files), never for large motion programs where it would double the peak.
    if (program.path.records.capacity() > 2 * program.path.records.size() + 1024) {
        program.path.records.shrink_to_fit();
        program.sources.shrink_to_fit();
        program.programmedFeeds.shrink_to_fit();
    }
    return program;
}

} // namespace

Result<GcodeProgram> parseGcode(std::string_view text, std::string_view fileName,
                                const kinematics::MachineModel& machine,
                                const ReadOptions& options) {
    return parseOwnedText(std::string(text), fileName, machine, options, {});
}

Result<GcodeProgram> parseOwnedGcode(std::string text, std::string_view fileName,
                                     const kinematics::MachineModel& machine,
                                     const ReadOptions& options, const ReadWatch& watch) {
    return parseOwnedText(std::move(text), fileName, machine, options, watch);
}

Result<std::size_t> streamGcodeRecords(std::string_view text, std::string_view fileName,
                                       const kinematics::MachineModel& machine,
                                       const ReadOptions& options,
                                       const RecordChunkConsumer& consume,
                                       const TextReadUpTo& readUpTo) {
    GcodeProgram program;
    if (Status ready = prepareProgram(text, fileName, options, program); !ready) {
        return std::unexpected(ready.error());
    }
    program.path.records.reserve(kStreamChunkRecords);
    program.sources.reserve(kStreamChunkRecords);
    std::size_t records = 0;
    const RecordChunkConsumer counting = [&](std::size_t first,
                                             std::span<const toolpath::ClRecord> chunk) {
        records = first + chunk.size();
        return consume(first, chunk);
    };
    RecordOutlet outlet(&counting, &readUpTo);
    if (Status read = interpretProgram(program, text, fileName, machine, options, outlet); !read) {
        return std::unexpected(read.error());
    }
    return records;
}

Result<GcodeProgram> readGcodeFile(const std::filesystem::path& path,
                                   const kinematics::MachineModel& machine,
                                   const ReadOptions& options) {
    Result<std::string> text = readTextFile(path);
    if (!text) {
        return std::unexpected(std::move(text.error()));
    }
    return parseOwnedText(std::move(*text), path.string(), machine, options, {});
}

Error programTooLarge(std::string_view fileName) {
    return Error{ErrorCode::Parse,
                 "file too large: expected at most 4 GiB of G-code",
                 {std::string(fileName), 1, 1},
                 {}};
}

} // namespace bladeaxis::io::nc
