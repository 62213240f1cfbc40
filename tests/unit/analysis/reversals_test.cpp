#include "core/analysis/reversals.h"
#include "core/base/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace bladeaxis::analysis {
namespace {

using units::degToRad;

TEST(AuditReversals, MonotoneSequenceHasNoReversalAndNoBackwardTravel) {
    const std::vector<double> a{0.0, 0.1, 0.3, 0.3, 1.0};
    const ReversalAudit audit = auditReversals(a);
    EXPECT_EQ(audit.count, 0);
    EXPECT_TRUE(audit.indices.empty());
    EXPECT_DOUBLE_EQ(audit.travel, 1.0);
    EXPECT_EQ(audit.backwardTravel, 0.0);
}

TEST(AuditReversals, CountsEachTurnAtTheSampleWhereTheNewDirectionStarts) {
    // up 2, down 0.5, up 1.5: turns at samples 2 and 3.
    const std::vector<double> a{0.0, 1.0, 2.0, 1.5, 3.0};
    const ReversalAudit audit = auditReversals(a);
    EXPECT_EQ(audit.count, 2);
    EXPECT_EQ(audit.indices, (std::vector<std::size_t>{2, 3}));
    EXPECT_DOUBLE_EQ(audit.travel, 4.0);
    EXPECT_DOUBLE_EQ(audit.backwardTravel, 0.5);
}

TEST(AuditReversals, DominantDirectionIsTheOneWithMoreTravel) {
    const std::vector<double> a{0.0, -2.0, -1.5, -3.0};
    const ReversalAudit audit = auditReversals(a);
    EXPECT_EQ(audit.count, 2);
    EXPECT_DOUBLE_EQ(audit.backwardTravel, 0.5);
    EXPECT_DOUBLE_EQ(audit.travel, 4.0);
}

TEST(AuditReversals, StepsBelowTheThresholdNeitherCountNorResetTheDirection) {
    const std::vector<double> jitter{0.0, 5e-7, 0.0, 5e-7, 0.0, 5e-7};
    EXPECT_EQ(auditReversals(jitter).count, 0);
    EXPECT_NEAR(auditReversals(jitter).travel, 2.5e-6, 1e-18);

    const std::vector<double> pause{0.0, 1.0, 1.0 - 5e-7, 2.0};
    EXPECT_EQ(auditReversals(pause).count, 0);

    // A real reversal across a tiny step is still one reversal, at the real backward step.
    const std::vector<double> across{0.0, 1.0, 1.0 + 5e-7, 0.5};
    const ReversalAudit audit = auditReversals(across);
    EXPECT_EQ(audit.count, 1);
    EXPECT_EQ(audit.indices, (std::vector<std::size_t>{2}));
}

TEST(AuditReversals, ThresholdIsConfigurable) {
    const std::vector<double> a{0.0, 1.0, 0.99, 2.0};
    EXPECT_EQ(auditReversals(a).count, 2); // up, down 0.01, up
    EXPECT_EQ(auditReversals(a, 0.05).count, 0);
}

TEST(AuditReversals, SurvivesEmptySingleAndNanInput) {
    EXPECT_EQ(auditReversals({}).count, 0);
    EXPECT_EQ(auditReversals(std::vector<double>{1.0}).travel, 0.0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const ReversalAudit audit = auditReversals(std::vector<double>{0.0, 1.0, nan, 2.0, 1.0});
    EXPECT_EQ(audit.count, 1);
    EXPECT_DOUBLE_EQ(audit.travel, 2.0);
}

TEST(UnwrapRotary, TurnsModuloProgramIntoContinuousAngle) {
    const std::vector<double> modulo{degToRad(350.0), degToRad(10.0), degToRad(30.0),
                                     degToRad(20.0), degToRad(300.0)};
    const std::vector<double> a = unwrapRotary(modulo);
    const std::vector<double> expectedDeg{350.0, 370.0, 390.0, 380.0, 300.0};
    ASSERT_EQ(a.size(), expectedDeg.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_NEAR(units::radToDeg(a[i]), expectedDeg[i], 1e-9) << i;
    }
}

TEST(UnwrapRotary, NonFiniteEntryDoesNotPoisonTheRest) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<double> a =
        unwrapRotary(std::vector<double>{degToRad(350.0), nan, degToRad(10.0)});
    EXPECT_TRUE(std::isnan(a[1]));
    EXPECT_NEAR(units::radToDeg(a[2]), 370.0, 1e-9);
}

} // namespace
} // namespace bladeaxis::analysis
