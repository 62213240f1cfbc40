#include "core/base/error.h"

#include <gtest/gtest.h>

namespace bladeaxis {
namespace {

TEST(Error, ToStringNamesFileLineColumnAndMessage) {
    const Error error{ErrorCode::Parse, "expected a number after 'X'", {"blade.nc", 12, 5}, {}};
    EXPECT_EQ(error.toString(), "blade.nc:12:5: parse error: expected a number after 'X'");
}

TEST(Error, ToStringOmitsUnknownLocationParts) {
    EXPECT_EQ((SourceLocation{"m.json", 3, 0}).toString(), "m.json:3");
    EXPECT_EQ((SourceLocation{"m.json", 0, 0}).toString(), "m.json");
    const Error error{ErrorCode::InvalidArgument, "bad", {}, {}};
    EXPECT_EQ(error.toString(), "invalid argument: bad");
}

TEST(Error, FurtherErrorsFollowOnTheirOwnLines) {
    Error error{ErrorCode::Parse, "first", {"a.nc", 1, 1}, {}};
    error.more.push_back({ErrorCode::Parse, "second", {"a.nc", 2, 1}, {}});
    EXPECT_EQ(error.toString(), "a.nc:1:1: parse error: first\na.nc:2:1: parse error: second");
}

TEST(Error, RepeatsOfOneMessageAreGroupedNamingTheirLines) {
    Error error{ErrorCode::Parse, "unexpected character '1'", {"a.nc", 12, 1}, {}};
    for (int line = 13; line <= 31; ++line) {
        error.more.push_back({ErrorCode::Parse, "unexpected character '1'", {"a.nc", line, 1}, {}});
    }
    error.more.push_back({ErrorCode::Parse, "other", {"a.nc", 40, 2}, {}});
    EXPECT_EQ(error.toString(),
              "a.nc:12:1: parse error: unexpected character '1' (and 19 more lines like it: 13, "
              "14, 15, 16, 17, 18, 19, 20, ...)\na.nc:40:2: parse error: other");
}

TEST(Error, OneRepeatIsNamedAsOneLine) {
    Error error{ErrorCode::Parse, "x", {"a.nc", 1, 1}, {}};
    error.more.push_back({ErrorCode::Parse, "x", {"a.nc", 5, 1}, {}});
    EXPECT_EQ(error.toString(), "a.nc:1:1: parse error: x (and 1 more line like it: 5)");
}

TEST(Error, MakeErrorBuildsAnUnexpectedResult) {
    const Result<int> result = makeError(ErrorCode::FileNotFound, "no such file", {"x.nc"});
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, ErrorCode::FileNotFound);
    EXPECT_EQ(result.error().where.file, "x.nc");
}

} // namespace
} // namespace bladeaxis
