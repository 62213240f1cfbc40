#include "core/baselines/quaternion.h"
#include "core/blade/presets.h"
#include "core/geometry/angles.h"
#include "core/scheduling/plane_path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace bladeaxis::baselines {
namespace {

struct Demo {
    scheduling::ScheduleInput input;
    scheduling::ScheduleResult reference;
    Demo() {
        auto bladeModel = blade::Blade::create(blade::demoBladeSpec());
        auto path = blade::generateHelicalPath(*bladeModel, blade::demoPathSpec());
        input.toolRadius = blade::demoPathSpec().toolRadius;
        input.centres = path->centre;
        for (const auto& record : path->path.records) {
            input.axes.push_back(record.axis);
        }
        reference = *scheduling::schedule(input, scheduling::bestPreset());
    }
};

const Demo& demo() {
    static const Demo d;
    return d;
}

std::vector<double> thetas(const std::vector<Vec3>& axes, int sign) {
    std::vector<double> out;
    for (const Vec3& axis : axes) {
        const double angle = scheduling::planeAngle(axis, sign);
        out.push_back(out.empty() ? angle : geometry::unwrapNear(angle, out.back()));
    }
    return out;
}

TEST(QuaternionBaseline, EverySettingEndsInsideTheRawChannelOnTheB0Cone) {
    std::vector<QuaternionSettings> settings = fairnessSettings();
    settings.push_back({.keysPerLayer = 8,
                        .interpolation = QuaternionInterpolation::Slerp,
                        .mode = QuaternionMode::Vector,
                        .margin = 0.05,
                        .maxAdaptiveKeys = 100000});
    for (const QuaternionSettings& setting : settings) {
        auto result = quaternionOrientations(demo().input, demo().reference, setting);
        ASSERT_TRUE(result.has_value()) << describe(setting) << ": " << result.error().toString();
        EXPECT_LE(result->worstViolation, 1e-9) << describe(setting);
        ASSERT_EQ(result->axes.size(), demo().input.centres.size());
        for (const Vec3& axis : result->axes) {
            ASSERT_NEAR(axis.norm(), 1.0, 1e-12);
            ASSERT_NEAR(std::asin(axis.x()), demo().reference.tiltB0, 1e-9) << describe(setting);
        }
        EXPECT_EQ(result->keys.front(), 0u);
        EXPECT_EQ(result->keys.back(), demo().input.centres.size() - 1);
    }
}

TEST(QuaternionBaseline, KeysKeepTheOriginalOrientationUnlessRepaired) {
    QuaternionSettings setting;
    setting.maxAdaptiveKeys = 0; // no channel repair: keys are the CAM's own orientations
    auto result = quaternionOrientations(demo().input, demo().reference, setting);
    ASSERT_TRUE(result.has_value());
    const auto theta = thetas(result->axes, demo().reference.traversalSign);
    const std::vector<double> originals =
        scheduling::absoluteAngles(demo().reference, scheduling::Orientation::Original);
    for (std::size_t key : result->keys) {
        const double original = originals[key];
        EXPECT_NEAR(std::remainder(theta[key] - original, 2.0 * std::numbers::pi), 0.0, 1e-9)
            << key;
    }
}

TEST(QuaternionBaseline, FrameSlerpIsLinearInAngleBetweenKeys) {
    QuaternionSettings setting;
    setting.maxAdaptiveKeys = 0;
    auto result = quaternionOrientations(demo().input, demo().reference, setting);
    ASSERT_TRUE(result.has_value());
    const auto theta = thetas(result->axes, demo().reference.traversalSign);
    const auto& centres = demo().input.centres;
    std::vector<double> s{0.0};
    for (std::size_t i = 1; i < centres.size(); ++i) {
        s.push_back(s.back() + (centres[i] - centres[i - 1]).norm());
    }
    for (std::size_t k = 0; k + 1 < result->keys.size(); ++k) {
        const std::size_t a = result->keys[k], b = result->keys[k + 1];
        for (std::size_t i = a + 1; i < b; ++i) {
            const double u = (s[i] - s[a]) / (s[b] - s[a]);
            ASSERT_NEAR(theta[i], theta[a] + u * (theta[b] - theta[a]), 1e-9) << i;
        }
    }
}

TEST(QuaternionBaseline, SquadPassesThroughTheKeysAndBendsBetweenThem) {
    QuaternionSettings slerp, squad;
    slerp.maxAdaptiveKeys = squad.maxAdaptiveKeys = 0;
    squad.interpolation = QuaternionInterpolation::Squad;
    auto a = quaternionOrientations(demo().input, demo().reference, slerp);
    auto b = quaternionOrientations(demo().input, demo().reference, squad);
    ASSERT_TRUE(a && b);
    ASSERT_EQ(a->keys, b->keys);
    double largestDifference = 0.0;
    for (std::size_t i = 0; i < a->axes.size(); ++i) {
        largestDifference = std::max(largestDifference, (a->axes[i] - b->axes[i]).norm());
    }
    for (std::size_t key : a->keys) {
        EXPECT_LT((a->axes[key] - b->axes[key]).norm(), 1e-12) << key;
    }
    EXPECT_GT(largestDifference, 1e-3);
}

// Followed sample by sample as the rotary axis does (not folded near the keys' straight line),
// every setting stays in the raw channel on a family blade where sparse SQUAD keys overshoot.
TEST(QuaternionBaseline, RepairHoldsWhenTheCurveIsFollowedContinuously) {
    auto family = blade::syntheticFamily(2022, 1);
    ASSERT_TRUE(family.has_value());
    const auto& member = family->front();
    auto bladeModel = blade::Blade::create(member.blade);
    auto path = blade::generateHelicalPath(*bladeModel, member.path);
    scheduling::ScheduleInput input;
    input.toolRadius = member.path.toolRadius;
    input.centres = path->centre;
    for (const auto& record : path->path.records) {
        input.axes.push_back(record.axis);
    }
    const auto reference = *scheduling::schedule(input, scheduling::bestPreset());
    for (const QuaternionSettings& setting : fairnessSettings()) {
        auto result = quaternionOrientations(input, reference, setting);
        ASSERT_TRUE(result.has_value()) << describe(setting);
        for (const auto& layer : reference.layers) {
            double theta = layer.thetaOriginal.front();
            for (std::size_t j = 0; j < layer.inputIndex.size(); ++j) {
                const Vec3& axis = result->axes[layer.inputIndex[j]];
                theta = geometry::unwrapNear(scheduling::planeAngle(axis, reference.traversalSign) -
                                                 layer.junctionAngle,
                                             theta);
                ASSERT_GE(theta, layer.thetaMin[j] - 1e-9) << describe(setting) << " " << j;
                ASSERT_LE(theta, layer.thetaMax[j] + 1e-9) << describe(setting) << " " << j;
            }
        }
    }
}

TEST(QuaternionBaseline, KeysHalfATurnApartAreRefused) {
    QuaternionSettings sparse;
    sparse.keysPerLayer = 1; // one key per revolution: about 360 deg between keys
    auto result = quaternionOrientations(demo().input, demo().reference, sparse);
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::Infeasible);
}

TEST(QuaternionBaseline, MismatchedReferenceIsAnError) {
    scheduling::ScheduleInput shorter = demo().input;
    shorter.centres.resize(10);
    shorter.axes.resize(10);
    auto result = quaternionOrientations(shorter, demo().reference, {});
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::InvalidArgument);
}

// Largest jump of the one-sided slopes dtheta/ds at the interior keys.
double largestSlopeJumpAtKeys(const QuaternionResult& result) {
    const auto theta = thetas(result.axes, demo().reference.traversalSign);
    const auto& centres = demo().input.centres;
    double largest = 0.0;
    for (std::size_t k = 1; k + 1 < result.keys.size(); ++k) {
        const std::size_t i = result.keys[k];
        const double left = (theta[i] - theta[i - 1]) / (centres[i] - centres[i - 1]).norm();
        const double right = (theta[i + 1] - theta[i]) / (centres[i + 1] - centres[i]).norm();
        largest = std::max(largest, std::abs(right - left));
    }
    return largest;
}

// SLERP is only C0 at the keys (the angle rate jumps); SQUAD's tangent quaternions make the
// rate continuous there, up to the unequal key spacing in arc length.
TEST(QuaternionBaseline, SquadSmoothsTheRateJumpsOfSlerpAtTheKeys) {
    QuaternionSettings slerp, squad;
    slerp.maxAdaptiveKeys = squad.maxAdaptiveKeys = 0;
    slerp.keysPerLayer = squad.keysPerLayer = 16;
    squad.interpolation = QuaternionInterpolation::Squad;
    auto a = quaternionOrientations(demo().input, demo().reference, slerp);
    auto b = quaternionOrientations(demo().input, demo().reference, squad);
    ASSERT_TRUE(a && b);
    const double slerpJump = largestSlopeJumpAtKeys(*a);
    const double squadJump = largestSlopeJumpAtKeys(*b);
    EXPECT_GT(slerpJump, 0.0);
    EXPECT_LT(squadJump, 0.5 * slerpJump) << "slerp " << slerpJump << " squad " << squadJump;
}

// With dense keys the great-circle axis SLERP (projected on the B0 cone) and the frame SLERP
// agree closely: both join the same key orientations by the short way.
TEST(QuaternionBaseline, VectorAndFrameSlerpAgreeBetweenDenseKeys) {
    QuaternionSettings frame, vector;
    frame.maxAdaptiveKeys = vector.maxAdaptiveKeys = 0;
    frame.keysPerLayer = vector.keysPerLayer = 32;
    vector.mode = QuaternionMode::Vector;
    auto a = quaternionOrientations(demo().input, demo().reference, frame);
    auto b = quaternionOrientations(demo().input, demo().reference, vector);
    ASSERT_TRUE(a && b);
    ASSERT_EQ(a->keys, b->keys);
    double largest = 0.0;
    for (std::size_t i = 0; i < a->axes.size(); ++i) {
        largest = std::max(largest, std::acos(std::clamp(a->axes[i].dot(b->axes[i]), -1.0, 1.0)));
    }
    EXPECT_LT(largest, 0.02) << "rad";
}

TEST(QuaternionBaseline, NonFiniteInputIsAnErrorNotACrash) {
    scheduling::ScheduleInput broken = demo().input;
    broken.axes[broken.axes.size() / 2] = Vec3(std::nan(""), 0.0, 1.0);
    auto result = quaternionOrientations(broken, demo().reference, {});
    ASSERT_FALSE(result.has_value());
    EXPECT_TRUE(result.error().code == ErrorCode::InvalidArgument ||
                result.error().code == ErrorCode::Geometry);
}

} // namespace
} // namespace bladeaxis::baselines
