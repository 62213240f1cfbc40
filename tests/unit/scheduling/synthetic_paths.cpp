#include "tests/unit/scheduling/synthetic_paths.h"

#include <cmath>
#include <numbers>

namespace bladeaxis::scheduling::testing {

namespace {

constexpr double kPi = std::numbers::pi;

struct NacaPoint {
    Vec2 upper, lower;
};

NacaPoint nacaAt(double m, double p, double t, double chord, double x) {
    const double yt = 5.0 * t *
                      (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x -
                       0.1036 * x * x * x * x);
    double yc = 0.0;
    double slope = 0.0;
    if (m > 0.0 && x < p) {
        yc = m / (p * p) * (2.0 * p * x - x * x);
        slope = 2.0 * m / (p * p) * (p - x);
    } else if (m > 0.0) {
        yc = m / ((1.0 - p) * (1.0 - p)) * ((1.0 - 2.0 * p) + 2.0 * p * x - x * x);
        slope = 2.0 * m / ((1.0 - p) * (1.0 - p)) * (p - x);
    }
    const double angle = std::atan(slope);
    const Vec2 upper(x - yt * std::sin(angle), yc + yt * std::cos(angle));
    const Vec2 lower(x + yt * std::sin(angle), yc - yt * std::cos(angle));
    return {chord * upper, chord * lower};
}

Vec2 outwardNormal(const Vec2& from, const Vec2& to) {
    const Vec2 d = (to - from).normalized();
    return {d.y(), -d.x()}; // right of the direction: outward for a counter-clockwise curve
}

double angleOf(const Vec2& v) {
    return std::atan2(v.y(), v.x());
}

} // namespace

std::vector<Vec2> nacaSection(double m, double p, double t, double chord, std::size_t perSide) {
    std::vector<Vec2> points;
    // Upper surface from the trailing edge to the leading edge, then the lower one back:
    // counter-clockwise. The TE point (x = 1) and the LE point (x = 0) appear once.
    for (std::size_t k = 0; k + 1 < perSide; ++k) {
        const double beta = kPi * static_cast<double>(k) / static_cast<double>(perSide - 1);
        const double x = 0.5 * (1.0 + std::cos(beta));
        points.push_back(k == 0 ? Vec2(chord, 0.0) : nacaAt(m, p, t, chord, x).upper);
    }
    for (std::size_t k = 0; k + 1 < perSide; ++k) {
        const double beta = kPi * static_cast<double>(k) / static_cast<double>(perSide - 1);
        const double x = 0.5 * (1.0 - std::cos(beta));
        points.push_back(nacaAt(m, p, t, chord, x).lower);
    }
    return points;
}

std::vector<Vec2> regularPolygon(std::size_t n, double r, double phase) {
    std::vector<Vec2> points;
    for (std::size_t k = 0; k < n; ++k) {
        const double a = phase + 2.0 * kPi * static_cast<double>(k) / static_cast<double>(n);
        points.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    return points;
}

OffsetCurve offsetSection(const std::vector<Vec2>& section, double radius, double maxArcStepRad) {
    OffsetCurve curve;
    const std::size_t n = section.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2& prev = section[(i + n - 1) % n];
        const Vec2& here = section[i];
        const Vec2& next = section[(i + 1) % n];
        const Vec2 n1 = outwardNormal(prev, here);
        const Vec2 n2 = outwardNormal(here, next);
        const double turn = std::remainder(angleOf(n2) - angleOf(n1), 2.0 * kPi);
        if (turn > maxArcStepRad) { // sharp convex vertex: an arc of the ball
            const int steps = static_cast<int>(std::ceil(turn / maxArcStepRad));
            for (int k = 0; k <= steps; ++k) {
                const double a = angleOf(n1) + turn * k / steps;
                const Vec2 normal(std::cos(a), std::sin(a));
                curve.points.push_back(here + radius * normal);
                curve.normals.push_back(normal);
            }
            continue;
        }
        const Vec2 normal = (n1 + n2).normalized();
        curve.points.push_back(here + radius / std::cos(0.5 * turn) * normal);
        curve.normals.push_back(normal);
    }
    return curve;
}

ScheduleInput helicalPath(const OffsetCurve& curve, const HelixOptions& options) {
    const std::size_t m = curve.points.size();
    std::vector<double> fraction(m + 1, 0.0);
    for (std::size_t j = 1; j <= m; ++j) {
        fraction[j] = fraction[j - 1] + (curve.points[j % m] - curve.points[j - 1]).norm();
    }
    for (double& f : fraction) {
        f /= fraction[m];
    }
    ScheduleInput input;
    input.toolRadius = options.toolRadius;
    const auto start = static_cast<std::size_t>(options.startFraction * static_cast<double>(m));
    const auto total = static_cast<std::size_t>(options.revolutions * static_cast<double>(m));
    for (std::size_t k = 0; k <= total; ++k) {
        const std::size_t j = (start + k) % m;
        const double turns = static_cast<double>((start + k) / m) + fraction[j];
        const double x = options.pitchMm * turns;
        const Eigen::Rotation2Dd twist(options.twistRadPerMm * x);
        const Vec2 q = twist * curve.points[j];
        const Vec2 normal = twist * curve.normals[j];
        const Vec2 tangent(-normal.y(), normal.x()); // feed direction (counter-clockwise)
        const Vec2 d = std::cos(options.leadRad) * normal + std::sin(options.leadRad) * tangent;
        const double sign = options.mirror ? -1.0 : 1.0;
        input.centres.emplace_back(x, sign * q.x(), q.y());
        input.axes.emplace_back(std::sin(options.tiltRad), sign * std::cos(options.tiltRad) * d.x(),
                                std::cos(options.tiltRad) * d.y());
    }
    return input;
}

OffsetCurve appendixBCurve(double toolRadius) {
    std::vector<Vec2> section = nacaSection(0.10, 0.45, 0.12, 80.0, 241);
    Vec2 centroid = Vec2::Zero();
    for (const Vec2& p : section) {
        centroid += p;
    }
    centroid /= static_cast<double>(section.size());
    for (Vec2& p : section) {
        p -= centroid; // the rotary axis passes through the section's middle
    }
    return offsetSection(section, toolRadius, 5.0 * kPi / 180.0);
}

} // namespace bladeaxis::scheduling::testing
