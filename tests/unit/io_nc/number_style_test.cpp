// How the reader learns the way a file writes the numbers of an axis: the scanner notes the
// style of a plain decimal while reading it, and that must be exactly what reading the word's
// text again gives.

#include "core/io/nc/detail/number_style.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <string>

namespace bladeaxis::io::nc {
namespace {

using detail::setPlainDecimalStyle;
using detail::styleOfWord;
using detail::WordTextStyle;

WordTextStyle styleWhileReading(const std::string& text) {
    const PlainDecimal number = readPlainDecimal(text);
    WordTextStyle style;
    setPlainDecimalStyle(style, text, number);
    return style;
}

void expectSameStyle(const std::string& text) {
    ASSERT_EQ(readPlainDecimal(text).length, text.size()) << text;
    const WordTextStyle read = styleOfWord(text);
    const WordTextStyle noted = styleWhileReading(text);
    EXPECT_EQ(noted.decimals, read.decimals) << text;
    EXPECT_EQ(noted.hasPoint, read.hasPoint) << text;
    EXPECT_EQ(noted.leadingZero, read.leadingZero) << text;
    EXPECT_EQ(noted.explicitPlus, read.explicitPlus) << text;
}

TEST(NumberStyle, NotedWhileReadingAPlainDecimalAsTheTextSays) {
    for (const char* text : {"10", "10.", "10.250", "-0.5", "+.5", ".5", "-.5", "0.", "00.00", "+0",
                             "-0", "7", "+12.5", "0000.0001"}) {
        expectSameStyle(text);
    }
    EXPECT_EQ(styleWhileReading(".5").leadingZero, false);
    EXPECT_EQ(styleWhileReading("0.5").leadingZero, true);
    EXPECT_FALSE(styleWhileReading("1.5").leadingZero.has_value());
    EXPECT_EQ(styleWhileReading("-1.250").decimals, 3);
    EXPECT_TRUE(styleWhileReading("+1").explicitPlus);
}

TEST(NumberStyle, NotedStyleAgreesWithTheTextForEveryShapeOfPlainDecimal) {
    std::mt19937 random(2024);
    for (int trial = 0; trial < 20000; ++trial) {
        std::string text;
        const int sign = static_cast<int>(random() % 3);
        text += sign == 0 ? "" : (sign == 1 ? "-" : "+");
        const int integerDigits = static_cast<int>(random() % 6);
        for (int i = 0; i < integerDigits; ++i) {
            text += static_cast<char>('0' + (random() % 3 == 0 ? 0 : random() % 10));
        }
        const bool point = random() % 4 != 0 || integerDigits == 0;
        if (point) {
            text += '.';
            const int fractionDigits = static_cast<int>(random() % 7) + (integerDigits == 0);
            for (int i = 0; i < fractionDigits; ++i) {
                text += static_cast<char>('0' + random() % 10);
            }
        }
        expectSameStyle(text);
    }
}

// The writer takes the value a rewritten word reads back as from numberLikeWord instead of
// parsing the word again: it must be exactly what parsing gives, or nothing.
TEST(NumberStyle, RewrittenWordCarriesTheValueItReadsBackAs) {
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const std::array<const char*, 8> oldWords{"1.500", ".5",  "+0.25", "10.",
                                              "-3",    "0.0", "+.125", "-.0000"};
    AxisNumberStyle fixedDecimals{.seen = true, .minDecimals = 3, .maxDecimals = 3};
    AxisNumberStyle trimmed{.seen = true, .minDecimals = 0, .maxDecimals = 4, .leadingZero = false};
    for (int trial = 0; trial < 200'000; ++trial) {
        const double value = unit(random) * std::pow(10.0, static_cast<int>(random() % 8) - 4);
        const char* old = oldWords[random() % oldWords.size()];
        for (const AxisNumberStyle& axis : {fixedDecimals, trimmed}) {
            const detail::WordNumber word = detail::numberLikeWord(value, old, axis);
            const std::optional<double> parsed = parseNumber(word.text);
            if (word.value) {
                ASSERT_EQ(word.value, parsed) << word.text;
                ASSERT_EQ(std::signbit(*word.value), std::signbit(*parsed)) << word.text;
            }
        }
    }
    // "0." without its leading zero is "." alone, which reads as nothing.
    const detail::WordNumber bare = detail::numberLikeWord(0.0, ".", trimmed);
    EXPECT_EQ(bare.text, ".");
    EXPECT_FALSE(bare.value.has_value());
}

} // namespace
} // namespace bladeaxis::io::nc
