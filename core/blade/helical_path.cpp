#include "core/blade/helical_path.h"

#include "core/base/number_io.h"
#include "core/blade/offset_curve.h"
#include "core/blade/random.h"

#include <cmath>
#include <string>

namespace bladeaxis::blade {
namespace {

constexpr int kMaxBisectionDepth = 40;
constexpr std::size_t kMaxRecords = 5'000'000;

Status outOfRange(const std::string& name, double value, const std::string& limit) {
    return makeError(ErrorCode::InvalidArgument,
                     name + " = " + formatShortest(value) + " is outside " + limit);
}

struct Sample {
    double u = 0.0;
    double x = 0.0; // of the section holding the contact point
    Vec3 contact = Vec3::Zero();
    Vec3 normal = Vec3::Zero(); // N, the unit surface normal at the contact
    Vec3 centre = Vec3::Zero();
};

// The blade surface is swept by its sections: at a contact point with in-plane outward normal n
// that moves with velocity v along the span, the surface tangents are (0, t) along the section
// and (1, v) along the span. N = (-b, n) / sqrt(1 + b^2) with b = n . v is orthogonal to both
// and points outwards. On a twisted or leaning blade b is not 0, and a ball centre offset along
// n alone would dip into the surface. b is taken with the offset curve's blended normal: the
// polygon's n jumps at concave vertices, and Q_x = P_x - R b / sqrt(1 + b^2) would jump with it
// (by ~10 um per vertex on the demo); the blend differs from n by at most half a vertex turn.
Vec3 surfaceNormal(const OffsetSample& point, const Vec2& v) {
    const double b = point.blendedNormal.dot(v);
    return Vec3(-b, point.normal.x(), point.normal.y()) / std::sqrt(1.0 + b * b);
}

class Sampler {
  public:
    Sampler(const Blade& blade, const HelicalPathSpec& spec, double xStart)
        : m_blade(blade), m_spec(spec), m_xStart(xStart) {}

    Result<Sample> at(double u) const {
        Sample sample;
        sample.u = u;
        sample.x = m_xStart + m_spec.pitch * u;
        Result<OffsetCurve> curve =
            OffsetCurve::create(m_blade.sectionAt(sample.x), m_spec.toolRadius);
        if (!curve) {
            Error error = curve.error();
            error.message += " (section x = " + formatTrimmed(sample.x, 6) + " mm)";
            return std::unexpected(std::move(error));
        }
        const OffsetSample point = curve->at(u - std::floor(u));
        const double lambda = point.edgeFraction;
        const std::size_t next = (point.edge + 1) % curve->vertexCount();
        const Vec2 velocity = (1.0 - lambda) * m_blade.sectionVelocity(sample.x, point.edge) +
                              lambda * m_blade.sectionVelocity(sample.x, next);
        sample.contact = Vec3(sample.x, point.contact.x(), point.contact.y());
        sample.normal = surfaceNormal(point, velocity);
        sample.centre = sample.contact + m_spec.toolRadius * sample.normal;
        return sample;
    }

    // Centre-curve length at revolution r, to size the initial grid.
    Result<double> lengthAt(double u) const {
        Result<OffsetCurve> curve =
            OffsetCurve::create(m_blade.sectionAt(m_xStart + m_spec.pitch * u), m_spec.toolRadius);
        if (!curve) {
            return std::unexpected(curve.error());
        }
        return curve->length();
    }

    bool needsSplit(const Sample& a, const Sample& mid, const Sample& b) const {
        const double chord = (b.centre - a.centre).norm();
        const double deviation = (mid.centre - 0.5 * (a.centre + b.centre)).norm();
        return chord > m_spec.maxStep || deviation > m_spec.chordalTolerance;
    }

  private:
    const Blade& m_blade;
    const HelicalPathSpec& m_spec;
    double m_xStart;
};

// Samples of one revolution [r, r + 1), in order, by bisection of an initial uniform grid.
Status sampleRevolution(const Sampler& sampler, const HelicalPathSpec& spec, int r,
                        std::vector<Sample>& out) {
    Result<double> length = sampler.lengthAt(r);
    if (!length) {
        return std::unexpected(length.error());
    }
    const int grid = std::max(32, static_cast<int>(std::ceil(*length / spec.maxStep)));
    Result<Sample> left = sampler.at(r);
    if (!left) {
        return std::unexpected(left.error());
    }
    out.push_back(*left);
    for (int k = 1; k <= grid; ++k) {
        Result<Sample> right = sampler.at(r + static_cast<double>(k) / grid);
        if (!right) {
            return std::unexpected(right.error());
        }
        // Depth-first bisection of [left, right]; the stack holds right ends still to reach.
        std::vector<std::pair<Sample, int>> pending{{*right, 0}};
        while (!pending.empty()) {
            const auto [target, depth] = pending.back();
            Result<Sample> mid = sampler.at(0.5 * (out.back().u + target.u));
            if (!mid) {
                return std::unexpected(mid.error());
            }
            if (depth < kMaxBisectionDepth && sampler.needsSplit(out.back(), *mid, target)) {
                // Both halves are one level deeper: the right one must not restart at `depth`,
                // or a jump in the curve would be bisected until u stops changing.
                pending.back().second = depth + 1;
                pending.emplace_back(*mid, depth + 1);
                continue;
            }
            pending.pop_back();
            if (k < grid || !pending.empty()) {
                out.push_back(target); // the revolution end is the next one's start
            }
            if (out.size() > kMaxRecords) {
                return makeError(ErrorCode::InvalidArgument,
                                 "more than " + std::to_string(kMaxRecords) +
                                     " points: raise the chordal tolerance");
            }
        }
    }
    return {};
}

Vec3 roundTo(const Vec3& v, double grid) {
    if (!(grid > 0.0)) {
        return v;
    }
    return Vec3(std::round(v.x() / grid) * grid, std::round(v.y() / grid) * grid,
                std::round(v.z() / grid) * grid);
}

void appendRecord(const Sample& s, int revolution, const HelicalPathSpec& spec, Random& random,
                  GeneratedPath& out) {
    // The B head keeps its tilt (four axes), so only the azimuth about the rotary axis is free:
    // the lead is taken from the azimuth of the true normal N (its (y, z) part is along n).
    const Vec3& n = s.normal;
    double phi = std::atan2(n.z(), n.y()) + spec.leadAngle;
    if (spec.leadNoise > 0.0) {
        phi += spec.leadNoise * random.normal();
    }
    const double b0 = spec.tiltB0;
    const Vec3 axis(std::sin(b0), std::cos(b0) * std::cos(phi), std::cos(b0) * std::sin(phi));
    toolpath::ClRecord record;
    record.axis = axis;
    record.tip = roundTo(s.centre - spec.toolRadius * axis, spec.roundTipTo);
    record.feed = spec.feed;
    record.motion = toolpath::MotionKind::Feed;
    out.path.records.push_back(record);
    out.contact.push_back(s.contact);
    out.normal.push_back(s.normal);
    out.centre.push_back(s.centre);
    out.sectionX.push_back(s.x);
    out.parameter.push_back(s.u);
    out.revolution.push_back(revolution);
}

} // namespace

Status validate(const HelicalPathSpec& spec) {
    if (!(spec.toolRadius > 0.0 && spec.toolRadius <= 100.0)) {
        return outOfRange("tool radius R (mm)", spec.toolRadius, "(0, 100]");
    }
    if (!(spec.pitch > 0.0 && spec.pitch <= 50.0)) {
        return outOfRange("pitch (mm per revolution)", spec.pitch, "(0, 50]");
    }
    if (spec.revolutions < 1 || spec.revolutions > 10000) {
        return outOfRange("revolutions", spec.revolutions, "[1, 10000]");
    }
    if (!(std::abs(spec.tiltB0) < units::degToRad(89.0))) {
        return outOfRange("tilt B0 (rad)", spec.tiltB0, "(-89 deg, 89 deg)");
    }
    if (!(std::abs(spec.leadAngle) < units::degToRad(89.0))) {
        return outOfRange("lead angle (rad)", spec.leadAngle, "(-89 deg, 89 deg)");
    }
    if (!(spec.chordalTolerance >= 1e-4 && spec.chordalTolerance <= 1.0)) {
        return outOfRange("chordal tolerance (mm)", spec.chordalTolerance, "[1e-4, 1]");
    }
    if (!(spec.maxStep >= 10.0 * spec.chordalTolerance && spec.maxStep <= 100.0)) {
        return outOfRange(
            "max step (mm)", spec.maxStep,
            "[10 x chordal tolerance = " + formatShortest(10.0 * spec.chordalTolerance) + ", 100]");
    }
    if (!(spec.feed > 0.0 && std::isfinite(spec.feed))) {
        return outOfRange("feed (mm/s)", spec.feed, "(0, inf)");
    }
    if (!(spec.leadNoise >= 0.0 && spec.leadNoise <= 0.5)) {
        return outOfRange("lead noise (rad)", spec.leadNoise, "[0, 0.5]");
    }
    if (!(spec.roundTipTo >= 0.0 && spec.roundTipTo <= 0.1)) {
        return outOfRange("tip rounding grid (mm)", spec.roundTipTo, "[0, 0.1]");
    }
    if (spec.xStart && !std::isfinite(*spec.xStart)) {
        return outOfRange("x start (mm)", *spec.xStart, "the finite numbers");
    }
    return {};
}

Result<GeneratedPath> generateHelicalPath(const Blade& blade, const HelicalPathSpec& spec) {
    if (auto ok = validate(spec); !ok) {
        return std::unexpected(ok.error());
    }
    const double xStart = spec.xStart.value_or(blade.spanStart());
    const double xEnd = xStart + spec.pitch * spec.revolutions;
    const double slack = 1e-9 * (1.0 + std::abs(blade.spanEnd()));
    if (xStart < blade.spanStart() - slack || xEnd > blade.spanEnd() + slack) {
        return makeError(ErrorCode::InvalidArgument,
                         "the path x range [" + formatTrimmed(xStart, 6) + ", " +
                             formatTrimmed(xEnd, 6) + "] mm (x start + pitch x revolutions) " +
                             "leaves the blade span [" + formatTrimmed(blade.spanStart(), 6) +
                             ", " + formatTrimmed(blade.spanEnd(), 6) + "] mm");
    }
    GeneratedPath out;
    out.minConcaveRadius = blade.minConcaveRadius(xStart, xEnd);
    if (!(spec.toolRadius < out.minConcaveRadius)) {
        return makeError(ErrorCode::Geometry,
                         "tool radius R = " + formatShortest(spec.toolRadius) +
                             " mm is not smaller than the minimum concave radius of curvature " +
                             formatTrimmed(out.minConcaveRadius, 4) + " mm of the sections in x [" +
                             formatTrimmed(xStart, 6) + ", " + formatTrimmed(xEnd, 6) + "] mm");
    }
    const Sampler sampler(blade, spec, xStart);
    Random random(spec.seed);
    out.path.sourceFile = "synthetic helical path";
    out.path.toolRadius = spec.toolRadius;
    std::vector<Sample> samples;
    for (int r = 0; r < spec.revolutions; ++r) {
        samples.clear();
        if (auto ok = sampleRevolution(sampler, spec, r, samples); !ok) {
            return std::unexpected(ok.error());
        }
        for (const Sample& s : samples) {
            appendRecord(s, r, spec, random, out);
        }
        // Projected from the revolutions so far, so that the refusal comes before the memory
        // is spent.
        const std::size_t perRevolution = out.path.records.size() / static_cast<std::size_t>(r + 1);
        const std::size_t projected = perRevolution * static_cast<std::size_t>(spec.revolutions);
        if (projected > kMaxGeneratedPoints) {
            return makeError(ErrorCode::InvalidArgument,
                             "the path would have about " + std::to_string(projected) +
                                 " points (" + std::to_string(perRevolution) +
                                 " per revolution), more than the " +
                                 std::to_string(kMaxGeneratedPoints) +
                                 " a generated program may have: fewer revolutions or a coarser "
                                 "chordal tolerance");
        }
    }
    Result<Sample> last = sampler.at(spec.revolutions);
    if (!last) {
        return std::unexpected(last.error());
    }
    appendRecord(*last, spec.revolutions - 1, spec, random, out);
    return out;
}

} // namespace bladeaxis::blade
