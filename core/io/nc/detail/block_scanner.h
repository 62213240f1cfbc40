#pragma once
// Splits one line of G-code into words without allocating: a letter, optional blanks, a number.
// Only the lexical level lives here (comments, block delete, '%', repeated words, numbers);
// what the words mean is the interpreter's job. Sinumerik and Heidenhain lines are scanned into
// the same words (sinumerik_scanner.h, heidenhain_scanner.h), with the dialect's instructions
// that matter to a four-axis reader as BlockControl bits.

#include "core/io/nc/detail/number_style.h"
#include "core/io/nc/gcode_program.h"
#include "core/io/read_options.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace bladeaxis::io::nc::detail {

inline constexpr std::uint32_t kNoOffset = 0xFFFFFFFFu;
inline constexpr int kMaxGCodesPerBlock = 10;
// Larger magnitudes are typing errors in any word of a machining program.
inline constexpr double kMaxWordMagnitude = 1e9;

// One word; offsets from the start of the line.
struct WordSpan {
    std::uint32_t letter = 0; // the word's first character ("A", the "I" of "IA+5")
    std::uint32_t valueBegin = 0;
    std::uint32_t valueEnd = 0;
    RotaryForm form = RotaryForm::Plain; // "A=DC(45)" is Shortest; ISO words are Plain
    double value = 0.0;
    // How a plain decimal ("-12.5", no exponent) is written, noted while reading it so that the
    // axis style need not read the text again; empty for other spellings.
    std::optional<WordTextStyle> plainStyle;

    std::string_view text(std::string_view line) const {
        return line.substr(valueBegin, valueEnd - valueBegin);
    }
};

// Instructions of the Sinumerik and Heidenhain dialects that change how later words read.
enum BlockControl : std::uint16_t {
    kToolTipOn = 1,       // TRAORI, M128, FUNCTION TCPM
    kToolTipOff = 2,      // TRAFOOF, M129, FUNCTION RESET TCPM
    kShortestPathOn = 4,  // Heidenhain M126: absolute rotary words the shortest way
    kShortestPathOff = 8, // M127
    kFeedAuto = 16,       // Heidenhain FAUTO: the feed of the TOOL CALL
    kToolCall = 32,       // Heidenhain TOOL CALL: `tool` holds its number, feed and DR
    kToolDef = 64,        // Heidenhain TOOL DEF: `tool` holds its number and R
};

// What a Heidenhain TOOL DEF or TOOL CALL block states.
struct StatedToolData {
    int number = 0;
    std::optional<double> radius;      // TOOL DEF R
    std::optional<double> deltaRadius; // TOOL CALL DR
    std::optional<double> feed;        // TOOL CALL F: the feed of FAUTO blocks
};

struct ScannedBlock {
    std::uint32_t present = 0; // bit (letter - 'A') for every word other than G and M
    std::array<WordSpan, 26> words;
    std::array<WordSpan, kMaxGCodesPerBlock> gCodes;
    int gCount = 0;
    std::uint32_t codeEnd = 0;                // just past the last word's number
    std::uint32_t firstComment = kNoOffset;   // the first '(' or ';'
    bool hasWords = false;                    // any word at all, G and M included
    bool programEnd = false;                  // M2 or M30: the program ends in this block
    std::uint32_t subprogramWord = kNoOffset; // the M98 (call) or M99 (return) word, if any
    std::uint16_t controls = 0;               // BlockControl bits
    StatedToolData tool;                      // with kToolCall / kToolDef

    bool has(char letter) const { return (present >> (letter - 'A')) & 1u; }
    const WordSpan& word(char letter) const {
        return words[static_cast<std::size_t>(letter - 'A')];
    }
};

// A lexical error: where (offset in the line) and what was expected.
struct ScanIssue {
    std::uint32_t offset = 0;
    std::string message;
};

// Scans `line` (without its line ending) into `block`. Returns the first problem found, if any.
std::optional<ScanIssue> scanBlock(std::string_view line, ScannedBlock& block);

// The same for a line of the given dialect.
std::optional<ScanIssue> scanBlock(std::string_view line, ScannedBlock& block, NcDialect dialect);

} // namespace bladeaxis::io::nc::detail
