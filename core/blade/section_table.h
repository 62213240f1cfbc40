#pragma once
// Blade sections given as point tables (spec §10.4 "real-shaped data"), one closed section per
// span station.
//
// Text format (UTF-8/ASCII, numbers in C-locale notation, mm):
//
//     # comment: from '#' to the end of the line is ignored, as are blank lines
//     station 0.0          # starts a section at x = 0.0 (x along the rotary axis A)
//     40.0   0.0           # one "y z" point per line, in W coordinates
//     20.0   4.5
//     ...
//     station 10.0
//     ...
//
// Every station needs >= 3 points; stations must be strictly increasing in x and there must
// be at least 2. The polygon is closed implicitly (a repeated first point is dropped) and its
// orientation is normalised to counter-clockwise in (y, z). Sections are used as given (their
// stacking is part of the data); each section is rotated to start at its phase vertex
// (closed_curve.h: phaseIndex). Errors carry file:line and say what was expected; up to 20
// problems are reported in one go.

#include "core/base/error.h"
#include "core/blade/closed_curve.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace bladeaxis::blade {

struct SectionStation {
    double x = 0.0; // mm along the rotary axis
    Curve2 points;  // closed, counter-clockwise, vertex 0 = phase vertex
    int line = 0;   // line of the "station" header in the source, 0 if built in code
};

struct SectionTable {
    std::string sourceFile;
    std::vector<SectionStation> stations; // strictly increasing x
};

Result<SectionTable> readSectionTable(std::string_view text, std::string_view fileName);
Result<SectionTable> readSectionTableFile(const std::filesystem::path& path);

// Normalises every station (closed_curve.h) and checks the station order; used by the reader
// and for tables built in code.
Result<SectionTable> normaliseSectionTable(SectionTable table);

} // namespace bladeaxis::blade
