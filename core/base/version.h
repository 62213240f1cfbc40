#pragma once
// The version of BladeAxis, from one place: the CMake project version, and the git revision of
// the checkout it was configured from ("unknown" outside a checkout). --version, the window's
// About box and report.json all read it here.

#include <string_view>

namespace bladeaxis {

// "0.1.0"
std::string_view projectVersion();

// `git describe --always --dirty --tags` at configure time, or "unknown".
std::string_view projectRevision();

} // namespace bladeaxis
