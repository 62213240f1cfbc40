#pragma once
// Closed 2-D curves (section polygons) in the section plane x = const, coordinates (y, z) of W.
// A closed curve is stored without repeating its first vertex. Normalised curves run
// counter-clockwise in (y, z), i.e. right-handed about +x, so the outward normal of an edge with
// direction (dy, dz) is (dz, -dy) / length.

#include "core/base/error.h"
#include "core/geometry/vec.h"

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

namespace bladeaxis::blade {

using Curve2 = std::vector<Vec2>;

// Shoelace area, positive for counter-clockwise curves (mm^2).
double signedArea(std::span<const Vec2> curve);
// Area centroid (not the vertex mean, which cosine spacing would pull towards the edges).
Vec2 areaCentroid(std::span<const Vec2> curve);
// Perimeter including the closing edge.
double perimeter(std::span<const Vec2> curve);

// Checks and normalises a closed curve: rejects non-finite points, drops repeated consecutive
// points and a repeated closing point, requires >= 3 points and a non-zero area, and makes it
// counter-clockwise while keeping vertex 0 first. `what` names the curve in messages.
Result<Curve2> normaliseClosedCurve(std::span<const Vec2> curve, std::string_view what);

// `count` points at equal arc-length spacing along the closed curve, starting at vertex 0.
Curve2 resampleByArcLength(std::span<const Vec2> curve, int count);

// The same closed curve with vertex `start` first.
Curve2 rotateToStart(std::span<const Vec2> curve, std::size_t start);

// Euclidean distance from p to the closed polygon (its edges, not its interior).
double distanceToCurve(const Vec2& p, std::span<const Vec2> curve);

// The phase vertex where a helical revolution starts: the vertex farthest from the chord line
// (the line through the two vertices farthest apart, i.e. leading and trailing edge). On a
// cambered section it lies on the convex suction side. When both sides are equally far (a
// symmetric section) the side whose chord normal points along `preferredSide` wins, so that
// consecutive stations agree. `side` returns the chosen unit chord normal.
std::size_t phaseIndex(std::span<const Vec2> curve, const Vec2& preferredSide, Vec2* side);

} // namespace bladeaxis::blade
