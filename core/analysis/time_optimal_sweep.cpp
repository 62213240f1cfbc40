#include "core/analysis/time_optimal_sweep.h"

#include <cmath>
#include <limits>
#include <string>

namespace bladeaxis::analysis {
kinematics::MachineModel scaledRotaryLimits(const kinematics::MachineModel& machine,
                                            double factor) {
    kinematics::MachineModel scaled = machine;
    for (const auto axis : {kinematics::AxisId::A, kinematics::AxisId::B}) {
        auto& limits = scaled.limit(axis);
        // Unlimited (<= 0) stays unlimited: scaling keeps the sign.
        limits.velocity *= factor;
        limits.acceleration *= factor;
        limits.jerk *= factor;
    }
    return scaled;
}

std::vector<double> defaultRotarySweepFactors() {
    return {0.5, 0.75, 1.0, 1.5, 2.0};
}

Result<std::vector<LimitSweepPoint>> sweepRotaryLimits(const AxisProfile& profile,
                                                       const kinematics::MachineModel& machine,
                                                       const std::vector<double>& factors,
                                                       const TimeOptimalOptions& options) {
    std::vector<LimitSweepPoint> points;
    points.reserve(factors.size());
    for (const double factor : factors) {
        if (!std::isfinite(factor) || factor <= 0.0) {
            return makeError(ErrorCode::InvalidArgument,
                             "rotary limit factor must be positive, got " + std::to_string(factor));
        }
        const auto t2 = timeOptimalTime(profile, scaledRotaryLimits(machine, factor), options);
        points.push_back({factor, t2 ? t2->time : std::numeric_limits<double>::quiet_NaN()});
    }
    return points;
}

} // namespace bladeaxis::analysis
