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

namespace {

std::string describeCutter(const toolpath::StatedCutter& cutter) {
    return "the program's cutter " + cutter.statement + " is not a ball end (corner radius " +
           formatShortest(cutter.cornerRadius) + " mm, half its diameter " +
           formatShortest(0.5 * cutter.diameter) + " mm)";
}

} // namespace

Status checkStatedCutter(const io::LoadedProgram& program, std::optional<double> given,
                         bool reschedules, std::vector<std::string>& warnings) {
    const toolpath::Toolpath& path = program.path();
    if (!path.nonBallCutter) {
        return {};
    }
    const toolpath::StatedCutter& cutter = *path.nonBallCutter;
    const std::string where = path.sourceFile + ":" + std::to_string(cutter.line) + ": ";
    if (given) {
        warnings.push_back(where + describeCutter(cutter) + "; it is re-scheduled as a ball of " +
                           formatShortest(*given) +
                           " mm as the job states, while the written program still states " +
                           cutter.statement);
        return {};
    }
    if (!reschedules) {
        warnings.push_back(where + describeCutter(cutter) + ": the figures use no ball radius");
        return {};
    }
    return makeError(
        ErrorCode::Geometry,
        describeCutter(cutter) +
            ": re-orienting a flat or bull-nose cutter moves its contact point and "
            "changes the surface; BladeAxis re-schedules ball-end cutters only. If the "
            "tool is a ball, state its radius (--tool-radius, job key tool_radius_mm)",
        SourceLocation{path.sourceFile, cutter.line, 0});
}

} // namespace bladeaxis::job
