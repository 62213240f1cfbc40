#include "core/base/number_io.h"

#include <gtest/gtest.h>

#include <clocale>
#include <cstdlib>

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

TEST(FormatFixed, WritesExactlyTheRequestedDecimals) {
    EXPECT_EQ(formatFixed(1.23456, 3), "1.235");
    EXPECT_EQ(formatFixed(-2.0, 4), "-2.0000");
    EXPECT_EQ(formatFixed(10.0, 0), "10");
}

TEST(FormatFixed, NeverWritesNegativeZero) {
    EXPECT_EQ(formatFixed(-0.0001, 3), "0.000");
    EXPECT_EQ(formatFixed(-0.0, 2), "0.00");
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
