#include "core/cad/cad_shape.h"

#include "core/cad/detail/occt_shape.h"

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

namespace bladeaxis::cad {

int CadShape::faceCount() const {
    if (isNull()) {
        return 0;
    }
    int count = 0;
    for (TopExp_Explorer face(m_impl->shape, TopAbs_FACE); face.More(); face.Next()) {
        ++count;
    }
    return count;
}

BoundingBox CadShape::bounds() const {
    if (isNull() || m_impl->shape.IsNull()) {
        return {};
    }
    Bnd_Box box;
    // The optimal box follows the surfaces, not their pole hulls.
    BRepBndLib::AddOptimal(m_impl->shape, box, /*useTriangulation=*/false,
                           /*useShapeTolerance=*/false);
    if (box.IsVoid()) {
        return {};
    }
    double x0 = 0, y0 = 0, z0 = 0, x1 = 0, y1 = 0, z1 = 0;
    box.Get(x0, y0, z0, x1, y1, z1);
    return {Vec3(x0, y0, z0), Vec3(x1, y1, z1)};
}

} // namespace bladeaxis::cad
