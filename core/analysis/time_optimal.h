#pragma once
// T2 of spec §8.3: the shortest time along the fixed path under per-axis velocity and
// acceleration limits and the programmed feed, by reachability analysis (TOPP-RA, Pham & Pham
// 2018) on the path grid of an axis profile. The tool starts and ends at rest.
//
// State x = sdot^2 per grid point, control u = sddot per interval, x_{i+1} = x_i + 2 Delta_i u_i.
// Constraints at grid point i: x q_j'^2 <= v_j^2, x <= F^2, |q_j' u + q_j'' x| <= a_j.
// Backward pass: the controllable sets K_i = [0, k_i] (0 is always controllable: standing
// still). For a fixed x every constraint bounds u by a line in x, so the largest controllable
// x is found exactly from the pairwise crossings of those lines (no LP solver, no bisection).
// Forward pass: from x_0 = 0, the largest u that stays controllable. T2 = sum 2 Delta /
// (sqrt x_i + sqrt x_{i+1}). Optimal up to the discretisation.

#include "core/analysis/axis_profile.h"
#include "core/base/error.h"
#include "core/kinematics/machine_model.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace bladeaxis::analysis {

struct TimeOptimalOptions {
    // Spec §8.3 "T2+J (heuristic)": where the numerical axis jerk of the result exceeds a jerk
    // limit, lower the state bound there by x0.9 and repeat (third-order path constraints are
    // non-convex; this is a heuristic, not an optimum).
    bool jerkHeuristic = false;
    int maxJerkRounds = 20;
    // Polled every 65,536 samples of each pass: once it is set, T2 ends with
    // ErrorCode::Cancelled (a cancelled job does not wait the 0.4 s T2 takes at five million
    // samples).
    const CancelToken* cancel = nullptr;
    // The grid: each interval between two profile samples is cut into this many equal steps.
    // One (a grid point per block) is what the profile offers; see convergedTimeOptimal.
    std::size_t subdivisions = 1;
    // Given (one entry >= 1 per interval between samples), each interval's own step count
    // instead of `subdivisions`.
    std::span<const std::uint32_t> stepsPerInterval = {};
};

struct TimeOptimalTime {
    double time = 0.0;             // s, T2
    std::vector<double> pathSpeed; // sdot per grid point, mm/s (subdivisions per interval)
    double peakPathSpeed = 0.0;    // mm/s
    double constantFeedTime = 0.0; // s, T1 at the same limits for reference
    int jerkRounds = 0;            // rounds of the jerk heuristic run
    bool jerkWithinLimits = true;  // false: the heuristic stopped with jerk above a limit
};

// The profile supplies the grid (pathParameter) and q', q'' per axis (velocity / F and
// acceleration / F^2 at the samples). Limits <= 0 or non-finite are "unlimited". Errors:
// InvalidArgument (fewer than 2 samples, no positive feed), Geometry (a path the limits cannot
// move along, e.g. an axis that must jump).
Result<TimeOptimalTime> timeOptimalTime(const AxisProfile& profile,
                                        const kinematics::MachineModel& machine,
                                        const TimeOptimalOptions& options = {});

// T2 refined until it holds. T2 on one grid point per block is not a converged figure: a
// reversal's acceleration spike is one block wide and on that grid it brakes the whole of both
// neighbouring blocks, which inflated the originals' T2 by 26-71 % while the smooth
// re-scheduled paths moved by about 1 %. Each round halves the steps of the blocks whose own
// time still moved by more than half their even share of `tolerance` x T2 in the round before
// (every block in the first round), until T2 changes by less than `tolerance` (relative) between
// two rounds or a block reaches `maxSubdivisions` steps. Refining only where the time moves keeps
// the cost near two or three passes: a uniform refinement to 64 steps per block took 127 passes, 10
// s on a million-block program.
struct ConvergedTimeOptions {
    double tolerance = 0.005;
    std::size_t maxSubdivisions = 64;
    const CancelToken* cancel = nullptr;
};

struct ConvergedTime {
    double time = 0.0;            // s, T2 on the finest grid computed
    std::size_t subdivisions = 1; // the most steps any block of that grid has
    double lastChange = 0.0;      // relative change of T2 from the grid before (0 on one grid)
    bool converged = false;       // lastChange < tolerance

    bool operator==(const ConvergedTime&) const = default;
};

// Errors as timeOptimalTime (on the first grid).
Result<ConvergedTime> convergedTimeOptimal(const AxisProfile& profile,
                                           const kinematics::MachineModel& machine,
                                           const ConvergedTimeOptions& options = {});

// The grid-converged T2 alone, or none when the machine's limits do not let the tool move
// along the path or `cancel` is set before it ends: what a job and a limit sweep report.
std::optional<ConvergedTime> convergedTimeOptimalOrNone(const AxisProfile& profile,
                                                        const kinematics::MachineModel& machine,
                                                        const CancelToken* cancel = nullptr);

// T2 alone (s) on the converged grid: convergedTimeOptimalOrNone's time.
std::optional<double> timeOptimalSeconds(const AxisProfile& profile,
                                         const kinematics::MachineModel& machine,
                                         const CancelToken* cancel = nullptr);

} // namespace bladeaxis::analysis
