#pragma once
// A dense point sampling of a triangle mesh with a bounding-volume hierarchy, for nearest-
// distance queries against convex tool solids.
//
// Why points and not exact triangle distances: the tool parts are solids of revolution (ball,
// cone, cylinder) whose exact distance to a triangle has no cheap closed form, while the signed
// distance from a point to each of them is a few flops (tool_geometry.h). Every point of the
// mesh lies within coverageRadius() (<= 2 x spacing) of a sample, so a sampled distance
// overestimates the true one by at most that; near a tangential contact (a ball or shank grazing
// the blade) the error is only second order, about e^2 / (2 R) for a lateral offset e. The
// hierarchy prunes with the 1-Lipschitz bound d(p) >= d(centre) - radius of a node's box.

#include "core/base/error.h"
#include "core/cad/triangle_mesh.h"
#include "core/geometry/vec.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace bladeaxis::cad {

class SurfaceSamples {
  public:
    // Samples every triangle on a grid with cell edges <= spacing (mesh vertices once).
    // Errors: InvalidArgument (spacing <= 0, empty mesh, bad indices).
    static Result<SurfaceSamples> create(const TriangleMesh& mesh, double spacing);

    std::size_t size() const { return m_points.size(); }
    const std::vector<Vec3>& points() const { return m_points; }
    // A bound on the distance from any point of the mesh to its nearest sample.
    double coverageRadius() const { return m_coverage; }

    // min over the samples of distance(p), or `limit` when every sample is at least that far;
    // `distance` must be 1-Lipschitz (a signed distance to a convex solid).
    template <class Distance>
    double minimum(Distance&& distance, double limit) const;

  private:
    struct Node {
        Vec3 centre;
        double radius = 0.0;              // of the node's bounding box, from its centre
        std::uint32_t first = 0, end = 0; // leaves: sample range; inner nodes: end = 0
        std::uint32_t left = 0, right = 0;
    };
    std::uint32_t build(std::uint32_t first, std::uint32_t end);

    std::vector<Vec3> m_points;
    std::vector<Node> m_nodes;
    double m_coverage = 0.0;
};

template <class Distance>
double SurfaceSamples::minimum(Distance&& distance, double limit) const {
    double best = limit;
    if (m_nodes.empty()) {
        return best;
    }
    // Depth first, nearer child first, skipping nodes whose lower bound cannot beat `best`.
    std::pair<std::uint32_t, double> stack[64];
    int top = 0;
    stack[top++] = {0, distance(m_nodes[0].centre) - m_nodes[0].radius};
    while (top > 0) {
        const auto [index, bound] = stack[--top];
        if (bound >= best) {
            continue;
        }
        const Node& node = m_nodes[index];
        if (node.end != 0) {
            for (std::uint32_t i = node.first; i < node.end; ++i) {
                const double d = distance(m_points[i]);
                best = d < best ? d : best;
            }
            continue;
        }
        const Node& left = m_nodes[node.left];
        const Node& right = m_nodes[node.right];
        const double boundLeft = distance(left.centre) - left.radius;
        const double boundRight = distance(right.centre) - right.radius;
        if (boundLeft < boundRight) {
            stack[top++] = {node.right, boundRight};
            stack[top++] = {node.left, boundLeft};
        } else {
            stack[top++] = {node.left, boundLeft};
            stack[top++] = {node.right, boundRight};
        }
    }
    return best;
}

} // namespace bladeaxis::cad
