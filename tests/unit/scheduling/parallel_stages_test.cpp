// The per-point stages split large inputs into ranges on several threads (core/base/parallel.h);
// each must give the serial result to the last bit, wherever the ranges fall.
#include "core/base/parallel.h"
#include "core/geometry/angles.h"
#include "core/scheduling/channel.h"
#include "core/scheduling/curvature_states.h"
#include "core/scheduling/detail/fast_angles.h"
#include "core/scheduling/plane_path.h"
#include "core/scheduling/reconstruction.h"
#include "core/scheduling/tangents.h"
#include "tests/unit/scheduling/synthetic_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

namespace bladeaxis::scheduling {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr unsigned kThreadCounts[] = {2, 3, 4};

ScheduleInput longHelix() {
    testing::HelixOptions options;
    options.revolutions = 140.0;
    return testing::helicalPath(testing::appendixBCurve(), options);
}

// The first input of range r when `count` inputs are split into `ranges` (parallel.h).
std::size_t rangeStart(std::size_t count, std::size_t ranges, std::size_t r) {
    return count * r / ranges;
}

TEST(ParallelStages, ReversalCountDoesNotDependOnTheThreadCount) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> step(-1.0, 1.0);
    const std::size_t count = 6 * kMinParallelRange + 17;
    std::vector<double> angles(count, 0.0);
    for (std::size_t i = 1; i < count; ++i) {
        angles[i] = angles[i - 1] + step(random);
    }
    // A whole range of steps below the threshold: the direction before it carries over.
    for (std::size_t i = 2 * kMinParallelRange; i < 4 * kMinParallelRange; ++i) {
        angles[i] = angles[i - 1] + 1e-9;
    }
    const std::size_t serial = countReversals(angles, 1e-6);
    EXPECT_GT(serial, 0u);
    for (unsigned threads : kThreadCounts) {
        const ThreadCountScope scope(threads);
        EXPECT_EQ(countReversals(angles, 1e-6), serial) << threads;
    }
    std::vector<double> oneTurn(count);
    const double top = static_cast<double>(count / 3);
    for (std::size_t i = 0; i < count; ++i) {
        const double x = static_cast<double>(i);
        oneTurn[i] = x < top ? x : 2.0 * top - x; // up, then down
    }
    for (unsigned threads : {1u, 2u, 3u, 4u}) {
        const ThreadCountScope scope(threads);
        EXPECT_EQ(countReversals(oneTurn, 0.5), 1u) << threads;
    }
}

// The check's maxima are those of the per-sample errors, to the bit, on any thread count: axes
// a little too long and too short, the rounding of tips made from centres far from the origin,
// a NaN axis (skipped, as std::max does).
TEST(ParallelStages, ReconstructionCheckGivesThePerSampleMaxima) {
    const std::size_t n = 3 * kMinParallelRange + 5;
    std::mt19937 random(23);
    std::uniform_real_distribution<double> noise(-1e-12, 1e-12);
    std::vector<Vec3> centres(n);
    ReconstructedPath path;
    for (std::size_t i = 0; i < n; ++i) {
        const double angle = 1e-3 * static_cast<double>(i);
        centres[i] = Vec3(700.0 + 0.1 * angle, 90.0 * std::sin(angle), 90.0 * std::cos(angle));
        const Vec3 axis(0.1 + noise(random), std::sin(angle) * (1.0 + 1e3 * noise(random)),
                        std::cos(angle));
        path.axes.push_back(axis);
    }
    path.axes[n / 2] = Vec3(std::nan(""), 0.0, 1.0);
    const std::vector<double> theta(n, 0.0);
    ReconstructionCheck expected;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3& v = path.axes[i];
        expected.maxCentreErrorMm =
            std::max(expected.maxCentreErrorMm,
                     (tipOfBall(centres[i], v, 8.0) + 8.0 * v - centres[i]).norm());
        expected.maxUnitError = std::max(expected.maxUnitError, std::abs(v.norm() - 1.0));
    }
    ASSERT_GT(expected.maxCentreErrorMm, 0.0); // the rounding is there to be found
    for (unsigned threads : {1u, 2u, 3u, 4u}) {
        const ThreadCountScope scope(threads);
        const ReconstructionCheck check = checkReconstruction(centres, path, theta, 0.1, 8.0);
        EXPECT_EQ(check.maxCentreErrorMm, expected.maxCentreErrorMm) << threads;
        EXPECT_EQ(check.maxUnitError, expected.maxUnitError) << threads;
    }
    path.axes.assign(2, Vec3(std::nan(""), 0.0, 0.0)); // no length at all: no unit error
    EXPECT_EQ(checkReconstruction(centres, path, theta, 0.1, 8.0).maxUnitError, 0.0);
}

void expectSamePlanePath(const PlanePath& a, const PlanePath& b) {
    EXPECT_EQ(a.points, b.points);
    EXPECT_EQ(a.arcLength, b.arcLength);
    EXPECT_EQ(a.originalAngle, b.originalAngle);
    EXPECT_EQ(a.firstInput, b.firstInput);
    EXPECT_EQ(a.tiltB0, b.tiltB0);
    EXPECT_EQ(a.traversalSign, b.traversalSign);
    EXPECT_EQ(a.warnings, b.warnings);
}

// A merge depends on the last kept centre, which may lie in an earlier range: duplicates at and
// across the first inputs of ranges, including a range that holds nothing but duplicates.
TEST(ParallelStages, MergedDuplicatesAcrossRangeBoundariesGiveTheSerialPath) {
    ScheduleInput input = longHelix();
    const std::size_t n = input.centres.size();
    ASSERT_GT(n, 4 * kMinParallelRange);
    const auto duplicate = [&input](std::size_t i, std::size_t of) {
        input.centres[i] = input.centres[of];
        input.axes[i] = input.axes[of];
    };
    for (std::size_t ranges : {2u, 3u, 4u}) {
        for (std::size_t r = 1; r < ranges; ++r) {
            const std::size_t start = rangeStart(n, ranges, r);
            duplicate(start, start - 1);     // the first input of a range is merged
            duplicate(start - 1, start - 2); // and so is the one before it: a chain
        }
    }
    // Range 1 of 4 entirely duplicates of the input before it.
    const std::size_t begin = rangeStart(n, 4, 1);
    const std::size_t end = rangeStart(n, 4, 2);
    for (std::size_t i = begin; i <= end; ++i) {
        duplicate(i, begin - 3);
    }
    auto serial = preparePlanePath(input.centres, input.axes);
    ASSERT_TRUE(serial.has_value()) << serial.error().toString();
    EXPECT_LT(serial->firstInput.size(), n - (end - begin));
    addOriginalAngles(*serial, input.axes);
    EXPECT_EQ(serial->originalAngle.size(), serial->firstInput.size());
    for (unsigned threads : kThreadCounts) {
        const ThreadCountScope scope(threads);
        auto parallel = preparePlanePath(input.centres, input.axes);
        ASSERT_TRUE(parallel.has_value());
        addOriginalAngles(*parallel, input.axes);
        expectSamePlanePath(*serial, *parallel);
        // Read in place from records that hold them among other members: the same path.
        struct Record {
            Vec3 centre;
            int line = 0;
            Vec3 axis;
        };
        std::vector<Record> records(n);
        for (std::size_t i = 0; i < n; ++i) {
            records[i] = {input.centres[i], static_cast<int>(i), input.axes[i]};
        }
        const std::span<const Record> view(records);
        const ScheduleSamples samples{.points = Vec3Run(view, &Record::centre),
                                      .axes = Vec3Run(view, &Record::axis),
                                      .toolRadius = input.toolRadius,
                                      .pointsAreTips = false};
        auto read = preparePlanePath(samples);
        ASSERT_TRUE(read.has_value());
        addOriginalAngles(*read, samples.axes);
        expectSamePlanePath(*serial, *read);
    }
}

// The tilt of every axis drifts a little: the median tilt (chunks of axial values on any
// thread, then the order statistic) and the warning are the serial ones, and the median is the
// middle axial value of all of them.
TEST(ParallelStages, AVaryingTiltGivesTheSerialMedianOnAnyThreadCount) {
    ScheduleInput input = longHelix();
    const std::size_t n = input.axes.size();
    ASSERT_GT(n, 4 * kMinParallelRange);
    std::vector<double> axial(n);
    for (std::size_t i = 0; i < n; ++i) {
        Vec3& axis = input.axes[i];
        axis.x() += 1e-3 * std::sin(0.37 * static_cast<double>(i));
        axial[i] = std::clamp(axis.x() / axis.norm(), -1.0, 1.0);
    }
    std::nth_element(axial.begin(), axial.begin() + static_cast<long>(n / 2), axial.end());
    auto serial = preparePlanePath(input.centres, input.axes);
    ASSERT_TRUE(serial.has_value()) << serial.error().toString();
    ASSERT_EQ(serial->firstInput.size(), n); // no duplicates: every axis counts
    EXPECT_EQ(serial->tiltB0, std::asin(axial[n / 2]));
    ASSERT_FALSE(serial->warnings.empty());
    EXPECT_NE(serial->warnings.front().find("input tilt B is not constant"), std::string::npos);
    for (unsigned threads : kThreadCounts) {
        const ThreadCountScope scope(threads);
        auto parallel = preparePlanePath(input.centres, input.axes);
        ASSERT_TRUE(parallel.has_value());
        expectSamePlanePath(*serial, *parallel);
    }
}

TEST(ParallelStages, TangentsAndCurvatureDoNotDependOnTheThreadCount) {
    const ScheduleInput input = longHelix();
    const auto path = preparePlanePath(input.centres, input.axes);
    ASSERT_TRUE(path.has_value());
    const auto serial = computeTangents(path->points, 0.5, 3.0);
    ASSERT_TRUE(serial.has_value());
    CurvatureSettings settings;
    settings.windowMm = 7.0;
    const CurvatureAnalysis serialStates =
        analyseCurvature(path->arcLength, serial->curvature, serial->turning, settings);
    EXPECT_FALSE(serialStates.runs.empty());
    for (unsigned threads : kThreadCounts) {
        const ThreadCountScope scope(threads);
        const auto parallel = computeTangents(path->points, 0.5, 3.0);
        ASSERT_TRUE(parallel.has_value());
        EXPECT_EQ(parallel->chordLengthMm, serial->chordLengthMm);
        EXPECT_EQ(parallel->forwardAngle, serial->forwardAngle);
        EXPECT_EQ(parallel->turning, serial->turning);
        EXPECT_EQ(parallel->curvature, serial->curvature);
        const CurvatureAnalysis states =
            analyseCurvature(path->arcLength, serial->curvature, serial->turning, settings);
        EXPECT_EQ(states.smoothedCurvature, serialStates.smoothedCurvature);
        EXPECT_EQ(states.hysteresis, serialStates.hysteresis);
        EXPECT_EQ(states.state, serialStates.state);
        ASSERT_EQ(states.runs.size(), serialStates.runs.size());
        for (std::size_t k = 0; k < states.runs.size(); ++k) {
            EXPECT_EQ(states.runs[k].entry, serialStates.runs[k].entry);
            EXPECT_EQ(states.runs[k].exit, serialStates.runs[k].exit);
        }
    }
}

// A window wider than a whole range: the window of a range's first sample starts in an earlier
// range and ends in a later one.
TEST(ParallelStages, CurvatureWindowsWiderThanARangeGiveTheSerialResult) {
    const std::size_t n = 4 * kMinParallelRange;
    std::vector<double> s(n), kappa(n), turning(n);
    for (std::size_t i = 0; i < n; ++i) {
        s[i] = 0.01 * double(i) + 1e-3 * std::sin(double(i)); // uneven spacing
        kappa[i] = std::sin(1e-3 * double(i));
        turning[i] = kappa[i] * 0.01;
    }
    CurvatureSettings settings;
    settings.windowMm = 0.03 * double(kMinParallelRange);
    const CurvatureAnalysis serial = analyseCurvature(s, kappa, turning, settings);
    for (unsigned threads : kThreadCounts) {
        const ThreadCountScope scope(threads);
        EXPECT_EQ(analyseCurvature(s, kappa, turning, settings).smoothedCurvature,
                  serial.smoothedCurvature)
            << threads;
    }
}

// The hysteresis and run finding of spec §1.6 as one loop each, in feed order: the oracle for
// the ranges decided at once.
std::vector<CurvatureState> serialHysteresis(std::span<const double> smoothed, double threshold) {
    std::vector<CurvatureState> states(smoothed.size(), CurvatureState::Convex);
    std::optional<CurvatureState> current;
    for (std::size_t i = 0; i < smoothed.size(); ++i) {
        if (std::abs(smoothed[i]) > threshold) {
            const CurvatureState decided =
                smoothed[i] > 0.0 ? CurvatureState::Convex : CurvatureState::Concave;
            if (!current) { // back-fill the undecided start with the first decided state
                std::fill(states.begin(), states.begin() + static_cast<long>(i), decided);
            }
            current = decided;
        }
        states[i] = current.value_or(CurvatureState::Convex);
    }
    return states;
}

std::vector<std::pair<std::size_t, std::size_t>>
serialRuns(std::span<const CurvatureState> states) {
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    for (std::size_t i = 0; i < states.size(); ++i) {
        const bool concave = states[i] == CurvatureState::Concave;
        const bool wasConcave = i > 0 && states[i - 1] == CurvatureState::Concave;
        if (concave && !wasConcave) {
            runs.emplace_back(i, states.size());
        } else if (!concave && wasConcave) {
            runs.back().second = i;
        }
    }
    return runs;
}

// Undecided samples across the first range boundaries, a whole range without a decisive
// sample, runs across boundaries and one reaching the path's end.
TEST(ParallelStages, HysteresisAndRunsAreTheSerialOnesWhereverTheRangesFall) {
    const std::size_t n = 4 * kMinParallelRange + 7;
    std::vector<double> s(n), kappa(n, 0.0), turning(n);
    const auto set = [&kappa](std::size_t from, std::size_t to, double value) {
        std::fill(kappa.begin() + static_cast<long>(from), kappa.begin() + static_cast<long>(to),
                  value);
    };
    set(20000, 20100, -1.0); // the first decisive samples: concave
    set(21000, 21010, 1.0);
    set(49100, 49200, -1.0); // across the boundary of the third of four ranges
    set(52000, 52010, 1.0);
    set(60000, 60005, -1.0); // concave to the end
    for (std::size_t i = 0; i < n; ++i) {
        s[i] = 0.01 * static_cast<double>(i);
        turning[i] = 1e-3 * kappa[i] + 1e-6 * static_cast<double>(i % 7);
    }
    CurvatureSettings settings;
    settings.windowMm = 0.001; // each sample its own window
    settings.mergeGapMm = 0.0;
    settings.minRunMm = 0.0;
    const CurvatureAnalysis serial = analyseCurvature(s, kappa, turning, settings);
    const std::vector<CurvatureState> expected =
        serialHysteresis(serial.smoothedCurvature, settings.hysteresisPerMm);
    const auto expectedRuns = serialRuns(expected);
    ASSERT_EQ(expectedRuns.size(), 3u);
    EXPECT_EQ(expectedRuns.back().second, n);
    for (unsigned threads : {1u, 2u, 3u, 4u}) {
        const ThreadCountScope scope(threads);
        const CurvatureAnalysis states = analyseCurvature(s, kappa, turning, settings);
        EXPECT_TRUE(std::equal(states.hysteresis.begin(), states.hysteresis.end(), expected.begin(),
                               expected.end()))
            << threads;
        ASSERT_EQ(states.runs.size(), expectedRuns.size()) << threads;
        for (std::size_t k = 0; k < expectedRuns.size(); ++k) {
            const auto [entry, exit] = expectedRuns[k];
            EXPECT_EQ(states.runs[k].entry, entry);
            EXPECT_EQ(states.runs[k].exit, exit);
            double sum = 0.0;
            for (std::size_t i = entry; i < exit; ++i) {
                sum += std::abs(turning[i]);
            }
            EXPECT_EQ(states.runs[k].absTurningRad, sum);
        }
    }
}

std::vector<double> randomWalk(std::mt19937& random, std::size_t n) {
    std::normal_distribution<double> step(0.0, 0.1);
    std::vector<double> values(n);
    double value = 0.0;
    for (double& v : values) {
        value += step(random);
        v = value;
    }
    return values;
}

TEST(MonotoneBounds, AreTheHullsBoundsAndFlags) {
    std::mt19937 random(17);
    for (int trial = 0; trial < 200; ++trial) {
        const std::vector<double> low = randomWalk(random, 1 + trial % 150);
        std::vector<double> high = randomWalk(random, low.size());
        for (std::size_t i = 0; i < high.size(); ++i) {
            high[i] += low[i] + (trial % 3 == 0 ? 0.1 : 1.5); // narrow ones pinch
        }
        const double margin = trial % 4 == 0 ? 0.0 : 0.05;
        const MonotoneHull hull = monotoneHull(low, high, margin);
        const MonotoneHull bounds = monotoneBounds(low, high, margin);
        EXPECT_EQ(bounds.lo, hull.lo) << trial;
        EXPECT_EQ(bounds.hi, hull.hi) << trial;
        EXPECT_EQ(bounds.pinched, hull.pinched) << trial;
        EXPECT_EQ(bounds.infeasible, hull.infeasible) << trial;
        EXPECT_EQ(bounds.minWidth, hull.minWidth) << trial;
        EXPECT_TRUE(bounds.lo0.empty() && bounds.marginHi.empty());
    }
    EXPECT_TRUE(monotoneBounds({}, {}, 0.1).lo.empty());
}

// Near every multiple of pi, with right and wrong guesses of the turn count.
TEST(FastAngles, WrapWithAGuessedTurnCountIsTheWrap) {
    const double ulp = std::numeric_limits<double>::epsilon();
    for (int k = -40; k <= 40; ++k) {
        for (double offset :
             {-1e-6, -1e-9, -1e-12, -4 * ulp, 0.0, 4 * ulp, 1e-12, 1e-9, 1e-6, 0.3, 1.0, 2.5}) {
            const double angle = k * kPi + offset * (1.0 + std::abs(k));
            for (double guess : {0.0, std::round(k / 2.0), std::round(k / 2.0) + 1.0, -3.0}) {
                double turns = guess;
                const double wrapped = detail::wrapAngleGuessed(angle, turns);
                EXPECT_EQ(wrapped, detail::wrapAngle(angle)) << angle << " " << guess;
                EXPECT_EQ(wrapped, geometry::wrapAngle(angle)) << angle << " " << guess;
            }
        }
    }
    double turns = 0.0;
    EXPECT_TRUE(std::isnan(detail::wrapAngleGuessed(std::nan(""), turns)));
    turns = 0.0;
    EXPECT_EQ(detail::wrapAngleGuessed(-0.0, turns), -0.0);
    EXPECT_TRUE(std::signbit(detail::wrapAngleGuessed(-0.0, turns)));
}

// Unwrapping a long rising angle keeps its guess from sample to sample: the same bits as
// unwrapNear.
TEST(FastAngles, UnwrapWithAGuessedTurnCountIsTheUnwrap) {
    double previousGuessed = 0.0;
    double previous = 0.0;
    double turns = 0.0;
    for (int i = 1; i < 200000; ++i) {
        const double wrapped = geometry::wrapAngle(1e-3 * i + 0.1 * std::sin(i));
        previousGuessed = detail::unwrapNearGuessed(wrapped, previousGuessed, turns);
        previous = detail::unwrapNear(wrapped, previous);
        ASSERT_EQ(previousGuessed, previous) << i;
    }
}

} // namespace
} // namespace bladeaxis::scheduling
