// Point tables: columns by header or position, blanks/commas/semicolons, feed from a column or
// the options, every malformed line named; the rewriter changes only the numbers that moved.

#include "core/base/units.h"
#include "core/io/table/point_table.h"

#include <gtest/gtest.h>

namespace bladeaxis::io::table {
namespace {

constexpr double kEps = 1e-12;

ReadOptions withFeed(double mmPerMin) {
    ReadOptions options;
    options.feedMmPerS = units::perMinuteToPerSecond(mmPerMin);
    return options;
}

TEST(PointTable, SixNumbersPerLineAreTipAndToolAxisWithTheFeedFromTheOptions) {
    const auto program = parsePointTable("1 2 3 0 0 1\n4 5 6 0 0.6 0.8\n", "t.txt", withFeed(600));
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    ASSERT_EQ(program->path.records.size(), 2u);
    EXPECT_NEAR((program->path.records[1].tip - Vec3(4, 5, 6)).norm(), 0.0, kEps);
    EXPECT_NEAR((program->path.records[1].axis - Vec3(0, 0.6, 0.8)).norm(), 0.0, kEps);
    EXPECT_NEAR(program->path.records[0].feed, 10.0, kEps);
    EXPECT_EQ(program->path.records[1].line, 2);
    EXPECT_EQ(program->path.format, toolpath::SourceFormat::Table);
}

TEST(PointTable, AHeaderLineNamesColumnsInAnyOrderAndAFeedColumnInMmPerMinute) {
    const auto program =
        parsePointTable("# exported\nI;J;K;X;Y;Z;F;T\n0;0;2;1;2;3;1200;7\n", "t.csv");
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    ASSERT_EQ(program->path.records.size(), 1u);
    EXPECT_NEAR((program->path.records[0].tip - Vec3(1, 2, 3)).norm(), 0.0, kEps);
    EXPECT_NEAR((program->path.records[0].axis - Vec3(0, 0, 1)).norm(), 0.0, kEps);
    EXPECT_NEAR(program->path.records[0].feed, 20.0, kEps);
    EXPECT_EQ(program->path.records[0].line, 3);
}

TEST(PointTable, CommaSeparatedWithCrlfLineEndsReadsLikeBlanks) {
    const auto blanks = parsePointTable("1 2 3 0 0 1\n", "a", withFeed(600));
    const auto commas = parsePointTable("1, 2, 3, 0, 0, 1\r\n", "b", withFeed(600));
    ASSERT_TRUE(blanks.has_value() && commas.has_value());
    EXPECT_NEAR((blanks->path.records[0].tip - commas->path.records[0].tip).norm(), 0.0, kEps);
}

TEST(PointTable, OtherColumnCountsNeedTheColumnsOption) {
    const auto refused = parsePointTable("1 2 3 0 0 1 900\n", "t.txt");
    ASSERT_FALSE(refused.has_value());
    EXPECT_NE(refused.error().message.find("--columns"), std::string::npos);
    EXPECT_EQ(refused.error().where.line, 1);
    ReadOptions options;
    options.tableColumns = "x,y,z,i,j,k,f";
    const auto read = parsePointTable("1 2 3 0 0 1 900\n", "t.txt", options);
    ASSERT_TRUE(read.has_value()) << read.error().toString();
    EXPECT_NEAR(read->path.records[0].feed, 15.0, kEps);
}

TEST(PointTable, TheColumnsOptionOverridesAHeaderLineItDoesNotKnowWithAWarning) {
    const std::string text = "x y z nx ny nz\n1 2 3 0 0.6 0.8\n";
    EXPECT_FALSE(parsePointTable(text, "t.txt", withFeed(600)).has_value());
    ReadOptions options = withFeed(600);
    options.tableColumns = "x,y,z,i,j,k";
    const auto read = parsePointTable(text, "t.txt", options);
    ASSERT_TRUE(read.has_value()) << read.error().toString();
    ASSERT_EQ(read->path.records.size(), 1u);
    EXPECT_NEAR((read->path.records[0].axis - Vec3(0, 0.6, 0.8)).norm(), 0.0, kEps);
    EXPECT_EQ(read->path.records[0].line, 2);
    ASSERT_EQ(read->path.warnings.size(), 1u);
    EXPECT_NE(read->path.warnings[0].find("t.txt:1: the header line is replaced by --columns"),
              std::string::npos)
        << read->path.warnings[0];
}

TEST(PointTable, NoFeedIsOneErrorNamingTheOption) {
    const auto refused = parsePointTable("1 2 3 0 0 1\n2 2 3 0 0 1\n3 2 3 0 0 1\n", "t.txt");
    ASSERT_FALSE(refused.has_value());
    EXPECT_NE(refused.error().message.find("--feed"), std::string::npos);
    EXPECT_TRUE(refused.error().more.empty()) << refused.error().toString();
}

TEST(PointTable, MalformedLinesAreNamedWithLineAndColumn) {
    struct Case {
        std::string text;
        int line;
        std::string expected;
    };
    for (const Case& c : {Case{"x y z i j\n1 2 3 0 0\n", 1, "do not include 'k'"},
                          Case{"1 2 3 0 0 1\n1 2 3 0 0\n", 2, "expected 6 numbers, got 5"},
                          Case{"1 2 3 0 0 1\n1 2 nan 0 0 1\n", 2, "finite number"},
                          Case{"1 2 3 0 0 1\n1 2 3 0 0 0\n", 2, "zero length"},
                          Case{"# only a comment\n", 1, "no data line"}}) {
        const auto refused = parsePointTable(c.text, "t.txt", withFeed(600));
        ASSERT_FALSE(refused.has_value()) << c.text;
        EXPECT_EQ(refused.error().code, ErrorCode::Parse);
        EXPECT_EQ(refused.error().where.line, c.line) << refused.error().toString();
        EXPECT_NE(refused.error().message.find(c.expected), std::string::npos)
            << refused.error().toString();
    }
}

TEST(PointTable, RewriteChangesOnlyMovedNumbersAndKeepsTheirDecimals) {
    const std::string text = "# head\ni j k x y z\n0.000 0.000 1.000 1.50 2.50 3.50\n"
                             "0.000 0.000 1.000 4.50 5.50 6.50\n";
    const auto program = parsePointTable(text, "t.txt", withFeed(600));
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    auto records = program->path.records;
    records[1].axis = Vec3(0.0, 0.6, 0.8);
    const auto written = rewritePointTable(*program, records);
    ASSERT_TRUE(written.has_value()) << written.error().toString();
    EXPECT_EQ(*written, "# head\ni j k x y z\n0.000 0.000 1.000 1.50 2.50 3.50\n"
                        "0.000 0.600 0.800 4.50 5.50 6.50\n");
}

TEST(PointTable, RewriteOfUnchangedRecordsIsByteForByteTheInput) {
    const std::string text = "x,y,z,i,j,k\r\n1e-3,2,3.25,0,0,1\r\n";
    const auto program = parsePointTable(text, "t.csv", withFeed(600));
    ASSERT_TRUE(program.has_value());
    const auto written = rewritePointTable(*program, program->path.records);
    ASSERT_TRUE(written.has_value());
    EXPECT_EQ(*written, text);
}

TEST(PointTable, LooksLikeATableOnlyWhenItsLinesAreNumbers) {
    EXPECT_TRUE(looksLikePointTable("x y z i j k\n1 2 3 0 0 1\n"));
    EXPECT_TRUE(looksLikePointTable("# c\n1,2,3,0,0,1\n"));
    EXPECT_FALSE(looksLikePointTable("N10 G1 X1 Y2 Z3\n"));
    EXPECT_FALSE(looksLikePointTable("GOTO/1,2,3\n"));
    EXPECT_FALSE(looksLikePointTable("x y z\nfoo bar baz\n1 2 3\n"));
}

} // namespace
} // namespace bladeaxis::io::table
