#pragma once
// The controller model each cycle-time estimate assumes, in the words report.json, the summary
// and the window's Review page print beside the figure (docs/figures.md, "Cycle times and their
// models"): one wording, so the batch and the window name a figure's model alike.

namespace bladeaxis::job {

inline constexpr const char* kConstantFeedModel =
    "T1: the whole pass at one constant feed, the highest the slowest point allows (a bound, not "
    "a controller)";
inline constexpr const char* kLookAheadModel =
    "T2: look-ahead, time-optimal along the path under the axes' velocity and acceleration "
    "limits and the feed (TOPP-RA), grid-converged";
inline constexpr const char* kBlockByBlockModel =
    "each block planned alone from rest to rest, parabolic blends, no blending across rotary "
    "blocks, F read as the XYZ speed (LinuxCNC 2.9's planner)";

} // namespace bladeaxis::job
