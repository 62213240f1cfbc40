#pragma once
// Triangulation of a CAD shape with OpenCASCADE's incremental mesher (BRepMesh).

#include "core/base/error.h"
#include "core/cad/cad_shape.h"
#include "core/cad/triangle_mesh.h"

namespace bladeaxis::cad {

struct MeshOptions {
    double linearDeflection = 0.01; // mm, largest distance between a triangle and the surface
    double angularDeflection = 0.3; // rad, largest angle between neighbouring triangle normals
};

// Meshes a private copy of the shape (BRepMesh stores its triangulation inside the shape, which
// copies of a CadShape share), then gathers every face's triangles with the face's placement
// and orientation applied; vertices are not merged across faces. Errors: InvalidArgument (null
// shape, options), Geometry (a face the mesher could not triangulate, or no triangle at all).
Result<TriangleMesh> tessellate(const CadShape& shape, const MeshOptions& options = {});

} // namespace bladeaxis::cad
