#pragma once
// What the user tells the readers that the file itself may not say: the unit of the rotary
// words, the feed and the columns of a point table. A reader that needs one of these and finds
// it neither in the file nor here refuses the file and names the option.

#include <optional>
#include <string>

namespace bladeaxis::io {

enum class AngleUnit { Degrees, Radians };

struct ReadOptions {
    // The unit of A/B words in G-code; empty: from the post header or the values, and a file
    // that could be either is refused (`--angle-unit deg|rad`).
    std::optional<AngleUnit> angleUnit;
    // Tip feed (mm/s) for CL data that programs none (bare GOTO lists, point tables).
    std::optional<double> feedMmPerS;
    // The column names of a point table without a header line, e.g. "x,y,z,i,j,k".
    std::optional<std::string> tableColumns;
};

const char* toString(AngleUnit unit);

} // namespace bladeaxis::io
