#pragma once
// How a tool-orientation schedule sits in the engine's S-theta channel, measured the same way
// for every method (spec §8.2, §9.5): clearance to the raw channel, theta'' peaks and energy, and
// reversals of theta inside the layers. Discrete (3-point, non-uniform S) for all methods, so the
// engine's analytic theta'' is not given an advantage.

#include "core/geometry/vec.h"
#include "core/scheduling/schedule.h"

#include <span>
#include <vector>

namespace bladeaxis::compare {

struct ChannelMetrics {
    double minClearance = 0.0;           // rad; negative: the schedule leaves the raw channel
    std::size_t samplesOutside = 0;      // samples more than 1e-9 rad outside the raw channel
    double peakSecondDerivative = 0.0;   // max |theta''|, rad/mm^2
    double secondDerivativeEnergy = 0.0; // sum over layers of the integral of theta''^2 dS
    std::size_t thetaReversals = 0;      // sign changes of dtheta/dS inside layers
};

// theta of every layer sample of `reference`, for tool axes given per input sample (the
// reference's layers index them through inputIndex), unwrapped along each layer from the
// branch nearest the channel's middle at its first sample. Angles relative to each layer's
// junctionAngle, rad.
std::vector<std::vector<double>> layerThetas(const scheduling::ScheduleResult& reference,
                                             std::span<const Vec3> axes);

ChannelMetrics measureInChannel(const scheduling::ScheduleResult& reference,
                                std::span<const Vec3> axes);

// Discrete theta'' on a non-uniform grid (exact for quadratics); ends are 0.
std::vector<double> secondDerivative(std::span<const double> s, std::span<const double> theta);

} // namespace bladeaxis::compare
