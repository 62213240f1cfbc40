#include "core/io/nc/detail/block_scanner.h"

#include "core/base/number_io.h"
#include "core/io/nc/detail/heidenhain_scanner.h"
#include "core/io/nc/detail/scan_helpers.h"
#include "core/io/nc/detail/sinumerik_scanner.h"

#include <cmath>
#include <cstring>
#include <expected>

namespace bladeaxis::io::nc::detail {

namespace {

// The longest number token accepted; longer ones are junk, not precision.
constexpr std::size_t kMaxNumberLength = 40;

bool isControl(unsigned char c) {
    return (c < 0x20 && !isBlank(static_cast<char>(c))) || c == 0x7F;
}

std::string hexByte(unsigned char c) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    return std::string("0x") + kHex[c >> 4] + kHex[c & 0xF];
}

// A macro variable (#101) or an expression ([#1+2]) where a number belongs.
ScanIssue macroIssue(std::size_t offset, char c) {
    return issueAt(offset, std::string(c == '#' ? "macro variable" : "expression") +
                               " in a word: BladeAxis reads flat programs with a number in every "
                               "word; have the post-processor write the values (no macro "
                               "variables, expressions or custom macros)");
}

// End of a number token: sign, digits and points, and an exponent when one follows. The token
// is taken greedily so that "1.2.3" is reported whole rather than as "1.2" and a stray ".3".
std::size_t numberEnd(std::string_view line, std::size_t begin) {
    std::size_t i = begin;
    if (i < line.size() && (line[i] == '+' || line[i] == '-')) {
        ++i;
    }
    while (i < line.size() && (isDigit(line[i]) || line[i] == '.')) {
        ++i;
    }
    if (i > begin && i < line.size() && (line[i] == 'e' || line[i] == 'E')) {
        std::size_t j = i + 1;
        if (j < line.size() && (line[j] == '+' || line[j] == '-')) {
            ++j;
        }
        if (j < line.size() && isDigit(line[j])) {
            while (j < line.size() && isDigit(line[j])) {
                ++j;
            }
            i = j;
        }
    }
    return i;
}

// True for a token shaped like a number ("-1.5", "2e400"): a failure to parse it means range.
bool looksNumeric(std::string_view token) {
    std::size_t i = 0;
    if (i < token.size() && (token[i] == '+' || token[i] == '-')) {
        ++i;
    }
    int digits = 0;
    int points = 0;
    for (; i < token.size() && token[i] != 'e' && token[i] != 'E'; ++i) {
        digits += isDigit(token[i]) ? 1 : 0;
        points += token[i] == '.' ? 1 : 0;
    }
    return digits > 0 && points <= 1;
}

// Whether the number token goes on at `end` (a second point, an exponent), so that a plain
// decimal read up to there is not the whole token.
bool numberGoesOn(std::string_view line, std::size_t end) {
    if (end == line.size()) {
        return false;
    }
    const char c = line[end];
    return isDigit(c) || c == '.' || c == 'e' || c == 'E';
}

// The number of a word in any spelling the plain-decimal path leaves (exponents, long or
// malformed numbers, magnitudes out of range), with the message for one that cannot be read.
std::optional<ScanIssue> readAnyNumber(std::string_view line, std::size_t begin, char letter,
                                       WordSpan& word) {
    const std::size_t end = numberEnd(line, begin);
    const std::string_view token = line.substr(begin, end - begin);
    // Built on the error paths only: this function runs for every word of the program.
    const auto quoted = [letter] { return std::string("'") + letter + "'"; };
    if (token.empty() && begin < line.size() && (line[begin] == '#' || line[begin] == '[')) {
        return macroIssue(begin, line[begin]);
    }
    if (token.empty() || token == "+" || token == "-") {
        return issueAt(begin, "expected a number after " + quoted());
    }
    if (token.size() > kMaxNumberLength) {
        return issueAt(begin, "number too long after " + quoted());
    }
    const std::optional<double> value = parseNumber(token);
    if (!value) {
        if (looksNumeric(token)) {
            return issueAt(begin, "number out of range after " + quoted() + ": '" +
                                      std::string(token) + "'");
        }
        return issueAt(begin, "expected a number after " + quoted() + ", found '" +
                                  std::string(token) + "'");
    }
    if (std::abs(*value) > kMaxWordMagnitude) {
        return issueAt(begin,
                       "number out of range after " + quoted() + ": '" + std::string(token) + "'");
    }
    word.valueBegin = static_cast<std::uint32_t>(begin);
    word.valueEnd = static_cast<std::uint32_t>(end);
    word.value = *value;
    return std::nullopt;
}

// The ISO scanner's loop runs on the internal functions below, which the compiler inlines into
// it; it would not inline an exported function, the library being built position-independent.
// The exported names forward to them for the Sinumerik and Heidenhain scanners.

// Whether `plain`, read at `begin`, is the word's whole number and within range, as nearly every
// word's is; any other spelling is readAnyNumber's.
inline bool isPlainWordNumber(std::string_view line, std::size_t begin, const PlainDecimal& plain) {
    return plain.length > 0 && !numberGoesOn(line, begin + plain.length) &&
           std::abs(plain.value) <= kMaxWordMagnitude;
}

// Field by field, in place: a word (or its style) built whole and copied in is read back with
// wide loads from narrow stores, which the processor cannot forward, and that stalled every
// word.
inline void setPlainNumber(WordSpan& word, std::string_view line, std::size_t begin,
                           const PlainDecimal& plain) {
    word.valueBegin = static_cast<std::uint32_t>(begin);
    word.valueEnd = static_cast<std::uint32_t>(begin + plain.length);
    word.value = plain.value;
    setPlainDecimalStyle(word.plainStyle.emplace(), line.substr(begin), plain);
}

ScanIssue repeatedWordIssue(char letter, std::uint32_t offset) {
    return issueAt(offset,
                   std::string("word '") + letter + "' repeated in one block: expected it once");
}

// The block's place for a word of `letter` (not G or M), marked present; refused when the block
// already has one.
inline std::expected<WordSpan*, ScanIssue> claimWord(char letter, std::uint32_t letterOffset,
                                                     ScannedBlock& block) {
    const int index = letter - 'A';
    if ((block.present >> index) & 1u) {
        return std::unexpected(repeatedWordIssue(letter, letterOffset));
    }
    block.present |= 1u << index;
    block.hasWords = true;
    return &block.words[static_cast<std::size_t>(index)];
}

// Where an ISO word read up to `valueEnd` goes: its place among the block's words or G codes,
// or none for an M word, which only marks the block. Refused when the block has too many G
// codes or this letter already.
inline std::expected<WordSpan*, ScanIssue> placeIsoWord(char letter, std::uint32_t letterOffset,
                                                        double value, std::size_t valueEnd,
                                                        ScannedBlock& block) {
    block.codeEnd = static_cast<std::uint32_t>(valueEnd);
    block.hasWords = true;
    if (letter == 'M') {
        // Kept verbatim; several M words may share a block. M2/M30 are noted so that a reader
        // can tell a complete program from a truncated one.
        block.programEnd = block.programEnd || value == 2.0 || value == 30.0;
        if (value == 98.0 || value == 99.0) {
            block.subprogramWord = letterOffset;
        }
        return nullptr;
    }
    if (letter == 'G') {
        if (block.gCount == kMaxGCodesPerBlock) {
            return std::unexpected(issueAt(letterOffset, "too many G codes in one block"));
        }
        return &block.gCodes[static_cast<std::size_t>(block.gCount++)];
    }
    return claimWord(letter, letterOffset, block);
}

// An ISO word whose number is not a plain decimal (an exponent, many digits) or is missing.
std::optional<ScanIssue> scanGeneralIsoWord(std::string_view line, std::size_t& i, char letter,
                                            std::uint32_t letterOffset, ScannedBlock& block) {
    WordSpan word;
    word.letter = letterOffset;
    if (auto issue = readAnyNumber(line, i, letter, word)) {
        return issue;
    }
    i = word.valueEnd;
    std::expected<WordSpan*, ScanIssue> place =
        placeIsoWord(letter, letterOffset, word.value, word.valueEnd, block);
    if (!place) {
        return std::move(place.error());
    }
    if (*place != nullptr) {
        **place = word;
    }
    return std::nullopt;
}

// One ISO word (letter, blanks, number) starting at the letter; advances `i` past it.
inline std::optional<ScanIssue> scanIsoWord(std::string_view line, std::size_t& i,
                                            ScannedBlock& block) {
    const char letter = upper(line[i] == ':' ? 'O' : line[i]);
    const auto letterOffset = static_cast<std::uint32_t>(i);
    ++i;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) {
        ++i;
    }
    const std::size_t valueBegin = i;
    const PlainDecimal plain = readPlainDecimal(line.substr(valueBegin));
    if (!isPlainWordNumber(line, valueBegin, plain)) {
        return scanGeneralIsoWord(line, i, letter, letterOffset, block);
    }
    i = valueBegin + plain.length;
    std::expected<WordSpan*, ScanIssue> place =
        placeIsoWord(letter, letterOffset, plain.value, i, block);
    if (!place) {
        return std::move(place.error());
    }
    if (*place != nullptr) {
        WordSpan& word = **place;
        word.letter = letterOffset;
        word.form = RotaryForm::Plain;
        setPlainNumber(word, line, valueBegin, plain);
    }
    return std::nullopt;
}

} // namespace

std::optional<ScanIssue> readNumber(std::string_view line, std::size_t begin, char letter,
                                    WordSpan& word) {
    const PlainDecimal plain = readPlainDecimal(line.substr(begin));
    if (isPlainWordNumber(line, begin, plain)) {
        setPlainNumber(word, line, begin, plain);
        return std::nullopt;
    }
    word.plainStyle.reset();
    return readAnyNumber(line, begin, letter, word);
}

std::optional<ScanIssue> checkCommentBytes(std::string_view line, std::size_t begin,
                                           std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
        if (isControl(static_cast<unsigned char>(line[i]))) {
            return issueAt(i, "binary data (byte " + hexByte(static_cast<unsigned char>(line[i])) +
                                  "): expected a text NC program");
        }
    }
    return std::nullopt;
}

ScanIssue unexpectedCharacter(std::string_view line, std::size_t i) {
    const auto c = static_cast<unsigned char>(line[i]);
    if (isControl(c)) {
        return issueAt(i, "binary data (byte " + hexByte(c) + "): expected a text NC program");
    }
    if (c >= 0x80) {
        return issueAt(i, "unexpected byte " + hexByte(c) + " outside a comment: expected a word");
    }
    if (c == ')') {
        return issueAt(i, "unbalanced parenthesis: ')' without a matching '('");
    }
    if (c == '#' || c == '[') {
        return macroIssue(i, static_cast<char>(c));
    }
    return issueAt(i, std::string("unexpected character '") + static_cast<char>(c) +
                          "': expected a word (a letter followed by a number)");
}

std::optional<ScanIssue> scanWord(std::string_view line, std::size_t& i, ScannedBlock& block) {
    return scanIsoWord(line, i, block);
}

std::optional<ScanIssue> storeWord(char letter, const WordSpan& word, ScannedBlock& block) {
    std::expected<WordSpan*, ScanIssue> claimed = claimWord(letter, word.letter, block);
    if (!claimed) {
        return std::move(claimed.error());
    }
    **claimed = word;
    return std::nullopt;
}

std::string readIdentifier(std::string_view line, std::size_t& i) {
    std::string name;
    while (i < line.size() && (isLetter(line[i]) || isDigit(line[i]) || line[i] == '_')) {
        name += upper(line[i]);
        ++i;
    }
    return name;
}

void resetBlock(ScannedBlock& block) {
    block.present = 0;
    block.gCount = 0;
    block.codeEnd = 0;
    block.firstComment = kNoOffset;
    block.hasWords = false;
    block.programEnd = false;
    block.subprogramWord = kNoOffset;
    block.controls = 0;
    block.tool = {};
}

namespace {

std::optional<ScanIssue> scanComment(std::string_view line, std::size_t& i, ScannedBlock& block) {
    if (block.firstComment == kNoOffset) {
        block.firstComment = static_cast<std::uint32_t>(i);
    }
    if (line[i] == ';') {
        auto issue = checkCommentBytes(line, i + 1, line.size());
        i = line.size();
        return issue;
    }
    const void* close = std::memchr(line.data() + i + 1, ')', line.size() - i - 1);
    if (close == nullptr) {
        return issueAt(i, "unbalanced parenthesis: expected ')' before the end of the line");
    }
    const auto end = static_cast<std::size_t>(static_cast<const char*>(close) - line.data());
    auto issue = checkCommentBytes(line, i + 1, end);
    i = end + 1;
    return issue;
}

} // namespace

std::optional<ScanIssue> scanBlock(std::string_view line, ScannedBlock& block, NcDialect dialect) {
    switch (dialect) {
    case NcDialect::Sinumerik:
        return scanSinumerikBlock(line, block);
    case NcDialect::Heidenhain:
        return scanHeidenhainBlock(line, block);
    case NcDialect::Iso:
        break;
    }
    return scanBlock(line, block);
}

std::optional<ScanIssue> scanBlock(std::string_view line, ScannedBlock& block) {
    resetBlock(block);
    std::size_t i = 0;
    while (i < line.size()) {
        const char c = line[i];
        if (isBlank(c)) {
            ++i;
        } else if (c == '(' || c == ';') {
            if (auto issue = scanComment(line, i, block)) {
                return issue;
            }
        } else if (isLetter(c) || (c == ':' && !block.hasWords)) {
            if (auto issue = scanIsoWord(line, i, block)) {
                return issue;
            }
        } else if (c == '%' && !block.hasWords) {
            return std::nullopt; // tape start/end marker: the rest of the line is ignored
        } else if (c == '/' && !block.hasWords) {
            // Block delete is treated as switched off: the block is active. "/2" names a level.
            i += (i + 1 < line.size() && isDigit(line[i + 1])) ? 2 : 1;
        } else {
            return unexpectedCharacter(line, i);
        }
    }
    return std::nullopt;
}

} // namespace bladeaxis::io::nc::detail
