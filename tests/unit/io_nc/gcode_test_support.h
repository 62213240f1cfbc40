#pragma once
// Shared helpers of the G-code tests: sample files and a synthetic four-axis toolpath.

#include "core/base/file_io.h"
#include "core/base/units.h"
#include "core/io/nc/gcode.h"
#include "core/kinematics/kinematics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace bladeaxis::io::nc::test {

inline std::filesystem::path sampleDir() {
    return std::filesystem::path(BLADEAXIS_TEST_DATA_DIR) / "nc";
}

inline std::string readSample(const std::string& name) {
    Result<std::string> text = readTextFile(sampleDir() / name);
    EXPECT_TRUE(text.has_value()) << name;
    return text ? *text : std::string();
}

// The samples are small programs whose rotary words stay within 2 pi: their unit is stated, as
// the angle-unit tests show the reader refuses to guess it.
inline ReadOptions inDegrees() {
    ReadOptions options;
    options.angleUnit = AngleUnit::Degrees;
    return options;
}

// A machine whose control reads "X1" as 1 mm: the hand-written test programs mix "X1" and
// "X1.5", which the default rule refuses (its own tests show that).
inline kinematics::MachineModel wholeUnitsMachine() {
    kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    machine.numbers.integerWords = kinematics::IntegerWords::Units;
    return machine;
}

inline GcodeProgram
parseSample(const std::string& name,
            const kinematics::MachineModel& machine = kinematics::defaultBladeMachine()) {
    Result<GcodeProgram> program = readGcodeFile(sampleDir() / name, machine, inDegrees());
    EXPECT_TRUE(program.has_value()) << (program ? "" : program.error().toString());
    return program ? std::move(*program) : GcodeProgram{};
}

inline std::vector<kinematics::MachineAxes> axesOf(const GcodeProgram& program) {
    std::vector<kinematics::MachineAxes> axes;
    for (const toolpath::ClRecord& record : program.path.records) {
        axes.push_back(*record.axes);
    }
    return axes;
}

// The line (without ending) of the 1-based line number.
inline std::string lineOf(const std::string& text, int lineNumber) {
    std::size_t begin = 0;
    for (int i = 1; i < lineNumber; ++i) {
        begin = text.find('\n', begin) + 1;
    }
    std::size_t end = text.find('\n', begin);
    end = end == std::string::npos ? text.size() : end;
    if (end > begin && text[end - 1] == '\r') {
        --end;
    }
    return text.substr(begin, end - begin);
}

// A blade-like helical path: the tip winds around the A axis for `turns` turns while moving
// along X, B fixed at 12 deg, A going past 360 deg; a rapid approach and retract, two feeds.
inline toolpath::Toolpath spiralPath(int points, double turns,
                                     const kinematics::TableAHeadB& chain = {}) {
    toolpath::Toolpath path;
    const double b = units::degToRad(12.0);
    for (int i = 0; i < points; ++i) {
        const double t = static_cast<double>(i) / (points - 1);
        const double a = units::kTwoPi * turns * t;
        toolpath::ClRecord record;
        record.axis = kinematics::toolAxisFor(chain, a, b);
        const double radius = 40.0 + 5.0 * std::sin(7.0 * t);
        record.tip =
            Vec3(-50.0 + 120.0 * t, radius * std::sin(a) * 0.3, radius) + 3.0 * record.axis;
        record.motion =
            (i == 0 || i == points - 1) ? toolpath::MotionKind::Rapid : toolpath::MotionKind::Feed;
        record.feed = record.motion == toolpath::MotionKind::Feed ? (t < 0.5 ? 20.0 : 25.0) : 0.0;
        path.records.push_back(record);
    }
    return path;
}

// One block a dialect's reader refuses: where (1-based column) and a part of the message.
struct BlockRefusal {
    const char* name; // the test's name
    const char* block;
    int column;
    const char* expected;
};

inline std::string refusalName(const ::testing::TestParamInfo<BlockRefusal>& param) {
    return param.param.name;
}

// The reading failed as a parse error at `line` and the refusal's column, saying what it names.
inline void expectRefused(const Result<GcodeProgram>& program, int line,
                          const BlockRefusal& refusal) {
    ASSERT_FALSE(program.has_value()) << refusal.block;
    EXPECT_EQ(program.error().code, ErrorCode::Parse);
    EXPECT_EQ(program.error().where.line, line);
    EXPECT_EQ(program.error().where.column, refusal.column);
    EXPECT_NE(program.error().message.find(refusal.expected), std::string::npos)
        << program.error().message;
}

} // namespace bladeaxis::io::nc::test
