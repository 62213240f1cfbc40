// CL data as CAM systems write it beyond plain GOTO lists: local frames (MSYS), incremental moves
// (GODLTA), start points (FROM), bare GOTO files without FEDRAT, and statements BladeAxis does not
// follow (circles, APT source motion), which are refused with their line.

#include "core/io/cl/apt_reader.h"
#include "core/io/cl/apt_writer.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bladeaxis::io::cl {
namespace {

constexpr double kEps = 1e-9;

Result<AptProgram> parse(std::string_view text, const ReadOptions& options = {}) {
    return parseApt(text, "shop.cl", options);
}

ReadOptions withFeed(double mmPerMin) {
    ReadOptions options;
    options.feedMmPerS = mmPerMin / 60.0;
    return options;
}

TEST(AptShopPrograms, GotoNumbersAfterMsysAreInTheLocalFrame) {
    // Local X along world Y, local Y along world -X, origin at (10, 20, 30).
    const auto local = parse("UNITS/MM\nFEDRAT/MMPM,1000\nMSYS/10,20,30,0,1,0,-1,0,0\n"
                             "GOTO/1,2,3,1,0,0\nGOTO/4,5,6\nFINI\n");
    ASSERT_TRUE(local.has_value()) << local.error().toString();
    const auto& records = local->path.records;
    ASSERT_EQ(records.size(), 2u);
    EXPECT_LT((records[0].tip - Vec3(10 - 2, 20 + 1, 30 + 3)).norm(), kEps);
    EXPECT_LT((records[0].axis - Vec3(0, 1, 0)).norm(), kEps);
    EXPECT_LT((records[1].tip - Vec3(10 - 5, 20 + 4, 30 + 6)).norm(), kEps);
    EXPECT_LT((records[1].axis - Vec3(0, 1, 0)).norm(), kEps) << "the modal axis is world";
}

TEST(AptShopPrograms, ARewriteUnderMsysWritesLocalNumbersThatReadBack) {
    const std::string text = "UNITS/MM\nFEDRAT/MMPM,1000\nMSYS/10,20,30,0,1,0,-1,0,0\n"
                             "MULTAX/ON\nGOTO/1.000,2.000,3.000,1.000000,0.000000,0.000000\nFINI\n";
    const auto program = parse(text);
    ASSERT_TRUE(program.has_value());
    auto records = program->path.records;
    records[0].tip += Vec3(0.5, 0.0, 0.25);
    records[0].axis = Vec3(0.0, 0.6, 0.8);
    const auto rewritten = rewriteApt(*program, records);
    ASSERT_TRUE(rewritten.has_value()) << rewritten.error().toString();
    EXPECT_NE(rewritten->find("GOTO/1.000,1.500,3.250,0.600000,0.000000,0.800000"),
              std::string::npos)
        << *rewritten;
    const auto back = parse(*rewritten);
    ASSERT_TRUE(back.has_value());
    EXPECT_LT((back->path.records[0].tip - records[0].tip).norm(), 1e-6);
    EXPECT_LT((back->path.records[0].axis - records[0].axis).norm(), 1e-6);
}

TEST(AptShopPrograms, GodltaMovesByAVectorOrAlongTheToolAxis) {
    const auto program = parse("FEDRAT/1000\nGOTO/1,2,3,0,0.6,0.8\nGODLTA/0,0,10\nGODLTA/5\n");
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    const auto& records = program->path.records;
    ASSERT_EQ(records.size(), 3u);
    EXPECT_LT((records[1].tip - Vec3(1, 2, 13)).norm(), kEps);
    EXPECT_LT((records[2].tip - Vec3(1, 5, 17)).norm(), kEps);
    EXPECT_EQ(records[2].line, 4);
}

TEST(AptShopPrograms, ARewrittenGodltaKeepsTheAbsolutePositionsOfTheRecords) {
    const auto program = parse("FEDRAT/1000\nGOTO/1.0,2.0,3.0\nGODLTA/0.0,0.0,10.0\nFINI\n");
    ASSERT_TRUE(program.has_value());
    auto records = program->path.records;
    records[0].tip.x() = 2.0; // the GOTO moves; the retract target stays where it was
    const auto rewritten = rewriteApt(*program, records);
    ASSERT_TRUE(rewritten.has_value()) << rewritten.error().toString();
    EXPECT_NE(rewritten->find("GODLTA/-1.0,0.0,10.0"), std::string::npos) << *rewritten;
    const auto back = parse(*rewritten);
    ASSERT_TRUE(back.has_value());
    EXPECT_LT((back->path.records[1].tip - records[1].tip).norm(), kEps);
}

TEST(AptShopPrograms, FromIsARapidStartPoint) {
    const auto program = parse("FROM/0,0,100\nFEDRAT/1000\nGOTO/1,2,3\n");
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    ASSERT_EQ(program->path.records.size(), 2u);
    EXPECT_EQ(program->path.records[0].motion, toolpath::MotionKind::Rapid);
    EXPECT_LT((program->path.records[0].tip - Vec3(0, 0, 100)).norm(), kEps);
}

TEST(AptShopPrograms, CirclesAndPartProgramMotionAreRefusedNamingTheLine) {
    for (const char* statement :
         {"CIRCLE/0,0,0,0,0,1,5", "GOFWD/(CIRCLE/0,0,0,5),TANTO,L1", "INDIRV/1,0,0", "GO/TO,PL1"}) {
        const auto program =
            parse(std::string("FEDRAT/1000\nGOTO/1,2,3\n") + statement + "\nGOTO/2,2,3\n");
        ASSERT_FALSE(program.has_value()) << statement;
        EXPECT_EQ(program.error().where.line, 3) << statement;
    }
    const auto circle = parse("FEDRAT/1000\nGOTO/1,2,3\nCIRCLE/0,0,0,0,0,1,5\nGOTO/2,2,3\n");
    EXPECT_NE(circle.error().message.find("post the program with linear moves"), std::string::npos);
}

TEST(AptShopPrograms, BareGotoListsReadWithTheFeedGiven) {
    const std::string bare = "GOTO/1,2,3,0,0,1\nGOTO/2,2,3,0,0,1\nGOTO/3,2,3,0,0,1\n";
    const auto fed = parse(bare, withFeed(1200.0));
    ASSERT_TRUE(fed.has_value()) << fed.error().toString();
    EXPECT_NEAR(fed->path.records[2].feed, 20.0, kEps);
}

TEST(AptShopPrograms, BareGotoListsWithoutAFeedGiveOneErrorNamingTheOption) {
    std::string bare;
    for (int i = 0; i < 25; ++i) {
        bare += "GOTO/" + std::to_string(i) + ",2,3,0,0,1\n";
    }
    const auto program = parse(bare);
    ASSERT_FALSE(program.has_value());
    EXPECT_TRUE(program.error().more.empty()) << program.error().toString();
    EXPECT_EQ(program.error().where.line, 1);
    EXPECT_NE(program.error().message.find("--feed"), std::string::npos);
}

} // namespace
} // namespace bladeaxis::io::cl
