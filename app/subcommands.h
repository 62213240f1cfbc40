#pragma once
// `bladeaxis COMMAND ...`: commands for what a CAM engineer does (reschedule, analyse, compare,
// generate, reproduce, gui, help, version), each shorthand for the flags that scripts already use,
// which stay.

#include <functional>
#include <optional>
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

// The refusal of a first word that is near a command's name ("reshedule") but neither a command
// nor an existing file: it would otherwise open the window on a file that does not exist.
// `arguments` as given (before expandSubcommand); nullopt when the word is no such typo.
std::optional<std::string>
mistypedSubcommand(const std::vector<std::string>& arguments,
                   const std::function<bool(const std::string&)>& fileExists);

} // namespace bladeaxis::app
