#pragma once
// A synthetic blade (spec §10.4): sections in the planes x = const of W, x along the rotary
// axis A (the span / stacking direction).
//
// Analytic profiles (NACA, turbine) are scaled to the chord c(x), placed with their area
// centroid on the axis, turned by the stagger gamma(x) (counter-clockwise in (y, z), i.e.
// right-handed about +x; gamma = 0 puts the chord along +y with the suction side towards +z)
// and shifted by the stacking-line offset (lean in y, bow in z). With xi = (x - x0)/(x1 - x0):
//     c(x)     = chordStart + (chordEnd - chordStart) xi
//     gamma(x) = staggerStart + (staggerEnd - staggerStart) xi + 4 staggerBow xi (1 - xi)
//     offset   = (lean xi, 4 bow xi (1 - xi))
// Point tables are used as given; the span is their station range and the section at x is
// interpolated between the neighbouring stations on normalised arc length from the phase vertex.

#include "core/base/error.h"
#include "core/blade/closed_curve.h"
#include "core/blade/profiles.h"
#include "core/blade/section_table.h"

#include <cstddef>
#include <variant>

namespace bladeaxis::blade {

struct BladeSpec {
    std::variant<NacaProfile, TurbineProfile, SectionTable> profile = NacaProfile{};
    double spanStart = 0.0; // mm (ignored for tables)
    double spanEnd = 20.0;  // mm
    double chordStart = 70.0;
    double chordEnd = 70.0;
    double staggerStart = 0.349; // rad
    double staggerEnd = 0.524;   // rad
    double staggerBow = 0.0;     // rad, extra stagger at mid-span (quadratic twist)
    double leanMm = 0.0;         // stacking-line offset in y at the span end, |lean| <= 2 mm
    double bowMm = 0.0;          // stacking-line offset in z at mid-span, |bow| <= 2 mm
    int pointsPerSide = 400;     // section density (tables: 2 * this per section)
};

class Blade {
  public:
    static Result<Blade> create(const BladeSpec& spec);

    const BladeSpec& spec() const { return m_spec; }
    double spanStart() const { return m_spanStart; }
    double spanEnd() const { return m_spanEnd; }
    bool isTable() const { return !m_stationX.empty(); }

    // Dense closed counter-clockwise section at x (clamped into the span), vertex 0 = the phase
    // vertex where a helical revolution starts (on the suction side, see phaseIndex).
    Curve2 sectionAt(double x) const;

    // d/dx of vertex `vertex` of sectionAt(x) (mm per mm of span): how that point of the
    // section moves along the span. With (1, v) it spans the surface's span-wise tangent, which
    // the true 3-D surface normal needs besides the section tangent. Outside the span (where
    // sectionAt clamps) it is the velocity at the nearer end. Tables are interpolated linearly
    // between stations: the velocity is that of the station interval holding x, exact for the
    // interpolated surface, and it jumps at the stations, where that surface has a kink.
    Vec2 sectionVelocity(double x, std::size_t vertex) const;

    // Smallest concave radius of curvature of the sections at `samples` evenly spaced x in
    // [xFrom, xTo] and of every table station inside it; +infinity when all are convex.
    double minConcaveRadius(double xFrom, double xTo, int samples = 21) const;

  private:
    Blade() = default;
    Curve2 analyticSectionAt(double x) const;
    Curve2 tableSectionAt(double x) const;
    Vec2 analyticVelocity(double x, std::size_t vertex) const;
    Vec2 tableVelocity(double x, std::size_t vertex) const;
    std::size_t stationBelow(double x) const; // lower station of the interval holding x

    BladeSpec m_spec;
    double m_spanStart = 0.0;
    double m_spanEnd = 0.0;
    Curve2 m_unitSection;           // analytic: unit chord, centroid at origin, phase first
    std::vector<double> m_stationX; // tables
    std::vector<Curve2> m_stations; // tables, resampled to a common count
};

} // namespace bladeaxis::blade
