#include "core/io/nc/gcode_emitter.h"

#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/kinematics/kinematics.h"

#include <array>
#include <cmath>

namespace bladeaxis::io::nc {

namespace {

using kinematics::MachineAxes;

// More decimals than a double carries would only write noise.
constexpr int kMaxDecimals = 12;
constexpr int kFeedDecimals = 3;

Status validateOptions(const GcodeEmitOptions& options) {
    if (options.linearDecimals < 0 || options.linearDecimals > kMaxDecimals ||
        options.angularDecimals < 0 || options.angularDecimals > kMaxDecimals) {
        return makeError(ErrorCode::InvalidArgument,
                         "decimals must lie in [0, " + std::to_string(kMaxDecimals) + "]");
    }
    if (options.blockNumbers && options.blockNumberStep <= 0) {
        return makeError(ErrorCode::InvalidArgument, "blockNumberStep must be positive");
    }
    return {};
}

// Comment text must not close the comment early.
std::string commentLine(std::string_view text) {
    std::string line = "(";
    for (char c : text) {
        if (c == '(' || c == '[') {
            line += '[';
        } else if (c == ')' || c == ']') {
            line += ']';
        } else if (c == '\n' || c == '\r') {
            line += ' ';
        } else {
            line += c;
        }
    }
    line += ")\n";
    return line;
}

// Programmed axes for every record, A unwrapped from record to record.
Result<std::vector<MachineAxes>> solveAxes(const toolpath::Toolpath& path,
                                           const kinematics::MachineModel& machine) {
    std::vector<MachineAxes> axes;
    axes.reserve(path.records.size());
    double aReference = 0.0;
    for (std::size_t i = 0; i < path.records.size(); ++i) {
        const toolpath::ClRecord& record = path.records[i];
        Result<MachineAxes> solved =
            kinematics::inverseKinematics(machine.chain, {record.tip, record.axis}, aReference);
        if (!solved) {
            Error error = std::move(solved.error());
            error.message = "record " + std::to_string(i) + ": " + error.message;
            return std::unexpected(std::move(error));
        }
        aReference = solved->a;
        axes.push_back(*solved);
    }
    return axes;
}

class BlockWriter {
  public:
    BlockWriter(const GcodeEmitOptions& options, const kinematics::MachineModel& machine)
        : m_options(options), m_machine(machine),
          m_moduloTable(machine.aMode == kinematics::RotaryMode::Modulo) {}

    void startBlock(std::string& out) {
        if (m_options.blockNumbers) {
            m_number += m_options.blockNumberStep;
            out += 'N';
            out += std::to_string(m_number);
            out += ' ';
        }
    }

    // In the program's letters and signs: X Y Z, then A and B, the table's modulo if it is.
    void axesWords(std::string& out, const MachineAxes& axes) const {
        const std::array<double, 5> values = m_machine.programValues(axes);
        const std::size_t table = m_machine.programWord(kinematics::AxisId::A).index;
        for (std::size_t i = 0; i < values.size(); ++i) {
            word(out, kinematics::kProgramLetters[i],
                 i < 3 ? formatFixed(values[i], m_options.linearDecimals)
                       : angle(values[i], m_moduloTable && i == table));
        }
    }

    static void word(std::string& out, char letter, const std::string& value) {
        out += ' ';
        out += letter;
        out += value;
    }

  private:
    std::string angle(double radians, bool modulo) const {
        double degrees = units::radToDeg(radians);
        if (modulo) {
            degrees = std::fmod(degrees, 360.0);
            degrees += degrees < 0.0 ? 360.0 : 0.0;
            std::string text = formatFixed(degrees, m_options.angularDecimals);
            // Rounding may reach 360 exactly; a modulo axis writes that as 0.
            return parseNumber(text).value_or(0.0) >= 360.0
                       ? formatFixed(0.0, m_options.angularDecimals)
                       : text;
        }
        return formatFixed(degrees, m_options.angularDecimals);
    }

    const GcodeEmitOptions& m_options;
    const kinematics::MachineModel& m_machine;
    bool m_moduloTable = false;
    int m_number = 0;
};

} // namespace

Result<std::string> emitGcode(const toolpath::Toolpath& path,
                              const kinematics::MachineModel& machine,
                              const GcodeEmitOptions& options) {
    if (Status valid = validateOptions(options); !valid) {
        return std::unexpected(std::move(valid.error()));
    }
    Result<std::vector<MachineAxes>> axes = solveAxes(path, machine);
    if (!axes) {
        return std::unexpected(std::move(axes.error()));
    }
    std::string out;
    out.reserve(64 * (path.records.size() + options.headerComments.size() + 2));
    for (const std::string& comment : options.headerComments) {
        out += commentLine(comment);
    }
    BlockWriter writer(options, machine);
    writer.startBlock(out);
    out += "G21 G90 G94\n";
    std::string lastFeed;
    for (std::size_t i = 0; i < path.records.size(); ++i) {
        const toolpath::ClRecord& record = path.records[i];
        const bool feedMove = record.motion == toolpath::MotionKind::Feed;
        std::string feed;
        if (feedMove && record.feed > 0.0 && std::isfinite(record.feed)) {
            feed = formatTrimmed(units::perSecondToPerMinute(record.feed), kFeedDecimals);
        }
        if (feedMove && feed.empty() && lastFeed.empty()) {
            return makeError(ErrorCode::InvalidArgument,
                             "record " + std::to_string(i) +
                                 ": feed move without a positive feed and no earlier feed");
        }
        writer.startBlock(out);
        out += feedMove ? "G1" : "G0";
        writer.axesWords(out, (*axes)[i]);
        if (feedMove && !feed.empty() && feed != lastFeed) {
            BlockWriter::word(out, 'F', feed);
            lastFeed = feed;
        }
        out += '\n';
    }
    writer.startBlock(out);
    out += "M30\n";
    return out;
}

} // namespace bladeaxis::io::nc
