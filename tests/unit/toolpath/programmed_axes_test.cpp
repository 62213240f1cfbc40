// A record's programmed machine axes behave as std::optional's did, in 8 bytes less per record.

#include "core/toolpath/toolpath.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>

namespace bladeaxis::toolpath {
namespace {

TEST(ProgrammedAxes, AreAbsentUntilSetAndAgainOnceReset) {
    ClRecord record;
    EXPECT_FALSE(record.axes.has_value());
    EXPECT_FALSE(record.axes);
    EXPECT_THROW((void)record.axes.value(), std::bad_optional_access);

    record.axes = kinematics::MachineAxes{1.0, -2.0, 3.5, 0.25, -0.125};
    ASSERT_TRUE(record.axes);
    EXPECT_EQ(record.axes->x, 1.0);
    EXPECT_EQ((*record.axes).b, -0.125);
    record.axes->a = 4.0;
    EXPECT_EQ(record.axes.value().a, 4.0);
    const std::optional<kinematics::MachineAxes> asOptional = record.axes;
    ASSERT_TRUE(asOptional.has_value());
    EXPECT_EQ(asOptional->y, -2.0);

    ClRecord copy = record;
    EXPECT_TRUE(copy.axes);
    record.axes.reset();
    EXPECT_FALSE(record.axes);
    EXPECT_TRUE(copy.axes);
    copy.axes = std::nullopt;
    EXPECT_FALSE(copy.axes);
    EXPECT_FALSE(static_cast<std::optional<kinematics::MachineAxes>>(copy.axes).has_value());
}

// Any value a reader or a computation gives is present: zeros, a negative zero, infinities and
// the NaNs arithmetic makes (a reader refuses them later, with the record's line).
TEST(ProgrammedAxes, AnyComputedValueIsPresentIncludingNaNAndInfinity) {
    const double values[] = {0.0,
                             -0.0,
                             std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::quiet_NaN(),
                             std::nan("1"),
                             0.0 / std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::infinity() -
                                 std::numeric_limits<double>::infinity()};
    for (double x : values) {
        ProgrammedAxes axes = kinematics::MachineAxes{x, 0.0, 0.0, 0.0, 0.0};
        EXPECT_TRUE(axes.has_value()) << x;
    }
}

TEST(ProgrammedAxes, KeepARecordAt104Bytes) {
    EXPECT_EQ(sizeof(ProgrammedAxes), sizeof(kinematics::MachineAxes));
    EXPECT_EQ(sizeof(ClRecord), 104u);
}

} // namespace
} // namespace bladeaxis::toolpath
