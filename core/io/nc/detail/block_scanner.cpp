#include "core/io/nc/detail/block_scanner.h"

#include "core/base/number_io.h"
#include "core/io/nc/detail/heidenhain_scanner.h"
#include "core/io/nc/detail/scan_helpers.h"
#include "core/io/nc/detail/sinumerik_scanner.h"

#include <cmath>
#include <cstring>

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

} // namespace

std::optional<ScanIssue> readNumber(std::string_view line, std::size_t begin, char letter,
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

// Scans one word starting at the letter; advances `i` past its number.
std::optional<ScanIssue> scanWord(std::string_view line, std::size_t& i, ScannedBlock& block) {
    const char letter = upper(line[i] == ':' ? 'O' : line[i]);
    const std::size_t letterOffset = i;
    ++i;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) {
        ++i;
    }
    WordSpan word;
    word.letter = static_cast<std::uint32_t>(letterOffset);
    if (auto issue = readNumber(line, i, letter, word)) {
        return issue;
    }
    i = word.valueEnd;
    block.codeEnd = word.valueEnd;
    block.hasWords = true;
    if (letter == 'M') {
        // Kept verbatim; several M words may share a block. M2/M30 are noted so that a reader
        // can tell a complete program from a truncated one.
        block.programEnd = block.programEnd || word.value == 2.0 || word.value == 30.0;
        if (word.value == 98.0 || word.value == 99.0) {
            block.subprogramWord = static_cast<std::uint32_t>(letterOffset);
        }
        return std::nullopt;
    }
    if (letter == 'G') {
        if (block.gCount == kMaxGCodesPerBlock) {
            return issueAt(letterOffset, "too many G codes in one block");
        }
        block.gCodes[static_cast<std::size_t>(block.gCount++)] = word;
        return std::nullopt;
    }
    return storeWord(letter, word, block);
}

std::optional<ScanIssue> storeWord(char letter, const WordSpan& word, ScannedBlock& block) {
    const int index = letter - 'A';
    if ((block.present >> index) & 1u) {
        return issueAt(word.letter, std::string("word '") + letter +
                                        "' repeated in one block: expected it once");
    }
    block.present |= 1u << index;
    block.words[static_cast<std::size_t>(index)] = word;
    block.hasWords = true;
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
            if (auto issue = scanWord(line, i, block)) {
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
