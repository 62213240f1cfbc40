#pragma once
// The built-in demo job as the job tests run it: one place for the spec and the quiet run.

#include "core/job/job.h"

#include <filesystem>
#include <string>

namespace bladeaxis::job::test {

// The demo job (with the comparison on request) writing into a fresh folder of that name under
// the temporary directory.
inline JobSpec demoJob(const std::string& folder, bool withComparison = false) {
    JobSpec spec;
    spec.demo = true;
    spec.compare = withComparison;
    spec.outputDir = std::filesystem::temp_directory_path() / folder;
    std::filesystem::remove_all(spec.outputDir);
    return spec;
}

// runJob without progress output, never cancelled.
inline Result<JobResult> runQuietly(const JobSpec& spec) {
    NullProgressSink progress;
    CancelToken cancel;
    return runJob(spec, progress, cancel);
}

} // namespace bladeaxis::job::test
