// Any file given as a program: format detection, then the G-code, APT/CLSF or point-table
// reader it picks (io::readProgramText, the path every job takes).
#include "core/io/program.h"
#include "core/kinematics/machine_model.h"
#include "tests/fuzz/fuzz_target.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace bladeaxis;
    static const kinematics::MachineModel machine = kinematics::defaultBladeMachine();
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    fuzz::withoutExceptions("program", [&] {
        fuzz::expectNoInternalError(io::readProgramText(text, "fuzz.nc", machine), "program");
    });
    return 0;
}
