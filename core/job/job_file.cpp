#include "core/job/job_file.h"

#include "core/base/file_io.h"
#include "core/base/json_key_lines.h"
#include "core/base/nearest_name.h"
#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/job/parameter_schema.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <optional>
#include <span>
#include <string_view>
#include <utility>

#include "generated/job_file_keys.h"

namespace bladeaxis::job {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

constexpr const char* kSchema = "bladeaxis-job/1";

class JobReader {
  public:
    JobReader(std::string_view text, const fs::path& path) : m_text(text), m_path(path) {}

    Status read(const Json& root, JobSpec& spec) const;

  private:
    // At the key's line, named as the file names it: "parameters.margin_deg",
    // "layer_edits[2].preset".
    std::unexpected<Error> failAt(const std::vector<std::string>& keyPath,
                                  const std::string& what) const {
        return makeError(ErrorCode::InvalidArgument, jsonKeyPathText(keyPath) + ": " + what,
                         {m_path.string(), lineOfJsonKey(m_text, keyPath), 0});
    }
    std::unexpected<Error> fail(std::string_view key, const std::string& what) const {
        return failAt({std::string(key)}, what);
    }
    Result<fs::path> pathValue(const Json& root, const char* key) const;
    Result<double> positiveNumber(const Json& root, const char* key) const;
    Result<Vec3> triple(const Json& root, const char* key, const std::string& expected) const;
    Status parameters(const Json& object, JobSpec& spec) const;
    Status analysisOptions(const Json& root, JobSpec& spec) const;
    Status programReading(const Json& root, JobSpec& spec) const;
    Status confineOutputs(const Json& root, const JobSpec& spec) const;
    Status knownKeys(const Json& object, std::span<const std::string_view> known,
                     std::string_view where, const std::vector<std::string>& at = {}) const;
    Status layerEdits(const Json& list, JobSpec& spec) const;
    Result<scheduling::LayerOverride> layerEdit(const Json& object, std::size_t index) const;
    Result<std::vector<Vec2>> keyPoints(const Json& list, const std::vector<std::string>& at) const;

    std::string_view m_text;
    fs::path m_path;
};

Result<fs::path> JobReader::pathValue(const Json& root, const char* key) const {
    const Json& value = root.at(key);
    if (!value.is_string() || value.get<std::string>().empty()) {
        return fail(key, "expected a file path as a string");
    }
    // "victim.json\u0000.nc" would be cut at the NUL by the system and name victim.json.
    if (value.get<std::string>().find('\0') != std::string::npos) {
        return fail(key, "a path with a NUL character (\\u0000), which the system would cut "
                         "short at the NUL");
    }
    const fs::path path = value.get<std::string>();
    return path.is_absolute() ? path : m_path.parent_path() / path;
}

namespace {

// Both made absolute first: weakly_canonical keeps a trailing "." of a bare relative folder
// (a job file named without a folder), which no output path would then be inside. The path's
// links are followed first, dangling ones too: weakly_canonical stops at a link whose target
// does not exist yet, and the write would follow it out of the folder.
bool isInside(const fs::path& path, const fs::path& folder) {
    std::error_code ec;
    const fs::path resolved = fs::weakly_canonical(fs::absolute(followLinks(path), ec), ec);
    const fs::path base = fs::weakly_canonical(fs::absolute(folder, ec).lexically_normal(), ec);
    const auto [end, unused] =
        std::mismatch(base.begin(), base.end(), resolved.begin(), resolved.end());
    return end == base.end();
}

std::string lowerExtension(const fs::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

} // namespace

// A job file may come from someone else: it writes only inside its own folder (links
// resolved), and its program output may replace only a program like the input (same
// extension). Outputs given on the command line are the user's own choice and replace these.
Status JobReader::confineOutputs(const Json& root, const JobSpec& spec) const {
    const fs::path folder = m_path.has_parent_path() ? m_path.parent_path() : fs::path(".");
    for (const auto& [key, path] :
         {std::pair{"output_program", &spec.outputProgram}, std::pair{"output_cl", &spec.outputCl},
          std::pair{"output_dir", &spec.outputDir}}) {
        if (root.contains(key) && !isInside(*path, folder)) {
            return fail(key, "a job file writes only inside its own folder (" + folder.string() +
                                 "), not to " + path->string() +
                                 "; give the output on the command line (-o, --cl-output, "
                                 "--out) to write elsewhere");
        }
    }
    std::error_code ec;
    const fs::path input = spec.demo ? fs::path("demo_blade.nc") : spec.program;
    if (root.contains("output_program") && fs::exists(spec.outputProgram, ec) &&
        lowerExtension(spec.outputProgram) != lowerExtension(input)) {
        return fail("output_program", "would replace " + spec.outputProgram.string() +
                                          ", which is not a program like the input (" +
                                          input.filename().string() +
                                          "); give -o on the command line to replace it");
    }
    return {};
}

namespace {

// The keys a job file, its parameters and its layer edits may hold are its schema's (generated
// from resources/schemas/job-file.schema.json, docs/job-file.md).
using file_keys::kJobKeys;
using file_keys::kLayerEditKeys;
using file_keys::kParameterKeys;

// "; did you mean \"output_cl\"?" for a key near a known one (core/base/nearest_name.h).
std::string suggestion(std::string_view key, std::span<const std::string_view> known) {
    const auto nearest = nearestName(key, known);
    return nearest ? "; did you mean \"" + std::string(*nearest) + "\"?" : "";
}

} // namespace

// A key the reader does not know was ignored, so a misspelt "output_programm" wrote nothing
// and a key a newer version reads was silently dropped: it is refused at its line.
Status JobReader::knownKeys(const Json& object, std::span<const std::string_view> known,
                            std::string_view where, const std::vector<std::string>& at) const {
    if (!object.is_object()) {
        return {};
    }
    for (const auto& [key, value] : object.items()) {
        if (std::ranges::find(known, key) == known.end()) {
            std::vector<std::string> keyPath = at;
            keyPath.push_back(key);
            return failAt(keyPath, "unknown key in " + std::string(where) + " (docs/job-file.md)" +
                                       suggestion(key, known));
        }
    }
    return {};
}

Result<double> JobReader::positiveNumber(const Json& root, const char* key) const {
    const Json& value = root.at(key);
    if (!value.is_number() || !(value.get<double>() > 0.0)) {
        return fail(key, "expected a positive number, got " + value.dump());
    }
    return value.get<double>();
}

Result<Vec3> JobReader::triple(const Json& root, const char* key,
                               const std::string& expected) const {
    const Json& value = root.at(key);
    if (!value.is_array() || value.size() != 3 ||
        !std::ranges::all_of(value, [](const Json& v) { return v.is_number(); })) {
        return fail(key, expected);
    }
    return Vec3(value[0].get<double>(), value[1].get<double>(), value[2].get<double>());
}

Status JobReader::parameters(const Json& object, JobSpec& spec) const {
    if (!object.is_object()) {
        return fail("parameters", "expected an object of scheduling parameters");
    }
    if (auto status =
            knownKeys(object, kParameterKeys, "the scheduling parameters", {"parameters"});
        !status) {
        return status;
    }
    for (const auto& [key, value] : object.items()) {
        const ParameterInfo* info = findParameter(key);
        if (info == nullptr) { // in the schema but not in the parameter schema: a bug
            return makeError(ErrorCode::Internal, "the scheduling parameter " + key +
                                                      " of the job-file schema is not known");
        }
        std::string text;
        if (value.is_string()) {
            text = value.get<std::string>();
        } else if (value.is_boolean()) {
            text = value.get<bool>() ? "true" : "false";
        } else if (value.is_number()) {
            text = formatShortest(value.get<double>());
        } else {
            return failAt({"parameters", key}, "expected a number, a string or true/false");
        }
        if (auto status = info->set(spec.parameters, text); !status) {
            return failAt({"parameters", key}, status.error().message.substr(key.size() + 2));
        }
    }
    return {};
}

// How the program is read and when it counts as a four-axis blade pass.
Status JobReader::programReading(const Json& root, JobSpec& spec) const {
    if (root.contains("angle_unit")) {
        const Json& value = root.at("angle_unit");
        const std::string unit = value.is_string() ? value.get<std::string>() : "";
        if (unit != "deg" && unit != "rad") {
            return fail("angle_unit", "expected \"deg\" or \"rad\"");
        }
        spec.read.angleUnit = unit == "deg" ? io::AngleUnit::Degrees : io::AngleUnit::Radians;
    }
    if (root.contains("dialect")) {
        const Json& value = root.at("dialect");
        const std::string name = value.is_string() ? value.get<std::string>() : "";
        if (name != "iso" && name != "sinumerik" && name != "heidenhain") {
            return fail("dialect", "expected \"iso\", \"sinumerik\" or \"heidenhain\"");
        }
        spec.read.dialect = name == "sinumerik"    ? io::NcDialect::Sinumerik
                            : name == "heidenhain" ? io::NcDialect::Heidenhain
                                                   : io::NcDialect::Iso;
    }
    if (root.contains("columns")) {
        if (!root.at("columns").is_string()) {
            return fail("columns", "expected the column names, e.g. \"x,y,z,i,j,k\"");
        }
        spec.read.tableColumns = root.at("columns").get<std::string>();
    }
    for (const auto& [key, target] :
         {std::pair{"b_tolerance_deg", &spec.check.tiltToleranceRad},
          std::pair{"channel_tolerance_deg", &spec.check.channelToleranceRad}}) {
        if (root.contains(key)) {
            auto value = positiveNumber(root, key);
            if (!value) {
                return std::unexpected(value.error());
            }
            *target = units::degToRad(*value);
        }
    }
    return {};
}

Status JobReader::analysisOptions(const Json& root, JobSpec& spec) const {
    if (root.contains("feed_reference")) {
        const std::string value = root.at("feed_reference").is_string()
                                      ? root.at("feed_reference").get<std::string>()
                                      : "";
        if (value != "tip" && value != "centre") {
            return fail("feed_reference", "expected \"tip\" or \"centre\"");
        }
        spec.analysis.feedReference =
            value == "tip" ? analysis::FeedReference::Tip : analysis::FeedReference::Centre;
    }
    if (root.contains("feed_mm_min")) {
        auto feed = positiveNumber(root, "feed_mm_min");
        if (!feed) {
            return std::unexpected(feed.error());
        }
        spec.analysis.feedOverride = units::perMinuteToPerSecond(*feed);
        spec.read.feedMmPerS = spec.analysis.feedOverride; // for CL data that programs none
    }
    if (auto status = programReading(root, spec); !status) {
        return status;
    }
    if (root.contains("derivatives")) {
        const Json& value = root.at("derivatives");
        const auto method = value.is_string()
                                ? analysis::derivativeMethodNamed(value.get<std::string>())
                                : std::optional<analysis::DerivativeMethod>();
        if (!method) {
            return fail("derivatives", "expected \"spline\", \"raw-spline\", \"fd\" or \"filter\"");
        }
        spec.analysis.method = *method;
    }
    if (root.contains("filter_ms")) {
        auto window = positiveNumber(root, "filter_ms");
        if (!window) {
            return std::unexpected(window.error());
        }
        spec.analysis.filterSeconds = *window / 1000.0;
    }
    return {};
}

Result<std::vector<Vec2>> JobReader::keyPoints(const Json& list,
                                               const std::vector<std::string>& at) const {
    std::vector<Vec2> points;
    if (!list.is_array()) {
        return failAt(at, "expected a list of [S mm, theta rad] pairs");
    }
    if (list.size() > kMaxKeyPointsPerLayer) {
        return failAt(at, "expected at most " + std::to_string(kMaxKeyPointsPerLayer) +
                              " key points in a layer, found " + std::to_string(list.size()));
    }
    for (const Json& pair : list) {
        if (!pair.is_array() || pair.size() != 2 || !pair[0].is_number() || !pair[1].is_number()) {
            return failAt(at, "expected [S mm, theta rad], got " + pair.dump());
        }
        points.emplace_back(pair[0].get<double>(), pair[1].get<double>());
    }
    return points;
}

Result<scheduling::LayerOverride> JobReader::layerEdit(const Json& object,
                                                       std::size_t index) const {
    const std::vector<std::string> at{"layer_edits", std::to_string(index)};
    const auto keyAt = [&at](const char* key) {
        std::vector<std::string> keyPath = at;
        keyPath.emplace_back(key);
        return keyPath;
    };
    scheduling::LayerOverride edit;
    if (!object.is_object() || !object.contains("layer") ||
        !object.at("layer").is_number_unsigned()) {
        return failAt(at, "expected an object with \"layer\": a layer number");
    }
    if (auto status = knownKeys(object, kLayerEditKeys, "a layer edit", at); !status) {
        return std::unexpected(status.error());
    }
    edit.layer = object.at("layer").get<std::size_t>();
    if (object.contains("preset")) {
        const Json& preset = object.at("preset");
        if (!preset.is_string() || !presetParameters(preset.get<std::string>())) {
            return failAt(keyAt("preset"), "expected \"faithful\" or \"best\"");
        }
        edit.preset = presetParameters(preset.get<std::string>())->preset;
    }
    if (object.contains("margin_deg")) {
        if (!object.at("margin_deg").is_number()) {
            return failAt(keyAt("margin_deg"), "expected a number of degrees");
        }
        edit.marginRad = units::degToRad(object.at("margin_deg").get<double>());
    }
    if (object.contains("eps_rule")) {
        const std::string rule = object.at("eps_rule").is_string()
                                     ? object.at("eps_rule").get<std::string>()
                                     : std::string();
        if (rule != "paper" && rule != "exact") {
            return failAt(keyAt("eps_rule"), "expected \"paper\" or \"exact\"");
        }
        edit.epsilonRule =
            rule == "paper" ? scheduling::EpsilonRule::Paper : scheduling::EpsilonRule::Exact;
    }
    if (object.contains("lead_fraction")) {
        if (!object.at("lead_fraction").is_number()) {
            return failAt(keyAt("lead_fraction"), "expected a number");
        }
        edit.leadFraction = object.at("lead_fraction").get<double>();
    }
    if (object.contains("key_points")) {
        auto points = keyPoints(object.at("key_points"), keyAt("key_points"));
        if (!points) {
            return std::unexpected(points.error());
        }
        edit.keyPoints = std::move(*points);
    }
    return edit;
}

Status JobReader::layerEdits(const Json& list, JobSpec& spec) const {
    if (!list.is_array()) {
        return fail("layer_edits", "expected a list of layer edits");
    }
    if (list.size() > kMaxLayerEdits) {
        return fail("layer_edits", "expected at most " + std::to_string(kMaxLayerEdits) +
                                       " layer edits (one per layer), found " +
                                       std::to_string(list.size()));
    }
    spec.layerEdits.clear();
    for (std::size_t index = 0; index < list.size(); ++index) {
        auto edit = layerEdit(list[index], index);
        if (!edit) {
            return std::unexpected(edit.error());
        }
        spec.layerEdits.push_back(std::move(*edit));
    }
    return {};
}

Status JobReader::read(const Json& root, JobSpec& spec) const {
    const bool schemaNamed = root.is_object() && root.contains("schema") &&
                             root.at("schema").is_string() && root.at("schema") == kSchema;
    if (!schemaNamed) {
        return fail("schema", std::string("expected \"schema\": \"") + kSchema + "\"");
    }
    if (auto status = knownKeys(root, kJobKeys, "a job file"); !status) {
        return status;
    }
    for (const auto& [key, target] :
         {std::pair{"program", &spec.program}, std::pair{"machine", &spec.machineFile},
          std::pair{"cad", &spec.cad.file}, std::pair{"output_program", &spec.outputProgram},
          std::pair{"output_cl", &spec.outputCl}, std::pair{"output_dir", &spec.outputDir}}) {
        if (root.contains(key)) {
            auto path = pathValue(root, key);
            if (!path) {
                return std::unexpected(path.error());
            }
            *target = *path;
        }
    }
    // What the job does: the command line's --demo, --analyse-only, --compare, --no-optimum
    // (before the outputs are confined: the demo's input is the program it generates).
    for (const auto& [key, member, inverted] :
         {std::tuple{"demo", &JobSpec::demo, false},
          std::tuple{"analyse_only", &JobSpec::reschedule, true},
          std::tuple{"compare", &JobSpec::compare, false},
          std::tuple{"compare_optimum", &JobSpec::compareOptimum, false}}) {
        if (root.contains(key)) {
            if (!root.at(key).is_boolean()) {
                return fail(key, "expected true or false");
            }
            spec.*member = root.at(key).get<bool>() != inverted;
        }
    }
    if (auto status = confineOutputs(root, spec); !status) {
        return status;
    }
    if (root.contains("tool_radius_mm")) {
        auto radius = positiveNumber(root, "tool_radius_mm");
        if (!radius) {
            return std::unexpected(radius.error());
        }
        spec.toolRadius = *radius;
    }
    if (root.contains("preset")) {
        auto preset = presetParameters(
            root.at("preset").is_string() ? root.at("preset").get<std::string>() : "");
        if (!preset) {
            return fail("preset", "expected \"faithful\" or \"best\"");
        }
        spec.parameters = *preset;
        spec.presetName = root.at("preset").get<std::string>();
    }
    if (root.contains("parameters")) {
        if (auto status = parameters(root.at("parameters"), spec); !status) {
            return status;
        }
    }
    if (root.contains("cad_translate_mm")) {
        auto translation = triple(root, "cad_translate_mm", "expected [x, y, z] in mm");
        if (!translation) {
            return std::unexpected(translation.error());
        }
        spec.cad.placement.translation = *translation;
    }
    if (root.contains("cad_rotate_deg")) {
        auto angles =
            triple(root, "cad_rotate_deg", "expected [rx, ry, rz] in degrees about X, Y and Z");
        if (!angles) {
            return std::unexpected(angles.error());
        }
        spec.cad.placement.rotationXyz = angles->unaryExpr(&units::degToRad);
    }
    // The tool beyond the ball, for the clearance check (--stick-out, --holder-radius,
    // --holder-length), so that a saved job checks the same tool.
    for (const auto& [key, member] :
         {std::pair{"stick_out_mm", &cad::ToolGeometry::stickOut},
          std::pair{"holder_radius_mm", &cad::ToolGeometry::holderRadius},
          std::pair{"holder_length_mm", &cad::ToolGeometry::holderLength}}) {
        if (root.contains(key)) {
            auto value = positiveNumber(root, key);
            if (!value) {
                return std::unexpected(value.error());
            }
            spec.cad.tool.*member = *value;
        }
    }
    if (root.contains("layer_edits")) {
        if (auto status = layerEdits(root.at("layer_edits"), spec); !status) {
            return status;
        }
    }
    return analysisOptions(root, spec);
}

// Key points are written in rad with the shortest round-trip digits, so a saved edit re-runs
// to the same program bit for bit.
Json layerEditsJson(const std::vector<scheduling::LayerOverride>& edits) {
    Json list = Json::array();
    for (const scheduling::LayerOverride& edit : edits) {
        Json object;
        object["layer"] = edit.layer;
        if (edit.preset) {
            object["preset"] = *edit.preset == scheduling::Preset::Faithful ? "faithful" : "best";
        }
        if (edit.marginRad) {
            object["margin_deg"] = units::radToDeg(*edit.marginRad);
        }
        if (edit.epsilonRule) {
            object["eps_rule"] =
                *edit.epsilonRule == scheduling::EpsilonRule::Paper ? "paper" : "exact";
        }
        if (edit.leadFraction) {
            object["lead_fraction"] = *edit.leadFraction;
        }
        if (!edit.keyPoints.empty()) {
            Json points = Json::array();
            for (const Vec2& point : edit.keyPoints) {
                points.push_back({point.x(), point.y()});
            }
            object["key_points"] = points;
        }
        list.push_back(object);
    }
    return list;
}

} // namespace

Status parseJobJson(std::string_view text, const fs::path& path, JobSpec& spec) {
    const Json root = Json::parse(text, nullptr, false);
    if (root.is_discarded()) {
        return makeError(ErrorCode::InvalidArgument, "invalid JSON in the job file",
                         {path.string()});
    }
    // A value of the wrong type where the reader asks nlohmann for one ("schema": true, a
    // layer number of -1) throws; it is the file's error, not a bug: an invalid argument naming
    // the file, never an internal error.
    try {
        return JobReader(text, path).read(root, spec);
    } catch (const Json::exception& error) {
        const std::string what = error.what();
        const std::size_t bracket = what.find("] ");
        return makeError(ErrorCode::InvalidArgument,
                         "unexpected value in the job file: " +
                             (bracket == std::string::npos ? what : what.substr(bracket + 2)),
                         {path.string()});
    }
}

Status readJobFile(const fs::path& path, JobSpec& spec) {
    std::error_code error;
    const auto size = fs::file_size(path, error);
    if (!error && size > kMaxJobFileBytes) {
        return makeError(ErrorCode::InvalidArgument,
                         "job file too large: " + std::to_string(size) +
                             " bytes, expected at most " + std::to_string(kMaxJobFileBytes) +
                             " (a job names its files and parameters and edits single layers)",
                         {path.string()});
    }
    auto text = readTextFile(path);
    if (!text) {
        return std::unexpected(text.error());
    }
    spec.jobFile = path; // an input too: no output may replace it
    return parseJobJson(*text, path, spec);
}

std::string jobJsonText(const JobSpec& spec, const fs::path& relativeTo) {
    // Keys in the order written: "schema" first, where the desktop's MIME magic looks for it
    // (packaging/bladeaxis-mime.xml searches the first 256 bytes), then the job as a reader
    // follows it. nlohmann::json would sort them and put "schema" after the layer edits.
    nlohmann::ordered_json json;
    json["schema"] = kSchema;
    auto relative = [&](const fs::path& path) {
        return path.lexically_proximate(relativeTo).generic_string();
    };
    if (!spec.program.empty()) {
        json["program"] = relative(spec.program);
    }
    if (spec.demo) {
        json["demo"] = true;
    }
    if (!spec.reschedule) {
        json["analyse_only"] = true;
    }
    if (spec.compare) {
        json["compare"] = true;
        json["compare_optimum"] = spec.compareOptimum;
    }
    if (!spec.cad.file.empty()) {
        json["cad"] = relative(spec.cad.file);
        const Vec3& t = spec.cad.placement.translation;
        json["cad_translate_mm"] = {t.x(), t.y(), t.z()};
        const Vec3 r = spec.cad.placement.rotationXyz.unaryExpr(&units::radToDeg);
        json["cad_rotate_deg"] = {r.x(), r.y(), r.z()};
    }
    json["stick_out_mm"] = spec.cad.tool.stickOut;
    json["holder_radius_mm"] = spec.cad.tool.holderRadius;
    json["holder_length_mm"] = spec.cad.tool.holderLength;
    if (!spec.machineFile.empty()) {
        json["machine"] = relative(spec.machineFile);
    }
    if (spec.toolRadius) {
        json["tool_radius_mm"] = *spec.toolRadius;
    }
    json["preset"] = spec.presetName;
    nlohmann::ordered_json parameters = nlohmann::ordered_json::object();
    for (const ParameterInfo& info : scheduleParameterSchema()) {
        const std::string text = info.get(spec.parameters);
        if (info.kind == ParameterInfo::Kind::Number || info.kind == ParameterInfo::Kind::Integer) {
            parameters[info.key] = parseNumber(text).value_or(0.0);
        } else if (info.kind == ParameterInfo::Kind::Flag) {
            parameters[info.key] = text == "true";
        } else {
            parameters[info.key] = text;
        }
    }
    json["parameters"] = parameters;
    if (!spec.layerEdits.empty()) {
        json["layer_edits"] = layerEditsJson(spec.layerEdits);
    }
    // The analysis settings, so that a saved job re-runs to the same report.
    json["feed_reference"] =
        spec.analysis.feedReference == analysis::FeedReference::Tip ? "tip" : "centre";
    if (spec.analysis.feedOverride > 0.0) {
        json["feed_mm_min"] = units::perSecondToPerMinute(spec.analysis.feedOverride);
    }
    if (spec.read.angleUnit) {
        json["angle_unit"] = io::toString(*spec.read.angleUnit);
    }
    if (spec.read.dialect) {
        json["dialect"] = io::toString(*spec.read.dialect);
    }
    if (spec.read.tableColumns) {
        json["columns"] = *spec.read.tableColumns;
    }
    json["b_tolerance_deg"] = units::radToDeg(spec.check.tiltToleranceRad);
    json["channel_tolerance_deg"] = units::radToDeg(spec.check.channelToleranceRad);
    json["derivatives"] = analysis::nameOf(spec.analysis.method);
    json["filter_ms"] = spec.analysis.filterSeconds * 1000.0;
    if (!spec.outputProgram.empty()) {
        json["output_program"] = relative(spec.outputProgram);
    }
    if (!spec.outputDir.empty()) {
        json["output_dir"] = relative(spec.outputDir);
    }
    return json.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

} // namespace bladeaxis::job
