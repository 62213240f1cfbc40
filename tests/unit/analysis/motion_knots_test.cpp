// The derivative spline's knots: micrometre chords on a straight move are merged, real motion
// over a short chord (a rotation at an almost fixed point, a corner) is kept.

#include "core/analysis/derivatives.h"
#include "core/analysis/motion_knots.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace bladeaxis::analysis {
namespace {

struct Sampled {
    std::vector<double> s;
    std::vector<kinematics::MachineAxes> axes;
    std::vector<RecordIndex> records;
};

// A smooth 4-axis motion sampled every 0.4 mm, with a point 2 um after every `every`-th one
// on the straight move to the next (what a post writes when it splits a move).
Sampled smoothMotion(int every) {
    Sampled out;
    const auto at = [](double s) {
        return kinematics::MachineAxes{s, 10.0 * std::sin(0.05 * s), 3.0 * std::cos(0.03 * s),
                                       0.3 * std::sin(0.1 * s) + 0.02 * s, 0.08};
    };
    for (int i = 0; i < 200; ++i) {
        const double s = 0.4 * i;
        out.s.push_back(s);
        out.axes.push_back(at(s));
        if (every > 0 && i % every == 0 && i + 1 < 200) {
            const double t = 0.002 / 0.4;
            const auto from = at(s), to = at(s + 0.4);
            kinematics::MachineAxes micro;
            for (kinematics::AxisId axis : kinematics::kAllAxes) {
                micro[axis] = from[axis] + t * (to[axis] - from[axis]);
            }
            out.s.push_back(s + 0.002);
            out.axes.push_back(micro);
        }
    }
    for (std::size_t i = 0; i < out.s.size(); ++i) {
        out.records.push_back(static_cast<RecordIndex>(i));
    }
    return out;
}

std::vector<double> positions(const Sampled& sampled, kinematics::AxisId axis) {
    std::vector<double> q;
    for (const auto& axes : sampled.axes) {
        q.push_back(axes[axis]);
    }
    return q;
}

TEST(MotionKnots, EveryPointOfAnEvenlySampledMotionIsAKnot) {
    const Sampled clean = smoothMotion(0);
    EXPECT_EQ(motionKnots(clean.s, clean.axes, clean.records).size(), clean.s.size());
}

TEST(MotionKnots, MicrometreChordsOnAStraightMoveAreMerged) {
    const Sampled micro = smoothMotion(5);
    const auto knots = motionKnots(micro.s, micro.axes, micro.records);
    EXPECT_EQ(knots.size(), smoothMotion(0).s.size());
    EXPECT_EQ(knots.front(), 0u);
    EXPECT_EQ(knots.back(), micro.s.size() - 1);
}

TEST(MotionKnots, ARotationOverAShortChordIsKept) {
    Sampled sampled = smoothMotion(0);
    // 3 um further along, A has turned by 2 degrees: real motion the figures must show.
    kinematics::MachineAxes turned = sampled.axes[100];
    turned.a += 0.035;
    sampled.s.insert(sampled.s.begin() + 101, sampled.s[100] + 0.003);
    sampled.axes.insert(sampled.axes.begin() + 101, turned);
    sampled.records.push_back(static_cast<RecordIndex>(sampled.records.size()));
    EXPECT_EQ(motionKnots(sampled.s, sampled.axes, sampled.records).size(), sampled.s.size());
}

TEST(MotionKnots, MergedChordsLeaveTheSplineDerivativesOfTheCleanMotion) {
    const Sampled clean = smoothMotion(0);
    const Sampled micro = smoothMotion(3);
    const auto knots = motionKnots(micro.s, micro.axes, micro.records);
    for (kinematics::AxisId axis : kinematics::kAllAxes) {
        const auto reference =
            differentiateAxis(clean.s, positions(clean, axis), 50.0, DerivativeMethod::Spline);
        const auto merged = differentiateAxis(micro.s, positions(micro, axis), 50.0,
                                              DerivativeMethod::Spline, 0.008, knots);
        const auto raw =
            differentiateAxis(micro.s, positions(micro, axis), 50.0, DerivativeMethod::RawSpline);
        ASSERT_TRUE(reference && merged && raw);
        if (reference->peakAcceleration == 0.0) {
            continue; // the still B axis
        }
        EXPECT_NEAR(merged->peakAcceleration, reference->peakAcceleration,
                    1e-9 * reference->peakAcceleration)
            << kinematics::axisName(axis);
        EXPECT_NEAR(merged->peakVelocity, reference->peakVelocity, 1e-9 * reference->peakVelocity);
        // The raw spline through the split points is what the merge is for.
        EXPECT_GT(raw->peakAcceleration, 1.2 * reference->peakAcceleration)
            << kinematics::axisName(axis);
    }
}

TEST(MotionKnots, KnotsThatDoNotStartAtTheFirstSampleAreRefused) {
    const Sampled clean = smoothMotion(0);
    const std::vector<std::size_t> knots{1, 5, clean.s.size() - 1};
    const auto result = differentiateAxis(clean.s, positions(clean, kinematics::AxisId::X), 50.0,
                                          DerivativeMethod::Spline, 0.008, knots);
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::InvalidArgument);
}

TEST(MotionKnots, MedianChordIsTheMiddleChord) {
    const std::vector<double> s{0.0, 1.0, 1.5, 4.5, 5.0};
    EXPECT_DOUBLE_EQ(medianChord(s), 1.0); // chords 1, 0.5, 3, 0.5 -> upper middle
    EXPECT_DOUBLE_EQ(medianChord(std::vector<double>{2.0}), 0.0);
}

} // namespace
} // namespace bladeaxis::analysis
