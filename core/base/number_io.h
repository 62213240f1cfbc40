#pragma once
// Locale-independent number parsing and formatting for every file BladeAxis reads or writes.
// A decimal-comma desktop locale must never change a file (docs/architecture.md, Conventions), so
// nothing here uses iostreams, printf or strtod.

#include <optional>
#include <string>
#include <string_view>

namespace bladeaxis {

// Parses a whole token as a decimal number ("12", "-0.5", ".5", "5.", "+3", "1e-3").
// Returns nullopt for anything else, including NaN/inf spellings and trailing garbage.
std::optional<double> parseNumber(std::string_view token);

// Fixed-point text with exactly `decimals` digits after the point, "-0.000" normalised to "0.000".
std::string formatFixed(double value, int decimals);

// Shortest text that reads back to exactly the same double ("0.1", "1e-09").
std::string formatShortest(double value);

// Fixed-point text with up to `maxDecimals` digits, trailing zeros and a trailing point removed.
std::string formatTrimmed(double value, int maxDecimals);

} // namespace bladeaxis
