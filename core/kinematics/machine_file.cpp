#include "core/kinematics/machine_file.h"

#include "core/base/file_io.h"
#include "core/base/json_key_lines.h"
#include "core/base/nearest_name.h"
#include "core/base/units.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <optional>
#include <ranges>
#include <span>
#include <vector>

#include "generated/machine_file_keys.h"

namespace bladeaxis::kinematics {

namespace {

using Json = nlohmann::json;

constexpr const char* kSchema = "bladeaxis-machine/1";

// The largest length a machine file may give (an offset, the pivot, a linear travel limit), in
// mm: ten metres is beyond any machine that turns a blade, and keeps every position the chain
// computes far inside the digits a program's coordinates carry (a 1e10 mm offset came back
// from the written program as "does not read back", an internal error).
constexpr double kMaxMachineLengthMm = 10000.0;

std::string lengthRange() {
    return "[-" + std::to_string(static_cast<int>(kMaxMachineLengthMm)) + ", " +
           std::to_string(static_cast<int>(kMaxMachineLengthMm)) + "] mm";
}

bool isMachineLength(double value) {
    return std::abs(value) <= kMaxMachineLengthMm;
}

std::vector<std::string> splitPath(std::string_view dotted) {
    std::vector<std::string> segments;
    for (const auto segment : std::views::split(dotted, '.')) {
        segments.emplace_back(segment.begin(), segment.end());
    }
    return segments;
}

// The keys each object of a machine file may hold are its schema's (generated from
// resources/schemas/machine-file.schema.json, docs/machine-file.md). A key outside them was
// ignored, so "max_mmm" silently dropped the travel check: it is refused.
using file_keys::kAxisLetters;
using file_keys::kControllerKeys;
using file_keys::kIncrementKeys;
using file_keys::kKinematicsKeys;
using file_keys::kLinearAxisKeys;
using file_keys::kTableAxisKeys;
using file_keys::kTopKeys;

// A head axis takes a table axis's keys but its mode: only the table turns modulo.
bool isHeadAxisKey(std::string_view key) {
    return key != "mode";
}

class MachineReader {
  public:
    MachineReader(std::string_view text, std::string_view file) : m_text(text), m_file(file) {}

    Result<MachineModel> read(const Json& root);

  private:
    // `path` is the value's JSON path, "axes.Z.max_mm": its key's line is the one named.
    std::unexpected<Error> fail(std::string_view path, const std::string& what) const {
        return failAt(splitPath(path), what);
    }
    std::unexpected<Error> failAt(const std::vector<std::string>& path,
                                  const std::string& what) const;
    Status knownKeys(const Json& object, const std::vector<std::string>& path,
                     std::span<const std::string_view> known) const;
    Result<double> number(const Json& object, std::string_view path, const char* key,
                          std::optional<double> fallback, bool positive) const;
    Result<AxisLimits> axis(const Json& axes, char letter, bool rotary) const;
    Status axisKeys(const Json& axes, char letter, AxisId id) const;
    Status chain(const Json& root, MachineModel& machine) const;
    Status axes(const Json& root, MachineModel& machine) const;
    Status numberRules(const Json& root, NumberRules& rules) const;
    Status controller(const Json& root, ControllerModel& controller) const;

    std::string_view m_text;
    std::string m_file;
};

// A missing key has no line of its own: its object's line is named instead.
std::unexpected<Error> MachineReader::failAt(const std::vector<std::string>& path,
                                             const std::string& what) const {
    int line = 0;
    for (std::size_t length = path.size(); line == 0 && length > 0; --length) {
        line = lineOfJsonKey(m_text, std::span(path).first(length));
    }
    return makeError(ErrorCode::MachineFile, jsonKeyPathText(path) + ": " + what,
                     {m_file, line, 0});
}

Status MachineReader::knownKeys(const Json& object, const std::vector<std::string>& path,
                                std::span<const std::string_view> known) const {
    for (const auto& [key, unused] : object.items()) {
        if (std::ranges::find(known, key) != known.end()) {
            continue;
        }
        const auto nearest = nearestName(key, known);
        std::vector<std::string> keyPath = path;
        keyPath.push_back(key);
        return failAt(keyPath, "unknown key in a machine file (docs/machine-file.md)" +
                                   (nearest ? "; did you mean \"" + std::string(*nearest) + "\"?"
                                            : std::string()));
    }
    return {};
}

Result<double> MachineReader::number(const Json& object, std::string_view path, const char* key,
                                     std::optional<double> fallback, bool positive) const {
    const std::string fullPath = std::string(path) + "." + key;
    if (!object.contains(key)) {
        if (fallback) {
            return *fallback;
        }
        return fail(fullPath, "missing, expected a number");
    }
    const Json& value = object.at(key);
    if (!value.is_number()) {
        return fail(fullPath, "expected a number, got " + value.dump());
    }
    const double number = value.get<double>();
    if (!std::isfinite(number) || (positive && !(number > 0.0))) {
        return fail(fullPath, "expected a positive number, got " + value.dump());
    }
    return number;
}

Result<AxisLimits> MachineReader::axis(const Json& axes, char letter, bool rotary) const {
    const std::string name(1, letter);
    const std::string path = "axes." + name;
    if (!axes.contains(name) || !axes.at(name).is_object()) {
        return fail(path, "missing, expected an object with the axis limits");
    }
    const Json& object = axes.at(name);
    // Linear axes in mm, rotary in degrees in the file; converted to rad here.
    const double scale = rotary ? units::degToRad(1.0) : 1.0;
    const char* unitLength = rotary ? "deg" : "mm";
    auto key = [&](const char* stem) { return std::string(stem) + "_" + unitLength; };
    AxisLimits limits;
    const std::string velocityKey = key("velocity") + "_s";
    const std::string accelerationKey = key("acceleration") + "_s2";
    const std::string jerkKey = key("jerk") + "_s3";
    const std::string backlashKey = key("backlash");
    auto velocity = number(object, path, velocityKey.c_str(), std::nullopt, true);
    auto acceleration = number(object, path, accelerationKey.c_str(), std::nullopt, true);
    auto jerk = number(object, path, jerkKey.c_str(), std::nullopt, true);
    auto backlash = number(object, path, backlashKey.c_str(), 0.0, false);
    for (const auto* value : {&velocity, &acceleration, &jerk, &backlash}) {
        if (!value->has_value()) {
            return std::unexpected(value->error());
        }
    }
    limits.velocity = *velocity * scale;
    limits.acceleration = *acceleration * scale;
    limits.jerk = *jerk * scale;
    limits.backlash = *backlash * scale;
    if (*backlash < 0.0) {
        return fail(path + "." + backlashKey, "expected a number >= 0");
    }
    const std::string minKey = key("min");
    const std::string maxKey = key("max");
    if (object.contains(minKey) || object.contains(maxKey)) {
        auto min = number(object, path, minKey.c_str(), std::nullopt, false);
        if (!min) {
            return std::unexpected(min.error());
        }
        auto max = number(object, path, maxKey.c_str(), std::nullopt, false);
        if (!max) {
            return std::unexpected(max.error());
        }
        if (!(*max > *min)) {
            return fail(path + "." + maxKey, "expected max > min");
        }
        if (!rotary && !(isMachineLength(*min) && isMachineLength(*max))) {
            const std::string& bad = isMachineLength(*min) ? maxKey : minKey;
            return fail(path + "." + bad, "expected a length in " + lengthRange());
        }
        limits.hasTravel = true;
        limits.min = *min * scale;
        limits.max = *max * scale;
    }
    return limits;
}

// A linear axis takes _mm keys, a rotary one _deg keys; only the table turns modulo.
Status MachineReader::axisKeys(const Json& axes, char letter, AxisId id) const {
    const std::string name(1, letter);
    if (!axes.contains(name) || !axes.at(name).is_object()) {
        return {}; // axis() names what is missing
    }
    const bool rotary = isRotary(id);
    std::vector<std::string_view> known(
        rotary ? std::begin(kTableAxisKeys) : std::begin(kLinearAxisKeys),
        rotary ? std::end(kTableAxisKeys) : std::end(kLinearAxisKeys));
    if (rotary && id != AxisId::A) {
        std::erase_if(known, [](std::string_view key) { return !isHeadAxisKey(key); });
    }
    // "min_deg" on a linear axis is three edits from "min_mm": the unit's counterpart is named.
    const auto [unit, otherUnit] = rotary ? std::pair{"_deg", "_mm"} : std::pair{"_mm", "_deg"};
    for (const auto& [key, unused] : axes.at(name).items()) {
        const std::size_t at = key.find(otherUnit);
        if (at == std::string::npos) {
            continue;
        }
        const std::string meant =
            key.substr(0, at) + unit + key.substr(at + std::strlen(otherUnit));
        if (std::ranges::find(known, meant) != known.end()) {
            return failAt({"axes", name, key},
                          std::string(rotary ? "a rotary axis takes _deg keys"
                                             : "a linear axis takes _mm keys") +
                              " (docs/machine-file.md); did you mean \"" + meant + "\"?");
        }
    }
    return knownKeys(axes.at(name), {"axes", name}, known);
}

struct LayoutDescription {
    Layout layout;
    const char* description;
};
constexpr std::array<LayoutDescription, 4> kLayouts{{
    {Layout::TableAHeadB, "rotary table A about X, head B about Y"},
    {Layout::TableA, "rotary table A about X, fixed head"},
    {Layout::TableBHeadA, "rotary table B about Y, head A about X"},
    {Layout::TableB, "rotary table B about Y, fixed head"},
}};

std::optional<Layout> layoutNamed(std::string_view type) {
    for (const LayoutDescription& entry : kLayouts) {
        if (type == layoutName(entry.layout)) {
            return entry.layout;
        }
    }
    return std::nullopt;
}

std::string layoutChoices() {
    std::string text;
    for (const LayoutDescription& entry : kLayouts) {
        text += (text.empty() ? "" : ", ") + std::string("\"") + layoutName(entry.layout) + "\" (" +
                entry.description + ")";
    }
    return text;
}

Status MachineReader::chain(const Json& root, MachineModel& machine) const {
    if (!root.contains("kinematics") || !root.at("kinematics").is_object()) {
        return fail("kinematics", "missing, expected an object");
    }
    const Json& object = root.at("kinematics");
    if (auto status = knownKeys(object, {"kinematics"}, kKinematicsKeys); !status) {
        return status;
    }
    const std::string type = object.value("type", "");
    const std::optional<Layout> layout = layoutNamed(type);
    if (!layout) {
        return fail("kinematics.type",
                    "expected one of " + layoutChoices() + ", got \"" + type + "\"");
    }
    machine.layout = *layout;
    TableAHeadB& chain = machine.chain;
    auto pivot = number(object, "kinematics", "pivot_length_mm", 0.0, false);
    if (!pivot) {
        return std::unexpected(pivot.error());
    }
    if (!isMachineLength(*pivot)) {
        return fail("kinematics.pivot_length_mm", "expected a length in " + lengthRange() +
                                                      ", got " +
                                                      object.at("pivot_length_mm").dump());
    }
    chain.pivotLength = *pivot;
    for (const auto& [key, target] : {std::pair{"table_offset_mm", &chain.tableOffset},
                                      std::pair{"head_offset_mm", &chain.headOffset}}) {
        if (!object.contains(key)) {
            continue;
        }
        const Json& value = object.at(key);
        if (!value.is_array() || value.size() != 3 || !value[0].is_number() ||
            !value[1].is_number() || !value[2].is_number()) {
            return fail(std::string("kinematics.") + key, "expected [x, y, z] in mm");
        }
        if (!std::ranges::all_of(value,
                                 [](const Json& v) { return isMachineLength(v.get<double>()); })) {
            return fail(std::string("kinematics.") + key,
                        "expected each of [x, y, z] in " + lengthRange() + ", got " + value.dump());
        }
        // Given in machine coordinates; the chain works in the engine's frame.
        *target = machine.toEngineFrame(
            Vec3(value[0].get<double>(), value[1].get<double>(), value[2].get<double>()));
    }
    // "a_sign" and "b_sign" name the program's letters: on a table-B machine b_sign is the
    // table's and a_sign the head's.
    for (const auto& [axis, target] :
         {std::pair{AxisId::A, &chain.aSign}, std::pair{AxisId::B, &chain.bSign}}) {
        const std::string key =
            std::string(1, static_cast<char>(std::tolower(machine.letter(axis)))) + "_sign";
        // Compared as a double: a huge number converted to int first would be undefined.
        const double sign = !object.contains(key)        ? 1.0
                            : object.at(key).is_number() ? object.at(key).get<double>()
                                                         : 0.0;
        if (sign != 1.0 && sign != -1.0) {
            return fail("kinematics." + key, "expected 1 or -1");
        }
        *target = sign > 0.0 ? 1 : -1;
    }
    return {};
}

// The file names axes by the program's letters; each becomes the engine axis its word drives.
// A word read with the opposite sign (a table-B machine's X) has its travel mirrored.
Status MachineReader::axes(const Json& root, MachineModel& machine) const {
    if (!root.contains("axes") || !root.at("axes").is_object()) {
        return fail("axes", "missing, expected an object with X, Y, Z and the rotary axes");
    }
    const std::string tilt(1, machine.letter(AxisId::B));
    if (!machine.hasB() && root.at("axes").contains(tilt)) {
        return fail("axes." + tilt, "the machine has a fixed head: expected no " + tilt + " axis");
    }
    if (auto status = knownKeys(root.at("axes"), {"axes"}, kAxisLetters); !status) {
        return status;
    }
    for (AxisId id : kAllAxes) {
        if (id == AxisId::B && !machine.hasB()) {
            // Never binding: the tilt stays 0. The table's dynamics keep every ratio finite.
            continue;
        }
        if (auto status = axisKeys(root.at("axes"), machine.letter(id), id); !status) {
            return status;
        }
        auto limits = axis(root.at("axes"), machine.letter(id), isRotary(id));
        if (!limits) {
            return std::unexpected(limits.error());
        }
        if (machine.programWord(id).sign < 0.0) {
            std::swap(limits->min, limits->max);
            limits->min = -limits->min;
            limits->max = -limits->max;
        }
        machine.limit(id) = *limits;
    }
    if (!machine.hasB()) {
        machine.limit(AxisId::B) = machine.limit(AxisId::A);
        machine.limit(AxisId::B).hasTravel = false;
        machine.limit(AxisId::B).backlash = 0.0;
    }
    return {};
}

Status MachineReader::numberRules(const Json& root, NumberRules& rules) const {
    if (root.contains("integer_words")) {
        const Json& value = root.at("integer_words");
        const std::string rule = value.is_string() ? value.get<std::string>() : "";
        if (rule == "refuse_mixed") {
            rules.integerWords = IntegerWords::RefuseMixed;
        } else if (rule == "units") {
            rules.integerWords = IntegerWords::Units;
        } else if (rule == "increments") {
            rules.integerWords = IntegerWords::Increments;
        } else {
            return fail("integer_words",
                        "expected \"refuse_mixed\", \"units\" or \"increments\", got " +
                            value.dump());
        }
    }
    if (!root.contains("least_input_increment")) {
        return {};
    }
    const Json& increments = root.at("least_input_increment");
    if (!increments.is_object()) {
        return fail("least_input_increment",
                    "expected an object {\"mm\": 0.001, \"inch\": 0.0001, \"deg\": 0.001}");
    }
    if (auto status = knownKeys(increments, {"least_input_increment"}, kIncrementKeys); !status) {
        return status;
    }
    for (const auto& [key, target] :
         {std::pair{"mm", &rules.incrementMm}, std::pair{"inch", &rules.incrementInch},
          std::pair{"deg", &rules.incrementDeg}}) {
        auto value = number(increments, "least_input_increment", key, *target, true);
        if (!value) {
            return std::unexpected(value.error());
        }
        *target = *value;
    }
    return {};
}

// "controller": {"planner": "look-ahead" | "block-by-block"}: which cycle-time model the report
// marks as the machine's.
Status MachineReader::controller(const Json& root, ControllerModel& controller) const {
    if (!root.contains("controller")) {
        return {};
    }
    const Json& value = root.at("controller");
    if (!value.is_object()) {
        return fail("controller",
                    "expected an object such as {\"planner\": \"block-by-block\"}, got " +
                        value.dump());
    }
    if (auto status = knownKeys(value, {"controller"}, kControllerKeys); !status) {
        return status;
    }
    if (value.contains("planner")) {
        const Json& planner = value.at("planner");
        const auto named =
            planner.is_string() ? plannerNamed(planner.get<std::string>()) : std::nullopt;
        if (!named) {
            return fail("controller.planner",
                        "expected \"look-ahead\" or \"block-by-block\", got " + planner.dump());
        }
        controller.planner = *named;
    }
    return {};
}

Result<MachineModel> MachineReader::read(const Json& root) {
    if (!root.is_object()) {
        return makeError(ErrorCode::MachineFile, "expected a JSON object at the top level",
                         {m_file, 1, 1});
    }
    if (root.value("schema", "") != kSchema) {
        return fail("schema", std::string("expected \"") + kSchema + "\"");
    }
    if (auto status = knownKeys(root, {}, kTopKeys); !status) {
        return std::unexpected(status.error());
    }
    MachineModel machine;
    machine.sourceFile = m_file;
    machine.name = root.value("name", "unnamed machine");
    if (auto status = chain(root, machine); !status) {
        return std::unexpected(status.error());
    }
    if (auto status = axes(root, machine); !status) {
        return std::unexpected(status.error());
    }
    if (auto status = numberRules(root, machine.numbers); !status) {
        return std::unexpected(status.error());
    }
    if (root.contains("feed_per_minute")) {
        const Json& value = root.at("feed_per_minute");
        const std::string meaning = value.is_string() ? value.get<std::string>() : "";
        if (meaning != "path" && meaning != "combined_axes") {
            return fail("feed_per_minute",
                        "expected \"path\" or \"combined_axes\", got " + value.dump());
        }
        machine.feedMeaning = meaning == "path" ? FeedMeaning::Path : FeedMeaning::CombinedAxes;
    }
    if (auto status = controller(root, machine.controller); !status) {
        return std::unexpected(status.error());
    }
    const std::string table(1, machine.letter(AxisId::A));
    const std::string mode = root.at("axes").at(table).value("mode", "continuous");
    if (mode == "continuous") {
        machine.aMode = RotaryMode::Continuous;
    } else if (mode == "modulo") {
        machine.aMode = RotaryMode::Modulo;
    } else {
        return fail("axes." + table + ".mode",
                    "expected \"continuous\" or \"modulo\", got \"" + mode + "\"");
    }
    return machine;
}

// Converts nlohmann's byte offset of a syntax error into line and column.
SourceLocation locateByte(std::string_view text, std::size_t byte, const std::string& file) {
    int line = 1;
    int column = 1;
    for (std::size_t i = 0; i < std::min(byte, text.size()); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return {file, line, std::max(1, column - 1)};
}

} // namespace

Result<MachineModel> parseMachineJson(std::string_view text, std::string_view fileName) {
    const std::string file(fileName);
    Json root;
    try {
        root = Json::parse(text);
    } catch (const Json::out_of_range& error) {
        // A number beyond double ("1e400"): nlohmann reports it as out of range, not as syntax.
        return makeError(ErrorCode::MachineFile,
                         std::string("invalid JSON: a number is out of range (") + error.what() +
                             ")",
                         {file, 0, 0});
    } catch (const Json::parse_error& error) {
        std::string what = error.what();
        // nlohmann's message starts with "[json.exception.parse_error.101] parse error at line..."
        const std::size_t colon = what.rfind(": ");
        const std::string detail = colon == std::string::npos ? what : what.substr(colon + 2);
        return makeError(ErrorCode::MachineFile, "invalid JSON: " + detail,
                         locateByte(text, error.byte, file));
    }
    // A value of the wrong type where the reader asks nlohmann for one ("name": 5, a sign of
    // "1") throws; it is the file's error, not a bug, and gets the machine-file exit code.
    try {
        return MachineReader(text, file).read(root);
    } catch (const Json::exception& error) {
        std::string what = error.what();
        const std::size_t bracket = what.find("] ");
        return makeError(ErrorCode::MachineFile,
                         "unexpected value: " +
                             (bracket == std::string::npos ? what : what.substr(bracket + 2)),
                         {file, 0, 0});
    }
}

Result<MachineModel> loadMachineFile(const std::filesystem::path& path) {
    auto text = readTextFile(path);
    if (!text) {
        return std::unexpected(text.error());
    }
    return parseMachineJson(*text, path.string());
}

} // namespace bladeaxis::kinematics
