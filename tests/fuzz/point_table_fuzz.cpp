// The x y z i j k point-table reader directly, with and without a feed.
#include "core/io/table/point_table.h"
#include "tests/fuzz/fuzz_target.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace bladeaxis;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    io::ReadOptions withFeed;
    withFeed.feedMmPerS = 50.0;
    fuzz::withoutExceptions("point_table", [&] {
        fuzz::expectNoInternalError(io::table::parsePointTable(text, "fuzz.csv"), "point_table");
        fuzz::expectNoInternalError(io::table::parsePointTable(text, "fuzz.csv", withFeed),
                                    "point_table");
    });
    return 0;
}
