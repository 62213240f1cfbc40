#include "core/base/file_io.h"
#include "core/cad/cad_files.h"
#include "tests/unit/cad/cad_test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace bladeaxis::cad {
namespace {

namespace fs = std::filesystem;
using testing::cadData;
using testing::demoSurface;
using testing::scratchDir;

std::string fileText(const fs::path& path) {
    Result<std::string> text = readTextFile(path);
    return text ? *text : std::string();
}

void expectSameBox(const BoundingBox& a, const BoundingBox& b, double tolerance) {
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(a.min[k], b.min[k], tolerance) << k;
        EXPECT_NEAR(a.max[k], b.max[k], tolerance) << k;
    }
}

TEST(CadWrite, StepFileInMillimetresReadsBackToTheSameSurface) {
    const fs::path path = scratchDir() / "demo_blade.step";
    ASSERT_TRUE(writeCadFile(demoSurface(), path, CadFormat::Step).has_value());
    const std::string text = fileText(path);
    EXPECT_EQ(text.rfind("ISO-10303-21;", 0), 0u);
    EXPECT_NE(text.find("B_SPLINE_SURFACE"), std::string::npos);
    EXPECT_NE(text.find(".MILLI.,.METRE."), std::string::npos);
    EXPECT_FALSE(fs::exists(path.string() + ".tmp"));

    const Result<CadShape> read = readCadFile(path);
    ASSERT_TRUE(read.has_value()) << read.error().toString();
    EXPECT_EQ(read->faceCount(), 1);
    expectSameBox(read->bounds(), demoSurface().bounds(), 1e-3);
}

TEST(CadWrite, IgesFileInMillimetresReadsBackToTheSameSurface) {
    const fs::path path = scratchDir() / "demo_blade.igs";
    ASSERT_TRUE(writeCadFile(demoSurface(), path, CadFormat::Iges).has_value());
    const std::string text = fileText(path);
    ASSERT_GT(text.size(), 80u);
    EXPECT_EQ(text[72], 'S'); // start section in column 73
    EXPECT_NE(text.find("2HMM"), std::string::npos);

    const Result<CadShape> read = readCadFile(path);
    ASSERT_TRUE(read.has_value()) << read.error().toString();
    EXPECT_GE(read->faceCount(), 1);
    expectSameBox(read->bounds(), demoSurface().bounds(), 1e-3);
}

// A model written in inches declares the inch and holds coordinates 25.4 times smaller; the
// reader scales them back to mm.
TEST(CadWrite, InchFilesDeclareTheUnitAndReadBackInMillimetres) {
    const fs::path dir = scratchDir();
    const fs::path step = dir / "blade_inch.step";
    const fs::path iges = dir / "blade_inch.igs";
    ASSERT_TRUE(writeCadFile(demoSurface(), step, CadFormat::Step, LengthUnit::Inch));
    ASSERT_TRUE(writeCadFile(demoSurface(), iges, CadFormat::Iges, LengthUnit::Inch));
    EXPECT_NE(fileText(step).find("'INCH'"), std::string::npos);
    EXPECT_NE(fileText(iges).find("4HINCH"), std::string::npos);
    for (const fs::path& path : {step, iges}) {
        const Result<CadShape> read = readCadFile(path);
        ASSERT_TRUE(read.has_value()) << read.error().toString();
        expectSameBox(read->bounds(), demoSurface().bounds(), 1e-3);
    }
}

TEST(CadWrite, RefusesAnEmptyShapeAndAnUnwritablePath) {
    const fs::path dir = scratchDir();
    const Status empty = writeCadFile(CadShape(), dir / "empty.step", CadFormat::Step);
    ASSERT_FALSE(empty.has_value());
    EXPECT_EQ(empty.error().code, ErrorCode::InvalidArgument);
    const Status missingDir =
        writeCadFile(demoSurface(), dir / "no" / "such" / "dir.step", CadFormat::Step);
    ASSERT_FALSE(missingDir.has_value());
    EXPECT_EQ(missingDir.error().code, ErrorCode::WriteFailed);
    EXPECT_NE(missingDir.error().toString().find("dir.step"), std::string::npos);
}

} // namespace
} // namespace bladeaxis::cad
