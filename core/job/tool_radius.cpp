#include "core/job/tool_radius.h"

#include "core/base/number_io.h"

#include <algorithm>
#include <cmath>

namespace bladeaxis::job {

std::string statedRadiusSource(const io::LoadedProgram& program) {
    if (!program.path().toolRadius) {
        return {};
    }
    switch (program.format()) {
    case io::ProgramFormat::Apt:
        return "CUTTER/TLDATA";
    case io::ProgramFormat::Gcode:
        return program.dialect() == io::NcDialect::Heidenhain ? "TOOL DEF" : "header comment";
    case io::ProgramFormat::Table:
        break;
    }
    return "the file";
}

bool toolRadiusDisagrees(std::optional<double> given, std::optional<double> stated) {
    return given && stated && std::abs(*given - *stated) > 1e-9 * std::max(1.0, *stated);
}

std::string toolRadiusConflict(std::optional<double> given, const io::LoadedProgram& program) {
    const toolpath::Toolpath& path = program.path();
    if (!toolRadiusDisagrees(given, path.toolRadius)) {
        return {};
    }
    return path.sourceFile + ": the ball radius " + formatShortest(*given) +
           " mm given replaces the file's " + formatShortest(*path.toolRadius) + " mm (" +
           statedRadiusSource(program) + "): every ball centre is computed with " +
           formatShortest(*given) + " mm, while the written program still states " +
           formatShortest(*path.toolRadius) + " mm";
}

} // namespace bladeaxis::job
