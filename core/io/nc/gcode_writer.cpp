#include "core/io/nc/gcode_writer.h"

#include "core/base/file_io.h"
#include "core/base/forward_text.h"
#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/io/nc/detail/axis_motion.h"
#include "core/io/nc/detail/block_scanner.h"
#include "core/io/nc/detail/number_style.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <vector>

namespace bladeaxis::io::nc {

namespace {

using kinematics::MachineAxes;
using kinematics::MachineModel;

constexpr std::array<char, 5> kAxisLetters = kinematics::kProgramLetters;
constexpr std::size_t kAxisA = 3; // the first rotary word

// A replacement (length > 0) or an insertion (length 0) inside one line. Only changed blocks
// create edits, so the string here is not a per-word cost of the whole program.
struct Edit {
    std::uint32_t offset = 0;
    std::uint32_t length = 0;
    std::string text;
};

// The engine's axes in their own order. Built here rather than through MachineAxes::operator[],
// which another library defines and the compiler cannot inline: this runs for every word.
std::array<double, 5> axisValues(const MachineAxes& axes) {
    return {axes.x, axes.y, axes.z, axes.a, axes.b};
}

double axisValue(const MachineAxes& axes, std::size_t axis) {
    return axisValues(axes)[axis];
}

// The engine's axes as the program's words (X Y Z A B order, the program's signs).
class ProgramWords {
  public:
    explicit ProgramWords(const MachineModel& machine) {
        for (const kinematics::AxisId axis : kinematics::kAllAxes) {
            m_words[static_cast<std::size_t>(axis)] = machine.programWord(axis);
        }
    }
    std::array<double, 5> of(const MachineAxes& axes) const {
        const std::array<double, 5> engine = axisValues(axes);
        std::array<double, 5> words{};
        for (std::size_t axis = 0; axis < engine.size(); ++axis) {
            words[m_words[axis].index] = m_words[axis].sign * engine[axis];
        }
        return words;
    }
    std::size_t tableWord() const { return m_words[3].index; }

  private:
    std::array<kinematics::ProgramWord, 5> m_words{};
};

// The axes every record is written with: the new ones of a pass, and the axes read for the
// records before and after it. A job re-schedules one pass of a program whose other records
// keep their axes; this spares a copy of every record's axes (40 bytes each).
class NewAxes {
  public:
    NewAxes(std::span<const toolpath::ClRecord> records, std::size_t passFirst,
            std::span<const MachineAxes> pass)
        : m_records(records), m_first(passFirst), m_pass(pass) {}

    std::size_t size() const { return m_records.size(); }
    bool given(std::size_t k) const { return k >= m_first && k - m_first < m_pass.size(); }
    // The rewrite compares a block's new words with the ones it was read with, so every record,
    // in the pass or not, needs the axes it was read with.
    bool read(std::size_t k) const { return m_records[k].axes.has_value(); }
    const MachineAxes& operator[](std::size_t k) const {
        return given(k) ? m_pass[k - m_first] : *m_records[k].axes;
    }

  private:
    std::span<const toolpath::ClRecord> m_records;
    std::size_t m_first;
    std::span<const MachineAxes> m_pass;
};

Status validateAxes(const GcodeProgram& program, const NewAxes& newAxes,
                    const MachineModel& machine) {
    for (std::size_t k = 0; k < newAxes.size(); ++k) {
        if (!newAxes.read(k)) {
            return makeError(ErrorCode::InvalidArgument,
                             "record " + std::to_string(k) + " has no programmed axes");
        }
        for (std::size_t axis = 0; axis < kAxisLetters.size(); ++axis) {
            if (!std::isfinite(axisValue(newAxes[k], axis))) {
                return makeError(ErrorCode::InvalidArgument, "newAxes[" + std::to_string(k) + "]." +
                                                                 kAxisLetters[axis] +
                                                                 " is not finite");
            }
        }
        if (!machine.hasB() && std::abs(newAxes[k].b) > 1e-9) {
            const std::string tilt(1, machine.letter(kinematics::AxisId::B));
            return makeError(ErrorCode::CheckFailed,
                             "the new orientation tilts " + tilt + " by " +
                                 formatTrimmed(units::radToDeg(newAxes[k].b), 4) +
                                 " deg, but the machine '" + machine.name +
                                 "' has a fixed head (no " + tilt + " axis)",
                             {program.path.sourceFile, program.path.records[k].line, 0});
        }
    }
    return {};
}

// A word as the program wrote it: its value and how it is written.
struct OldWord {
    double value = 0.0;
    detail::WordTextStyle style;
};

// Nearly every word is a plain decimal, whose value and style one pass reads, as the scanner
// does; parseNumber and styleOfWord give the same for it, in two passes.
OldWord readOldWord(std::string_view old) {
    OldWord word;
    if (const PlainDecimal plain = readPlainDecimal(old);
        !old.empty() && plain.length == old.size()) {
        word.value = plain.value;
        detail::setPlainDecimalStyle(word.style, old, plain);
    } else {
        word.value = parseNumber(old).value_or(0.0);
        word.style = detail::styleOfWord(old);
    }
    return word;
}

// A word's new number against its old one: a loop over a dozen characters, cheaper than the
// memcmp call that comparing strings makes, for every changed word.
bool sameText(std::string_view a, std::string_view b) {
    return std::ranges::equal(a, b, [](char x, char y) { return x == y; });
}

bool isModuloForm(RotaryForm form) {
    return form == RotaryForm::Shortest || form == RotaryForm::Positive ||
           form == RotaryForm::Negative;
}

class Rewriter {
  public:
    Rewriter(const GcodeProgram& program, const MachineModel& machine)
        : m_program(program), m_words(machine), m_tableWord(m_words.tableWord()),
          m_modulo(machine.aMode == kinematics::RotaryMode::Modulo), m_numbers(machine.numbers) {
        if (program.dialect != NcDialect::Iso) {
            m_numbers.integerWords = kinematics::IntegerWords::Units; // as the reader took them
        }
        m_combinedFeed = program.programmedFeeds.size() == program.path.records.size();
    }

    Result<std::string> run(const NewAxes& newAxes, ForwardText& text,
                            const RewriteStreams& streams) {
        std::string out;
        out.reserve(streams.writtenPiece ? kPieceBytes + kPieceBytes / 4
                                         : text.size() + text.size() / 16);
        std::size_t cursor = 0;
        std::size_t reported = 0;
        for (std::size_t k = 0; k < newAxes.size(); ++k) {
            const RecordSource& source = m_program.sources[k];
            // A long run of unchanged blocks is copied on, so that a text read again from its
            // file needs a window of a few megabytes only.
            if (source.lineBegin - cursor >= kPieceBytes) {
                if (Status copied = copyText(text, cursor, source.lineBegin, out, streams);
                    !copied) {
                    return std::unexpected(std::move(copied.error()));
                }
                cursor = source.lineBegin;
            }
            const std::string_view line = text.lineFrom(source.lineBegin);
            if (text.failure()) {
                return std::unexpected(*text.failure());
            }
            const std::array<double, 5> before = m_written;
            std::vector<Edit>& edits = m_edits;
            edits.clear();
            editsFor(k, line, newAxes[k], edits);
            if (m_combinedFeed) {
                feedEdit(k, line, before, edits);
            }
            if (m_failure) {
                return std::unexpected(std::move(*m_failure));
            }
            if (edits.empty()) {
                continue;
            }
            out.append(text.range(cursor, source.lineBegin));
            appendEdited(out, line, edits);
            cursor = source.lineBegin + line.size();
            // The blocks of a flat program stand in file order: nothing before the cursor,
            // nor any source up to this block's, is read again.
            text.releaseBefore(cursor);
            if (streams.rewrittenUpTo && cursor - reported >= kReportEveryBytes) {
                streams.rewrittenUpTo(cursor, k + 1);
                reported = cursor;
            }
            if (Status handed = handOnPiece(out, streams, kPieceBytes); !handed) {
                return std::unexpected(std::move(handed.error()));
            }
        }
        if (Status copied = copyText(text, cursor, text.size(), out, streams); !copied) {
            return std::unexpected(std::move(copied.error()));
        }
        if (streams.writtenPiece) {
            if (Status handed = handOnPiece(out, streams, 0); !handed) {
                return std::unexpected(std::move(handed.error()));
            }
            return std::string();
        }
        return out;
    }

  private:
    static constexpr std::size_t kReportEveryBytes = std::size_t{4} << 20;
    static constexpr std::size_t kPieceBytes = std::size_t{4} << 20;

    struct AxisContext {
        std::size_t axis = 0;
        bool incremental = false;
        bool inch = false;
        RotaryForm form = RotaryForm::Plain;
    };

    static AxisContext contextOf(std::size_t axis, const RecordSource& source) {
        const RotaryForm form =
            axis >= kAxisA ? source.rotaryForms[axis - kAxisA] : RotaryForm::Plain;
        const bool incremental = form == RotaryForm::Incremental ||
                                 (form == RotaryForm::Plain && (source.flags & kIncremental) != 0);
        return {axis, incremental, (source.flags & kInch) != 0, form};
    }
    bool wrapsAbsolute(const AxisContext& c) const {
        return isModuloForm(c.form) || (c.axis == m_tableWord && m_modulo);
    }

    // With a piece taker, hands `out` on once it holds at least `least` bytes.
    static Status handOnPiece(std::string& out, const RewriteStreams& streams, std::size_t least) {
        if (!streams.writtenPiece || out.size() < least || (least == 0 && out.empty())) {
            return {};
        }
        if (Status handed = streams.writtenPiece(out); !handed) {
            return handed;
        }
        out.clear();
        return {};
    }

    // Copies the unchanged text [begin, end) on, a window at a time.
    static Status copyText(ForwardText& text, std::size_t begin, std::size_t end, std::string& out,
                           const RewriteStreams& streams) {
        while (begin < end) {
            const std::size_t stop = std::min(end, begin + kPieceBytes);
            out.append(text.range(begin, stop));
            if (text.failure()) {
                return std::unexpected(*text.failure());
            }
            text.releaseBefore(stop);
            begin = stop;
            if (Status handed = handOnPiece(out, streams, kPieceBytes); !handed) {
                return handed;
            }
        }
        return {};
    }

    bool radians() const { return m_program.angleUnit == AngleUnit::Radians; }
    double fullTurn() const { return radians() ? units::kTwoPi : 360.0; }

    // Internal value (mm / rad) to the number written in the file (mm, inch, deg or rad).
    double toFile(const AxisContext& c, double value, bool absolute) const {
        if (c.axis < kAxisA) {
            return c.inch ? units::mmToInch(value) : value;
        }
        double angle = radians() ? value : units::radToDeg(value);
        if (absolute && wrapsAbsolute(c)) {
            angle = std::fmod(angle, fullTurn());
            angle += angle < 0.0 ? fullTurn() : 0.0;
        }
        return angle;
    }
    double fromFile(const AxisContext& c, double value) const {
        if (c.axis < kAxisA) {
            return c.inch ? units::inchToMm(value) : value;
        }
        return radians() ? value : units::degToRad(value);
    }
    // A new word. A program written in increments has axis words without decimals; a new
    // word there gets a decimal point (read as units by such a control) and enough decimals.
    std::string insertionText(double fileValue, const AxisNumberStyle& style) const {
        if (m_numbers.integerWords == kinematics::IntegerWords::Increments &&
            style.maxDecimals == 0) {
            return formatFixed(fileValue, 4);
        }
        return detail::formatForInsertion(fileValue, style);
    }

    // File units per written unit of a word: a least input increment for a word without a
    // decimal point on a control that counts increments, else 1. The word keeps its style.
    double wordScale(const AxisContext& c, std::string_view old) const {
        if (m_numbers.integerWords != kinematics::IntegerWords::Increments || old.empty() ||
            old.find_first_of(".eE") != std::string_view::npos) {
            return 1.0;
        }
        if (c.axis >= kAxisA) {
            return m_numbers.incrementDeg;
        }
        return c.inch ? m_numbers.incrementInch : m_numbers.incrementMm;
    }

    // What a word's number reads back as: known from its formatting, else parsed again.
    static double readBack(const detail::WordNumber& number, double unreadable) {
        return number.value ? *number.value : parseNumber(number.text).value_or(unreadable);
    }

    // A modulo A written as "360.000" after rounding is written as 0 instead.
    detail::WordNumber wrapFormatted(const AxisContext& c, detail::WordNumber number,
                                     double fileValue, std::string_view old) const {
        if (c.axis >= kAxisA && wrapsAbsolute(c) && !c.incremental &&
            readBack(number, 0.0) * wordScale(c, old) >= fullTurn()) {
            const AxisNumberStyle& style = m_program.axisStyles[c.axis];
            const double wrapped = (fileValue - fullTurn()) / wordScale(c, old);
            return old.empty() ? detail::WordNumber{detail::formatForInsertion(wrapped, style), {}}
                               : detail::numberLikeWord(wrapped, old, style);
        }
        return number;
    }
    // An inserted word's text, wrapped like a rewritten one.
    std::string wrappedInsertion(const AxisContext& c, double fileValue,
                                 const AxisNumberStyle& style) const {
        return wrapFormatted(c, {insertionText(fileValue, style), {}}, fileValue, "").text;
    }

    double increment(const AxisContext& c, double target, double before) const {
        double delta = target - before;
        if (c.axis == m_tableWord && m_modulo && c.form == RotaryForm::Plain) {
            // A modulo table holds its angle in [0, 360): the shortest rotation reaches it.
            delta = std::remainder(delta, units::kTwoPi);
        }
        return delta;
    }

    void editsFor(std::size_t k, std::string_view line, const MachineAxes& target,
                  std::vector<Edit>& edits);
    void checkModuloMove(std::size_t k, const AxisContext& c, double before, double wanted);
    void feedEdit(std::size_t k, std::string_view line, const std::array<double, 5>& before,
                  std::vector<Edit>& edits);
    double reachedAfter(const AxisContext& c, double before, double writtenFile) const;
    std::string wordText(const AxisContext& c, std::string number) const;
    std::uint32_t insertionOffset(std::size_t axis, const RecordSource& source,
                                  std::string_view line, const detail::ScannedBlock& block,
                                  bool& after) const;
    Edit insertion(const AxisContext& c, const RecordSource& source, std::string_view line,
                   std::string number) const;
    static void appendEdited(std::string& out, std::string_view line, std::vector<Edit>& edits);

    const GcodeProgram& m_program;
    ProgramWords m_words;
    std::size_t m_tableWord = kAxisA;
    bool m_modulo = false;
    kinematics::NumberRules m_numbers;
    std::array<double, 5> m_written{}; // what the controller holds after the previous record
    std::optional<Error> m_failure;    // a move the block's word form cannot make
    bool m_combinedFeed = false;       // F over the combined axis move: rescaled per block
    bool m_feedChanged = false;        // the previous record was written with another F
    std::vector<Edit> m_edits;         // the current record's, reused: no allocation per block
};

// On a control that reads G94 F over the combined axis move, a block whose A and B steps change
// would change its time, and with it the speed of the ball centre along the unchanged path. The
// block gets the F that keeps its time: F x new length / old length. The block after a changed
// one states its F again, so the program's own F holds from there on.
void Rewriter::feedEdit(std::size_t k, std::string_view line, const std::array<double, 5>& before,
                        std::vector<Edit>& edits) {
    const RecordSource& source = m_program.sources[k];
    const double programmed = m_program.programmedFeeds[k];
    double wanted = programmed;
    if ((source.flags & kCombinedFeed) && k > 0) {
        const bool inch = (source.flags & kInch) != 0;
        const double oldLength =
            detail::combinedAxisMove(m_words.of(*m_program.path.records[k - 1].axes),
                                     m_words.of(*m_program.path.records[k].axes), inch);
        const double newLength = detail::combinedAxisMove(before, m_written, inch);
        if (oldLength > 1e-9 && newLength > 1e-9) {
            wanted = programmed * newLength / oldLength;
        }
    }
    const std::string wantedText = formatTrimmed(wanted, 1);
    const bool changed = wantedText != formatTrimmed(programmed, 1);
    const bool restate = m_feedChanged && programmed > 0.0;
    m_feedChanged = changed;
    if (!(changed || restate)) {
        return;
    }
    detail::ScannedBlock block;
    (void)detail::scanBlock(line, block, m_program.dialect);
    if (block.has('F')) {
        const detail::WordSpan& word = block.word('F');
        if (word.text(line) != wantedText) {
            edits.push_back({word.valueBegin, word.valueEnd - word.valueBegin, wantedText});
        }
        return;
    }
    const std::string_view code = line.substr(0, block.codeEnd);
    const bool spaced = code.find_first_of(" \t") != std::string_view::npos;
    const bool lower = code.find_first_of("xyzabg") != std::string_view::npos;
    edits.push_back(
        {block.codeEnd, 0, std::string(spaced ? " " : "") + (lower ? "f" : "F") + wantedText});
}

// A DC / M126 word turns the short way, ACP only up, ACN only down: a new position the form
// cannot reach from the previous one is refused rather than written as a move the other way.
void Rewriter::checkModuloMove(std::size_t k, const AxisContext& c, double before, double wanted) {
    if (!isModuloForm(c.form) || m_failure) {
        return;
    }
    const double delta = wanted - before;
    const double tolerance = 1e-9;
    const bool reachable =
        c.form == RotaryForm::Shortest
            ? std::abs(delta) < units::kPi - tolerance
            : (c.form == RotaryForm::Positive ? delta > -tolerance : delta < tolerance) &&
                  std::abs(delta) < units::kTwoPi - tolerance;
    if (reachable) {
        return;
    }
    static constexpr std::array<const char*, 6> kFormNames{"",
                                                           "",
                                                           "DC (the shorter way)",
                                                           "ACP (positive direction only)",
                                                           "ACN (negative direction only)",
                                                           ""};
    m_failure =
        Error{ErrorCode::CheckFailed,
              std::string("the new ") + kAxisLetters[c.axis] + " turns " +
                  formatTrimmed(units::radToDeg(delta), 3) + " deg in a block whose word is " +
                  kFormNames[static_cast<std::size_t>(c.form)] +
                  ": written so, the control would turn the other way; nothing is written",
              {m_program.path.sourceFile, m_program.path.records[k].line, 0},
              {}};
}

// The controller's position after a word that reads `writtenFile` (file units).
double Rewriter::reachedAfter(const AxisContext& c, double before, double writtenFile) const {
    const double value = fromFile(c, writtenFile);
    if (c.incremental) {
        return before + value;
    }
    return isModuloForm(c.form) ? detail::reachedByModulo(c.form, before, value) : value;
}

// The whole word for an inserted number in the block's dialect and the form the program
// uses for that axis: "A12.5", "A=DC(12.5)", Heidenhain "A+12.5" / "IA+5".
std::string Rewriter::wordText(const AxisContext& c, std::string number) const {
    const std::string letter(1, kAxisLetters[c.axis]);
    if (m_program.dialect == NcDialect::Heidenhain) {
        if (!number.starts_with('-') && !number.starts_with('+')) {
            number = "+" + number;
        }
        return (c.form == RotaryForm::Incremental ? "I" : "") + letter + number;
    }
    if (m_program.dialect == NcDialect::Sinumerik) {
        static constexpr std::array<const char*, 6> kFunctions{"", "AC", "DC", "ACP", "ACN", "IC"};
        const char* function = kFunctions[static_cast<std::size_t>(c.form)];
        if (*function != '\0') {
            return letter + "=" + function + "(" + number + ")";
        }
    }
    return letter + number;
}

void Rewriter::editsFor(std::size_t k, std::string_view line, const MachineAxes& target,
                        std::vector<Edit>& edits) {
    const RecordSource& source = m_program.sources[k];
    const std::array<double, 5> original = m_words.of(*m_program.path.records[k].axes);
    const std::array<double, 5> wantedWords = m_words.of(target);
    for (std::size_t axis = 0; axis < kAxisLetters.size(); ++axis) {
        const AxisContext c = contextOf(axis, source);
        const AxisNumberStyle& style = m_program.axisStyles[axis];
        const bool hasWord = source.hasWord(static_cast<int>(axis));
        const std::string_view old =
            hasWord ? line.substr(source.wordBegin[axis], source.wordLength[axis]) : "";
        const double scale = wordScale(c, old);
        const OldWord oldWord = hasWord ? readOldWord(old) : OldWord{};
        const double oldFile = hasWord ? oldWord.value * scale : 0.0;
        double before = m_written[axis];
        if (source.setOutside & (1u << axis)) {
            before = original[axis] - (c.incremental && hasWord ? fromFile(c, oldFile) : 0.0);
        }
        const double wanted = wantedWords[axis];
        checkModuloMove(k, c, before, wanted);
        const double fileValue = c.incremental ? toFile(c, increment(c, wanted, before), false)
                                               : toFile(c, wanted, true);
        double writtenFile = 0.0;
        if (hasWord) {
            writtenFile = oldFile;
            if (std::abs(fileValue - oldFile) > 1e-12 * std::max(1.0, std::abs(oldFile))) {
                detail::WordNumber number = wrapFormatted(
                    c, detail::numberInWordStyle(fileValue / scale, oldWord.style, style),
                    fileValue, old);
                if (!sameText(number.text, old)) {
                    writtenFile = readBack(number, fileValue / scale) * scale;
                    edits.push_back(
                        {source.wordBegin[axis], source.wordLength[axis], std::move(number.text)});
                }
            }
        } else {
            std::string text = wrappedInsertion(c, fileValue, style);
            const std::string modal = c.incremental
                                          ? insertionText(0.0, style)
                                          : wrappedInsertion(c, toFile(c, before, true), style);
            if (text == modal) {
                m_written[axis] = before;
                continue;
            }
            writtenFile = parseNumber(text).value_or(fileValue);
            edits.push_back(insertion(c, source, line, std::move(text)));
        }
        m_written[axis] = reachedAfter(c, before, writtenFile);
    }
}

// Where a missing word goes: right after the nearest preceding axis word of the block (after
// the ')' of "A=DC(..)"), else right before the nearest following one (a record always has at
// least one axis word).
std::uint32_t Rewriter::insertionOffset(std::size_t axis, const RecordSource& source,
                                        std::string_view line, const detail::ScannedBlock& block,
                                        bool& after) const {
    for (std::size_t j = axis; j-- > 0;) {
        if (source.hasWord(static_cast<int>(j))) {
            after = true;
            std::uint32_t end = source.wordBegin[j] + source.wordLength[j];
            while (end < line.size() && (line[end] == ' ' || line[end] == '\t')) {
                ++end;
            }
            return end < line.size() && line[end] == ')'
                       ? end + 1
                       : static_cast<std::uint32_t>(source.wordBegin[j] + source.wordLength[j]);
        }
    }
    after = false;
    for (std::size_t j = axis + 1; j < kAxisLetters.size(); ++j) {
        if (source.hasWord(static_cast<int>(j))) {
            return block.word(kAxisLetters[j]).letter;
        }
    }
    return static_cast<std::uint32_t>(line.size());
}

Edit Rewriter::insertion(const AxisContext& c, const RecordSource& source, std::string_view line,
                         std::string number) const {
    // Follow the block's own layout: words separated by blanks or run together, letter case.
    detail::ScannedBlock block;
    (void)detail::scanBlock(line, block, m_program.dialect);
    bool after = false;
    const std::uint32_t offset = insertionOffset(c.axis, source, line, block, after);
    const std::string_view code = line.substr(0, block.codeEnd);
    const bool spaced = m_program.dialect == NcDialect::Heidenhain ||
                        code.find_first_of(" \t") != std::string_view::npos;
    const bool lower = code.find_first_of("xyzab") != std::string_view::npos;
    std::string word = wordText(c, std::move(number));
    if (lower) {
        std::transform(word.begin(), word.end(), word.begin(), [](char ch) {
            return ch >= 'A' && ch <= 'Z' ? static_cast<char>(ch - 'A' + 'a') : ch;
        });
    }
    if (spaced) {
        word = after ? " " + word : word + " ";
    }
    return {offset, 0, std::move(word)};
}

void Rewriter::appendEdited(std::string& out, std::string_view line, std::vector<Edit>& edits) {
    // At most a handful per block: an insertion sort, stable like std::stable_sort, without its
    // buffer allocation.
    for (std::size_t i = 1; i < edits.size(); ++i) {
        for (std::size_t j = i; j > 0 && edits[j].offset < edits[j - 1].offset; --j) {
            std::swap(edits[j], edits[j - 1]);
        }
    }
    std::size_t cursor = 0;
    for (const Edit& edit : edits) {
        out.append(line.substr(cursor, edit.offset - cursor));
        out.append(edit.text);
        cursor = edit.offset + edit.length;
    }
    out.append(line.substr(cursor));
}

} // namespace

Result<std::string> rewriteGcodePass(const GcodeProgram& program, std::size_t passFirst,
                                     std::span<const MachineAxes> passAxes,
                                     const MachineModel& machine, const RewriteStreams& streams) {
    const std::size_t records = program.path.records.size();
    if (program.sources.size() != records) {
        return makeError(ErrorCode::InvalidArgument,
                         "program has no source data for its records: parse it with parseGcode");
    }
    if (passFirst > records || passAxes.size() > records - passFirst) {
        return makeError(ErrorCode::InvalidArgument,
                         "expected at most " +
                             std::to_string(records - std::min(passFirst, records)) +
                             " axis sets from record " + std::to_string(passFirst) + ", got " +
                             std::to_string(passAxes.size()));
    }
    const NewAxes newAxes(program.path.records, passFirst, passAxes);
    if (Status valid = validateAxes(program, newAxes, machine); !valid) {
        return std::unexpected(std::move(valid.error()));
    }
    if (streams.textFile) {
        auto text = ForwardText::reopen(*streams.textFile);
        if (!text) {
            return std::unexpected(text.error());
        }
        return Rewriter(program, machine).run(newAxes, *text, streams);
    }
    ForwardText text(program.text);
    return Rewriter(program, machine).run(newAxes, text, streams);
}

Result<std::string> rewriteGcode(const GcodeProgram& program, std::span<const MachineAxes> newAxes,
                                 const MachineModel& machine) {
    if (newAxes.size() != program.path.records.size()) {
        return makeError(ErrorCode::InvalidArgument,
                         "expected " + std::to_string(program.path.records.size()) +
                             " axis sets (one per record), got " + std::to_string(newAxes.size()));
    }
    return rewriteGcodePass(program, 0, newAxes, machine);
}

Status writeGcodeFile(const std::filesystem::path& out, const GcodeProgram& program,
                      std::span<const MachineAxes> newAxes, const MachineModel& machine) {
    Result<std::string> text = rewriteGcode(program, newAxes, machine);
    if (!text) {
        return std::unexpected(std::move(text.error()));
    }
    const std::filesystem::path inputs[] = {std::filesystem::path(program.path.sourceFile)};
    return writeFileAtomically(out, *text, inputs);
}

} // namespace bladeaxis::io::nc
