#include "core/scheduling/detail/exact_epsilon.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace bladeaxis::scheduling::detail {

namespace {

// Samples are solved against half the predicate's tolerance, so that the round-off of a later
// evaluation (far below kRoundOff) never turns a solved bound into a predicate failure.
constexpr double kRoomTolerance = 0.5 * kFeasibilityTolerance;
constexpr double kRoundOff = 1e-13;

struct Rooms {
    double nearSide; // bound on the curve's side minus the polyline (>= the deviation needed)
    double farSide;  // polyline minus the other bound (must stay >= 0)
};

class CornerRooms {
  public:
    CornerRooms(const CornerGeometry& corner, const ChannelView& channel)
        : m_corner(corner), m_channel(channel) {}

    Rooms atSample(std::size_t j) const {
        return rooms(m_channel.s[j], m_channel.rawMin[j] + m_channel.clearance,
                     m_channel.rawMax[j] - m_channel.clearance);
    }
    Rooms atAbscissa(double x) const {
        const auto [low, high] = m_channel.at(x);
        return rooms(x, low, high);
    }

  private:
    Rooms rooms(double x, double low, double high) const {
        const Vec2& p2 = m_corner.p2;
        const double line = p2.y() + (x < p2.x() ? m_corner.kIn : m_corner.kOut) * (x - p2.x());
        return m_corner.sign > 0.0
                   ? Rooms{high - line + kRoomTolerance, line - low + kRoomTolerance}
                   : Rooms{line - low + kRoomTolerance, high - line + kRoomTolerance};
    }

    const CornerGeometry& m_corner;
    const ChannelView& m_channel;
};

double bernstein(const std::array<double, 4>& h, double t) {
    const double u = 1.0 - t;
    return u * u * u * h[0] + 3.0 * u * u * t * h[1] + 3.0 * u * t * t * h[2] + t * t * t * h[3];
}

double bernsteinSlope(const std::array<double, 4>& h, double t) {
    const double u = 1.0 - t;
    return 3.0 * (u * u * (h[1] - h[0]) + 2.0 * u * t * (h[2] - h[1]) + t * t * (h[3] - h[2]));
}

// The root in [0, 1] of a cubic in Bernstein form whose end values have opposite signs:
// Newton safeguarded by the sign bracket, to a relative step of a few ulp.
double bracketedRoot(const std::array<double, 4>& h) {
    const bool rising = h[3] > h[0];
    double low = 0.0;
    double high = 1.0;
    double t = std::clamp(h[0] / (h[0] - h[3]), 0.0, 1.0);
    for (int step = 0; step < 200; ++step) {
        const double f = bernstein(h, t);
        if (f == 0.0) {
            return t;
        }
        ((f < 0.0) == rising ? low : high) = t;
        double next = t - f / bernsteinSlope(h, t);
        if (std::abs(next - t) <= 4.0 * std::numeric_limits<double>::epsilon() * t) {
            return next; // converged (quadratically, a few steps from the linear guess)
        }
        if (!(next > low && next < high)) {
            next = 0.5 * (low + high);
        }
        t = next;
    }
    return t;
}

double bezierX(const CubicBezier& cubic, double t) {
    return bernstein(
        {cubic.control[0].x(), cubic.control[1].x(), cubic.control[2].x(), cubic.control[3].x()},
        t);
}

// The largest m for which the sample at offset a != 0 with room r stays feasible: the deviation
// m E(a / m) equals r where the unit curve meets the line Y = (k + r / a) X (k the flipped
// polyline slope on that side), i.e. at the root of a cubic in t.
double sampleBound(const CornerGeometry& corner, double a, double room) {
    const CubicBezier& cubic = a > 0.0 ? corner.unitOffsets.second : corner.unitOffsets.first;
    const double edge = a > 0.0 ? cubic.control[3].x() : cubic.control[0].x();
    if (room < 0.0) { // the polyline itself violates: the span must stop short of the sample
        return a / edge * (1.0 - 1e-9);
    }
    const double slope = corner.sign * (a > 0.0 ? corner.kOut : corner.kIn) + room / a;
    std::array<double, 4> h{};
    for (std::size_t k = 0; k < 4; ++k) {
        h[k] = cubic.control[k].y() - slope * cubic.control[k].x();
    }
    return a / bezierX(cubic, bracketedRoot(h));
}

// Deviation from the polyline at abscissa x of the pair with |epsilon| = m.
double deviation(const CornerGeometry& corner, double m, double x) {
    const double u = (x - corner.p2.x()) / m;
    if (u <= corner.unitOffsets.sBegin() || u >= corner.unitOffsets.sEnd()) {
        return 0.0;
    }
    const double line = corner.sign * (u < 0.0 ? corner.kIn : corner.kOut) * u;
    return m * (evaluatePair(corner.unitOffsets, u).value - line);
}

BezierPair pairAt(const CornerGeometry& corner, double m) {
    BezierPair pair = corner.unitOffsets;
    for (CubicBezier* cubic : {&pair.first, &pair.second}) {
        for (Vec2& p : cubic->control) {
            p = Vec2(corner.p2.x() + m * p.x(), corner.p2.y() + corner.sign * m * p.y());
        }
    }
    return pair;
}

// Sufficient for pairFeasible(pairAt(m)): between consecutive abscissae (span ends and the
// samples inside) both rooms are linear, the deviation is monotone on each side of S2 and never
// above m, so the rooms' minimum must cover the deviation at the end nearer to S2.
bool clearlyFeasible(const CornerGeometry& corner, double m, const ChannelView& channel,
                     const CornerRooms& rooms) {
    const double s2 = corner.p2.x();
    const double begin = s2 + m * corner.unitOffsets.sBegin();
    const double end = s2 + m * corner.unitOffsets.sEnd();
    double previousX = begin;
    Rooms previous = rooms.atAbscissa(begin);
    const std::size_t last = channel.lowerIndex(end);
    for (std::size_t j = channel.upperIndex(begin); j <= last; ++j) {
        const double x = j < last ? channel.s[j] : end;
        const Rooms current = j < last ? rooms.atSample(j) : rooms.atAbscissa(end);
        if (current.farSide < 0.0 || previous.farSide < 0.0) {
            return false;
        }
        const double low = std::min(previous.nearSide, current.nearSide);
        if (low < m) {
            const double bound =
                previousX < s2 && x > s2 ? m : deviation(corner, m, x <= s2 ? x : previousX);
            if (low + kRoundOff < bound) {
                return false;
            }
        }
        previousX = x;
        previous = current;
    }
    return true;
}

// When every sample in the span cleared the chord bound m - reach (scanSide without binding),
// the rooms and the chord are both linear between samples, so the chord (>= the deviation)
// stays below the room everywhere if it does at the span ends (chord 0) and at S2 (chord m).
bool chordClearsSpan(double s2, double begin, double end, double peakDeviation,
                     const ChannelView& channel, const CornerRooms& rooms) {
    const Rooms atBegin = rooms.atAbscissa(begin);
    const Rooms atEnd = rooms.atAbscissa(end);
    if (std::min({atBegin.nearSide, atBegin.farSide, atEnd.nearSide, atEnd.farSide}) < 0.0) {
        return false;
    }
    const std::size_t j = channel.lowerIndex(s2);
    if (j < channel.s.size() && channel.s[j] == s2) {
        return true; // S2 is a sample: checked by the scan
    }
    const Rooms middle = rooms.atAbscissa(s2);
    return middle.nearSide >= peakDeviation && middle.farSide >= 0.0;
}

bool chordClears(const CornerGeometry& corner, double m, const ChannelView& channel,
                 const CornerRooms& rooms) {
    const double s2 = corner.p2.x();
    return chordClearsSpan(s2, s2 + m * corner.unitOffsets.sBegin(),
                           s2 + m * corner.unitOffsets.sEnd(), m, channel, rooms);
}

// The original rule: bisection of the (monotone) predicate on [0, high].
double bisect(const CornerGeometry& corner, double high, const ChannelView& channel, int checks,
              int steps) {
    double low = 0.0;
    for (int step = 0; step < steps; ++step) {
        const double mid = 0.5 * (low + high);
        (pairFeasible(pairAt(corner, mid), channel, checks) ? low : high) = mid;
    }
    return low;
}

// Lowers m to the bound of every binding sample on one side of S2 (direction -1: samples
// before `split`, +1: from `split` on), scanning outward while the samples lie inside the
// current span: farther ones have no deviation, so they cannot bind below m. Returns false when
// the polyline itself violates the far side at a sample (then the bound is not monotone).
bool scanSide(const CornerGeometry& corner, const ChannelView& channel, std::size_t split,
              int direction, double& m, bool& binding) {
    const bool right = direction > 0;
    const double s2 = corner.p2.x();
    const double slope = right ? corner.kOut : corner.kIn;
    const double inverseEdge =
        1.0 / (right ? corner.unitOffsets.sEnd() : corner.unitOffsets.sBegin()); // a / edge >= 0
    const double sign = corner.sign;
    const std::span<const double> nearBound = sign > 0.0 ? channel.rawMax : channel.rawMin;
    const std::span<const double> farBound = sign > 0.0 ? channel.rawMin : channel.rawMax;
    const double slack = kRoomTolerance - channel.clearance;
    const std::size_t n = channel.s.size();
    for (std::size_t j = right ? split : split - 1; j < n;
         j += static_cast<std::size_t>(direction)) {
        const double a = channel.s[j] - s2;
        const double reach = a * inverseEdge; // the m at which the span edge reaches the sample
        if (reach * (1.0 - 1e-9) > m) {
            break;
        }
        const double line = corner.p2.y() + slope * a;
        if (sign * (line - farBound[j]) + slack < 0.0) {
            return false;
        }
        const double room = sign * (nearBound[j] - line) + slack;
        // The deviation is convex on each side of S2 (one-signed theta'', §5.3), m at S2 and 0 at
        // the span edge: below its chord m - reach. Such samples cannot bind.
        if (room >= m - reach) {
            continue;
        }
        binding = true;
        m = std::min(m, a == 0.0 ? std::max(room, 0.0) : sampleBound(corner, a, room));
    }
    return true;
}

} // namespace

CornerGeometry cornerGeometry(const Vec2& p2, double kIn, double kOut, double sign,
                              const BezierPair& unitPair) {
    CornerGeometry corner{p2, kIn, kOut, sign, unitPair};
    for (CubicBezier* cubic : {&corner.unitOffsets.first, &corner.unitOffsets.second}) {
        for (Vec2& p : cubic->control) {
            p = Vec2(p.x() - p2.x(), sign * (p.y() - p2.y()));
        }
    }
    return corner;
}

double exactEpsilon(const CornerGeometry& corner, double geometric, const ChannelView& channel,
                    int checks, int bisectionSteps) {
    if (!(geometric > 0.0)) {
        return 0.0;
    }
    double m = geometric;
    bool binding = false;
    const std::size_t split = channel.upperIndex(corner.p2.x()); // S2 itself scans left
    const bool farViolated = !scanSide(corner, channel, split, -1, m, binding) ||
                             !scanSide(corner, channel, split, +1, m, binding);
    if (farViolated) { // not monotone in m: the original search, unchanged
        return pairFeasible(pairAt(corner, geometric), channel, checks)
                   ? geometric
                   : bisect(corner, geometric, channel, checks, bisectionSteps);
    }
    if (!(m > 0.0)) {
        return 0.0;
    }
    const CornerRooms rooms(corner, channel);
    if (!binding && chordClears(corner, m, channel, rooms)) {
        return m;
    }
    if (clearlyFeasible(corner, m, channel, rooms) ||
        pairFeasible(pairAt(corner, m), channel, checks)) {
        return m;
    }
    return bisect(corner, m, channel, checks, bisectionSteps);
}

namespace {

// The plateau corner of half-width w at (p2, k1, k2).
PlateauCorner plateauAt(const CornerGeometry& corner, double w) {
    return {corner.p2, corner.kIn, corner.kOut, w};
}

// |deviation| of the plateau corner of half-width w at distance `distance` from S2.
double plateauDeviationAt(double turn, double w, double distance) {
    return turn * w / 1.6 * plateauDeviation(distance / w);
}

// The largest w whose deviation at distance d > 0 from S2 is `room` (>= 0), given a u0 = d / w0
// at which the deviation still exceeds the room: with u = d / w, P(u) = R u, R = 1.6 room /
// (turn d). P(u) - R u is convex and decreasing on [0, 1] and positive at u0, so Newton from u0
// rises monotonically to the root (quadratically: a few steps from the current bound).
double plateauSampleBound(double turn, double distance, double room, double u0) {
    const double ratio = 1.6 * room / (turn * distance);
    double u = u0;
    for (int step = 0; step < 100; ++step) {
        const double f = plateauDeviation(u) - ratio * u;
        const double next = u - f / (plateauDeviationSlope(u) - ratio);
        if (!(next < 1.0)) {
            return distance;
        }
        if (next - u <= 1e-15 * next) {
            return distance / next;
        }
        u = next;
    }
    return distance / u;
}

// Lowers w to the bound of every binding sample on one side of S2, scanning outward while the
// samples lie inside the current span (as scanSide for the Bezier pair).
void plateauScanSide(const CornerGeometry& corner, const ChannelView& channel, std::size_t split,
                     int direction, double& w, bool& binding) {
    const bool right = direction > 0;
    const double s2 = corner.p2.x();
    const double slope = right ? corner.kOut : corner.kIn;
    const double sign = corner.sign;
    const double turn = std::abs(corner.kOut - corner.kIn);
    const std::span<const double> nearBound = sign > 0.0 ? channel.rawMax : channel.rawMin;
    const std::span<const double> farBound = sign > 0.0 ? channel.rawMin : channel.rawMax;
    const double slack = kRoomTolerance - channel.clearance;
    const std::size_t n = channel.s.size();
    double peak = turn * w / 4.8; // |epsilon| at the current w, kept with w
    const auto lowerTo = [&](double lower) {
        w = lower;
        peak = turn * w / 4.8;
    };
    for (std::size_t j = right ? split : split - 1; j < n;
         j += static_cast<std::size_t>(direction)) {
        const double a = channel.s[j] - s2;
        const double distance = std::abs(a);
        if (distance >= w) {
            break; // outside the span: the curve is the polyline there
        }
        const double line = corner.p2.y() + slope * a;
        const double room = sign * (nearBound[j] - line) + slack;
        if (sign * (line - farBound[j]) + slack < 0.0 || room < 0.0) {
            lowerTo(distance * (1.0 - 1e-9)); // the polyline itself violates: stop short of it
            binding = true;
            continue;
        }
        // Convex deviation below its chord |epsilon| (1 - distance / w): cannot bind. Most
        // samples have room for the whole |epsilon|, which decides it without the division
        // (a rounded product by a factor in [0, 1] is never above |epsilon|).
        if (room >= peak || room >= peak * (1.0 - distance / w)) {
            continue;
        }
        binding = true;
        if (distance == 0.0) {
            lowerTo(std::min(w, 4.8 * room / turn));
            continue;
        }
        const double u0 = distance / w;
        if (room >= turn * w / 1.6 * plateauDeviation(u0)) {
            continue; // below the chord but not binding at the current w
        }
        lowerTo(plateauSampleBound(turn, distance, room, u0));
    }
}

// The exact rule's predicate for the plateau corner: within the channel at every sample in its
// span and at 2 `checks` + 1 evenly spaced abscissae (the interpolated channel).
bool plateauFeasible(const PlateauCorner& plateau, const ChannelView& channel, int checks) {
    const std::size_t end = channel.upperIndex(plateau.sEnd());
    for (std::size_t j = channel.lowerIndex(plateau.sBegin()); j < end; ++j) {
        const double value = plateau.at(channel.s[j]).value;
        if (value < channel.rawMin[j] + channel.clearance - kFeasibilityTolerance ||
            value > channel.rawMax[j] - channel.clearance + kFeasibilityTolerance) {
            return false;
        }
    }
    for (int k = -checks; k <= checks; ++k) {
        const double x = plateau.p2.x() + plateau.halfWidth * k / checks;
        const double value = plateau.at(x).value;
        const auto [low, high] = channel.at(x);
        if (value < low - kFeasibilityTolerance || value > high + kFeasibilityTolerance) {
            return false;
        }
    }
    return true;
}

// Sufficient for plateauFeasible, as clearlyFeasible for the pair: rooms linear between
// abscissae, the deviation monotone on each side of S2.
bool plateauClearlyFeasible(const CornerGeometry& corner, double w, const ChannelView& channel,
                            const CornerRooms& rooms) {
    const double s2 = corner.p2.x();
    const double turn = std::abs(corner.kOut - corner.kIn);
    const double peakDeviation = turn * w / 4.8;
    double previousX = s2 - w;
    Rooms previous = rooms.atAbscissa(previousX);
    const std::size_t last = channel.lowerIndex(s2 + w);
    for (std::size_t j = channel.upperIndex(previousX); j <= last; ++j) {
        const double x = j < last ? channel.s[j] : s2 + w;
        const Rooms current = j < last ? rooms.atSample(j) : rooms.atAbscissa(x);
        if (current.farSide < 0.0 || previous.farSide < 0.0) {
            return false;
        }
        const double low = std::min(previous.nearSide, current.nearSide);
        if (low < peakDeviation) {
            const double nearer = x <= s2 ? x : previousX;
            const double bound = previousX < s2 && x > s2
                                     ? peakDeviation
                                     : plateauDeviationAt(turn, w, std::abs(nearer - s2));
            if (low + kRoundOff < bound) {
                return false;
            }
        }
        previousX = x;
        previous = current;
    }
    return true;
}

} // namespace

double exactPlateauHalfWidth(const Vec2& p2, double k1, double k2, double geometric,
                             const ChannelView& channel, int checks, int bisectionSteps) {
    if (!(geometric > 0.0) || !(k2 != k1)) {
        return 0.0;
    }
    const CornerGeometry corner{p2, k1, k2, k2 > k1 ? 1.0 : -1.0, {}};
    double w = geometric;
    bool binding = false;
    const std::size_t split = channel.upperIndex(p2.x()); // S2 itself scans left
    plateauScanSide(corner, channel, split, -1, w, binding);
    plateauScanSide(corner, channel, split, +1, w, binding);
    if (!(w > 0.0)) {
        return 0.0;
    }
    const CornerRooms rooms(corner, channel);
    // Every sample cleared the chord: chord and rooms are linear between samples, so the span
    // ends (chord 0) and S2 (chord |epsilon|) decide, as chordClears does for the pair.
    if (!binding && chordClearsSpan(p2.x(), p2.x() - w, p2.x() + w, std::abs(k2 - k1) * w / 4.8,
                                    channel, rooms)) {
        return w;
    }
    if (plateauClearlyFeasible(corner, w, channel, rooms) ||
        plateauFeasible(plateauAt(corner, w), channel, checks)) {
        return w;
    }
    double low = 0.0; // bisection of the monotone predicate (homothety in w)
    double high = w;
    for (int step = 0; step < bisectionSteps; ++step) {
        const double mid = 0.5 * (low + high);
        (plateauFeasible(plateauAt(corner, mid), channel, checks) ? low : high) = mid;
    }
    return low;
}

} // namespace bladeaxis::scheduling::detail
