#include "core/job/parameter_schema.h"

#include "core/base/number_io.h"

#include <cmath>
#include <utility>

namespace bladeaxis::job {

namespace {

using scheduling::ScheduleParameters;
using Kind = ParameterInfo::Kind;

Status outOfDomain(const std::string& key, std::string_view text, const std::string& expected) {
    return makeError(ErrorCode::InvalidArgument,
                     key + ": expected " + expected + ", got '" + std::string(text) + "'");
}

// A real parameter stored in internal units; `scale` converts the user unit to the internal
// one (pi/180 for degrees).
ParameterInfo number(std::string key, std::string unit, std::string help, double min, double max,
                     double ScheduleParameters::*member, double scale = 1.0) {
    ParameterInfo info{
        std::move(key), std::move(unit), std::move(help), Kind::Number, {}, min, max, {}, {}};
    info.get = [member, scale](const ScheduleParameters& p) {
        return formatShortest(p.*member / scale);
    };
    info.set = [member, scale, key = info.key, min, max](ScheduleParameters& p,
                                                         std::string_view text) -> Status {
        const auto value = parseNumber(text);
        if (!value || *value < min || *value > max) {
            return outOfDomain(
                key, text, "a number from " + formatShortest(min) + " to " + formatShortest(max));
        }
        p.*member = *value * scale;
        return {};
    };
    return info;
}

template <class Integer>
ParameterInfo integer(std::string key, std::string help, double min, double max,
                      Integer ScheduleParameters::*member) {
    ParameterInfo info{std::move(key), "", std::move(help), Kind::Integer, {}, min, max, {}, {}};
    info.get = [member](const ScheduleParameters& p) { return std::to_string(p.*member); };
    info.set = [member, key = info.key, min, max](ScheduleParameters& p,
                                                  std::string_view text) -> Status {
        const auto value = parseNumber(text);
        if (!value || std::floor(*value) != *value || *value < min || *value > max) {
            return outOfDomain(key, text,
                               "a whole number from " + formatShortest(min) + " to " +
                                   formatShortest(max));
        }
        p.*member = static_cast<Integer>(*value);
        return {};
    };
    return info;
}

template <class Enum>
ParameterInfo choice(std::string key, std::string help,
                     std::vector<std::pair<std::string, Enum>> options,
                     Enum ScheduleParameters::*member) {
    ParameterInfo info{std::move(key), "", std::move(help), Kind::Choice, {}, 0, 0, {}, {}};
    std::string expected;
    for (const auto& [name, value] : options) {
        info.choices.push_back(name);
        expected += (expected.empty() ? "" : " or ") + name;
    }
    info.get = [member, options](const ScheduleParameters& p) {
        for (const auto& [name, value] : options) {
            if (p.*member == value) {
                return name;
            }
        }
        return std::string("?");
    };
    info.set = [member, options, key = info.key, expected](ScheduleParameters& p,
                                                           std::string_view text) -> Status {
        for (const auto& [name, value] : options) {
            if (text == name) {
                p.*member = value;
                return {};
            }
        }
        return outOfDomain(key, text, expected);
    };
    return info;
}

ParameterInfo flag(std::string key, std::string help, bool ScheduleParameters::*member) {
    ParameterInfo info{
        std::move(key), "", std::move(help), Kind::Flag, {"true", "false"}, 0, 0, {}, {}};
    info.get = [member](const ScheduleParameters& p) {
        return std::string(p.*member ? "true" : "false");
    };
    info.set = [member, key = info.key](ScheduleParameters& p, std::string_view text) -> Status {
        if (text != "true" && text != "false") {
            return outOfDomain(key, text, "true or false");
        }
        p.*member = text == "true";
        return {};
    };
    return info;
}

constexpr double kDeg = 3.14159265358979323846 / 180.0;

std::vector<ParameterInfo> geometryParameters() {
    using P = ScheduleParameters;
    return {
        number("taper_deg", "deg", "Taper half-angle of the shank (§2.3)", 0, 80,
               &P::taperHalfAngleRad, kDeg),
        number("safety_deg", "deg", "Holder/safety angle added to the taper (§2.3)", 0, 80,
               &P::safetyAngleRad, kDeg),
        number("tangent_chord_min_mm", "mm", "Minimum chord for robust tangents l_t (§1.5)", 1e-4,
               100, &P::tangentChordMinMm),
        number("tangent_chord_median_factor", "",
               "l_t is at least this times the median chord (§1.5)", 0, 100,
               &P::tangentChordMedianFactor),
        number("curvature_window_min_mm", "mm", "Minimum curvature smoothing window w (§1.6)", 1e-3,
               1000, &P::curvatureWindowMinMm),
        number("curvature_window_fraction", "", "w as a fraction of one revolution (§1.6)", 0, 1,
               &P::curvatureWindowRevolutionFraction),
        number("curvature_hysteresis_per_mm", "1/mm",
               "Hysteresis kappa_h of the convex/concave state (§1.6)", 0, 1,
               &P::curvatureHysteresisPerMm),
        number("concave_gap_tool_radii", "R",
               "Merge concave runs closer than this many tool radii (§1.6)", 0, 100,
               &P::concaveGapToolRadii),
        number("concave_min_run_tool_radii", "R",
               "Drop concave runs shorter than this many tool radii (§1.6)", 0, 100,
               &P::concaveMinRunToolRadii),
        number("concave_min_run_fraction", "",
               "... or shorter than this fraction of a revolution (§1.6)", 0, 1,
               &P::concaveMinRunRevolutionFraction),
        choice("base_point", "Base point at the concave run's exit or entry (§1.7)",
               std::vector<std::pair<std::string, scheduling::BasePointRule>>{
                   {"exit", scheduling::BasePointRule::Exit},
                   {"entry", scheduling::BasePointRule::Entry}},
               &P::basePoint),
        choice("visibility", "Channel from the local rule of the paper or global visibility (§2.4)",
               std::vector<std::pair<std::string, scheduling::Visibility>>{
                   {"local", scheduling::Visibility::Local},
                   {"global", scheduling::Visibility::Global}},
               &P::visibility),
        flag("lead_band",
             "Narrow the channel to lead angles lead_band_min_deg..max_deg from the surface "
             "normal (§2.4)",
             &P::leadBand),
        number("lead_band_min_deg", "deg", "Smallest lead angle of the lead band (§2.4)", -89, 89,
               &P::leadBandMinRad, kDeg),
        number("lead_band_max_deg", "deg", "Largest lead angle of the lead band (§2.4)", -89, 89,
               &P::leadBandMaxRad, kDeg),
        number("margin_deg", "deg", "Margin m from the channel before the monotone hull (§2.5)", 0,
               45, &P::marginRad, kDeg),
        flag("despike",
             "Replace isolated channel outliers by a local median (§4.6, non-conservative)",
             &P::despike),
        flag("allow_nonmonotone",
             "A layer without a monotone path gets the original projected into the raw channel "
             "and smoothed (A may reverse) instead of keeping the original (§2.5)",
             &P::allowNonmonotone),
    };
}

std::vector<ParameterInfo> curveParameters() {
    using P = ScheduleParameters;
    return {
        choice("lead_mode",
               "Lead-in/lead-out length fixed or searched to minimise peak theta'' (§3.4)",
               std::vector<std::pair<std::string, scheduling::LeadMode>>{
                   {"fixed", scheduling::LeadMode::Fixed}, {"auto", scheduling::LeadMode::Auto}},
               &P::leadMode),
        number("lead_fraction", "",
               "Lead fraction rho of the layer length for lead_mode=fixed (§3.4)", 0.001, 0.49,
               &P::leadFraction),
        number("lead_search_min", "", "Smallest rho tried by lead_mode=auto (§3.4)", 0.001, 0.49,
               &P::leadSearchMinFraction),
        number("lead_search_max", "", "Largest rho tried by lead_mode=auto (§3.4)", 0.001, 0.49,
               &P::leadSearchMaxFraction),
        integer("lead_search_evaluations", "Golden-section evaluations for lead_mode=auto (§3.4)",
                3, 200, &P::leadSearchEvaluations),
        choice("key_mode", "Insert both extremes per guidance line or only the worst (§4.3)",
               std::vector<std::pair<std::string, scheduling::KeyMode>>{
                   {"both", scheduling::KeyMode::Both}, {"worst", scheduling::KeyMode::Worst}},
               &P::keyMode),
        choice(
            "adjust",
            "Key points crossing the channel: recursion only, or first the paper's shift of "
            "the key inward (§4.5)",
            std::vector<std::pair<std::string, scheduling::Adjust>>{
                {"recursive", scheduling::Adjust::Recursive}, {"shift", scheduling::Adjust::Shift}},
            &P::adjust),
        number("key_tolerance_deg", "deg",
               "Feasibility tolerance of the key-point recursion (§4.3)", 0, 1, &P::keyToleranceRad,
               kDeg),
        choice("eps_rule", "Corner size: the paper's epsilon0 rule or exact bisection (§5.4)",
               std::vector<std::pair<std::string, scheduling::EpsilonRule>>{
                   {"paper", scheduling::EpsilonRule::Paper},
                   {"exact", scheduling::EpsilonRule::Exact}},
               &P::epsilonRule),
        choice("corner_form",
               "Bezier corners in the rad/mm plane or the unit-free graph limit (§5.2, §5.5)",
               std::vector<std::pair<std::string, scheduling::CornerForm>>{
                   {"euclidean", scheduling::CornerForm::Euclidean},
                   {"graph-limit", scheduling::CornerForm::GraphLimit}},
               &P::cornerForm),
        choice("corner_profile",
               "Graph-limit corners: the paper's Bezier pair or the plateau corner whose peak "
               "theta'' is 1.25x the least possible (docs/results.md)",
               std::vector<std::pair<std::string, scheduling::CornerProfile>>{
                   {"bezier", scheduling::CornerProfile::Bezier},
                   {"plateau", scheduling::CornerProfile::Plateau}},
               &P::cornerProfile),
        number("final_clearance_deg", "deg", "Clearance c_final kept after smoothing (§5.4)", 0, 45,
               &P::finalClearanceRad, kDeg),
        integer("eps_bisection_steps", "Bisection steps of the exact epsilon rule (§5.4)", 1, 200,
                &P::epsilonBisectionSteps),
        integer("curve_checks_per_cubic", "Curve points checked per cubic by the exact rule (§5.4)",
                2, 10000, &P::curveChecksPerCubic),
        integer("threads", "Threads the job runs on, 0 = all cores", 0, 1024, &P::threads),
    };
}

} // namespace

const std::vector<ParameterInfo>& scheduleParameterSchema() {
    static const std::vector<ParameterInfo> schema = [] {
        std::vector<ParameterInfo> all = geometryParameters();
        for (ParameterInfo& info : curveParameters()) {
            all.push_back(std::move(info));
        }
        return all;
    }();
    return schema;
}

const ParameterInfo* findParameter(std::string_view key) {
    for (const ParameterInfo& info : scheduleParameterSchema()) {
        if (info.key == key) {
            return &info;
        }
    }
    return nullptr;
}

Result<scheduling::ScheduleParameters> presetParameters(std::string_view name) {
    if (name == "faithful") {
        return scheduling::faithfulPreset();
    }
    if (name == "best") {
        return scheduling::bestPreset();
    }
    return makeError(ErrorCode::InvalidArgument,
                     "preset: expected faithful or best, got '" + std::string(name) + "'");
}

} // namespace bladeaxis::job
