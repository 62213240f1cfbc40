#include "core/scheduling/schedule_parameters.h"

#include <cmath>
#include <string>

namespace bladeaxis::scheduling {

ScheduleParameters faithfulPreset() {
    ScheduleParameters parameters;
    parameters.preset = Preset::Faithful;
    parameters.leadMode = LeadMode::Fixed;
    parameters.epsilonRule = EpsilonRule::Paper;
    parameters.cornerForm = CornerForm::Euclidean;
    parameters.cornerProfile = CornerProfile::Bezier;
    parameters.keyMode = KeyMode::Both;
    return parameters;
}

ScheduleParameters bestPreset() {
    ScheduleParameters parameters;
    parameters.preset = Preset::Best;
    parameters.leadMode = LeadMode::Auto;
    parameters.epsilonRule = EpsilonRule::Exact;
    parameters.cornerForm = CornerForm::GraphLimit;
    parameters.cornerProfile = CornerProfile::Plateau;
    return parameters;
}

namespace {

Status requireRange(const char* name, double value, double low, double high) {
    if (!std::isfinite(value) || value < low || value > high) {
        return makeError(ErrorCode::InvalidArgument,
                         std::string(name) + " = " + std::to_string(value) + " is outside [" +
                             std::to_string(low) + ", " + std::to_string(high) + "]");
    }
    return {};
}

} // namespace

Status validateParameters(const ScheduleParameters& p) {
    const double halfPi = units::kPi / 2.0;
    const struct {
        const char* name;
        double value, low, high;
    } checks[] = {
        {"taperHalfAngleRad", p.taperHalfAngleRad, 0.0, halfPi},
        {"safetyAngleRad", p.safetyAngleRad, 0.0, halfPi},
        {"tangentChordMinMm", p.tangentChordMinMm, 0.0, 1e6},
        {"tangentChordMedianFactor", p.tangentChordMedianFactor, 0.0, 1e6},
        {"curvatureWindowMinMm", p.curvatureWindowMinMm, 0.0, 1e6},
        {"curvatureWindowRevolutionFraction", p.curvatureWindowRevolutionFraction, 0.0, 1.0},
        {"curvatureHysteresisPerMm", p.curvatureHysteresisPerMm, 0.0, 1e6},
        {"concaveGapToolRadii", p.concaveGapToolRadii, 0.0, 1e6},
        {"concaveMinRunToolRadii", p.concaveMinRunToolRadii, 0.0, 1e6},
        {"concaveMinRunRevolutionFraction", p.concaveMinRunRevolutionFraction, 0.0, 1.0},
        {"marginRad", p.marginRad, 0.0, halfPi},
        {"leadFraction", p.leadFraction, 0.0, 0.5},
        {"leadSearchMinFraction", p.leadSearchMinFraction, 0.0, 0.5},
        {"leadSearchMaxFraction", p.leadSearchMaxFraction, p.leadSearchMinFraction, 0.5},
        {"keyToleranceRad", p.keyToleranceRad, 0.0, 1e-3},
        {"finalClearanceRad", p.finalClearanceRad, 0.0, halfPi},
        {"leadBandMinRad", p.leadBandMinRad, -units::kPi, units::kPi},
        {"leadBandMaxRad", p.leadBandMaxRad, p.leadBandMinRad, units::kPi},
    };
    for (const auto& check : checks) {
        if (auto status = requireRange(check.name, check.value, check.low, check.high); !status) {
            return status;
        }
    }
    if (p.leadSearchEvaluations < 1 || p.leadSearchEvaluations > 1000) {
        return makeError(ErrorCode::InvalidArgument, "leadSearchEvaluations must be in [1, 1000]");
    }
    if (p.epsilonBisectionSteps < 1 || p.epsilonBisectionSteps > 200) {
        return makeError(ErrorCode::InvalidArgument, "epsilonBisectionSteps must be in [1, 200]");
    }
    if (p.curveChecksPerCubic < 2 || p.curveChecksPerCubic > 100000) {
        return makeError(ErrorCode::InvalidArgument, "curveChecksPerCubic must be in [2, 100000]");
    }
    return {};
}

} // namespace bladeaxis::scheduling
