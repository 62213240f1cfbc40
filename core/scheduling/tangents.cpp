#include "core/scheduling/tangents.h"

#include "core/geometry/angles.h"

#include <algorithm>
#include <cmath>
#include <optional>

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

// e+_i (step = +1) or e-_i (step = -1, returned pointing forward: q_i - q_j).
std::optional<Vec2> chordFrom(std::span<const Vec2> points, std::size_t i, int step,
                              double length) {
    const std::size_t n = points.size();
    std::optional<Vec2> farthest;
    for (std::size_t j = i; step > 0 ? j + 1 < n : j > 0;) {
        j = step > 0 ? j + 1 : j - 1;
        const Vec2 chord = step > 0 ? Vec2(points[j] - points[i]) : Vec2(points[i] - points[j]);
        const double norm = chord.norm();
        if (norm >= length) {
            return chord;
        }
        if (norm > kDegenerateChordMm && (!farthest || norm > farthest->norm())) {
            farthest = chord;
        }
    }
    return farthest;
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
    std::vector<double> forwardRaw(n);
    field.turning.resize(n);
    field.curvature.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        std::optional<Vec2> forward = chordFrom(points, i, +1, field.chordLengthMm);
        std::optional<Vec2> backward = chordFrom(points, i, -1, field.chordLengthMm);
        if (!forward && !backward) {
            return makeError(ErrorCode::Geometry,
                             "the projected path is degenerate at point " + std::to_string(i));
        }
        // [A] At the ends one side is missing: use the other, so tau = 0 there.
        const Vec2 ePlus = forward ? *forward : *backward;
        const Vec2 eMinus = backward ? *backward : *forward;
        forwardRaw[i] = angleOf(ePlus);
        field.turning[i] = geometry::wrapAngle(angleOf(ePlus) - angleOf(eMinus));
        // [A] Normalised curvature: the chords' directions are the tangents at their
        // mid-points, so tau spans (|e+| + |e-|)/2 of arc. This keeps kappa_h in 1/mm
        // independent of the point density (the literal sum of tau / w of §1.6 is not).
        field.curvature[i] = 2.0 * field.turning[i] / (ePlus.norm() + eMinus.norm());
    }
    field.forwardAngle = geometry::unwrap(forwardRaw);
    return field;
}

} // namespace bladeaxis::scheduling
