#pragma once
// The stages of a job that the pipeline (pipeline.cpp) runs in order, each on the job's result
// so far. Internal to the job library.

#include "core/base/error.h"
#include "core/base/progress.h"
#include "core/io/read_watch.h"
#include "core/job/cad_check.h"
#include "core/job/job.h"
#include "core/job/program_check.h"

#include <optional>
#include <string>
#include <vector>

namespace bladeaxis::job {

// The most a job lets the controller filter's millisecond series hold at once (8 bytes per
// millisecond of the pass and axis), in both analyses: a five-million-block program's series are
// about 190 MB per axis, and two at once took the job's peak above its 1.5 GB bound; a
// million-block program's (about 40 MB each) still go on every thread.
inline constexpr double kFilterSeriesBytesAtOnce = 256.0 * 1024.0 * 1024.0;

// The program read and parsed (or the demo program generated, with its radius in `toolRadius`).
Result<io::LoadedProgram> loadInput(const JobSpec& spec, const Retention& keep,
                                    const kinematics::MachineModel& machine,
                                    std::optional<double>& toolRadius, const io::ReadWatch& watch);

// The radius the job uses (the spec's over the file's, with a warning when they differ), and
// its plausibility check.
std::optional<double> jobToolRadius(const JobSpec& spec, std::optional<double> generated,
                                    const io::LoadedProgram& program,
                                    std::vector<std::string>& warnings);
Status checkToolRadius(std::optional<double> radius, const toolpath::Toolpath& path);
// Why the file gave no radius, in the words of its format.
std::string radiusSourceHint(io::ProgramFormat format);

// Whether the job checks the tool against CAD (a CAD file, or the demo's own surface), and the
// check's spec, validated before any scheduling.
bool checksCad(const JobSpec& spec);
Result<CadCheckSpec> cadCheckSpec(const JobSpec& spec, std::optional<double> toolRadius);

// The input's cutting pass found, its machine axes and its motion analysed (all but T2).
Status analyse(JobResult& result, const JobSpec& spec, const CancelToken& cancel);

// The four-axis condition on B (and the helical check) before scheduling; noise within the
// tolerance snapped to the median.
Status checkTilt(JobResult& result, const JobSpec& spec, ProgressSink& progress);

// The program checks' letters of the table and the tilt and the tilt's sign.
RotaryLetters rotaryLetters(const kinematics::MachineModel& machine);

Status cadCheckInto(JobResult& result, const JobSpec& spec, const CadCheckSpec& cadSpec,
                    ProgressSink& progress);
Status compareInto(JobResult& result, const JobSpec& spec, const CancelToken& cancel);

} // namespace bladeaxis::job
