#include "core/cad/tessellation.h"

#include "core/cad/detail/occt_shape.h"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <cmath>
#include <string>

namespace bladeaxis::cad {
namespace {

// Appends one face's triangulation; false when the face has none.
bool appendFace(const TopoDS_Face& face, TriangleMesh& mesh) {
    TopLoc_Location location;
    const Handle(Poly_Triangulation) triangulation = BRep_Tool::Triangulation(face, location);
    if (triangulation.IsNull() || triangulation->NbTriangles() == 0) {
        return false;
    }
    const gp_Trsf transform = location.Transformation();
    const auto offset = static_cast<std::uint32_t>(mesh.vertices.size());
    for (int i = 1; i <= triangulation->NbNodes(); ++i) {
        const gp_Pnt p = triangulation->Node(i).Transformed(transform);
        mesh.vertices.emplace_back(p.X(), p.Y(), p.Z());
    }
    // A reversed face's material lies on the other side: flip its triangles so that the
    // counter-clockwise normal follows the face normal.
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (int t = 1; t <= triangulation->NbTriangles(); ++t) {
        int a = 0, b = 0, c = 0;
        triangulation->Triangle(t).Get(a, b, c);
        if (reversed) {
            std::swap(b, c);
        }
        mesh.triangles.push_back({offset + static_cast<std::uint32_t>(a - 1),
                                  offset + static_cast<std::uint32_t>(b - 1),
                                  offset + static_cast<std::uint32_t>(c - 1)});
    }
    return true;
}

Result<TriangleMesh> meshWithOcct(const TopoDS_Shape& original, const MeshOptions& options) {
    const TopoDS_Shape shape = BRepBuilderAPI_Copy(original, /*copyGeom=*/false).Shape();
    const BRepMesh_IncrementalMesh mesher(shape, options.linearDeflection, Standard_False,
                                          options.angularDeflection, Standard_False);
    if (!mesher.IsDone()) {
        return makeError(ErrorCode::Geometry, "tessellation: OpenCASCADE's mesher failed");
    }
    TriangleMesh mesh;
    int face = 0;
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
        ++face;
        if (!appendFace(TopoDS::Face(it.Current()), mesh)) {
            return makeError(ErrorCode::Geometry, "tessellation: face " + std::to_string(face) +
                                                      " could not be triangulated");
        }
    }
    if (mesh.empty()) {
        return makeError(ErrorCode::Geometry, "tessellation: the shape has no face to mesh");
    }
    return mesh;
}

} // namespace

Result<TriangleMesh> tessellate(const CadShape& shape, const MeshOptions& options) {
    if (shape.isNull()) {
        return makeError(ErrorCode::InvalidArgument, "tessellation: no shape");
    }
    if (!(options.linearDeflection > 0.0) || !(options.angularDeflection > 0.0) ||
        !std::isfinite(options.linearDeflection) || !std::isfinite(options.angularDeflection)) {
        return makeError(ErrorCode::InvalidArgument,
                         "tessellation: the deflections must be positive numbers");
    }
    return catchOcct(ErrorCode::Geometry, "tessellation",
                     [&] { return meshWithOcct(occtShape(shape), options); });
}

} // namespace bladeaxis::cad
