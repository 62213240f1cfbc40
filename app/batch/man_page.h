#pragma once
// The manual page bladeaxis(1), generated from the same CLI11 option table as --help, so the two
// never disagree. The build writes it with `bladeaxis --man` and installs it.

#include <string>
#include <string_view>

namespace CLI {
class App;
}

namespace bladeaxis::app {

struct ManPageText {
    std::string_view version;   // "0.1.0"
    std::string_view commands;  // the subcommand list, as --help prints it
    std::string_view exitCodes; // the exit-code table, as --help prints it
};

// roff source of bladeaxis.1 (man(7) macros).
std::string manPage(const CLI::App& cli, const ManPageText& text);

} // namespace bladeaxis::app
