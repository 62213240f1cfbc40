#include "app/subcommands.h"

#include "core/base/nearest_name.h"

#include <algorithm>
#include <array>
#include <initializer_list>

namespace bladeaxis::app {

namespace {

struct Subcommand {
    std::string_view name;
    std::initializer_list<std::string_view> flags;
};

// "analyze" is accepted too: half the CAM world spells it so. "help" and "version" run the
// headless program, which needs no display.
const std::array<Subcommand, 9> kSubcommands{{
    {"reschedule", {"--batch"}},
    {"analyse", {"--batch", "--analyse-only"}},
    {"analyze", {"--batch", "--analyse-only"}},
    {"compare", {"--batch", "--compare"}},
    {"generate", {"--batch", "--generate"}},
    {"reproduce", {"--batch", "--reproduce"}},
    {"gui", {}},
    {"help", {"--help"}},
    {"version", {"--version"}},
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
  gui [PROGRAM | JOB.json]    open the window (the default without --batch)
  help                        this help (--help)
  version                     the version (--version))";
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

std::optional<std::string>
mistypedSubcommand(const std::vector<std::string>& arguments,
                   const std::function<bool(const std::string&)>& fileExists) {
    if (arguments.size() < 2 || arguments[1].empty() || arguments[1].front() == '-') {
        return std::nullopt;
    }
    const std::string& word = arguments[1];
    std::array<std::string_view, kSubcommands.size()> names{};
    std::ranges::transform(kSubcommands, names.begin(),
                           [](const Subcommand& command) { return command.name; });
    if (std::ranges::find(names, word) != names.end() || fileExists(word)) {
        return std::nullopt;
    }
    const auto nearest = nearestName(word, names);
    if (!nearest) {
        return std::nullopt;
    }
    return "unknown command '" + word + "'; did you mean `" + std::string(*nearest) +
           "`? (a program file of that name is given as ./" + word + ")";
}

} // namespace bladeaxis::app
