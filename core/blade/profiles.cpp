#include "core/blade/profiles.h"

#include "core/base/number_io.h"
#include "core/base/units.h"

#include <cmath>
#include <string>

namespace bladeaxis::blade {
namespace {

Status outOfRange(const std::string& name, double value, const std::string& limit) {
    return makeError(ErrorCode::InvalidArgument,
                     name + " = " + formatShortest(value) + " is outside " + limit);
}

// Chord fraction of sample k of n on one side, cosine spacing: dense at both edges.
double cosineStation(int k, int n) {
    return 0.5 * (1.0 - std::cos(units::kPi * static_cast<double>(k) / n));
}

Status checkPointsPerSide(int pointsPerSide) {
    if (pointsPerSide < 8 || pointsPerSide > 100000) {
        return outOfRange("points per side", pointsPerSide, "[8, 100000]");
    }
    return {};
}

} // namespace

Status validate(const NacaProfile& profile) {
    if (!(profile.camber >= 0.0 && profile.camber <= 0.2)) {
        return outOfRange("NACA camber m", profile.camber, "[0, 0.2]");
    }
    if (profile.camber > 0.0 && !(profile.camberPosition >= 0.1 && profile.camberPosition <= 0.9)) {
        return outOfRange("NACA camber position p", profile.camberPosition, "[0.1, 0.9]");
    }
    if (!(profile.thickness >= 0.01 && profile.thickness <= 0.4)) {
        return outOfRange("NACA thickness t", profile.thickness, "[0.01, 0.4]");
    }
    return {};
}

Status validate(const TurbineProfile& profile) {
    if (!(profile.turning >= 0.0 && profile.turning <= units::degToRad(140.0))) {
        return outOfRange("turbine turning angle (rad)", profile.turning, "[0, 140 deg]");
    }
    if (!(profile.maxThickness >= 0.02 && profile.maxThickness <= 0.4)) {
        return outOfRange("turbine max thickness", profile.maxThickness, "[0.02, 0.4]");
    }
    const double half = 0.5 * profile.maxThickness;
    if (!(profile.leRadius > 0.0 && profile.leRadius <= half)) {
        return outOfRange("turbine leading-edge radius", profile.leRadius,
                          "(0, max thickness / 2 = " + formatShortest(half) + "]");
    }
    if (!(profile.teRadius > 0.0 && profile.teRadius <= half)) {
        return outOfRange("turbine trailing-edge radius", profile.teRadius,
                          "(0, max thickness / 2 = " + formatShortest(half) + "]");
    }
    return {};
}

double nacaCamber(const NacaProfile& profile, double x) {
    const double m = profile.camber;
    const double p = profile.camberPosition;
    if (m <= 0.0) {
        return 0.0;
    }
    if (x < p) {
        return m / (p * p) * (2.0 * p * x - x * x);
    }
    return m / ((1.0 - p) * (1.0 - p)) * ((1.0 - 2.0 * p) + 2.0 * p * x - x * x);
}

double nacaCamberSlope(const NacaProfile& profile, double x) {
    const double m = profile.camber;
    const double p = profile.camberPosition;
    if (m <= 0.0) {
        return 0.0;
    }
    if (x < p) {
        return 2.0 * m / (p * p) * (p - x);
    }
    return 2.0 * m / ((1.0 - p) * (1.0 - p)) * (p - x);
}

double nacaHalfThickness(double thickness, double x) {
    const double sx = std::sqrt(std::max(x, 0.0));
    return 5.0 * thickness *
           (0.2969 * sx + x * (-0.1260 + x * (-0.3516 + x * (0.2843 + x * -0.1036))));
}

Result<Curve2> nacaSection(const NacaProfile& profile, int pointsPerSide) {
    if (auto ok = validate(profile); !ok) {
        return std::unexpected(ok.error());
    }
    if (auto ok = checkPointsPerSide(pointsPerSide); !ok) {
        return std::unexpected(ok.error());
    }
    const int n = pointsPerSide;
    Curve2 points;
    points.reserve(static_cast<std::size_t>(2 * n));
    // Thickness is applied perpendicular to the camber line (the standard definition).
    auto surface = [&](double x, double sign) {
        const double slope = std::atan(nacaCamberSlope(profile, x));
        const double yt = nacaHalfThickness(profile.thickness, x);
        return Vec2(x - sign * yt * std::sin(slope),
                    nacaCamber(profile, x) + sign * yt * std::cos(slope));
    };
    for (int k = n; k >= 0; --k) { // suction side, trailing edge to leading edge
        points.push_back(surface(cosineStation(k, n), 1.0));
    }
    for (int k = 1; k < n; ++k) { // pressure side, back to (not including) the trailing edge
        points.push_back(surface(cosineStation(k, n), -1.0));
    }
    return normaliseClosedCurve(points, "NACA section");
}

Result<Curve2> turbineSection(const TurbineProfile& profile, int pointsPerSide) {
    if (auto ok = validate(profile); !ok) {
        return std::unexpected(ok.error());
    }
    if (auto ok = checkPointsPerSide(pointsPerSide); !ok) {
        return std::unexpected(ok.error());
    }
    const double half = 0.5 * profile.turning;
    const bool straight = half < 1e-9;
    const double radius = straight ? 0.0 : 0.5 / std::sin(half);
    // Camber angle psi runs from +half (leading edge) to -half (trailing edge).
    auto camberAt = [&](double xi) -> Vec2 {
        if (straight) {
            return {xi, 0.0};
        }
        const double psi = half - xi * profile.turning;
        return {0.5 - radius * std::sin(psi), radius * (std::cos(psi) - std::cos(half))};
    };
    auto normalAt = [&](double xi) {
        const double psi = half - xi * profile.turning;
        return Vec2(-std::sin(psi), std::cos(psi));
    };
    // Smoothstep blend of the edge radii plus a bump: zero slope at both ends, so the sides
    // meet the edge circles tangentially.
    auto halfThickness = [&](double xi) {
        const double blend = xi * xi * (3.0 - 2.0 * xi);
        const double bump = 16.0 * xi * xi * (1.0 - xi) * (1.0 - xi);
        const double edges = 0.5 * (profile.leRadius + profile.teRadius);
        return profile.leRadius + (profile.teRadius - profile.leRadius) * blend +
               (0.5 * profile.maxThickness - edges) * bump;
    };
    const int n = pointsPerSide;
    const int capPoints = std::max(8, n / 4);
    Curve2 points;
    auto cap = [&](const Vec2& centre, double r, double from) {
        for (int k = 1; k < capPoints; ++k) {
            const double a = from + units::kPi * static_cast<double>(k) / capPoints;
            points.emplace_back(centre + r * Vec2(std::cos(a), std::sin(a)));
        }
    };
    for (int k = n; k >= 0; --k) { // suction side, trailing edge to leading edge
        const double xi = cosineStation(k, n);
        points.push_back(camberAt(xi) + halfThickness(xi) * normalAt(xi));
    }
    const Vec2 leNormal = normalAt(0.0);
    cap(camberAt(0.0), profile.leRadius, std::atan2(leNormal.y(), leNormal.x()));
    for (int k = 0; k <= n; ++k) { // pressure side, leading edge to trailing edge
        const double xi = cosineStation(k, n);
        points.push_back(camberAt(xi) - halfThickness(xi) * normalAt(xi));
    }
    const Vec2 teNormal = -normalAt(1.0);
    cap(camberAt(1.0), profile.teRadius, std::atan2(teNormal.y(), teNormal.x()));
    return normaliseClosedCurve(points, "turbine section");
}

} // namespace bladeaxis::blade
