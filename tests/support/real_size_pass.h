#pragma once
// A finishing pass of a real size, as the optimum's tests and benchmarks solve it: a helical
// pass of `revolutions` at 0.4 mm pitch and 1.5 um chordal tolerance on `bladeSpec` (40
// revolutions of a NACA 4418 blade: 34,641 samples in 41 layers of up to 867), scheduled with
// the best preset.

#include "core/blade/presets.h"
#include "core/scheduling/schedule.h"

namespace bladeaxis::test {

inline Result<scheduling::ScheduleResult> scheduleRealSizePass(const blade::BladeSpec& bladeSpec,
                                                               int revolutions) {
    blade::HelicalPathSpec pathSpec = blade::demoPathSpec();
    pathSpec.revolutions = revolutions;
    pathSpec.pitch = 0.4;
    pathSpec.chordalTolerance = 0.0015;
    auto bladeModel = blade::Blade::create(bladeSpec);
    if (!bladeModel) {
        return std::unexpected(bladeModel.error());
    }
    auto path = blade::generateHelicalPath(*bladeModel, pathSpec);
    if (!path) {
        return std::unexpected(path.error());
    }
    scheduling::ScheduleInput input;
    input.toolRadius = pathSpec.toolRadius;
    input.centres = path->centre;
    for (const auto& record : path->path.records) {
        input.axes.push_back(record.axis);
    }
    return scheduling::schedule(input, scheduling::bestPreset());
}

} // namespace bladeaxis::test
