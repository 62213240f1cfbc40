#pragma once
// Is the CAD the program's blade? A STEP box a metre away, a blade placed 100 mm off or read in
// the wrong unit would otherwise pass the clearance check silently, every distance capped at the
// search limit. The cutting pass of a finishing program runs round the blade touching it, so
//  - the CAD must span the ball centres' x range (less R: a ball reaches R beyond its centre),
//  - and most CL points must lie within the search limit of it (more than half: a pass that
//    stays clear at most of its points is not cutting this part).

#include "core/base/error.h"
#include "core/cad/clearance.h"
#include "core/cad/triangle_mesh.h"
#include "core/geometry/vec.h"

#include <span>
#include <string>

namespace bladeaxis::job {

struct CadFitInput {
    const cad::TriangleMesh* blade = nullptr;
    const cad::ClearanceReport* clearance = nullptr; // of the input program's cutting pass
    std::span<const Vec3> centres;                   // ball centres of that pass
    double toolRadius = 0.0;                         // mm
    double searchLimit = 0.0;                        // mm, the clearance check's cap
    std::string cadName;                             // for the message
    std::string programName;
};

// Geometry error naming the CAD file, what was expected and what was found.
Status checkCadFitsProgram(const CadFitInput& input);

} // namespace bladeaxis::job
