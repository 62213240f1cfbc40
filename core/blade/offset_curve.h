#pragma once
// The cutter-centre curve of a ball of radius R rolling around a closed section polygon: the
// exact offset of the polygon at distance R. Every edge contributes a segment shifted by R along
// its outward normal; every convex vertex an arc of radius R about the vertex (this fills the
// gap at sharp convex corners such as a closed NACA trailing edge); at concave vertices the two
// neighbouring segments are trimmed where they meet. The curve has no self-intersection as long
// as R is smaller than the minimum concave radius of the polygon (checked by create()).

#include "core/base/error.h"
#include "core/blade/closed_curve.h"

#include <cstddef>
#include <span>
#include <vector>

namespace bladeaxis::blade {

struct OffsetSample {
    Vec2 contact; // P: contact point on the section
    Vec2 normal;  // n: outward unit normal of the section at P
    Vec2 centre;  // Q = P + R n: ball centre
    // Where P lies on the polygon: P = (1 - edgeFraction) vertex[edge] + edgeFraction
    // vertex[edge + 1] (0 on the arc about a convex vertex), so that a caller can follow the
    // same point of the section to a neighbouring one (the span-wise surface derivative).
    std::size_t edge = 0;
    double edgeFraction = 0.0;
    // A unit normal that is continuous along the whole centre curve. `normal` jumps at concave
    // vertices, where the centre curve has a corner (Q is continuous there, P and n are not);
    // this one turns linearly along each segment towards the bisector of the two edge normals
    // at a concave end. For quantities derived from the normal that must not jump.
    Vec2 blendedNormal;
};

// Discrete concave radius of curvature of a counter-clockwise closed polygon: the largest R for
// which every edge survives the trimming at its concave end vertices (a concave circle of
// radius r gives r). +infinity when the polygon has no concave vertex.
double minConcaveRadius(std::span<const Vec2> curve);

class OffsetCurve {
  public:
    // `section` must be normalised (counter-clockwise, see closed_curve.h).
    static Result<OffsetCurve> create(std::span<const Vec2> section, double radius);

    double length() const { return m_length; }
    double radius() const { return m_radius; }
    std::size_t vertexCount() const { return m_vertexCount; } // of the section polygon
    // The point at normalised arc length `fraction` of the centre curve, measured from the start
    // of vertex 0 (fractions outside [0, 1) wrap around).
    OffsetSample at(double fraction) const;

  private:
    struct Piece {
        Vec2 contactStart; // segments: P at the piece start; arcs: the vertex
        Vec2 contactEnd;   // segments only
        double angleStart; // normal angle at the start (rad)
        double angleSweep; // arcs: normal rotation over the piece (rad); segments: 0
        double start;      // arc length of the centre curve at the piece start
        double length;
        std::size_t edge;     // arcs: the vertex; segments: the edge (from vertex `edge`)
        double fractionStart; // of the edge at contactStart (arcs: 0)
        double fractionEnd;   // of the edge at contactEnd (arcs: 0)
        double blendStart;    // segments: blended normal angle at the start (rad)
        double blendEnd;      // and at the end; arcs: unused (the blend is the normal)
    };
    std::vector<Piece> m_pieces;
    double m_length = 0.0;
    double m_radius = 0.0;
    std::size_t m_vertexCount = 0;
};

} // namespace bladeaxis::blade
