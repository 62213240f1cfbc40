#include "app/subcommands.h"

#include <array>
#include <initializer_list>

namespace bladeaxis::app {

namespace {

struct Subcommand {
    std::string_view name;
    std::initializer_list<std::string_view> flags;
};

// "analyze" is accepted too: half the CAM world spells it so.
const std::array<Subcommand, 7> kSubcommands{{
    {"reschedule", {"--batch"}},
    {"analyse", {"--batch", "--analyse-only"}},
    {"analyze", {"--batch", "--analyse-only"}},
    {"compare", {"--batch", "--compare"}},
    {"generate", {"--batch", "--generate"}},
    {"reproduce", {"--batch", "--reproduce"}},
    {"gui", {}},
}};

} // namespace

std::string_view subcommandHelp() {
    return R"(
Commands (shorthand for the flags, which stay):
  reschedule PROGRAM -o OUT   re-schedule and write the program (--batch)
  analyse PROGRAM             analyse only, write nothing but reports (--batch --analyse-only)
  compare PROGRAM             re-schedule and compare every method (--batch --compare)
  generate OUT                write a synthetic blade program (--batch --generate OUT)
  reproduce                   the comparison over a synthetic family (--batch --reproduce)
  gui [PROGRAM | JOB.json]    open the window (the default without --batch))";
}

std::vector<std::string> expandSubcommand(const std::vector<std::string>& arguments) {
    if (arguments.size() < 2) {
        return arguments;
    }
    for (const Subcommand& command : kSubcommands) {
        if (arguments[1] != command.name) {
            continue;
        }
        std::vector<std::string> expanded{arguments.front()};
        expanded.insert(expanded.end(), command.flags.begin(), command.flags.end());
        expanded.insert(expanded.end(), arguments.begin() + 2, arguments.end());
        return expanded;
    }
    return arguments;
}

} // namespace bladeaxis::app
