#include "core/blade/section_table.h"

#include "core/base/file_io.h"
#include "core/base/number_io.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace bladeaxis::blade {
namespace {

constexpr std::size_t kMaxReportedErrors = 20;

std::vector<std::string_view> tokens(std::string_view line) {
    std::vector<std::string_view> result;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) {
            ++i;
        }
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') {
            ++i;
        }
        if (i > start) {
            result.push_back(line.substr(start, i - start));
        }
    }
    return result;
}

// Collects parse errors; the first becomes the returned Error, the rest go to Error::more.
class ErrorList {
  public:
    explicit ErrorList(std::string_view file) : m_file(file) {}
    void add(int line, std::string message) {
        if (m_errors.size() < kMaxReportedErrors) {
            m_errors.push_back(Error{ErrorCode::Parse, std::move(message), {m_file, line, 0}, {}});
        }
    }
    bool empty() const { return m_errors.empty(); }
    Error take() {
        Error first = std::move(m_errors.front());
        first.more.assign(m_errors.begin() + 1, m_errors.end());
        return first;
    }

  private:
    std::string m_file;
    std::vector<Error> m_errors;
};

std::string quoted(std::string_view token) {
    return "'" + std::string(token) + "'";
}

void parseStationHeader(const std::vector<std::string_view>& words, int lineNumber,
                        SectionTable& table, ErrorList& errors) {
    if (words.size() != 2) {
        errors.add(lineNumber, "expected 'station <x>' with exactly one number");
        return;
    }
    const std::optional<double> x = parseNumber(words[1]);
    if (!x) {
        errors.add(lineNumber,
                   "expected a finite number for the station x, got " + quoted(words[1]));
        return;
    }
    if (!table.stations.empty() && !(*x > table.stations.back().x)) {
        errors.add(lineNumber, "station x = " + formatShortest(*x) +
                                   " must be greater than the previous station x = " +
                                   formatShortest(table.stations.back().x));
    }
    table.stations.push_back(SectionStation{*x, {}, lineNumber});
}

void parsePoint(const std::vector<std::string_view>& words, int lineNumber, SectionTable& table,
                ErrorList& errors) {
    if (table.stations.empty()) {
        errors.add(lineNumber, "expected a 'station <x>' line before the first point");
        return;
    }
    if (words.size() != 2) {
        errors.add(lineNumber, "expected a point 'y z' (2 numbers), got " +
                                   std::to_string(words.size()) + " fields");
        return;
    }
    const std::optional<double> y = parseNumber(words[0]);
    const std::optional<double> z = parseNumber(words[1]);
    if (!y || !z) {
        errors.add(lineNumber, "expected a finite number for " + std::string(!y ? "y" : "z") +
                                   ", got " + quoted(!y ? words[0] : words[1]));
        return;
    }
    table.stations.back().points.emplace_back(*y, *z);
}

} // namespace

Result<SectionTable> readSectionTable(std::string_view text, std::string_view fileName) {
    SectionTable table;
    table.sourceFile = std::string(fileName);
    ErrorList errors(fileName);
    int lineNumber = 0;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        const std::size_t end = std::min(text.find('\n', pos), text.size());
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        ++lineNumber;
        line = line.substr(0, std::min(line.find('#'), line.size()));
        const std::vector<std::string_view> words = tokens(line);
        if (words.empty()) {
            continue;
        }
        if (words[0] == "station" || words[0] == "STATION") {
            parseStationHeader(words, lineNumber, table, errors);
        } else {
            parsePoint(words, lineNumber, table, errors);
        }
    }
    for (const SectionStation& station : table.stations) {
        if (station.points.size() < 3) {
            errors.add(station.line, "station x = " + formatShortest(station.x) + " has " +
                                         std::to_string(station.points.size()) +
                                         " points, expected at least 3");
        }
    }
    if (errors.empty() && table.stations.size() < 2) {
        errors.add(lineNumber,
                   "expected at least 2 stations, found " + std::to_string(table.stations.size()));
    }
    if (!errors.empty()) {
        return std::unexpected(errors.take());
    }
    return normaliseSectionTable(std::move(table));
}

Result<SectionTable> readSectionTableFile(const std::filesystem::path& path) {
    Result<std::string> text = readTextFile(path);
    if (!text) {
        return std::unexpected(text.error());
    }
    return readSectionTable(*text, path.string());
}

Result<SectionTable> normaliseSectionTable(SectionTable table) {
    if (table.stations.size() < 2) {
        return makeError(ErrorCode::Geometry,
                         "a section table needs at least 2 stations, got " +
                             std::to_string(table.stations.size()),
                         {table.sourceFile, 0, 0});
    }
    Vec2 side(0.0, 1.0);
    for (std::size_t i = 0; i < table.stations.size(); ++i) {
        SectionStation& station = table.stations[i];
        const SourceLocation where{table.sourceFile, station.line, 0};
        if (!std::isfinite(station.x) || (i > 0 && !(station.x > table.stations[i - 1].x))) {
            return makeError(ErrorCode::Geometry,
                             "station x = " + formatShortest(station.x) +
                                 " must be finite and greater than the previous station",
                             where);
        }
        Result<Curve2> curve =
            normaliseClosedCurve(station.points, "station x = " + formatShortest(station.x));
        if (!curve) {
            return makeError(ErrorCode::Geometry, curve.error().message, where);
        }
        station.points = rotateToStart(*curve, phaseIndex(*curve, side, &side));
    }
    return table;
}

} // namespace bladeaxis::blade
