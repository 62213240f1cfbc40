#include "core/cad/blade_surface.h"

#include "core/cad/detail/occt_shape.h"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS_Face.hxx>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace bladeaxis::cad {
namespace {

// Exterior turning angle at every vertex of a closed polygon (0 on a straight run).
std::vector<double> turningAngles(const blade::Curve2& curve) {
    const std::size_t n = curve.size();
    std::vector<double> turning(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 in = curve[i] - curve[(i + n - 1) % n];
        const Vec2 out = curve[(i + 1) % n] - curve[i];
        turning[i] = std::abs(std::atan2(in.x() * out.y() - in.y() * out.x(), in.dot(out)));
    }
    return turning;
}

// The seam goes where the sections are sharpest (summed over all stations so that every
// station uses the same vertex index): a closed trailing edge is a crease the interpolating
// spline could not follow inside a row, but it can be the row's end points.
std::size_t seamIndex(const std::vector<blade::Curve2>& sections) {
    std::vector<double> sum(sections.front().size(), 0.0);
    for (const blade::Curve2& section : sections) {
        const std::vector<double> turning = turningAngles(section);
        for (std::size_t i = 0; i < sum.size(); ++i) {
            sum[i] += turning[i];
        }
    }
    return static_cast<std::size_t>(std::distance(sum.begin(), std::ranges::max_element(sum)));
}

Status checkOptions(const BladeSurfaceOptions& options) {
    if (options.stations != 0 && options.stations < 4) {
        return makeError(ErrorCode::InvalidArgument,
                         "blade surface: stations must be 0 (automatic) or >= 4, got " +
                             std::to_string(options.stations));
    }
    if (!(options.stationSpacing > 0.0) || !std::isfinite(options.stationSpacing)) {
        return makeError(ErrorCode::InvalidArgument,
                         "blade surface: station spacing must be a positive number of mm");
    }
    return {};
}

int stationCount(const blade::Blade& blade, const BladeSurfaceOptions& options) {
    if (options.stations != 0) {
        return options.stations;
    }
    const double span = blade.spanEnd() - blade.spanStart();
    return std::max(4, static_cast<int>(std::ceil(span / options.stationSpacing)) + 1);
}

Result<CadShape> interpolateSections(const std::vector<double>& stationX,
                                     const std::vector<blade::Curve2>& sections) {
    const std::size_t count = sections.front().size();
    const std::size_t seam = seamIndex(sections);
    // Rows along u close on themselves: the seam point is repeated at the end.
    TColgp_Array2OfPnt points(1, static_cast<int>(count) + 1, 1, static_cast<int>(sections.size()));
    for (std::size_t j = 0; j < sections.size(); ++j) {
        for (std::size_t i = 0; i <= count; ++i) {
            const Vec2& p = sections[j][(seam + i) % count];
            points.SetValue(static_cast<int>(i) + 1, static_cast<int>(j) + 1,
                            gp_Pnt(stationX[j], p.x(), p.y()));
        }
    }
    GeomAPI_PointsToBSplineSurface builder;
    builder.Interpolate(points, Approx_ChordLength);
    if (!builder.IsDone() || builder.Surface().IsNull()) {
        return makeError(ErrorCode::Geometry,
                         "blade surface: OpenCASCADE could not interpolate the sections");
    }
    BRepBuilderAPI_MakeFace face(builder.Surface(), 1e-7);
    if (!face.IsDone()) {
        return makeError(ErrorCode::Geometry, "blade surface: no face from the B-spline surface");
    }
    return wrapShape(face.Face());
}

} // namespace

Result<CadShape> makeBladeSurface(const blade::Blade& blade, const BladeSurfaceOptions& options) {
    if (Status ok = checkOptions(options); !ok) {
        return std::unexpected(ok.error());
    }
    const double span = blade.spanEnd() - blade.spanStart();
    if (!(span > 0.0)) {
        return makeError(ErrorCode::Geometry, "blade surface: the blade has no span");
    }
    const int stations = stationCount(blade, options);
    std::vector<double> stationX;
    std::vector<blade::Curve2> sections;
    for (int j = 0; j < stations; ++j) {
        const double x = blade.spanStart() + span * j / (stations - 1);
        stationX.push_back(x);
        sections.push_back(blade.sectionAt(x));
        if (sections.back().size() != sections.front().size() || sections.back().size() < 3) {
            return makeError(ErrorCode::Geometry,
                             "blade surface: the sections do not have a common vertex count");
        }
    }
    return catchOcct(ErrorCode::Geometry, "blade surface",
                     [&] { return interpolateSections(stationX, sections); });
}

} // namespace bladeaxis::cad
