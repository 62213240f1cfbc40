#include "core/base/file_io.h"
#include "core/base/units.h"
#include "core/kinematics/machine_file.h"

#include <gtest/gtest.h>

#include <array>
#include <string>

namespace bladeaxis::kinematics {
namespace {

const std::string kShippedMachine =
    std::string(BLADEAXIS_SOURCE_DIR) + "/resources/machines/blade_ab.json";

TEST(MachineFile, ShippedDefaultMachineLoadsAndMatchesTheBuiltIn) {
    auto machine = loadMachineFile(kShippedMachine);
    ASSERT_TRUE(machine.has_value()) << machine.error().toString();
    const MachineModel builtIn = defaultBladeMachine();
    for (AxisId id : kAllAxes) {
        EXPECT_NEAR(machine->limit(id).velocity, builtIn.limit(id).velocity, 1e-12) << axisName(id);
        EXPECT_NEAR(machine->limit(id).acceleration, builtIn.limit(id).acceleration, 1e-12);
        EXPECT_NEAR(machine->limit(id).jerk, builtIn.limit(id).jerk, 1e-12);
        EXPECT_EQ(machine->limit(id).hasTravel, builtIn.limit(id).hasTravel);
    }
    EXPECT_EQ(machine->aMode, RotaryMode::Continuous);
}

TEST(MachineFile, RotaryLimitsAreConvertedFromDegreesToRadians) {
    auto machine = loadMachineFile(kShippedMachine);
    ASSERT_TRUE(machine.has_value());
    EXPECT_NEAR(machine->limit(AxisId::A).velocity, units::degToRad(360.0), 1e-12);
    EXPECT_NEAR(machine->limit(AxisId::B).max, units::degToRad(87.0), 1e-12);
}

// A table-B machine names its axes by its own letters; each drives the engine axis of its role:
// the table (B) is the engine's A, the head's A its B, Y its x and X its y with the travel
// mirrored. The sign keys name letters too: b_sign is the table's.
TEST(MachineFile, ATableBMachineMapsItsLettersOntoTheEnginesRoles) {
    const auto machine = parseMachineJson(
        R"({"schema": "bladeaxis-machine/1", "kinematics": {"type": "table_b_head_a",
        "b_sign": -1, "a_sign": 1, "table_offset_mm": [1, 2, 3]}, "axes": {
        "X": {"min_mm": -100, "max_mm": 300, "velocity_mm_s": 11, "acceleration_mm_s2": 1, "jerk_mm_s3": 1},
        "Y": {"min_mm": -900, "max_mm": 900, "velocity_mm_s": 22, "acceleration_mm_s2": 1, "jerk_mm_s3": 1},
        "Z": {"velocity_mm_s": 33, "acceleration_mm_s2": 1, "jerk_mm_s3": 1},
        "A": {"min_deg": -80, "max_deg": 30, "velocity_deg_s": 44, "acceleration_deg_s2": 1, "jerk_deg_s3": 1},
        "B": {"mode": "modulo", "velocity_deg_s": 55, "acceleration_deg_s2": 1, "jerk_deg_s3": 1}}})",
        "b.json");
    ASSERT_TRUE(machine) << machine.error().toString();
    EXPECT_EQ(machine->layout, Layout::TableBHeadA);
    EXPECT_TRUE(machine->hasB());
    EXPECT_EQ(machine->letter(AxisId::A), 'B');
    EXPECT_EQ(machine->letter(AxisId::B), 'A');
    EXPECT_EQ(machine->letter(AxisId::X), 'Y');
    EXPECT_EQ(machine->letter(AxisId::Y), 'X');
    EXPECT_DOUBLE_EQ(machine->limit(AxisId::X).velocity, 22.0);
    EXPECT_DOUBLE_EQ(machine->limit(AxisId::Y).velocity, 11.0);
    EXPECT_DOUBLE_EQ(machine->limit(AxisId::Y).min, -300.0);
    EXPECT_DOUBLE_EQ(machine->limit(AxisId::Y).max, 100.0);
    EXPECT_NEAR(machine->limit(AxisId::A).velocity, units::degToRad(55.0), 1e-12);
    EXPECT_NEAR(machine->limit(AxisId::B).min, units::degToRad(-30.0), 1e-12);
    EXPECT_NEAR(machine->limit(AxisId::B).max, units::degToRad(80.0), 1e-12);
    EXPECT_EQ(machine->aMode, RotaryMode::Modulo);
    EXPECT_EQ(machine->chain.aSign, -1);
    EXPECT_EQ(machine->chain.bSign, 1);
    EXPECT_LT((machine->chain.tableOffset - Vec3(2.0, -1.0, 3.0)).norm(), 1e-15);
    // Program values and engine axes convert both ways.
    const std::array<double, 5> words{1.0, 2.0, 3.0, 0.4, 0.5};
    EXPECT_EQ(machine->programValues(machine->fromProgramValues(words)), words);
}

TEST(MachineFile, AFixedHeadTableBMachineRefusesAnAAxis) {
    const auto machine = parseMachineJson(
        R"({"schema": "bladeaxis-machine/1", "kinematics": {"type": "table_b"}, "axes": {
        "X": {"velocity_mm_s": 1, "acceleration_mm_s2": 1, "jerk_mm_s3": 1},
        "Y": {"velocity_mm_s": 1, "acceleration_mm_s2": 1, "jerk_mm_s3": 1},
        "Z": {"velocity_mm_s": 1, "acceleration_mm_s2": 1, "jerk_mm_s3": 1},
        "A": {"velocity_deg_s": 1, "acceleration_deg_s2": 1, "jerk_deg_s3": 1},
        "B": {"velocity_deg_s": 1, "acceleration_deg_s2": 1, "jerk_deg_s3": 1}}})",
        "fixed.json");
    ASSERT_FALSE(machine.has_value());
    EXPECT_NE(machine.error().toString().find("axes.A: the machine has a fixed head"),
              std::string::npos)
        << machine.error().toString();
}

struct BadMachineCase {
    const char* name;
    const char* json;
    const char* expected; // substring of Error::toString()
};

std::string validAxes(const std::string& aAxis) {
    const std::string linear =
        R"({"velocity_mm_s": 500, "acceleration_mm_s2": 3000, "jerk_mm_s3": 30000})";
    return R"("axes": {"X": )" + linear + R"(, "Y": )" + linear + R"(, "Z": )" + linear +
           R"(, "A": )" + aAxis +
           R"(, "B": {"velocity_deg_s": 90, "acceleration_deg_s2": 900, "jerk_deg_s3": 9000}})";
}

const std::string kHeader =
    R"({"schema": "bladeaxis-machine/1", "kinematics": {"type": "table_a_head_b"}, )";
const std::string kGoodA =
    R"({"velocity_deg_s": 360, "acceleration_deg_s2": 1800, "jerk_deg_s3": 18000})";

class BadMachineFile : public ::testing::TestWithParam<BadMachineCase> {};

TEST_P(BadMachineFile, IsRejectedWithAMessageNamingTheProblem) {
    const BadMachineCase& c = GetParam();
    auto machine = parseMachineJson(c.json, "m.json");
    ASSERT_FALSE(machine.has_value()) << c.name;
    EXPECT_EQ(machine.error().code, ErrorCode::MachineFile);
    EXPECT_NE(machine.error().toString().find(c.expected), std::string::npos)
        << "got: " << machine.error().toString();
}

const std::string kNegativeVelocity =
    kHeader +
    validAxes(R"({"velocity_deg_s": -3, "acceleration_deg_s2": 1800, "jerk_deg_s3": 1})") + "}";
const std::string kMissingJerk =
    kHeader + validAxes(R"({"velocity_deg_s": 3, "acceleration_deg_s2": 1800})") + "}";
const std::string kBadMode =
    kHeader +
    validAxes(
        R"({"mode": "spiral", "velocity_deg_s": 3, "acceleration_deg_s2": 1, "jerk_deg_s3": 1})") +
    "}";
const std::string kTextVelocity =
    kHeader +
    validAxes(R"({"velocity_deg_s": "fast", "acceleration_deg_s2": 1, "jerk_deg_s3": 1})") + "}";
const std::string kTravelReversed =
    kHeader +
    validAxes(
        R"({"min_deg": 10, "max_deg": -10, "velocity_deg_s": 3, "acceleration_deg_s2": 1, "jerk_deg_s3": 1})") +
    "}";
const std::string kNoAxes = kHeader + "\"name\": \"m\"}";
const std::string kWrongType =
    R"({"schema": "bladeaxis-machine/1", "kinematics": {"type": "head_head"}, )" +
    validAxes(kGoodA) + "}";
const std::string kBadSign =
    R"({"schema": "bladeaxis-machine/1", "kinematics": {"type": "table_a_head_b", "a_sign": 2}, )" +
    validAxes(kGoodA) + "}";
const std::string kBadOffset =
    R"({"schema": "bladeaxis-machine/1", "kinematics": {"type": "table_a_head_b", "table_offset_mm": [1, 2]}, )" +
    validAxes(kGoodA) + "}";

INSTANTIATE_TEST_SUITE_P(
    Corpus, BadMachineFile,
    ::testing::Values(
        BadMachineCase{"syntax", "{\n  \"schema\": \n}",
                       "m.json:3:1: machine file error: invalid JSON"},
        BadMachineCase{"empty", "", "invalid JSON"},
        BadMachineCase{"not an object", "[1, 2]", "expected a JSON object"},
        BadMachineCase{"wrong schema", R"({"schema": "other/2"})",
                       "schema: expected \"bladeaxis-machine/1\""},
        BadMachineCase{"no kinematics", R"({"schema": "bladeaxis-machine/1"})",
                       "kinematics: missing"},
        BadMachineCase{"wrong chain", kWrongType.c_str(),
                       "kinematics.type: expected one of \"table_a_head_b\""},
        BadMachineCase{"bad sign", kBadSign.c_str(), "kinematics.a_sign: expected 1 or -1"},
        BadMachineCase{"bad offset", kBadOffset.c_str(),
                       "table_offset_mm: expected [x, y, z] in mm"},
        BadMachineCase{"no axes", kNoAxes.c_str(), "axes: missing"},
        BadMachineCase{"negative velocity", kNegativeVelocity.c_str(),
                       "axes.A.velocity_deg_s: expected a positive number, got -3"},
        BadMachineCase{"missing jerk", kMissingJerk.c_str(), "axes.A.jerk_deg_s3: missing"},
        BadMachineCase{"bad mode", kBadMode.c_str(),
                       "axes.A.mode: expected \"continuous\" or \"modulo\""},
        BadMachineCase{"text velocity", kTextVelocity.c_str(), "expected a number, got \"fast\""},
        BadMachineCase{"travel reversed", kTravelReversed.c_str(),
                       "axes.A.max_deg: expected max > min"}));

// A table offset of 1e10 mm was taken, and the job ended in "internal error: the re-scheduled
// program does not read back" (exit 1): a length beyond any machine is the file's error.
TEST(MachineFile, ALengthBeyondTenMetresIsRefusedNamingTheKeyAndItsLine) {
    const std::string linear = R"({"velocity_mm_s": 1, "acceleration_mm_s2": 1, "jerk_mm_s3": 1)";
    const std::string rotary =
        R"({"velocity_deg_s": 1, "acceleration_deg_s2": 1, "jerk_deg_s3": 1})";
    const auto machine = [&](const std::string& kinematics, const std::string& x) {
        return "{\"schema\": \"bladeaxis-machine/1\",\n\"kinematics\": {\"type\": \"table_a\"" +
               kinematics + "},\n\"axes\": {\"X\": " + linear + x + "},\n\"Y\": " + linear +
               "}, \"Z\": " + linear + "}, \"A\": " + rotary + "}}";
    };
    const std::pair<std::string, std::string> cases[] = {
        {machine(",\n\"table_offset_mm\": [0, 1e10, 0]", ""), "m.json:3: machine file error: "
                                                              "kinematics.table_offset_mm"},
        {machine(",\n\"head_offset_mm\": [0, 0, -10001]", ""), "m.json:3: machine file error: "
                                                               "kinematics.head_offset_mm"},
        {machine(",\n\"pivot_length_mm\": 1e10", ""), "m.json:3: machine file error: "
                                                      "kinematics.pivot_length_mm"},
        {machine("", ", \"min_mm\": -1e12, \"max_mm\": 100"), "axes.X.min_mm"}};
    for (const auto& [json, expected] : cases) {
        auto parsed = parseMachineJson(json, "m.json");
        ASSERT_FALSE(parsed.has_value()) << json;
        EXPECT_EQ(parsed.error().code, ErrorCode::MachineFile);
        EXPECT_NE(parsed.error().toString().find(expected), std::string::npos)
            << parsed.error().toString();
        EXPECT_NE(parsed.error().message.find("[-10000, 10000] mm"), std::string::npos)
            << parsed.error().message;
    }
    auto edge =
        parseMachineJson(machine(",\n\"table_offset_mm\": [0, -10000, 10000]", ""), "m.json");
    EXPECT_TRUE(edge.has_value()) << edge.error().toString();
}

TEST(MachineFile, ErrorNamesTheLineOfTheOffendingKey) {
    const std::string json =
        "{\n\"schema\": \"bladeaxis-machine/1\",\n\"kinematics\": {\"type\": \"x\"}\n}";
    auto machine = parseMachineJson(json, "m.json");
    ASSERT_FALSE(machine.has_value());
    EXPECT_EQ(machine.error().where.line, 3);
}

TEST(MachineFile, AnAxisSignOtherThanPlusOrMinusOneIsRefusedNamingTheKey) {
    for (const char* sign : {"1e82", "0.5", "\"-1\"", "2"}) {
        const std::string json =
            std::string("{\"schema\": \"bladeaxis-machine/1\", "
                        "\"kinematics\": {\"type\": \"table_a_head_b\", \"a_sign\": ") +
            sign + "}}";
        auto machine = parseMachineJson(json, "m.json");
        ASSERT_FALSE(machine.has_value()) << sign;
        EXPECT_EQ(machine.error().code, ErrorCode::MachineFile);
        EXPECT_NE(machine.error().message.find("a_sign"), std::string::npos)
            << machine.error().message;
    }
    std::string shipped = readTextFile(kShippedMachine).value_or("");
    for (const std::string key : {"\"a_sign\": 1", "\"b_sign\": 1"}) {
        const auto at = shipped.find(key);
        ASSERT_NE(at, std::string::npos) << key;
        shipped.replace(at, key.size(), key.substr(0, key.size() - 1) + "-1.0");
    }
    auto flipped = parseMachineJson(shipped, "m.json");
    ASSERT_TRUE(flipped.has_value()) << flipped.error().toString();
    EXPECT_EQ(flipped->chain.aSign, -1);
    EXPECT_EQ(flipped->chain.bSign, -1);
}

TEST(MachineFile, MissingFileIsFileNotFound) {
    auto machine = loadMachineFile("/nonexistent/machine.json");
    ASSERT_FALSE(machine.has_value());
    EXPECT_EQ(machine.error().code, ErrorCode::FileNotFound);
}

TEST(MachineFile, ModuloModeIsRead) {
    const std::string json =
        kHeader +
        validAxes(
            R"({"mode": "modulo", "velocity_deg_s": 3, "acceleration_deg_s2": 1, "jerk_deg_s3": 1})") +
        "}";
    auto machine = parseMachineJson(json, "m.json");
    ASSERT_TRUE(machine.has_value()) << machine.error().toString();
    EXPECT_EQ(machine->aMode, RotaryMode::Modulo);
}

} // namespace
} // namespace bladeaxis::kinematics

namespace bladeaxis::kinematics {
namespace {

std::string machineWithController(const std::string& controller) {
    const std::string linear =
        R"({"velocity_mm_s": 500, "acceleration_mm_s2": 3000, "jerk_mm_s3": 30000})";
    return R"({"schema": "bladeaxis-machine/1", "kinematics": {"type": "table_a_head_b"}, "axes": {"X": )" +
           linear + R"(, "Y": )" + linear + R"(, "Z": )" + linear +
           R"(, "A": {"velocity_deg_s": 360, "acceleration_deg_s2": 1800, "jerk_deg_s3": 18000})" +
           R"(, "B": {"velocity_deg_s": 90, "acceleration_deg_s2": 900, "jerk_deg_s3": 9000}})" +
           (controller.empty() ? "" : ", \"controller\": " + controller) + "}";
}

TEST(MachineFileController, WithoutTheKeyTheControlIsALookAheadOne) {
    const auto machine = parseMachineJson(machineWithController(""), "m.json");
    ASSERT_TRUE(machine.has_value()) << machine.error().toString();
    EXPECT_EQ(machine->controller.planner, Planner::LookAhead);
}

TEST(MachineFileController, NamesTheBlockByBlockPlanner) {
    const auto machine =
        parseMachineJson(machineWithController(R"({"planner": "block-by-block"})"), "m.json");
    ASSERT_TRUE(machine.has_value()) << machine.error().toString();
    EXPECT_EQ(machine->controller.planner, Planner::BlockByBlock);
    EXPECT_STREQ(plannerName(machine->controller.planner), "block-by-block");
}

TEST(MachineFileController, RefusesAnUnknownPlannerAndATypo) {
    const auto unknown =
        parseMachineJson(machineWithController(R"({"planner": "magic"})"), "m.json");
    ASSERT_FALSE(unknown.has_value());
    EXPECT_NE(unknown.error().toString().find("controller.planner"), std::string::npos);
    const auto typo =
        parseMachineJson(machineWithController(R"({"planer": "look-ahead"})"), "m.json");
    ASSERT_FALSE(typo.has_value());
    EXPECT_NE(typo.error().toString().find("unknown key"), std::string::npos);
}

// One key a line, so that a test can name the line of each: X, Y and Z all hold "max_mm", and
// an error in Z's must name Z's line (34), not X's (20) (a value on line 55 was reported at 47).
std::string lineByLineMachine() {
    std::string text = R"({
  "schema": "bladeaxis-machine/1",
  "name": "one key a line",
  "kinematics": {
    "type": "table_a_head_b",
    "pivot_length_mm": 0,
    "a_sign": 1,
    "b_sign": 1
  },
  "least_input_increment": {
    "mm": 0.001,
    "deg": 0.001
  },
  "controller": {
    "planner": "look-ahead"
  },
  "axes": {
    "X": {
      "min_mm": -1400,
      "max_mm": 1400,
      "velocity_mm_s": 500,
      "acceleration_mm_s2": 3000,
      "jerk_mm_s3": 30000
    },
    "Y": {
      "min_mm": -330,
      "max_mm": 330,
      "velocity_mm_s": 500,
      "acceleration_mm_s2": 3000,
      "jerk_mm_s3": 30000
    },
    "Z": {
      "min_mm": -300,
      "max_mm": 500,
      "velocity_mm_s": 500,
      "acceleration_mm_s2": 3000,
      "jerk_mm_s3": 30000
    },
    "A": {
      "mode": "continuous",
      "velocity_deg_s": 360,
      "acceleration_deg_s2": 1800,
      "jerk_deg_s3": 18000
    },
    "B": {
      "min_deg": -87,
      "max_deg": 87,
      "velocity_deg_s": 90,
      "acceleration_deg_s2": 900,
      "jerk_deg_s3": 9000
    }
  }
}
)";
    return text;
}

// Replaces the first occurrence of `from` at or after line `line` (1-based) of the text.
std::string replacedOnLine(std::string text, int line, const std::string& from,
                           const std::string& to) {
    std::size_t at = 0;
    for (int i = 1; i < line; ++i) {
        at = text.find('\n', at) + 1;
    }
    const std::size_t end = text.find('\n', at);
    const std::size_t found = text.find(from, at);
    EXPECT_LT(found, end) << from << " is not on line " << line;
    return text.replace(found, from.size(), to);
}

TEST(MachineFileLines, TheLineByLineMachineLoads) {
    const auto machine = parseMachineJson(lineByLineMachine(), "m.json");
    ASSERT_TRUE(machine.has_value()) << machine.error().toString();
    EXPECT_TRUE(machine->limit(AxisId::Z).hasTravel);
}

struct LineCase {
    int line;
    std::string from;
    std::string to;
    std::string expected; // the whole "file:line: kind: path: ..." prefix
};

// The line-by-line machine with the case's edit is refused with the case's message, from the
// start of the message (file:line first).
void expectRefusedAsCaseSays(const LineCase& c) {
    const auto machine =
        parseMachineJson(replacedOnLine(lineByLineMachine(), c.line, c.from, c.to), "m.json");
    ASSERT_FALSE(machine.has_value()) << c.expected;
    EXPECT_EQ(machine.error().code, ErrorCode::MachineFile);
    EXPECT_EQ(machine.error().toString().rfind(c.expected, 0), 0U)
        << "expected: " << c.expected << "\n     got: " << machine.error().toString();
}

// Each bad value is put on a known line; the error names that line, not the first line that
// holds the same key in another object.
TEST(MachineFileLines, EachErrorNamesTheLineOfItsValue) {
    const LineCase cases[] = {
        {35, "\"velocity_mm_s\": 500", "\"velocity_mm_s\": -1",
         "m.json:35: machine file error: axes.Z.velocity_mm_s: expected a positive number"},
        {33, "-300", "900", "m.json:34: machine file error: axes.Z.max_mm: expected max > min"},
        {34, "500", "1e6",
         "m.json:34: machine file error: axes.Z.max_mm: expected a length in [-10000, 10000]"},
        {27, "\"max_mm\": 330", "\"max_mm\": \"far\"",
         "m.json:27: machine file error: axes.Y.max_mm: expected a number, got \"far\""},
        {46, "-87", "87", "m.json:47: machine file error: axes.B.max_deg: expected max > min"},
        {40, "continuous", "spiral", "m.json:40: machine file error: axes.A.mode: expected"},
        {15, "look-ahead", "magic", "m.json:15: machine file error: controller.planner"},
        {12, "0.001", "0", "m.json:12: machine file error: least_input_increment.deg"},
        {8, "\"b_sign\": 1", "\"b_sign\": 3", "m.json:8: machine file error: kinematics.b_sign"},
    };
    for (const LineCase& c : cases) {
        expectRefusedAsCaseSays(c);
    }
}

TEST(MachineFileLines, AMissingKeyNamesTheLineOfItsObject) {
    const auto machine = parseMachineJson(
        replacedOnLine(lineByLineMachine(), 37, "\"jerk_mm_s3\": 30000", "\"backlash_mm\": 0"),
        "m.json");
    ASSERT_FALSE(machine.has_value());
    EXPECT_EQ(machine.error().toString().rfind(
                  "m.json:32: machine file error: axes.Z.jerk_mm_s3: missing", 0),
              0U)
        << machine.error().toString();
}

// A misspelt key was ignored: "max_mmm" dropped the travel check without a word. Every object
// of the file refuses a key it does not know, at its line, naming the nearest known key.
TEST(MachineFileLines, AnUnknownKeyInEveryObjectIsRefusedAtItsLineWithTheNearestKnownKey) {
    const LineCase cases[] = {
        {3, "\"name\"", "\"nmae\"",
         "m.json:3: machine file error: nmae: unknown key in a "
         "machine file (docs/machine-file.md); did you mean \"name\"?"},
        {6, "\"pivot_length_mm\"", "\"pivot_lenght_mm\"",
         "m.json:6: machine file error: kinematics.pivot_lenght_mm: unknown key in a machine "
         "file (docs/machine-file.md); did you mean \"pivot_length_mm\"?"},
        {11, "\"mm\"", "\"mmm\"",
         "m.json:11: machine file error: least_input_increment.mmm: unknown key in a machine "
         "file (docs/machine-file.md); did you mean \"mm\"?"},
        {15, "\"planner\"", "\"planer\"",
         "m.json:15: machine file error: controller.planer: unknown key in a machine file "
         "(docs/machine-file.md); did you mean \"planner\"?"},
        {32, "\"Z\"", "\"z\"",
         "m.json:32: machine file error: axes.z: unknown key in a machine "
         "file (docs/machine-file.md); did you mean \"Z\"?"},
        {34, "\"max_mm\"", "\"max_mmm\"",
         "m.json:34: machine file error: axes.Z.max_mmm: unknown key in a machine file "
         "(docs/machine-file.md); did you mean \"max_mm\"?"},
        {19, "\"min_mm\"", "\"min_deg\"",
         "m.json:19: machine file error: axes.X.min_deg: a linear axis takes _mm keys "
         "(docs/machine-file.md); did you mean \"min_mm\"?"},
        {43, "\"jerk_deg_s3\"", "\"jerk_deg_s\"",
         "m.json:43: machine file error: axes.A.jerk_deg_s: unknown key in a machine file "
         "(docs/machine-file.md); did you mean \"jerk_deg_s3\"?"},
        // Only the table turns modulo: "mode" on the head's B is not a key of B.
        {47, "\"max_deg\": 87", "\"mode\": \"modulo\"",
         "m.json:47: machine file error: axes.B.mode: unknown key in a machine file"},
    };
    for (const LineCase& c : cases) {
        expectRefusedAsCaseSays(c);
    }
}

} // namespace
} // namespace bladeaxis::kinematics
