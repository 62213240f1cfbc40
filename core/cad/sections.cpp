#include "core/cad/sections.h"

#include "core/base/parallel.h"
#include "core/cad/detail/occt_shape.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_TangentialDeflection.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAPI_IntSS.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_Plane.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <gp_Pln.hxx>
#include <optional>
#include <string>
#include <thread>

namespace bladeaxis::cad {
namespace {

// One edge of the section as points in its own direction.
std::vector<Vec3> discretiseEdge(const TopoDS_Edge& edge, const SectionOptions& options) {
    const BRepAdaptor_Curve curve(edge);
    const GCPnts_TangentialDeflection points(curve, options.angularDeflection, options.deflection,
                                             2);
    std::vector<Vec3> result;
    result.reserve(static_cast<std::size_t>(points.NbPoints()));
    for (int i = 1; i <= points.NbPoints(); ++i) {
        const gp_Pnt p = points.Value(i);
        result.emplace_back(p.X(), p.Y(), p.Z());
    }
    if (edge.Orientation() == TopAbs_REVERSED) {
        std::ranges::reverse(result);
    }
    return result;
}

// Signed area of the projection onto the (y, z) plane: positive when counter-clockwise, i.e.
// right-handed about +x like the blade sections.
double areaAboutX(const std::vector<Vec3>& ring) {
    double twice = 0.0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const Vec3& a = ring[i];
        const Vec3& b = ring[(i + 1) % ring.size()];
        twice += a.y() * b.z() - b.y() * a.z();
    }
    return 0.5 * twice;
}

// Appends `piece` to `chain` when one of its ends meets the chain's end (within `gap`),
// reversing it if needed. False when neither end meets.
bool appendIfJoined(std::vector<Vec3>& chain, std::vector<Vec3>& piece, double gap) {
    if ((piece.front() - chain.back()).norm() > gap) {
        if ((piece.back() - chain.back()).norm() > gap) {
            return false;
        }
        std::ranges::reverse(piece);
    }
    chain.insert(chain.end(), piece.begin() + 1, piece.end());
    return true;
}

// The section edges come in no particular order or direction: join them greedily at both ends
// of a growing chain. Quadratic in the edge count, which is small (a few edges per face cut).
std::vector<Polyline3> chainPieces(std::vector<std::vector<Vec3>> pieces, double gap) {
    std::vector<Polyline3> result;
    std::vector<bool> used(pieces.size(), false);
    for (std::size_t seed = 0; seed < pieces.size(); ++seed) {
        if (used[seed]) {
            continue;
        }
        used[seed] = true;
        std::vector<Vec3> chain = pieces[seed];
        for (bool grew = true; grew;) {
            grew = false;
            for (std::size_t k = 0; k < pieces.size(); ++k) {
                if (used[k]) {
                    continue;
                }
                if (appendIfJoined(chain, pieces[k], gap)) {
                    used[k] = grew = true;
                    continue;
                }
                std::ranges::reverse(chain); // try the other end of the chain
                if (appendIfJoined(chain, pieces[k], gap)) {
                    used[k] = grew = true;
                }
            }
        }
        Polyline3 polyline;
        polyline.closed = chain.size() > 2 && (chain.front() - chain.back()).norm() <= gap;
        if (polyline.closed) {
            chain.pop_back();
            if (areaAboutX(chain) < 0.0) {
                std::ranges::reverse(chain);
            }
        }
        polyline.points = std::move(chain);
        result.push_back(std::move(polyline));
    }
    return result;
}

Status checkOptions(const CadShape& shape, const SectionOptions& options) {
    if (shape.isNull()) {
        return makeError(ErrorCode::InvalidArgument, "section: no shape");
    }
    if (!(options.deflection > 0.0) || !(options.angularDeflection > 0.0)) {
        return makeError(ErrorCode::InvalidArgument,
                         "section: the deflections must be positive numbers");
    }
    return {};
}

// A face whose boundary is the natural boundary of a bounded surface (B-spline or Bezier): every
// boundary edge lies on one side of the surface's parameter rectangle. The generated blade and
// most exported free-form faces are like that; planes and other trimmed faces are not.
bool hasNaturalBounds(const TopoDS_Face& face, const Handle(Geom_Surface) & surface) {
    if (!surface->IsKind(STANDARD_TYPE(Geom_BSplineSurface)) &&
        !surface->IsKind(STANDARD_TYPE(Geom_BezierSurface))) {
        return false;
    }
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    surface->Bounds(u0, u1, v0, v1);
    const double eps = 1e-9 * std::max({1.0, u1 - u0, v1 - v0});
    auto onSide = [&](const gp_Pnt2d& p) {
        return std::array<bool, 4>{std::abs(p.X() - u0) < eps, std::abs(p.X() - u1) < eps,
                                   std::abs(p.Y() - v0) < eps, std::abs(p.Y() - v1) < eps};
    };
    int wires = 0;
    for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) {
        ++wires;
    }
    if (wires != 1) {
        return false;
    }
    for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
        double first = 0, last = 0;
        const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
        if (pcurve.IsNull()) {
            return false;
        }
        const auto a = onSide(pcurve->Value(first));
        const auto m = onSide(pcurve->Value(0.5 * (first + last)));
        const auto b = onSide(pcurve->Value(last));
        bool shared = false;
        for (std::size_t k = 0; k < 4; ++k) {
            shared = shared || (a[k] && m[k] && b[k]);
        }
        if (!shared) {
            return false;
        }
    }
    return true;
}

// Plane against the surface alone: no boolean bookkeeping, about 50 times faster than the
// boolean section on a blade surface with hundreds of poles. The result is bounded by the
// surface's parameter rectangle, which is the face.
std::vector<std::vector<Vec3>> intersectSurface(const Handle(Geom_Surface) & surface, double x,
                                                const SectionOptions& options) {
    const Handle(Geom_Plane) plane = new Geom_Plane(gp_Pln(gp_Pnt(x, 0, 0), gp_Dir(1, 0, 0)));
    const GeomAPI_IntSS intersection(surface, plane, 1e-7);
    std::vector<std::vector<Vec3>> pieces;
    if (!intersection.IsDone()) {
        return pieces;
    }
    for (int k = 1; k <= intersection.NbLines(); ++k) {
        const GeomAdaptor_Curve curve(intersection.Line(k));
        const GCPnts_TangentialDeflection points(curve, options.angularDeflection,
                                                 options.deflection, 2);
        std::vector<Vec3> piece;
        for (int i = 1; i <= points.NbPoints(); ++i) {
            const gp_Pnt p = points.Value(i);
            piece.emplace_back(p.X(), p.Y(), p.Z());
        }
        if (piece.size() >= 2) {
            pieces.push_back(std::move(piece));
        }
    }
    return pieces;
}

// The general path: OpenCASCADE's boolean section, which trims by the face boundaries.
Result<std::vector<std::vector<Vec3>>> booleanSection(const TopoDS_Shape& shape, double x,
                                                      const SectionOptions& options, double& gap) {
    const gp_Pln plane(gp_Pnt(x, 0.0, 0.0), gp_Dir(1.0, 0.0, 0.0));
    BRepAlgoAPI_Section section(shape, plane, Standard_False);
    section.Approximation(Standard_True); // B-spline section curves, not raw walking lines
    section.ComputePCurveOn1(Standard_False);
    section.Build();
    if (!section.IsDone() || section.HasErrors()) {
        return makeError(ErrorCode::Geometry,
                         "section: OpenCASCADE could not intersect the shape with x = " +
                             std::to_string(x));
    }
    std::vector<std::vector<Vec3>> pieces;
    for (TopExp_Explorer it(section.Shape(), TopAbs_EDGE); it.More(); it.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
        if (BRep_Tool::Degenerated(edge)) {
            continue;
        }
        gap = std::max(gap, 2.0 * BRep_Tool::Tolerance(edge));
        std::vector<Vec3> points = discretiseEdge(edge, options);
        if (points.size() >= 2) {
            pieces.push_back(std::move(points));
        }
    }
    return pieces;
}

Result<std::vector<Polyline3>> sectionWithOcct(const TopoDS_Shape& shape, double x,
                                               const SectionOptions& options) {
    std::vector<std::vector<Vec3>> pieces;
    double gap = 1e-4; // mm; widened to the tolerance of the faces and section edges
    BRep_Builder builder;
    TopoDS_Compound trimmed; // faces that need the boolean section
    builder.MakeCompound(trimmed);
    bool anyTrimmed = false;
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
        const TopoDS_Face& face = TopoDS::Face(it.Current());
        gap = std::max(gap, 2.0 * BRep_Tool::Tolerance(face));
        const Handle(Geom_Surface) surface = BRep_Tool::Surface(face); // located copy
        if (!options.booleanOnly && !surface.IsNull() && hasNaturalBounds(face, surface)) {
            for (std::vector<Vec3>& piece : intersectSurface(surface, x, options)) {
                pieces.push_back(std::move(piece));
            }
        } else {
            builder.Add(trimmed, face);
            anyTrimmed = true;
        }
    }
    if (anyTrimmed) {
        Result<std::vector<std::vector<Vec3>>> more = booleanSection(trimmed, x, options, gap);
        if (!more) {
            return std::unexpected(more.error());
        }
        for (std::vector<Vec3>& piece : *more) {
            pieces.push_back(std::move(piece));
        }
    }
    return chainPieces(std::move(pieces), gap);
}

} // namespace

Result<std::vector<Polyline3>> sectionAtX(const CadShape& shape, double x,
                                          const SectionOptions& options) {
    if (Status ok = checkOptions(shape, options); !ok) {
        return std::unexpected(ok.error());
    }
    if (!std::isfinite(x)) {
        return makeError(ErrorCode::InvalidArgument, "section: x is not a finite number");
    }
    return catchOcct(ErrorCode::Geometry, "section at x = " + std::to_string(x),
                     [&] { return sectionWithOcct(occtShape(shape), x, options); });
}

Result<std::vector<std::vector<Polyline3>>>
sectionsAtX(const CadShape& shape, std::span<const double> xs, const SectionOptions& options) {
    std::vector<std::optional<Result<std::vector<Polyline3>>>> results(xs.size());
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t i = next++; i < xs.size(); i = next++) {
            results[i] = sectionAtX(shape, xs[i], options);
        }
    };
    const unsigned count = std::min<unsigned>(
        currentThreadCount(), static_cast<unsigned>(std::max<std::size_t>(1, xs.size())));
    std::vector<std::jthread> pool;
    for (unsigned t = 1; t < count; ++t) {
        pool.emplace_back(worker);
    }
    worker();
    pool.clear(); // joins
    std::vector<std::vector<Polyline3>> sections;
    sections.reserve(xs.size());
    for (auto& result : results) {
        if (!*result) {
            return std::unexpected(result->error());
        }
        sections.push_back(std::move(**result));
    }
    return sections;
}

} // namespace bladeaxis::cad
