#include "core/analysis/constant_feed.h"

#include <cmath>

namespace bladeaxis::analysis {

namespace {

// Highest feed a limit allows when the path derivative peaks at `pathPeak`: the axis quantity
// scales with F^order, so F <= (limit / pathPeak)^(1/order). Infinity when it cannot bind.
double feedAllowed(double limit, double pathPeak, int order) {
    if (!(limit > 0.0) || !std::isfinite(limit) || !(pathPeak > 0.0)) {
        return HUGE_VAL;
    }
    const double ratio = limit / pathPeak;
    switch (order) {
    case 1:
        return ratio;
    case 2:
        return std::sqrt(ratio);
    default:
        return std::cbrt(ratio);
    }
}

} // namespace

ConstantFeedTime constantFeedTime(const AxisProfile& profile,
                                  const kinematics::MachineModel& machine, bool includeJerk) {
    ConstantFeedTime result;
    const double feed = profile.feed;
    if (!(feed > 0.0) || !std::isfinite(feed)) {
        return result;
    }
    result.feed = feed;
    double tightest = HUGE_VAL;
    ConstantFeedTime::Binding tightestKind = ConstantFeedTime::Binding::Velocity;
    for (kinematics::AxisId id : kinematics::kAllAxes) {
        const AxisSeries& series = profile.axis(id);
        const kinematics::AxisLimits& limits = machine.limit(id);
        const double candidates[3] = {
            feedAllowed(limits.velocity, series.peakVelocity / feed, 1),
            feedAllowed(limits.acceleration, series.peakAcceleration / (feed * feed), 2),
            includeJerk ? feedAllowed(limits.jerk, series.peakJerk / (feed * feed * feed), 3)
                        : HUGE_VAL,
        };
        for (int k = 0; k < 3; ++k) {
            if (candidates[k] < tightest) {
                tightest = candidates[k];
                tightestKind = static_cast<ConstantFeedTime::Binding>(k + 1);
                result.bindingAxis = id;
            }
        }
    }
    result.binding = tightest < feed ? tightestKind : ConstantFeedTime::Binding::Programmed;
    result.achievableFeed = std::min(feed, tightest);
    // The path parameter is the tip's arc length, or F x the block times of a program timed by
    // its blocks (AxisProfileOptions::blockTimes): the programmed time scaled to the feed.
    const double parameterLength =
        profile.pathParameter.empty() ? profile.pathLength : profile.pathParameter.back();
    result.time = parameterLength / result.achievableFeed;
    return result;
}

} // namespace bladeaxis::analysis
