// G word values as the reader keys them: ten times the number, so that G43.4 is 434.

#include "core/io/nc/detail/g_codes.h"

#include <gtest/gtest.h>

namespace bladeaxis::io::nc {
namespace {

using detail::gCodeTimesTen;
using detail::kNotAGCode;

TEST(GCodeTimesTen, WholeCodes) {
    EXPECT_EQ(gCodeTimesTen(0.0), 0);
    EXPECT_EQ(gCodeTimesTen(-0.0), 0);
    EXPECT_EQ(gCodeTimesTen(1.0), 10);
    EXPECT_EQ(gCodeTimesTen(90.0), 900);
    EXPECT_EQ(gCodeTimesTen(9999.0), 99990);
}

TEST(GCodeTimesTen, CodesWithOneDecimal) {
    EXPECT_EQ(gCodeTimesTen(43.4), 434);
    EXPECT_EQ(gCodeTimesTen(54.1), 541);
    EXPECT_EQ(gCodeTimesTen(7.1), 71);
}

TEST(GCodeTimesTen, ValuesThatAreNoGCode) {
    EXPECT_EQ(gCodeTimesTen(-1.0), kNotAGCode);
    EXPECT_EQ(gCodeTimesTen(1.05), kNotAGCode);
    EXPECT_EQ(gCodeTimesTen(10000.0), kNotAGCode);
    EXPECT_EQ(gCodeTimesTen(1e9), kNotAGCode);
}

} // namespace
} // namespace bladeaxis::io::nc
