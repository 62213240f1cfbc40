#include "core/io/nc/gcode_writer.h"

#include "core/base/file_io.h"
#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/io/nc/detail/block_scanner.h"
#include "core/io/nc/detail/number_style.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

namespace bladeaxis::io::nc {

namespace {

using kinematics::MachineAxes;
using kinematics::MachineModel;

constexpr std::array<char, 5> kAxisLetters{'X', 'Y', 'Z', 'A', 'B'};
constexpr std::size_t kAxisA = 3;

// A replacement (length > 0) or an insertion (length 0) inside one line. Only changed blocks
// create edits, so the string here is not a per-word cost of the whole program.
struct Edit {
    std::uint32_t offset = 0;
    std::uint32_t length = 0;
    std::string text;
};

double axisValue(const MachineAxes& axes, std::size_t axis) {
    return axes[kinematics::kAllAxes[axis]];
}

Status validateAxes(const GcodeProgram& program, std::span<const MachineAxes> newAxes) {
    if (newAxes.size() != program.path.records.size()) {
        return makeError(ErrorCode::InvalidArgument,
                         "expected " + std::to_string(program.path.records.size()) +
                             " axis sets (one per record), got " + std::to_string(newAxes.size()));
    }
    for (std::size_t k = 0; k < newAxes.size(); ++k) {
        for (std::size_t axis = 0; axis < kAxisLetters.size(); ++axis) {
            if (!std::isfinite(axisValue(newAxes[k], axis))) {
                return makeError(ErrorCode::InvalidArgument, "newAxes[" + std::to_string(k) + "]." +
                                                                 kAxisLetters[axis] +
                                                                 " is not finite");
            }
        }
        if (!program.path.records[k].axes) {
            return makeError(ErrorCode::InvalidArgument,
                             "record " + std::to_string(k) + " has no programmed axes");
        }
    }
    return {};
}

class Rewriter {
  public:
    Rewriter(const GcodeProgram& program, const MachineModel& machine)
        : m_program(program), m_modulo(machine.aMode == kinematics::RotaryMode::Modulo),
          m_numbers(machine.numbers) {}

    std::string run(std::span<const MachineAxes> newAxes) {
        const std::string& text = m_program.text;
        std::string out;
        out.reserve(text.size() + text.size() / 16);
        std::size_t cursor = 0;
        for (std::size_t k = 0; k < newAxes.size(); ++k) {
            const RecordSource& source = m_program.sources[k];
            const std::string_view line = lineAt(source.lineBegin);
            std::vector<Edit> edits = editsFor(k, line, newAxes[k]);
            if (edits.empty()) {
                continue;
            }
            out.append(text, cursor, source.lineBegin - cursor);
            appendEdited(out, line, edits);
            cursor = source.lineBegin + line.size();
        }
        out.append(text, cursor, std::string::npos);
        return out;
    }

  private:
    struct AxisContext {
        std::size_t axis = 0;
        bool incremental = false;
        bool inch = false;
    };

    std::string_view lineAt(std::uint32_t begin) const {
        const std::string_view text = m_program.text;
        const void* newline = std::memchr(text.data() + begin, '\n', text.size() - begin);
        std::size_t end =
            newline ? static_cast<std::size_t>(static_cast<const char*>(newline) - text.data())
                    : text.size();
        if (end > begin && text[end - 1] == '\r') {
            --end;
        }
        return text.substr(begin, end - begin);
    }

    bool radians() const { return m_program.angleUnit == AngleUnit::Radians; }
    double fullTurn() const { return radians() ? units::kTwoPi : 360.0; }

    // Internal value (mm / rad) to the number written in the file (mm, inch, deg or rad).
    double toFile(const AxisContext& c, double value, bool absolute) const {
        if (c.axis < kAxisA) {
            return c.inch ? units::mmToInch(value) : value;
        }
        double angle = radians() ? value : units::radToDeg(value);
        if (absolute && c.axis == kAxisA && m_modulo) {
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

    // A modulo A written as "360.000" after rounding is written as 0 instead.
    std::string wrapFormatted(const AxisContext& c, std::string text, double fileValue,
                              std::string_view old) const {
        if (c.axis == kAxisA && m_modulo && !c.incremental &&
            parseNumber(text).value_or(0.0) * wordScale(c, old) >= fullTurn()) {
            const AxisNumberStyle& style = m_program.axisStyles[c.axis];
            const double wrapped = (fileValue - fullTurn()) / wordScale(c, old);
            return old.empty() ? detail::formatForInsertion(wrapped, style)
                               : detail::formatLikeWord(wrapped, old, style);
        }
        return text;
    }

    double increment(const AxisContext& c, double target, double before) const {
        double delta = target - before;
        if (c.axis == kAxisA && m_modulo) {
            // A modulo axis holds A in [0, 360): the shortest rotation reaches the target.
            delta = std::remainder(delta, units::kTwoPi);
        }
        return delta;
    }

    std::vector<Edit> editsFor(std::size_t k, std::string_view line, const MachineAxes& target);
    std::uint32_t insertionOffset(std::size_t axis, const RecordSource& source,
                                  std::string_view line, bool& after) const;
    Edit insertion(std::size_t axis, const RecordSource& source, std::string_view line,
                   std::string number) const;
    static void appendEdited(std::string& out, std::string_view line, std::vector<Edit>& edits);

    const GcodeProgram& m_program;
    bool m_modulo = false;
    kinematics::NumberRules m_numbers;
    std::array<double, 5> m_written{}; // what the controller holds after the previous record
};

std::vector<Edit> Rewriter::editsFor(std::size_t k, std::string_view line,
                                     const MachineAxes& target) {
    const RecordSource& source = m_program.sources[k];
    const MachineAxes& original = *m_program.path.records[k].axes;
    std::vector<Edit> edits;
    for (std::size_t axis = 0; axis < kAxisLetters.size(); ++axis) {
        const AxisContext c{axis, (source.flags & kIncremental) != 0, (source.flags & kInch) != 0};
        const AxisNumberStyle& style = m_program.axisStyles[axis];
        const bool hasWord = source.hasWord(static_cast<int>(axis));
        const std::string_view old =
            hasWord ? line.substr(source.wordBegin[axis], source.wordLength[axis]) : "";
        const double scale = wordScale(c, old);
        const double oldFile = hasWord ? parseNumber(old).value_or(0.0) * scale : 0.0;
        double before = m_written[axis];
        if (source.setOutside & (1u << axis)) {
            before =
                axisValue(original, axis) - (c.incremental && hasWord ? fromFile(c, oldFile) : 0.0);
        }
        const double wanted = axisValue(target, axis);
        const double fileValue = c.incremental ? toFile(c, increment(c, wanted, before), false)
                                               : toFile(c, wanted, true);
        double writtenFile = 0.0;
        if (hasWord) {
            writtenFile = oldFile;
            if (std::abs(fileValue - oldFile) > 1e-12 * std::max(1.0, std::abs(oldFile))) {
                std::string text = wrapFormatted(
                    c, detail::formatLikeWord(fileValue / scale, old, style), fileValue, old);
                if (text != old) {
                    writtenFile = parseNumber(text).value_or(fileValue / scale) * scale;
                    edits.push_back({source.wordBegin[axis], source.wordLength[axis], text});
                }
            }
        } else {
            std::string text = wrapFormatted(c, insertionText(fileValue, style), fileValue, "");
            const std::string modal =
                c.incremental ? insertionText(0.0, style)
                              : wrapFormatted(c, insertionText(toFile(c, before, true), style),
                                              toFile(c, before, true), "");
            if (text == modal) {
                m_written[axis] = before;
                continue;
            }
            writtenFile = parseNumber(text).value_or(fileValue);
            edits.push_back(insertion(axis, source, line, std::move(text)));
        }
        m_written[axis] =
            c.incremental ? before + fromFile(c, writtenFile) : fromFile(c, writtenFile);
    }
    return edits;
}

// Where a missing word goes: right after the nearest preceding axis word of the block, else
// right before the nearest following one (a record always has at least one axis word).
std::uint32_t Rewriter::insertionOffset(std::size_t axis, const RecordSource& source,
                                        std::string_view line, bool& after) const {
    for (std::size_t j = axis; j-- > 0;) {
        if (source.hasWord(static_cast<int>(j))) {
            after = true;
            return static_cast<std::uint32_t>(source.wordBegin[j] + source.wordLength[j]);
        }
    }
    after = false;
    for (std::size_t j = axis + 1; j < kAxisLetters.size(); ++j) {
        if (source.hasWord(static_cast<int>(j))) {
            std::uint32_t letter = source.wordBegin[j];
            while (letter > 0 && (line[letter - 1] == ' ' || line[letter - 1] == '\t')) {
                --letter; // blanks between letter and number ("X 1.0")
            }
            return letter - 1;
        }
    }
    return static_cast<std::uint32_t>(line.size());
}

Edit Rewriter::insertion(std::size_t axis, const RecordSource& source, std::string_view line,
                         std::string number) const {
    bool after = false;
    const std::uint32_t offset = insertionOffset(axis, source, line, after);
    // Follow the block's own layout: words separated by blanks or run together, letter case.
    detail::ScannedBlock block;
    (void)detail::scanBlock(line, block);
    const std::string_view code = line.substr(0, block.codeEnd);
    const bool spaced = code.find_first_of(" \t") != std::string_view::npos;
    const bool lower = code.find_first_of("xyzab") != std::string_view::npos;
    const char letter = static_cast<char>(kAxisLetters[axis] + (lower ? 'a' - 'A' : 0));
    std::string word = std::string(1, letter) + number;
    if (spaced) {
        word = after ? " " + word : word + " ";
    }
    return {offset, 0, std::move(word)};
}

void Rewriter::appendEdited(std::string& out, std::string_view line, std::vector<Edit>& edits) {
    std::stable_sort(edits.begin(), edits.end(),
                     [](const Edit& a, const Edit& b) { return a.offset < b.offset; });
    std::size_t cursor = 0;
    for (const Edit& edit : edits) {
        out.append(line.substr(cursor, edit.offset - cursor));
        out.append(edit.text);
        cursor = edit.offset + edit.length;
    }
    out.append(line.substr(cursor));
}

} // namespace

Result<std::string> rewriteGcode(const GcodeProgram& program, std::span<const MachineAxes> newAxes,
                                 const MachineModel& machine) {
    if (program.sources.size() != program.path.records.size()) {
        return makeError(ErrorCode::InvalidArgument,
                         "program has no source data for its records: parse it with parseGcode");
    }
    if (Status valid = validateAxes(program, newAxes); !valid) {
        return std::unexpected(std::move(valid.error()));
    }
    return Rewriter(program, machine).run(newAxes);
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
