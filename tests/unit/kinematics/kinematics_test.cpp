#include "core/base/execution.h"
#include "core/base/units.h"
#include "core/kinematics/kinematics.h"
#include "core/kinematics/machine_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace bladeaxis::kinematics {
namespace {

using units::degToRad;

TableAHeadB offsetChain() {
    TableAHeadB chain;
    chain.pivotLength = 310.0;
    chain.tableOffset = Vec3(12.0, -4.0, 150.0);
    chain.headOffset = Vec3(0.5, 0.0, -2.0);
    return chain;
}

// The worked example of docs/machine-file.md, so the document stays true.
TEST(ForwardKinematics, TheMachineFileDocumentsWorkedExample) {
    const MachineModel machine = defaultBladeMachine();
    const ToolPose pose =
        forwardKinematics(machine.chain, {10.0, 20.0, 5.0, degToRad(30.0), degToRad(10.0)});
    EXPECT_LT((pose.tip - Vec3(10.0, 19.8205, -5.6699)).norm(), 1e-4);
    EXPECT_LT((pose.axis - Vec3(0.1736, 0.4924, 0.8529)).norm(), 1e-4);
    EXPECT_LT((pose.tip + 4.0 * pose.axis - Vec3(10.6946, 21.7901, -2.2584)).norm(), 1e-4);
}

TEST(ForwardKinematics, ToolTipProgrammingReadsXyzAsTheTipInTheWorkpieceFrame) {
    TableAHeadB chain = defaultBladeMachine().chain;
    chain.pivotLength = 250.0;
    chain.tipInWorkpiece = true;
    const MachineAxes axes{10.0, 20.0, 5.0, degToRad(30.0), degToRad(10.0)};
    const ToolPose pose = forwardKinematics(chain, axes);
    EXPECT_LT((pose.tip - Vec3(10.0, 20.0, 5.0)).norm(), 1e-12);
    EXPECT_LT((pose.axis - toolAxisFor(chain, axes.a, axes.b)).norm(), 1e-12);
    const auto back = inverseKinematics(chain, pose, axes.a);
    ASSERT_TRUE(back.has_value());
    EXPECT_NEAR(back->x, 10.0, 1e-9);
    EXPECT_NEAR(back->a, axes.a, 1e-9);
    EXPECT_NEAR(back->b, axes.b, 1e-9);
}

TEST(ForwardKinematics, ZeroAnglesGiveTheToolAlongZ) {
    const ToolPose pose = forwardKinematics({}, {1.0, 2.0, 3.0, 0.0, 0.0});
    EXPECT_NEAR((pose.tip - Vec3(1, 2, 3)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((pose.axis - Vec3::UnitZ()).norm(), 0.0, 1e-15);
}

// Spec §6.1: V = (sin B0, sin A cos B0, cos A cos B0) in W.
TEST(ForwardKinematics, ToolAxisFollowsTheSpecFormula) {
    const double a = degToRad(37.0);
    const double b = degToRad(5.0);
    const ToolPose pose = forwardKinematics({}, {0, 0, 0, a, b});
    const Vec3 expected(std::sin(b), std::sin(a) * std::cos(b), std::cos(a) * std::cos(b));
    EXPECT_NEAR((pose.axis - expected).norm(), 0.0, 1e-15);
    EXPECT_NEAR((toolAxisFor({}, a, b) - expected).norm(), 0.0, 1e-15);
}

// With B fixed the programmed X does not depend on A (spec §6.3).
TEST(ForwardKinematics, RotatingTheTableLeavesXUnchanged) {
    const TableAHeadB chain{};
    const Vec3 tip(5.0, 20.0, -3.0);
    for (double a : {0.0, 0.7, 2.0, -1.3}) {
        auto axes = inverseKinematics(chain, {tip, toolAxisFor(chain, a, degToRad(5))}, a);
        ASSERT_TRUE(axes.has_value());
        EXPECT_NEAR(axes->x, 5.0, 1e-12);
        EXPECT_NEAR(axes->a, a, 1e-12);
    }
}

TEST(Kinematics, ForwardOfInverseReproducesRandomPoses) {
    std::mt19937_64 random(42);
    std::uniform_real_distribution<double> coordinate(-200.0, 200.0);
    std::uniform_real_distribution<double> angle(-3.0, 3.0);
    std::uniform_real_distribution<double> tilt(-1.2, 1.2);
    for (int sign : {1, -1}) {
        TableAHeadB chain = offsetChain();
        chain.aSign = sign;
        chain.bSign = -sign;
        for (int i = 0; i < 1000; ++i) {
            const ToolPose pose{Vec3(coordinate(random), coordinate(random), coordinate(random)),
                                toolAxisFor(chain, angle(random), tilt(random))};
            auto axes = inverseKinematics(chain, pose, 0.0);
            ASSERT_TRUE(axes.has_value());
            const ToolPose back = forwardKinematics(chain, *axes);
            EXPECT_LT((back.tip - pose.tip).norm(), 1e-12 * 400);
            EXPECT_LT((back.axis - pose.axis).norm(), 1e-12);
        }
    }
}

TEST(Kinematics, InverseOfForwardReproducesRandomAxes) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> coordinate(-300.0, 300.0);
    std::uniform_real_distribution<double> angle(-10.0, 10.0);
    std::uniform_real_distribution<double> tilt(-1.4, 1.4);
    const TableAHeadB chain = offsetChain();
    for (int i = 0; i < 1000; ++i) {
        const MachineAxes axes{coordinate(random), coordinate(random), coordinate(random),
                               angle(random), tilt(random)};
        // The A branch is selected by the reference: give the original A as reference.
        auto back = inverseKinematics(chain, forwardKinematics(chain, axes), axes.a);
        ASSERT_TRUE(back.has_value());
        for (AxisId id : kAllAxes) {
            EXPECT_NEAR((*back)[id], axes[id], 1e-9) << axisName(id);
        }
    }
}

TEST(InverseKinematics, UnwrapsANearTheReference) {
    const Vec3 axis = toolAxisFor({}, degToRad(10.0), degToRad(5.0));
    auto axes = inverseKinematics({}, {Vec3::Zero(), axis}, degToRad(700.0));
    ASSERT_TRUE(axes.has_value());
    EXPECT_NEAR(units::radToDeg(axes->a), 730.0, 1e-9);
}

TEST(InverseKinematics, RejectsNanZeroAndAxisParallelToA) {
    const double nan = std::nan("");
    EXPECT_EQ(inverseKinematics({}, {Vec3(nan, 0, 0), Vec3::UnitZ()}).error().code,
              ErrorCode::Geometry);
    EXPECT_EQ(inverseKinematics({}, {Vec3::Zero(), Vec3::Zero()}).error().code,
              ErrorCode::Geometry);
    const auto parallel = inverseKinematics({}, {Vec3::Zero(), Vec3::UnitX()});
    ASSERT_FALSE(parallel.has_value());
    EXPECT_NE(parallel.error().message.find("parallel to the A axis"), std::string::npos);
}

// The chain the spiral poses are made with.
TableAHeadB spiralChain() {
    TableAHeadB chain;
    chain.pivotLength = 250.0;
    chain.tableOffset = Vec3(0.0, 10.0, -5.0);
    return chain;
}

// A spiral of poses turning several times, long enough to be split over threads.
std::vector<ToolPose> spiralPoses(std::size_t count) {
    const TableAHeadB chain = spiralChain();
    std::vector<ToolPose> poses;
    for (std::size_t i = 0; i < count; ++i) {
        const double a = 1e-3 * static_cast<double>(i);
        const MachineAxes axes{1e-4 * static_cast<double>(i), 30.0 * std::cos(7.0 * a),
                               40.0 + 5.0 * std::sin(3.0 * a), a, degToRad(5.0)};
        poses.push_back(forwardKinematics(chain, axes));
    }
    return poses;
}

TEST(InverseKinematicsAlong, SeveralThreadsGiveTheOneThreadResultBitForBit) {
    const TableAHeadB chain = spiralChain();
    const std::vector<ToolPose> poses = spiralPoses(100'000);
    const IkAlongResult serial = inverseKinematicsAlong(chain, poses, 0.0);
    const ThreadCountScope three(3);
    const IkAlongResult parallel = inverseKinematicsAlong(chain, poses, 0.0);
    ASSERT_FALSE(serial.failedIndex || parallel.failedIndex);
    ASSERT_EQ(serial.axes.size(), poses.size());
    for (std::size_t i = 0; i < poses.size(); ++i) {
        ASSERT_TRUE(
            serial.axes[i].a == parallel.axes[i].a && serial.axes[i].x == parallel.axes[i].x &&
            serial.axes[i].y == parallel.axes[i].y && serial.axes[i].z == parallel.axes[i].z &&
            serial.axes[i].b == parallel.axes[i].b)
            << i;
        // One call at a time with the previous A as reference is the definition.
        if (i % 9973 == 0) {
            const double reference = i == 0 ? 0.0 : serial.axes[i - 1].a;
            EXPECT_EQ(inverseKinematics(chain, poses[i], reference)->a, serial.axes[i].a) << i;
        }
    }
    EXPECT_NEAR(serial.axes.back().a, 1e-3 * 99'999.0, 1e-9); // unwrapped over 15 turns
}

TEST(InverseKinematicsAlong, ReportsTheFirstFailingPoseWhateverTheThreads) {
    std::vector<ToolPose> poses = spiralPoses(100'000);
    poses[90'000].axis = Vec3::Zero();
    poses[60'000].axis = Vec3::UnitX(); // parallel to A: the first failure
    const ThreadCountScope four(4);
    const IkAlongResult result = inverseKinematicsAlong({}, poses, 0.0);
    ASSERT_TRUE(result.failedIndex.has_value());
    EXPECT_EQ(*result.failedIndex, 60'000u);
    EXPECT_NE(result.failure.message.find("parallel to the A axis"), std::string::npos);
    EXPECT_TRUE(result.axes.empty());
}

// The job makes each new pose when the IK reads it instead of keeping an array of them.
TEST(InverseKinematicsAlong, PosesMadeOnDemandGiveThePoseArraysResultBitForBit) {
    const TableAHeadB chain = spiralChain();
    const std::vector<ToolPose> poses = spiralPoses(50'000);
    const IkAlongResult fromArray = inverseKinematicsAlong(chain, poses, 0.3);
    const ThreadCountScope two(2);
    const Result<IkAlongResult> onDemand = inverseKinematicsAlong(
        chain, poses.size(), [&poses](std::size_t i) { return poses[i]; }, 0.3);
    ASSERT_TRUE(onDemand.has_value());
    ASSERT_FALSE(fromArray.failedIndex || onDemand->failedIndex);
    ASSERT_EQ(onDemand->axes.size(), poses.size());
    for (std::size_t i = 0; i < poses.size(); ++i) {
        ASSERT_TRUE(fromArray.axes[i].a == onDemand->axes[i].a &&
                    fromArray.axes[i].b == onDemand->axes[i].b &&
                    fromArray.axes[i].x == onDemand->axes[i].x &&
                    fromArray.axes[i].y == onDemand->axes[i].y &&
                    fromArray.axes[i].z == onDemand->axes[i].z)
            << i;
    }
    std::vector<ToolPose> failing = poses;
    failing[20'000].axis = Vec3::UnitX();
    const Result<IkAlongResult> failed = inverseKinematicsAlong(
        chain, failing.size(), [&failing](std::size_t i) { return failing[i]; }, 0.0);
    ASSERT_TRUE(failed.has_value());
    ASSERT_TRUE(failed->failedIndex.has_value());
    EXPECT_EQ(*failed->failedIndex, 20'000u);
    EXPECT_TRUE(failed->axes.empty());
}

// A job interrupted while the new axes are solved stops within 65,536 poses, in either pass,
// instead of solving the rest of a path of millions; a token never set changes nothing.
TEST(InverseKinematicsAlong, StopsSoonAfterTheTokenIsSetInEitherPass) {
    const TableAHeadB chain = spiralChain();
    const std::vector<ToolPose> poses = spiralPoses(200'000);
    const IkAlongResult whole = inverseKinematicsAlong(chain, poses, 0.0);
    ASSERT_FALSE(whole.failedIndex);
    // Each pose is asked for twice, once per pass: call 70,000 is in the first pass, call
    // 270,000 the second pass's pose 70,000.
    for (const std::size_t setAtCall : {std::size_t{70'000}, std::size_t{270'000}}) {
        CancelToken cancel;
        std::size_t calls = 0;
        const Result<IkAlongResult> stopped = inverseKinematicsAlong(
            chain, poses.size(),
            [&](std::size_t i) {
                if (++calls == setAtCall) {
                    cancel.requestCancel();
                }
                return poses[i];
            },
            0.0, &cancel);
        ASSERT_FALSE(stopped.has_value()) << setAtCall;
        EXPECT_EQ(stopped.error().code, ErrorCode::Cancelled) << setAtCall;
        EXPECT_EQ(stopped.error().message, cancelledError().message) << setAtCall;
        EXPECT_LE(calls, setAtCall + 65'536) << setAtCall;
    }
    CancelToken never;
    const ThreadCountScope two(2);
    const Result<IkAlongResult> watched = inverseKinematicsAlong(
        chain, poses.size(), [&poses](std::size_t i) { return poses[i]; }, 0.0, &never);
    ASSERT_TRUE(watched.has_value());
    ASSERT_EQ(watched->axes.size(), whole.axes.size());
    for (std::size_t i = 0; i < poses.size(); ++i) {
        ASSERT_TRUE(watched->axes[i].a == whole.axes[i].a && watched->axes[i].x == whole.axes[i].x)
            << i;
    }
}

} // namespace
} // namespace bladeaxis::kinematics
