#include "core/io/nc/detail/heidenhain_scanner.h"

#include "core/base/number_io.h"
#include "core/io/nc/detail/scan_helpers.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace bladeaxis::io::nc::detail {

namespace {

struct Token {
    std::size_t begin = 0;
    std::string_view text;
};

// The next blank-separated token, or an empty one at a comment or the end of the line.
Token nextToken(std::string_view line, std::size_t& i) {
    while (i < line.size() && isBlank(line[i])) {
        ++i;
    }
    if (i >= line.size() || line[i] == ';') {
        return {i, {}};
    }
    const std::size_t begin = i;
    while (i < line.size() && !isBlank(line[i]) && line[i] != ';') {
        ++i;
    }
    return {begin, line.substr(begin, i - begin)};
}

std::string upperCase(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(), upper);
    return out;
}

ScanIssue refusal(const Token& token, std::string_view why) {
    return issueAt(token.begin, "'" + std::string(token.text) + "': " + std::string(why));
}

// The number after a word's letters ("X+10.5" from offset 1), for words the reader keeps.
std::optional<ScanIssue> readWordNumber(std::string_view line, const Token& token,
                                        std::size_t letters, WordSpan& word) {
    word.letter = static_cast<std::uint32_t>(token.begin);
    const std::size_t begin = token.begin + letters;
    if (auto issue = readNumber(line, begin, token.text[letters - 1], word)) {
        return issue;
    }
    if (word.valueEnd != token.begin + token.text.size()) {
        return issueAt(word.valueEnd,
                       "unexpected characters after '" +
                           std::string(line.substr(token.begin, word.valueEnd - token.begin)) +
                           "': expected a blank before the next word");
    }
    return std::nullopt;
}

std::optional<ScanIssue> addGCode(ScannedBlock& block, std::size_t at, double value) {
    if (block.gCount == kMaxGCodesPerBlock) {
        return issueAt(at, "too many G codes in one block");
    }
    WordSpan g;
    g.letter = static_cast<std::uint32_t>(at);
    g.value = value;
    block.gCodes[static_cast<std::size_t>(block.gCount++)] = g;
    return std::nullopt;
}

// "M3", "M126": the control bits and program end they mean; other M functions are kept.
std::optional<ScanIssue> scanMWord(std::string_view line, const Token& token, ScannedBlock& block) {
    WordSpan word;
    if (auto issue = readWordNumber(line, token, 1, word)) {
        return issue;
    }
    const double m = word.value;
    if (m == 2.0 || m == 30.0) {
        block.programEnd = true;
    } else if (m == 126.0 || m == 127.0) {
        block.controls |= m == 126.0 ? kShortestPathOn : kShortestPathOff;
    } else if (m == 128.0 || m == 129.0) {
        block.controls |= m == 128.0 ? kToolTipOn : kToolTipOff;
    } else if (m == 91.0 || m == 92.0) {
        return addGCode(block, token.begin, 53.0); // machine datum: like ISO G53
    } else if (m == 140.0) {
        return refusal(token, "retraction along the tool axis: the position it reaches depends "
                              "on the machine; post the retract as an L block");
    }
    return std::nullopt;
}

std::optional<ScanIssue> scanFeed(std::string_view line, const Token& token, ScannedBlock& block) {
    const std::string text = upperCase(token.text);
    if (text == "FMAX") {
        block.gCodes[0].value = 0.0; // rapid for this block only; F stays as it was
        return std::nullopt;
    }
    if (text == "FAUTO") {
        block.controls |= kFeedAuto;
        return std::nullopt;
    }
    if (text.starts_with("FU") || text.starts_with("FZ")) {
        return refusal(token, "feed per revolution or per tooth is not supported: expected F in "
                              "mm/min, FMAX or FAUTO");
    }
    WordSpan word;
    if (auto issue = readWordNumber(line, token, 1, word)) {
        return issue;
    }
    return storeWord('F', word, block);
}

// One word of an L block.
std::optional<ScanIssue> scanLinearWord(std::string_view line, const Token& token,
                                        ScannedBlock& block) {
    const char first = upper(token.text[0]);
    const char second = token.text.size() > 1 ? upper(token.text[1]) : '\0';
    if (first == 'I' && std::string_view("XYZ").find(second) != std::string_view::npos) {
        return refusal(token, "incremental linear words are not supported: post absolute X Y Z");
    }
    if (first == 'I' && (second == 'A' || second == 'B')) {
        WordSpan word;
        if (auto issue = readWordNumber(line, token, 2, word)) {
            return issue;
        }
        word.form = RotaryForm::Incremental;
        return storeWord(second, word, block);
    }
    if (std::string_view("XYZABC").find(first) != std::string_view::npos) {
        WordSpan word;
        if (auto issue = readWordNumber(line, token, 1, word)) {
            return issue;
        }
        return storeWord(first, word, block);
    }
    if (first == 'R') {
        return upperCase(token.text) == "R0"
                   ? std::nullopt
                   : std::optional(refusal(token, "radius compensation is not supported: post "
                                                  "tool positions with R0"));
    }
    if (first == 'F') {
        return scanFeed(line, token, block);
    }
    if (first == 'M') {
        return scanMWord(line, token, block);
    }
    return refusal(token, "unexpected word in an L block: expected X Y Z A B C (IA IB), R0, "
                          "F / FMAX / FAUTO or M words");
}

std::optional<ScanIssue> scanLinear(std::string_view line, std::size_t i, std::size_t at,
                                    ScannedBlock& block) {
    if (auto issue = addGCode(block, at, 1.0)) {
        return issue;
    }
    for (Token token = nextToken(line, i); !token.text.empty(); token = nextToken(line, i)) {
        if (auto issue = scanLinearWord(line, token, block)) {
            return issue;
        }
        block.codeEnd = static_cast<std::uint32_t>(token.begin + token.text.size());
    }
    return std::nullopt;
}

constexpr double kMaxToolNumber = 32767.0;

// "TOOL DEF 1 L+0 R+4" / "TOOL CALL 1 Z S12000 F3000 DR+0.02".
std::optional<ScanIssue> scanTool(std::string_view line, std::size_t i, const Token& what,
                                  ScannedBlock& block) {
    const std::string kind = upperCase(what.text);
    if (kind != "DEF" && kind != "CALL") {
        return refusal(what, "expected TOOL DEF or TOOL CALL");
    }
    block.controls |= kind == "DEF" ? kToolDef : kToolCall;
    const Token number = nextToken(line, i);
    if (const auto value = parseNumber(number.text)) {
        // TNC tool tables hold numbers 0 to 32767; anything else is not a tool number (and
        // would not fit the int it is kept in).
        if (!(*value >= 0.0 && *value <= kMaxToolNumber) || std::floor(*value) != *value) {
            return refusal(number, "expected a tool number from 0 to 32767");
        }
        block.tool.number = static_cast<int>(*value);
    }
    for (Token token = nextToken(line, i); !token.text.empty(); token = nextToken(line, i)) {
        const std::string text = upperCase(token.text);
        WordSpan word;
        if (text == "Z") {
            continue;
        }
        if (text == "X" || text == "Y") {
            return refusal(token, "a tool axis other than Z is not supported: the machine's tool "
                                  "axis is +Z at B = 0");
        }
        const std::size_t letters =
            text.starts_with("DR2") ? 3
                                    : (text.starts_with("DR") || text.starts_with("DL") ? 2 : 1);
        if (auto issue = readWordNumber(line, token, letters, word)) {
            return issue;
        }
        if (kind == "DEF" && text.starts_with("R")) {
            block.tool.radius = word.value;
        } else if (kind == "CALL" && letters == 2 && text.starts_with("DR")) {
            block.tool.deltaRadius = word.value;
        } else if (kind == "CALL" && text.starts_with("F")) {
            block.tool.feed = word.value;
        }
    }
    return std::nullopt;
}

std::optional<ScanIssue> scanBegin(std::string_view line, std::size_t i, std::size_t at,
                                   ScannedBlock& block) {
    Token token = nextToken(line, i);
    if (upperCase(token.text) != "PGM") {
        return issueAt(token.begin, "expected BEGIN PGM");
    }
    nextToken(line, i); // the program's name
    token = nextToken(line, i);
    const std::string unit = upperCase(token.text);
    if (unit == "INCH") {
        return refusal(token, "inch programs are not supported for Heidenhain (their feeds are "
                              "in 0.1 inch/min); post the program in MM");
    }
    if (unit != "MM") {
        return issueAt(token.begin, "expected MM after the program's name");
    }
    return addGCode(block, at, 21.0);
}

std::optional<ScanIssue> scanFunction(std::string_view line, std::size_t i, const Token& what,
                                      ScannedBlock& block) {
    const std::string kind = upperCase(what.text);
    const std::string rest = upperCase(line.substr(i, line.find(';', i) - i));
    if (kind == "TCPM") {
        if (rest.find("SPAT") != std::string::npos) {
            return refusal(what, "spatial angles (AXIS SPAT) are not supported: expected "
                                 "FUNCTION TCPM ... AXIS POS (A and B as axis positions)");
        }
        block.controls |= kToolTipOn;
        return std::nullopt;
    }
    if (kind == "RESET" && rest.find("TCPM") != std::string::npos) {
        block.controls |= kToolTipOff;
        return std::nullopt;
    }
    if (kind == "MODE") {
        return std::nullopt;
    }
    return refusal(what, "unknown FUNCTION: expected FUNCTION TCPM, FUNCTION RESET TCPM or "
                         "FUNCTION MODE");
}

std::optional<ScanIssue> scanCycle(std::string_view line, std::size_t i, const Token& what) {
    if (upperCase(what.text) == "DEF") {
        const Token number = nextToken(line, i);
        const std::optional<double> cycle = parseNumber(number.text);
        if (cycle && std::floor(*cycle) == 32.0) {
            return std::nullopt; // the path tolerance: no motion
        }
    }
    return refusal(what, "cycles other than CYCL DEF 32 (tolerance) are not supported: datum "
                         "shifts, rotations, mirrors, scaling, tilted planes and machining "
                         "cycles change or add motion BladeAxis would not see");
}

constexpr std::array<std::string_view, 7> kArcs{"CC", "C", "CP", "CR", "CT", "RND", "CHF"};

std::optional<ScanIssue> scanStatement(std::string_view line, std::size_t& i, const Token& head,
                                       ScannedBlock& block) {
    const std::string name = upperCase(head.text);
    block.hasWords = true;
    block.codeEnd = static_cast<std::uint32_t>(line.size());
    if (name == "L") {
        block.codeEnd = static_cast<std::uint32_t>(head.begin + 1);
        return scanLinear(line, i, head.begin, block);
    }
    if (name == "BEGIN") {
        return scanBegin(line, i, head.begin, block);
    }
    if (name == "END") {
        block.programEnd = true;
        return std::nullopt;
    }
    if (name == "TOOL") {
        const Token what = nextToken(line, i);
        return scanTool(line, i, what, block);
    }
    if (name == "FUNCTION") {
        const Token what = nextToken(line, i);
        return scanFunction(line, i, what, block);
    }
    if (name == "CYCL") {
        const Token what = nextToken(line, i);
        return scanCycle(line, i, what);
    }
    if (name == "PLANE") {
        const Token what = nextToken(line, i);
        return upperCase(what.text) == "RESET"
                   ? std::nullopt
                   : std::optional(refusal(head, "a tilted working plane turns the coordinates: "
                                                 "post the program without PLANE"));
    }
    if (name == "BLK" || name == "STOP") {
        for (Token token = nextToken(line, i); name == "STOP" && !token.text.empty();
             token = nextToken(line, i)) {
            if (auto issue = scanMWord(line, token, block)) {
                return issue;
            }
        }
        return std::nullopt;
    }
    if (name.size() > 1 && name[0] == 'M' && parseNumber(std::string_view(name).substr(1))) {
        return scanMWord(line, head, block);
    }
    if (std::find(kArcs.begin(), kArcs.end(), name) != kArcs.end()) {
        return refusal(head, "arcs are not supported in four-axis programs: post straight L "
                             "blocks");
    }
    if (name == "APPR" || name == "DEP" || name == "LN" || name == "LP") {
        return refusal(head, "approach/departure contours, LN vectors and polar lines are not "
                             "supported: post straight L blocks with A and B");
    }
    if (name == "FN" || name.starts_with("Q") || name == "LBL" || name == "CALL" || name == "SEL" ||
        name == "DECLARE") {
        return refusal(head, "Q parameters, labels and program calls are not supported: "
                             "BladeAxis reads one flat program with a number in every word");
    }
    return refusal(head, "unknown Heidenhain statement; a program BladeAxis does not understand "
                         "is not rewritten");
}

} // namespace

std::optional<ScanIssue> scanHeidenhainBlock(std::string_view line, ScannedBlock& block) {
    resetBlock(block);
    std::size_t i = 0;
    while (i < line.size() && isBlank(line[i])) {
        ++i;
    }
    while (i < line.size() && isDigit(line[i])) {
        ++i; // the block number
    }
    for (std::size_t c = 0; c < line.size(); ++c) {
        if (line[c] == ';') {
            block.firstComment = static_cast<std::uint32_t>(c);
            if (auto issue = checkCommentBytes(line, c + 1, line.size())) {
                return issue;
            }
            break;
        }
    }
    const Token head = nextToken(line, i);
    if (head.text.empty() || head.text.starts_with("*")) {
        return std::nullopt; // a blank line, a comment or a "* - section" line
    }
    if (!isLetter(head.text[0])) {
        return unexpectedCharacter(line, head.begin);
    }
    std::size_t after = head.begin;
    while (after < line.size() && (isLetter(line[after]) || isDigit(line[after]))) {
        ++after;
    }
    const Token word{head.begin, line.substr(head.begin, after - head.begin)};
    i = after;
    return scanStatement(line, i, word, block);
}

} // namespace bladeaxis::io::nc::detail
