// Compares a reference output with an actual one, number by number with a relative tolerance,
// so golden tests survive the last-digit noise of floating point (docs/architecture.md,
// Conventions). JSON: same structure and strings; keys named in kIgnoredKeys (timings, versions)
// are skipped. CSV: same header, same row count, every cell equal as text or as numbers within
// tolerance. Exit 0 when equal, 1 with the first differences printed otherwise, 2 on unreadable
// input.

#include "core/base/file_io.h"
#include "core/base/number_io.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr double kRelative = 1e-6;
constexpr double kAbsolute = 1e-9;
constexpr std::array<const char*, 4> kIgnoredKeys{"timing", "bladeaxis_version",
                                                  "bladeaxis_revision", "file"};
constexpr int kMaxReported = 20;

struct Comparison {
    std::vector<std::string> differences;
    void add(const std::string& text) {
        if (static_cast<int>(differences.size()) < kMaxReported) {
            differences.push_back(text);
        }
    }
};

bool closeEnough(double expected, double actual) {
    return std::abs(expected - actual) <= kAbsolute + kRelative * std::abs(expected);
}

bool ignored(const std::string& key) {
    for (const char* name : kIgnoredKeys) {
        if (key == name) {
            return true;
        }
    }
    return false;
}

void compareJson(const nlohmann::json& expected, const nlohmann::json& actual,
                 const std::string& path, Comparison& result) {
    if (expected.is_number() && actual.is_number()) {
        if (!closeEnough(expected.get<double>(), actual.get<double>())) {
            result.add(path + ": expected " + expected.dump() + ", got " + actual.dump());
        }
        return;
    }
    if (expected.type() != actual.type()) {
        result.add(path + ": expected " + expected.dump() + ", got " + actual.dump());
        return;
    }
    if (expected.is_object()) {
        for (const auto& [key, value] : expected.items()) {
            if (ignored(key)) {
                continue;
            }
            if (!actual.contains(key)) {
                result.add(path + "." + key + ": missing");
                continue;
            }
            compareJson(value, actual.at(key), path + "." + key, result);
        }
        for (const auto& [key, value] : actual.items()) {
            if (!expected.contains(key) && !ignored(key)) {
                result.add(path + "." + key + ": unexpected key");
            }
        }
    } else if (expected.is_array()) {
        if (expected.size() != actual.size()) {
            result.add(path + ": expected " + std::to_string(expected.size()) + " elements, got " +
                       std::to_string(actual.size()));
            return;
        }
        for (std::size_t i = 0; i < expected.size(); ++i) {
            compareJson(expected[i], actual[i], path + "[" + std::to_string(i) + "]", result);
        }
    } else if (expected != actual) {
        result.add(path + ": expected " + expected.dump() + ", got " + actual.dump());
    }
}

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream stream(text);
    while (std::getline(stream, part, separator)) {
        parts.push_back(part);
    }
    return parts;
}

void compareCsv(const std::string& expected, const std::string& actual, Comparison& result) {
    const auto expectedRows = split(expected, '\n');
    const auto actualRows = split(actual, '\n');
    if (expectedRows.size() != actualRows.size()) {
        result.add("expected " + std::to_string(expectedRows.size()) + " rows, got " +
                   std::to_string(actualRows.size()));
        return;
    }
    for (std::size_t row = 0; row < expectedRows.size(); ++row) {
        const auto want = split(expectedRows[row], ',');
        const auto got = split(actualRows[row], ',');
        if (want.size() != got.size()) {
            result.add("row " + std::to_string(row + 1) + ": cell count differs");
            continue;
        }
        for (std::size_t cell = 0; cell < want.size(); ++cell) {
            const auto a = bladeaxis::parseNumber(want[cell]);
            const auto b = bladeaxis::parseNumber(got[cell]);
            const bool same = (a && b) ? closeEnough(*a, *b) : want[cell] == got[cell];
            if (!same) {
                result.add("row " + std::to_string(row + 1) + " column " +
                           std::to_string(cell + 1) + ": expected " + want[cell] + ", got " +
                           got[cell]);
            }
        }
    }
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: golden_compare EXPECTED ACTUAL\n";
        return 2;
    }
    auto expected = bladeaxis::readTextFile(argv[1]);
    auto actual = bladeaxis::readTextFile(argv[2]);
    if (!expected || !actual) {
        std::cerr << (expected ? actual.error() : expected.error()).toString() << '\n';
        return 2;
    }
    Comparison result;
    const std::string name = argv[1];
    if (name.size() > 5 && name.substr(name.size() - 5) == ".json") {
        const auto want = nlohmann::json::parse(*expected, nullptr, false);
        const auto got = nlohmann::json::parse(*actual, nullptr, false);
        if (want.is_discarded() || got.is_discarded()) {
            std::cerr << "invalid JSON\n";
            return 2;
        }
        compareJson(want, got, "$", result);
    } else {
        compareCsv(*expected, *actual, result);
    }
    for (const std::string& difference : result.differences) {
        std::cout << difference << '\n';
    }
    return result.differences.empty() ? 0 : 1;
}
