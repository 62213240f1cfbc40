#include "core/job/program_check.h"

#include "core/base/number_io.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace bladeaxis::job {

namespace {

std::string degrees(double radians, int decimals = 3) {
    return formatFixed(units::radToDeg(radians), decimals) + " deg";
}

std::string at(const std::string& file, int line) {
    return SourceLocation{file, line, 0}.toString();
}

double medianOf(std::vector<double> values) {
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

// How far `theta` lies outside [low, high], rad; 0 inside. The orientation is physical, so
// theta is taken on the 2 pi branch nearest the channel's middle.
double outsideDistance(double theta, double low, double high) {
    const double middle = 0.5 * (low + high);
    const double nearest = middle + std::remainder(theta - middle, units::kTwoPi);
    return std::max({low - nearest, nearest - high, 0.0});
}

// The refusal of a varying tilt, in the program's letter and sign of the tilt (`tilts` and
// `median` in the engine's, rad).
std::string varyingTiltMessage(std::span<const toolpath::ClRecord> pass, std::vector<double> tilts,
                               std::size_t offending, double median, const std::string& file,
                               const ProgramCheckOptions& options, RotaryLetters letters) {
    for (double& tilt : tilts) {
        tilt *= letters.tiltSign;
    }
    median *= letters.tiltSign;
    const auto [low, high] = std::minmax_element(tilts.begin(), tilts.end());
    const auto lineOf = [&](auto it) {
        return pass[static_cast<std::size_t>(it - tilts.begin())].line;
    };
    const std::string b(1, letters.tilt);
    std::string message =
        "not a four-axis blade pass: the tool tilt " + b + " is " + degrees(tilts[offending]) +
        " here, " + degrees(tilts[offending] - median) + " from its median " + degrees(median) +
        " along the cutting pass (" + b + " ranges from " + degrees(*low) + " at " +
        at(file, lineOf(low)) + " to " + degrees(*high) + " at " + at(file, lineOf(high)) + ")";
    message += "; a four-axis pass holds " + b + " within " + degrees(options.tiltToleranceRad, 4) +
               ". BladeAxis re-schedules passes with a fixed " + b +
               " head only, so nothing was written. If the variation is noise of "
               "the post-processor, allow it with --b-tolerance-deg (" +
               b + " is then snapped to its median); a five-axis program cannot be re-scheduled";
    return message;
}

} // namespace

double tiltOf(const Vec3& axis) {
    return std::asin(std::clamp(axis.x() / axis.norm(), -1.0, 1.0));
}

Result<TiltCheck> checkConstantTilt(std::span<const toolpath::ClRecord> pass,
                                    const std::string& file, const ProgramCheckOptions& options,
                                    RotaryLetters letters) {
    TiltCheck check;
    if (pass.empty()) {
        return check;
    }
    std::vector<double> tilts;
    tilts.reserve(pass.size());
    for (const toolpath::ClRecord& record : pass) {
        tilts.push_back(tiltOf(record.axis));
    }
    check.medianRad = medianOf(tilts);
    std::size_t firstOffending = pass.size();
    for (std::size_t i = 0; i < pass.size(); ++i) {
        const double deviation = std::abs(tilts[i] - check.medianRad);
        check.largestDeviationRad = std::max(check.largestDeviationRad, deviation);
        if (deviation > options.tiltToleranceRad && firstOffending == pass.size()) {
            firstOffending = i;
        }
    }
    if (firstOffending == pass.size()) {
        return check;
    }
    const toolpath::ClRecord& offending = pass[firstOffending];
    return makeError(
        ErrorCode::Geometry,
        varyingTiltMessage(pass, tilts, firstOffending, check.medianRad, file, options, letters),
        {file, offending.line, 0});
}

std::size_t snapTilt(std::span<toolpath::ClRecord> pass, double tiltRad, double toolRadius) {
    std::size_t snapped = 0;
    const double axial = std::sin(tiltRad);
    const double inPlane = std::cos(tiltRad);
    for (toolpath::ClRecord& record : pass) {
        const Vec3 axis = record.axis.normalized();
        const Eigen::Vector2d radial = axis.tail<2>();
        if (radial.norm() < 1e-12) {
            continue; // along the rotary axis: refused later as degenerate geometry
        }
        const Vec3 snappedAxis(axial, inPlane * radial.x() / radial.norm(),
                               inPlane * radial.y() / radial.norm());
        const Vec3 centre = record.tip + toolRadius * axis;
        snapped += std::abs(tiltOf(axis) - tiltRad) > kReportedTiltDeviationRad ? 1 : 0;
        record.axis = snappedAxis;
        record.tip = centre - toolRadius * snappedAxis;
    }
    return snapped;
}

std::string describeSnap(const TiltCheck& tilt, const std::string& file, RotaryLetters letters) {
    if (tilt.snappedRecords == 0 || tilt.largestDeviationRad <= kReportedTiltDeviationRad) {
        return {};
    }
    const std::string b(1, letters.tilt);
    return file + ": the tool tilt " + b + " varies by up to " +
           degrees(tilt.largestDeviationRad, 5) + " from its median " +
           degrees(letters.tiltSign * tilt.medianRad, 4) + " (within the tolerance); " + b +
           " of " + std::to_string(tilt.snappedRecords) +
           " cutting record(s) was snapped to the median, every ball centre kept";
}

namespace {

std::string helicalAdvice(RotaryLetters letters, AngleWordsRead angles) {
    const std::string words =
        "the " + std::string(1, letters.table) + " and " + std::string(1, letters.tilt) + " words";
    const std::string machine = "check that the machine file's rotary axis is the program's";
    switch (angles) {
    case AngleWordsRead::NoAngleWords:
        return "Check that the machine file's rotary axis is the program's";
    case AngleWordsRead::Inferred:
        return "If " + words + " are in radians, give --angle-unit rad; " + machine;
    case AngleWordsRead::GivenDegrees:
        return "--angle-unit deg read " + words +
               " as degrees: if they are radians, give "
               "--angle-unit rad; " +
               machine;
    case AngleWordsRead::GivenRadians:
        return "--angle-unit rad read " + words +
               " as radians: check that they are, and that the machine file's rotary axis is "
               "the program's";
    }
    return machine;
}

} // namespace

Status checkHelical(std::span<const toolpath::ClRecord> pass, double toolRadius,
                    const std::string& file, RotaryLetters letters, AngleWordsRead angles) {
    if (pass.size() < 2) {
        return {};
    }
    double turned = 0.0;
    double previous = 0.0;
    for (std::size_t i = 0; i < pass.size(); ++i) {
        const Vec3 centre = toolpath::ballCentre(pass[i], toolRadius);
        const double angle = std::atan2(centre.z(), centre.y());
        if (i > 0) {
            turned += std::remainder(angle - previous, units::kTwoPi);
        }
        previous = angle;
    }
    if (std::abs(turned) >= kMinimumHelicalTurnRad) {
        return {};
    }
    return makeError(ErrorCode::Geometry,
                     "not a helical blade pass: the ball centres turn only " +
                         degrees(std::abs(turned), 1) + " about the rotary axis from here to " +
                         at(file, pass.back().line) +
                         " (a helical pass turns 360 deg per layer, at least " +
                         degrees(kMinimumHelicalTurnRad, 0) + "). " +
                         helicalAdvice(letters, angles) + ". Nothing was written",
                     {file, pass.front().line, 0});
}

Status checkOrientationInChannel(const scheduling::ScheduleResult& schedule,
                                 std::span<const toolpath::ClRecord> pass, const std::string& file,
                                 const ProgramCheckOptions& options, RotaryLetters letters) {
    double largest = 0.0;
    std::size_t layerOfLargest = 0;
    std::size_t recordOfLargest = 0;
    std::size_t firstOffending = pass.size();
    for (std::size_t k = 0; k < schedule.layers.size(); ++k) {
        const scheduling::LayerResult& layer = schedule.layers[k];
        for (std::size_t j = 0; j < layer.thetaOriginal.size(); ++j) {
            if (!std::isfinite(layer.thetaMin[j]) || !std::isfinite(layer.thetaMax[j])) {
                continue;
            }
            const double outside =
                outsideDistance(layer.thetaOriginal[j], layer.thetaMin[j], layer.thetaMax[j]);
            const std::size_t record = layer.inputIndex[j];
            if (outside > options.channelToleranceRad && record < firstOffending) {
                firstOffending = record;
            }
            if (outside > largest) {
                largest = outside;
                layerOfLargest = k;
                recordOfLargest = record;
            }
        }
    }
    if (firstOffending == pass.size()) {
        return {};
    }
    return makeError(
        ErrorCode::Geometry,
        "not the blade pass this machine re-schedules: the CAM tool orientation lies outside the "
        "feasible S-theta channel by up to " +
            degrees(largest, 1) + " (layer " + std::to_string(layerOfLargest + 1) + ", " +
            at(file, pass[recordOfLargest].line) + "), more than the " +
            degrees(options.channelToleranceRad, 1) +
            " allowed; the first such record is here. A four-axis blade program with a fixed lead "
            "lies inside its channel: check the machine file (--machine: rotary axis, " +
            std::string(1, letters.tilt) +
            " head, "
            "sign conventions) and that the tool axis points away from the blade. Nothing was "
            "written; --channel-tolerance-deg accepts a larger distance",
        {file, pass[firstOffending].line, 0});
}

} // namespace bladeaxis::job
