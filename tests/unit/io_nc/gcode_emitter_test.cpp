#include "core/io/nc/gcode_emitter.h"
#include "tests/unit/io_nc/gcode_test_support.h"

#include <gtest/gtest.h>

#include <clocale>

namespace bladeaxis::io::nc {
namespace {

using kinematics::defaultBladeMachine;
using units::radToDeg;

GcodeProgram emitAndParse(const toolpath::Toolpath& path, const GcodeEmitOptions& options,
                          const kinematics::MachineModel& machine = defaultBladeMachine()) {
    const Result<std::string> text = emitGcode(path, machine, options);
    EXPECT_TRUE(text.has_value()) << (text ? "" : text.error().toString());
    Result<GcodeProgram> program = parseGcode(text ? *text : "", "emitted.nc", machine);
    EXPECT_TRUE(program.has_value()) << (program ? "" : program.error().toString());
    return program ? std::move(*program) : GcodeProgram{};
}

TEST(GcodeEmitter, RoundTripWithTenDecimalsKeepsTipsAxesAndA) {
    const toolpath::Toolpath path = test::spiralPath(200, 2.5);
    GcodeEmitOptions options;
    options.linearDecimals = 10;
    options.angularDecimals = 10;
    const GcodeProgram program = emitAndParse(path, options);
    ASSERT_EQ(program.path.records.size(), path.records.size());
    double previousA = -1.0;
    for (std::size_t i = 0; i < path.records.size(); ++i) {
        const toolpath::ClRecord& got = program.path.records[i];
        EXPECT_LT((got.tip - path.records[i].tip).norm(), 1e-9) << i;
        EXPECT_LT((got.axis - path.records[i].axis).norm(), 1e-9) << i;
        EXPECT_EQ(got.motion, path.records[i].motion) << i;
        EXPECT_GT(got.axes->a, previousA) << "A unwrapped continuously at " << i;
        previousA = got.axes->a;
    }
    EXPECT_NEAR(radToDeg(program.path.records.back().axes->a), 900.0, 1e-9);
}

TEST(GcodeEmitter, RoundTripWithDefaultDecimalsIsWithinHalfTheLastDigit) {
    const toolpath::Toolpath path = test::spiralPath(200, 1.5);
    const GcodeProgram program = emitAndParse(path, {});
    ASSERT_EQ(program.path.records.size(), path.records.size());
    double aReference = 0.0;
    for (std::size_t i = 0; i < path.records.size(); ++i) {
        const auto exact = kinematics::inverseKinematics(
            {}, {path.records[i].tip, path.records[i].axis}, aReference);
        ASSERT_TRUE(exact.has_value());
        aReference = exact->a;
        const kinematics::MachineAxes& got = *program.path.records[i].axes;
        EXPECT_NEAR(got.x, exact->x, 0.5e-4 + 1e-12) << i;
        EXPECT_NEAR(got.y, exact->y, 0.5e-4 + 1e-12) << i;
        EXPECT_NEAR(got.z, exact->z, 0.5e-4 + 1e-12) << i;
        EXPECT_NEAR(radToDeg(got.a), radToDeg(exact->a), 0.5e-4 + 1e-9) << i;
        EXPECT_NEAR(radToDeg(got.b), radToDeg(exact->b), 0.5e-4 + 1e-9) << i;
        EXPECT_NEAR(program.path.records[i].feed, path.records[i].feed, 1e-9) << i;
    }
}

TEST(GcodeEmitter, WritesHeaderModesBlockNumbersAndFeedOnlyWhenItChanges) {
    toolpath::Toolpath path = test::spiralPath(5, 0.1);
    GcodeEmitOptions options;
    options.headerComments = {"BLADE (DEMO)", "second"};
    const Result<std::string> text = emitGcode(path, defaultBladeMachine(), options);
    ASSERT_TRUE(text.has_value());
    EXPECT_EQ(test::lineOf(*text, 1), "(BLADE [DEMO])");
    EXPECT_EQ(test::lineOf(*text, 3), "N10 G21 G90 G94");
    EXPECT_EQ(test::lineOf(*text, 4).substr(0, 11), "N20 G0 X-49");
    EXPECT_EQ(test::lineOf(*text, 4).find(" F"), std::string::npos); // rapid
    EXPECT_NE(test::lineOf(*text, 5).find(" F1200"), std::string::npos);
    EXPECT_NE(test::lineOf(*text, 6).find(" F1500"), std::string::npos);
    EXPECT_EQ(test::lineOf(*text, 7).find(" F"), std::string::npos); // unchanged feed
    EXPECT_EQ(test::lineOf(*text, 9), "N70 M30");
}

TEST(GcodeEmitter, ModuloMachinesGetAInZeroTo360) {
    kinematics::MachineModel machine = defaultBladeMachine();
    machine.aMode = kinematics::RotaryMode::Modulo;
    const GcodeProgram program = emitAndParse(test::spiralPath(100, 2.0), {}, machine);
    for (const toolpath::ClRecord& record : program.path.records) {
        EXPECT_GE(radToDeg(record.axes->a), 0.0);
        EXPECT_LT(radToDeg(record.axes->a), 360.0);
    }
}

TEST(GcodeEmitter, FeedMoveWithoutAnyFeedIsAnError) {
    toolpath::Toolpath path = test::spiralPath(5, 0.1);
    path.records[1].feed = 0.0;
    const auto text = emitGcode(path, defaultBladeMachine(), {});
    ASSERT_FALSE(text.has_value());
    EXPECT_EQ(text.error().code, ErrorCode::InvalidArgument);
    EXPECT_NE(text.error().message.find("record 1"), std::string::npos);
}

TEST(GcodeEmitter, UnreachablePoseNamesTheRecord) {
    toolpath::Toolpath path = test::spiralPath(5, 0.1);
    path.records[3].axis = Vec3::UnitX();
    const auto text = emitGcode(path, defaultBladeMachine(), {});
    ASSERT_FALSE(text.has_value());
    EXPECT_NE(text.error().message.find("record 3"), std::string::npos);
}

// A decimal-comma desktop must not change what is read or written (docs/architecture.md,
// Conventions).
TEST(GcodeLocale, ParseAndEmitAreIndependentOfADecimalCommaLocale) {
    const toolpath::Toolpath path = test::spiralPath(50, 1.0);
    const std::string sample = test::readSample("fanuc_basic.nc");
    const auto emittedC = emitGcode(path, defaultBladeMachine(), {});
    const auto parsedC = parseGcode(sample, "f.nc", defaultBladeMachine());
    ASSERT_TRUE(emittedC && parsedC);

    const char* previous = std::setlocale(LC_ALL, nullptr);
    const std::string saved = previous ? previous : "C";
    if (std::setlocale(LC_ALL, "de_DE.UTF-8") == nullptr) {
        GTEST_SKIP() << "de_DE.UTF-8 locale not installed";
    }
    const auto emittedDe = emitGcode(path, defaultBladeMachine(), {});
    const auto parsedDe = parseGcode(sample, "f.nc", defaultBladeMachine());
    std::setlocale(LC_ALL, saved.c_str());

    ASSERT_TRUE(emittedDe && parsedDe);
    EXPECT_EQ(*emittedDe, *emittedC);
    ASSERT_EQ(parsedDe->path.records.size(), parsedC->path.records.size());
    for (std::size_t i = 0; i < parsedC->path.records.size(); ++i) {
        EXPECT_EQ(parsedDe->path.records[i].tip, parsedC->path.records[i].tip) << i;
        EXPECT_EQ(parsedDe->path.records[i].feed, parsedC->path.records[i].feed) << i;
    }
}

} // namespace
} // namespace bladeaxis::io::nc
