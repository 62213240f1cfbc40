// Inputs a careless or hostile user gives: an absurd tool radius, file names that are not UTF-8.
// Each is refused with a clear message or handled, never an internal error or a partial output.

#include "core/base/file_io.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "awkward_programs.h"
#include "demo_job.h"

namespace bladeaxis::job::test {
namespace {

namespace fs = std::filesystem;

fs::path freshFolder(const std::string& name) {
    const fs::path folder = fs::temp_directory_path() / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

fs::path writeCleanProgram(const fs::path& path) {
    const CleanPass& clean = cleanPass();
    std::ofstream(path, std::ios::binary)
        << aptText(clean.path, clean.toolRadius, clean.feedMmPerMin);
    return path;
}

TEST(HostileInput, AToolRadiusNoBallEndCutterHasIsRefusedAsAnInvalidArgument) {
    const fs::path folder = freshFolder("bladeaxis_hostile_radius");
    JobSpec spec;
    spec.program = writeCleanProgram(folder / "blade.cl");
    spec.outputProgram = folder / "out.cl";
    for (const double radius : {1e12, 1e308, 0.0, -4.0}) {
        spec.toolRadius = radius;
        const auto result = runQuietly(spec);
        ASSERT_FALSE(result.has_value()) << radius;
        EXPECT_EQ(result.error().code, ErrorCode::InvalidArgument) << result.error().toString();
        EXPECT_NE(result.error().message.find("not a ball-end cutter"), std::string::npos);
        EXPECT_FALSE(fs::exists(spec.outputProgram));
    }
}

TEST(HostileInput, FileNamesThatAreNotUtf8AreReadAndNamedInTheReports) {
    const fs::path folder = freshFolder("bladeaxis_hostile_names");
    JobSpec spec;
    spec.program = writeCleanProgram(folder / "blade\xff.cl");
    spec.outputProgram = folder / "out\xfe.cl";
    spec.outputDir = folder / "report\xff";
    const auto result = runQuietly(spec);
    ASSERT_TRUE(result.has_value()) << result.error().toString();
    const auto written = writeJobOutputs(spec, *result);
    ASSERT_TRUE(written.has_value()) << written.error().toString();
    EXPECT_TRUE(fs::exists(spec.outputProgram));
    const std::string report = readTextFile(spec.outputDir / "report.json").value_or("");
    // The byte that is not UTF-8 is replaced in the JSON (U+FFFD), the rest of the name kept.
    EXPECT_NE(report.find("blade\xef\xbf\xbd.cl"), std::string::npos);
}

} // namespace
} // namespace bladeaxis::job::test
