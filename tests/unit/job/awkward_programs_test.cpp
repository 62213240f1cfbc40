// Awkward programs as real CAM systems and posts write them, each with its expected outcome: a
// refusal that names its condition and line and writes nothing, or the clean program's result.

#include "core/base/file_io.h"
#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/io/table/point_table.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <unistd.h>

#include "awkward_programs.h"
#include "demo_job.h"

namespace bladeaxis::job::test {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
    // One folder per process: ctest runs the tests of this file in parallel processes, which
    // would otherwise write the same clean program while another reads it.
    const fs::path folder =
        fs::temp_directory_path() / ("bladeaxis_awkward_" + std::to_string(::getpid()));
    fs::create_directories(folder);
    return folder / name;
}

fs::path writeProgram(const std::string& name, const std::string& text) {
    const fs::path path = scratch(name);
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

// A re-scheduling job of `program` writing `<name>.out` (removed first).
JobSpec rescheduleJob(const fs::path& program) {
    JobSpec spec;
    spec.program = program;
    spec.toolRadius = cleanPass().toolRadius;
    spec.outputProgram = program.string() + ".out";
    fs::remove(spec.outputProgram);
    return spec;
}

// Runs the job and writes its outputs, as the batch front end does.
Result<JobResult> runAndWrite(const JobSpec& spec) {
    auto result = runQuietly(spec);
    if (!result) {
        return result;
    }
    if (auto written = writeJobOutputs(spec, *result); !written) {
        return std::unexpected(written.error());
    }
    return result;
}

void expectRefused(const JobSpec& spec, ErrorCode code, const std::string& condition) {
    const auto result = runAndWrite(spec);
    ASSERT_FALSE(result.has_value()) << "expected a refusal: " << condition;
    EXPECT_EQ(result.error().code, code) << result.error().toString();
    EXPECT_NE(result.error().message.find(condition), std::string::npos)
        << result.error().toString();
    EXPECT_GT(result.error().where.line, 0) << "no line: " << result.error().toString();
    EXPECT_FALSE(fs::exists(spec.outputProgram)) << "a refused program was written";
}

// The re-scheduled A of every cutting record, rad.
std::vector<double> rescheduledA(const JobResult& result) {
    std::vector<double> a;
    for (const auto& axes : *result.rescheduled->axes) {
        a.push_back(axes.a);
    }
    return a;
}

void expectSameSchedule(const JobResult& actual, const JobResult& clean, double toleranceRad) {
    const auto a = rescheduledA(actual);
    const auto reference = rescheduledA(clean);
    ASSERT_EQ(a.size(), reference.size());
    double largest = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        largest = std::max(largest, std::abs(a[i] - reference[i]));
    }
    EXPECT_LE(largest, toleranceRad)
        << "largest A difference " << units::radToDeg(largest) << " deg";
}

const JobResult& cleanAptResult() {
    static const JobResult result = [] {
        const CleanPass& clean = cleanPass();
        const auto spec = rescheduleJob(
            writeProgram("clean.cl", aptText(clean.path, clean.toolRadius, clean.feedMmPerMin)));
        auto run = runAndWrite(spec);
        if (!run) {
            throw std::runtime_error(run.error().toString());
        }
        return std::move(*run);
    }();
    return result;
}

TEST(AwkwardPrograms, FiveAxisClWithVaryingTiltIsRefusedBeforeAnythingIsWritten) {
    const CleanPass& clean = cleanPass();
    const auto varied = withVaryingTilt(clean.path, clean.toolRadius, 20.0);
    const auto spec = rescheduleJob(
        writeProgram("five_axis.cl", aptText(varied, clean.toolRadius, clean.feedMmPerMin)));
    expectRefused(spec, ErrorCode::Geometry, "not a four-axis blade pass");
}

TEST(AwkwardPrograms, ToolAxisFromBelowTheSurfaceIsRefusedAsOutsideTheChannel) {
    const CleanPass& clean = cleanPass();
    const auto flipped = withAxisFromBelow(clean.path, clean.toolRadius);
    const auto spec = rescheduleJob(
        writeProgram("from_below.cl", aptText(flipped, clean.toolRadius, clean.feedMmPerMin)));
    expectRefused(spec, ErrorCode::Geometry, "outside the feasible S-theta channel");
}

TEST(AwkwardPrograms, AnalysisOnlyReportsAFiveAxisProgramInsteadOfRefusingIt) {
    const CleanPass& clean = cleanPass();
    const auto varied = withVaryingTilt(clean.path, clean.toolRadius, 20.0);
    JobSpec spec = rescheduleJob(writeProgram(
        "five_axis_analysis.cl", aptText(varied, clean.toolRadius, clean.feedMmPerMin)));
    spec.outputProgram.clear();
    spec.reschedule = false;
    const auto result = runQuietly(spec);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    const bool reported = std::any_of(
        result->warnings.begin(), result->warnings.end(), [](const std::string& warning) {
            return warning.find("not a four-axis") != std::string::npos;
        });
    EXPECT_TRUE(reported);
}

TEST(AwkwardPrograms, BNoiseWithinTheToleranceIsSnappedAndReschedulesLikeTheCleanProgram) {
    const CleanPass& clean = cleanPass();
    const auto machine = kinematics::defaultBladeMachine();
    const auto cleanSpec = rescheduleJob(writeProgram(
        "clean.nc", gcodeText(clean.path, machine, clean.feedMmPerMin, RotaryUnit::Degrees)));
    const auto noisySpec =
        rescheduleJob(writeProgram("b_noise.nc", gcodeText(clean.path, machine, clean.feedMmPerMin,
                                                           RotaryUnit::Degrees, 0.001)));
    const auto reference = runAndWrite(cleanSpec);
    ASSERT_TRUE(reference.has_value()) << reference.error().toString();
    const auto noisy = runAndWrite(noisySpec);
    ASSERT_TRUE(noisy.has_value()) << noisy.error().toString();
    EXPECT_TRUE(fs::exists(noisySpec.outputProgram));
    const bool reported =
        std::any_of(noisy->warnings.begin(), noisy->warnings.end(), [](const std::string& warning) {
            return warning.find("snapped to the median") != std::string::npos;
        });
    EXPECT_TRUE(reported);
    // 0.001 deg of B moves the programmed tip by microns; the schedule follows within 0.01 deg.
    expectSameSchedule(*noisy, *reference, units::degToRad(0.01));
}

// The written program is read back and its ball centres compared with the input's; a program
// whose linear words carry two decimals cannot hold the new centres to the 5 um the check
// accepts (rounding moves them by up to 8.7 um), so the rewrite is refused and nothing written.
TEST(AwkwardPrograms, LinearWordsTooCoarseForTheNewCentresAreRefusedByTheReReadCheck) {
    const CleanPass& clean = cleanPass();
    const std::string fine = gcodeText(clean.path, kinematics::defaultBladeMachine(),
                                       clean.feedMmPerMin, RotaryUnit::Degrees);
    const std::regex linearWord("([XYZ]-?[0-9]+\\.[0-9]{2})[0-9]+");
    const auto spec =
        rescheduleJob(writeProgram("two_decimals.nc", std::regex_replace(fine, linearWord, "$1")));
    expectRefused(spec, ErrorCode::CheckFailed, "ball centres of the written program deviate");
}

TEST(AwkwardPrograms, AGcodeProgramWhosePostStatesTheBallNeedsNoToolRadius) {
    const CleanPass& clean = cleanPass();
    const auto machine = kinematics::defaultBladeMachine();
    const std::string moves =
        gcodeText(clean.path, machine, clean.feedMmPerMin, RotaryUnit::Degrees);
    const std::string header = "(T1 D=" + formatShortest(2.0 * clean.toolRadius) +
                               " CR=" + formatShortest(clean.toolRadius) + " - ball end mill)\n";
    JobSpec stated = rescheduleJob(writeProgram("stated_ball.nc", header + moves));
    stated.toolRadius.reset();
    const auto result = runAndWrite(stated);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    ASSERT_TRUE(result->toolRadius.has_value());
    EXPECT_DOUBLE_EQ(*result->toolRadius, clean.toolRadius);
    EXPECT_TRUE(fs::exists(stated.outputProgram));

    JobSpec unstated = rescheduleJob(writeProgram("unstated_ball.nc", moves));
    unstated.toolRadius.reset();
    const auto refused = runAndWrite(unstated);
    ASSERT_FALSE(refused.has_value());
    EXPECT_NE(refused.error().message.find("such as (T1 D=8. CR=4.)"), std::string::npos)
        << refused.error().toString();
}

TEST(AwkwardPrograms, BNoiseAboveTheToleranceIsRefusedUnlessTheUserAllowsIt) {
    const CleanPass& clean = cleanPass();
    const auto machine = kinematics::defaultBladeMachine();
    JobSpec spec = rescheduleJob(
        writeProgram("b_noise_large.nc", gcodeText(clean.path, machine, clean.feedMmPerMin,
                                                   RotaryUnit::Degrees, 0.05)));
    expectRefused(spec, ErrorCode::Geometry, "--b-tolerance-deg");
    spec.check.tiltToleranceRad = units::degToRad(0.1);
    const auto allowed = runAndWrite(spec);
    ASSERT_TRUE(allowed.has_value()) << allowed.error().toString();
    EXPECT_TRUE(fs::exists(spec.outputProgram));
}

// Two revolutions in radians reach |A| = 12.6 > 2 pi, so the values alone look like degrees: read
// so, the ball centres turn by 12.6 deg about the rotary axis, not two turns.
TEST(AwkwardPrograms, RadiansReadAsDegreesAreRefusedAsNotHelicalAndReadWithTheAngleUnit) {
    const CleanPass& clean = cleanPass();
    const auto machine = kinematics::defaultBladeMachine();
    const auto cleanSpec = rescheduleJob(
        writeProgram("clean_for_radians.nc",
                     gcodeText(clean.path, machine, clean.feedMmPerMin, RotaryUnit::Degrees)));
    JobSpec spec = rescheduleJob(writeProgram(
        "radians.nc", gcodeText(clean.path, machine, clean.feedMmPerMin, RotaryUnit::Radians)));
    expectRefused(spec, ErrorCode::Geometry, "--angle-unit rad");
    spec.read.angleUnit = io::AngleUnit::Radians;
    const auto result = runAndWrite(spec);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    const auto reference = runAndWrite(cleanSpec);
    ASSERT_TRUE(reference.has_value()) << reference.error().toString();
    // Degrees at 4 decimals against radians at 7: the programs agree to 1e-4 deg.
    expectSameSchedule(*result, *reference, units::degToRad(0.01));
    const std::string written = readTextFile(spec.outputProgram).value_or("");
    EXPECT_NE(written.find(" B0.08726"), std::string::npos) << "B not written in radians";
}

// The analysis reports figures of what it read: it says the pass does not turn and why, instead
// of reporting radians read as degrees silently.
TEST(AwkwardPrograms, AnAnalysisOfRadiansReadAsDegreesWarnsThatThePassDoesNotTurn) {
    const CleanPass& clean = cleanPass();
    const auto machine = kinematics::defaultBladeMachine();
    JobSpec spec = rescheduleJob(
        writeProgram("radians_analysis.nc",
                     gcodeText(clean.path, machine, clean.feedMmPerMin, RotaryUnit::Radians)));
    spec.outputProgram.clear();
    spec.reschedule = false;
    const auto result = runQuietly(spec);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    const auto warning =
        std::find_if(result->warnings.begin(), result->warnings.end(), [](const std::string& text) {
            return text.find("not a helical blade pass") != std::string::npos;
        });
    ASSERT_NE(warning, result->warnings.end());
    EXPECT_NE(warning->find("give --angle-unit rad"), std::string::npos) << *warning;
    EXPECT_NE(warning->find("the analysis's figures take the program as read"), std::string::npos)
        << *warning;
    EXPECT_EQ(warning->find("Nothing was written"), std::string::npos) << *warning;
}

// With --angle-unit rad given, the advice is not to give it again.
TEST(AwkwardPrograms, APassThatDoesNotTurnWithRadiansGivenIsNotToldToGiveRadians) {
    const CleanPass& clean = cleanPass();
    const auto machine = kinematics::defaultBladeMachine();
    toolpath::Toolpath shortPass = clean.path;
    shortPass.records.resize(shortPass.records.size() / 20);
    JobSpec spec = rescheduleJob(
        writeProgram("short_radians.nc",
                     gcodeText(shortPass, machine, clean.feedMmPerMin, RotaryUnit::Radians)));
    spec.read.angleUnit = io::AngleUnit::Radians;
    const auto result = runQuietly(spec);
    ASSERT_FALSE(result.has_value());
    EXPECT_NE(result.error().message.find("not a helical blade pass"), std::string::npos)
        << result.error().message;
    EXPECT_NE(result.error().message.find("--angle-unit rad read the A and B words as radians"),
              std::string::npos)
        << result.error().message;
    EXPECT_EQ(result.error().message.find("give --angle-unit rad"), std::string::npos)
        << result.error().message;
}

TEST(AwkwardPrograms, CrlfAndContinuationLinesRescheduleLikeTheCleanProgram) {
    const CleanPass& clean = cleanPass();
    AptStyle style;
    style.lineEnd = LineEnd::Crlf;
    style.continuations = true;
    const auto spec = rescheduleJob(writeProgram(
        "crlf_continued.cl", aptText(clean.path, clean.toolRadius, clean.feedMmPerMin, style)));
    const auto result = runAndWrite(spec);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    expectSameSchedule(*result, cleanAptResult(), 1e-12);
}

// CL data that is only GOTO lines (no FEDRAT, no CUTTER) needs the feed and the radius from the
// user; with them it is the clean program.
TEST(AwkwardPrograms, HeaderlessGotoListNeedsTheFeedAndThenReschedulesLikeTheCleanProgram) {
    const CleanPass& clean = cleanPass();
    AptStyle style;
    style.header = false;
    JobSpec spec = rescheduleJob(writeProgram(
        "headerless.cl", aptText(clean.path, clean.toolRadius, clean.feedMmPerMin, style)));
    expectRefused(spec, ErrorCode::Parse, "--feed");
    spec.read.feedMmPerS = units::perMinuteToPerSecond(clean.feedMmPerMin);
    const auto result = runAndWrite(spec);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    expectSameSchedule(*result, cleanAptResult(), 1e-12);
}

// x y z i j k tables, whitespace or CSV, with or without a header line, are read by content
// whatever their extension, and re-schedule like the clean program once the feed is given.
TEST(AwkwardPrograms, PointTablesRescheduleLikeTheCleanProgram) {
    const CleanPass& clean = cleanPass();
    struct Variant {
        std::string name;
        char separator;
        bool header;
    };
    for (const Variant& variant :
         {Variant{"table.txt", ' ', false}, Variant{"table.csv", ',', true},
          Variant{"table_named_as.nc", ';', true}}) {
        JobSpec spec = rescheduleJob(
            writeProgram(variant.name, tableText(clean.path, variant.separator, variant.header)));
        expectRefused(spec, ErrorCode::Parse, "--feed");
        spec.read.feedMmPerS = units::perMinuteToPerSecond(clean.feedMmPerMin);
        const auto result = runAndWrite(spec);
        ASSERT_TRUE(result.has_value()) << variant.name << ": " << result.error().toString();
        expectSameSchedule(*result, cleanAptResult(), 1e-12);
        // The written table reads back to the schedule's own tool axes.
        const std::string written = readTextFile(spec.outputProgram).value_or("");
        const auto reread = io::table::parsePointTable(written, "written", spec.read);
        ASSERT_TRUE(reread.has_value()) << reread.error().toString();
        ASSERT_EQ(reread->path.records.size(), clean.path.records.size());
    }
}

} // namespace
} // namespace bladeaxis::job::test
