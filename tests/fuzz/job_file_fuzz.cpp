// The job-file reader (JSON), including its layer edits (the S-theta editor's saved input) and
// the confinement of the paths it names.
#include "core/job/job_file.h"
#include "tests/fuzz/fuzz_target.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace bladeaxis;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    fuzz::withoutExceptions("job_file", [&] {
        job::JobSpec spec;
        const Status status =
            job::parseJobJson(text, std::filesystem::path("/nonexistent/fuzz/job.json"), spec);
        fuzz::expectNoInternalError(status, "job_file");
    });
    return 0;
}
