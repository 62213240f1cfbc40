#pragma once
// The tile the million-point benchmarks repeat along x: the demo section without twist (every
// revolution is the previous one moved by the pitch), 10 revolutions at a fine tolerance. Tiled
// 128 times it gives 1,007,361 points (2 times in a smoke run).

#include "core/blade/presets.h"
#include "tests/bench/bench_size.h"

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

inline int millionTiles() {
    return scaled(128, 2);
}

} // namespace bladeaxis::bench
