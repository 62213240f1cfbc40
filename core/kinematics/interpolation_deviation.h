#pragma once
// What the control cuts between two programmed points. A control without tool-centre-point
// interpolation moves every machine axis linearly through a block, so while the table turns
// the ball centre sweeps an arc about the rotary axis instead of the straight chord between the
// block's two centres: for a step dA at a distance r from the axis it strays about
// r dA^2 / 8 (0.8 um for 1 deg at 20 mm, 12 um for 4 deg). Keeping the programmed points is
// not keeping the surface between them; this measures the difference.

#include "core/base/progress.h"
#include "core/kinematics/machine_model.h"

#include <cstddef>
#include <span>

namespace bladeaxis::kinematics {

struct InterpolationDeviation {
    double maxMm = 0.0;     // largest distance of an interpolated ball centre from its chord
    std::size_t block = 0;  // index of the record that ends the block where it occurs
    std::size_t blocks = 0; // blocks measured
};

// axes: the machine axes of consecutive records; the ball of radius `ballRadius` (mm) sits on
// the tool axis. Each block is sampled at `samplesPerBlock` interior points, the blocks on the
// context's threads (the same result on any number). Once `cancel` is set it ends early with a
// partial result, which a caller that looks at the token then drops.
InterpolationDeviation interpolationDeviation(std::span<const MachineAxes> axes,
                                              const TableAHeadB& chain, double ballRadius,
                                              int samplesPerBlock = 3,
                                              const CancelToken* cancel = nullptr);

} // namespace bladeaxis::kinematics
