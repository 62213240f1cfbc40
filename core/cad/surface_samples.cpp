#include "core/cad/surface_samples.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bladeaxis::cad {
namespace {

constexpr std::uint32_t kLeafSize = 8;

// Samples triangle abc on a grid along its two shorter edges from their common vertex a, with
// cells no longer than `spacing` per edge: a long sliver (common on blades, which are nearly
// ruled along the span) gets a row of points, not a square grid. Corners are skipped (the mesh
// vertices are added once). Returns the cell diameter bound |u| + |v|: every point of the
// triangle lies in a cell whose grid corner nearest a is a sample.
double sampleTriangle(Vec3 a, Vec3 b, Vec3 c, double spacing, std::vector<Vec3>& out) {
    const double ab = (b - a).norm(), bc = (c - b).norm(), ca = (a - c).norm();
    if (ab >= bc && ab >= ca) { // ab longest: c is opposite, make it the apex
        std::swap(a, c);
    } else if (ca >= ab && ca >= bc) { // ca longest: b is the apex
        std::swap(a, b);
    }
    const int n1 = std::max(1, static_cast<int>(std::ceil((b - a).norm() / spacing)));
    const int n2 = std::max(1, static_cast<int>(std::ceil((c - a).norm() / spacing)));
    const Vec3 u = (b - a) / n1, v = (c - a) / n2;
    for (int i = 0; i <= n1; ++i) {
        for (int j = 0; j <= n2; ++j) {
            // inside: i/n1 + j/n2 <= 1, in integers to avoid rounding at the far edge
            if (i * n2 + j * n1 > n1 * n2) {
                break;
            }
            const bool isCorner = (i == 0 && j == 0) || (i == n1 && j == 0) || (i == 0 && j == n2);
            if (!isCorner) {
                out.push_back(a + i * u + j * v);
            }
        }
    }
    return u.norm() + v.norm();
}

} // namespace

Result<SurfaceSamples> SurfaceSamples::create(const TriangleMesh& mesh, double spacing) {
    if (!(spacing > 0.0) || !std::isfinite(spacing)) {
        return makeError(ErrorCode::InvalidArgument, "surface samples: spacing must be > 0 mm");
    }
    if (mesh.empty()) {
        return makeError(ErrorCode::InvalidArgument, "surface samples: the mesh has no triangle");
    }
    SurfaceSamples samples;
    samples.m_points = mesh.vertices;
    double coverage = 0.0;
    for (const auto& t : mesh.triangles) {
        if (std::ranges::any_of(t, [&](std::uint32_t v) { return v >= mesh.vertices.size(); })) {
            return makeError(ErrorCode::InvalidArgument,
                             "surface samples: a triangle refers to a missing vertex");
        }
        coverage =
            std::max(coverage, sampleTriangle(mesh.vertices[t[0]], mesh.vertices[t[1]],
                                              mesh.vertices[t[2]], spacing, samples.m_points));
    }
    if (samples.m_points.size() >= std::numeric_limits<std::uint32_t>::max() / 2) {
        return makeError(ErrorCode::InvalidArgument, "surface samples: too many samples");
    }
    samples.m_coverage = coverage;
    samples.m_nodes.reserve(2 * samples.m_points.size() / kLeafSize + 2);
    samples.build(0, static_cast<std::uint32_t>(samples.m_points.size()));
    return samples;
}

// Median split along the longest box axis; the points are reordered so that every node owns a
// contiguous range.
std::uint32_t SurfaceSamples::build(std::uint32_t first, std::uint32_t end) {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 hi = -lo;
    for (std::uint32_t i = first; i < end; ++i) {
        lo = lo.cwiseMin(m_points[i]);
        hi = hi.cwiseMax(m_points[i]);
    }
    const auto index = static_cast<std::uint32_t>(m_nodes.size());
    m_nodes.push_back({(lo + hi) / 2.0, (hi - lo).norm() / 2.0, first, 0, 0, 0});
    if (end - first <= kLeafSize) {
        m_nodes[index].end = end;
        return index;
    }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const std::uint32_t middle = first + (end - first) / 2;
    std::nth_element(m_points.begin() + first, m_points.begin() + middle, m_points.begin() + end,
                     [axis](const Vec3& a, const Vec3& b) { return a[axis] < b[axis]; });
    const std::uint32_t left = build(first, middle);
    const std::uint32_t right = build(middle, end);
    m_nodes[index].left = left;
    m_nodes[index].right = right;
    return index;
}

} // namespace bladeaxis::cad
