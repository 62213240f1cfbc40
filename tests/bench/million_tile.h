#pragma once
// The tile the million-point benchmarks repeat along x: the demo section without twist (every
// revolution is the previous one moved by the pitch), 10 revolutions at a fine tolerance. Tiled
// 128 times it gives 1,007,361 points.

#include "core/blade/presets.h"

namespace bladeaxis::bench {

inline blade::BladeSpec twistFreeDemoBlade() {
    blade::BladeSpec spec = blade::demoBladeSpec();
    spec.staggerEnd = spec.staggerStart;
    return spec;
}

inline blade::HelicalPathSpec fineTilePath() {
    blade::HelicalPathSpec spec = blade::demoPathSpec();
    spec.pitch = 0.5;
    spec.revolutions = 10;
    spec.chordalTolerance = 0.002;
    spec.maxStep = 0.25;
    return spec;
}

inline constexpr int kMillionTiles = 128;

} // namespace bladeaxis::bench
