// docs/results.md quotes the reproduction's figures; this keeps the page true. It runs the
// page's command (36 blades, seed 2022) and compares every row of the page's "Pinned figures"
// table with the reproduction's median and quartiles at the printed precision. Times are not
// pinned: they are measurements, reported with their spread.

#include "core/base/file_io.h"
#include "core/job/reproduction.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace bladeaxis::job {
namespace {

struct PinnedRow {
    std::string method, figure;
    double median = 0.0, q1 = 0.0, q3 = 0.0;
    std::size_t blades = 0;
    std::string line;
};

std::vector<std::string> cellsOf(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream stream(line);
    std::string cell;
    std::getline(stream, cell, '|'); // before the first bar
    while (std::getline(stream, cell, '|')) {
        const auto first = cell.find_first_not_of(' ');
        const auto last = cell.find_last_not_of(' ');
        cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
    }
    return cells;
}

// The rows of the table under "## Pinned figures" (header and separator skipped).
std::vector<PinnedRow> pinnedRows(const std::string& page) {
    std::vector<PinnedRow> rows;
    const auto section = page.find("## Pinned figures");
    if (section == std::string::npos) {
        return rows;
    }
    std::stringstream stream(page.substr(section));
    std::string line;
    while (std::getline(stream, line)) {
        if (!line.starts_with("| ") || line.starts_with("| method") || line.starts_with("|---")) {
            continue;
        }
        const std::vector<std::string> cells = cellsOf(line);
        if (cells.size() < 6) {
            continue;
        }
        rows.push_back({cells[0], cells[1], std::stod(cells[2]), std::stod(cells[3]),
                        std::stod(cells[4]), static_cast<std::size_t>(std::stoul(cells[5])), line});
    }
    return rows;
}

TEST(ResultsPage, FiguresMatchTheReproduction) {
    const auto page =
        readTextFile(std::filesystem::path(BLADEAXIS_SOURCE_DIR) / "docs" / "results.md");
    ASSERT_TRUE(page.has_value()) << page.error().toString();
    const std::vector<PinnedRow> rows = pinnedRows(*page);
    ASSERT_GE(rows.size(), 20U) << "docs/results.md has no pinned-figures table";

    ReproductionSpec spec; // the page's command: 36 blades, seed 2022, default presets
    ASSERT_EQ(spec.blades, 36);
    ASSERT_EQ(spec.seed, 2022U);
    NullProgressSink progress;
    auto result = runReproduction(spec, progress, CancelToken{});
    ASSERT_TRUE(result.has_value()) << result.error().toString();

    constexpr double kPrinted = 0.0005 + 1e-9; // three decimals
    for (const PinnedRow& row : rows) {
        const auto method = result->summary.find(row.method);
        ASSERT_NE(method, result->summary.end()) << row.line;
        const auto figure = method->second.find(row.figure);
        ASSERT_NE(figure, method->second.end()) << row.line;
        const Spread& spread = figure->second;
        EXPECT_NEAR(spread.median, row.median, kPrinted) << row.line;
        EXPECT_NEAR(spread.q1, row.q1, kPrinted) << row.line;
        EXPECT_NEAR(spread.q3, row.q3, kPrinted) << row.line;
        EXPECT_EQ(spread.count, row.blades) << row.line;
    }
}

} // namespace
} // namespace bladeaxis::job
