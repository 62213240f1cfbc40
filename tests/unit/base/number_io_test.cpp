#include "core/base/number_io.h"

#include <gtest/gtest.h>

#include <array>
#include <charconv>
#include <clocale>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace bladeaxis {
namespace {

TEST(ParseNumber, AcceptsTheSpellingsNcFilesUse) {
    EXPECT_EQ(parseNumber("12"), 12.0);
    EXPECT_EQ(parseNumber("-0.5"), -0.5);
    EXPECT_EQ(parseNumber("+3"), 3.0);
    EXPECT_EQ(parseNumber(".5"), 0.5);
    EXPECT_EQ(parseNumber("-.25"), -0.25);
    EXPECT_EQ(parseNumber("5."), 5.0);
    EXPECT_EQ(parseNumber("1e-3"), 1e-3);
}

TEST(ParseNumber, RejectsGarbageNanAndInfinity) {
    for (const char* bad : {"", "-", "+", ".", "1.2.3", "12a", "nan", "NaN", "inf", "-inf", "1,5",
                            "0x10", " 1", "1 ", "e5", "1e999"}) {
        EXPECT_FALSE(parseNumber(bad).has_value()) << "accepted '" << bad << "'";
    }
}

TEST(ParseNumber, KeepsTheSignOfZero) {
    EXPECT_TRUE(std::signbit(*parseNumber("-0.0")));
    EXPECT_TRUE(std::signbit(*parseNumber("-.0")));
    EXPECT_FALSE(std::signbit(*parseNumber("+0")));
}

// Short plain decimals take a direct path; it must give the same double as from_chars, the
// correctly rounded one, for every digit count and point position it covers and just beyond.
TEST(ParseNumber, AgreesWithFromCharsOnPlainDecimals) {
    std::mt19937_64 random(12345);
    for (int trial = 0; trial < 200000; ++trial) {
        const int digitCount = 1 + static_cast<int>(random() % 18);
        std::string digits;
        for (int i = 0; i < digitCount; ++i) {
            digits += static_cast<char>('0' + random() % 10);
        }
        const auto point = static_cast<std::size_t>(random() % (digits.size() + 2));
        std::string text = digits;
        if (point <= digits.size()) {
            text.insert(point, ".");
        }
        const std::string spelled = text.front() == '.' ? "0" + text : text;
        double expected = 0.0;
        const auto [end, ec] =
            std::from_chars(spelled.data(), spelled.data() + spelled.size(), expected);
        ASSERT_EQ(ec, std::errc{}) << text;
        ASSERT_EQ(end, spelled.data() + spelled.size()) << text;
        const std::optional<double> parsed = parseNumber(text);
        ASSERT_TRUE(parsed.has_value()) << text;
        ASSERT_EQ(*parsed, expected) << text;
        ASSERT_EQ(parseNumber("-" + text), -expected) << text;
    }
}

TEST(ReadPlainDecimal, ReadsTheNumberAtTheStartAndHowItIsWritten) {
    const PlainDecimal number = readPlainDecimal("-012.250Y3");
    EXPECT_EQ(number.value, -12.25);
    EXPECT_EQ(number.length, 8u) << "stops before the next word";
    EXPECT_EQ(number.integerDigits, 3u);
    EXPECT_EQ(number.fractionDigits, 3u);
    EXPECT_TRUE(number.hasPoint);
    EXPECT_FALSE(number.integerPartZero);

    const PlainDecimal fraction = readPlainDecimal("+.5");
    EXPECT_EQ(fraction.value, 0.5);
    EXPECT_EQ(fraction.length, 3u);
    EXPECT_EQ(fraction.integerDigits, 0u);
    EXPECT_TRUE(fraction.integerPartZero);

    const PlainDecimal whole = readPlainDecimal("5.");
    EXPECT_EQ(whole.value, 5.0);
    EXPECT_EQ(whole.length, 2u);
    EXPECT_TRUE(whole.hasPoint);
    EXPECT_EQ(whole.fractionDigits, 0u);

    const PlainDecimal zero = readPlainDecimal("00.0");
    EXPECT_TRUE(zero.integerPartZero);
    EXPECT_TRUE(std::signbit(readPlainDecimal("-0").value));
}

TEST(ReadPlainDecimal, StopsWhereThePlainSpellingEnds) {
    EXPECT_EQ(readPlainDecimal("1.2.3").length, 3u) << "a second point is the caller's to judge";
    EXPECT_EQ(readPlainDecimal("1.5e3").length, 3u) << "so is an exponent";
    EXPECT_EQ(readPlainDecimal("123456789012345").length, 15u) << "15 digits are exact";
}

TEST(ReadPlainDecimal, HasNoLengthForWhatIsNotAPlainDecimal) {
    for (const char* other : {"", "-", "+", ".", "-.", "e5", "X1", " 1", "1234567890123456",
                              "0.000000000000001", "12345678.12345678"}) {
        EXPECT_EQ(readPlainDecimal(other).length, 0u) << "read '" << other << "'";
    }
}

TEST(FormatFixed, WritesExactlyTheRequestedDecimals) {
    EXPECT_EQ(formatFixed(1.23456, 3), "1.235");
    EXPECT_EQ(formatFixed(-2.0, 4), "-2.0000");
    EXPECT_EQ(formatFixed(10.0, 0), "10");
}

TEST(FormatFixed, NeverWritesNegativeZero) {
    EXPECT_EQ(formatFixed(-0.0001, 3), "0.000");
    EXPECT_EQ(formatFixed(-0.0, 2), "0.00");
}

// What formatFixed wrote when it always went through to_chars (the shortest form when 64
// characters do not hold it): the reference its fast path must match byte for byte.
std::string fixedThroughToChars(double value, int decimals) {
    std::array<char, 64> buffer{};
    auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                   std::chars_format::fixed, decimals);
    if (ec != std::errc{}) {
        end = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value).ptr;
    }
    std::string text(buffer.data(), end);
    if (text.front() == '-' && text.find_first_not_of("-0.") == std::string::npos) {
        text.erase(0, 1);
    }
    return text;
}

void expectFixedLikeToChars(double value, int decimals) {
    const NumberText text = fixedText(value, decimals);
    ASSERT_EQ(text.view(), fixedThroughToChars(value, decimals))
        << std::hexfloat << value << " to " << decimals << " decimals";
    // The value it carries is the one reading the text back gives, without reading it.
    if (text.value) {
        ASSERT_EQ(*text.value, parseNumber(text.view()));
        ASSERT_EQ(std::signbit(*text.value), std::signbit(*parseNumber(text.view())));
    }
}

TEST(FormatFixed, AgreesWithToCharsOnRandomValues) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> magnitude(-8.0, 8.0);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int trial = 0; trial < 2'000'000; ++trial) {
        const double value = unit(random) * std::pow(10.0, magnitude(random));
        expectFixedLikeToChars(value, static_cast<int>(random() % 9));
    }
}

TEST(FormatFixed, AgreesWithToCharsOnHalfwayAndNearHalfwayValues) {
    std::mt19937_64 random(11);
    for (int trial = 0; trial < 1'000'000; ++trial) {
        const int decimals = static_cast<int>(random() % 9);
        // k + 1/2 units of the last place: a true tie when the double is exact (0.125 to 2),
        // else its nearest doubles on either side.
        const double units = static_cast<double>(random() % 2'000'000) + 0.5;
        const double tie = units / std::pow(10.0, decimals);
        for (const double value : {tie, std::nextafter(tie, 0.0), std::nextafter(tie, 1e300)}) {
            expectFixedLikeToChars(value, decimals);
            expectFixedLikeToChars(-value, decimals);
        }
    }
}

TEST(FormatFixed, AgreesWithToCharsOnEdgeValues) {
    std::vector<double> values{0.0,     -0.0,
                               0.125,   2.5,
                               0.5,     1.5,
                               -2.5,    0.005,
                               1.005,   1e-300,
                               5e-324,  1e15,
                               1e16,    1e20,
                               1e300,   -1e300,
                               0x1p50,  0x1p53,
                               0x1p63,  0x1p64,
                               -0.0001, 0.49999999999999994};
    for (int power = -10; power <= 22; ++power) {
        const double ten = std::pow(10.0, power);
        values.insert(values.end(), {ten, std::nextafter(ten, 0.0), std::nextafter(ten, 1e300)});
    }
    for (const double value : values) {
        for (int decimals = 0; decimals <= 17; ++decimals) {
            expectFixedLikeToChars(value, decimals);
            expectFixedLikeToChars(-value, decimals);
        }
    }
}

TEST(FormatFixed, WritesNonFiniteValuesAsToCharsDoes) {
    for (const double value :
         {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::quiet_NaN()}) {
        EXPECT_EQ(formatFixed(value, 3), fixedThroughToChars(value, 3));
    }
}

TEST(FormatTrimmed, DropsTrailingZerosAndPoint) {
    EXPECT_EQ(formatTrimmed(1.5, 4), "1.5");
    EXPECT_EQ(formatTrimmed(2.0, 4), "2");
    EXPECT_EQ(formatTrimmed(-0.00001, 3), "0");
}

TEST(FormatShortest, RoundTripsExactly) {
    for (double value : {0.1, 1.0 / 3.0, -123.456e-7, 6.02214076e23}) {
        EXPECT_EQ(parseNumber(formatShortest(value)), value);
    }
}

// A decimal-comma desktop locale must not change what we read or write (docs/architecture.md,
// Conventions).
TEST(NumberIo, IsIndependentOfADecimalCommaLocale) {
    const char* previous = std::setlocale(LC_ALL, nullptr);
    const std::string saved = previous ? previous : "C";
    if (std::setlocale(LC_ALL, "de_DE.UTF-8") == nullptr) {
        GTEST_SKIP() << "de_DE.UTF-8 locale not installed (packaging/install-deps.sh installs it)";
    }
    EXPECT_EQ(formatFixed(1.5, 3), "1.500");
    EXPECT_EQ(formatShortest(0.25), "0.25");
    EXPECT_EQ(parseNumber("1.5"), 1.5);
    EXPECT_FALSE(parseNumber("1,5").has_value());
    std::setlocale(LC_ALL, saved.c_str());
}

} // namespace
} // namespace bladeaxis
