#include "core/scheduling/reconstruction.h"

#include "core/base/number_io.h"
#include "core/base/parallel.h"
#include "core/base/tolerances.h"
#include "core/base/units.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bladeaxis::scheduling {

ReconstructedPath reconstructAxes(std::span<const double> thetaAbs, double tiltB0,
                                  int traversalSign) {
    ReconstructedPath path;
    const std::size_t n = thetaAbs.size();
    path.axes.resize(n);
    // axisFromPlaneAngle with the tilt's sine and cosine taken once (the same arithmetic).
    const double axial = std::sin(tiltB0);
    const double inPlane = std::cos(tiltB0);
    // Each thread takes its own copies of what it reads: with references to the caller's
    // locals, every sin and cos (calls the compiler cannot see into) made the loop read them
    // again from the caller's stack, and on two threads the loop took longer than on one
    // (14.6 ms against 11.2 at a million points; 5.5 ms with the copies).
    Vec3* const axes = path.axes.data();
    forEachRange(n, [=](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const double angle = thetaAbs[i];
            const Vec3 axis(axial, -traversalSign * std::sin(angle) * inPlane,
                            std::cos(angle) * inPlane);
            axes[i] = axis;
        }
    });
    return path;
}

namespace {

// The reversals inside one range of steps, and the first and last direction there (0: none),
// so that ranges combine in order into the count of the whole sequence.
struct ReversalRun {
    std::size_t reversals = 0;
    int firstSign = 0, lastSign = 0;
};

// Steps i in [begin, end), i >= 1: from angles[i - 1] to angles[i].
ReversalRun reversalsIn(std::span<const double> angles, double step, std::size_t begin,
                        std::size_t end) {
    // Without branches: whether a step counts follows the data (the input orientation swings
    // back and forth), so branches on it would be mispredicted often.
    ReversalRun run;
    for (std::size_t i = std::max<std::size_t>(begin, 1); i < end; ++i) {
        const double d = angles[i] - angles[i - 1];
        const bool counts = !(std::abs(d) <= step);
        const int sign = d > 0.0 ? 1 : -1;
        run.reversals +=
            static_cast<std::size_t>(counts && run.lastSign != 0 && sign != run.lastSign);
        run.firstSign = counts && run.firstSign == 0 ? sign : run.firstSign;
        run.lastSign = counts ? sign : run.lastSign;
    }
    return run;
}

// The check's maxima over [begin, end). The square root and |sqrt(x) - 1| are monotone on
// either side of their extremes, with correct rounding too, so the largest centre error is the
// root of the largest squared one, and the largest unit error is at the least or the greatest
// squared length: two roots per range instead of two per sample, and the same values.
// `centreAt` is copied: each thread then reads a function of its own rather than one on the
// caller's stack, beside values the caller's thread writes (a shared one made reads through it
// three times slower on two threads).
template <class CentreAt>
ReconstructionCheck checkRange(CentreAt centreAt, const ReconstructedPath& path, double axial,
                               double toolRadius, std::size_t begin, std::size_t end) {
    ReconstructionCheck check;
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    double maxCentreSquared = 0.0;
    double minLengthSquared = kInfinity;
    double maxLengthSquared = -kInfinity;
    for (std::size_t i = begin; i < end; ++i) {
        const Vec3& v = path.axes[i];
        const Vec3 centre = centreAt(i);
        maxCentreSquared =
            std::max(maxCentreSquared,
                     (tipOfBall(centre, v, toolRadius) + toolRadius * v - centre).squaredNorm());
        const double lengthSquared = v.squaredNorm();
        minLengthSquared = std::min(minLengthSquared, lengthSquared);
        maxLengthSquared = std::max(maxLengthSquared, lengthSquared);
        check.maxTiltError = std::max(check.maxTiltError, std::abs(v.x() - axial));
    }
    check.maxCentreErrorMm = std::sqrt(maxCentreSquared);
    // std::max skips NaN lengths, as the per-sample maximum did; none left means 0.
    if (minLengthSquared <= maxLengthSquared) {
        check.maxUnitError = std::max(std::abs(std::sqrt(minLengthSquared) - 1.0),
                                      std::abs(std::sqrt(maxLengthSquared) - 1.0));
    }
    return check;
}

} // namespace

std::size_t countReversals(std::span<const double> angles, double step) {
    std::vector<ReversalRun> runs(rangeCount(angles.size()));
    forEachRangeOf(angles.size(), runs.size(),
                   [&](std::size_t range, std::size_t begin, std::size_t end) {
                       runs[range] = reversalsIn(angles, step, begin, end);
                   });
    std::size_t reversals = 0;
    int lastSign = 0;
    for (const ReversalRun& run : runs) {
        reversals += run.reversals;
        reversals += lastSign != 0 && run.firstSign != 0 && run.firstSign != lastSign ? 1 : 0;
        lastSign = run.lastSign != 0 ? run.lastSign : lastSign;
    }
    return reversals;
}

namespace {

template <class CentreAt>
ReconstructionCheck checkWith(const CentreAt& centreAt, std::size_t count,
                              const ReconstructedPath& path, std::span<const double> thetaAbs,
                              double tiltB0, double toolRadius) {
    const double axial = std::sin(tiltB0);
    const std::size_t n = std::min(path.axes.size(), count);
    // Maxima per range, then over the ranges: a maximum does not depend on the order.
    std::vector<ReconstructionCheck> ranges(rangeCount(n));
    forEachRangeOf(n, ranges.size(), [&](std::size_t range, std::size_t begin, std::size_t end) {
        ranges[range] = checkRange(centreAt, path, axial, toolRadius, begin, end);
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

} // namespace

ReconstructionCheck checkReconstruction(std::span<const Vec3> centres,
                                        const ReconstructedPath& path,
                                        std::span<const double> thetaAbs, double tiltB0,
                                        double toolRadius) {
    return checkWith([centres](std::size_t i) -> const Vec3& { return centres[i]; }, centres.size(),
                     path, thetaAbs, tiltB0, toolRadius);
}

ReconstructionCheck checkReconstruction(const ScheduleSamples& samples,
                                        const ReconstructedPath& path,
                                        std::span<const double> thetaAbs, double tiltB0) {
    if (const auto array = samples.contiguousCentres()) {
        return checkReconstruction(*array, path, thetaAbs, tiltB0, samples.toolRadius);
    }
    const SampleCentres centres(samples);
    return checkWith([centres](std::size_t i) { return centres[i]; }, centres.size(), path,
                     thetaAbs, tiltB0, samples.toolRadius);
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
