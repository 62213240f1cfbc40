#pragma once
// The parsed form of a G-code family program (ISO/Fanuc, Sinumerik, Heidenhain): the toolpath every
// stage consumes, plus a compact description of where each CL record came from in the original
// text, so that a writer can change exactly the X Y Z A B words of a block and copy every other
// byte.

#include "core/io/read_options.h"
#include "core/toolpath/toolpath.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace bladeaxis::io::nc {

// Marks an axis that has no word in a record's block (its value is modal).
inline constexpr std::uint16_t kNoWord = 0xFFFF;

// Per-record modal flags needed to write the block back in its own terms.
enum RecordFlag : std::uint8_t {
    kIncremental = 1, // G91: axis words are increments
    kInch = 2,        // G20: linear words are inches
    // G93: F is the inverse of the block's time, so a block whose tip chord changes changes its
    // tip speed when written back with the same F (its ball-centre speed does not).
    kInverseTime = 4,
    // Tool-tip programming (Sinumerik TRAORI, Heidenhain M128 / FUNCTION TCPM): X Y Z are the
    // tool tip in the workpiece frame, the control moves the machine axes.
    kToolTip = 8,
    // G94 on a control that reads F over the combined axis move (FeedMeaning::CombinedAxes):
    // the block's time depends on its A and B steps, so a re-scheduled block gets a new F.
    kCombinedFeed = 16,
};

// How a rotary word of a Sinumerik or Heidenhain block reaches its value. ISO words are Plain.
enum class RotaryForm : std::uint8_t {
    Plain,       // G90 absolute (G91: an increment), "A45." / "A=45"
    Absolute,    // "A=AC(45)": absolute in any G90/G91 mode
    Shortest,    // "A=DC(45)", or Heidenhain M126: to 45 mod 360 the shortest way
    Positive,    // "A=ACP(45)": to 45 mod 360 turning in the positive direction
    Negative,    // "A=ACN(45)": to 45 mod 360 turning in the negative direction
    Incremental, // "A=IC(5)", Heidenhain "IA+5": an increment in any mode
};

// Where one CL record lives in GcodeProgram::text. Offsets, not strings: 24 bytes per record,
// so a million-block program costs 24 MB here.
struct RecordSource {
    std::uint32_t lineBegin = 0; // byte offset of the first character of the block's line
    // Offset of each axis word's number (after the letter) from lineBegin, in AxisId order
    // (X Y Z A B); kNoWord when the block has no word for that axis.
    std::array<std::uint16_t, 5> wordBegin{kNoWord, kNoWord, kNoWord, kNoWord, kNoWord};
    std::array<std::uint8_t, 5> wordLength{}; // characters of that number
    std::uint8_t flags = 0;                   // RecordFlag bits
    // Bit i set: axis i was last set by a block that is not a record (leading partial rapids,
    // the program start), so its modal value here is the original one, whatever the rewrite.
    std::uint8_t setOutside = 0;
    // How the block's A and B words reach their values; for an axis without a word, the form
    // the program used for it last (an inserted word takes that form: DC stays DC).
    std::array<RotaryForm, 2> rotaryForms{RotaryForm::Plain, RotaryForm::Plain};

    bool hasWord(int axis) const { return wordBegin[static_cast<std::size_t>(axis)] != kNoWord; }
};

// How the file writes the numbers of one axis, learnt from all its words. A file whose words
// carry varying decimals ("X10." "X10.25") trims trailing zeros; otherwise it writes a fixed
// number of decimals.
struct AxisNumberStyle {
    bool seen = false;
    int minDecimals = 0;
    int maxDecimals = 0;
    bool trailingPoint = false; // some word ends in "." ("X10.")
    bool leadingZero = true;    // "0.5" rather than ".5"
    bool explicitPlus = false;  // "+1.5"

    bool trimsZeros() const { return seen && (minDecimals != maxDecimals || trailingPoint); }
};

struct GcodeProgram {
    toolpath::Toolpath path;
    std::string text;                  // the original program, byte for byte
    std::vector<RecordSource> sources; // one per path.records entry, same order
    std::array<AxisNumberStyle, 5> axisStyles{};
    AngleUnit angleUnit = AngleUnit::Degrees; // of the rotary words, as read (and written back)
    NcDialect dialect = NcDialect::Iso;
    // With kCombinedFeed records: the F in effect at each record (file units per minute), so
    // the writer can give a block whose axis steps change the F that keeps its time.
    std::vector<double> programmedFeeds;
};

} // namespace bladeaxis::io::nc
