#pragma once
// A plain triangle mesh in mm (W frame), e.g. for a 3-D view or the clearance check.
// Triangles are counter-clockwise seen from the side their face normal points to (outwards
// for solids and for the generated blade surface).

#include "core/geometry/vec.h"

#include <array>
#include <cstdint>
#include <vector>

namespace bladeaxis::cad {

struct TriangleMesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles; // indices into vertices

    bool empty() const { return triangles.empty(); }
};

} // namespace bladeaxis::cad
