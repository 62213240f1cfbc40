#include "core/job/cad_fit.h"

#include "core/base/number_io.h"

#include <algorithm>

namespace bladeaxis::job {
namespace {

struct Box {
    Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());
    void add(const Vec3& p) {
        min = min.cwiseMin(p);
        max = max.cwiseMax(p);
    }
};

template <typename Points>
Box boxOf(const Points& points) {
    Box box;
    for (const Vec3& p : points) {
        box.add(p);
    }
    return box;
}

std::string describe(const Box& box) {
    auto range = [](double a, double b) { return formatFixed(a, 1) + " .. " + formatFixed(b, 1); };
    return "x " + range(box.min.x(), box.max.x()) + ", y " + range(box.min.y(), box.max.y()) +
           ", z " + range(box.min.z(), box.max.z()) + " mm";
}

// A little beyond the exact limits: the mesh deflection and sampling, and rounded programs.
constexpr double kSlack = 0.1; // mm

} // namespace

Status checkCadFitsProgram(const CadFitInput& input) {
    if (input.centres.empty()) {
        return {};
    }
    const Box cad = boxOf(input.blade->vertices);
    const Box centres = boxOf(input.centres);
    std::size_t far = 0;
    for (const cad::RecordClearance& c : input.clearance->records) {
        far += c.ball >= input.searchLimit ? 1 : 0;
    }
    const double reach = input.toolRadius + kSlack;
    const bool spansX =
        cad.min.x() <= centres.min.x() + reach && cad.max.x() >= centres.max.x() - reach;
    const bool nearMost = 2 * far <= input.clearance->records.size();
    if (spansX && nearMost) {
        return {};
    }
    return makeError(
        ErrorCode::Geometry,
        "the CAD does not fit the program, is it the blade of " + input.programName +
            " and is its placement right (--cad-rotate-deg, --cad-translate)? Expected a blade "
            "spanning the ball "
            "centres' x range less R = " +
            formatTrimmed(input.toolRadius, 3) + " mm (centres at " + describe(centres) +
            "), found the CAD at " + describe(cad) + "; " + std::to_string(far) + " of " +
            std::to_string(input.clearance->records.size()) + " CL points are farther than the " +
            formatTrimmed(input.searchLimit, 3) + " mm search limit from it",
        {input.cadName});
}

} // namespace bladeaxis::job
