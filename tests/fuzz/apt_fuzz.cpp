// The APT/CLSF reader directly, with and without a feed for GOTO lists that state none.
#include "core/io/cl/apt_reader.h"
#include "tests/fuzz/fuzz_target.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace bladeaxis;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    io::ReadOptions withFeed;
    withFeed.feedMmPerS = 50.0;
    fuzz::withoutExceptions("apt", [&] {
        fuzz::expectNoInternalError(io::cl::parseApt(text, "fuzz.cl"), "apt");
        fuzz::expectNoInternalError(io::cl::parseApt(text, "fuzz.cl", withFeed), "apt");
    });
    return 0;
}
