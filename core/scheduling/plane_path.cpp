#include "core/scheduling/plane_path.h"

#include "core/base/number_io.h"
#include "core/base/parallel.h"
#include "core/base/tolerances.h"
#include "core/base/units.h"
#include "core/scheduling/detail/fast_angles.h"

#include <algorithm>
#include <cmath>

namespace bladeaxis::scheduling {

double planeAngle(const Vec3& v, int traversalSign) {
    // r = +z, p = w x r = traversalSign * (x x z) = -traversalSign * y.
    return detail::atan2(-traversalSign * v.y(), v.z());
}

Vec3 axisFromPlaneAngle(double angle, double tiltB0, int traversalSign) {
    const double inPlane = std::cos(tiltB0);
    return {std::sin(tiltB0), -traversalSign * std::sin(angle) * inPlane,
            std::cos(angle) * inPlane};
}

namespace {

enum class PointFault { None, NonFinite, ZeroAxis };

PointFault faultOf(const Vec3& centre, const Vec3& axis) {
    if (!isFinite(centre) || !isFinite(axis)) {
        return PointFault::NonFinite;
    }
    if (axis.squaredNorm() < tol::kZeroVector * tol::kZeroVector) { // no square root
        return PointFault::ZeroAxis;
    }
    return PointFault::None;
}

Status validateInput(std::span<const Vec3> centres, std::span<const Vec3> axes, unsigned threads) {
    if (centres.empty()) {
        return makeError(ErrorCode::InvalidArgument, "the toolpath has no points");
    }
    if (centres.size() != axes.size()) {
        return makeError(ErrorCode::InvalidArgument, "centres and axes differ in length (" +
                                                         std::to_string(centres.size()) + " vs " +
                                                         std::to_string(axes.size()) + ")");
    }
    const std::size_t n = centres.size();
    const std::size_t i = forEachUntilFirstFailure(n, threads, [&](std::size_t k) {
        return faultOf(centres[k], axes[k]) == PointFault::None;
    });
    if (i == n) {
        return {};
    }
    if (faultOf(centres[i], axes[i]) == PointFault::NonFinite) {
        return makeError(ErrorCode::Geometry,
                         "non-finite centre or axis at point " + std::to_string(i));
    }
    return makeError(ErrorCode::Geometry, "zero tool axis at point " + std::to_string(i));
}

// Spec §1.3: w = +a when the projected path turns positively about +x around its centroid.
// [A] The centroid of the projected points replaces "any point on the axis": for a path that
// is not a whole number of turns the sum then no longer depends on where the axis is.
int traversalSignOf(std::span<const Vec3> centres) {
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
    for (const Vec3& q : centres) {
        centroid += q.tail<2>();
    }
    centroid /= static_cast<double>(centres.size());
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < centres.size(); ++i) {
        const Eigen::Vector2d r = centres[i].tail<2>() - centroid;
        const Eigen::Vector2d d = centres[i + 1].tail<2>() - centres[i].tail<2>();
        sum += r.x() * d.y() - r.y() * d.x(); // (y, z) components: (r x d) . x
    }
    return sum >= 0.0 ? 1 : -1;
}

// Spec §1.2: B_in = asin(V . a) must be constant; otherwise take the median and warn.
double tiltOf(const PlanePath& path, std::span<const Vec3> axes, std::vector<std::string>& warn,
              unsigned threads) {
    // asin is monotone, so the extremes and the median are taken on V . a / |V| and only those
    // three go through asin (the same values as asin of every sample, without n asin calls).
    std::vector<double> axial(path.firstInput.size());
    forEachRange(axial.size(), threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
            // x / |V|: the axial component of V.normalized() without the other two divisions.
            const Vec3& axis = axes[path.firstInput[k]];
            axial[k] = std::clamp(axis.x() / axis.norm(), -1.0, 1.0);
        }
    });
    const auto [low, high] = std::minmax_element(axial.begin(), axial.end());
    const double spread = std::asin(*high) - std::asin(*low);
    std::nth_element(axial.begin(), axial.begin() + static_cast<long>(axial.size() / 2),
                     axial.end());
    const double median = std::asin(axial[axial.size() / 2]);
    if (spread > tol::kConstantTiltRad) {
        warn.push_back("input tilt B is not constant (spread " +
                       formatFixed(units::radToDeg(spread), 4) + " deg); the median " +
                       formatFixed(units::radToDeg(median), 4) + " deg is used");
    }
    return median;
}

} // namespace

Result<PlanePath> preparePlanePath(std::span<const Vec3> centres, std::span<const Vec3> axes,
                                   unsigned threads) {
    if (auto status = validateInput(centres, axes, threads); !status) {
        return std::unexpected(status.error());
    }
    PlanePath path;
    path.sampleOfInput.resize(centres.size());
    path.centres.reserve(centres.size());
    path.firstInput.reserve(centres.size());
    path.arcLength.reserve(centres.size());
    double s = 0.0;
    for (std::size_t i = 0; i < centres.size(); ++i) {
        if (!path.centres.empty()) {
            const double step = (centres[i] - path.centres.back()).norm();
            if (step < tol::kDuplicatePointMm) { // spec §1.2: merge, keep S strictly increasing
                path.sampleOfInput[i] = path.centres.size() - 1;
                continue;
            }
            s += step;
        }
        path.sampleOfInput[i] = path.centres.size();
        path.centres.push_back(centres[i]);
        path.firstInput.push_back(i);
        path.arcLength.push_back(s);
    }
    if (path.centres.size() < 3) {
        return makeError(ErrorCode::Geometry,
                         "the toolpath needs at least 3 distinct centres, it has " +
                             std::to_string(path.centres.size()));
    }
    if (path.centres.size() < centres.size()) {
        path.warnings.push_back(std::to_string(centres.size() - path.centres.size()) +
                                " duplicate centre(s) merged");
    }
    path.traversalSign = traversalSignOf(path.centres);
    path.tiltB0 = tiltOf(path, axes, path.warnings, threads);
    if (std::cos(path.tiltB0) < 1e-6) {
        return makeError(ErrorCode::Geometry, "the tool axis is parallel to the rotary axis");
    }
    path.points.resize(path.centres.size());
    path.originalAngle.resize(path.centres.size());
    forEachRange(path.centres.size(), threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
            const Vec3& q = path.centres[k];
            path.points[k] = Vec2(q.z(), -path.traversalSign * q.y());
            path.originalAngle[k] = planeAngle(axes[path.firstInput[k]], path.traversalSign);
        }
    });
    return path;
}

} // namespace bladeaxis::scheduling
