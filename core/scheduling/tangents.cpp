#include "core/scheduling/tangents.h"

#include "core/scheduling/detail/fast_angles.h"

#include <algorithm>
#include <cmath>

namespace bladeaxis::scheduling {

namespace {

constexpr double kDegenerateChordMm = 1e-9;

double medianChord(std::span<const Vec2> points) {
    std::vector<double> chords;
    chords.reserve(points.size());
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        chords.push_back((points[i + 1] - points[i]).norm());
    }
    auto middle = chords.begin() + static_cast<long>(chords.size() / 2);
    std::nth_element(chords.begin(), middle, chords.end());
    return *middle;
}

struct Chord {
    Vec2 vector = Vec2::Zero(); // e+_i, or e-_i pointing forward (q_i - q_j)
    double norm = 0.0;
    bool found = false; // false when every chord on that side is degenerate
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
            farthest = {chord, norm, true};
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
    for (std::size_t j = i; step > 0 ? j + 1 < n : j > 0;) {
        j = step > 0 ? j + 1 : j - 1;
        const Vec2 chord = chordTo(points, i, j, step);
        const double squared = chord.squaredNorm();
        if (squared >= surelyLonger || (squared > surelyShorter && std::sqrt(squared) >= length)) {
            return {chord, std::sqrt(squared), true};
        }
    }
    return farthestChord(points, i, step);
}

double angleOf(const Vec2& v) {
    return std::atan2(v.y(), v.x());
}

} // namespace

Result<TangentField> computeTangents(std::span<const Vec2> points, double minChordMm,
                                     double medianFactor) {
    const std::size_t n = points.size();
    if (n < 2) {
        return makeError(ErrorCode::Geometry, "tangents need at least 2 points");
    }
    TangentField field;
    field.chordLengthMm = std::max(minChordMm, medianFactor * medianChord(points));
    field.forwardAngle.resize(n); // first the wrapped angles, unwrapped in place below
    field.turning.resize(n);
    field.curvature.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Chord forward = chordFrom(points, i, +1, field.chordLengthMm);
        const Chord backward = chordFrom(points, i, -1, field.chordLengthMm);
        if (!forward.found && !backward.found) {
            return makeError(ErrorCode::Geometry,
                             "the projected path is degenerate at point " + std::to_string(i));
        }
        // [A] At the ends one side is missing: use the other, so tau = 0 there.
        const Chord& ePlus = forward.found ? forward : backward;
        const Chord& eMinus = backward.found ? backward : forward;
        field.forwardAngle[i] = angleOf(ePlus.vector);
        field.turning[i] = detail::wrapAngle(field.forwardAngle[i] - angleOf(eMinus.vector));
        // [A] Normalised curvature: the chords' directions are the tangents at their
        // mid-points, so tau spans (|e+| + |e-|)/2 of arc. This keeps kappa_h in 1/mm
        // independent of the point density (the literal sum of tau / w of §1.6 is not).
        field.curvature[i] = 2.0 * field.turning[i] / (ePlus.norm + eMinus.norm);
    }
    // Unwrapped along the whole path (geometry::unwrap, with the fast wrap), in place: each
    // step reads the wrapped value at i before overwriting it.
    for (std::size_t i = 1; i < n; ++i) {
        field.forwardAngle[i] =
            detail::unwrapNear(field.forwardAngle[i], field.forwardAngle[i - 1]);
    }
    return field;
}

} // namespace bladeaxis::scheduling
