#pragma once
// The comparison method of spec §7: tool orientation smoothing by quaternion interpolation
// (Ho, Hwang, Hu 2003, reconstructed as in §7.2 [A]). Key CL points keep the original CAM
// orientation (so the original reciprocation partly survives, as in [L] Fig. 15b); between
// keys the tool frame R = Rx(-A) Ry(B0) is interpolated by SLERP or SQUAD in the cutter-centre
// arc length; keys are added where the result leaves the raw channel until it does not.

#include "core/base/error.h"
#include "core/geometry/vec.h"
#include "core/scheduling/schedule.h"

#include <string>
#include <vector>

namespace bladeaxis::baselines {

enum class QuaternionInterpolation { Slerp, Squad };
enum class QuaternionMode { Frame, Vector }; // frame quaternions, or great-circle axis SLERP

struct QuaternionSettings {
    int keysPerLayer = 8; // n_key: uniform keys per layer (about one revolution)
    QuaternionInterpolation interpolation = QuaternionInterpolation::Slerp;
    QuaternionMode mode = QuaternionMode::Frame;
    double margin = 0.0523598775598; // rad (3 deg): adaptive keys are clamped this far inside
    int maxAdaptiveKeys = 100000;
};

std::string describe(const QuaternionSettings& settings); // "squad, 8 keys/layer, frame"

// The settings of the fairness rule: n_key in {4, 8, 16, 32} x {slerp, squad}, frame mode.
std::vector<QuaternionSettings> fairnessSettings();

struct QuaternionResult {
    QuaternionSettings settings;
    std::vector<Vec3> axes;        // unit tool axis per input sample
    std::vector<std::size_t> keys; // input indices of the keys, increasing
    std::size_t adaptiveKeys = 0;  // keys added by the channel repair
    double worstViolation = 0.0;   // rad outside the raw channel after repair (0: inside)
};

// `reference` is the engine's schedule of the same input: its layers, base points, raw
// channel and original angles frame the baseline, so the methods are compared like for like.
// Errors: InvalidArgument (settings, sizes), Infeasible (two consecutive keys 180 deg or more
// apart, where the shortest-arc SLERP would turn the wrong way; spec §7.2 (1b)).
Result<QuaternionResult> quaternionOrientations(const scheduling::ScheduleInput& input,
                                                const scheduling::ScheduleResult& reference,
                                                const QuaternionSettings& settings);

} // namespace bladeaxis::baselines
