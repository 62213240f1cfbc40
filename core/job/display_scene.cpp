#include "core/job/display_scene.h"

#include "core/cad/tessellation.h"
#include "core/job/job.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace bladeaxis::job {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

std::size_t strideFor(std::size_t count, std::size_t limit) {
    const std::size_t cap = std::max<std::size_t>(limit, 1);
    return std::max<std::size_t>((count + cap - 1) / cap, 1);
}

// Revolutions about the rotary axis x, counted from the first centre: the polar angle of the
// centre in (y, z), unwrapped, oriented so that it grows along the path and made non-decreasing
// (a helical pass turns one way; a local back-step must not create a layer or fold the surface).
struct Revolutions {
    std::vector<double> turns; // per centre
    int sense = 1;             // +1: the polar angle grows along the path (counter-clockwise)
};

Revolutions revolutionsAboutX(std::span<const Vec3> centres) {
    Revolutions result;
    std::vector<double>& u = result.turns;
    u.assign(centres.size(), 0.0);
    if (centres.empty()) {
        return result;
    }
    double previous = std::atan2(centres[0].z(), centres[0].y());
    for (std::size_t i = 1; i < centres.size(); ++i) {
        const double angle = std::atan2(centres[i].z(), centres[i].y());
        u[i] = u[i - 1] + std::remainder(angle - previous, kTwoPi);
        previous = angle;
    }
    result.sense = u.back() < 0.0 ? -1 : 1;
    double highest = 0.0;
    for (double& value : u) {
        highest = std::max(highest, result.sense * value / kTwoPi);
        value = highest;
    }
    return result;
}

// Inclusive pass-record ranges of the layers: the schedule's (a shared junction sample belongs
// to the later layer), or whole revolutions of an unscheduled pass.
std::vector<std::pair<std::size_t, std::size_t>> layerRanges(const DisplaySceneInput& input,
                                                             std::span<const double> revolution) {
    const std::size_t n = input.pass.size();
    std::vector<std::pair<std::size_t, std::size_t>> ranges;
    if (input.schedule != nullptr && !input.schedule->layers.empty()) {
        const auto& layers = input.schedule->layers;
        for (std::size_t k = 0; k < layers.size(); ++k) {
            const std::size_t first = k == 0 ? 0 : std::min(layers[k].first, n - 1);
            const std::size_t last =
                k + 1 < layers.size() ? std::max(layers[k + 1].first, first + 1) - 1 : n - 1;
            if (first <= last && (ranges.empty() || first > ranges.back().second)) {
                ranges.emplace_back(first, std::min(last, n - 1));
            }
        }
        ranges.back().second = n - 1;
        return ranges;
    }
    std::size_t first = 0;
    for (std::size_t i = 1; i < n; ++i) {
        if (std::floor(revolution[i]) > std::floor(revolution[first])) {
            ranges.emplace_back(first, i - 1);
            first = i;
        }
    }
    ranges.emplace_back(first, n - 1);
    return ranges;
}

// Every stride-th record, the last one and the first record of every layer (so that each
// drawn layer starts where the program's does).
std::vector<std::size_t> drawnRecords(std::size_t count, std::size_t stride,
                                      std::span<const std::pair<std::size_t, std::size_t>> ranges) {
    std::vector<std::size_t> records;
    records.reserve(count / stride + ranges.size() + 2);
    for (std::size_t i = 0; i < count; i += stride) {
        records.push_back(i);
    }
    records.push_back(count - 1);
    for (const auto& range : ranges) {
        records.push_back(range.first);
    }
    std::sort(records.begin(), records.end());
    records.erase(std::unique(records.begin(), records.end()), records.end());
    return records;
}

// |dA/dt| of the profile sample that covers each record (merged duplicates take the speed of
// the sample before them).
std::vector<double> aSpeedAt(const analysis::AxisProfile& profile,
                             std::span<const std::size_t> records) {
    const auto& samples = profile.sampleRecord;
    const analysis::AxisSeries& a = profile.axis(kinematics::AxisId::A);
    std::vector<double> speed;
    if (samples.empty()) {
        return speed;
    }
    speed.reserve(records.size());
    for (const std::size_t record : records) {
        const auto after = std::upper_bound(samples.begin(), samples.end(), record);
        const auto index =
            static_cast<std::size_t>(std::max<std::ptrdiff_t>(after - samples.begin() - 1, 0));
        speed.push_back(std::abs(a.velocityAt(index)));
    }
    return speed;
}

// Unit in-plane (x = const) direction from the ball centre towards the blade: the centre path
// is the section offset by R, so the blade lies on its inner side.
Vec3 towardsBlade(std::span<const Vec3> centres, std::size_t i, int sense) {
    const std::size_t before = i > 0 ? i - 1 : i;
    const std::size_t after = i + 1 < centres.size() ? i + 1 : i;
    const Vec3 tangent = centres[after] - centres[before];
    const Vec3 inward(0.0, -sense * tangent.z(), sense * tangent.y());
    const double length = inward.norm();
    return length > 0.0 ? Vec3(inward / length) : Vec3::Zero();
}

// The nearest point to p on segment ab.
Vec3 nearestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return a + t * ab;
}

// The point of the centre path nearest to centre i on the turn `offset` revolutions away;
// nullopt where the pass has no such turn. The search starts at the same revolution parameter
// and walks downhill: matching by the parameter alone fails around the blade's edges, where
// the polar angle about x barely changes while the centre goes round the edge.
std::optional<Vec3> nearestOnTurn(std::span<const Vec3> centres, std::span<const double> revolution,
                                  std::size_t i, double offset) {
    const double u = revolution[i] + offset;
    if (u < revolution.front() || u > revolution.back()) {
        return std::nullopt;
    }
    const Vec3& p = centres[i];
    const auto distance = [&](std::size_t k) { return (centres[k] - p).squaredNorm(); };
    auto k = static_cast<std::size_t>(std::lower_bound(revolution.begin(), revolution.end(), u) -
                                      revolution.begin());
    while (k + 1 < centres.size() && distance(k + 1) < distance(k)) {
        ++k;
    }
    while (k > 0 && distance(k - 1) < distance(k)) {
        --k;
    }
    if (std::abs(revolution[k] - revolution[i]) < 0.5) {
        return std::nullopt; // walked back onto the centre's own turn: no neighbour there
    }
    Vec3 best = centres[k];
    for (const std::size_t other : {k > 0 ? k - 1 : k, k + 1 < centres.size() ? k + 1 : k}) {
        const Vec3 candidate = nearestOnSegment(p, centres[k], centres[other]);
        if ((candidate - p).squaredNorm() < (best - p).squaredNorm()) {
            best = candidate;
        }
    }
    return best;
}

// Unit 3-D direction from the ball centre towards the blade, along the blade's normal at the
// contact. The centres lie on the blade offset by R along that normal (the 3-D normal, which
// the twist tilts out of the section plane), so it is also the normal of the centres' own
// surface, spanned by the path tangent and the chord between the nearest points one turn
// earlier and later (central, or one-sided over two turns at the ends of the pass, so that the
// surface's curvature cancels to first order). The in-plane direction stands in where the pass has
// fewer than three turns, and orients the normal.
Vec3 normalTowardsBlade(std::span<const Vec3> centres, std::span<const double> revolution,
                        std::size_t i, const Vec3& inPlane) {
    const std::size_t before = i > 0 ? i - 1 : i;
    const std::size_t after = i + 1 < centres.size() ? i + 1 : i;
    const Vec3 tangent = centres[after] - centres[before];
    const auto turn = [&](double offset) { return nearestOnTurn(centres, revolution, i, offset); };
    const auto next = turn(1.0), previous = turn(-1.0);
    Vec3 across;
    if (next && previous) {
        across = *next - *previous;
    } else if (const auto nextTwo = next ? turn(2.0) : std::nullopt; nextTwo) {
        across = 4.0 * *next - *nextTwo - 3.0 * centres[i]; // one-sided, second order
    } else if (const auto previousTwo = previous ? turn(-2.0) : std::nullopt; previousTwo) {
        across = 3.0 * centres[i] - 4.0 * *previous + *previousTwo;
    } else {
        return inPlane; // fewer than three turns: no second-order estimate
    }
    Vec3 normal = tangent.cross(across);
    const double length = normal.norm();
    // Degenerate where the path stalls or the turns touch: keep the section-plane estimate.
    if (!(length > 1e-9 * tangent.norm() * across.norm())) {
        return inPlane;
    }
    normal /= length;
    return normal.dot(inPlane) < 0.0 ? Vec3(-normal) : normal;
}

void orientOutwards(cad::TriangleMesh& mesh, std::span<const Vec3> inward) {
    double agreement = 0.0;
    for (const auto& t : mesh.triangles) {
        const Vec3 normal = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                                .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        agreement -= normal.dot(inward[t[0]] + inward[t[1]] + inward[t[2]]);
    }
    if (agreement < 0.0) {
        for (auto& t : mesh.triangles) {
            std::swap(t[1], t[2]);
        }
    }
}

// Joins each revolution of the contact points to the next one: two cursors, one revolution
// apart, advance along the path in the order of their revolution parameter, each step adding
// one triangle (a ribbon between neighbouring rings of a helix).
cad::TriangleMesh ribbonBetweenRevolutions(std::span<const Vec3> points,
                                           std::span<const double> revolution) {
    cad::TriangleMesh mesh;
    mesh.vertices.assign(points.begin(), points.end());
    const std::size_t m = points.size();
    std::size_t upper = 0;
    while (upper < m && revolution[upper] < revolution[0] + 1.0) {
        ++upper;
    }
    std::size_t lower = 0;
    const auto index = [](std::size_t i) { return static_cast<std::uint32_t>(i); };
    while (upper + 1 < m) {
        if (lower + 1 < upper && revolution[lower + 1] + 1.0 <= revolution[upper + 1]) {
            mesh.triangles.push_back({index(lower), index(lower + 1), index(upper)});
            ++lower;
        } else {
            mesh.triangles.push_back({index(lower), index(upper + 1), index(upper)});
            ++upper;
        }
    }
    return mesh;
}

std::vector<Vec3> vertexNormals(const cad::TriangleMesh& mesh) {
    std::vector<Vec3> normals(mesh.vertices.size(), Vec3::Zero());
    for (const auto& t : mesh.triangles) {
        // Area-weighted: the cross product's length is twice the area.
        const Vec3 normal = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                                .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        for (const std::uint32_t v : t) {
            normals[v] += normal;
        }
    }
    for (Vec3& normal : normals) {
        const double length = normal.norm();
        normal = length > 0.0 ? Vec3(normal / length) : Vec3::UnitZ();
    }
    return normals;
}

struct Contacts {
    std::vector<Vec3> points; // per drawn point
    std::vector<Vec3> inward; // unit, towards the blade
};

Contacts contactPoints(const DisplayScene& scene, std::span<const double> revolution, int sense) {
    Contacts contacts;
    contacts.points.reserve(scene.centres.size());
    contacts.inward.reserve(scene.centres.size());
    for (std::size_t i = 0; i < scene.centres.size(); ++i) {
        const Vec3 inward =
            normalTowardsBlade(scene.centres, revolution, i, towardsBlade(scene.centres, i, sense));
        contacts.inward.push_back(inward);
        contacts.points.push_back(scene.toolRadius > 0.0
                                      ? Vec3(scene.centres[i] + scene.toolRadius * inward)
                                      : scene.tips[i]);
    }
    return contacts;
}

void reconstructSurface(DisplayScene& scene, std::span<const double> drawnRevolution, int sense,
                        std::size_t maxVertices) {
    const Contacts contacts = contactPoints(scene, drawnRevolution, sense);
    for (DisplayLayer& layer : scene.layers) {
        cad::Polyline3 ring;
        ring.points.assign(contacts.points.begin() + static_cast<std::ptrdiff_t>(layer.firstPoint),
                           contacts.points.begin() + static_cast<std::ptrdiff_t>(layer.lastPoint) +
                               1);
        layer.section = {std::move(ring)};
    }
    const std::size_t stride = strideFor(contacts.points.size(), maxVertices);
    std::vector<Vec3> points, inward;
    std::vector<double> revolution;
    for (std::size_t i = 0; i < contacts.points.size(); i += stride) {
        points.push_back(contacts.points[i]);
        inward.push_back(contacts.inward[i]);
        revolution.push_back(drawnRevolution[i]);
    }
    scene.surface = ribbonBetweenRevolutions(points, revolution);
    orientOutwards(scene.surface, inward);
    scene.surfaceNormals = vertexNormals(scene.surface);
    scene.surfaceSource =
        scene.surface.empty() ? SurfaceSource::None : SurfaceSource::Reconstructed;
    scene.surfaceName = scene.toolRadius > 0.0 ? "contact points" : "tool tips (no radius)";
}

// The CAD mesh and the section of every layer; false (with a warning) when either fails.
bool cadSurface(DisplayScene& scene, const DisplaySceneInput& input) {
    cad::MeshOptions mesh;
    mesh.linearDeflection = input.limits.cadDeflection;
    auto triangles = cad::tessellate(*input.blade, mesh);
    if (!triangles) {
        scene.warnings.push_back("the 3-D view could not mesh the blade CAD (" +
                                 triangles.error().toString() + "); showing the contact points");
        return false;
    }
    std::vector<double> xs;
    for (const DisplayLayer& layer : scene.layers) {
        xs.push_back(layer.sectionX);
    }
    auto sections = cad::sectionsAtX(*input.blade, xs);
    if (!sections) {
        scene.warnings.push_back("the 3-D view could not section the blade CAD (" +
                                 sections.error().toString() + "); showing the contact points");
        return false;
    }
    for (std::size_t k = 0; k < scene.layers.size(); ++k) {
        scene.layers[k].section = std::move((*sections)[k]);
    }
    scene.surface = std::move(*triangles);
    scene.surfaceNormals = vertexNormals(scene.surface);
    scene.surfaceSource = SurfaceSource::Cad;
    scene.surfaceName = input.bladeName.empty() ? std::string("blade CAD") : input.bladeName;
    return true;
}

bool scheduleMatches(const DisplaySceneInput& input) {
    return input.schedule != nullptr && input.schedule->newAxes.size() == input.pass.size();
}

void fillPoints(DisplayScene& scene, const DisplaySceneInput& input,
                std::span<const std::size_t> layerOfRecord) {
    const bool rescheduled = scheduleMatches(input);
    const std::size_t n = scene.record.size();
    scene.tips.reserve(n);
    scene.centres.reserve(n);
    scene.originalAxes.reserve(n);
    scene.layer.reserve(n);
    for (const std::size_t r : scene.record) {
        const toolpath::ClRecord& record = input.pass[r];
        const Vec3 axis = record.axis.normalized();
        scene.originalAxes.push_back(axis);
        scene.centres.push_back(record.tip + scene.toolRadius * axis);
        // The schedule keeps the ball centres and no tips.
        scene.tips.push_back(rescheduled ? tipOfBall(scene.centres.back(),
                                                     input.schedule->newAxes[r], scene.toolRadius)
                                         : record.tip);
        scene.layer.push_back(layerOfRecord[r]);
        if (rescheduled) {
            scene.rescheduledAxes.push_back(input.schedule->newAxes[r].normalized());
        }
    }
    if (input.schedule != nullptr && !rescheduled) {
        scene.warnings.push_back("the schedule does not match the cutting pass; showing the "
                                 "original orientation only");
    }
    if (input.originalProfile != nullptr) {
        scene.aSpeedOriginal = aSpeedAt(*input.originalProfile, scene.record);
    }
    if (input.rescheduledProfile != nullptr && rescheduled) {
        scene.aSpeedRescheduled = aSpeedAt(*input.rescheduledProfile, scene.record);
    }
}

} // namespace

const char* toString(SurfaceSource source) {
    switch (source) {
    case SurfaceSource::None:
        return "none";
    case SurfaceSource::Cad:
        return "CAD";
    case SurfaceSource::Reconstructed:
        return "reconstructed";
    }
    return "?";
}

DisplayScene buildDisplayScene(const DisplaySceneInput& input) {
    DisplayScene scene;
    const std::size_t n = input.pass.size();
    scene.passRecords = n;
    scene.toolRadius = input.toolRadius > 0.0 ? input.toolRadius : 0.0;
    if (n == 0) {
        return scene;
    }
    std::vector<Vec3> centres;
    centres.reserve(n);
    for (const toolpath::ClRecord& record : input.pass) {
        centres.push_back(toolpath::ballCentre(record, scene.toolRadius));
    }
    const Revolutions revolutions = revolutionsAboutX(centres);
    const std::vector<double>& revolution = revolutions.turns;
    const auto ranges = layerRanges(input, revolution);
    std::vector<std::size_t> layerOfRecord(n, 0);
    for (std::size_t k = 0; k < ranges.size(); ++k) {
        std::fill(layerOfRecord.begin() + static_cast<std::ptrdiff_t>(ranges[k].first),
                  layerOfRecord.begin() + static_cast<std::ptrdiff_t>(ranges[k].second) + 1, k);
    }
    scene.record = drawnRecords(n, strideFor(n, input.limits.maxPathPoints), ranges);
    fillPoints(scene, input, layerOfRecord);

    std::size_t point = 0;
    for (const auto& [first, last] : ranges) {
        DisplayLayer layer;
        layer.firstRecord = first;
        layer.lastRecord = last;
        layer.firstPoint = point;
        while (point + 1 < scene.record.size() && scene.record[point + 1] <= last) {
            ++point;
        }
        layer.lastPoint = point;
        ++point;
        layer.sectionX = centres[(first + last) / 2].x();
        scene.layers.push_back(std::move(layer));
    }
    const std::size_t pointsPerLayer = scene.record.size() / scene.layers.size();
    const std::size_t glyphStride =
        std::max(strideFor(scene.record.size(), input.limits.maxGlyphs),
                 strideFor(pointsPerLayer, input.limits.maxGlyphsPerLayer));
    for (std::size_t i = 0; i < scene.record.size(); i += glyphStride) {
        scene.glyphPoints.push_back(i);
    }

    if (input.blade != nullptr && !input.blade->isNull() && cadSurface(scene, input)) {
        return scene;
    }
    std::vector<double> drawnRevolution;
    drawnRevolution.reserve(scene.record.size());
    for (const std::size_t r : scene.record) {
        drawnRevolution.push_back(revolution[r]);
    }
    reconstructSurface(scene, drawnRevolution, revolutions.sense, input.limits.maxSurfaceVertices);
    return scene;
}

DisplayScene buildDisplayScene(const JobResult& result, const DisplayLimits& limits) {
    DisplaySceneInput input;
    const auto& records = result.program.path().records;
    if (result.pass.first + result.pass.count <= records.size()) {
        input.pass = std::span(records).subspan(result.pass.first, result.pass.count);
    }
    input.toolRadius = result.toolRadius.value_or(0.0);
    if (result.cadCheck) {
        input.blade = &result.cadCheck->blade;
        input.bladeName = result.cadCheck->source;
    }
    if (result.rescheduled) {
        input.schedule = &result.rescheduled->schedule;
        input.rescheduledProfile = &result.rescheduled->profile;
    }
    input.originalProfile = &result.original;
    input.limits = limits;
    return buildDisplayScene(input);
}

} // namespace bladeaxis::job
