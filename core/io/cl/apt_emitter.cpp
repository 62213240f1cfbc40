#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/io/cl/apt_writer.h"

#include <algorithm>

namespace bladeaxis::io::cl {
namespace {

// Tool sizes are written with enough digits that CUTTER/2r,r reads back as a ball end.
constexpr int kToolDecimals = 12;
constexpr int kMaxDecimals = 17;

// A comment or part name must stay on one line and must not end in a continuation `$`.
std::string oneLine(std::string_view text) {
    std::string line(text);
    std::replace_if(
        line.begin(), line.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    while (!line.empty() && (line.back() == '$' || line.back() == ' ')) {
        line.pop_back();
    }
    return line;
}

void appendGoto(std::string& out, const toolpath::ClRecord& record, int decimals) {
    const Vec3 axis = record.axis.normalized();
    out += "GOTO/";
    out += formatFixed(record.tip.x(), decimals);
    out += ',';
    out += formatFixed(record.tip.y(), decimals);
    out += ',';
    out += formatFixed(record.tip.z(), decimals);
    out += ',';
    out += formatFixed(axis.x(), decimals);
    out += ',';
    out += formatFixed(axis.y(), decimals);
    out += ',';
    out += formatFixed(axis.z(), decimals);
    out += '\n';
}

void appendHeader(std::string& out, const toolpath::Toolpath& path, const AptEmitOptions& options) {
    out += "PARTNO " + oneLine(options.partName) + "\n";
    for (const std::string& comment : options.comments) {
        out += "$$ " + oneLine(comment) + "\n";
    }
    out += "UNITS/MM\n";
    const std::optional<double> radius = options.toolRadius ? options.toolRadius : path.toolRadius;
    if (radius) {
        out += "CUTTER/" + formatTrimmed(2.0 * *radius, kToolDecimals) + "," +
               formatTrimmed(*radius, kToolDecimals) + "\n";
    }
    out += "MULTAX/ON\n";
}

} // namespace

std::string emitApt(const toolpath::Toolpath& path, const AptEmitOptions& options) {
    const int decimals = std::clamp(options.decimals, 0, kMaxDecimals);
    std::string out;
    out.reserve(128 + path.records.size() * static_cast<std::size_t>(40 + 6 * decimals));
    appendHeader(out, path, options);
    std::string lastFeed;
    for (const toolpath::ClRecord& record : path.records) {
        if (record.motion == toolpath::MotionKind::Rapid) {
            out += "RAPID\n";
        } else if (record.feed > 0.0) {
            // FEDRAT only when its printed value changes, as a post-processor expects.
            std::string feed = formatFixed(units::perSecondToPerMinute(record.feed), decimals);
            if (feed != lastFeed) {
                out += "FEDRAT/MMPM," + feed + "\n";
                lastFeed = std::move(feed);
            }
        }
        appendGoto(out, record, decimals);
    }
    out += "END\nFINI\n";
    return out;
}

} // namespace bladeaxis::io::cl
