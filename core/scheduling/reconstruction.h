#pragma once
// Spec §6.1, §6.2, §6.5: new tool axes from the absolute in-plane angle and B0, and the cheap
// reconstruction checks. The new tips O = Q - R V are not kept (tipOfBall makes them).

#include "core/geometry/vec.h"
#include "core/scheduling/schedule_samples.h"

#include <span>
#include <string>
#include <vector>

namespace bladeaxis::scheduling {

struct ReconstructedPath {
    std::vector<Vec3> axes; // unit V_i with V . a = sin B0
};

// One unit axis per absolute in-plane angle.
ReconstructedPath reconstructAxes(std::span<const double> thetaAbs, double tiltB0,
                                  int traversalSign);

struct ReconstructionCheck {
    double maxCentreErrorMm = 0.0; // max |O + R V - Q|, O = tipOfBall(Q, V, R)
    double maxUnitError = 0.0;     // max ||V| - 1|
    double maxTiltError = 0.0;     // max |V . a - sin B0|
    std::size_t reversals = 0;     // sign changes of dtheta beyond tol::kReversalStepRad (§6.4)
    // Largest |theta_end(k) - theta_start(k+1)| at a base point, rad: 0 when every layer meets its
    // neighbour (§6.5); a layer kept original whose orientation lies outside its neighbour's hull
    // leaves a step there.
    double maxJunctionGapRad = 0.0;

    static constexpr double kCentreLimitMm = 1e-9, kUnitLimit = 1e-12, kTiltLimit = 1e-12;

    bool passes() const {
        return maxCentreErrorMm < kCentreLimitMm && maxUnitError < kUnitLimit &&
               maxTiltError < kTiltLimit;
    }
};

// Each criterion of the check that failed, with its value and limit ("tilt error 3.2e-08 rad
// (limit 1e-12)"); empty when it passes.
std::string describeFailures(const ReconstructionCheck& check);

ReconstructionCheck checkReconstruction(std::span<const Vec3> centres,
                                        const ReconstructedPath& path,
                                        std::span<const double> thetaAbs, double tiltB0,
                                        double toolRadius);

// The same with the centres a sample reader makes where the caller keeps its input.
ReconstructionCheck checkReconstruction(const ScheduleSamples& samples,
                                        const ReconstructedPath& path,
                                        std::span<const double> thetaAbs, double tiltB0);

// Direction reversals of an angle sequence: sign changes among steps larger than `step`. Counted
// on the context's threads (core/base/execution.h), with the same count as on one.
std::size_t countReversals(std::span<const double> angles, double step);

} // namespace bladeaxis::scheduling
