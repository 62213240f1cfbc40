#include "core/report/schedule_report.h"

#include "core/analysis/reversals.h"
#include "core/base/number_io.h"
#include "core/base/units.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace bladeaxis::report {

namespace {

using kinematics::AxisId;
using units::radToDeg;

void appendCell(std::string& row, double value) {
    row += ',';
    row += formatShortest(value);
}

struct Peaks {
    double velocity = 0.0;
    double acceleration = 0.0;
};

// Peak |q'| and |q''| of one axis over the samples of a profile whose records fall in
// [first, last].
Peaks peaksWithin(const analysis::AxisProfile& profile, AxisId axis, std::size_t first,
                  std::size_t last) {
    Peaks peaks;
    const analysis::AxisSeries& a = profile.axis(axis);
    const auto begin =
        std::lower_bound(profile.sampleRecord.begin(), profile.sampleRecord.end(), first);
    for (auto it = begin; it != profile.sampleRecord.end() && *it <= last; ++it) {
        const auto i = static_cast<std::size_t>(it - profile.sampleRecord.begin());
        peaks.velocity = std::max(peaks.velocity, std::abs(a.velocityAt(i)));
        peaks.acceleration = std::max(peaks.acceleration, std::abs(a.accelerationAt(i)));
    }
    return peaks;
}

// The A reversals of records [first, last] of `count`, A of record i being aAt(i).
template <class AAt>
int reversalsWithin(std::size_t count, AAt&& aAt, std::size_t first, std::size_t last) {
    std::vector<double> a;
    for (std::size_t i = first; i <= last && i < count; ++i) {
        a.push_back(aAt(i));
    }
    return analysis::auditReversals(a).count;
}

template <class AAt>
std::vector<LayerAxisMotion> layerAxisMotionWith(std::span<const scheduling::LayerBounds> layers,
                                                 const analysis::AxisProfile& profile,
                                                 std::size_t records, AAt&& aAt) {
    std::vector<LayerAxisMotion> motion;
    motion.reserve(layers.size());
    for (const scheduling::LayerBounds& layer : layers) {
        LayerAxisMotion side;
        side.aReversals = reversalsWithin(records, aAt, layer.first, layer.last);
        for (AxisId axis : {AxisId::X, AxisId::Y, AxisId::Z, AxisId::A}) {
            const Peaks peaks = peaksWithin(profile, axis, layer.first, layer.last);
            side.peakVelocity[static_cast<int>(axis)] = peaks.velocity;
            side.peakAcceleration[static_cast<int>(axis)] = peaks.acceleration;
        }
        motion.push_back(side);
    }
    return motion;
}

nlohmann::json statusesJson(const scheduling::LayerResult& layer) {
    nlohmann::json flags = nlohmann::json::array();
    for (scheduling::LayerStatus status : layer.flags) {
        flags.push_back(scheduling::toString(status));
    }
    if (flags.empty()) {
        flags.push_back(scheduling::toString(scheduling::LayerStatus::Ok));
    }
    return flags;
}

double reduction(double before, double after) {
    return before > 0.0 ? (before - after) / before : 0.0;
}

} // namespace

std::string layersCsv(const scheduling::ScheduleResult& schedule, std::span<const int> lines) {
    std::string csv =
        "record,line,layer,s_mm,theta_original_deg,theta_min_deg,theta_max_deg,lo_deg,hi_deg,"
        "theta_deg,dtheta_deg_mm,ddtheta_deg_mm2\n";
    std::string row;
    for (std::size_t k = 0; k < schedule.layers.size(); ++k) {
        const scheduling::LayerResult& layer = schedule.layers[k];
        // The end sample is shared with the next layer; it is written once, by the next layer.
        const bool lastLayer = k + 1 == schedule.layers.size();
        const std::size_t count = layer.s.size() - (lastLayer ? 0 : 1);
        for (std::size_t i = 0; i < count; ++i) {
            const std::size_t record = layer.inputIndex[i];
            const int line = record < lines.size() ? lines[record] : 0;
            row = std::to_string(record) + ',' + std::to_string(line) + ',' + std::to_string(k);
            appendCell(row, layer.s[i]);
            for (const auto* series :
                 {&layer.thetaOriginal, &layer.thetaMin, &layer.thetaMax, &layer.lo, &layer.hi,
                  &layer.theta, &layer.dTheta, &layer.ddTheta}) {
                appendCell(row, radToDeg((*series)[i]));
            }
            csv += row + '\n';
        }
    }
    return csv;
}

std::vector<LayerAxisMotion> layerAxisMotion(std::span<const scheduling::LayerBounds> layers,
                                             const analysis::AxisProfile& profile,
                                             std::span<const kinematics::MachineAxes> axes) {
    return layerAxisMotionWith(layers, profile, axes.size(),
                               [axes](std::size_t i) { return axes[i].a; });
}

std::vector<LayerAxisMotion> layerAxisMotion(std::span<const scheduling::LayerBounds> layers,
                                             const analysis::AxisProfile& profile,
                                             std::span<const double> aOfRecords) {
    return layerAxisMotionWith(layers, profile, aOfRecords.size(),
                               [aOfRecords](std::size_t i) { return aOfRecords[i]; });
}

std::vector<LayerMotion> layerMotion(const BeforeAfter& data) {
    constexpr int kA = static_cast<int>(AxisId::A);
    std::vector<LayerMotion> motion;
    motion.reserve(data.before.size());
    for (std::size_t k = 0; k < data.before.size() && k < data.after.size(); ++k) {
        const LayerAxisMotion& before = data.before[k];
        const LayerAxisMotion& after = data.after[k];
        motion.push_back({before.aReversals, after.aReversals, before.peakVelocity[kA],
                          after.peakVelocity[kA], before.peakAcceleration[kA],
                          after.peakAcceleration[kA]});
    }
    return motion;
}

// Peak X/Y/Z velocity (mm/s) and acceleration (mm/s^2) of one layer before and after, at the
// programmed feed: where on the blade the linear axes gain or lose.
void addLinearPeaks(nlohmann::json& json, const LayerAxisMotion& before,
                    const LayerAxisMotion& after) {
    for (AxisId axis : {AxisId::X, AxisId::Y, AxisId::Z}) {
        std::string name = "peak_";
        name += static_cast<char>(std::tolower(kinematics::axisName(axis)[0]));
        const int index = static_cast<int>(axis);
        json[name + "_velocity_mm_s_before"] = before.peakVelocity[index];
        json[name + "_velocity_mm_s_after"] = after.peakVelocity[index];
        json[name + "_acceleration_mm_s2_before"] = before.peakAcceleration[index];
        json[name + "_acceleration_mm_s2_after"] = after.peakAcceleration[index];
    }
}

nlohmann::json layersJson(const scheduling::ScheduleResult& schedule, const BeforeAfter& data) {
    nlohmann::json layers = nlohmann::json::array();
    const std::vector<LayerMotion> motion = layerMotion(data);
    for (std::size_t k = 0; k < schedule.layers.size() && k < motion.size(); ++k) {
        const scheduling::LayerResult& layer = schedule.layers[k];
        const LayerMotion& m = motion[k];
        nlohmann::json json;
        json["index"] = k;
        json["status"] = statusesJson(layer);
        json["first_line"] =
            layer.first < data.sourceLines.size() ? data.sourceLines[layer.first] : 0;
        json["last_line"] = layer.last < data.sourceLines.size() ? data.sourceLines[layer.last] : 0;
        json["samples"] = layer.s.size();
        json["length_mm"] = layer.s.empty() ? 0.0 : layer.s.back();
        json["a_reversals_before"] = m.reversalsBefore;
        json["a_reversals_after"] = m.reversalsAfter;
        json["peak_a_velocity_deg_s_before"] = radToDeg(m.peakVelocityBefore);
        json["peak_a_velocity_deg_s_after"] = radToDeg(m.peakVelocityAfter);
        json["peak_a_acceleration_deg_s2_before"] = radToDeg(m.peakAccelerationBefore);
        json["peak_a_acceleration_deg_s2_after"] = radToDeg(m.peakAccelerationAfter);
        addLinearPeaks(json, data.before[k], data.after[k]);
        json["min_channel_clearance_deg"] = radToDeg(layer.minClearance);
        json["lead_fraction"] = layer.leadFraction;
        json["key_points"] = layer.keyPoints.size();
        json["corners"] = layer.corners.size();
        json["peak_theta_dd_deg_mm2"] = radToDeg(layer.peakSecondDerivative);
        json["timing"] = {{"seconds", layer.seconds}};
        layers.push_back(json);
    }
    return layers;
}

nlohmann::json reductionsJson(const analysis::AxisProfile& before,
                              const analysis::AxisProfile& after) {
    nlohmann::json json;
    for (AxisId axis : {AxisId::X, AxisId::Y, AxisId::Z, AxisId::A}) {
        const auto& b = before.axis(axis);
        const auto& a = after.axis(axis);
        json[kinematics::axisName(axis)] = {
            {"peak_velocity", reduction(b.peakVelocity, a.peakVelocity)},
            {"peak_acceleration", reduction(b.peakAcceleration, a.peakAcceleration)},
        };
    }
    return json;
}

} // namespace bladeaxis::report
