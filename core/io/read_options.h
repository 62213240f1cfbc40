#pragma once
// What the user tells the readers that the file itself may not say: the unit of the rotary
// words, the feed and the columns of a point table. A reader that needs one of these and finds
// it neither in the file nor here refuses the file and names the option.

#include <optional>
#include <string>

namespace bladeaxis::io {

enum class AngleUnit { Degrees, Radians };

// The NC language of a G-code family program: ISO/Fanuc words, Siemens Sinumerik 840D
// (";" comments, "A=DC(..)", TRAORI...) or Heidenhain conversational ("L X+10 A+45 FMAX").
enum class NcDialect { Iso, Sinumerik, Heidenhain };

struct ReadOptions {
    // The unit of A/B words in G-code; empty: from the post header or the values, and a file
    // that could be either is refused (`--angle-unit deg|rad`).
    std::optional<AngleUnit> angleUnit;
    // Tip feed (mm/s) for CL data that programs none (bare GOTO lists, point tables).
    std::optional<double> feedMmPerS;
    // The column names of a point table without a header line, e.g. "x,y,z,i,j,k".
    std::optional<std::string> tableColumns;
    // The NC dialect; empty: from the content, then the extension (`--dialect`).
    std::optional<NcDialect> dialect;
};

const char* toString(AngleUnit unit);
const char* toString(NcDialect dialect); // "iso", "sinumerik", "heidenhain"

} // namespace bladeaxis::io
