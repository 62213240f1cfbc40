#include "app/gui_arguments.h"

#include <algorithm>
#include <array>
#include <string_view>

namespace bladeaxis::app {

namespace {

// Qt's own options that take a value ("-platform offscreen"), and those that do not.
constexpr std::array<std::string_view, 7> kQtOptionsWithValue{
    "-platform", "-platformpluginpath", "-platformtheme", "-plugin", "-qmljsdebugger",
    "-style",    "-stylesheet"};
constexpr std::array<std::string_view, 3> kQtFlags{"-reverse", "-widgetcount", "-nograb"};

bool isOneOf(std::string_view argument, auto const& list) {
    return std::find(list.begin(), list.end(), argument) != list.end();
}

bool hasDisplay(const std::vector<std::string>& arguments,
                const std::function<const char*(const char*)>& environment) {
    const auto set = [&environment](const char* name) {
        const char* value = environment(name);
        return value != nullptr && *value != '\0';
    };
    // An explicit platform (offscreen, vnc, eglfs...) needs no X11 or Wayland display.
    const bool platformGiven =
        set("QT_QPA_PLATFORM") ||
        std::find(arguments.begin(), arguments.end(), "-platform") != arguments.end();
    return platformGiven || set("DISPLAY") || set("WAYLAND_DISPLAY");
}

} // namespace

std::optional<std::string>
checkGuiArguments(const std::vector<std::string>& arguments,
                  const std::function<const char*(const char*)>& environment) {
    int files = 0;
    for (std::size_t index = 1; index < arguments.size(); ++index) {
        const std::string& argument = arguments[index];
        if (isOneOf(argument, kQtOptionsWithValue)) {
            ++index; // its value
            continue;
        }
        if (isOneOf(argument, kQtFlags)) {
            continue;
        }
        if (argument.size() > 1 && argument.front() == '-') {
            return "unknown option '" + argument +
                   "': the window takes [PROGRAM or JOB.json]; options such as this one belong "
                   "to the headless program (bladeaxis --batch --help lists them)";
        }
        if (++files > 1) {
            return "the window opens one program or job at a time, got '" + argument + "' as well";
        }
    }
    if (!hasDisplay(arguments, environment)) {
        return "no display: the window needs X11 or Wayland (DISPLAY and WAYLAND_DISPLAY are not "
               "set); run the headless program with --batch, or set QT_QPA_PLATFORM=offscreen";
    }
    return std::nullopt;
}

} // namespace bladeaxis::app
