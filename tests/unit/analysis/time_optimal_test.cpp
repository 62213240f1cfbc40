// T2 (spec §8.3) against the analytic cases of §10.1 and the invariants of a time-optimal
// parameterisation: every limit respected along the result, never slower than needed.

#include "core/analysis/axis_profile.h"
#include "core/analysis/constant_feed.h"
#include "core/analysis/time_optimal.h"
#include "tests/unit/analysis/test_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace bladeaxis::analysis {
namespace {

// These paths are analytic: the spline through their points is exact, where the default
// controller filter would round their corners by its 8 ms.
const AxisProfileOptions kExactSpline{.method = DerivativeMethod::Spline};

using kinematics::AxisId;

kinematics::MachineModel linearMachine(double velocity, double acceleration) {
    kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    for (auto& limits : machine.limits) {
        limits.velocity = 0.0; // unlimited
        limits.acceleration = 0.0;
        limits.jerk = 0.0;
    }
    machine.limit(AxisId::X).velocity = velocity;
    machine.limit(AxisId::X).acceleration = acceleration;
    return machine;
}

// X moves `length` mm along a straight line sampled `samples` times at feed F.
AxisProfile straightLine(double length, std::size_t samples, double feed) {
    testing::Program program;
    for (std::size_t i = 0; i < samples; ++i) {
        const double x = length * static_cast<double>(i) / static_cast<double>(samples - 1);
        program.add(Vec3(x, 0.0, 0.0), 0.0, feed);
    }
    return *analyseAxisMotion(program.axes, program.records, kExactSpline);
}

TEST(TimeOptimal, TrapezoidOnOneAxisMatchesTheClosedForm) {
    const double length = 100.0, v = 50.0, a = 100.0;
    const auto result = timeOptimalTime(straightLine(length, 4001, 1e4), linearMachine(v, a));
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    EXPECT_NEAR(result->time, length / v + v / a, 0.01 * (length / v + v / a));
    EXPECT_NEAR(result->peakPathSpeed, v, 1e-6 * v);
}

TEST(TimeOptimal, TriangleWhenTheAxisCannotReachItsVelocity) {
    const double length = 10.0, v = 50.0, a = 100.0; // v^2 / a = 25 mm > length
    const auto result = timeOptimalTime(straightLine(length, 4001, 1e4), linearMachine(v, a));
    ASSERT_TRUE(result.has_value());
    EXPECT_NEAR(result->time, 2.0 * std::sqrt(length / a), 0.01 * 2.0 * std::sqrt(length / a));
}

TEST(TimeOptimal, FeedBoundsThePathSpeed) {
    const double length = 200.0, feed = 10.0, a = 1e6;
    const auto result = timeOptimalTime(straightLine(length, 2001, feed), linearMachine(1e3, a));
    ASSERT_TRUE(result.has_value());
    EXPECT_NEAR(result->time, length / feed, 1e-3 * length / feed);
    EXPECT_LE(result->peakPathSpeed, feed * (1.0 + 1e-12));
}

// A circle in Y-Z with A turning: every axis moves, the limits bind in turn.
AxisProfile helixLikeProfile() {
    testing::Program program;
    for (int i = 0; i <= 720; ++i) {
        const double t = 0.01 * i;
        program.add(Vec3(0.2 * t, 20.0 * std::cos(t), 20.0 * std::sin(t)),
                    0.5 * t + 0.2 * std::sin(3.0 * t), 50.0);
    }
    return *analyseAxisMotion(program.axes, program.records, kExactSpline);
}

kinematics::MachineModel bladeMachine() {
    return kinematics::defaultBladeMachine();
}

TEST(TimeOptimal, EveryAxisStaysWithinItsLimits) {
    const AxisProfile profile = helixLikeProfile();
    const auto machine = bladeMachine();
    const auto result = timeOptimalTime(profile, machine);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    const auto& s = profile.pathParameter;
    for (std::size_t j = 0; j < kinematics::kAllAxes.size(); ++j) {
        const auto& limits = machine.limit(kinematics::kAllAxes[j]);
        const AxisSeries& series = profile.axes[j];
        for (std::size_t i = 0; i + 1 < s.size(); ++i) {
            const double q1 = series.velocityAt(i) / profile.feed;
            const double q2 = series.accelerationAt(i) / (profile.feed * profile.feed);
            const double v = result->pathSpeed[i];
            const double u =
                (std::pow(result->pathSpeed[i + 1], 2) - v * v) / (2.0 * (s[i + 1] - s[i]));
            ASSERT_LE(std::abs(q1 * v), limits.velocity * (1.0 + 1e-9)) << j << " " << i;
            ASSERT_LE(std::abs(q1 * u + q2 * v * v), limits.acceleration * (1.0 + 1e-6) + 1e-9)
                << j << " " << i;
        }
    }
}

TEST(TimeOptimal, IsNoSlowerThanConstantFeedBeyondTheStartAndStopRamps) {
    const AxisProfile profile = helixLikeProfile();
    const auto machine = bladeMachine();
    const auto result = timeOptimalTime(profile, machine);
    ASSERT_TRUE(result.has_value());
    const ConstantFeedTime t1 = constantFeedTime(profile, machine, false);
    EXPECT_DOUBLE_EQ(result->constantFeedTime, t1.time);
    // Constant feed F* is feasible everywhere but at the ends, where T2 starts and stops at
    // rest: it may lose at most a ramp to F* at each end, at the path acceleration the limits
    // leave at F* (a_j - |q_j''| F*^2) / |q_j'|, taken at its smallest along the path.
    const double feed = t1.achievableFeed;
    double pathAcceleration = 1e300;
    for (std::size_t j = 0; j < kinematics::kAllAxes.size(); ++j) {
        const double a = machine.limit(kinematics::kAllAxes[j]).acceleration;
        for (std::size_t i = 0; i < profile.pathParameter.size(); ++i) {
            const double q1 = std::abs(profile.axes[j].velocityAt(i)) / profile.feed;
            const double q2 =
                std::abs(profile.axes[j].accelerationAt(i)) / std::pow(profile.feed, 2);
            if (q1 > 1e-9) {
                pathAcceleration = std::min(pathAcceleration, (a - q2 * feed * feed) / q1);
            }
        }
    }
    ASSERT_GT(pathAcceleration, 0.0);
    EXPECT_LE(result->time, t1.time + 2.0 * feed / pathAcceleration);
    EXPECT_GT(result->time, t1.time * 0.5); // the same limits: no free lunch
}

TEST(TimeOptimal, HigherAccelerationLimitsNeverMakeItSlower) {
    const AxisProfile profile = helixLikeProfile();
    auto machine = bladeMachine();
    const double before = timeOptimalTime(profile, machine)->time;
    for (auto& limits : machine.limits) {
        limits.acceleration *= 2.0;
    }
    EXPECT_LE(timeOptimalTime(profile, machine)->time, before * (1.0 + 1e-12));
}

TEST(TimeOptimal, JerkHeuristicOnlyEverSlowsDownAndIdlesWithoutJerkLimits) {
    const AxisProfile profile = helixLikeProfile();
    auto machine = bladeMachine();
    const auto plain = timeOptimalTime(profile, machine);
    const auto limited = timeOptimalTime(profile, machine, {.jerkHeuristic = true});
    ASSERT_TRUE(plain && limited);
    EXPECT_GE(limited->time, plain->time * (1.0 - 1e-12));
    EXPECT_GT(limited->jerkRounds, 0) << "the blade machine's jerk limits bind on this path";
    for (auto& limits : machine.limits) {
        limits.jerk = 0.0; // unlimited
    }
    const auto unlimited = timeOptimalTime(profile, machine, {.jerkHeuristic = true});
    ASSERT_TRUE(unlimited.has_value());
    EXPECT_EQ(unlimited->jerkRounds, 0);
    EXPECT_TRUE(unlimited->jerkWithinLimits);
    EXPECT_DOUBLE_EQ(unlimited->time, timeOptimalTime(profile, machine)->time);
}

// Issue 4: a constant path acceleration per interval cannot cross an interval that starts and
// ends at rest; T2 used to fail there (the original of some family blades reaches rest at the
// last but one sample). Accelerating over half of it and braking over the other half takes
// 2 sqrt(L / a) on one axis, the §10.1 triangle.
TEST(TimeOptimal, AnIntervalFromRestToRestIsTheTriangleProfile) {
    const double length = 0.5, a = 100.0;
    const auto result = timeOptimalTime(straightLine(length, 2, 1e4), linearMachine(1e3, a));
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    EXPECT_NEAR(result->time, 2.0 * std::sqrt(length / a), 1e-9);
}

TEST(TimeOptimal, TooShortOrFeedlessProfilesAreErrors) {
    AxisProfile profile;
    profile.pathParameter = {0.0};
    profile.feed = 10.0;
    EXPECT_FALSE(timeOptimalTime(profile, bladeMachine()).has_value());
    AxisProfile line = straightLine(10.0, 11, 10.0);
    line.feed = 0.0;
    EXPECT_FALSE(timeOptimalTime(line, bladeMachine()).has_value());
}

TEST(TimeOptimal, SecondsAreTheTimeOfTheSolutionAndNoneWhereItFails) {
    const AxisProfile line = straightLine(0.5, 2, 1e4);
    const kinematics::MachineModel machine = linearMachine(1e3, 100.0);
    const std::optional<double> seconds = timeOptimalSeconds(line, machine);
    ASSERT_TRUE(seconds.has_value());
    EXPECT_EQ(*seconds, timeOptimalTime(line, machine)->time);
    AxisProfile feedless = line;
    feedless.feed = 0.0;
    EXPECT_FALSE(timeOptimalSeconds(feedless, machine).has_value());
}

// Each pass looks at the token at its first sample and every 65,536 after: a set token ends
// even a short T2 with Cancelled, and its seconds are none.
TEST(TimeOptimal, ACancelledTokenEndsItWithCancelledInsteadOfATime) {
    const AxisProfile line = straightLine(10.0, 11, 10.0);
    const kinematics::MachineModel machine = linearMachine(1e3, 100.0);
    CancelToken cancel;
    ASSERT_TRUE(timeOptimalTime(line, machine, {.cancel = &cancel}).has_value());
    cancel.requestCancel();
    const auto stopped = timeOptimalTime(line, machine, {.cancel = &cancel});
    ASSERT_FALSE(stopped.has_value());
    EXPECT_EQ(stopped.error().code, ErrorCode::Cancelled);
    EXPECT_FALSE(timeOptimalSeconds(line, machine, &cancel).has_value());
}

TEST(TimeOptimal, NonFiniteProfileValuesAreErrors) {
    AxisProfile derivative = straightLine(10.0, 11, 10.0);
    derivative.axes[0].velocity[5] = std::nan("");
    EXPECT_FALSE(timeOptimalTime(derivative, bladeMachine()).has_value());
    AxisProfile parameter = straightLine(10.0, 11, 10.0);
    parameter.pathParameter[3] = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(timeOptimalTime(parameter, bladeMachine()).has_value());
}

// A with a sharp reversal every 40 samples (a reciprocating CAM orientation): the acceleration
// spike at each reversal is one block wide.
AxisProfile reciprocatingProfile() {
    testing::Program program;
    for (int i = 0; i <= 400; ++i) {
        const double t = 0.01 * i;
        const double phase = std::fmod(static_cast<double>(i), 80.0);
        const double triangle = phase < 40.0 ? phase : 80.0 - phase;
        program.add(Vec3(0.2 * t, 20.0 * std::cos(t), 20.0 * std::sin(t)),
                    0.5 * t + 0.004 * triangle, 50.0);
    }
    return *analyseAxisMotion(program.axes, program.records, {});
}

// An independent reference written here: the classic forward-backward integration in the
// phase plane (x = sdot^2) on a very fine grid, each step's acceleration bounds taken at its
// known end, the maximum velocity curve by bisection. Within an interval of the profile the
// default spline's q'' is linear and q' its integral.
struct FineGridReference {
    const AxisProfile& profile;
    const kinematics::MachineModel& machine;

    struct Point {
        std::array<double, 5> first{}, second{};
    };

    Point at(std::size_t sample, double fraction) const {
        Point p;
        const double h = profile.pathParameter[sample + 1] - profile.pathParameter[sample];
        const double f2 = profile.feed * profile.feed;
        for (std::size_t j = 0; j < 5; ++j) {
            const AxisSeries& axis = profile.axes[j];
            const double q1a = axis.velocityAt(sample) / profile.feed;
            const double q2a = axis.accelerationAt(sample) / f2;
            const double q2b = axis.accelerationAt(sample + 1) / f2;
            p.second[j] = q2a + (q2b - q2a) * fraction;
            p.first[j] = q1a + h * (q2a * fraction + (q2b - q2a) * fraction * fraction / 2.0);
        }
        return p;
    }

    // The bounds on u = sddot at state x: [lower, upper] (lower > upper: infeasible).
    std::pair<double, double> controlBounds(const Point& p, double x) const {
        double lower = -1e300, upper = 1e300;
        for (std::size_t j = 0; j < 5; ++j) {
            const double a = machine.limits[j].acceleration;
            if (!(a > 0.0) || std::abs(p.first[j]) < 1e-12) {
                if (a > 0.0 && std::abs(p.second[j] * x) > a) {
                    return {1.0, -1.0};
                }
                continue;
            }
            const double b1 = (-a - p.second[j] * x) / p.first[j];
            const double b2 = (a - p.second[j] * x) / p.first[j];
            lower = std::max(lower, std::min(b1, b2));
            upper = std::min(upper, std::max(b1, b2));
        }
        return {lower, upper};
    }

    double maximumState(const Point& p) const {
        double high = profile.feed * profile.feed;
        for (std::size_t j = 0; j < 5; ++j) {
            const double v = machine.limits[j].velocity;
            if (v > 0.0 && std::abs(p.first[j]) > 1e-12) {
                high = std::min(high, std::pow(v / p.first[j], 2));
            }
        }
        double low = 0.0;
        if (controlBounds(p, high).first <= controlBounds(p, high).second) {
            return high;
        }
        for (int k = 0; k < 60; ++k) {
            const double mid = 0.5 * (low + high);
            const auto [lower, upper] = controlBounds(p, mid);
            (lower <= upper ? low : high) = mid;
        }
        return low;
    }

    double time(std::size_t subdivisions) const {
        std::vector<Point> points;
        std::vector<double> steps;
        const std::size_t n = profile.pathParameter.size();
        for (std::size_t i = 0; i + 1 < n; ++i) {
            const double h = profile.pathParameter[i + 1] - profile.pathParameter[i];
            for (std::size_t k = 0; k < subdivisions; ++k) {
                points.push_back(at(i, static_cast<double>(k) / static_cast<double>(subdivisions)));
                steps.push_back(h / static_cast<double>(subdivisions));
            }
        }
        points.push_back(at(n - 2, 1.0));
        std::vector<double> x(points.size());
        for (std::size_t g = 0; g < points.size(); ++g) {
            x[g] = maximumState(points[g]);
        }
        x.front() = 0.0;
        x.back() = 0.0;
        for (std::size_t g = 0; g + 1 < points.size(); ++g) {
            const double u = controlBounds(points[g], x[g]).second;
            x[g + 1] = std::min(x[g + 1], std::max(0.0, x[g] + 2.0 * steps[g] * u));
        }
        for (std::size_t g = points.size() - 1; g > 0; --g) {
            const double u = controlBounds(points[g], x[g]).first;
            x[g - 1] = std::min(x[g - 1], std::max(0.0, x[g] - 2.0 * steps[g - 1] * u));
        }
        double total = 0.0;
        for (std::size_t g = 0; g + 1 < points.size(); ++g) {
            total += 2.0 * steps[g] / (std::sqrt(x[g]) + std::sqrt(x[g + 1]));
        }
        return total;
    }
};

TEST(ConvergedTimeOptimal, RefinesTheGridUntilTheTimeHolds) {
    const AxisProfile profile = reciprocatingProfile();
    const auto machine = kinematics::defaultBladeMachine();
    const auto converged = convergedTimeOptimal(profile, machine);
    ASSERT_TRUE(converged.has_value()) << converged.error().toString();
    EXPECT_TRUE(converged->converged);
    EXPECT_LT(converged->lastChange, 0.005);
    EXPECT_GE(converged->subdivisions, 2U);
    // One grid point per block misjudges the spike at each reversal: on this path the time it
    // gives differs from the converged one by more than the tolerance.
    const double coarse = timeOptimalTime(profile, machine)->time;
    EXPECT_GT(std::abs(coarse - converged->time), 0.005 * converged->time);
}

TEST(ConvergedTimeOptimal, AgreesWithAnIndependentFineGridSolution) {
    const AxisProfile profile = reciprocatingProfile();
    const auto machine = kinematics::defaultBladeMachine();
    const auto converged = convergedTimeOptimal(profile, machine);
    ASSERT_TRUE(converged.has_value());
    const double reference = FineGridReference{profile, machine}.time(256);
    EXPECT_NEAR(converged->time, reference, 0.01 * reference);
}

TEST(ConvergedTimeOptimal, ASmoothPathConvergesOnTheFirstRefinement) {
    const AxisProfile profile = helixLikeProfile();
    const auto machine = kinematics::defaultBladeMachine();
    const auto converged = convergedTimeOptimal(profile, machine);
    ASSERT_TRUE(converged.has_value());
    EXPECT_TRUE(converged->converged);
    EXPECT_NEAR(converged->time, timeOptimalTime(profile, machine)->time, 0.01 * converged->time);
    EXPECT_EQ(timeOptimalSeconds(profile, machine), converged->time);
}

} // namespace
} // namespace bladeaxis::analysis
