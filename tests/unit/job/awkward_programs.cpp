#include "awkward_programs.h"

#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/io/cl/apt_reader.h"
#include "core/job/demo_program.h"
#include "core/kinematics/kinematics.h"

#include <array>
#include <cmath>
#include <stdexcept>

namespace bladeaxis::job::test {

namespace {

using toolpath::ClRecord;

CleanPass makeCleanPass() {
    GenerateRequest request;
    request.format = "apt";
    request.revolutions = 2.0;
    auto generated = generateProgram(request, kinematics::defaultBladeMachine());
    if (!generated) {
        throw std::runtime_error(generated.error().toString());
    }
    auto program = io::cl::parseApt(generated->text, "clean.cl");
    if (!program) {
        throw std::runtime_error(program.error().toString());
    }
    CleanPass pass;
    pass.path = program->path;
    pass.toolRadius = generated->toolRadius;
    for (const ClRecord& record : pass.path.records) {
        if (record.motion == toolpath::MotionKind::Feed && record.feed > 0.0) {
            pass.feedMmPerMin = units::perSecondToPerMinute(record.feed);
            break;
        }
    }
    return pass;
}

std::string number(double value, int decimals = 6) {
    return formatFixed(value, decimals);
}

std::string endOf(LineEnd end) {
    return end == LineEnd::Crlf ? "\r\n" : "\n";
}

// Turns `axis` to the tilt `tilt` (rad) keeping its in-plane direction.
Vec3 withTilt(const Vec3& axis, double tilt) {
    const Eigen::Vector2d radial = axis.tail<2>().normalized();
    return {std::sin(tilt), std::cos(tilt) * radial.x(), std::cos(tilt) * radial.y()};
}

// The record with a new axis and the tip moved so that the ball centre stays.
ClRecord keepingCentre(ClRecord record, const Vec3& axis, double toolRadius) {
    const Vec3 centre = toolpath::ballCentre(record, toolRadius);
    record.axis = axis.normalized();
    record.tip = centre - toolRadius * record.axis;
    record.axes.reset();
    return record;
}

} // namespace

const CleanPass& cleanPass() {
    static const CleanPass pass = makeCleanPass();
    return pass;
}

std::string aptText(const toolpath::Toolpath& path, double toolRadius, double feedMmPerMin,
                    const AptStyle& style) {
    const std::string end = endOf(style.lineEnd);
    std::string text;
    if (style.header) {
        text += "PARTNO/AWKWARD BLADE" + end + "UNITS/MM" + end;
        text += "CUTTER/" + number(2.0 * toolRadius, 4) + "," + number(toolRadius, 4) + end;
        text += "MULTAX/ON" + end + "FEDRAT/MMPM," + number(feedMmPerMin, 1) + end;
    }
    for (const ClRecord& record : path.records) {
        const Vec3 axis = record.axis.normalized();
        const std::string point =
            number(record.tip.x()) + "," + number(record.tip.y()) + "," + number(record.tip.z());
        const std::string vector =
            number(axis.x()) + "," + number(axis.y()) + "," + number(axis.z());
        text += style.continuations ? "GOTO/" + point + ",$" + end + "  " + vector + end
                                    : "GOTO/" + point + "," + vector + end;
    }
    if (style.header) {
        text += "FINI" + end;
    }
    return text;
}

std::string tableText(const toolpath::Toolpath& path, char separator, bool header) {
    const std::string sep(1, separator);
    std::string text;
    if (header) {
        text += "x" + sep + "y" + sep + "z" + sep + "i" + sep + "j" + sep + "k\n";
    }
    for (const ClRecord& record : path.records) {
        const Vec3 axis = record.axis.normalized();
        text += number(record.tip.x()) + sep + number(record.tip.y()) + sep +
                number(record.tip.z()) + sep + number(axis.x()) + sep + number(axis.y()) + sep +
                number(axis.z()) + "\n";
    }
    return text;
}

// F of block i: one F for G94, the feed over the tip chord into the block for G93 (the first
// block's chord is the one out of it).
std::string feedWord(const toolpath::Toolpath& path, std::size_t i, double feedMmPerMin,
                     FeedMode feedMode) {
    if (feedMode == FeedMode::PerMinute) {
        return i == 0 ? " F" + number(feedMmPerMin, 1) : "";
    }
    const auto& records = path.records;
    const std::size_t from = i == 0 ? 0 : i - 1, to = i == 0 ? 1 : i;
    const double chord = (records[to].tip - records[from].tip).norm();
    return " F" + number(feedMmPerMin / std::max(chord, 1e-6), 3);
}

std::string gcodeText(const toolpath::Toolpath& path, const kinematics::MachineModel& machine,
                      double feedMmPerMin, RotaryUnit unit, double bNoiseDeg, FeedMode feedMode) {
    std::vector<kinematics::ToolPose> poses;
    for (const ClRecord& record : path.records) {
        poses.push_back({record.tip, record.axis.normalized()});
    }
    const auto solved = kinematics::inverseKinematicsAlong(machine.chain, poses, 0.0);
    if (solved.failedIndex) {
        throw std::runtime_error(solved.failure.toString());
    }
    const auto rotary = [unit](double radians) {
        return unit == RotaryUnit::Radians ? number(radians, 7)
                                           : number(units::radToDeg(radians), 4);
    };
    std::string text = feedMode == FeedMode::PerMinute ? "(AWKWARD BLADE PROGRAM)\nG21 G90 G94\n"
                                                       : "(AWKWARD BLADE PROGRAM)\nG21 G90 G93\n";
    for (std::size_t i = 0; i < solved.axes.size(); ++i) {
        kinematics::MachineAxes axes = solved.axes[i];
        axes.b += (i % 2 == 0 ? 1.0 : -1.0) * units::degToRad(bNoiseDeg);
        // In the program's letters: a table-B machine's words are the engine's axes turned.
        const std::array<double, 5> words = machine.programValues(axes);
        text += "G1 X" + number(words[0], 4) + " Y" + number(words[1], 4) + " Z" +
                number(words[2], 4) + " A" + rotary(words[3]) + " B" + rotary(words[4]);
        text += feedWord(path, i, feedMmPerMin, feedMode) + "\n";
    }
    return text + "M30\n";
}

toolpath::Toolpath withVaryingTilt(const toolpath::Toolpath& path, double toolRadius,
                                   double extraTiltDeg) {
    toolpath::Toolpath varied = path;
    const double count = static_cast<double>(std::max<std::size_t>(path.records.size() - 1, 1));
    for (std::size_t i = 0; i < varied.records.size(); ++i) {
        const Vec3 axis = path.records[i].axis.normalized();
        const double tilt =
            std::asin(axis.x()) + units::degToRad(extraTiltDeg) * static_cast<double>(i) / count;
        varied.records[i] = keepingCentre(path.records[i], withTilt(axis, tilt), toolRadius);
    }
    return varied;
}

toolpath::Toolpath withAxisFromBelow(const toolpath::Toolpath& path, double toolRadius) {
    toolpath::Toolpath flipped = path;
    for (std::size_t i = 0; i < flipped.records.size(); ++i) {
        const Vec3 axis = path.records[i].axis.normalized();
        flipped.records[i] =
            keepingCentre(path.records[i], Vec3(axis.x(), axis.y(), -axis.z()), toolRadius);
    }
    return flipped;
}

toolpath::Toolpath withMicroChords(const toolpath::Toolpath& path, double toolRadius,
                                   double chordMm, int every) {
    toolpath::Toolpath chorded = path;
    chorded.records.clear();
    for (std::size_t i = 0; i < path.records.size(); ++i) {
        const ClRecord& record = path.records[i];
        chorded.records.push_back(record);
        if (i + 1 >= path.records.size() || i % static_cast<std::size_t>(every) != 0) {
            continue;
        }
        const ClRecord& next = path.records[i + 1];
        const Vec3 from = toolpath::ballCentre(record, toolRadius);
        const Vec3 to = toolpath::ballCentre(next, toolRadius);
        const double length = (to - from).norm();
        if (length <= 2.0 * chordMm) {
            continue;
        }
        const double t = chordMm / length;
        ClRecord inserted = record;
        // Interpolated in the plane, at the record's own tilt: a post splits a move, it does
        // not tilt the tool.
        const Vec3 blend = (1.0 - t) * record.axis.normalized() + t * next.axis.normalized();
        const Vec3 centre = from + t * (to - from);
        inserted.axis = withTilt(blend, std::asin(record.axis.normalized().x()));
        inserted.tip = centre - toolRadius * inserted.axis;
        chorded.records.push_back(inserted);
    }
    return chorded;
}

} // namespace bladeaxis::job::test
