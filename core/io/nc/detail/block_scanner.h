#pragma once
// Splits one line of G-code into words without allocating: a letter, optional blanks, a number.
// Only the lexical level lives here (comments, block delete, '%', repeated words, numbers);
// what the words mean is the interpreter's job.

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
    std::uint32_t letter = 0;
    std::uint32_t valueBegin = 0;
    std::uint32_t valueEnd = 0;
    double value = 0.0;

    std::string_view text(std::string_view line) const {
        return line.substr(valueBegin, valueEnd - valueBegin);
    }
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

} // namespace bladeaxis::io::nc::detail
