#pragma once
// Issue 6: where the blade's sections (from CAD) turn concave, compared with where the engine
// found the concave runs from the toolpath alone (spec §1.6-1.7). At every base point of the
// schedule, the CAD section through the ball centre's x is analysed with the engine's own
// curvature rules, and the angle about the rotary axis of its nearest concave-run exit is set
// against the base point's: the disagreement a reviewer should see before trusting the layers.

#include "core/base/error.h"
#include "core/cad/cad_shape.h"
#include "core/geometry/vec.h"
#include "core/scheduling/schedule.h"

#include <optional>
#include <span>
#include <vector>

namespace bladeaxis::job {

struct SectionComparison {
    std::size_t basePoint = 0;        // input index of the engine's base point
    double x = 0.0;                   // mm, the section plane
    double engineExitDeg = 0.0;       // angle of the ball centre about x at the base point
    bool engineFallback = false;      // the engine found no concave run there (§1.7 fallback)
    std::size_t cadConcaveRuns = 0;   // concave runs of the CAD section
    std::optional<double> cadExitDeg; // nearest CAD concave-run exit, angle about x
    double differenceDeg = 0.0;       // |engine - CAD| wrapped to [0, 180]; 0 without a CAD run
};

// Errors: Geometry (a plane OpenCASCADE cannot intersect).
Result<std::vector<SectionComparison>>
compareConcaveExits(const cad::CadShape& blade, const scheduling::ScheduleResult& schedule,
                    std::span<const Vec3> centres, double toolRadius);

} // namespace bladeaxis::job
