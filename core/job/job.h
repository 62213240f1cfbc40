#pragma once
// The one entry point of BladeAxis: the GUI and `--batch` both build a JobSpec, call runJob
// and present the JobResult, so they give identical results (docs/architecture.md, Conventions).

#include "core/analysis/analysis.h"
#include "core/analysis/lost_motion.h"
#include "core/base/error.h"
#include "core/base/progress.h"
#include "core/compare/compare.h"
#include "core/io/program.h"
#include "core/job/cad_check.h"
#include "core/job/program_check.h"
#include "core/job/reschedule.h"
#include "core/kinematics/interpolation_deviation.h"
#include "core/kinematics/machine_model.h"
#include "core/report/schedule_report.h"
#include "core/scheduling/schedule_parameters.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace bladeaxis::job {

enum class ResultDetail { Figures, PerSample };

struct JobSpec {
    std::filesystem::path program; // input NC or CL file; ignored when demo is set
    // The program's bytes when they do not come from the file `program` names (standard input
    // in a pipe): `program` then only names it in messages.
    std::optional<std::string> programText;
    bool demo = false;                 // run on the built-in demo blade program instead
    std::filesystem::path machineFile; // empty: the built-in default blade machine
    std::optional<double> toolRadius;  // mm; overrides the radius the program states
    io::ReadOptions read;              // angle unit, feed and table columns the file may not state
    // When a program counts as a four-axis blade pass (B tolerance, distance to the channel).
    ProgramCheckOptions check;
    analysis::AxisProfileOptions analysis;
    bool reschedule = true;     // false: analyse the input only (`--analyse-only`)
    bool compare = false;       // also run and evaluate every comparison method (`--compare`)
    bool sweepLimits = false;   // with compare: machining times with the rotary limits x0.5 ... x2
    bool compareOptimum = true; // with compare: the optimal schedules (slow on large programs)
    scheduling::ScheduleParameters parameters = scheduling::bestPreset();
    std::string presetName = "best"; // recorded in the report; "custom" once edited
    // The engineer's edits of single layers (the GUI's S-theta editor), saved with the job and
    // applied on every run; a key-point edit the layer's channel refuses fails the job.
    std::vector<scheduling::LayerOverride> layerEdits;
    std::filesystem::path outputProgram; // the re-scheduled program; empty: not written
    std::filesystem::path outputCl;      // the re-scheduled toolpath as CL data (APT); empty: none
    CadCheckSpec cad; // blade CAD for the clearance check (the demo uses its own surface)
    std::filesystem::path outputDir; // report.json, axes.csv (and the demo program); empty: none
    std::filesystem::path jobFile;   // the job file this spec was read from, if any
    // What the caller reads of the result besides the outputs named above: the figures alone
    // (the batch front end, which writes its outputs and ends) or every per-sample array too
    // (the window's plots, editor and export; the API). The job keeps what this and the named
    // outputs need (retentionOf) and frees the rest once read for the last time.
    ResultDetail detail = ResultDetail::PerSample;
};

// What a job keeps of what its stages make, decided once from its spec: per-sample data that
// no asked-for output reads goes as soon as the figures are taken from it.
Retention retentionOf(const JobSpec& spec);

// The part of the program that is analysed: the longest run of consecutive feed records (the
// helical cutting pass); rapids and short feed moves around it are counted but not analysed.
struct CuttingPass {
    std::size_t first = 0;
    std::size_t count = 0;
    bool toolTip = false; // programmed as the tool tip in the workpiece frame (TRAORI, M128)
};

struct JobResult {
    kinematics::MachineModel machine;
    io::LoadedProgram program;
    std::optional<double> toolRadius; // mm, from the spec or the file
    CuttingPass pass;
    // Per record of the pass, A continuous; shared with the original profile, which reads its
    // positions from them. Null once the input's figures are taken, unless kept.inputSamples.
    analysis::SharedMachineAxes axes;
    analysis::AxisProfile original;
    analysis::ConstantFeedTime constantFeed;
    // T2 under the machine limits (spec §8.3), grid-converged: the look-ahead controller model.
    std::optional<analysis::ConvergedTime> timeOptimal;
    // The block-by-block controller model (LinuxCNC 2.9's planner on rotary blocks).
    analysis::BlockPlannerTime blockByBlock;
    // How far the ball centre strays from the chord between the input's points as its axes
    // interpolate (none without a tool radius).
    std::optional<kinematics::InterpolationDeviation> originalInterpolation;
    // Per layer of the re-scheduled pass, the input's motion (report::layerAxisMotion), taken as
    // soon as the layers were known; empty without a re-scheduling.
    std::vector<report::LayerAxisMotion> layerMotionBefore;
    // The input's lost motion on the machine's axes with backlash, taken with its analysis.
    std::vector<analysis::LostMotion> originalLostMotion;
    std::optional<RescheduleOutcome> rescheduled;  // when spec.reschedule
    std::optional<compare::Comparison> comparison; // when spec.compare
    std::optional<CadCheckResult> cadCheck;        // when CAD is given, and for the demo
    std::vector<std::string> warnings;
    double seconds = 0.0; // wall time of runJob
    Retention kept;       // what of the per-sample data the job kept (retentionOf its spec)

    // The input text (the demo program when generated); held once, by the parsed document.
    // A re-scheduling consumes it unless kept.inputTextAfterRewrite (a demo job keeps it for
    // demo_blade.nc).
    const std::string& programText() const { return program.text(); }
};

// The spec's machine file, or the built-in default blade machine. A missing or invalid file is
// ErrorCode::MachineFile.
Result<kinematics::MachineModel> loadMachine(const JobSpec& spec);

// Errors carry file:line diagnostics of the input; see app/batch/exit_codes.h for their mapping
// to process exit codes.
Result<JobResult> runJob(const JobSpec& spec, ProgressSink& progress, const CancelToken& cancel);

// The same, calling `originalReady` (on the job's thread) as soon as the program is read and its
// original motion analysed, before the re-scheduling: the GUI shows the program in 3D while the
// rest of the job runs. The original's T2 (timeOptimal) is not in that partial result yet: it is
// computed beside the re-scheduling.
using OriginalReadyHook = std::function<void(const JobResult& partial)>;
Result<JobResult> runJob(const JobSpec& spec, ProgressSink& progress, const CancelToken& cancel,
                         const OriginalReadyHook& originalReady);

// The comparison's name of the engineer's edited schedule (what Export writes once a layer is
// edited); without edits, the job's schedule is the comparison's "stheta-best".
inline constexpr const char* kEditedMethod = "edited";

// With layer edits and a comparison: the edited schedule as one more method of the comparison,
// evaluated exactly like the others (replacing an earlier "edited" row). A job with --compare
// does it; the window calls it after a re-run for an edit, which keeps the comparison it had.
Status appendEditedMethod(JobResult& result, const JobSpec& spec);

// The files a job reads, which no output may replace (also through links).
std::vector<std::filesystem::path> protectedInputsOf(const JobSpec& spec);

// Writes the re-scheduled program to spec.outputProgram (moving a staged one into place), and
// report.json, axes.csv and layers.csv (and demo_blade.nc for a demo job; compare.json, compare.csv
// and report.html for a comparison) into spec.outputDir, each atomically; refuses to overwrite the
// input program. All are published or none (see OutputSet): every file is staged first, then
// moved into place; an output folder the call created is removed again when it fails. With
// `cancel`, a cancel requested by the time every file is staged writes nothing (Cancelled).
Status writeJobOutputs(const JobSpec& spec, const JobResult& result,
                       const CancelToken* cancel = nullptr);

// Per layer of the re-scheduled pass: A reversals and peak A velocity/acceleration before and
// after (the figures of report.json's layers); empty without a re-scheduling.
std::vector<report::LayerMotion> layerMotionOf(const JobResult& result);

// The whole toolpath with the re-scheduled cutting pass, as CL data (APT GOTO/x,y,z,i,j,k in
// mm): what CAM verifiers and other post-processors read. Needs a re-scheduling.
Result<std::string> rescheduledClText(const JobResult& result);

// The content of report.json (also printed by `--batch --json`).
std::string reportJsonText(const JobResult& result, const JobSpec* spec = nullptr);

// The readable summary the batch front end prints.
std::string formatSummary(const JobResult& result);

// One line for a status bar: the machine's cycle-time model first, each time with its model's
// name ("block-by-block 108.2 -> 95.0 s (this machine), look-ahead T2 40.0 -> 27.2 s").
std::string cycleTimeStatus(const JobResult& result);

} // namespace bladeaxis::job
