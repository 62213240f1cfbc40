#pragma once
// `bladeaxis COMMAND ...`: commands for what a CAM engineer does (reschedule, analyse, compare,
// generate, reproduce, gui), each shorthand for the flags that scripts already use, which stay.

#include <string>
#include <string_view>
#include <vector>

namespace bladeaxis::app {

// The command list as --help and the manual page print it.
std::string_view subcommandHelp();

// argv with a leading command replaced by its flags ("analyse x.nc" -> "--batch --analyse-only
// x.nc"; "gui x.nc" -> "x.nc"); argv unchanged when its first argument is not a command. A
// program file named like a command is given as ./analyse.
std::vector<std::string> expandSubcommand(const std::vector<std::string>& arguments);

} // namespace bladeaxis::app
