#pragma once
// Cycle-time model (b), "block-by-block": a controller that plans every block on its own and
// does not blend across blocks that move a rotary axis, as LinuxCNC 2.9's trajectory planner
// does (src/emc/tp: a rotary block gets no blend arc and no look-ahead, only a parabolic blend).
//
// Per block (the move from one record to the next), as LinuxCNC's canonical layer plans it:
//   L    = the XYZ length of the move (the ABC length in degrees for a purely rotary move),
//   v    = min(F, L / max_j |dq_j| / v_j)   (F is read as the XYZ speed of the move),
//   a    = L / max_j |dq_j| / a_j,
// and then as its planner runs it: the block accelerates with half of a (the other half is left
// to the blend with its neighbour) from rest and decelerates to rest at its end; the next block
// starts when this one, decelerating, falls below the blend velocity (the smaller of the two
// blocks' reachable peaks). The program's time is the sum of the blocks' durations less the
// overlaps. LinuxCNC's planner also caps a blend with the G64 P tolerance at a corner; on the
// demo that cap, modelled as its source reads, put the model 9 % above the planner's measured
// time and the blocks it touched 31 % above theirs, while the model without it came within
// 1 % (correlation 0.98 per block), so the model leaves it out.
//
// On short blocks this reduces to t = sqrt(2 L / a) per block: block length and the rotary step
// per block, not the smoothness of A, set the time. tests/controller runs the same programs
// through LinuxCNC's real planner; docs/results.md compares the two.

#include "core/analysis/axis_profile.h"
#include "core/kinematics/machine_model.h"

#include <cstddef>
#include <span>

namespace bladeaxis::analysis {

struct BlockPlannerTime {
    double time = 0.0;            // s, from the first record at rest to the last at rest
    std::size_t blocks = 0;       // moves planned (zero-length moves are skipped, as LinuxCNC does)
    std::size_t rotaryBlocks = 0; // of them, moves that turn a rotary axis
    double meanBlockSeconds = 0.0; // time / blocks
};

// axes: the machine axes of consecutive records (mm, rad); feeds: F of the move ending at each
// record, mm/s (feeds[0] is not read). Limits <= 0 or non-finite are unlimited; a block that no
// limit bounds moves at F. Sizes must match; fewer than two records give no time.
BlockPlannerTime blockByBlockTime(std::span<const kinematics::MachineAxes> axes,
                                  std::span<const double> feeds,
                                  const kinematics::MachineModel& machine);

// The same with each block's feed as the path states it (PathSamples::feed: a program's own
// feeds, or those a re-scheduled program writes). None when the sizes differ.
BlockPlannerTime blockByBlockTime(std::span<const kinematics::MachineAxes> axes,
                                  const PathSamples& path, const kinematics::MachineModel& machine);

} // namespace bladeaxis::analysis
