// Fuzz-ish robustness: seeded random mutations of a sample program must each give a value or an
// error, never a crash or a hang; accepted programs must still rewrite byte-identically.

#include "core/io/nc/gcode.h"
#include "tests/unit/io_nc/gcode_test_support.h"

#include <gtest/gtest.h>

#include <random>

namespace bladeaxis::io::nc {
namespace {

std::string mutate(std::string text, std::mt19937& random) {
    // Word letters, digits, punctuation, line endings, a NUL and a non-ASCII byte.
    static constexpr char kChars[] = "GXYZABCFNM0123456789.-+()%;/ \n\r\t\0\xff";
    const std::string_view kAlphabet(kChars, sizeof(kChars) - 1);
    const int edits = 1 + static_cast<int>(random() % 4);
    for (int e = 0; e < edits; ++e) {
        const std::size_t at = text.empty() ? 0 : random() % text.size();
        const char c = kAlphabet[random() % kAlphabet.size()];
        switch (random() % 5) {
        case 0:
            if (!text.empty()) {
                text[at] = c;
            }
            break;
        case 1:
            text.insert(text.begin() + static_cast<std::ptrdiff_t>(at), c);
            break;
        case 2:
            text.erase(at, std::min<std::size_t>(random() % 8, text.size() - at));
            break;
        case 3:
            text.insert(at, text.substr(at, random() % 40));
            break;
        default:
            text.insert(at, "99999999999999999999e99");
            break;
        }
    }
    return text;
}

TEST(GcodeRobustness, TwoThousandMutationsGiveAValueOrALocatedError) {
    const std::string sample = test::readSample("fanuc_basic.nc");
    const auto machine = kinematics::defaultBladeMachine();
    std::mt19937 random(20261122u);
    int accepted = 0;
    for (int i = 0; i < 2000; ++i) {
        const std::string text = mutate(sample, random);
        const Result<GcodeProgram> program = parseGcode(text, "fuzz.nc", machine);
        if (!program) {
            EXPECT_EQ(program.error().code, ErrorCode::Parse) << text;
            EXPECT_FALSE(program.error().message.empty());
            EXPECT_LE(program.error().more.size(), static_cast<std::size_t>(kMaxParseErrors));
            continue;
        }
        ++accepted;
        for (const toolpath::ClRecord& record : program->path.records) {
            ASSERT_TRUE(record.tip.allFinite() && record.axis.allFinite()) << text;
        }
        const auto again = rewriteGcode(*program, test::axesOf(*program), machine);
        ASSERT_TRUE(again.has_value());
        EXPECT_EQ(*again, text);
    }
    EXPECT_GT(accepted, 0);
}

} // namespace
} // namespace bladeaxis::io::nc
