// The machine-file reader (JSON): values out of range, wrong types and deep nesting must be
// named errors (exit 4), never an exception or an internal error.
#include "core/kinematics/machine_file.h"
#include "tests/fuzz/fuzz_target.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace bladeaxis;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    fuzz::withoutExceptions("machine_file", [&] {
        fuzz::expectNoInternalError(kinematics::parseMachineJson(text, "fuzz.json"),
                                    "machine_file");
    });
    return 0;
}
