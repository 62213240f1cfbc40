#pragma once
// Shared helpers of the CAD tests: the demo blade, its surface (built once, it takes a moment)
// and a scratch directory per test.

#include "core/blade/blade.h"
#include "core/blade/presets.h"
#include "core/cad/blade_surface.h"
#include "core/cad/cad_shape.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace bladeaxis::cad::testing {

inline const blade::Blade& demoBlade() {
    static const blade::Blade blade = *blade::demoBlade();
    return blade;
}

inline const CadShape& demoSurface() {
    static const CadShape shape = *makeBladeSurface(demoBlade());
    return shape;
}

// A fresh empty directory named after the running test.
inline std::filesystem::path scratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "bladeaxis_cad" /
                                      (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::filesystem::path cadData(const std::string& name) {
    return std::filesystem::path(BLADEAXIS_TEST_DATA_DIR) / "cad" / name;
}

} // namespace bladeaxis::cad::testing
