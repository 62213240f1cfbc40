// Programs are recognised by content; the extension only breaks ties and a contradicting one is
// reported. Text in no known format and binary files get one error naming what was expected.

#include "core/io/program.h"
#include "core/kinematics/machine_model.h"

#include <gtest/gtest.h>

namespace bladeaxis::io {
namespace {

TEST(FormatDetection, ContentDecidesTheFormat) {
    EXPECT_EQ(detectFormat("a.nc", "%\nO1000\nN10 G1 X1. Y2. Z3. A4. B5.\n")->format,
              ProgramFormat::Gcode);
    EXPECT_EQ(detectFormat("a.cl", "$$ cam\nGOTO/1,2,3,0,0,1\n")->format, ProgramFormat::Apt);
    EXPECT_EQ(detectFormat("a.csv", "x,y,z,i,j,k\n1,2,3,0,0,1\n")->format, ProgramFormat::Table);
}

TEST(FormatDetection, AnExtensionThatContradictsTheContentIsAWarningNotAnError) {
    const auto probed = detectFormat("points.nc", "1 2 3 0 0 1\n2 2 3 0 0 1\n");
    ASSERT_TRUE(probed.has_value());
    EXPECT_EQ(probed->format, ProgramFormat::Table);
    ASSERT_TRUE(probed->warning.has_value());
    EXPECT_NE(probed->warning->find("read as"), std::string::npos) << *probed->warning;
    const auto apt = detectFormat("cl.txt", "GOTO/1,2,3,0,0,1\nGOTO/2,2,3,0,0,1\n");
    ASSERT_TRUE(apt.has_value());
    EXPECT_EQ(apt->format, ProgramFormat::Apt);
}

TEST(FormatDetection, TextInNoKnownFormatIsOneErrorNamingTheLineAndWhatWasExpected) {
    const auto probed = detectFormat("notes.nc", "(header)\nDear customer,\nplease find\n");
    ASSERT_FALSE(probed.has_value());
    EXPECT_EQ(probed.error().code, ErrorCode::Parse);
    EXPECT_NE(probed.error().message.find("format not recognised"), std::string::npos);
    EXPECT_NE(probed.error().message.find("point table"), std::string::npos);
    EXPECT_EQ(probed.error().where.line, 2);
    EXPECT_TRUE(probed.error().more.empty());
}

TEST(FormatDetection, BinaryDataIsNotATextProgram) {
    const std::string zipped("PK\x03\x04\x14\x00\x00\x00", 8);
    const auto probed = detectFormat("part.nc", zipped);
    ASSERT_FALSE(probed.has_value());
    EXPECT_NE(probed.error().message.find("not a text program"), std::string::npos);
}

TEST(FormatDetection, ATableNamedLikeGcodeIsReadAsATableWithTheWarningFirst) {
    ReadOptions options;
    options.feedMmPerS = 10.0;
    const auto program = readProgramText("1 2 3 0 0 1\n2 2 3 0 0 1\n", "points.nc",
                                         kinematics::defaultBladeMachine(), options);
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    EXPECT_EQ(program->format(), ProgramFormat::Table);
    ASSERT_FALSE(program->path().warnings.empty());
    EXPECT_NE(program->path().warnings.front().find("extension"), std::string::npos);
}

} // namespace
} // namespace bladeaxis::io
