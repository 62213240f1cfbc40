#include "app/gui_arguments.h"

#include <gtest/gtest.h>

#include <map>

namespace bladeaxis::app {
namespace {

// An environment with just these variables.
auto environmentWith(std::map<std::string, std::string> variables) {
    return [variables = std::move(variables)](const char* name) -> const char* {
        const auto found = variables.find(name);
        return found == variables.end() ? nullptr : found->second.c_str();
    };
}

TEST(GuiArguments, AProgramWithADisplayStartsTheWindow) {
    EXPECT_FALSE(
        checkGuiArguments({"bladeaxis", "blade.nc"}, environmentWith({{"DISPLAY", ":0"}})));
    EXPECT_FALSE(checkGuiArguments({"bladeaxis"}, environmentWith({{"WAYLAND_DISPLAY", "w-0"}})));
}

TEST(GuiArguments, AnUnknownOptionIsNamedInsteadOfStartingQt) {
    const auto problem =
        checkGuiArguments({"bladeaxis", "-V"}, environmentWith({{"DISPLAY", ":0"}}));
    ASSERT_TRUE(problem);
    EXPECT_NE(problem->find("unknown option '-V'"), std::string::npos);
}

TEST(GuiArguments, QtsOwnOptionsAndTheirValuesAreAccepted) {
    EXPECT_FALSE(checkGuiArguments({"bladeaxis", "-platform", "offscreen", "-reverse", "job.json"},
                                   environmentWith({})));
}

TEST(GuiArguments, NoDisplaySaysSoAndPointsToBatch) {
    const auto problem = checkGuiArguments({"bladeaxis", "blade.nc"}, environmentWith({}));
    ASSERT_TRUE(problem);
    EXPECT_NE(problem->find("no display"), std::string::npos);
    EXPECT_NE(problem->find("--batch"), std::string::npos);
    EXPECT_FALSE(
        checkGuiArguments({"bladeaxis"}, environmentWith({{"QT_QPA_PLATFORM", "offscreen"}})));
}

TEST(GuiArguments, TwoFilesAreRefused) {
    EXPECT_TRUE(
        checkGuiArguments({"bladeaxis", "a.nc", "b.nc"}, environmentWith({{"DISPLAY", ":0"}})));
}

} // namespace
} // namespace bladeaxis::app
