#include "core/base/json_key_lines.h"
#include "core/base/nearest_name.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace bladeaxis {
namespace {

int lineOf(std::string_view text, std::vector<std::string> path) {
    return lineOfJsonKey(text, path);
}

TEST(JsonKeyLines, NamesTheKeyOfThePathNotTheFirstKeyOfThatName) {
    const std::string text = "{\"a\": {\"k\": 1},\n \"b\": {\"k\": \"x,}{\\\"k\\\"\",\n \"k\": 2}}";
    EXPECT_EQ(lineOf(text, {"a", "k"}), 1);
    EXPECT_EQ(lineOf(text, {"b", "k"}), 3); // the last of a repeated key, as nlohmann keeps it
    EXPECT_EQ(lineOf(text, {"k"}), 0);
    EXPECT_EQ(lineOf(text, {"b"}), 2);
}

TEST(JsonKeyLines, AnArrayElementIsNamedByItsIndex) {
    const std::string text = "{\"l\": [{\"p\": 1},\n{\"q\": [1, 2]},\n{\"p\": 3}]}";
    EXPECT_EQ(lineOf(text, {"l", "0", "p"}), 1);
    EXPECT_EQ(lineOf(text, {"l", "2", "p"}), 3);
    EXPECT_EQ(lineOf(text, {"l", "1", "p"}), 0);
}

TEST(NearestName, SuggestsOnlyANearName) {
    constexpr std::string_view known[] = {"max_mm", "min_mm", "velocity_mm_s"};
    EXPECT_EQ(nearestName("max_mmm", known), "max_mm");
    EXPECT_EQ(nearestName("velocty_mm_s", known), "velocity_mm_s");
    EXPECT_FALSE(nearestName("colour", known).has_value());
}

} // namespace
} // namespace bladeaxis
