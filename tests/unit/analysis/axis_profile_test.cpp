#include "core/analysis/axis_profile.h"
#include "core/base/execution.h"
#include "core/base/units.h"
#include "tests/unit/analysis/test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace bladeaxis::analysis {
namespace {

using kinematics::AxisId;
using testing::Program;

constexpr DerivativeMethod kMethods[] = {DerivativeMethod::Spline,
                                         DerivativeMethod::FiniteDifference};

AxisProfileOptions withMethod(DerivativeMethod method) {
    AxisProfileOptions options;
    options.method = method;
    return options;
}

// A straight line along a unit direction with random non-uniform spacing; s = distance.
Program straightLine(const Vec3& direction, int count, double feed, double aPerMm = 0.0,
                     double aPerMm2 = 0.0) {
    std::mt19937 rng(29);
    std::uniform_real_distribution<double> gap(0.05, 1.5);
    Program program;
    double u = 0.0;
    for (int i = 0; i < count; ++i) {
        program.add(direction * u, aPerMm * u + aPerMm2 * u * u, feed);
        u += gap(rng);
    }
    return program;
}

TEST(AnalyseAxisMotion, StraightLineAtConstantFeedMovesEachAxisAtFeedTimesDirection) {
    const Vec3 direction = Vec3(1.0, 2.0, -2.0) / 3.0;
    const double feed = 50.0;
    const Program program = straightLine(direction, 60, feed);
    for (DerivativeMethod method : kMethods) {
        const Result<AxisProfile> profile =
            analyseAxisMotion(program.axes, program.records, withMethod(method));
        ASSERT_TRUE(profile.has_value()) << profile.error().toString();
        EXPECT_EQ(profile->feed, feed);
        for (int j = 0; j < 3; ++j) {
            const AxisSeries& axis = profile->axes[j];
            for (std::size_t i = 0; i < axis.velocity.size(); ++i) {
                EXPECT_NEAR(axis.velocity[i], feed * direction[j], 1e-9 * feed) << j << " " << i;
                EXPECT_NEAR(axis.acceleration[i], 0.0, 1e-7) << j << " " << i;
            }
            EXPECT_NEAR(axis.peakVelocity, feed * std::abs(direction[j]), 1e-9 * feed);
            EXPECT_NEAR(axis.p999Velocity, feed * std::abs(direction[j]), 1e-9 * feed);
        }
        EXPECT_EQ(profile->axis(AxisId::A).peakVelocity, 0.0);
    }
}

TEST(AnalyseAxisMotion, TimeIsPathOverFeedAndPathIsTipArcLength) {
    const Program program = straightLine(Vec3::UnitY(), 20, 25.0);
    const Result<AxisProfile> profile = analyseAxisMotion(
        program.axes, program.records, AxisProfileOptions{.method = DerivativeMethod::Spline});
    ASSERT_TRUE(profile.has_value());
    const double length = program.records.back().tip.y();
    EXPECT_NEAR(profile->pathLength, length, 1e-12);
    EXPECT_NEAR(profile->cycleTime, length / 25.0, 1e-12);
    ASSERT_EQ(profile->times().size(), 20u);
    for (std::size_t i = 0; i < 20; ++i) {
        EXPECT_NEAR(profile->pathParameter[i], program.records[i].tip.y(), 1e-12);
        EXPECT_DOUBLE_EQ(profile->times()[i], profile->pathParameter[i] / 25.0);
        EXPECT_EQ(profile->sampleRecord[i], i);
    }
}

// Tip on a circle of radius r in the YZ plane with A = s / r (s = chord arc length as analysed):
// Adot = F / r exactly, and the linear axes move at speed F with centripetal acceleration F^2/r.
TEST(AnalyseAxisMotion, UniformCircleWithATiedToArcLengthTurnsAAtFeedOverRadius) {
    const double r = 10.0;
    const double feed = 100.0;
    const int count = 400;
    Program program;
    double s = 0.0;
    Vec3 previous = Vec3::Zero();
    for (int i = 0; i < count; ++i) {
        const double phi = 1.8 * units::kPi * i / count;
        const Vec3 tip(0.0, r * std::cos(phi), r * std::sin(phi));
        s += i == 0 ? 0.0 : (tip - previous).norm();
        previous = tip;
        program.add(tip, s / r, feed);
    }
    const Result<AxisProfile> profile = analyseAxisMotion(
        program.axes, program.records, AxisProfileOptions{.method = DerivativeMethod::Spline});
    ASSERT_TRUE(profile.has_value());
    const AxisSeries& a = profile->axis(AxisId::A);
    const AxisSeries& y = profile->axis(AxisId::Y);
    const AxisSeries& z = profile->axis(AxisId::Z);
    for (std::size_t i = 0; i < a.velocity.size(); ++i) {
        EXPECT_NEAR(a.velocity[i], feed / r, 1e-9) << i;
        EXPECT_NEAR(a.acceleration[i], 0.0, 1e-6) << i;
        EXPECT_NEAR(std::hypot(y.velocity[i], z.velocity[i]), feed, 1e-4 * feed) << i;
        EXPECT_NEAR(std::hypot(y.acceleration[i], z.acceleration[i]), feed * feed / r,
                    1e-3 * feed * feed / r)
            << i;
    }
    EXPECT_NEAR(a.peakVelocity, feed / r, 1e-9);
    EXPECT_EQ(profile->aReversals.count, 0);
    EXPECT_NEAR(profile->aReversals.travel, s / r, 1e-12);
}

TEST(AnalyseAxisMotion, ReleasedSampleDataLeavesTheFiguresAndTheSampleCount) {
    const Program program = straightLine(Vec3(0.6, 0.0, 0.8), 300, 50.0, 0.01, 2e-4);
    const Result<AxisProfile> kept = analyseAxisMotion(
        program.axes, program.records, AxisProfileOptions{.method = DerivativeMethod::Spline});
    ASSERT_TRUE(kept.has_value()) << kept.error().toString();
    AxisProfile released = *kept;
    released.releaseSampleData();

    EXPECT_FALSE(kept->sampleDataReleased);
    EXPECT_TRUE(released.sampleDataReleased);
    EXPECT_EQ(released.pathParameter.capacity(), 0u);
    EXPECT_EQ(released.sampleRecord.capacity(), 0u);
    EXPECT_EQ(released.sampleCount(), kept->sampleCount());
    EXPECT_EQ(released.sampleCount(), kept->pathParameter.size());
    EXPECT_EQ(released.pathLength, kept->pathLength);
    EXPECT_EQ(released.cycleTime, kept->cycleTime);
    EXPECT_EQ(released.aReversals.count, kept->aReversals.count);
    for (AxisId id : kinematics::kAllAxes) {
        const AxisSeries& before = kept->axis(id);
        const AxisSeries& after = released.axis(id);
        EXPECT_EQ(after.velocity.capacity(), 0u); // freed, not only cleared
        EXPECT_EQ(after.acceleration.capacity(), 0u);
        EXPECT_EQ(after.peakVelocity, before.peakVelocity);
        EXPECT_EQ(after.peakAcceleration, before.peakAcceleration);
        EXPECT_EQ(after.peakJerk, before.peakJerk);
        EXPECT_EQ(after.p999Velocity, before.p999Velocity);
        EXPECT_EQ(after.p999Acceleration, before.p999Acceleration);
        EXPECT_EQ(after.minPosition, before.minPosition);
        EXPECT_EQ(after.maxPosition, before.maxPosition);
        EXPECT_TRUE(released.positions(id).empty());
    }
    EXPECT_FALSE(released.recordAxes);           // its share of the machine axes given up
    EXPECT_FALSE(kept->axis(AxisId::A).still()); // the release had something to free
}

TEST(AnalyseAxisMotion, ParabolicAGivesConstantAccelerationTwiceCTimesFeedSquared) {
    const double c = 0.003; // rad/mm^2
    const double feed = 40.0;
    const Program program = straightLine(Vec3::UnitX(), 50, feed, 0.0, c);
    for (DerivativeMethod method : kMethods) {
        const Result<AxisProfile> profile =
            analyseAxisMotion(program.axes, program.records, withMethod(method));
        ASSERT_TRUE(profile.has_value());
        const AxisSeries& a = profile->axis(AxisId::A);
        for (std::size_t i = 0; i < a.acceleration.size(); ++i) {
            const double s = profile->pathParameter[i];
            EXPECT_NEAR(a.acceleration[i], 2 * c * feed * feed, 1e-7) << i;
            EXPECT_NEAR(a.velocity[i], 2 * c * s * feed, 1e-8) << i;
        }
        EXPECT_NEAR(a.peakJerk, 0.0, 1e-4);
        EXPECT_NEAR(a.peakAcceleration, 2 * c * feed * feed, 1e-7);
    }
}

TEST(AnalyseAxisMotion, MergesAndCountsDuplicatePoints) {
    const Program line = straightLine(Vec3::UnitX(), 10, 30.0, 0.01);
    Program program;
    for (std::size_t i = 0; i < line.records.size(); ++i) {
        program.records.push_back(line.records[i]);
        program.axes.push_back(line.axes[i]);
        if (i == 2 || i == 5) {
            program.records.push_back(line.records[i]); // exact repeat
            program.axes.push_back(line.axes[i]);
        }
        if (i == 7) { // 1e-10 mm away: below the 1e-9 mm merge distance
            program.add(line.records[i].tip + Vec3(1e-10, 0, 0), line.axes[i].a, 30.0);
        }
    }
    const Result<AxisProfile> merged =
        analyseAxisMotion(program.axes, program.records, AxisProfileOptions{});
    const Result<AxisProfile> clean =
        analyseAxisMotion(line.axes, line.records, AxisProfileOptions{});
    ASSERT_TRUE(merged.has_value() && clean.has_value());
    EXPECT_EQ(merged->mergedDuplicates, 3u);
    EXPECT_EQ(merged->sampleRecord, (std::vector<RecordIndex>{0, 1, 2, 4, 5, 6, 8, 9, 11, 12}));
    EXPECT_EQ(merged->pathParameter, clean->pathParameter);
    EXPECT_EQ(merged->axis(AxisId::A).velocity, clean->axis(AxisId::A).velocity);
}

TEST(AnalyseAxisMotion, NonFiniteInputIsAnErrorNamingTheLine) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Program line = straightLine(Vec3::UnitX(), 5, 30.0);
    Program badTip = line;
    badTip.records[3].tip.y() = nan;
    Program badAxis = line;
    badAxis.axes[2].a = std::numeric_limits<double>::infinity();
    Program badFeed = line;
    badFeed.records[1].feed = nan;
    for (const Program* program : {&badTip, &badAxis, &badFeed}) {
        const Result<AxisProfile> profile =
            analyseAxisMotion(program->axes, program->records, AxisProfileOptions{});
        ASSERT_FALSE(profile.has_value());
        EXPECT_EQ(profile.error().code, ErrorCode::Geometry);
        EXPECT_NE(profile.error().message.find("line"), std::string::npos);
    }
}

TEST(AnalyseAxisMotion, RejectsEmptyMismatchedAndFeedlessInput) {
    const Program line = straightLine(Vec3::UnitX(), 5, 30.0);
    EXPECT_EQ(analyseAxisMotion({}, std::span<const toolpath::ClRecord>{}, {}).error().code,
              ErrorCode::InvalidArgument);
    const std::span<const kinematics::MachineAxes> fewer(line.axes.data(), 4);
    EXPECT_EQ(analyseAxisMotion(fewer, line.records, {}).error().code, ErrorCode::InvalidArgument);
    Program rapidOnly = line;
    for (toolpath::ClRecord& record : rapidOnly.records) {
        record.feed = 0.0;
    }
    EXPECT_FALSE(analyseAxisMotion(rapidOnly.axes, rapidOnly.records, {}).has_value());
    AxisProfileOptions override;
    override.feedOverride = 12.0;
    const Result<AxisProfile> profile =
        analyseAxisMotion(rapidOnly.axes, rapidOnly.records, override);
    ASSERT_TRUE(profile.has_value());
    EXPECT_EQ(profile->feed, 12.0);
    override.feedOverride = -1.0;
    EXPECT_FALSE(analyseAxisMotion(line.axes, line.records, override).has_value());
}

// A re-scheduled pass lends its new tool axes and feeds instead of copying every record, and its
// poses keep the records' ball centres: the analysis must be the one of records that carry them.
TEST(AnalyseAxisMotion, LentPosesAndFeedsGiveWhatRecordsCarryingThemGive) {
    const Program line = straightLine(Vec3(1.0, 2.0, -2.0) / 3.0, 40, 30.0, 0.01, 0.002);
    constexpr double kRadius = 4.0;
    Program moved = line;
    std::vector<Vec3> toolAxes;
    std::vector<double> feeds;
    for (std::size_t i = 0; i < moved.records.size(); ++i) {
        toolpath::ClRecord& record = moved.records[i];
        const Vec3 centre = toolpath::ballCentre(line.records[i], kRadius);
        record.axis =
            Vec3(0.0, 0.2 + 0.05 * std::sin(0.3 * static_cast<double>(i)), 1.0).normalized();
        record.tip = tipOfBall(centre, record.axis, kRadius);
        record.feed = 20.0 + static_cast<double>(i % 3);
        toolAxes.push_back(record.axis);
        feeds.push_back(record.feed);
    }
    const AxisProfileOptions tip; // the tip's path: the lent axes move it
    const Result<AxisProfile> carried = analyseAxisMotion(moved.axes, moved.records, tip);
    const PathSamples lent{
        .records = line.records, .toolAxes = toolAxes, .keptCentreRadius = kRadius, .feeds = feeds};
    const Result<AxisProfile> borrowed = analyseAxisMotion(line.axes, lent, tip);
    ASSERT_TRUE(carried.has_value() && borrowed.has_value());
    EXPECT_EQ(borrowed->feed, carried->feed);
    EXPECT_EQ(borrowed->pathParameter, carried->pathParameter);
    EXPECT_EQ(borrowed->axis(AxisId::A).acceleration, carried->axis(AxisId::A).acceleration);
    EXPECT_NE(borrowed->pathParameter,
              analyseAxisMotion(line.axes, line.records, tip)->pathParameter);

    const PathSamples fewAxes{.records = line.records,
                              .toolAxes = std::span(toolAxes).first(5),
                              .keptCentreRadius = kRadius};
    const Result<AxisProfile> mismatched = analyseAxisMotion(line.axes, fewAxes, tip);
    ASSERT_FALSE(mismatched.has_value());
    EXPECT_EQ(mismatched.error().code, ErrorCode::InvalidArgument);
    const PathSamples withoutRadius{.records = line.records, .toolAxes = toolAxes};
    const Result<AxisProfile> unknownCentres = analyseAxisMotion(line.axes, withoutRadius, tip);
    ASSERT_FALSE(unknownCentres.has_value());
    EXPECT_EQ(unknownCentres.error().code, ErrorCode::InvalidArgument);
}

TEST(AnalyseAxisMotion, LentPosesFreedOnceReadGiveTheProfileOfKeptOnes) {
    const Program line = straightLine(Vec3(1.0, 2.0, -2.0) / 3.0, 40, 30.0, 0.01, 0.002);
    constexpr double kRadius = 4.0;
    std::vector<Vec3> toolAxes;
    for (std::size_t i = 0; i < line.records.size(); ++i) {
        toolAxes.push_back(
            Vec3(0.0, 0.2 + 0.05 * std::sin(0.3 * static_cast<double>(i)), 1.0).normalized());
    }
    const AxisProfileOptions tip;
    const PathSamples kept{
        .records = line.records, .toolAxes = toolAxes, .keptCentreRadius = kRadius};
    const Result<AxisProfile> fromKept = analyseAxisMotion(line.axes, kept, tip);

    std::vector<Vec3> lentAxes = toolAxes;
    int calls = 0;
    PathSamples lent{.records = line.records, .toolAxes = lentAxes, .keptCentreRadius = kRadius};
    lent.posesRead = [&] {
        ++calls;
        // Overwritten where a lender would free them: nothing may read them any more.
        std::ranges::fill(lentAxes, Vec3(std::nan(""), std::nan(""), std::nan("")));
    };
    const Result<AxisProfile> fromLent = analyseAxisMotion(line.axes, lent, tip);
    ASSERT_TRUE(fromKept.has_value() && fromLent.has_value()) << fromLent.error().toString();
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(fromLent->pathParameter, fromKept->pathParameter);
    for (AxisId axis : kinematics::kAllAxes) {
        EXPECT_EQ(fromLent->axis(axis).velocity, fromKept->axis(axis).velocity);
        EXPECT_EQ(fromLent->axis(axis).acceleration, fromKept->axis(axis).acceleration);
        EXPECT_EQ(fromLent->axis(axis).peakVelocity, fromKept->axis(axis).peakVelocity);
    }
}

TEST(AnalyseAxisMotion, ACancelledAnalysisEndsWithCancelledInsteadOfAProfile) {
    const Program line = straightLine(Vec3(1.0, 2.0, -2.0) / 3.0, 40, 30.0, 0.01, 0.002);
    CancelToken cancel;
    cancel.requestCancel();
    AxisProfileOptions options;
    options.cancel = &cancel;
    const Result<AxisProfile> profile = analyseAxisMotion(line.axes, line.records, options);
    ASSERT_FALSE(profile.has_value());
    EXPECT_EQ(profile.error().code, ErrorCode::Cancelled);
}

// The token set once the path parameter is made (where a lender frees its poses) stops the
// analysis before the derivatives, the longest part of it; unset, the same analysis ends.
TEST(AnalyseAxisMotion, ACancelWhileThePathIsReadStopsBeforeTheDerivatives) {
    const Program line = straightLine(Vec3(1.0, 2.0, -2.0) / 3.0, 40, 30.0, 0.01, 0.002);
    for (const bool cancelling : {false, true}) {
        CancelToken cancel;
        PathSamples samples{.records = line.records};
        samples.posesRead = [&] {
            if (cancelling) {
                cancel.requestCancel();
            }
        };
        AxisProfileOptions options;
        options.cancel = &cancel;
        const Result<AxisProfile> profile = analyseAxisMotion(line.axes, samples, options);
        if (cancelling) {
            ASSERT_FALSE(profile.has_value());
            EXPECT_EQ(profile.error().code, ErrorCode::Cancelled);
        } else {
            EXPECT_TRUE(profile.has_value()) << profile.error().toString();
        }
    }
}

// A profile keeps no positions of its own: it reads them from the machine axes it was made from,
// which it shares with their maker, through the records its samples stand for.
TEST(AnalyseAxisMotion, PositionsAreTheSharedMachineAxesOfTheSampledRecords) {
    Program program = straightLine(Vec3(0.6, 0.8, 0.0), 30, 40.0, 0.02, 0.001);
    const Vec3 end = program.records.back().tip;
    program.add(end, program.axes.back().a, 40.0); // merged: the same tip
    program.add(end + Vec3(0.5, 0.0, 0.0), 0.7, 40.0);
    const auto shared = std::make_shared<const std::vector<kinematics::MachineAxes>>(program.axes);
    const Result<AxisProfile> profile =
        analyseAxisMotion(shared, PathSamples{.records = program.records}, {});
    ASSERT_TRUE(profile.has_value()) << profile.error().toString();
    EXPECT_EQ(profile->recordAxes, shared) << "shared, not copied";
    EXPECT_EQ(profile->mergedDuplicates, 1u);
    ASSERT_EQ(profile->sampleRecord.size(), program.axes.size() - 1);
    for (AxisId id : kinematics::kAllAxes) {
        const std::vector<double> positions = profile->positions(id);
        ASSERT_EQ(positions.size(), profile->sampleRecord.size());
        for (std::size_t i = 0; i < positions.size(); ++i) {
            EXPECT_EQ(positions[i], program.axes[profile->sampleRecord[i]][id]);
            EXPECT_EQ(profile->position(id, i), positions[i]);
        }
        const auto [low, high] = std::ranges::minmax(positions);
        EXPECT_EQ(profile->axis(id).minPosition, low);
        EXPECT_EQ(profile->axis(id).maxPosition, high);
    }
    EXPECT_EQ(profile->positions(AxisId::A).back(), 0.7);
    EXPECT_EQ(analyseAxisMotion(analysis::SharedMachineAxes{},
                                PathSamples{.records = program.records}, {})
                  .error()
                  .code,
              ErrorCode::InvalidArgument);
}

// B stays put in four-axis work: its profile keeps no zeros, yet reads as zero at every sample.
TEST(AnalyseAxisMotion, AStillAxisKeepsNoSamplesAndReadsAsZero) {
    const Program program = straightLine(Vec3(0.6, 0.8, 0.0), 40, 30.0, 0.01, 0.002);
    for (DerivativeMethod method :
         {DerivativeMethod::Spline, DerivativeMethod::RawSpline, DerivativeMethod::FiniteDifference,
          DerivativeMethod::Filtered}) {
        const Result<AxisProfile> profile =
            analyseAxisMotion(program.axes, program.records, withMethod(method));
        ASSERT_TRUE(profile.has_value()) << nameOf(method);
        const std::size_t n = profile->pathParameter.size();
        const AxisSeries& b = profile->axis(AxisId::B);
        EXPECT_TRUE(b.still()) << nameOf(method);
        EXPECT_TRUE(b.velocity.empty() && b.acceleration.empty()) << nameOf(method);
        EXPECT_EQ(b.velocities(n), std::vector<double>(n, 0.0)) << nameOf(method);
        EXPECT_EQ(b.accelerations(n), std::vector<double>(n, 0.0)) << nameOf(method);
        EXPECT_EQ(b.velocityAt(n - 1), 0.0);
        EXPECT_EQ(b.peakVelocity + b.peakAcceleration + b.peakJerk, 0.0) << nameOf(method);
        const AxisSeries& a = profile->axis(AxisId::A);
        ASSERT_FALSE(a.still()) << nameOf(method);
        ASSERT_EQ(a.velocity.size(), n);
        EXPECT_EQ(a.velocities(n), a.velocity);
        EXPECT_EQ(a.accelerationAt(n / 2), a.acceleration[n / 2]);
    }
}

TEST(AnalyseAxisMotion, EveryMethodGivesTheSameFiguresOnAnyNumberOfThreads) {
    // Long enough for the axes to be differentiated on several threads.
    const Program line = straightLine(Vec3(1.0, 2.0, -2.0) / 3.0, 20000, 30.0, 0.01, 2e-6);
    for (DerivativeMethod method :
         {DerivativeMethod::Spline, DerivativeMethod::RawSpline, DerivativeMethod::FiniteDifference,
          DerivativeMethod::Filtered}) {
        AxisProfileOptions options = withMethod(method);
        const Result<AxisProfile> serial = analyseAxisMotion(line.axes, line.records, options);
        ASSERT_TRUE(serial.has_value()) << nameOf(method);
        for (unsigned threads : {0u, 2u, 3u}) {
            const ThreadCountScope scope(threads);
            const Result<AxisProfile> parallel =
                analyseAxisMotion(line.axes, line.records, options);
            ASSERT_TRUE(parallel.has_value()) << nameOf(method);
            for (std::size_t k = 0; k < serial->axes.size(); ++k) {
                const AxisSeries& one = serial->axes[k];
                const AxisSeries& many = parallel->axes[k];
                EXPECT_EQ(many.minPosition, one.minPosition) << nameOf(method) << " axis " << k;
                EXPECT_EQ(many.maxPosition, one.maxPosition) << nameOf(method) << " axis " << k;
                EXPECT_EQ(many.velocity, one.velocity) << nameOf(method) << " axis " << k;
                EXPECT_EQ(many.acceleration, one.acceleration) << nameOf(method) << " axis " << k;
                EXPECT_EQ(many.peakVelocity, one.peakVelocity) << nameOf(method);
                EXPECT_EQ(many.peakAcceleration, one.peakAcceleration) << nameOf(method);
                EXPECT_EQ(many.peakJerk, one.peakJerk) << nameOf(method);
                EXPECT_EQ(many.p999Velocity, one.p999Velocity) << nameOf(method);
                EXPECT_EQ(many.p999Acceleration, one.p999Acceleration) << nameOf(method);
            }
        }
    }
}

TEST(AnalyseAxisMotion, SinglePointOrAllDuplicatesGiveOneSampleAtRest) {
    Program program;
    for (int i = 0; i < 4; ++i) {
        program.add(Vec3(1, 2, 3), 0.5, 10.0);
    }
    for (std::size_t n : {1u, 4u}) {
        const Result<AxisProfile> profile =
            analyseAxisMotion(std::span(program.axes).first(n), std::span(program.records).first(n),
                              AxisProfileOptions{});
        ASSERT_TRUE(profile.has_value());
        EXPECT_EQ(profile->pathParameter.size(), 1u);
        EXPECT_EQ(profile->mergedDuplicates, n - 1);
        EXPECT_EQ(profile->cycleTime, 0.0);
        EXPECT_EQ(profile->positions(AxisId::X), std::vector<double>{1.0});
        EXPECT_EQ(profile->axis(AxisId::X).peakVelocity, 0.0);
    }
}

TEST(AnalyseAxisMotion, VaryingProgrammedFeedsUseTheMedianOfPositiveFeeds) {
    Program program = straightLine(Vec3::UnitX(), 5, 0.0);
    const double feeds[] = {0.0, 10.0, 40.0, 20.0, 30.0}; // the rapid (0) is ignored
    for (int i = 0; i < 5; ++i) {
        program.records[i].feed = feeds[i];
    }
    EXPECT_DOUBLE_EQ(analyseAxisMotion(program.axes, program.records, {})->feed, 25.0);
    program.records[0].feed = 35.0; // odd count: the middle value
    EXPECT_DOUBLE_EQ(analyseAxisMotion(program.axes, program.records, {})->feed, 30.0);
}

// The tip stays put while the tool axis swings: with the tip as reference every point merges;
// the cutter centre Q = O + R V moves on a circle of radius R.
TEST(AnalyseAxisMotion, CentreReferenceMeasuresTheCutterCentrePath) {
    const double radius = 5.0;
    const double step = 0.01;
    Program program;
    for (int i = 0; i < 50; ++i) {
        const double phi = step * i;
        program.add(Vec3::Zero(), phi, 20.0, Vec3(0.0, std::sin(phi), std::cos(phi)));
    }
    const Result<AxisProfile> tip = analyseAxisMotion(
        program.axes, program.records, AxisProfileOptions{.method = DerivativeMethod::Spline});
    ASSERT_TRUE(tip.has_value());
    EXPECT_EQ(tip->mergedDuplicates, 49u);
    AxisProfileOptions centre;
    centre.feedReference = FeedReference::Centre;
    EXPECT_FALSE(analyseAxisMotion(program.axes, program.records, centre).has_value());
    centre.toolRadius = radius;
    const Result<AxisProfile> profile = analyseAxisMotion(program.axes, program.records, centre);
    ASSERT_TRUE(profile.has_value());
    EXPECT_EQ(profile->mergedDuplicates, 0u);
    EXPECT_NEAR(profile->pathLength, 49 * 2 * radius * std::sin(step / 2), 1e-12);
    EXPECT_EQ(profile->feedReference, FeedReference::Centre);
}

TEST(AnalyseAxisMotion, AuditsAReversalsOverAllRecords) {
    Program program;
    const double a[] = {0.0, 0.1, 0.2, 0.15, 0.3};
    for (int i = 0; i < 5; ++i) {
        program.add(Vec3(i, 0, 0), a[i], 10.0);
    }
    const Result<AxisProfile> profile = analyseAxisMotion(
        program.axes, program.records, AxisProfileOptions{.method = DerivativeMethod::Spline});
    ASSERT_TRUE(profile.has_value());
    EXPECT_EQ(profile->aReversals.count, 2);
    EXPECT_EQ(profile->aReversals.indices, (std::vector<std::size_t>{2, 3}));
    EXPECT_NEAR(profile->aReversals.backwardTravel, 0.05, 1e-15);
}

} // namespace
} // namespace bladeaxis::analysis
