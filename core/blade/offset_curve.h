#pragma once
// The cutter-centre curve of a ball of radius R rolling around a closed section polygon: the
// exact offset of the polygon at distance R. Every edge contributes a segment shifted by R along
// its outward normal; every convex vertex an arc of radius R about the vertex (this fills the
// gap at sharp convex corners such as a closed NACA trailing edge); at concave vertices the two
// neighbouring segments are trimmed where they meet. The curve has no self-intersection as long
// as R is smaller than the minimum concave radius of the polygon (checked by create()).

#include "core/base/error.h"
#include "core/blade/closed_curve.h"

#include <span>
#include <vector>

namespace bladeaxis::blade {

struct OffsetSample {
    Vec2 contact; // P: contact point on the section
    Vec2 normal;  // n: outward unit normal of the section at P
    Vec2 centre;  // Q = P + R n: ball centre
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
    };
    std::vector<Piece> m_pieces;
    double m_length = 0.0;
    double m_radius = 0.0;
};

} // namespace bladeaxis::blade
