// A streamed read (streamGcodeRecords) must see exactly the records a whole parse gives, in the
// same order, and refuse exactly what a whole parse refuses: the re-read check of a written
// program relies on it instead of parsing the program a second time.

#include "core/io/nc/gcode_reader.h"
#include "tests/unit/io_nc/gcode_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace bladeaxis::io::nc {
namespace {

using toolpath::ClRecord;

// A helical pass of `moves` feed blocks, long enough to span several runs of a streamed read.
// It switches to inverse time (G93) halfway, where a record's feed depends on the tip of the
// record before it, so a run boundary inside that part must not lose the previous tip.
std::string helicalProgram(int moves) {
    std::string text = "%\nO1000 (ANGLES IN DEGREES)\nG90 G94 G21\nG0 X0. Y0. Z80. A0. B12.\n";
    for (int i = 0; i < moves; ++i) {
        if (i == moves / 2) {
            text += "G93\n";
        }
        const double a = 0.37 * i;
        const double y = 40.0 * std::cos(a * 3.14159265358979 / 180.0);
        const double z = 40.0 * std::sin(a * 3.14159265358979 / 180.0);
        text += "G1 X" + std::to_string(0.01 * i) + " Y" + std::to_string(y) + " Z" +
                std::to_string(z) + " A" + std::to_string(a) +
                (i >= moves / 2 ? " F" + std::to_string(500 + i % 7) : " F1200.") + "\n";
    }
    text += "M30\n%\n";
    return text;
}

struct StreamedRecords {
    std::vector<ClRecord> records;
    std::vector<std::size_t> runSizes;
    bool contiguous = true;
};

Result<std::size_t> stream(std::string_view text, StreamedRecords& seen) {
    return streamGcodeRecords(text, "t.nc", kinematics::defaultBladeMachine(), {},
                              [&](std::size_t first, std::span<const ClRecord> run) {
                                  seen.contiguous = seen.contiguous && first == seen.records.size();
                                  seen.runSizes.push_back(run.size());
                                  seen.records.insert(seen.records.end(), run.begin(), run.end());
                                  return Status{};
                              });
}

void expectSameRecord(const ClRecord& streamed, const ClRecord& parsed, std::size_t index) {
    EXPECT_EQ(streamed.tip, parsed.tip) << index;
    EXPECT_EQ(streamed.axis, parsed.axis) << index;
    ASSERT_TRUE(streamed.axes && parsed.axes) << index;
    EXPECT_EQ(streamed.axes->x, parsed.axes->x) << index;
    EXPECT_EQ(streamed.axes->a, parsed.axes->a) << index;
    EXPECT_EQ(streamed.axes->b, parsed.axes->b) << index;
    EXPECT_EQ(streamed.feed, parsed.feed) << index;
    EXPECT_EQ(streamed.motion, parsed.motion) << index;
    EXPECT_EQ(streamed.line, parsed.line) << index;
}

TEST(StreamedReading, HandsOnEveryRecordAWholeParseGivesInOrderAndInBoundedRuns) {
    const std::string text = helicalProgram(3 * static_cast<int>(kStreamChunkRecords) + 517);
    const auto parsed = parseGcode(text, "t.nc", kinematics::defaultBladeMachine());
    ASSERT_TRUE(parsed.has_value()) << parsed.error().toString();
    StreamedRecords seen;
    const auto count = stream(text, seen);
    ASSERT_TRUE(count.has_value()) << count.error().toString();

    EXPECT_EQ(*count, parsed->path.records.size());
    ASSERT_EQ(seen.records.size(), parsed->path.records.size());
    EXPECT_TRUE(seen.contiguous);
    EXPECT_GE(seen.runSizes.size(), 4u);
    for (std::size_t size : seen.runSizes) {
        EXPECT_LE(size, kStreamChunkRecords);
        EXPECT_GT(size, 0u);
    }
    for (std::size_t i = 0; i < seen.records.size(); ++i) {
        expectSameRecord(seen.records[i], parsed->path.records[i], i);
    }
}

// The re-read check maps the written file and gives its pages back behind the reader: what the
// reader says it has read must lie before every block it hands on later, at a line start.
TEST(StreamedReading, SaysHowFarItHasReadAndNeverHandsOnABlockBeforeThat) {
    const std::string text = helicalProgram(3 * static_cast<int>(kStreamChunkRecords) + 517);
    std::vector<std::size_t> lineStarts{0, 0}; // 1-based lines
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\n') {
            lineStarts.push_back(i + 1);
        }
    }
    std::vector<std::size_t> reports;
    std::size_t readUpTo = 0;
    bool handedOnBeforeReport = false;
    const auto count = streamGcodeRecords(
        text, "t.nc", kinematics::defaultBladeMachine(), {},
        [&](std::size_t, std::span<const ClRecord> run) {
            for (const ClRecord& record : run) {
                handedOnBeforeReport = handedOnBeforeReport ||
                                       lineStarts[static_cast<std::size_t>(record.line)] < readUpTo;
            }
            return Status{};
        },
        [&](std::size_t offset) {
            reports.push_back(offset);
            readUpTo = offset;
        });
    ASSERT_TRUE(count.has_value()) << count.error().toString();
    EXPECT_FALSE(handedOnBeforeReport);
    ASSERT_GE(reports.size(), 4u);
    for (std::size_t i = 0; i < reports.size(); ++i) {
        EXPECT_LE(reports[i], text.size());
        EXPECT_EQ(text[reports[i] - 1], '\n') << "not at a line start: " << reports[i];
        if (i > 0) {
            EXPECT_GT(reports[i], reports[i - 1]);
        }
    }
    EXPECT_GT(reports.back(), text.size() / 2);
}

// A cancelled job stops its re-read check this way: the consumer's error ends the read at
// once and is what the read returns, not a parse error.
TEST(StreamedReading, AConsumerThatFailsStopsTheReadWithItsError) {
    const std::string text = helicalProgram(3 * static_cast<int>(kStreamChunkRecords));
    std::size_t runs = 0;
    const auto count = streamGcodeRecords(text, "t.nc", kinematics::defaultBladeMachine(), {},
                                          [&](std::size_t, std::span<const ClRecord>) -> Status {
                                              ++runs;
                                              return makeError(ErrorCode::Cancelled, "enough");
                                          });
    ASSERT_FALSE(count.has_value());
    EXPECT_EQ(count.error().code, ErrorCode::Cancelled);
    EXPECT_EQ(count.error().message, "enough");
    EXPECT_EQ(runs, 1u);
}

// A whole parse looks at its watch every few thousand blocks. The token unset, a long program
// is read; set, the same read ends Cancelled instead of reading to the end.
TEST(WatchedReading, AWholeParseOfALongProgramStopsOnceTheTokenIsSet) {
    const std::string text = helicalProgram(3 * static_cast<int>(kStreamChunkRecords));
    CancelToken cancel;
    const auto read = parseOwnedGcode(text, "t.nc", kinematics::defaultBladeMachine(), {},
                                      {.cancel = &cancel, .progress = {}});
    ASSERT_TRUE(read.has_value()) << read.error().toString();
    cancel.requestCancel();
    const auto stopped = parseOwnedGcode(text, "t.nc", kinematics::defaultBladeMachine(), {},
                                         {.cancel = &cancel, .progress = {}});
    ASSERT_FALSE(stopped.has_value());
    EXPECT_EQ(stopped.error().code, ErrorCode::Cancelled);
}

// The watch hears the share of the text read every 4,096 lines, rising, never past the end.
TEST(WatchedReading, HearsTheShareOfTheTextReadEveryFewThousandLines) {
    const std::string text = helicalProgram(3 * static_cast<int>(kStreamChunkRecords));
    std::vector<double> heard;
    const auto read = parseOwnedGcode(
        text, "t.nc", kinematics::defaultBladeMachine(), {},
        {.cancel = nullptr, .progress = [&](double share) { heard.push_back(share); }});
    ASSERT_TRUE(read.has_value()) << read.error().toString();
    ASSERT_EQ(heard.size(), 3u); // 12,295 lines
    for (std::size_t i = 0; i < heard.size(); ++i) {
        EXPECT_GT(heard[i], i == 0 ? 0.0 : heard[i - 1]);
        EXPECT_LE(heard[i], 1.0);
    }
}

TEST(StreamedReading, RefusesWhatAWholeParseRefusesWithTheSameMessage) {
    std::string text = helicalProgram(2 * static_cast<int>(kStreamChunkRecords));
    // A macro variable deep in the program, after runs have been handed on.
    text.insert(text.rfind("M30"), "#1=5\n");
    const auto parsed = parseGcode(text, "t.nc", kinematics::defaultBladeMachine());
    ASSERT_FALSE(parsed.has_value());
    StreamedRecords seen;
    const auto count = stream(text, seen);
    ASSERT_FALSE(count.has_value());
    EXPECT_EQ(count.error().toString(), parsed.error().toString());
    EXPECT_EQ(count.error().code, ErrorCode::Parse);
}

TEST(StreamedReading, RefusesAProgramWithoutMovesLikeAWholeParse) {
    const std::string text = "%\nO1000\nG90 G21\nM30\n%\n";
    StreamedRecords seen;
    const auto count = stream(text, seen);
    ASSERT_FALSE(count.has_value());
    EXPECT_NE(count.error().message.find("no moves"), std::string::npos);
    EXPECT_TRUE(seen.records.empty());
}

} // namespace
} // namespace bladeaxis::io::nc
