#pragma once
// One schema for the scheduling parameters (spec Appendix A), reused by the command line, the
// job file and (later) the GUI's property panels and settings (docs/architecture.md, Conventions).
// Each entry has a key, a unit as the user sees it (degrees, not radians), a domain and accessors
// that convert at this one edge.

#include "core/base/error.h"
#include "core/scheduling/schedule_parameters.h"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace bladeaxis::job {

struct ParameterInfo {
    enum class Kind { Number, Integer, Choice, Flag };
    std::string key;  // job-file key and, with '_' -> '-', the command-line option: "margin_deg"
    std::string unit; // "deg", "mm", "1/mm", "" for pure numbers and choices
    std::string help;
    Kind kind = Kind::Number;
    std::vector<std::string> choices; // for Kind::Choice
    double min = 0.0;                 // domain for numbers, in the user unit
    double max = 0.0;
    // Reads the value in the user unit as text ("3", "exact", "true").
    std::function<std::string(const scheduling::ScheduleParameters&)> get;
    // Validates and stores a value given as text in the user unit.
    std::function<Status(scheduling::ScheduleParameters&, std::string_view)> set;
};

const std::vector<ParameterInfo>& scheduleParameterSchema();

// The preset by name ("faithful" | "best"); InvalidArgument otherwise.
Result<scheduling::ScheduleParameters> presetParameters(std::string_view name);

// Finds an entry by key; nullptr when unknown.
const ParameterInfo* findParameter(std::string_view key);

} // namespace bladeaxis::job
