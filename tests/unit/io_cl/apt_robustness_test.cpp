// Seeded random mutations of a sample file: the reader (and the rewriter on what it accepts)
// must return a value or an error, never crash or hang.

#include "core/io/cl/apt.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>

namespace bladeaxis::io::cl {
namespace {

constexpr char kAlphabet[] = "GOTO/,$.-+0123456789eE \r\n\tMULTAXFEDRAT$$NaNinf\x00\x7f";

std::string mutate(std::string text, std::mt19937& rng) {
    std::uniform_int_distribution<int> edits(1, 8);
    std::uniform_int_distribution<int> kind(0, 3);
    std::uniform_int_distribution<std::size_t> symbol(0, sizeof(kAlphabet) - 1);
    const int count = edits(rng);
    for (int e = 0; e < count && !text.empty(); ++e) {
        std::uniform_int_distribution<std::size_t> where(0, text.size() - 1);
        const std::size_t at = where(rng);
        switch (kind(rng)) {
        case 0:
            text[at] = kAlphabet[symbol(rng)];
            break;
        case 1:
            text.insert(at, 1, kAlphabet[symbol(rng)]);
            break;
        case 2:
            text.erase(at, std::min<std::size_t>(text.size() - at, 1 + at % 7));
            break;
        default:
            text.resize(at); // truncation, e.g. inside a continuation
            break;
        }
    }
    return text;
}

TEST(AptRobustness, TwoThousandMutationsOfASampleNeverCrash) {
    Result<AptProgram> sample =
        readAptFile(std::filesystem::path(BLADEAXIS_TEST_DATA_DIR) / "cl" / "nx_clsf_crlf.cls");
    ASSERT_TRUE(sample.has_value());
    std::mt19937 rng(20240611);
    int accepted = 0;
    for (int i = 0; i < 2000; ++i) {
        const std::string text = mutate(sample->text, rng);
        Result<AptProgram> program = parseApt(text, "mutated.cls");
        if (!program) {
            EXPECT_FALSE(program.error().message.empty());
            EXPECT_LE(program.error().more.size(), static_cast<std::size_t>(kMaxReportedErrors));
            continue;
        }
        ++accepted;
        // What was accepted must rewrite to itself.
        Result<std::string> rewritten = rewriteApt(*program, program->path.records);
        ASSERT_TRUE(rewritten.has_value()) << rewritten.error().toString();
        EXPECT_EQ(*rewritten, text);
    }
    EXPECT_GT(accepted, 0);
}

} // namespace
} // namespace bladeaxis::io::cl
