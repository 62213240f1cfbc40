#include "core/blade/blade.h"
#include "core/blade/helical_path.h"
#include "core/blade/section_table.h"
#include "tests/unit/blade/blade_distance.h"

#include <gtest/gtest.h>

#include <string>

namespace bladeaxis::blade {
namespace {

const std::string kTableFile =
    std::string(BLADEAXIS_TEST_DATA_DIR) + "/blade/naca0015_three_stations.txt";

Error parseError(std::string_view text) {
    const Result<SectionTable> table = readSectionTable(text, "t.txt");
    EXPECT_FALSE(table.has_value());
    return table ? Error{} : table.error();
}

TEST(SectionTable, ReadsStationsFromTheDataFile) {
    const Result<SectionTable> table = readSectionTableFile(kTableFile);
    ASSERT_TRUE(table.has_value()) << table.error().toString();
    ASSERT_EQ(table->stations.size(), 3u);
    EXPECT_DOUBLE_EQ(table->stations[1].x, 10.0);
    EXPECT_EQ(table->stations[0].points.size(), 48u);
    EXPECT_EQ(table->stations[0].line, 4);
}

TEST(SectionTable, NormalisesClockwiseSectionsAndDropsTheClosingPoint) {
    const Result<SectionTable> table = readSectionTable(
        "station 0\n0 0\n0 1\n1 1\n1 0\n0 0\nstation 1 # comment\n0 0\n1 0\n1 1\n", "t.txt");
    ASSERT_TRUE(table.has_value()) << table.error().toString();
    EXPECT_EQ(table->stations[0].points.size(), 4u);
    EXPECT_GT(signedArea(table->stations[0].points), 0.0);
    EXPECT_GT(signedArea(table->stations[1].points), 0.0);
}

TEST(SectionTable, MissingNumberIsReportedWithFileAndLine) {
    const Error error = parseError("station 0\n0 0\n1 0\n1\n0 1\nstation 1\n0 0\n1 0\n0 1\n");
    EXPECT_EQ(error.code, ErrorCode::Parse);
    EXPECT_EQ(error.where.toString(), "t.txt:4");
    EXPECT_NE(error.message.find("2 numbers"), std::string::npos);
}

TEST(SectionTable, StationWithTwoPointsIsReportedAtItsHeader) {
    const Error error =
        parseError("# two points only\nstation 0\n0 0\n1 0\nstation 1\n0 0\n1 0\n0 1\n");
    EXPECT_EQ(error.where.line, 2);
    EXPECT_NE(error.message.find("at least 3"), std::string::npos);
}

TEST(SectionTable, NanIsNotANumber) {
    const Error error = parseError("station 0\n0 0\n1 nan\n0 1\nstation 1\n0 0\n1 0\n0 1\n");
    EXPECT_EQ(error.where.line, 3);
    EXPECT_NE(error.message.find("'nan'"), std::string::npos);
}

TEST(SectionTable, StationsMustIncrease) {
    const Error error = parseError("station 1\n0 0\n1 0\n0 1\nstation 1\n0 0\n1 0\n0 1\n");
    EXPECT_EQ(error.where.line, 5);
    EXPECT_NE(error.message.find("greater than the previous"), std::string::npos);
}

TEST(SectionTable, PointBeforeAnyStationAndLaterErrorsAreAllReported) {
    const Error error =
        parseError("0 0\nstation 0\n0 0\n1 x\n0 1\n1 1\nstation -1\n0 0\n1 0\n0 1\n");
    EXPECT_EQ(error.where.line, 1);
    ASSERT_EQ(error.more.size(), 2u);
    EXPECT_EQ(error.more[0].where.line, 4);
    EXPECT_EQ(error.more[1].where.line, 7);
}

TEST(SectionTable, MissingFileIsFileNotFound) {
    const Result<SectionTable> table = readSectionTableFile("/nonexistent/blade/table.txt");
    ASSERT_FALSE(table.has_value());
    EXPECT_EQ(table.error().code, ErrorCode::FileNotFound);
}

TEST(SectionTable, TableBladeGivesAHelicalPathOnItsOffsetSurface) {
    const Result<SectionTable> table = readSectionTableFile(kTableFile);
    ASSERT_TRUE(table.has_value());
    BladeSpec spec;
    spec.profile = *table;
    spec.pointsPerSide = 150;
    const Result<Blade> blade = Blade::create(spec);
    ASSERT_TRUE(blade.has_value()) << blade.error().toString();
    HelicalPathSpec path;
    path.toolRadius = 4.0;
    path.pitch = 2.0;
    path.revolutions = 4;
    path.xStart = 3.0;
    const Result<GeneratedPath> generated = generateHelicalPath(*blade, path);
    ASSERT_TRUE(generated.has_value()) << generated.error().toString();
    ASSERT_GT(generated->centre.size(), 100u);
    for (std::size_t i = 0; i < generated->centre.size(); i += 5) {
        const Vec3& p = generated->contact[i];
        EXPECT_NEAR(distanceToCurve(p.tail<2>(), blade->sectionAt(p.x())), 0.0, 1e-9);
        EXPECT_NEAR((generated->centre[i] - p).norm(), 4.0, 1e-9);
    }
    // The surface is linear between stations; the ball, offset along its exact normal, touches
    // it (the kink at the station x = 10 mm is convex enough not to reach into the ball).
    for (std::size_t i = 0; i < generated->centre.size(); i += 23) {
        EXPECT_NEAR(testing::distanceToBlade(*blade, generated->centre[i], 5.0), 4.0, 2e-3) << i;
    }
    EXPECT_EQ(generated->revolution.back(), 3);
}

} // namespace
} // namespace bladeaxis::blade
