#pragma once
// Reports of a re-scheduling: layers.csv (one row per CL point of the cutting pass) and the
// per-layer and overall before/after figures of report.json. Angles are written in degrees.

#include "core/analysis/axis_profile.h"
#include "core/kinematics/machine_model.h"
#include "core/scheduling/schedule.h"

#include <nlohmann/json.hpp>

#include <array>
#include <span>
#include <string>
#include <vector>

namespace bladeaxis::report {

// Columns: record, line, layer, s_mm, theta_original_deg, theta_min_deg, theta_max_deg, lo_deg,
// hi_deg, theta_deg, dtheta_deg_mm, ddtheta_deg_mm2 (theta relative to the layer's start).
// `lines` (optional, per input sample) adds the source line of every CL point, so a reviewer can
// find it in the program.
std::string layersCsv(const scheduling::ScheduleResult& schedule, std::span<const int> lines = {});

// One side (the input, or the re-scheduled program) of every layer's machine-axis motion:
// A reversals and the peak |velocity| and |acceleration| of X Y Z A (indexed by
// kinematics::AxisId) over the profile's samples in the layer. Internal units.
struct LayerAxisMotion {
    int aReversals = 0;
    std::array<double, 4> peakVelocity{}, peakAcceleration{};
};

// Per layer: `profile`'s peaks over the samples of its records and the reversals of `axes`
// (per pass record, A continuous) over them. A job takes the input's side as soon as the
// layers are known, so that a batch job can free the input profile's derivatives and the
// pass's axes before the layers are scheduled.
std::vector<LayerAxisMotion> layerAxisMotion(std::span<const scheduling::LayerBounds> layers,
                                             const analysis::AxisProfile& profile,
                                             std::span<const kinematics::MachineAxes> axes);
// The same with only the A of each pass record (rad, continuous): what a batch job keeps of
// the pass's machine axes once the input is analysed.
std::vector<LayerAxisMotion> layerAxisMotion(std::span<const scheduling::LayerBounds> layers,
                                             const analysis::AxisProfile& profile,
                                             std::span<const double> aOfRecords);

struct BeforeAfter {
    std::span<const LayerAxisMotion> before, after; // per layer
    std::span<const int> sourceLines;               // per pass record
};

// The A-axis motion of one layer before and after (internal units: rad/s, rad/s^2): what the
// GUI's layer list and report.json show per layer.
struct LayerMotion {
    int reversalsBefore = 0, reversalsAfter = 0;
    double peakVelocityBefore = 0.0, peakVelocityAfter = 0.0;
    double peakAccelerationBefore = 0.0, peakAccelerationAfter = 0.0;
};
std::vector<LayerMotion> layerMotion(const BeforeAfter& data);

// One object per layer: statuses, source lines, reversals, peak A (and X/Y/Z) velocity and
// acceleration before and after, channel clearance, lead fraction, corners, peak theta'', time.
nlohmann::json layersJson(const scheduling::ScheduleResult& schedule, const BeforeAfter& data);

// Relative reductions (before - after) / before of the headline figures.
nlohmann::json reductionsJson(const analysis::AxisProfile& before,
                              const analysis::AxisProfile& after);

} // namespace bladeaxis::report
