#include "core/scheduling/reconstruction.h"

#include "core/base/number_io.h"
#include "core/base/parallel.h"
#include "core/base/tolerances.h"
#include "core/base/units.h"

#include <algorithm>
#include <cmath>

namespace bladeaxis::scheduling {

ReconstructedPath reconstructAxes(std::span<const Vec3> centres, std::span<const double> thetaAbs,
                                  double tiltB0, int traversalSign, double toolRadius,
                                  unsigned threads) {
    ReconstructedPath path;
    const std::size_t n = std::min(centres.size(), thetaAbs.size());
    path.axes.resize(n);
    path.tips.resize(n);
    // axisFromPlaneAngle with the tilt's sine and cosine taken once (the same arithmetic).
    const double axial = std::sin(tiltB0);
    const double inPlane = std::cos(tiltB0);
    forEachRange(n, threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const double angle = thetaAbs[i];
            const Vec3 axis(axial, -traversalSign * std::sin(angle) * inPlane,
                            std::cos(angle) * inPlane);
            path.axes[i] = axis;
            path.tips[i] = centres[i] - toolRadius * axis;
        }
    });
    return path;
}

std::size_t countReversals(std::span<const double> angles, double step) {
    std::size_t reversals = 0;
    int lastSign = 0;
    for (std::size_t i = 1; i < angles.size(); ++i) {
        const double d = angles[i] - angles[i - 1];
        if (std::abs(d) <= step) {
            continue;
        }
        const int sign = d > 0.0 ? 1 : -1;
        reversals += lastSign != 0 && sign != lastSign ? 1 : 0;
        lastSign = sign;
    }
    return reversals;
}

ReconstructionCheck checkReconstruction(std::span<const Vec3> centres,
                                        const ReconstructedPath& path,
                                        std::span<const double> thetaAbs, double tiltB0,
                                        double toolRadius, unsigned threads) {
    const double axial = std::sin(tiltB0);
    const std::size_t n = std::min(path.axes.size(), centres.size());
    // Maxima per range, then over the ranges: a maximum does not depend on the order.
    std::vector<ReconstructionCheck> ranges(rangeCount(n, threads));
    forEachRangeOf(n, ranges.size(), [&](std::size_t range, std::size_t begin, std::size_t end) {
        ReconstructionCheck& check = ranges[range];
        for (std::size_t i = begin; i < end; ++i) {
            const Vec3& v = path.axes[i];
            check.maxCentreErrorMm = std::max(check.maxCentreErrorMm,
                                              (path.tips[i] + toolRadius * v - centres[i]).norm());
            check.maxUnitError = std::max(check.maxUnitError, std::abs(v.norm() - 1.0));
            check.maxTiltError = std::max(check.maxTiltError, std::abs(v.x() - axial));
        }
    });
    ReconstructionCheck check;
    for (const ReconstructionCheck& range : ranges) {
        check.maxCentreErrorMm = std::max(check.maxCentreErrorMm, range.maxCentreErrorMm);
        check.maxUnitError = std::max(check.maxUnitError, range.maxUnitError);
        check.maxTiltError = std::max(check.maxTiltError, range.maxTiltError);
    }
    check.reversals = countReversals(thetaAbs, tol::kReversalStepRad);
    return check;
}

std::string describeFailures(const ReconstructionCheck& check) {
    std::string text;
    const auto add = [&text](bool failed, const char* what, double value, double limit,
                             const char* unit) {
        if (failed) {
            text += (text.empty() ? "" : ", ") + std::string(what) + " " + formatShortest(value) +
                    " " + unit + " (limit " + formatShortest(limit) + " " + unit + ")";
        }
    };
    add(!(check.maxCentreErrorMm < ReconstructionCheck::kCentreLimitMm), "ball centre error",
        check.maxCentreErrorMm, ReconstructionCheck::kCentreLimitMm, "mm");
    add(!(check.maxUnitError < ReconstructionCheck::kUnitLimit), "tool axis length error",
        check.maxUnitError, ReconstructionCheck::kUnitLimit, "");
    add(!(check.maxTiltError < ReconstructionCheck::kTiltLimit), "tilt B error",
        units::radToDeg(check.maxTiltError), units::radToDeg(ReconstructionCheck::kTiltLimit),
        "deg");
    return text;
}

} // namespace bladeaxis::scheduling
