#include "core/blade/blade.h"

#include "core/base/number_io.h"
#include "core/blade/offset_curve.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace bladeaxis::blade {
namespace {

Status outOfRange(const std::string& name, double value, const std::string& limit) {
    return makeError(ErrorCode::InvalidArgument,
                     name + " = " + formatShortest(value) + " is outside " + limit);
}

Status validateSpec(const BladeSpec& spec, bool table) {
    if (spec.pointsPerSide < 8 || spec.pointsPerSide > 100000) {
        return outOfRange("points per side", spec.pointsPerSide, "[8, 100000]");
    }
    if (table) {
        return {};
    }
    if (!std::isfinite(spec.spanStart) || !std::isfinite(spec.spanEnd) ||
        !(spec.spanEnd > spec.spanStart)) {
        return outOfRange("span end (mm)", spec.spanEnd,
                          "(span start = " + formatShortest(spec.spanStart) + ", inf)");
    }
    for (double chord : {spec.chordStart, spec.chordEnd}) {
        if (!(chord >= 1.0 && chord <= 5000.0)) {
            return outOfRange("chord (mm)", chord, "[1, 5000]");
        }
    }
    for (double stagger : {spec.staggerStart, spec.staggerEnd, spec.staggerBow}) {
        if (!(std::abs(stagger) <= 2.0 * std::numbers::pi)) {
            return outOfRange("stagger (rad)", stagger, "[-2 pi, 2 pi]");
        }
    }
    if (!(std::abs(spec.leanMm) <= 2.0)) {
        return outOfRange("lean (mm)", spec.leanMm, "[-2, 2]");
    }
    if (!(std::abs(spec.bowMm) <= 2.0)) {
        return outOfRange("bow (mm)", spec.bowMm, "[-2, 2]");
    }
    return {};
}

// Unit-chord section with its area centroid at the origin and the phase vertex first.
Result<Curve2> unitSection(const BladeSpec& spec) {
    Result<Curve2> curve =
        std::holds_alternative<NacaProfile>(spec.profile)
            ? nacaSection(std::get<NacaProfile>(spec.profile), spec.pointsPerSide)
            : turbineSection(std::get<TurbineProfile>(spec.profile), spec.pointsPerSide);
    if (!curve) {
        return curve;
    }
    const Vec2 centroid = areaCentroid(*curve);
    for (Vec2& p : *curve) {
        p -= centroid;
    }
    // +z is the suction side of the generated profiles: it wins a tie (symmetric sections).
    return rotateToStart(*curve, phaseIndex(*curve, Vec2(0.0, 1.0), nullptr));
}

} // namespace

Result<Blade> Blade::create(const BladeSpec& spec) {
    const bool table = std::holds_alternative<SectionTable>(spec.profile);
    if (auto ok = validateSpec(spec, table); !ok) {
        return std::unexpected(ok.error());
    }
    Blade blade;
    blade.m_spec = spec;
    if (!table) {
        Result<Curve2> unit = unitSection(spec);
        if (!unit) {
            return std::unexpected(unit.error());
        }
        blade.m_unitSection = std::move(*unit);
        blade.m_spanStart = spec.spanStart;
        blade.m_spanEnd = spec.spanEnd;
        return blade;
    }
    Result<SectionTable> normalised = normaliseSectionTable(std::get<SectionTable>(spec.profile));
    if (!normalised) {
        return std::unexpected(normalised.error());
    }
    const int count = 2 * spec.pointsPerSide;
    for (const SectionStation& station : normalised->stations) {
        blade.m_stationX.push_back(station.x);
        blade.m_stations.push_back(resampleByArcLength(station.points, count));
    }
    blade.m_spanStart = blade.m_stationX.front();
    blade.m_spanEnd = blade.m_stationX.back();
    blade.m_spec.profile = std::move(*normalised);
    return blade;
}

Curve2 Blade::sectionAt(double x) const {
    const double clamped = std::clamp(x, m_spanStart, m_spanEnd);
    return isTable() ? tableSectionAt(clamped) : analyticSectionAt(clamped);
}

Curve2 Blade::analyticSectionAt(double x) const {
    const double xi = (x - m_spanStart) / (m_spanEnd - m_spanStart);
    const double bump = 4.0 * xi * (1.0 - xi);
    const double chord = m_spec.chordStart + (m_spec.chordEnd - m_spec.chordStart) * xi;
    const double stagger = m_spec.staggerStart + (m_spec.staggerEnd - m_spec.staggerStart) * xi +
                           m_spec.staggerBow * bump;
    const Vec2 offset(m_spec.leanMm * xi, m_spec.bowMm * bump);
    const double c = std::cos(stagger);
    const double s = std::sin(stagger);
    Curve2 section;
    section.reserve(m_unitSection.size());
    for (const Vec2& p : m_unitSection) {
        const Vec2 scaled = chord * p;
        section.emplace_back(
            offset + Vec2(c * scaled.x() - s * scaled.y(), s * scaled.x() + c * scaled.y()));
    }
    return section;
}

std::size_t Blade::stationBelow(double x) const {
    const auto upper = std::upper_bound(m_stationX.begin(), m_stationX.end(), x);
    const std::size_t hi = std::min<std::size_t>(
        static_cast<std::size_t>(upper - m_stationX.begin()), m_stationX.size() - 1);
    return hi - 1;
}

Curve2 Blade::tableSectionAt(double x) const {
    const std::size_t lo = stationBelow(x);
    const std::size_t hi = lo + 1;
    const double t = std::clamp((x - m_stationX[lo]) / (m_stationX[hi] - m_stationX[lo]), 0.0, 1.0);
    Curve2 section(m_stations[lo].size());
    for (std::size_t i = 0; i < section.size(); ++i) {
        section[i] = (1.0 - t) * m_stations[lo][i] + t * m_stations[hi][i];
    }
    return section;
}

Vec2 Blade::sectionVelocity(double x, std::size_t vertex) const {
    const double clamped = std::clamp(x, m_spanStart, m_spanEnd);
    return isTable() ? tableVelocity(clamped, vertex) : analyticVelocity(clamped, vertex);
}

// The x-derivative of analyticSectionAt's point offset(x) + chord(x) rot(stagger(x)) p.
Vec2 Blade::analyticVelocity(double x, std::size_t vertex) const {
    const double span = m_spanEnd - m_spanStart;
    const double xi = (x - m_spanStart) / span;
    const double bump = 4.0 * xi * (1.0 - xi);
    const double bumpRate = 4.0 * (1.0 - 2.0 * xi) / span;
    const double chord = m_spec.chordStart + (m_spec.chordEnd - m_spec.chordStart) * xi;
    const double chordRate = (m_spec.chordEnd - m_spec.chordStart) / span;
    const double stagger = m_spec.staggerStart + (m_spec.staggerEnd - m_spec.staggerStart) * xi +
                           m_spec.staggerBow * bump;
    const double staggerRate =
        (m_spec.staggerEnd - m_spec.staggerStart) / span + m_spec.staggerBow * bumpRate;
    const Vec2 offsetRate(m_spec.leanMm / span, m_spec.bowMm * bumpRate);
    const double c = std::cos(stagger);
    const double s = std::sin(stagger);
    const Vec2& p = m_unitSection[vertex % m_unitSection.size()];
    const Vec2 turned(c * p.x() - s * p.y(), s * p.x() + c * p.y());
    const Vec2 quarter(-turned.y(), turned.x()); // d(rot(stagger) p) / d stagger
    return offsetRate + chordRate * turned + chord * staggerRate * quarter;
}

Vec2 Blade::tableVelocity(double x, std::size_t vertex) const {
    const std::size_t lo = stationBelow(x);
    const std::size_t i = vertex % m_stations[lo].size();
    return (m_stations[lo + 1][i] - m_stations[lo][i]) / (m_stationX[lo + 1] - m_stationX[lo]);
}

double Blade::minConcaveRadius(double xFrom, double xTo, int samples) const {
    double best = std::numeric_limits<double>::infinity();
    const int count = std::max(samples, 2);
    for (int k = 0; k < count; ++k) {
        const double x = xFrom + (xTo - xFrom) * static_cast<double>(k) / (count - 1);
        best = std::min(best, blade::minConcaveRadius(sectionAt(x)));
    }
    for (double x : m_stationX) {
        if (x >= std::min(xFrom, xTo) && x <= std::max(xFrom, xTo)) {
            best = std::min(best, blade::minConcaveRadius(sectionAt(x)));
        }
    }
    return best;
}

} // namespace bladeaxis::blade
