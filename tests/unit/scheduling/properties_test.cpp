// Spec §10.2 pipeline invariants as property tests over a seeded random family of synthetic
// blades (core/blade, spec §10.4): NACA high-camber, symmetric and turbine sections with varied
// camber, thickness, twist, chord, lean, pitch, tool radius, point density, lead noise and tip
// rounding to 1e-3 mm. The seed and the family size can be overridden with
// BLADEAXIS_PROPERTY_SEED and BLADEAXIS_PROPERTY_COUNT (e.g. to explore more members locally).
#include "core/blade/presets.h"
#include "core/scheduling/plane_path.h"
#include "core/scheduling/schedule.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>

namespace bladeaxis::scheduling {
namespace {

constexpr double kPi = std::numbers::pi;

struct Member {
    std::string name;
    ScheduleInput input;
    int revolutions = 0;
    bool concaveSections = false; // the swept sections have a concave part
    ScheduleResult result;        // best preset, computed once
};

std::uint64_t environmentNumber(const char* name, std::uint64_t fallback) {
    const char* value = std::getenv(name);
    return value != nullptr ? std::strtoull(value, nullptr, 10) : fallback;
}

// Members of the family: 60, or fewer where BLADEAXIS_PROPERTY_COUNT says so (the sanitizer
// run of CI, where each member costs ten times as much).
std::uint64_t propertyCount() {
    return environmentNumber("BLADEAXIS_PROPERTY_COUNT", 60);
}

// The CL data as a reader would see it: tips (rounded for some members) and axes, so that the
// centres Q = O + R V carry the rounding noise.
ScheduleInput inputOf(const blade::GeneratedPath& generated, double radius) {
    ScheduleInput input;
    input.toolRadius = radius;
    for (const toolpath::ClRecord& record : generated.path.records) {
        input.centres.push_back(record.tip + radius * record.axis);
        input.axes.push_back(record.axis);
    }
    return input;
}

const std::vector<Member>& family() {
    static const std::vector<Member> members = [] {
        const auto seed = environmentNumber("BLADEAXIS_PROPERTY_SEED", 20261122);
        const auto count = static_cast<int>(propertyCount());
        std::vector<Member> out;
        auto specs = blade::syntheticFamily(seed, count);
        if (!specs) {
            ADD_FAILURE() << specs.error().message;
            return out;
        }
        for (const blade::FamilyMember& spec : *specs) {
            auto model = blade::Blade::create(spec.blade);
            auto generated = model ? blade::generateHelicalPath(*model, spec.path)
                                   : Result<blade::GeneratedPath>(std::unexpected(model.error()));
            if (!generated) {
                ADD_FAILURE() << spec.name << ": " << generated.error().message;
                continue;
            }
            Member member;
            member.name = spec.name;
            member.input = inputOf(*generated, spec.path.toolRadius);
            member.revolutions = spec.path.revolutions;
            member.concaveSections = std::isfinite(spec.minConcaveRadius);
            auto result = schedule(member.input, bestPreset());
            if (!result) {
                ADD_FAILURE() << spec.name << ": " << result.error().message;
                continue;
            }
            member.result = std::move(*result);
            out.push_back(std::move(member));
        }
        return out;
    }();
    return members;
}

bool hasFlag(const LayerResult& layer, LayerStatus status) {
    return std::find(layer.flags.begin(), layer.flags.end(), status) != layer.flags.end();
}

bool scheduled(const LayerResult& layer) {
    return !hasFlag(layer, LayerStatus::MonotoneInfeasible);
}

// Layers with both ends at junctions (not the partial first and last ones).
bool intermediate(const ScheduleResult& result, std::size_t k) {
    return k > 0 && k + 1 < result.layers.size();
}

TEST(SchedulingProperties, FamilyIsLargeAndVaried) {
    ASSERT_GE(family().size(), std::min<std::uint64_t>(50u, propertyCount()));
    std::size_t points = 0;
    std::size_t minPoints = SIZE_MAX;
    std::size_t maxPoints = 0;
    for (const Member& m : family()) {
        points += m.input.centres.size();
        minPoints = std::min(minPoints, m.input.centres.size());
        maxPoints = std::max(maxPoints, m.input.centres.size());
    }
    EXPECT_GT(maxPoints, 2 * minPoints); // varied densities and revolution counts
    std::printf("[ measure  ] %zu blades, %zu CL points (%zu..%zu per path)\n", family().size(),
                points, minPoints, maxPoints);
}

// §10.2 items 1-2: no A reversal, theta non-decreasing in each layer, inside the raw channel.
TEST(SchedulingProperties, MonotoneAndInsideTheRawChannel) {
    for (const Member& m : family()) {
        SCOPED_TRACE(m.name);
        EXPECT_EQ(m.result.check.reversals, 0u);
        for (std::size_t k = 0; k < m.result.layers.size(); ++k) {
            const LayerResult& layer = m.result.layers[k];
            EXPECT_TRUE(scheduled(layer)) << "layer " << k;
            for (std::size_t i = 0; i < layer.theta.size(); ++i) {
                ASSERT_GE(layer.theta[i], layer.thetaMin[i] - 1e-9) << k << " " << i;
                ASSERT_LE(layer.theta[i], layer.thetaMax[i] + 1e-9) << k << " " << i;
                if (i > 0) {
                    ASSERT_GE(layer.theta[i] - layer.theta[i - 1], -1e-12) << k << " " << i;
                }
            }
        }
    }
}

double pathPeak(const ScheduleResult& result) {
    double peak = 0.0;
    for (const LayerResult& layer : result.layers) {
        peak = std::max(peak, layer.peakSecondDerivative);
    }
    return peak;
}

// [X] The best preset's plateau corners (1.25 x the least peak for their span) never raise the
// path's peak theta'' above that of the same preset with the Bezier pairs (8/3 x); both keep the
// invariants above (the test before runs on the plateau default).
TEST(SchedulingProperties, PlateauCornersLowerThePeakOfTheBezierCorners) {
    ScheduleParameters bezier = bestPreset();
    bezier.cornerProfile = CornerProfile::Bezier;
    double worstRatio = 0.0;
    for (const Member& m : family()) {
        SCOPED_TRACE(m.name);
        auto withBezier = schedule(m.input, bezier);
        ASSERT_TRUE(withBezier.has_value());
        EXPECT_EQ(withBezier->check.reversals, 0u);
        const double plateauPeak = pathPeak(m.result);
        const double bezierPeak = pathPeak(*withBezier);
        EXPECT_LE(plateauPeak, bezierPeak * (1.0 + 1e-9));
        if (bezierPeak > 0.0) {
            worstRatio = std::max(worstRatio, plateauPeak / bezierPeak);
        }
    }
    std::printf("[ measure  ] plateau / Bezier peak theta'' per path: at most %.3f\n", worstRatio);
}

// §10.2 item 3: zero slope and zero theta'' at the ends of intermediate layers (C2 junctions).
TEST(SchedulingProperties, FlatEndsAtIntermediateLayerJunctions) {
    for (const Member& m : family()) {
        SCOPED_TRACE(m.name);
        for (std::size_t k = 0; k < m.result.layers.size(); ++k) {
            const LayerResult& layer = m.result.layers[k];
            if (!intermediate(m.result, k) || hasFlag(layer, LayerStatus::ShortLayer)) {
                continue;
            }
            EXPECT_NEAR(layer.dTheta.front(), 0.0, 1e-9) << k;
            EXPECT_NEAR(layer.dTheta.back(), 0.0, 1e-9) << k;
            EXPECT_NEAR(layer.ddTheta.front(), 0.0, 1e-9) << k;
            EXPECT_NEAR(layer.ddTheta.back(), 0.0, 1e-9) << k;
        }
    }
}

// §10.2 item 4: the orientation at a junction is the same seen from both layers.
TEST(SchedulingProperties, OrientationIsContinuousAcrossLayers) {
    for (const Member& m : family()) {
        SCOPED_TRACE(m.name);
        const ScheduleResult& r = m.result;
        for (std::size_t k = 0; k + 1 < r.layers.size(); ++k) {
            const LayerResult& a = r.layers[k];
            const LayerResult& b = r.layers[k + 1];
            ASSERT_EQ(a.inputIndex.back(), b.inputIndex.front());
            const Vec3 end =
                axisFromPlaneAngle(a.junctionAngle + a.theta.back(), r.tiltB0, r.traversalSign);
            const Vec3 start =
                axisFromPlaneAngle(b.junctionAngle + b.theta.front(), r.tiltB0, r.traversalSign);
            EXPECT_LT((end - start).norm(), 1e-12) << k;
        }
    }
}

// §10.2 item 5: every ball centre is kept.
TEST(SchedulingProperties, TipReconstructionKeepsEveryBallCentre) {
    for (const Member& m : family()) {
        SCOPED_TRACE(m.name);
        const ScheduleInput& in = m.input;
        ASSERT_EQ(m.result.newAxes.size(), in.centres.size());
        double worst = 0.0;
        for (std::size_t i = 0; i < in.centres.size(); ++i) {
            const Vec3 q = tipOfBall(in.centres[i], m.result.newAxes[i], in.toolRadius) +
                           in.toolRadius * m.result.newAxes[i];
            worst = std::max(worst, (q - in.centres[i]).norm());
            ASSERT_NEAR(m.result.newAxes[i].norm(), 1.0, 1e-12);
        }
        EXPECT_LT(worst, 1e-9);
        EXPECT_TRUE(m.result.check.passes());
    }
}

void expectSameIntermediateLayers(const ScheduleResult& a, const ScheduleResult& b,
                                  double tolerance) {
    ASSERT_EQ(a.layers.size(), b.layers.size());
    for (std::size_t k = 1; k + 1 < a.layers.size(); ++k) {
        ASSERT_EQ(a.layers[k].theta.size(), b.layers[k].theta.size()) << k;
        for (std::size_t i = 0; i < a.layers[k].theta.size(); ++i) {
            ASSERT_NEAR(a.layers[k].theta[i], b.layers[k].theta[i], tolerance) << k << " " << i;
        }
    }
}

// §10.2 item 6: scheduling the output again reproduces it (channel and junctions depend on Q),
// the free first and last ends included.
TEST(SchedulingProperties, IdempotentOnItsOwnOutput) {
    for (const Member& m : family()) {
        SCOPED_TRACE(m.name);
        ScheduleInput again = m.input;
        again.axes = m.result.newAxes;
        auto second = schedule(again, bestPreset());
        ASSERT_TRUE(second.has_value());
        expectSameIntermediateLayers(m.result, *second, 1e-9);
        EXPECT_EQ(second->originalReversals, 0u);
        // The free ends reproduce too: the clamp into the hull is idempotent.
        const auto absolute = [](const LayerResult& layer, bool front) {
            return layer.junctionAngle + (front ? layer.theta.front() : layer.theta.back());
        };
        EXPECT_NEAR(absolute(second->layers.front(), true), absolute(m.result.layers.front(), true),
                    1e-9);
        EXPECT_NEAR(absolute(second->layers.back(), false), absolute(m.result.layers.back(), false),
                    1e-9);
    }
}

// §10.2 item 7: any other in-channel input orientation (here the middle of the raw channel, with
// the same tilt) gives the same intermediate layers.
TEST(SchedulingProperties, IndependentOfTheInputOrientation) {
    for (const Member& m : family()) {
        SCOPED_TRACE(m.name);
        ScheduleInput other = m.input;
        const ScheduleResult& r = m.result;
        for (const LayerResult& layer : r.layers) {
            for (std::size_t j = 0; j < layer.inputIndex.size(); ++j) {
                const double middle =
                    layer.junctionAngle + 0.5 * (layer.thetaMin[j] + layer.thetaMax[j]);
                other.axes[layer.inputIndex[j]] =
                    axisFromPlaneAngle(middle, r.tiltB0, r.traversalSign);
            }
        }
        for (std::size_t i = 0; i < other.axes.size(); ++i) { // merged duplicates
            if (other.centres[i] == (i > 0 ? other.centres[i - 1] : Vec3::Constant(NAN))) {
                other.axes[i] = other.axes[i - 1];
            }
        }
        auto second = schedule(other, bestPreset());
        ASSERT_TRUE(second.has_value());
        expectSameIntermediateLayers(r, *second, 1e-9);
    }
}

// §10.2 item 8: a rotation about the A axis shifts the absolute angle only.
TEST(SchedulingProperties, RigidRotationAboutTheRotaryAxis) {
    const double phi = 1.3;
    for (const Member& m : family()) {
        SCOPED_TRACE(m.name);
        ScheduleInput rotated = m.input;
        for (std::size_t i = 0; i < rotated.centres.size(); ++i) {
            rotated.centres[i] = rotationX(phi) * m.input.centres[i];
            rotated.axes[i] = rotationX(phi) * m.input.axes[i];
        }
        auto second = schedule(rotated, bestPreset());
        ASSERT_TRUE(second.has_value());
        expectSameIntermediateLayers(m.result, *second, 1e-8);
        const double expected = -m.result.traversalSign * phi; // A = -sign * angle (§6.1)
        const std::vector<double> before = absoluteAngles(m.result, Orientation::Rescheduled);
        const std::vector<double> after = absoluteAngles(*second, Orientation::Rescheduled);
        for (std::size_t i = 0; i < rotated.centres.size(); i += 37) {
            const double shift = before[i] - after[i];
            ASSERT_NEAR(std::remainder(shift - expected, 2.0 * kPi), 0.0, 1e-8) << i;
        }
    }
}

// §10.2 item 8, second half: translating the CL set along the rotary axis a = x changes only X:
// the same orientations, the tips moved by the same distance.
TEST(SchedulingProperties, TranslationAlongTheRotaryAxisMovesOnlyX) {
    const Vec3 shift(37.5, 0.0, 0.0);
    for (const Member& m : family()) {
        SCOPED_TRACE(m.name);
        ScheduleInput moved = m.input;
        for (Vec3& q : moved.centres) {
            q += shift;
        }
        auto second = schedule(moved, bestPreset());
        ASSERT_TRUE(second.has_value());
        ASSERT_EQ(second->newAxes.size(), m.result.newAxes.size());
        for (std::size_t i = 0; i < moved.centres.size(); ++i) {
            ASSERT_LT((second->newAxes[i] - m.result.newAxes[i]).norm(), 1e-9) << i;
            const Vec3 tipChange =
                tipOfBall(moved.centres[i], second->newAxes[i], moved.toolRadius) -
                tipOfBall(m.input.centres[i], m.result.newAxes[i], m.input.toolRadius);
            ASSERT_NEAR(tipChange.x(), shift.x(), 1e-8) << i;
            ASSERT_NEAR(tipChange.y(), 0.0, 1e-8) << i;
            ASSERT_NEAR(tipChange.z(), 0.0, 1e-8) << i;
        }
    }
}

double polylineAt(const std::vector<Vec2>& polyline, double s) {
    const auto after = std::upper_bound(polyline.begin(), polyline.end(), s,
                                        [](double value, const Vec2& p) { return value < p.x(); });
    if (after == polyline.begin()) {
        return polyline.front().y();
    }
    if (after == polyline.end()) {
        return polyline.back().y();
    }
    const Vec2& a = *(after - 1);
    const Vec2& b = *after;
    return b.x() > a.x() ? a.y() + (b.y() - a.y()) * (s - a.x()) / (b.x() - a.x()) : b.y();
}

// §10.2 item 2, second half: before smoothing, the polyline through the key points keeps the
// margin m from the raw channel, i.e. it lies inside the shrunk monotone hull [LO, HI] (whose
// margin is reduced only where a pinch was relieved, §2.5). This includes layers that end at a
// fallback base point, where the hull still rises up to the junction.
TEST(SchedulingProperties, PolylineKeepsTheMarginBeforeSmoothing) {
    for (const Member& m : family()) {
        SCOPED_TRACE(m.name);
        for (std::size_t k = 0; k < m.result.layers.size(); ++k) {
            const LayerResult& layer = m.result.layers[k];
            ASSERT_GE(layer.polyline.size(), 2u) << k;
            for (std::size_t i = 0; i < layer.s.size(); ++i) {
                const double theta = polylineAt(layer.polyline, layer.s[i]);
                ASSERT_GE(theta, layer.lo[i] - 1e-9) << k << " " << i;
                ASSERT_LE(theta, layer.hi[i] + 1e-9) << k << " " << i;
            }
        }
    }
}

// §10.2 item 3 at the path's ends: the first layer ends and the last layer starts flat at their
// junctions, like the intermediate layers.
TEST(SchedulingProperties, FlatEndsAtTheJunctionsOfTheFirstAndLastLayers) {
    for (const Member& m : family()) {
        SCOPED_TRACE(m.name);
        if (m.result.layers.size() < 2) {
            continue;
        }
        const LayerResult& first = m.result.layers.front();
        const LayerResult& last = m.result.layers.back();
        if (!hasFlag(first, LayerStatus::ShortLayer)) {
            EXPECT_NEAR(first.dTheta.back(), 0.0, 1e-9);
            EXPECT_NEAR(first.ddTheta.back(), 0.0, 1e-9);
        }
        if (!hasFlag(last, LayerStatus::ShortLayer)) {
            EXPECT_NEAR(last.dTheta.front(), 0.0, 1e-9);
            EXPECT_NEAR(last.ddTheta.front(), 0.0, 1e-9);
        }
    }
}

// No layer of the family needs the one-sample lead of a pinched base point: the junction
// leaves room for a horizontal lead-out (§3.1, §3.4).
TEST(SchedulingProperties, NoLayerNeedsAOneSampleLead) {
    for (const Member& m : family()) {
        SCOPED_TRACE(m.name);
        for (const std::string& warning : m.result.warnings) {
            EXPECT_EQ(warning.find("one-sample lead"), std::string::npos) << warning;
        }
    }
}

// §10.2 item 11: one base point per revolution, give or take one.
TEST(SchedulingProperties, LayerCountFollowsTheRevolutions) {
    for (const Member& m : family()) {
        SCOPED_TRACE(m.name);
        const double bases = static_cast<double>(m.result.basePoints.size());
        EXPECT_NEAR(bases, m.revolutions, 1.0);
        EXPECT_EQ(m.result.layers.size(), m.result.basePoints.size() + 1);
    }
}

// §10.2 item 10 (reversal part): the fixed-lead original reverses wherever a concave run exists;
// the schedule never does.
TEST(SchedulingProperties, OriginalReversesWhereverAConcaveRunExists) {
    std::size_t concave = 0;
    for (const Member& m : family()) {
        SCOPED_TRACE(m.name);
        const bool detected =
            std::any_of(m.result.layers.begin(), m.result.layers.end(), [](const LayerResult& l) {
                return !hasFlag(l, LayerStatus::NoConcaveRun);
            });
        if (m.concaveSections && detected) {
            ++concave;
            EXPECT_GT(m.result.originalReversals, 0u);
        }
        EXPECT_EQ(m.result.check.reversals, 0u);
    }
    EXPECT_GT(concave, family().size() / 2);
}

} // namespace
} // namespace bladeaxis::scheduling
