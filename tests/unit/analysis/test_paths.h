#pragma once
// Synthetic programs for the analysis tests: records plus machine axes, built point by point.

#include "core/geometry/vec.h"
#include "core/kinematics/machine_model.h"
#include "core/toolpath/toolpath.h"

#include <vector>

namespace bladeaxis::analysis::testing {

struct Program {
    std::vector<toolpath::ClRecord> records;
    std::vector<kinematics::MachineAxes> axes;

    // Appends a record with the tip at `tip` and machine axes X Y Z = tip, A = a, B = 0.
    void add(const Vec3& tip, double a, double feed, const Vec3& axis = Vec3::UnitZ()) {
        toolpath::ClRecord record;
        record.tip = tip;
        record.axis = axis;
        record.feed = feed;
        record.line = static_cast<int>(records.size()) + 1;
        records.push_back(record);
        axes.push_back({tip.x(), tip.y(), tip.z(), a, 0.0});
    }
};

} // namespace bladeaxis::analysis::testing
