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

// Bounds on what a job file may ask for: a blade program has at most thousands of layers and
// an edited layer tens of key points, so a file beyond these is refused (InvalidArgument,
// naming the key) before it costs memory or time.
inline constexpr std::size_t kMaxJobFileBytes = 64u << 20;
inline constexpr std::size_t kMaxLayerEdits = 100'000;
inline constexpr std::size_t kMaxKeyPointsPerLayer = 100'000;

// The job as JSON text, paths relative to `relativeTo` (the folder the job file goes in).
std::string jobJsonText(const JobSpec& spec, const std::filesystem::path& relativeTo);

} // namespace bladeaxis::job
