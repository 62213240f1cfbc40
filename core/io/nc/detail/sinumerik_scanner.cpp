#include "core/io/nc/detail/sinumerik_scanner.h"

#include "core/io/nc/detail/scan_helpers.h"

#include <algorithm>
#include <array>
#include <cstring>

namespace bladeaxis::io::nc::detail {

namespace {

// Instructions that change nothing a four-axis reader tracks (orientation interpolation,
// acceleration and look-ahead modes, feed-override styles): kept verbatim.
constexpr std::array<std::string_view, 26> kKeptInstructions{
    "ORIWKS",  "ORIMKS",   "ORIAXES",  "ORIVECT", "ORICONO", "ORIEULER", "ORIRPY",
    "ORISON",  "ORISOF",   "SOFT",     "BRISK",   "DRIVE",   "FFWON",    "FFWOF",
    "COMPCAD", "COMPCURV", "COMPSURF", "COMPOF",  "UPATH",   "SPATH",    "CFC",
    "CFTCP",   "CFIN",     "FNORM",    "STOPRE",  "FLIN"};

// Instructions with arguments that do not move the axes: a high-speed-cutting setting, a
// message on the control's screen, the blank's description.
constexpr std::array<std::string_view, 3> kKeptCalls{"CYCLE832", "MSG", "WORKPIECE"};

constexpr std::array<std::string_view, 14> kFrames{
    "TRANS", "ATRANS", "ROT",    "AROT",    "ROTS",     "AROTS",   "CROTS",
    "SCALE", "ASCALE", "MIRROR", "AMIRROR", "CYCLE800", "TOFRAME", "TOROT"};

constexpr std::array<std::string_view, 22> kControlFlow{
    "DEF",  "GOTO",    "GOTOF", "GOTOB",    "GOTOC", "IF",     "ELSE",   "ENDIF",
    "LOOP", "ENDLOOP", "WHILE", "ENDWHILE", "FOR",   "ENDFOR", "REPEAT", "UNTIL",
    "CALL", "PCALL",   "MCALL", "EXTCALL",  "CASE",  "PROC"};

constexpr std::array<std::string_view, 4> kOtherTransformations{"TRANSMIT", "TRACYL", "TRAANG",
                                                                "TRACON"};

template <std::size_t N>
bool among(const std::array<std::string_view, N>& list, std::string_view name) {
    return std::find(list.begin(), list.end(), name) != list.end();
}

bool isOperator(char c) {
    return c == '+' || c == '-' || c == '*' || c == '/' || c == '<' || c == '>' || c == '=';
}

void skipBlanks(std::string_view line, std::size_t& i) {
    while (i < line.size() && isBlank(line[i])) {
        ++i;
    }
}

// Past a quoted string starting at `i` (on the '"').
std::optional<ScanIssue> skipString(std::string_view line, std::size_t& i) {
    const std::size_t open = i;
    const std::size_t close = line.find('"', i + 1);
    if (close == std::string_view::npos) {
        return issueAt(open, "unbalanced quote: expected '\"' before the end of the line");
    }
    i = close + 1;
    return std::nullopt;
}

// Past the arguments of a call starting at `i` (on the '('), strings and nesting included.
std::optional<ScanIssue> skipArguments(std::string_view line, std::size_t& i) {
    const std::size_t open = i;
    int depth = 0;
    while (i < line.size()) {
        const char c = line[i];
        if (c == '"') {
            if (auto issue = skipString(line, i)) {
                return issue;
            }
            continue;
        }
        depth += c == '(' ? 1 : (c == ')' ? -1 : 0);
        ++i;
        if (depth == 0) {
            return std::nullopt;
        }
    }
    return issueAt(open, "unbalanced parenthesis: expected ')' before the end of the line");
}

std::optional<RotaryForm> formOfFunction(std::string_view name) {
    if (name == "DC") {
        return RotaryForm::Shortest;
    }
    if (name == "ACP") {
        return RotaryForm::Positive;
    }
    if (name == "ACN") {
        return RotaryForm::Negative;
    }
    if (name == "AC") {
        return RotaryForm::Absolute;
    }
    if (name == "IC") {
        return RotaryForm::Incremental;
    }
    return std::nullopt;
}

ScanIssue parameterIssue(std::size_t offset, std::string_view what) {
    return issueAt(offset, std::string(what) +
                               ": R-parameters, variables and expressions are not supported; "
                               "have the post-processor write a number in every axis word");
}

// After a word: the next word, a comment or the end of the line, never an operator.
std::optional<ScanIssue> checkWordEnd(std::string_view line, std::size_t i, char letter) {
    std::size_t next = i;
    skipBlanks(line, next);
    if (next < line.size() && isOperator(line[next])) {
        return parameterIssue(next, std::string("an expression in the word '") + letter + "'");
    }
    return std::nullopt;
}

// "DC(45)": the number inside the function's parentheses, its form in `word`.
std::optional<ScanIssue> readFunctionValue(std::string_view line, std::size_t& i, char letter,
                                           RotaryForm form, WordSpan& word) {
    ++i; // '('
    skipBlanks(line, i);
    if (auto issue = readNumber(line, i, letter, word)) {
        return issue;
    }
    i = word.valueEnd;
    skipBlanks(line, i);
    if (i >= line.size() || line[i] != ')') {
        return i < line.size() && isOperator(line[i])
                   ? parameterIssue(i, std::string("an expression in the word '") + letter + "'")
                   : issueAt(i, "expected ')' after the value of '" + std::string(1, letter) + "'");
    }
    ++i;
    word.form = form;
    return std::nullopt;
}

// "A=45", "A=DC(45)", "T=\"BALL8\"": `i` on the '=' of the word whose letter is at `letterAt`.
std::optional<ScanIssue> scanAssignedWord(std::string_view line, std::size_t& i,
                                          std::size_t letterAt, ScannedBlock& block) {
    const char letter = upper(line[letterAt]);
    ++i;
    skipBlanks(line, i);
    block.hasWords = true;
    if (i < line.size() && line[i] == '"') {
        if (letter != 'T') {
            return issueAt(i, "a text value is expected only in T=\"..\" (the tool's name)");
        }
        return skipString(line, i);
    }
    if (std::string_view("XYZABCFS").find(letter) == std::string_view::npos) {
        return issueAt(letterAt, std::string("'") + letter +
                                     "=' is not supported: expected X Y Z A B C F S or T=\"..\"");
    }
    WordSpan word;
    word.letter = static_cast<std::uint32_t>(letterAt);
    if (i < line.size() && isLetter(line[i])) {
        const std::size_t nameAt = i;
        const std::string name = readIdentifier(line, i);
        const std::optional<RotaryForm> form = formOfFunction(name);
        if (!form || i >= line.size() || line[i] != '(') {
            return parameterIssue(nameAt, "'" + name + "' in the word '" + letter + "'");
        }
        if (letter != 'A' && letter != 'B') {
            return issueAt(nameAt, std::string("'") + letter + "=" + name +
                                       "(..)' is not supported: only A and B take DC, ACP, ACN, "
                                       "AC or IC; post absolute X Y Z and a constant C");
        }
        if (auto issue = readFunctionValue(line, i, letter, *form, word)) {
            return issue;
        }
    } else {
        if (auto issue = readNumber(line, i, letter, word)) {
            return issue;
        }
        i = word.valueEnd;
    }
    if (auto issue = checkWordEnd(line, i, letter)) {
        return issue;
    }
    block.codeEnd = static_cast<std::uint32_t>(i);
    return storeWord(letter, word, block);
}

// "TRAORI", "CYCLE832(0.01,1)", "M17"-like identifiers: what they do to the block.
std::optional<ScanIssue> scanInstruction(std::string_view line, std::size_t& i,
                                         ScannedBlock& block) {
    const std::size_t at = i;
    const std::string name = readIdentifier(line, i);
    const bool call = i < line.size() && line[i] == '(';
    block.hasWords = true;
    block.codeEnd = static_cast<std::uint32_t>(i);
    const auto refuse = [&](const std::string& why) {
        return std::optional<ScanIssue>(issueAt(at, "'" + name + "': " + why));
    };
    if (name == "TRAORI" || name == "TRAFOOF") {
        block.controls |= name == "TRAORI" ? kToolTipOn : kToolTipOff;
    } else if (name == "RET") {
        block.programEnd = true;
    } else if (name == "SUPA") {
        if (block.gCount == kMaxGCodesPerBlock) {
            return issueAt(at, "too many G codes in one block");
        }
        WordSpan g;
        g.letter = static_cast<std::uint32_t>(at);
        g.value = 53.0; // machine coordinates for this block, as G53
        block.gCodes[static_cast<std::size_t>(block.gCount++)] = g;
    } else if (among(kFrames, name)) {
        return refuse("a programmable frame moves or turns the coordinates; BladeAxis re-schedules "
                      "the axes as written, so post the program without frames (or with them "
                      "applied)");
    } else if (among(kControlFlow, name)) {
        return refuse("control flow, definitions and subprogram calls are not supported: "
                      "BladeAxis reads one flat program; have the post-processor expand them");
    } else if (among(kOtherTransformations, name)) {
        return refuse("this kinematic transformation is not supported: expected TRAORI (tool-tip "
                      "programming) or none");
    } else if (!(call ? among(kKeptCalls, name) : among(kKeptInstructions, name))) {
        return refuse(std::string("unknown Sinumerik instruction") + (call ? " call" : "") +
                      " (a subprogram call, a cycle or a setting BladeAxis does not know); a "
                      "program it does not understand is not rewritten");
    }
    if (call) {
        if (auto issue = skipArguments(line, i)) {
            return issue;
        }
        block.codeEnd = static_cast<std::uint32_t>(i);
    }
    return std::nullopt;
}

bool startsInstruction(std::string_view line, std::size_t i) {
    return i + 1 < line.size() && isLetter(line[i + 1]);
}

std::optional<ScanIssue> scanIsoWordOrAssignment(std::string_view line, std::size_t& i,
                                                 ScannedBlock& block) {
    const std::size_t letterAt = i;
    std::size_t next = i + 1;
    skipBlanks(line, next);
    if (next < line.size() && line[next] == '=') {
        i = next;
        return scanAssignedWord(line, i, letterAt, block);
    }
    if (auto issue = scanWord(line, i, block)) {
        return issue;
    }
    const char letter = upper(line[letterAt]);
    std::size_t after = i;
    skipBlanks(line, after);
    if (after < line.size() && line[after] == '=') {
        return parameterIssue(letterAt, "the assignment '" +
                                            std::string(line.substr(letterAt, after - letterAt)) +
                                            "=' (an R-parameter, or an orientation vector A3= B3= "
                                            "C3=)");
    }
    if (letter == 'M') {
        // M17 ends a Sinumerik subprogram as M30 ends a main program.
        std::string_view digits = line.substr(letterAt + 1, i - letterAt - 1);
        digits.remove_prefix(std::min(digits.find_first_not_of(" \t"), digits.size()));
        block.programEnd = block.programEnd || digits == "17";
    }
    return checkWordEnd(line, i, letter);
}

} // namespace

std::optional<ScanIssue> scanSinumerikBlock(std::string_view line, ScannedBlock& block) {
    resetBlock(block);
    std::size_t i = 0;
    while (i < line.size()) {
        const char c = line[i];
        if (isBlank(c)) {
            ++i;
        } else if (c == ';') {
            if (block.firstComment == kNoOffset) {
                block.firstComment = static_cast<std::uint32_t>(i);
            }
            return checkCommentBytes(line, i + 1, line.size());
        } else if (isLetter(c) && startsInstruction(line, i)) {
            if (auto issue = scanInstruction(line, i, block)) {
                return issue;
            }
        } else if (isLetter(c) || (c == ':' && !block.hasWords)) {
            if (auto issue = scanIsoWordOrAssignment(line, i, block)) {
                return issue;
            }
        } else if (c == '%' && !block.hasWords) {
            return std::nullopt; // "%_N_BLADE_MPF": the file's header line
        } else if (c == '/' && !block.hasWords) {
            i += (i + 1 < line.size() && isDigit(line[i + 1])) ? 2 : 1;
        } else if (c == '(') {
            return issueAt(i, "unexpected '(': Sinumerik comments start with ';'");
        } else {
            return unexpectedCharacter(line, i);
        }
    }
    return std::nullopt;
}

} // namespace bladeaxis::io::nc::detail
