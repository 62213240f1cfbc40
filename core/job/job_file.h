#pragma once
// Job files (`bladeaxis-job/1`, documented in docs/job-file.md): a JobSpec saved as JSON so a
// shop can rerun the same job, and the GUI can save its edits. Paths inside are relative to
// the job file. Parameters use the keys and user units of parameter_schema.h.

#include "core/base/error.h"
#include "core/job/job.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace bladeaxis::job {

// Reads a job file into `spec`, on top of what it holds (so defaults stay where the file is
// silent). Errors: FileNotFound/FileUnreadable, InvalidArgument naming file, line and key.
Status readJobFile(const std::filesystem::path& path, JobSpec& spec);
Status parseJobJson(std::string_view text, const std::filesystem::path& path, JobSpec& spec);

// The job as JSON text, paths relative to `relativeTo` (the folder the job file goes in).
std::string jobJsonText(const JobSpec& spec, const std::filesystem::path& relativeTo);

} // namespace bladeaxis::job
