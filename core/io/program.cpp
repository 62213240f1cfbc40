#include "core/io/program.h"

#include "core/base/file_io.h"
#include "core/base/free_storage.h"
#include "core/base/memory_policy.h"
#include "core/io/nc/dialect.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace bladeaxis::io {

const char* toString(AngleUnit unit) {
    return unit == AngleUnit::Degrees ? "deg" : "rad";
}

const char* toString(ProgramFormat format) {
    switch (format) {
    case ProgramFormat::Gcode:
        return "gcode";
    case ProgramFormat::Apt:
        return "apt";
    case ProgramFormat::Table:
        return "table";
    }
    return "gcode";
}

namespace {

// How many meaningful lines decide the format.
constexpr int kLinesToClassify = 200;

std::string lowerExtension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

std::optional<ProgramFormat> formatOfExtension(const std::filesystem::path& path) {
    static constexpr std::array<std::string_view, 9> kGcode{
        ".nc", ".ngc", ".tap", ".gcode", ".mpf", ".spf", ".iso", ".cnc", ".h"};
    static constexpr std::array<std::string_view, 5> kApt{".cl", ".cls", ".apt", ".aptsource",
                                                          ".clsf"};
    static constexpr std::array<std::string_view, 4> kTable{".txt", ".csv", ".xyz", ".dat"};
    const std::string extension = lowerExtension(path);
    const auto in = [&extension](const auto& list) {
        return std::find(list.begin(), list.end(), extension) != list.end();
    };
    if (in(kGcode)) {
        return ProgramFormat::Gcode;
    }
    if (in(kApt)) {
        return ProgramFormat::Apt;
    }
    if (in(kTable)) {
        return ProgramFormat::Table;
    }
    return std::nullopt;
}

bool isAlpha(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) != 0;
}

// "N10 G1 X1.", "g1x.5", "T1 M6", "O1000", ":1000": a letter, blanks, then a number.
bool looksLikeGcodeBlock(std::string_view line) {
    std::size_t i = line.starts_with("/") ? 1 : 0; // block delete
    if (i >= line.size() || !(isAlpha(line[i]) || line[i] == ':')) {
        return false;
    }
    ++i;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) {
        ++i;
    }
    return i < line.size() && (std::isdigit(static_cast<unsigned char>(line[i])) ||
                               line[i] == '-' || line[i] == '+' || line[i] == '.');
}

// "GOTO/1,2,3", "TOOL PATH/...", "END-OF-PATH", "PARTNO BLADE", "$$ comment".
bool looksLikeAptStatement(std::string_view line) {
    if (line.starts_with("$$")) {
        return true;
    }
    const std::size_t slash = line.find('/');
    const std::string_view word = line.substr(0, slash);
    const bool wordOnly = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
        return isAlpha(c) || c == ' ' || c == '-' || c == '_';
    });
    if (slash != std::string_view::npos) {
        return wordOnly && isAlpha(word.front());
    }
    static constexpr std::array<std::string_view, 8> kBare{
        "FINI", "END-OF-PATH", "RAPID", "MULTAX", "PARTNO", "PPRINT", "REMARK", "END"};
    std::string upper;
    for (char c : line.substr(0, line.find(' '))) {
        upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    return std::find(kBare.begin(), kBare.end(), upper) != kBare.end();
}

bool isCommentOrBlank(std::string_view line) {
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) {
        return true;
    }
    const char c = line[first];
    return c == '(' || c == ';' || c == '%' || c == '#';
}

// A byte that cannot be in a text program: NUL and control characters other than blanks and
// line ends, in the first 64 KiB.
std::optional<std::size_t> binaryByte(std::string_view text) {
    const std::string_view head = text.substr(0, std::min<std::size_t>(text.size(), 1 << 16));
    for (std::size_t i = 0; i < head.size(); ++i) {
        const auto c = static_cast<unsigned char>(head[i]);
        if ((c < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\f' && c != '\v') ||
            c == 0x7F) {
            return i;
        }
    }
    return std::nullopt;
}

int lineOfOffset(std::string_view text, std::size_t offset) {
    return static_cast<int>(std::count(text.begin(), text.begin() + offset, '\n')) + 1;
}

struct LineCounts {
    int gcode = 0, apt = 0;
    int firstUnknownLine = 0;
};

LineCounts classifyLines(std::string_view text) {
    LineCounts counts;
    std::size_t begin = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
    int number = 0;
    int meaningful = 0;
    while (begin < text.size() && meaningful < kLinesToClassify) {
        const std::size_t newline = text.find('\n', begin);
        const std::size_t end = newline == std::string_view::npos ? text.size() : newline;
        std::string_view line = text.substr(begin, end - begin);
        line.remove_prefix(std::min(line.find_first_not_of(" \t"), line.size()));
        ++number;
        begin = end + 1;
        if (isCommentOrBlank(line)) {
            continue;
        }
        ++meaningful;
        if (nc::looksLikeHeidenhainLine(line)) {
            ++counts.gcode;
        } else if (looksLikeAptStatement(line)) {
            ++counts.apt;
        } else if (looksLikeGcodeBlock(line)) {
            ++counts.gcode;
        } else if (counts.firstUnknownLine == 0) {
            counts.firstUnknownLine = number;
        }
    }
    return counts;
}

std::optional<ProgramFormat> formatOfContent(std::string_view text, int& unknownLine) {
    if (table::looksLikePointTable(text)) {
        return ProgramFormat::Table;
    }
    const LineCounts counts = classifyLines(text);
    unknownLine = counts.firstUnknownLine;
    if (counts.apt == 0 && counts.gcode == 0) {
        return std::nullopt;
    }
    return counts.apt > counts.gcode ? ProgramFormat::Apt : ProgramFormat::Gcode;
}

} // namespace

Result<ProbedFormat> detectFormat(const std::filesystem::path& path, std::string_view text) {
    const std::string file = path.string();
    if (const auto binary = binaryByte(text)) {
        return makeError(
            ErrorCode::Parse,
            "not a text program: binary data (byte " +
                std::to_string(static_cast<unsigned>(static_cast<unsigned char>(text[*binary]))) +
                ") where G-code, CL data or a point table was expected",
            {file, lineOfOffset(text, *binary), 0});
    }
    const std::optional<ProgramFormat> byExtension = formatOfExtension(path);
    int unknownLine = 0;
    const std::optional<ProgramFormat> byContent = formatOfContent(text, unknownLine);
    if (!byContent) {
        if (text.find_first_not_of(" \t\r\n") == std::string_view::npos && byExtension) {
            return ProbedFormat{*byExtension, std::nullopt}; // empty: the reader says so
        }
        return makeError(ErrorCode::Parse,
                         "format not recognised: expected G-code (blocks such as 'N10 G1 X1.5 "
                         "Y2. Z3. A45.'), APT/CLSF CL data (statements such as "
                         "'GOTO/1.5,2,3,0,0,1') or a point table (lines of x y z i j k numbers)",
                         {file, std::max(unknownLine, 1), 0});
    }
    ProbedFormat probed{*byContent, std::nullopt};
    if (byExtension && *byExtension != *byContent) {
        probed.warning = file + ": the extension says " + toString(*byExtension) +
                         " but the content is " + toString(*byContent) + "; read as " +
                         toString(*byContent);
    }
    return probed;
}

ProgramFormat probeFormat(const std::filesystem::path& path, std::string_view text) {
    if (auto probed = detectFormat(path, text)) {
        return probed->format;
    }
    return formatOfExtension(path).value_or(ProgramFormat::Gcode);
}

const toolpath::Toolpath& LoadedProgram::path() const {
    return std::visit([](const auto& program) -> const toolpath::Toolpath& { return program.path; },
                      document);
}

toolpath::Toolpath& LoadedProgram::mutablePath() {
    return std::visit([](auto& program) -> toolpath::Toolpath& { return program.path; }, document);
}

const std::string& LoadedProgram::text() const {
    return std::visit([](const auto& program) -> const std::string& { return program.text; },
                      document);
}

namespace {

// What only each format's rewriter reads.
void releaseRewriteSourcesOf(nc::GcodeProgram& program) {
    freeStorage(program.text);
    freeStorage(program.sources);
    freeStorage(program.programmedFeeds);
}
void releaseRewriteSourcesOf(cl::AptProgram& program) {
    freeStorage(program.text);
    freeStorage(program.source);
}
void releaseRewriteSourcesOf(table::TableProgram& program) {
    freeStorage(program.text);
    freeStorage(program.sources);
}

} // namespace

void LoadedProgram::releaseRewriteSources() {
    std::visit([](auto& program) { releaseRewriteSourcesOf(program); }, document);
}

namespace {

// The front of a container, up to `end` elements, back to the system (whole pages only).
template <class Container>
void returnFront(Container& container, std::size_t end) {
    const std::size_t count = std::min(end, container.size());
    returnWholePagesToTheSystem(container.data(), count * sizeof(*container.data()));
}

} // namespace

void LoadedProgram::dropTextKeptInItsFile(const FileSnapshot& file) {
    auto* gcode = std::get_if<nc::GcodeProgram>(&document);
    if (gcode == nullptr || static_cast<std::size_t>(file.size) != gcode->text.size()) {
        return;
    }
    freeStorage(gcode->text);
    textFile = file;
}

void LoadedProgram::releaseRewriteSourcesBefore(std::size_t textEnd, std::size_t blockEnd) {
    auto* gcode = std::get_if<nc::GcodeProgram>(&document);
    if (gcode == nullptr) {
        return;
    }
    returnFront(gcode->text, textEnd);
    returnFront(gcode->sources, blockEnd);
    returnFront(gcode->programmedFeeds, blockEnd);
}

std::optional<bool> programsToolTip(const LoadedProgram& program, std::size_t first,
                                    std::size_t count) {
    const auto* gcode = std::get_if<nc::GcodeProgram>(&program.document);
    if (gcode == nullptr || count == 0 || first + count > gcode->sources.size()) {
        return false;
    }
    const auto tip = [gcode](std::size_t k) {
        return (gcode->sources[k].flags & nc::kToolTip) != 0;
    };
    const bool firstTip = tip(first);
    for (std::size_t k = first + 1; k < first + count; ++k) {
        if (tip(k) != firstTip) {
            return std::nullopt;
        }
    }
    return firstTip;
}

std::optional<NcDialect> LoadedProgram::dialect() const {
    if (const auto* gcode = std::get_if<nc::GcodeProgram>(&document)) {
        return gcode->dialect;
    }
    return std::nullopt;
}

ProgramFormat LoadedProgram::format() const {
    if (std::holds_alternative<nc::GcodeProgram>(document)) {
        return ProgramFormat::Gcode;
    }
    return std::holds_alternative<cl::AptProgram>(document) ? ProgramFormat::Apt
                                                            : ProgramFormat::Table;
}

namespace {

// The formats whose readers keep a copy of their own: CL data and point tables.
Result<LoadedProgram> readTextFormat(std::string_view text, std::string_view fileName,
                                     ProgramFormat format, const ReadOptions& options) {
    if (format == ProgramFormat::Table) {
        auto table = table::parsePointTable(text, fileName, options);
        if (!table) {
            return std::unexpected(table.error());
        }
        return LoadedProgram{std::move(*table), options, std::nullopt};
    }
    auto apt = cl::parseApt(text, fileName, options);
    if (!apt) {
        return std::unexpected(apt.error());
    }
    return LoadedProgram{std::move(*apt), options, std::nullopt};
}

// Such a program read and turned into the engine's frame, the one place every read does it.
Result<LoadedProgram> parseTextFormat(std::string_view text, std::string_view fileName,
                                      ProgramFormat format, const kinematics::MachineModel& machine,
                                      const ReadOptions& options) {
    auto program = readTextFormat(text, fileName, format, options);
    if (program) {
        toEngineFrame(program->mutablePath().records, machine);
    }
    return program;
}

} // namespace

void toEngineFrame(std::span<toolpath::ClRecord> records, const kinematics::MachineModel& machine) {
    if (!machine.turnsAboutY()) {
        return;
    }
    for (toolpath::ClRecord& record : records) {
        record.tip = machine.toEngineFrame(record.tip);
        record.axis = machine.toEngineFrame(record.axis);
    }
}

void toProgramFrame(std::span<toolpath::ClRecord> records,
                    const kinematics::MachineModel& machine) {
    if (!machine.turnsAboutY()) {
        return;
    }
    for (toolpath::ClRecord& record : records) {
        record.tip = machine.toProgramFrame(record.tip);
        record.axis = machine.toProgramFrame(record.axis);
    }
}

Result<LoadedProgram> parseOwnedProgram(std::string text, std::string_view fileName,
                                        ProgramFormat format,
                                        const kinematics::MachineModel& machine,
                                        const ReadOptions& options, const ReadWatch& watch) {
    if (format != ProgramFormat::Gcode) {
        auto program = parseTextFormat(text, fileName, format, machine, options);
        if (program && isCancelled(watch.cancel)) {
            return std::unexpected(cancelledError());
        }
        return program;
    }
    auto program = nc::parseOwnedGcode(std::move(text), fileName, machine, options, watch);
    if (!program) {
        return std::unexpected(program.error());
    }
    ReadOptions resolved = options;
    resolved.angleUnit = program->angleUnit; // the written program is read back in it
    return LoadedProgram{std::move(*program), resolved, std::nullopt};
}

Result<std::size_t>
streamProgramRecords(std::string_view text, std::string_view fileName, ProgramFormat format,
                     const kinematics::MachineModel& machine, const ReadOptions& options,
                     const nc::RecordChunkConsumer& consume, const nc::TextReadUpTo& readUpTo) {
    if (format == ProgramFormat::Gcode) {
        return nc::streamGcodeRecords(text, fileName, machine, options, consume, readUpTo);
    }
    auto program = parseTextFormat(text, fileName, format, machine, options);
    if (!program) {
        return std::unexpected(program.error());
    }
    const std::vector<toolpath::ClRecord>& records = program->path().records;
    if (Status taken = consume(0, records); !taken) {
        return std::unexpected(taken.error());
    }
    return records.size();
}

Result<LoadedProgram> parseProgram(std::string_view text, std::string_view fileName,
                                   ProgramFormat format, const kinematics::MachineModel& machine,
                                   const ReadOptions& options) {
    if (format != ProgramFormat::Gcode) {
        return parseTextFormat(text, fileName, format, machine, options); // no copy of the text
    }
    return parseOwnedProgram(std::string(text), fileName, format, machine, options);
}

namespace {

Result<LoadedProgram> readOwnedProgramText(std::string text, const std::filesystem::path& path,
                                           const kinematics::MachineModel& machine,
                                           const ReadOptions& options, const ReadWatch& watch) {
    auto probed = detectFormat(path, text);
    if (!probed) {
        return std::unexpected(probed.error());
    }
    auto program =
        parseOwnedProgram(std::move(text), path.string(), probed->format, machine, options, watch);
    if (program && probed->warning) {
        program->mutablePath().warnings.insert(program->mutablePath().warnings.begin(),
                                               *probed->warning);
    }
    return program;
}

} // namespace

Result<LoadedProgram> readProgramText(std::string_view text, const std::filesystem::path& path,
                                      const kinematics::MachineModel& machine,
                                      const ReadOptions& options, const ReadWatch& watch) {
    return readOwnedProgramText(std::string(text), path, machine, options, watch);
}

Result<LoadedProgram> loadProgram(const std::filesystem::path& path,
                                  const kinematics::MachineModel& machine,
                                  const ReadOptions& options, const ReadWatch& watch) {
    auto text = readTextFile(path);
    if (!text) {
        return std::unexpected(text.error());
    }
    return readOwnedProgramText(std::move(*text), path, machine, options, watch);
}

} // namespace bladeaxis::io
