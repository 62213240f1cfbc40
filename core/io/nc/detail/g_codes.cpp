#include "core/io/nc/detail/g_codes.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace bladeaxis::io::nc::detail {

namespace {

// Modal or one-shot codes that change nothing a four-axis tip/axis reading depends on.
constexpr std::array<int, 28> kNoOpCodes{50,  51,  80,  90,  150, 170, 180, 190, 400, 430,
                                         500, 501, 540, 541, 550, 560, 570, 580, 590, 610,
                                         611, 620, 640, 670, 690, 800, 980, 990};

struct Rejected {
    int code;
    const char* reason;
};

constexpr const char* kMacroCall =
    "custom macro calls G65/G66 are not supported: BladeAxis reads a flat program; have the "
    "post-processor write every move";

constexpr std::array<Rejected, 17> kRejectedCodes{{
    {435, "tool centre point control G43.5 (the tool axis as I J K) is not supported: post the "
          "orientation as A and B words, with G43.4 or without tool centre point control"},
    {650, kMacroCall},
    {660, kMacroCall},
    {661, kMacroCall},
    {20, "circular interpolation G2/G3 is not supported in four-axis programs: post the program "
         "with linear moves"},
    {30, "circular interpolation G2/G3 is not supported in four-axis programs: post the program "
         "with linear moves"},
    {71, "cylindrical interpolation G7.1 is not supported: post the program with linear moves"},
    {100, "data setting G10 is not supported: set offsets on the machine, not in the program"},
    {160, "polar coordinates G16 are not supported: post Cartesian X Y Z"},
    {410, "cutter radius compensation G41/G42 is not supported: post tool tip positions"},
    {420, "cutter radius compensation G41/G42 is not supported: post tool tip positions"},
    {510, "scaling G51 is not supported: post unscaled positions"},
    {520, "local coordinate system G52 is not supported: post positions in one work offset"},
    {680, "coordinate rotation G68 is not supported: post unrotated positions"},
    {920, "coordinate system setting G92 is not supported: use a work offset G54..G59"},
    {950, "feed per revolution G95 is not supported: expected G94 (mm/min) or G93 (inverse time)"},
    {1120, "polar coordinate interpolation G112 is not supported"},
}};

} // namespace

int gCodeTimesTen(double value) {
    // Whole codes (G1, G90) are nearly all of them and need no rounding (a library call here).
    if (value >= 0.0 && value < 10000.0) {
        const auto whole = static_cast<int>(value);
        if (static_cast<double>(whole) == value) {
            return whole * 10;
        }
    }
    const double scaled = value * 10.0;
    const double rounded = std::round(scaled);
    if (value < 0.0 || value >= 10000.0 || std::abs(scaled - rounded) > 1e-6) {
        return kNotAGCode;
    }
    return static_cast<int>(rounded);
}

GCodeInfo classifyGCode(int code) {
    switch (code) {
    case 0:
        return {GKind::Rapid};
    case 10:
        return {GKind::Linear};
    case 40:
        return {GKind::Dwell};
    case 280:
    case 300:
        return {GKind::ReferenceReturn};
    case 530:
        return {GKind::MachineCoordinates};
    case 200:
        return {GKind::Inch};
    case 210:
        return {GKind::Metric};
    case 900:
        return {GKind::Absolute};
    case 910:
        return {GKind::Incremental};
    case 930:
        return {GKind::InverseTime};
    case 940:
        return {GKind::PerMinute};
    case 434:
        return {GKind::ToolTipOn};
    case 490:
        return {GKind::ToolTipOff};
    default:
        break;
    }
    for (int noOp : kNoOpCodes) {
        if (noOp == code) {
            return {GKind::NoOp};
        }
    }
    for (const Rejected& rejected : kRejectedCodes) {
        if (rejected.code == code) {
            return {GKind::Unsupported, rejected.reason};
        }
    }
    if (code >= 810 && code <= 890) {
        return {GKind::Unsupported, "canned cycles G81..G89 are not supported in four-axis "
                                    "programs: post the program with linear moves"};
    }
    return {GKind::Unsupported, nullptr};
}

std::string gCodeName(int code) {
    std::string name = "G" + std::to_string(code / 10);
    if (code % 10 != 0) {
        name += "." + std::to_string(code % 10);
    }
    return name;
}

} // namespace bladeaxis::io::nc::detail

namespace bladeaxis::io::nc::detail {

namespace {

// G9, G60, G64, G641..G645, G601..G603 (exact stop and continuous-path modes), G500 and
// G505..G599 work offsets, G17..G19 planes, G40: nothing a four-axis reading depends on.
bool isSinumerikNoOp(int code) {
    static constexpr std::array<int, 16> kCodes{90,   170,  180,  190,  400,  600,  640,  6010,
                                                6020, 6030, 6410, 6420, 6430, 6440, 6450, 5000};
    return std::find(kCodes.begin(), kCodes.end(), code) != kCodes.end() ||
           (code >= 5050 && code <= 5990 && code % 10 == 0) ||
           (code >= 540 && code <= 570 && code % 10 == 0);
}

} // namespace

GCodeInfo classifySinumerikGCode(int code) {
    switch (code) {
    case 700:
    case 7000:
        return {GKind::Inch};
    case 710:
    case 7100:
        return {GKind::Metric};
    case 1530:
        return {GKind::MachineCoordinates};
    case 200:
    case 210:
        return {GKind::Unsupported, "G20/G21 are ISO-mode codes: a Sinumerik program states inch "
                                    "or metric with G70/G71 (G700/G710)"};
    default:
        break;
    }
    if (isSinumerikNoOp(code)) {
        return {GKind::NoOp};
    }
    return classifyGCode(code);
}

} // namespace bladeaxis::io::nc::detail
