#include "core/analysis/motion_knots.h"

#include <algorithm>
#include <cmath>

namespace bladeaxis::analysis {

namespace {

using kinematics::AxisId;

// How far `middle` lies off the straight move from `from` to `to` (at the fraction t of the
// path parameter between them), in units of the tolerances: the largest over the axes.
double offStraightMove(const kinematics::MachineAxes& from, const kinematics::MachineAxes& middle,
                       const kinematics::MachineAxes& to, double t,
                       const MotionKnotTolerances& tolerances) {
    double largest = 0.0;
    for (AxisId axis : kinematics::kAllAxes) {
        const double expected = from[axis] + t * (to[axis] - from[axis]);
        const double limit =
            kinematics::isRotary(axis) ? tolerances.rotaryRad : tolerances.linearMm;
        const double off = std::abs(middle[axis] - expected) / limit;
        largest = std::isnan(off) ? HUGE_VAL : std::max(largest, off);
    }
    return largest;
}

} // namespace

double medianChord(std::span<const double> s) {
    if (s.size() < 2) {
        return 0.0;
    }
    std::vector<double> chords(s.size() - 1);
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
        chords[i] = s[i + 1] - s[i];
    }
    const auto middle = chords.begin() + static_cast<std::ptrdiff_t>(chords.size() / 2);
    std::nth_element(chords.begin(), middle, chords.end());
    return *middle;
}

std::vector<std::size_t> motionKnots(std::span<const double> s,
                                     std::span<const kinematics::MachineAxes> axes,
                                     std::span<const RecordIndex> sampleRecord,
                                     const MotionKnotTolerances& tolerances) {
    const std::size_t n = s.size();
    std::vector<std::size_t> knots;
    if (n == 0) {
        return knots;
    }
    knots.reserve(n);
    knots.push_back(0);
    const double shortChord = tolerances.shortChordFraction * medianChord(s);
    const auto at = [&](std::size_t sample) -> const kinematics::MachineAxes& {
        return axes[sampleRecord[sample]];
    };
    const auto off = [&](std::size_t from, std::size_t sample, std::size_t to) {
        const double t = (s[sample] - s[from]) / (s[to] - s[from]);
        return offStraightMove(at(from), at(sample), at(to), t, tolerances);
    };
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const std::size_t knot = knots.back();
        const bool shortFromKnot = s[i] - s[knot] < shortChord;
        const bool shortToNext = s[i + 1] - s[i] < shortChord;
        const double offHere = shortFromKnot || shortToNext ? off(knot, i, i + 1) : HUGE_VAL;
        // Of the two ends of a short chord both lie almost on the line through the other: the
        // one that lies closer to the straight move past it is the split point, the other the
        // CL point (kept, so the knots are the program's own points).
        const bool nextIsTheSplit = shortToNext && i + 2 < n && off(i, i + 1, i + 2) < offHere;
        if (!(offHere <= 1.0) || nextIsTheSplit) {
            knots.push_back(i);
        }
    }
    if (n > 1) {
        knots.push_back(n - 1);
    }
    return knots;
}

} // namespace bladeaxis::analysis
