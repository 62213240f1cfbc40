#pragma once
// What the window accepts on its command line, checked before Qt starts: Qt aborts (exit 134)
// on a platform plugin it cannot load, and silently ignores options it does not know, so a typo
// (`-V`) or a missing display would otherwise crash or do nothing.

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace bladeaxis::app {

// Empty when the window can start with these arguments (the program name first); otherwise the
// message to print before exiting with the usage code. `environment` looks a variable up
// (getenv in the program, a map in tests).
std::optional<std::string>
checkGuiArguments(const std::vector<std::string>& arguments,
                  const std::function<const char*(const char*)>& environment);

} // namespace bladeaxis::app
