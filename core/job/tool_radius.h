#pragma once
// Where a program's ball radius comes from, and the one rule for a radius given beside it
// (--tool-radius, a job file's tool_radius_mm, the window's tool bar): the given radius is used,
// and a given radius that disagrees with the one the program states is a conflict the batch
// warns about and the window shows and asks about before it exports.

#include "core/base/error.h"
#include "core/io/program.h"

#include <optional>
#include <string>
#include <vector>

namespace bladeaxis::job {

// The statement the program's radius was read from, as the engineer knows it: "CUTTER/TLDATA"
// (APT, CLSF), "TOOL DEF" (Heidenhain), "header comment" (a G-code post's (T1 D=8. CR=4.) or the
// generator's (ball end R=8 mm ...)); empty when the program states none.
std::string statedRadiusSource(const io::LoadedProgram& program);

// Whether `given` and the program's stated radius differ beyond rounding (1e-9 relative); false
// when either is missing.
bool toolRadiusDisagrees(std::optional<double> given, std::optional<double> stated);

// The warning of a given radius that disagrees with the stated one, naming the file, both radii
// and the statement; empty when they agree or either is missing.
std::string toolRadiusConflict(std::optional<double> given, const io::LoadedProgram& program);

// A flat or bull-nose cutter the program states (toolpath::StatedCutter): re-scheduling it is
// refused (Geometry, at the statement's line) unless the job gives a ball radius, in which case
// a warning says the stated cutter is overruled; an analysis alone only warns.
Status checkStatedCutter(const io::LoadedProgram& program, std::optional<double> given,
                         bool reschedules, std::vector<std::string>& warnings);

} // namespace bladeaxis::job
