#include "core/report/analysis_report.h"

#include "core/base/number_io.h"
#include "core/base/units.h"

#include <algorithm>

namespace bladeaxis::report {

using kinematics::AxisId;

double toReportUnit(AxisId axis, double value) {
    return kinematics::isRotary(axis) ? units::radToDeg(value) : value;
}

const char* unitOf(AxisId axis) {
    return kinematics::isRotary(axis) ? "deg" : "mm";
}

nlohmann::json lostMotionJson(std::span<const analysis::LostMotion> losses) {
    nlohmann::json json = nlohmann::json::object();
    for (const analysis::LostMotion& loss : losses) {
        const std::string unit = unitOf(loss.axis);
        json[kinematics::axisName(loss.axis)] = {
            {"backlash_" + unit, toReportUnit(loss.axis, loss.backlash)},
            {"reversals", loss.reversals},
            {"lost_motion_" + unit, toReportUnit(loss.axis, loss.lostMotion)}};
    }
    return json;
}

namespace {

nlohmann::json axisJson(AxisId axis, const analysis::AxisProfile& profile) {
    const analysis::AxisSeries& series = profile.axis(axis);
    const std::string unit = unitOf(axis);
    nlohmann::json json;
    json["peak_velocity_" + unit + "_s"] = toReportUnit(axis, series.peakVelocity);
    json["peak_acceleration_" + unit + "_s2"] = toReportUnit(axis, series.peakAcceleration);
    json["peak_jerk_" + unit + "_s3"] = toReportUnit(axis, series.peakJerk);
    json["p999_velocity_" + unit + "_s"] = toReportUnit(axis, series.p999Velocity);
    json["p999_acceleration_" + unit + "_s2"] = toReportUnit(axis, series.p999Acceleration);
    if (profile.sampleCount() > 0) {
        json["min_" + unit] = toReportUnit(axis, series.minPosition);
        json["max_" + unit] = toReportUnit(axis, series.maxPosition);
    }
    return json;
}

const char* bindingName(analysis::ConstantFeedTime::Binding binding) {
    switch (binding) {
    case analysis::ConstantFeedTime::Binding::Programmed:
        return "programmed feed";
    case analysis::ConstantFeedTime::Binding::Velocity:
        return "velocity";
    case analysis::ConstantFeedTime::Binding::Acceleration:
        return "acceleration";
    case analysis::ConstantFeedTime::Binding::Jerk:
        return "jerk";
    }
    return "unknown";
}

} // namespace

nlohmann::json analysisJson(const analysis::AxisProfile& profile,
                            const analysis::ConstantFeedTime& constantFeed) {
    nlohmann::json json;
    json["samples"] = profile.sampleCount();
    json["merged_duplicates"] = profile.mergedDuplicates;
    json["path_length_mm"] = profile.pathLength;
    json["feed_mm_min"] = units::perSecondToPerMinute(profile.feed);
    json["cycle_time_at_programmed_feed_s"] = profile.cycleTime;
    json["feed_reference"] =
        profile.feedReference == analysis::FeedReference::Centre ? "centre" : "tip";
    json["derivatives"] = analysis::nameOf(profile.method);
    json["merged_short_chords"] = profile.mergedShortChords;
    nlohmann::json axes;
    for (AxisId axis : kinematics::kAllAxes) {
        axes[kinematics::axisName(axis)] = axisJson(axis, profile);
    }
    json["axes"] = axes;
    json["a_reversals"] = profile.aReversals.count;
    json["a_travel_deg"] = units::radToDeg(profile.aReversals.travel);
    json["a_backward_travel_deg"] = units::radToDeg(profile.aReversals.backwardTravel);
    json["constant_feed_time"] = {
        {"programmed_feed_mm_min", units::perSecondToPerMinute(constantFeed.feed)},
        {"achievable_feed_mm_min", units::perSecondToPerMinute(constantFeed.achievableFeed)},
        {"time_s", constantFeed.time},
        {"binding_axis", kinematics::axisName(constantFeed.bindingAxis)},
        {"binding_limit", bindingName(constantFeed.binding)},
    };
    return json;
}

namespace {

void appendNumber(std::string& row, double value) {
    row += formatShortest(value);
    row += ',';
}

std::string csvHeader() {
    std::string header = "record,line,s_mm,t_s";
    for (AxisId axis : kinematics::kAllAxes) {
        header += std::string(",") + kinematics::axisName(axis) + "_" + unitOf(axis);
    }
    for (AxisId axis : kinematics::kAllAxes) {
        header += std::string(",v") + kinematics::axisName(axis) + "_" + unitOf(axis) + "_s";
    }
    for (AxisId axis : kinematics::kAllAxes) {
        header += std::string(",a") + kinematics::axisName(axis) + "_" + unitOf(axis) + "_s2";
    }
    return header + ",a_reversal\n";
}

} // namespace

std::string axesCsv(const analysis::AxisProfile& profile,
                    std::span<const toolpath::ClRecord> records) {
    std::string csv = csvHeader();
    const std::size_t n = profile.pathParameter.size();
    csv.reserve(csv.size() + n * 200);
    // Reversal indices are record indices (a rotation at a merged point still counts).
    std::vector<bool> reversal(records.size(), false);
    for (std::size_t index : profile.aReversals.indices) {
        if (index < reversal.size()) {
            reversal[index] = true;
        }
    }
    std::string row;
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t record = profile.sampleRecord[i];
        row = std::to_string(record) + ',' +
              std::to_string(record < records.size() ? records[record].line : 0) + ',';
        appendNumber(row, profile.pathParameter[i]);
        appendNumber(row, profile.timeAt(i));
        for (AxisId axis : kinematics::kAllAxes) {
            appendNumber(row, toReportUnit(axis, profile.position(axis, i)));
        }
        for (AxisId axis : kinematics::kAllAxes) {
            appendNumber(row, toReportUnit(axis, profile.axis(axis).velocityAt(i)));
        }
        for (AxisId axis : kinematics::kAllAxes) {
            appendNumber(row, toReportUnit(axis, profile.axis(axis).accelerationAt(i)));
        }
        row += record < reversal.size() && reversal[record] ? "1\n" : "0\n";
        csv += row;
    }
    return csv;
}

} // namespace bladeaxis::report
