#include "core/scheduling/plane_path.h"

#include "core/base/number_io.h"
#include "core/base/order_statistic.h"
#include "core/base/parallel.h"
#include "core/base/tolerances.h"
#include "core/base/units.h"
#include "core/scheduling/detail/fast_angles.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

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

// The input's centres or axes are read through operator[]: an array (std::span), a run of
// values in the caller's records (Vec3Run) or the centres a sample reader makes (SampleCentres).
// Each parallel range reads through a copy of its own: an accessor shared by two threads, on the
// caller's stack beside values the caller's thread writes, made reads through it three times
// slower on two threads than on one.

template <class Centres, class Axes>
Status checkSizes(const Centres& centres, const Axes& axes) {
    if (centres.empty()) {
        return makeError(ErrorCode::InvalidArgument, "the toolpath has no points");
    }
    if (centres.size() > std::numeric_limits<std::uint32_t>::max()) {
        return makeError(ErrorCode::InvalidArgument,
                         "the toolpath has " + std::to_string(centres.size()) +
                             " points, more than the 2^32 - 1 the scheduling indexes");
    }
    if (centres.size() != axes.size()) {
        return makeError(ErrorCode::InvalidArgument, "centres and axes differ in length (" +
                                                         std::to_string(centres.size()) + " vs " +
                                                         std::to_string(axes.size()) + ")");
    }
    return {};
}

template <class Centres, class Axes>
Status faultError(const Centres& centres, const Axes& axes, std::size_t i) {
    if (faultOf(centres[i], axes[i]) == PointFault::NonFinite) {
        return makeError(ErrorCode::Geometry,
                         "non-finite centre or axis at point " + std::to_string(i));
    }
    return makeError(ErrorCode::Geometry, "zero tool axis at point " + std::to_string(i));
}

// Spec §1.2: a centre closer than tol::kDuplicatePointMm to the last kept one is merged into
// it, which keeps S strictly increasing. Whether a centre is kept depends on the last kept centre
// before it, so ranges of inputs are merged at once on the guess that the input before each range
// was kept, and a range whose guess proves wrong is merged again, in order. Each range writes its
// distinct samples from its own first input on (as if nothing before it were merged); ranges
// after merged inputs are moved down afterwards. The arc length is summed in input order, as one
// loop would.
struct MergeRange {
    std::size_t begin = 0, end = 0;
    std::size_t kept = 0;       // distinct samples in the range
    std::size_t lastKept = 0;   // the last kept input up to the range's end
    std::size_t firstFault = 0; // the first faulty input (faultOf) in the range, or end
};

// Merges the inputs of [begin, end); `lastKept` is the last kept input before `begin` (unused
// for begin = 0: the first input is always kept). arcLength holds the steps until summed. The
// inputs are validated in the same pass (a faulty input fails the whole path, whatever it merged).
template <class Centres, class Axes>
MergeRange mergeRange(Centres centres, Axes axes, PlanePath& path, std::size_t begin,
                      std::size_t end, std::size_t lastKept) {
    MergeRange range{begin, end, 0, lastKept, end};
    for (std::size_t i = begin; i < end; ++i) {
        // References into an array (a copy here went through the stack and cost a third of
        // the plane path's time); a centre read through a function is a temporary kept alive.
        const Vec3& centre = centres[i];
        if (range.firstFault == end && faultOf(centre, axes[i]) != PointFault::None) {
            range.firstFault = i;
        }
        const double step = i == 0 ? 0.0 : (centre - centres[range.lastKept]).norm();
        if (i > 0 && step < tol::kDuplicatePointMm) {
            continue; // merged into the last kept sample
        }
        const std::size_t sample = begin + range.kept;
        path.firstInput[sample] = static_cast<std::uint32_t>(i);
        path.arcLength[sample] = step;
        ++range.kept;
        range.lastKept = i;
    }
    return range;
}

template <class Centres, class Axes>
std::vector<MergeRange> mergeRanges(const Centres& centres, const Axes& axes, PlanePath& path) {
    std::vector<MergeRange> ranges(rangeCount(centres.size()));
    forEachRangeOf(centres.size(), ranges.size(),
                   [&](std::size_t r, std::size_t begin, std::size_t end) {
                       ranges[r] = mergeRange(centres, axes, path, begin, end, begin - 1);
                   });
    for (std::size_t r = 1; r < ranges.size(); ++r) {
        const std::size_t lastKept = ranges[r - 1].lastKept;
        if (lastKept != ranges[r].begin - 1) {
            ranges[r] = mergeRange(centres, axes, path, ranges[r].begin, ranges[r].end, lastKept);
        }
    }
    return ranges;
}

// Moves each range's samples down to follow those of the ranges before it (nothing moves when
// no input was merged) and returns the distinct count.
std::size_t compactRanges(std::span<const MergeRange> ranges, PlanePath& path) {
    std::size_t distinct = 0;
    for (const MergeRange& range : ranges) {
        const std::size_t shift = range.begin - distinct;
        if (shift > 0) {
            const auto move = [&](auto& values) {
                const auto from = values.begin() + static_cast<long>(range.begin);
                std::copy(from, from + static_cast<long>(range.kept),
                          from - static_cast<long>(shift));
            };
            move(path.firstInput);
            move(path.arcLength);
        }
        distinct += range.kept;
    }
    return distinct;
}

// Returns the first faulty input (faultOf), or the input count when there is none.
template <class Centres, class Axes>
std::size_t mergeDuplicates(const Centres& centres, const Axes& axes, PlanePath& path) {
    const std::size_t n = centres.size();
    path.firstInput.resize(n);
    path.arcLength.resize(n);
    const std::vector<MergeRange> ranges = mergeRanges(centres, axes, path);
    for (const MergeRange& range : ranges) {
        if (range.firstFault < range.end) {
            return range.firstFault;
        }
    }
    const std::size_t distinct = compactRanges(ranges, path);
    path.firstInput.resize(distinct);
    path.arcLength.resize(distinct);
    double s = 0.0;
    for (double& length : path.arcLength) {
        s += length; // the first step is 0: S starts at 0
        length = s;
    }
    return n;
}

// Spec §1.3: w = +a when the projected path turns positively about +x around its centroid.
// [A] The centroid of the projected points replaces "any point on the axis": for a path that
// is not a whole number of turns the sum then no longer depends on where the axis is.
template <class Centres>
int traversalSignOf(Centres centres, std::span<const std::uint32_t> distinct) {
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
    for (std::size_t i : distinct) {
        const Vec3& centre = centres[i];
        centroid += centre.tail<2>();
    }
    centroid /= static_cast<double>(distinct.size());
    double sum = 0.0;
    for (std::size_t k = 0; k + 1 < distinct.size(); ++k) {
        const Vec3& q = centres[distinct[k]];
        const Vec3& next = centres[distinct[k + 1]];
        const Eigen::Vector2d r = q.tail<2>() - centroid;
        const Eigen::Vector2d d = next.tail<2>() - q.tail<2>();
        sum += r.x() * d.y() - r.y() * d.x(); // (y, z) components: (r x d) . x
    }
    return sum >= 0.0 ? 1 : -1;
}

// x / |V| of the input axes of the distinct samples [begin, end) (the axial component of
// V.normalized() without the other two divisions), and their least and greatest values. The
// samples' inputs and the values are passed by address: read through a reference to the path,
// the addresses were read again after every square root, from the calling thread's frame.
template <class Axes>
std::pair<double, double> axialRange(const std::uint32_t* inputs, Axes axes, double* axial,
                                     std::size_t begin, std::size_t end) {
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    for (std::size_t k = begin; k < end; ++k) {
        const Vec3& axis = axes[inputs[k]];
        axial[k] = std::clamp(axis.x() / axis.norm(), -1.0, 1.0);
        low = std::min(low, axial[k]);
        high = std::max(high, axial[k]);
    }
    return {low, high};
}

// Spec §1.2: B_in = asin(V . a) must be constant; otherwise take the median and warn. asin is
// monotone, so the extremes and the median are taken on the axial values and only those three
// go through asin (the same values as asin of every sample, without n asin calls).
double tiltFrom(std::span<const double> axial, std::span<const std::pair<double, double>> extremes,
                std::vector<std::string>& warn) {
    double low = extremes.front().first;
    double high = extremes.front().second;
    for (const auto& [rangeLow, rangeHigh] : extremes) {
        low = std::min(low, rangeLow);
        high = std::max(high, rangeHigh);
    }
    const double spread = std::asin(high) - std::asin(low);
    // A constant tilt (the usual case) is its own median. Otherwise nthSmallest finds it on
    // every thread, without reordering the values.
    const double median = std::asin(
        low == high ? low : nthSmallest(axial.size(), axial.size() / 2, [axial](std::size_t k) {
            return axial[k];
        }));
    if (spread > tol::kConstantTiltRad) {
        warn.push_back("input tilt B is not constant (spread " +
                       formatFixed(units::radToDeg(spread), 4) + " deg); the median " +
                       formatFixed(units::radToDeg(median), 4) + " deg is used");
    }
    return median;
}

// The traversal sign is one sum in order, so it takes one thread; meanwhile the axial values
// of the tilt, in chunks handed to whichever thread is free, take the others, and the thread
// of the sum joins them when it is done.
template <class Centres, class Axes>
void addSignAndTilt(PlanePath& path, const Centres& centres, const Axes& axes) {
    const std::size_t n = path.firstInput.size();
    DefaultInitVector<double> axial(n);
    const std::size_t chunks = (n + kMinParallelRange - 1) / kMinParallelRange;
    std::vector<std::pair<double, double>> extremes(chunks);
    const std::uint32_t* const inputs = path.firstInput.data();
    int sign = 1;
    // The work is two passes over the samples: the sum and the axial values.
    forEachItem(chunks + 1, 2 * n, [&, inputs, values = axial.data()](std::size_t item) {
        if (item == 0) {
            sign = traversalSignOf(centres, path.firstInput);
            return;
        }
        const std::size_t begin = (item - 1) * kMinParallelRange;
        extremes[item - 1] =
            axialRange(inputs, axes, values, begin, std::min(n, begin + kMinParallelRange));
    });
    path.traversalSign = sign;
    path.tiltB0 = tiltFrom(axial, extremes, path.warnings);
}

template <class Centres, class Axes>
Result<PlanePath> preparePlanePathOf(const Centres& centres, const Axes& axes) {
    if (auto status = checkSizes(centres, axes); !status) {
        return std::unexpected(status.error());
    }
    PlanePath path;
    if (const std::size_t fault = mergeDuplicates(centres, axes, path); fault < centres.size()) {
        return std::unexpected(faultError(centres, axes, fault).error());
    }
    if (path.firstInput.size() < 3) {
        return makeError(ErrorCode::Geometry,
                         "the toolpath needs at least 3 distinct centres, it has " +
                             std::to_string(path.firstInput.size()));
    }
    if (path.firstInput.size() < centres.size()) {
        path.warnings.push_back(std::to_string(centres.size() - path.firstInput.size()) +
                                " duplicate centre(s) merged");
    }
    addSignAndTilt(path, centres, axes);
    if (std::cos(path.tiltB0) < 1e-6) {
        return makeError(ErrorCode::Geometry, "the tool axis is parallel to the rotary axis");
    }
    const std::size_t distinct = path.firstInput.size();
    path.points.resize(distinct);
    forEachRange(distinct, [&](std::size_t begin, std::size_t end) {
        const Centres ownCentres = centres;
        for (std::size_t k = begin; k < end; ++k) {
            const Vec3& q = ownCentres[path.firstInput[k]];
            path.points[k] = Vec2(q.z(), -path.traversalSign * q.y());
        }
    });
    return path;
}

template <class Axes>
void addOriginalAnglesOf(PlanePath& path, const Axes& axes) {
    const std::size_t distinct = path.firstInput.size();
    path.originalAngle.resize(distinct);
    forEachRange(distinct, [&](std::size_t begin, std::size_t end) {
        const Axes ownAxes = axes;
        for (std::size_t k = begin; k < end; ++k) {
            path.originalAngle[k] = planeAngle(ownAxes[path.firstInput[k]], path.traversalSign);
        }
    });
}

} // namespace

Result<PlanePath> preparePlanePath(std::span<const Vec3> centres, std::span<const Vec3> axes) {
    return preparePlanePathOf(centres, axes);
}

void addOriginalAngles(PlanePath& path, std::span<const Vec3> axes) {
    addOriginalAnglesOf(path, axes);
}

void addOriginalAngles(PlanePath& path, const Vec3Run& axes) {
    if (const auto array = axes.contiguous()) {
        addOriginalAnglesOf(path, *array);
    } else {
        addOriginalAnglesOf(path, axes);
    }
}

Result<PlanePath> preparePlanePath(const ScheduleSamples& samples) {
    const auto centres = samples.contiguousCentres();
    const auto axes = samples.axes.contiguous();
    if (centres && axes) {
        return preparePlanePathOf(*centres, *axes);
    }
    return preparePlanePathOf(SampleCentres(samples), samples.axes);
}

} // namespace bladeaxis::scheduling
