// Programs are recognised by content; the extension only breaks ties and a contradicting one is
// reported. Text in no known format and binary files get one error naming what was expected.

#include "core/base/forward_text.h"
#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/io/nc/gcode_writer.h"
#include "core/io/program.h"
#include "core/kinematics/machine_model.h"
#include "tests/unit/io_nc/gcode_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

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

// CL data and point tables are parsed whole, then the token is looked at: a cancelled read
// ends Cancelled in every format.
TEST(OwnedText, ACancelledReadEndsCancelledInEveryFormat) {
    const auto machine = kinematics::defaultBladeMachine();
    ReadOptions options;
    options.feedMmPerS = 10.0;
    CancelToken cancel;
    cancel.requestCancel();
    for (const auto& [text, format] :
         {std::pair{std::string("FEDRAT/1000\nGOTO/1,2,3,0,0,1\nGOTO/2,2,3,0,0,1\n"),
                    ProgramFormat::Apt},
          std::pair{std::string("1 2 3 0 0 1\n2 2 3 0 0 1\n"), ProgramFormat::Table}}) {
        ASSERT_TRUE(parseOwnedProgram(text, "a", format, machine, options).has_value());
        const auto stopped = parseOwnedProgram(text, "a", format, machine, options,
                                               {.cancel = &cancel, .progress = {}});
        ASSERT_FALSE(stopped.has_value());
        EXPECT_EQ(stopped.error().code, ErrorCode::Cancelled);
    }
}

// A program read from text it keeps, and the re-read check's stream of a written program, must
// give the records a read of copied text gives, in every format; on a machine whose table turns
// about Y every read turns CL data into the engine's frame.
TEST(OwnedText, OwnedAndStreamedReadsGiveTheRecordsACopiedTextGives) {
    auto machine = kinematics::defaultBladeMachine();
    machine.layout = kinematics::Layout::TableBHeadA;
    const std::string gcode =
        "%\nG21 G90 G94\nG1 X1. Y2. Z3. A40. B5. F1000.\nG1 X2. A60.\nM30\n%\n";
    const std::string apt = "FEDRAT/1000\nGOTO/1,2,3,0,0,1\nGOTO/2,2,3,0,0,1\n";
    for (const auto& [text, format] :
         {std::pair{gcode, ProgramFormat::Gcode}, std::pair{apt, ProgramFormat::Apt}}) {
        auto copied = parseProgram(text, "a", format, machine);
        auto owned = parseOwnedProgram(std::string(text), "a", format, machine);
        ASSERT_TRUE(copied.has_value()) << copied.error().toString();
        ASSERT_TRUE(owned.has_value()) << owned.error().toString();
        ASSERT_EQ(copied->path().records.size(), owned->path().records.size());
        if (format == ProgramFormat::Apt) {
            EXPECT_EQ(copied->path().records[1].tip, machine.toEngineFrame(Vec3(2.0, 2.0, 3.0)));
        }
        for (std::size_t i = 0; i < owned->path().records.size(); ++i) {
            EXPECT_EQ(copied->path().records[i].tip, owned->path().records[i].tip);
            EXPECT_EQ(copied->path().records[i].axis, owned->path().records[i].axis);
        }
        std::vector<toolpath::ClRecord> streamed;
        const auto count =
            streamProgramRecords(text, "a", format, machine, {},
                                 [&](std::size_t first, std::span<const toolpath::ClRecord> run) {
                                     EXPECT_EQ(first, streamed.size());
                                     streamed.insert(streamed.end(), run.begin(), run.end());
                                     return Status{};
                                 });
        ASSERT_TRUE(count.has_value()) << count.error().toString();
        ASSERT_EQ(*count, copied->path().records.size());
        ASSERT_EQ(streamed.size(), copied->path().records.size());
        for (std::size_t i = 0; i < streamed.size(); ++i) {
            EXPECT_EQ(streamed[i].tip, copied->path().records[i].tip);
            EXPECT_EQ(streamed[i].axis, copied->path().records[i].axis);
            EXPECT_EQ(streamed[i].feed, copied->path().records[i].feed);
        }
        // A consumer's error ends the read and is what it returns, in every format.
        const auto stopped = streamProgramRecords(
            text, "a", format, machine, {}, [](std::size_t, std::span<const toolpath::ClRecord>) {
                return Status(makeError(ErrorCode::Cancelled, "stop"));
            });
        ASSERT_FALSE(stopped.has_value());
        EXPECT_EQ(stopped.error().code, ErrorCode::Cancelled);
    }
}

// Every format frees its text and per-record sources; the records (what every reader after a
// rewrite uses) stay exactly as they were.
TEST(ReleasedRewriteSources, LeaveTheRecordsAndFreeTheText) {
    const kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    const std::pair<const char*, const char*> programs[] = {
        {"a.nc", "%\nO1000\nG90 G94 F600\nN10 G1 X1. Y2. Z3. A40. B0.\nN20 X2. A50.\n%\n"},
        {"a.cl", "$$ cam\nFEDRAT/600\nGOTO/1,2,3,0,0,1\nGOTO/2,2,3,0,0,1\n"},
        {"a.csv", "x,y,z,i,j,k,f\n1,2,3,0,0,1,10\n2,2,3,0,0,1,10\n"},
    };
    for (const auto& [name, text] : programs) {
        auto program = readProgramText(text, name, machine);
        ASSERT_TRUE(program.has_value()) << name << ": " << program.error().toString();
        const std::size_t records = program->path().records.size();
        ASSERT_GT(records, 0u) << name;
        const toolpath::ClRecord last = program->path().records.back();
        program->releaseRewriteSources();
        EXPECT_TRUE(program->text().empty()) << name;
        ASSERT_EQ(program->path().records.size(), records) << name;
        EXPECT_EQ(program->path().records.back().tip, last.tip) << name;
        EXPECT_EQ(program->path().records.back().line, last.line) << name;
        EXPECT_EQ(programsToolTip(*program, 0, records), false) << name;
    }
}

// A program of `lines` feed blocks, about 45 bytes each, turning A by 0.01 deg per block.
std::string longProgram(std::size_t lines) {
    std::string text = "%\nO1000\nG21 G90 G94 F600\n";
    for (std::size_t i = 0; i < lines; ++i) {
        const double t = static_cast<double>(i);
        text += "N" + std::to_string(10 * (i + 1)) + " G1 X" + formatFixed(1e-3 * t, 3) + " Y" +
                formatFixed(20.0 * std::cos(1e-3 * t), 3) + " Z" +
                formatFixed(30.0 + 2.0 * std::sin(1e-3 * t), 3) + " A" + formatFixed(1e-2 * t, 3) +
                " B0.\n";
    }
    return text + "M30\n%\n";
}

// Every record's programmed axes with A turned by `degrees`: the new axes of a rewrite.
std::vector<kinematics::MachineAxes> axesTurnedBy(const LoadedProgram& program, double degrees) {
    std::vector<kinematics::MachineAxes> axes;
    for (const toolpath::ClRecord& record : program.path().records) {
        axes.push_back(*record.axes);
        axes.back().a += units::degToRad(degrees);
    }
    return axes;
}

// The ways a rewrite is told to stream, one at a time.
nc::RewriteStreams reportingTo(nc::RewrittenUpTo rewrittenUpTo) {
    nc::RewriteStreams streams;
    streams.rewrittenUpTo = std::move(rewrittenUpTo);
    return streams;
}
nc::RewriteStreams inPieces(nc::WrittenPiece writtenPiece,
                            std::optional<FileSnapshot> textFile = std::nullopt) {
    nc::RewriteStreams streams;
    streams.writtenPiece = std::move(writtenPiece);
    streams.textFile = std::move(textFile);
    return streams;
}
nc::RewriteStreams fromFile(std::optional<FileSnapshot> textFile) {
    nc::RewriteStreams streams;
    streams.textFile = std::move(textFile);
    return streams;
}

// A job gives back the input's text and block sources as the rewrite reads past them: the
// rewrite must never read them again, so the written text is the one a rewrite that is told
// nothing gives, and what it reports only grows and stays inside the program.
TEST(ReleasedRewriteSources, AGcodeRewriteThatGivesBackWhatItReadWritesTheSameText) {
    const kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    const std::string text = longProgram(200'000); // about 9 MB: reported twice at least
    const auto reference =
        io::parseProgram(text, "long.nc", ProgramFormat::Gcode, machine, nc::test::inDegrees());
    ASSERT_TRUE(reference.has_value()) << reference.error().toString();
    const auto& referenceGcode = std::get<nc::GcodeProgram>(reference->document);
    const auto pass = axesTurnedBy(*reference, 0.5); // every block's A word changes
    const auto told = nc::rewriteGcodePass(referenceGcode, 0, pass, machine);
    ASSERT_TRUE(told.has_value()) << told.error().toString();

    auto consumed =
        io::parseProgram(text, "long.nc", ProgramFormat::Gcode, machine, nc::test::inDegrees());
    ASSERT_TRUE(consumed.has_value());
    std::vector<std::pair<std::size_t, std::size_t>> reports;
    const auto givenBack =
        nc::rewriteGcodePass(std::get<nc::GcodeProgram>(consumed->document), 0, pass, machine,
                             reportingTo([&](std::size_t textEnd, std::size_t blockEnd) {
                                 reports.emplace_back(textEnd, blockEnd);
                                 consumed->releaseRewriteSourcesBefore(textEnd, blockEnd);
                             }));
    ASSERT_TRUE(givenBack.has_value()) << givenBack.error().toString();
    EXPECT_EQ(*givenBack, *told);
    ASSERT_GE(reports.size(), 2u);
    for (std::size_t i = 0; i < reports.size(); ++i) {
        EXPECT_LE(reports[i].first, text.size());
        EXPECT_LE(reports[i].second, pass.size());
        if (i > 0) {
            EXPECT_GT(reports[i].first, reports[i - 1].first);
            EXPECT_GT(reports[i].second, reports[i - 1].second);
        }
    }
    // The text after the last report is still the input's, byte for byte.
    const std::string& kept = consumed->text();
    ASSERT_EQ(kept.size(), text.size());
    EXPECT_EQ(kept.substr(reports.back().first), text.substr(reports.back().first));
}

// A job stages the written program in its output file as the rewrite goes: the pieces, in
// order, are the text a rewrite into memory gives, and a piece refused stops the rewrite.
TEST(RewriteInPieces, TheWrittenPiecesAreTheTextARewriteIntoMemoryGives) {
    const kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    const std::string text = longProgram(200'000);
    const auto program =
        io::parseProgram(text, "long.nc", ProgramFormat::Gcode, machine, nc::test::inDegrees());
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    const auto& gcode = std::get<nc::GcodeProgram>(program->document);
    const auto pass = axesTurnedBy(*program, 0.25);
    const auto whole = nc::rewriteGcodePass(gcode, 0, pass, machine);
    ASSERT_TRUE(whole.has_value()) << whole.error().toString();

    std::string joined;
    std::size_t pieces = 0;
    const auto streamed = nc::rewriteGcodePass(gcode, 0, pass, machine,
                                               inPieces([&](std::string_view piece) -> Status {
                                                   joined += piece;
                                                   ++pieces;
                                                   return {};
                                               }));
    ASSERT_TRUE(streamed.has_value()) << streamed.error().toString();
    EXPECT_TRUE(streamed->empty());
    EXPECT_GE(pieces, 3u);
    EXPECT_EQ(joined, *whole);

    const auto refused =
        nc::rewriteGcodePass(gcode, 0, pass, machine, inPieces([](std::string_view) {
                                 return makeError(ErrorCode::WriteFailed, "the disk is full");
                             }));
    ASSERT_FALSE(refused.has_value());
    EXPECT_EQ(refused.error().code, ErrorCode::WriteFailed);
}

// The batch front end drops the input's text once parsed and has the rewrite read it again from
// its file: the written text is the one a rewrite from memory gives, and a file written since
// it was read is refused rather than rewritten.
class RewriteFromTheFile : public ::testing::Test {
  protected:
    void SetUp() override {
        m_file = std::filesystem::temp_directory_path() /
                 ("bladeaxis_reread_" + std::to_string(::getpid()) + ".nc");
        m_text = longProgram(200'000); // several windows of the file
        std::ofstream(m_file, std::ios::binary) << m_text;
    }
    void TearDown() override { std::filesystem::remove(m_file); }

    std::filesystem::path m_file;
    std::string m_text;
};

TEST_F(RewriteFromTheFile, GivesTheTextARewriteFromMemoryGives) {
    const kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    auto program = io::loadProgram(m_file, machine, nc::test::inDegrees());
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    const auto pass = axesTurnedBy(*program, 0.25);
    const auto& gcode = std::get<nc::GcodeProgram>(program->document);
    const auto fromMemory = nc::rewriteGcodePass(gcode, 0, pass, machine);
    ASSERT_TRUE(fromMemory.has_value()) << fromMemory.error().toString();

    const auto snapshot = snapshotOf(m_file);
    ASSERT_TRUE(snapshot.has_value());
    program->dropTextKeptInItsFile(*snapshot);
    EXPECT_TRUE(program->text().empty());
    ASSERT_TRUE(program->textFile.has_value());
    const auto rereadText =
        nc::rewriteGcodePass(gcode, 0, pass, machine, fromFile(program->textFile));
    ASSERT_TRUE(rereadText.has_value()) << rereadText.error().toString();
    EXPECT_EQ(*rereadText, *fromMemory);

    std::string joined;
    const auto piecewise = nc::rewriteGcodePass(gcode, 0, pass, machine,
                                                inPieces(
                                                    [&](std::string_view piece) -> Status {
                                                        joined += piece;
                                                        return {};
                                                    },
                                                    program->textFile));
    ASSERT_TRUE(piecewise.has_value()) << piecewise.error().toString();
    EXPECT_EQ(joined, *fromMemory);
}

TEST_F(RewriteFromTheFile, RefusesAFileWrittenAgainSinceItWasRead) {
    const kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    auto program = io::loadProgram(m_file, machine, nc::test::inDegrees());
    ASSERT_TRUE(program.has_value()) << program.error().toString();
    program->dropTextKeptInItsFile(*snapshotOf(m_file));
    const auto pass = axesTurnedBy(*program, 0.0);
    // Another post of the same length: only the modification time tells it apart.
    std::string other = m_text;
    other[other.find("X")] = 'Y';
    std::filesystem::last_write_time(m_file, std::filesystem::last_write_time(m_file) +
                                                 std::chrono::seconds(1));
    std::ofstream(m_file, std::ios::binary | std::ios::in | std::ios::out) << other;
    const auto refused = nc::rewriteGcodePass(std::get<nc::GcodeProgram>(program->document), 0,
                                              pass, machine, fromFile(program->textFile));
    ASSERT_FALSE(refused.has_value());
    EXPECT_EQ(refused.error().code, ErrorCode::FileUnreadable);
    EXPECT_NE(refused.error().toString().find("changed while the job ran"), std::string::npos)
        << refused.error().toString();
}

} // namespace
} // namespace bladeaxis::io
