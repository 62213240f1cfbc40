#pragma once
// Machine-readable reports of an axis-motion analysis: JSON objects for report.json and the
// per-CL-point axes.csv. Rotary values are written in degrees (files are for people and
// shops); the unit is part of every key and column name.

#include "core/analysis/analysis.h"
#include "core/analysis/lost_motion.h"
#include "core/toolpath/toolpath.h"

#include <nlohmann/json.hpp>

#include <span>
#include <string>

namespace bladeaxis::report {

// Rotary quantities are reported in degrees, linear ones in mm.
double toReportUnit(kinematics::AxisId axis, double value);
const char* unitOf(kinematics::AxisId axis);

// {"A": {"backlash_deg": 0.005, "reversals": 16, "lost_motion_deg": 0.08}, ...}: the play of
// every axis the machine file gives one, taken up at each direction change.
nlohmann::json lostMotionJson(std::span<const analysis::LostMotion> losses);

// {"path_length_mm", "feed_mm_min", "cycle_time_s", "axes": {"X": {...}, ...},
//  "a_reversals", "a_travel_deg", "a_backward_travel_deg", "constant_feed_time": {...}}
nlohmann::json analysisJson(const analysis::AxisProfile& profile,
                            const analysis::ConstantFeedTime& constantFeed);

// One row per analysed sample: record, source line, s, t, X Y Z A B, their velocities and
// accelerations, and whether A reverses there. Locale-independent numbers.
std::string axesCsv(const analysis::AxisProfile& profile,
                    std::span<const toolpath::ClRecord> records);

} // namespace bladeaxis::report
