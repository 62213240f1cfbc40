#include "core/scheduling/tangents.h"

#include "core/base/order_statistic.h"
#include "core/base/parallel.h"
#include "core/scheduling/detail/fast_angles.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace bladeaxis::scheduling {

namespace {

constexpr double kDegenerateChordMm = 1e-9;

// The square root is monotone, so the median of the squared chords gives the same element as
// the median of the chords with one square root instead of one per chord.
double medianChord(std::span<const Vec2> points) {
    const std::size_t chords = points.size() - 1;
    return std::sqrt(nthSmallest(chords, chords / 2, [points](std::size_t i) {
        return (points[i + 1] - points[i]).squaredNorm();
    }));
}

struct Chord {
    Vec2 vector = Vec2::Zero(); // e+_i, or e-_i pointing forward (q_i - q_j)
    double norm = 0.0;
    bool found = false;  // false when every chord on that side is degenerate
    std::size_t end = 0; // j, the far end of the chord
};

Vec2 chordTo(std::span<const Vec2> points, std::size_t i, std::size_t j, int step) {
    return step > 0 ? Vec2(points[j] - points[i]) : Vec2(points[i] - points[j]);
}

// Where no chord reaches `length` (near the path ends): the farthest non-degenerate one.
Chord farthestChord(std::span<const Vec2> points, std::size_t i, int step) {
    const std::size_t n = points.size();
    Chord farthest;
    for (std::size_t j = i; step > 0 ? j + 1 < n : j > 0;) {
        j = step > 0 ? j + 1 : j - 1;
        const Vec2 chord = chordTo(points, i, j, step);
        const double norm = chord.norm();
        if (norm > kDegenerateChordMm && (!farthest.found || norm > farthest.norm)) {
            farthest = {chord, norm, true, j};
        }
    }
    return farthest;
}

// e+_i (step = +1) or e-_i (step = -1): the first chord of length >= `length`. The walk
// compares squared lengths and takes the square root only within a relative 1e-12 of the
// threshold, which decides exactly as comparing the lengths would.
Chord chordFrom(std::span<const Vec2> points, std::size_t i, int step, double length) {
    const std::size_t n = points.size();
    const double surelyLonger = length * length * (1.0 + 1e-12);
    const double surelyShorter = length * length * (1.0 - 1e-12);
    // Scalar coordinates: the same squared norms as chord.squaredNorm(), without building each
    // chord vector on the way.
    const double xi = points[i].x();
    const double yi = points[i].y();
    const auto longEnough = [&](std::size_t j, double& squared) {
        const double dx = points[j].x() - xi;
        const double dy = points[j].y() - yi;
        squared = dx * dx + dy * dy;
        return squared >= surelyLonger || (squared > surelyShorter && std::sqrt(squared) >= length);
    };
    double squared = 0.0;
    if (step > 0) {
        for (std::size_t j = i + 1; j < n; ++j) {
            if (longEnough(j, squared)) {
                return {chordTo(points, i, j, step), std::sqrt(squared), true, j};
            }
        }
    } else {
        for (std::size_t j = i; j-- > 0;) {
            if (longEnough(j, squared)) {
                return {chordTo(points, i, j, step), std::sqrt(squared), true, j};
            }
        }
    }
    return farthestChord(points, i, step);
}

double angleOf(const Vec2& v) {
    return detail::atan2(v.y(), v.x());
}

// The arrays the two passes over the chords read and write, by address.
struct PassArrays {
    PassArrays(std::span<const Vec2> points_, TangentField& field,
               DefaultInitVector<std::uint32_t>& forwardEnd_)
        : points(points_), chordLength(field.chordLengthMm),
          forwardAngle(field.forwardAngle.data()), turning(field.turning.data()),
          norm(field.curvature.data()), forwardEnd(forwardEnd_.data()) {}
    std::span<const Vec2> points;
    double chordLength;
    double* forwardAngle;
    double* turning;
    double* norm; // |e+_i| after pass 1, the curvature after pass 2
    std::uint32_t* forwardEnd;
};

} // namespace

Result<TangentField> computeWrappedTangents(std::span<const Vec2> points, double minChordMm,
                                            double medianFactor) {
    const std::size_t n = points.size();
    if (n < 2) {
        return makeError(ErrorCode::Geometry, "tangents need at least 2 points");
    }
    constexpr std::uint32_t kNoChord = std::numeric_limits<std::uint32_t>::max();
    TangentField field;
    field.chordLengthMm = std::max(minChordMm, medianFactor * medianChord(points));
    field.forwardAngle.resize(n); // wrapped here, unwrapped in place by unwrapForwardAngles
    field.turning.resize(n);
    field.curvature.resize(n); // holds |e+_i| between the two passes
    // Pass 1: the forward chords e+_i, their angles and far ends.
    DefaultInitVector<std::uint32_t> forwardEnd(n);
    // Each range works on copies of the arrays' addresses: read through references to this
    // frame, they were read again after each call the compiler cannot see into, from a cache
    // line the calling thread writes, which slowed two threads more than the work.
    const PassArrays arrays{points, field, forwardEnd};
    forEachRange(n, [arrays](std::size_t begin, std::size_t end) {
        const PassArrays own = arrays;
        for (std::size_t i = begin; i < end; ++i) {
            const Chord forward = chordFrom(own.points, i, +1, own.chordLength);
            own.forwardEnd[i] = forward.found ? static_cast<std::uint32_t>(forward.end) : kNoChord;
            if (forward.found) {
                own.forwardAngle[i] = angleOf(forward.vector);
                own.norm[i] = forward.norm;
            }
        }
    });
    // Pass 2: the backward chords e-_i. On evenly sampled paths e-_i (q_i - q_j) is mostly the
    // very same vector as e+_j, whose angle pass 1 computed: reusing it saves an atan2 per
    // point and gives bit-identical values. Point i reads the angle of j only when j has a
    // forward chord, and writes its own angle only when it has none, so ranges of points can
    // run at once.
    const std::size_t degenerate = forEachUntilFirstFailure(n, [arrays](std::size_t i) {
        const Chord backward = chordFrom(arrays.points, i, -1, arrays.chordLength);
        const bool hasForward = arrays.forwardEnd[i] != kNoChord;
        if (!hasForward && !backward.found) {
            return false;
        }
        double minusAngle = 0.0;
        if (backward.found) {
            minusAngle = arrays.forwardEnd[backward.end] == i ? arrays.forwardAngle[backward.end]
                                                              : angleOf(backward.vector);
        }
        // [A] At the ends one side is missing: use the other, so tau = 0 there.
        const double plusAngle = hasForward ? arrays.forwardAngle[i] : minusAngle;
        const double plusNorm = hasForward ? arrays.norm[i] : backward.norm;
        if (!backward.found) {
            minusAngle = plusAngle;
        }
        const double minusNorm = backward.found ? backward.norm : plusNorm;
        if (!hasForward) {
            arrays.forwardAngle[i] = plusAngle;
        }
        arrays.turning[i] = detail::wrapAngle(plusAngle - minusAngle);
        // [A] Normalised curvature: the chords' directions are the tangents at their
        // mid-points, so tau spans (|e+| + |e-|)/2 of arc. This keeps kappa_h in 1/mm
        // independent of the point density (the literal sum of tau / w of §1.6 is not).
        arrays.norm[i] = 2.0 * arrays.turning[i] / (plusNorm + minusNorm);
        return true;
    });
    if (degenerate < n) {
        return makeError(ErrorCode::Geometry,
                         "the projected path is degenerate at point " + std::to_string(degenerate));
    }
    return field;
}

void unwrapForwardAngles(TangentField& field) {
    // As geometry::unwrap, with the fast wrap, in place: each step reads the wrapped value at i
    // before overwriting it. The loop is a chain through the previous value, so the turn count
    // is guessed from the previous step (the same bits).
    auto& angles = field.forwardAngle;
    if (angles.empty()) {
        return;
    }
    double previous = angles[0];
    double turns = 0.0;
    for (std::size_t i = 1; i < angles.size(); ++i) {
        previous = detail::unwrapNearGuessed(angles[i], previous, turns);
        angles[i] = previous;
    }
}

Result<TangentField> computeTangents(std::span<const Vec2> points, double minChordMm,
                                     double medianFactor) {
    auto field = computeWrappedTangents(points, minChordMm, medianFactor);
    if (field) {
        unwrapForwardAngles(*field);
    }
    return field;
}

} // namespace bladeaxis::scheduling
