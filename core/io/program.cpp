#include "core/io/program.h"

#include "core/base/file_io.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace bladeaxis::io {

const char* toString(AngleUnit unit) {
    return unit == AngleUnit::Degrees ? "deg" : "rad";
}

const char* toString(ProgramFormat format) {
    return format == ProgramFormat::Gcode ? "gcode" : "apt";
}

namespace {

std::string lowerExtension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

bool containsGotoStatement(std::string_view text) {
    const std::string_view head = text.substr(0, std::min<std::size_t>(text.size(), 1 << 16));
    for (std::size_t at = head.find('/'); at != std::string_view::npos;
         at = head.find('/', at + 1)) {
        if (at >= 4) {
            std::string word(head.substr(at - 4, 4));
            std::transform(word.begin(), word.end(), word.begin(),
                           [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
            if (word == "GOTO") {
                return true;
            }
        }
    }
    return false;
}

} // namespace

ProgramFormat probeFormat(const std::filesystem::path& path, std::string_view text) {
    static constexpr std::array<std::string_view, 6> kGcode{".nc",    ".ngc", ".tap",
                                                            ".gcode", ".mpf", ".iso"};
    static constexpr std::array<std::string_view, 5> kApt{".cl", ".cls", ".apt", ".aptsource",
                                                          ".clsf"};
    const std::string extension = lowerExtension(path);
    if (std::find(kGcode.begin(), kGcode.end(), extension) != kGcode.end()) {
        return ProgramFormat::Gcode;
    }
    if (std::find(kApt.begin(), kApt.end(), extension) != kApt.end()) {
        return ProgramFormat::Apt;
    }
    return containsGotoStatement(text) ? ProgramFormat::Apt : ProgramFormat::Gcode;
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

ProgramFormat LoadedProgram::format() const {
    return std::holds_alternative<nc::GcodeProgram>(document) ? ProgramFormat::Gcode
                                                              : ProgramFormat::Apt;
}

Result<LoadedProgram> parseProgram(std::string_view text, std::string_view fileName,
                                   ProgramFormat format, const kinematics::MachineModel& machine,
                                   const ReadOptions& options) {
    if (format == ProgramFormat::Gcode) {
        auto program = nc::parseGcode(text, fileName, machine, options);
        if (!program) {
            return std::unexpected(program.error());
        }
        ReadOptions resolved = options;
        resolved.angleUnit = program->angleUnit; // the written program is read back in it
        return LoadedProgram{std::move(*program), resolved};
    }
    auto program = cl::parseApt(text, fileName, options);
    if (!program) {
        return std::unexpected(program.error());
    }
    return LoadedProgram{std::move(*program), options};
}

Result<LoadedProgram> loadProgram(const std::filesystem::path& path,
                                  const kinematics::MachineModel& machine,
                                  const ReadOptions& options) {
    auto text = readTextFile(path);
    if (!text) {
        return std::unexpected(text.error());
    }
    return parseProgram(*text, path.string(), probeFormat(path, *text), machine, options);
}

} // namespace bladeaxis::io
