#include "core/analysis/lost_motion.h"

#include "core/analysis/reversals.h"

namespace bladeaxis::analysis {

std::vector<LostMotion> lostMotion(const AxisProfile& profile,
                                   const kinematics::MachineModel& machine) {
    std::vector<LostMotion> losses;
    for (const kinematics::AxisId axis : kinematics::kAllAxes) {
        const double backlash = machine.limit(axis).backlash;
        if (!(backlash > 0.0)) {
            continue;
        }
        LostMotion loss;
        loss.axis = axis;
        loss.backlash = backlash;
        if (axis == kinematics::AxisId::A) {
            loss.reversals = profile.aReversals.count;
        } else {
            const double minStep =
                kinematics::isRotary(axis) ? tol::kReversalStepRad : kLinearReversalStepMm;
            loss.reversals = auditReversals(profile.positions(axis), minStep).count;
        }
        loss.lostMotion = backlash * loss.reversals;
        losses.push_back(loss);
    }
    return losses;
}

} // namespace bladeaxis::analysis
