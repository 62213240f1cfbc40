#include "core/io/nc/dialect.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace bladeaxis::io {

const char* toString(NcDialect dialect) {
    switch (dialect) {
    case NcDialect::Iso:
        return "iso";
    case NcDialect::Sinumerik:
        return "sinumerik";
    case NcDialect::Heidenhain:
        return "heidenhain";
    }
    return "iso";
}

} // namespace bladeaxis::io

namespace bladeaxis::io::nc {

namespace {

// Markers are looked for in the head of the program, where posts write their set-up blocks.
constexpr std::size_t kHeadBytes = 256 * 1024;
constexpr std::string_view kBeginProgram = "BEGIN PGM";

std::string upperCopy(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return out;
}

std::string_view withoutBlockNumber(std::string_view line) {
    std::size_t i = line.find_first_not_of(" \t");
    if (i == std::string_view::npos) {
        return {};
    }
    const std::size_t digits = i;
    while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i]))) {
        ++i;
    }
    if (i > digits && (i == line.size() || line[i] == ' ' || line[i] == '\t')) {
        line.remove_prefix(i);
        return line.substr(std::min(line.find_first_not_of(" \t"), line.size()));
    }
    return line.substr(digits);
}

bool hasSinumerikMarker(const std::string& head) {
    static constexpr std::array<std::string_view, 16> kMarkers{
        "TRAORI", "TRAFOOF", "=DC(",   "=ACP(",  "=ACN(", "=IC(",   "=AC(", "CYCLE832",
        "MSG(",   "SUPA",    "ORIWKS", "ORIMKS", "%_N_",  ";$PATH", "T=\"", "G642"};
    return std::any_of(kMarkers.begin(), kMarkers.end(), [&head](std::string_view marker) {
        return head.find(marker) != std::string::npos;
    });
}

std::string lowerExtension(std::string_view fileName) {
    const std::size_t dot = fileName.rfind('.');
    const std::size_t slash = fileName.find_last_of("/\\");
    if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) {
        return {};
    }
    std::string extension(fileName.substr(dot));
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

std::optional<NcDialect> dialectOfExtension(std::string_view fileName) {
    const std::string extension = lowerExtension(fileName);
    if (extension == ".h") {
        return NcDialect::Heidenhain;
    }
    if (extension == ".mpf" || extension == ".spf") {
        return NcDialect::Sinumerik;
    }
    return std::nullopt;
}

std::optional<NcDialect> dialectOfContent(std::string_view text) {
    const std::string_view head = text.substr(0, std::min(text.size(), kHeadBytes));
    std::size_t begin = 0;
    int heidenhainLines = 0;
    while (begin < head.size()) {
        std::size_t end = head.find('\n', begin);
        end = end == std::string_view::npos ? head.size() : end;
        const std::string_view content = withoutBlockNumber(head.substr(begin, end - begin));
        begin = end + 1;
        // The start of a line decides for most lines: the whole line is upper-cased only for
        // those that begin with "L ", not for every line of the head.
        const std::string start = upperCopy(content.substr(0, kBeginProgram.size()));
        if (start.starts_with(kBeginProgram)) {
            return NcDialect::Heidenhain;
        }
        heidenhainLines +=
            start.starts_with("L ") && looksLikeHeidenhainLine(upperCopy(content)) ? 1 : 0;
    }
    if (heidenhainLines > 0) {
        return NcDialect::Heidenhain;
    }
    if (hasSinumerikMarker(upperCopy(head))) {
        return NcDialect::Sinumerik;
    }
    return std::nullopt;
}

} // namespace

bool looksLikeHeidenhainLine(std::string_view line) {
    const std::string text = upperCopy(withoutBlockNumber(line));
    if (text.starts_with("L ")) {
        // "L X+1 Y-2": Heidenhain words carry their sign; ISO has no bare "L" word.
        return text.find("X+") != std::string::npos || text.find("X-") != std::string::npos ||
               text.find("Z+") != std::string::npos || text.find("Z-") != std::string::npos ||
               text.find("A+") != std::string::npos || text.find("A-") != std::string::npos ||
               text.find("FMAX") != std::string::npos || text.find(" R0") != std::string::npos;
    }
    static constexpr std::array<std::string_view, 7> kStatements{
        "BEGIN PGM", "END PGM", "BLK FORM", "TOOL CALL", "TOOL DEF", "CYCL DEF", "FUNCTION TCPM"};
    return std::any_of(kStatements.begin(), kStatements.end(),
                       [&text](std::string_view statement) { return text.starts_with(statement); });
}

DetectedDialect detectDialect(std::string_view text, std::string_view fileName) {
    const std::optional<NcDialect> byContent = dialectOfContent(text);
    const std::optional<NcDialect> byExtension = dialectOfExtension(fileName);
    DetectedDialect detected;
    detected.dialect = byContent.value_or(byExtension.value_or(NcDialect::Iso));
    if (byContent && byExtension && *byContent != *byExtension) {
        detected.warning = std::string(fileName) + ": the extension says " +
                           toString(*byExtension) + " but the content is " + toString(*byContent) +
                           "; read as " + toString(*byContent) + " (--dialect overrides)";
    }
    return detected;
}

} // namespace bladeaxis::io::nc
