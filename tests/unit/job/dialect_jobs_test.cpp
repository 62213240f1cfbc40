// One blade cut posted three ways (ISO, Sinumerik with TRAORI and A=DC(..), Heidenhain with
// M126), as tests/data/dialects/make_dialect_programs.py writes them: the job reads each in its
// own dialect, finds the same motion, re-schedules it the same way and writes the program back
// in the input's own words, every line without a move byte for byte.

#include "core/base/file_io.h"
#include "core/io/program.h"
#include "core/kinematics/machine_model.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>

#include "demo_job.h"

namespace bladeaxis::job::test {
namespace {

namespace fs = std::filesystem;

fs::path data(const std::string& relative) {
    return fs::path(BLADEAXIS_TEST_DATA_DIR) / relative;
}

const JobResult& jobOn(const std::string& relative) {
    static std::map<std::string, Result<JobResult>> runs;
    auto found = runs.find(relative);
    if (found == runs.end()) {
        JobSpec spec;
        spec.program = data(relative);
        spec.toolRadius = 8.0;
        found = runs.emplace(relative, runQuietly(spec)).first;
    }
    EXPECT_TRUE(found->second.has_value())
        << relative << ": " << (found->second ? "" : found->second.error().toString());
    return *found->second;
}

constexpr const char* kIso = "programs/naca_weak_3rev.nc";
constexpr const char* kSinumerik = "dialects/naca_weak_3rev.mpf";
constexpr const char* kHeidenhain = "dialects/naca_weak_3rev.h";

double peakA(const analysis::AxisProfile& profile) {
    return profile.axes[static_cast<int>(kinematics::AxisId::A)].peakAcceleration;
}

TEST(DialectJobs, TheSameCutInThreeDialectsGivesTheSameFigures) {
    const JobResult& iso = jobOn(kIso);
    for (const char* other : {kSinumerik, kHeidenhain}) {
        const JobResult& result = jobOn(other);
        ASSERT_TRUE(result.rescheduled.has_value()) << other;
        EXPECT_EQ(result.pass.count, iso.pass.count) << other;
        EXPECT_EQ(result.original.aReversals.count, iso.original.aReversals.count) << other;
        // The Sinumerik copy rounds the workpiece-frame tips to 0.1 um: its figures move a
        // little; the Heidenhain copy writes the ISO numbers.
        const double tolerance = std::string(other) == kHeidenhain ? 1e-9 : 0.03;
        EXPECT_NEAR(peakA(result.original) / peakA(iso.original), 1.0, tolerance) << other;
        EXPECT_NEAR(peakA(result.rescheduled->profile) / peakA(iso.rescheduled->profile), 1.0,
                    tolerance)
            << other;
        EXPECT_LT(result.rescheduled->maxCentreDeviationMm, 1e-3) << other;
    }
}

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        lines.push_back(line);
    }
    return lines;
}

// Every line that is not a move of the cutting pass is copied unchanged, and the moves keep
// their dialect's words.
void expectOwnWordsKept(const char* relative, const std::string& moveMarker) {
    const JobResult& result = jobOn(relative);
    ASSERT_TRUE(result.rescheduled.has_value());
    // The job has released the input's text after the rewrite: compare with the file.
    const std::vector<std::string> before = linesOf(readTextFile(data(relative)).value_or(""));
    const std::vector<std::string> after = linesOf(result.rescheduled->programText);
    ASSERT_EQ(before.size(), after.size()) << relative;
    std::size_t changed = 0;
    for (std::size_t i = 0; i < before.size(); ++i) {
        if (before[i] != after[i]) {
            ++changed;
            EXPECT_NE(before[i].find(moveMarker), std::string::npos) << relative << ":" << i + 1;
            EXPECT_NE(after[i].find(moveMarker), std::string::npos) << relative << ":" << i + 1;
        }
    }
    EXPECT_GT(changed, result.pass.count / 2) << relative;
}

TEST(DialectJobs, SinumerikMovesKeepTheirDirectWordsAndNothingElseChanges) {
    expectOwnWordsKept(kSinumerik, "A=DC(");
}

TEST(DialectJobs, HeidenhainMovesKeepTheirLBlocksAndNothingElseChanges) {
    expectOwnWordsKept(kHeidenhain, " L X");
}

TEST(DialectJobs, HeidenhainTakesTheBallRadiusFromToolDef) {
    JobSpec spec;
    spec.program = data(kHeidenhain);
    const auto result = runQuietly(spec);
    ASSERT_TRUE(result) << result.error().toString();
    ASSERT_TRUE(result->toolRadius.has_value());
    EXPECT_DOUBLE_EQ(*result->toolRadius, 8.0);
}

TEST(DialectJobs, ToolTipProgrammingSwitchedInsideThePassIsRefused) {
    JobSpec spec;
    spec.program = "mixed.mpf";
    spec.programText = "N10 G71 G90 G94\nN20 G1 X0 Y0 Z5 A=DC(10) B5 F3000\nN30 X1 A=DC(11)\n"
                       "N40 TRAORI\nN50 X2 A=DC(12)\nN60 X3 A=DC(13)\nN70 M30\n";
    spec.toolRadius = 4.0;
    const auto result = runQuietly(spec);
    ASSERT_FALSE(result.has_value());
    EXPECT_NE(result.error().message.find("TRAORI"), std::string::npos);
    EXPECT_EQ(result.error().where.line, 2);
}

} // namespace
} // namespace bladeaxis::job::test
