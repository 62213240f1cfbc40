// The job pipeline: read -> analyse the input -> schedule (plane path, layers, layer schedules)
// -> new machine axes -> rewrite -> read back and analyse the new motion -> CAD check and
// comparison. Each stage takes values and returns values; what the job keeps of them is decided
// once (retentionOf), and this file is where anything a later stage no longer reads is freed
// (docs/architecture.md, "Lifetime").

#include "core/analysis/time_optimal.h"
#include "core/base/execution.h"
#include "core/base/free_storage.h"
#include "core/base/memory_policy.h"
#include "core/job/job.h"
#include "core/job/job_stages.h"
#include "core/job/output_paths.h"
#include "core/job/progress_share.h"
#include "core/job/tool_radius.h"
#include "core/report/schedule_report.h"

#include <chrono>
#include <future>

namespace bladeaxis::job {

namespace {

using InputT2 = std::future<std::optional<analysis::ConvergedTime>>;

// The input's T2 into the result, unless already there.
void waitForInputT2(JobResult& result, InputT2& timeOptimal) {
    if (timeOptimal.valid()) {
        result.timeOptimal = timeOptimal.get();
    }
}

// What the input's per-sample motion is reduced to once its figures are taken: the A of each
// record, for the layers' reversals (the re-scheduling starts from A's first value). Its T2 reads
// no positions.
std::vector<double> releaseInputSamples(JobResult& result, bool keepA) {
    std::vector<double> a;
    if (keepA) {
        a.reserve(result.axes->size());
        for (const kinematics::MachineAxes& axes : *result.axes) {
            a.push_back(axes.a);
        }
    }
    result.axes.reset();
    result.original.recordAxes.reset();
    return a;
}

// The input's figures that stay once its samples go, taken where the job is at its lowest: the
// scheduling grows from here.
struct InputAtScheduling {
    std::vector<double> passA; // when the input's machine axes were released
    InputT2 timeOptimal;       // running since the input was analysed
};

// Once the layers are known, before they are scheduled: the input's motion per layer, the last
// reading of the input profile's derivatives. A job that does not keep them waits for the
// input's T2 (the other reader) and frees them here, before the scheduling's memory peaks.
void takeInputLayerMotion(JobResult& result, std::span<const scheduling::LayerBounds> layers,
                          InputAtScheduling& input) {
    result.layerMotionBefore = result.axes
                                   ? report::layerAxisMotion(layers, result.original, *result.axes)
                                   : report::layerAxisMotion(layers, result.original, input.passA);
    freeStorage(input.passA);
    if (!result.kept.inputSamples) {
        waitForInputT2(result, input.timeOptimal);
        result.original.releaseSampleData();
        returnFreedHeapToTheSystem();
    }
}

std::span<const toolpath::ClRecord> passRecords(const JobResult& result) {
    return std::span(result.program.path().records).subspan(result.pass.first, result.pass.count);
}

// The three scheduling stages with the job's work between them. On five million blocks the
// input's T2 arrays (16-24 bytes per sample) beside the tangents and curvature took the peak above
// 1.5 GB when T2 was slow: a job that does not keep the input's samples waits for it once the
// plane path is made.
Result<scheduling::ScheduleResult> scheduleStage(JobResult& result, const JobSpec& spec,
                                                 InputAtScheduling& input,
                                                 const CancelToken& cancel) {
    const scheduling::ScheduleSamples samples =
        scheduleSamplesOf(passRecords(result), *result.toolRadius);
    auto path = scheduling::makePlanePath(samples, spec.parameters);
    if (!path) {
        return std::unexpected(path.error());
    }
    if (!result.kept.inputSamples) {
        waitForInputT2(result, input.timeOptimal);
    }
    if (auto status = checkCancelled(cancel); !status) {
        return std::unexpected(status.error());
    }
    auto plan = scheduling::planLayers(std::move(*path), samples, spec.parameters, &cancel);
    if (!plan) {
        return std::unexpected(plan.error());
    }
    takeInputLayerMotion(result, plan->bounds, input);
    return scheduling::scheduleLayers(std::move(*plan), samples, spec.parameters, &cancel,
                                      spec.layerEdits);
}

// The input's orientation against the layers' channels, the last reading of the layers' curves
// unless kept.
Status checkScheduledLayers(const JobResult& result, const JobSpec& spec,
                            scheduling::ScheduleResult& schedule) {
    Status orientation =
        checkOrientationInChannel(schedule, passRecords(result), result.program.path().sourceFile,
                                  spec.check, rotaryLetters(result.machine));
    if (!result.kept.layerCurves) {
        scheduling::releaseLayerSamples(schedule);
        returnFreedHeapToTheSystem(); // a layer's curves are small blocks the C library keeps
    }
    return orientation;
}

Result<std::shared_ptr<StagedFile>> stagedProgramOf(const JobSpec& spec, const Retention& keep) {
    if (keep.writtenText) {
        return nullptr;
    }
    auto staged = StagedFile::open(spec.outputProgram, protectedInputsOf(spec));
    if (!staged) {
        return std::unexpected(staged.error());
    }
    return std::make_shared<StagedFile>(std::move(*staged));
}

RescheduleInput rescheduleInputOf(JobResult& result, const JobSpec& spec,
                                  const InputAtScheduling& input) {
    RescheduleInput reschedule;
    reschedule.pass = {.program = &result.program,
                       .machine = &result.machine,
                       .passFirst = result.pass.first,
                       .passCount = result.pass.count,
                       .toolTip = result.pass.toolTip,
                       .startA = result.axes ? result.axes->front().a : input.passA.front(),
                       .toolRadius = *result.toolRadius};
    reschedule.keep = result.kept;
    reschedule.analysis = spec.analysis;
    reschedule.analysis.toolRadius = *result.toolRadius;
    reschedule.analysis.filterSeriesBytesAtOnce = kFilterSeriesBytesAtOnce;
    reschedule.analysis.blockTimes =
        passIsBlockTimed(result.program, result.pass.first, result.pass.count);
    return reschedule;
}

Status rescheduleInto(JobResult& result, const JobSpec& spec, ProgressSink& progress,
                      InputAtScheduling& input, const CancelToken& cancel) {
    if (!result.toolRadius || !(*result.toolRadius > 0.0)) {
        return makeError(ErrorCode::InvalidArgument,
                         "the ball radius is not known: give --tool-radius (" +
                             radiusSourceHint(result.program.format()) + ")",
                         {result.program.path().sourceFile});
    }
    RescheduleInput reschedule = rescheduleInputOf(result, spec, input);
    auto staged = stagedProgramOf(spec, result.kept);
    if (!staged) {
        return std::unexpected(staged.error());
    }
    reschedule.stagedProgram = std::move(*staged);
    ProgressShare share(progress, 0.5, 0.65);
    share.report(0.0, "re-scheduling the tool orientation");
    const auto start = std::chrono::steady_clock::now();
    auto schedule = scheduleStage(result, spec, input, cancel);
    if (!schedule) {
        Error error = schedule.error();
        if (error.where.empty()) {
            error.where = {result.program.path().sourceFile};
        }
        return std::unexpected(error);
    }
    // Its refusal comes after the re-scheduling's own.
    const Status orientationInChannel = checkScheduledLayers(result, spec, *schedule);
    const double scheduleSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (auto status = checkCancelled(cancel); !status) {
        return std::unexpected(status.error());
    }
    auto outcome = job::reschedule(std::move(*schedule), reschedule, share, cancel);
    if (!outcome) {
        return std::unexpected(outcome.error());
    }
    outcome->stageSeconds.schedule = scheduleSeconds;
    result.rescheduled = std::move(*outcome);
    if (!orientationInChannel) {
        return orientationInChannel;
    }
    for (const std::string& warning : result.rescheduled->schedule.warnings) {
        progress.warning(warning);
        result.warnings.push_back(warning);
    }
    return {};
}

// The input once analysed: reduced to the A of each record unless its samples are kept, and its
// T2 started beside the rest of the job (it reads only the input's profile, which nothing
// changes from here on).
InputAtScheduling handOverInput(JobResult& result, const JobSpec& spec, const CancelToken& cancel) {
    InputAtScheduling input;
    if (!result.kept.inputSamples) {
        input.passA = releaseInputSamples(result, spec.reschedule);
    }
    input.timeOptimal = runAsync([&result, &cancel] {
        return analysis::convergedTimeOptimalOrNone(result.original, result.machine, &cancel);
    });
    return input;
}

// The stages up to the input's analysis; `generatedRadius` is the demo program's.
Result<JobResult> readStage(const JobSpec& spec, const Retention& keep, ProgressSink& progress,
                            const CancelToken& cancel) {
    progress.progress(0.0, "loading the machine");
    auto machine = loadMachine(spec);
    if (!machine) {
        return std::unexpected(machine.error());
    }
    const std::string_view readingStage =
        spec.demo ? "generating the demo blade program" : "reading the program";
    ProgressShare reading(progress, 0.05, 0.3);
    reading.report(0.0, readingStage);
    const io::ReadWatch watch{.cancel = &cancel,
                              .progress = [&](double read) { reading.report(read, readingStage); }};
    std::optional<double> generatedRadius;
    auto program = loadInput(spec, keep, *machine, generatedRadius, watch);
    if (!program) {
        return std::unexpected(program.error());
    }
    if (auto status = checkCancelled(cancel); !status) {
        return std::unexpected(status.error());
    }
    JobResult result;
    result.machine = std::move(*machine);
    result.program = std::move(*program);
    result.kept = keep;
    result.warnings = result.program.path().warnings;
    if (auto status =
            checkStatedCutter(result.program, spec.toolRadius, spec.reschedule, result.warnings);
        !status) {
        return std::unexpected(status.error());
    }
    result.toolRadius = jobToolRadius(spec, generatedRadius, result.program, result.warnings);
    if (auto status = checkToolRadius(result.toolRadius, result.program.path()); !status) {
        return std::unexpected(status.error());
    }
    for (const std::string& warning : result.warnings) {
        progress.warning(warning);
    }
    return result;
}

Status analyseStage(JobResult& result, const JobSpec& spec, ProgressSink& progress,
                    const CancelToken& cancel) {
    progress.progress(0.3, "analysing the original axis motion");
    const std::size_t warningsBeforeAnalysis = result.warnings.size();
    if (auto status = analyse(result, spec, cancel); !status) {
        return status;
    }
    // Now, not only in the summary: a refused output prints no summary.
    for (std::size_t i = warningsBeforeAnalysis; i < result.warnings.size(); ++i) {
        progress.warning(result.warnings[i]);
    }
    return {};
}

// The CAD check and the comparison, which read the job's samples once it has run.
Status evaluateStage(JobResult& result, const JobSpec& spec,
                     const std::optional<CadCheckSpec>& cadSpec, ProgressSink& progress,
                     const CancelToken& cancel) {
    if (cadSpec) {
        progress.progress(0.65, spec.demo && spec.cad.file.empty()
                                    ? "checking the tool against the demo blade's surface"
                                    : "checking the tool against the blade CAD");
        if (auto status = cadCheckInto(result, spec, *cadSpec, progress); !status) {
            return status;
        }
    }
    if (!spec.compare) {
        return {};
    }
    progress.progress(0.7, "comparing with the other methods");
    if (auto status = compareInto(result, spec, cancel); !status) {
        return status;
    }
    return appendEditedMethod(result, spec);
}

Result<std::optional<CadCheckSpec>> cadSpecOf(const JobSpec& spec, const JobResult& result) {
    if (!checksCad(spec)) {
        return std::nullopt;
    }
    auto checked = cadCheckSpec(spec, result.toolRadius);
    if (!checked) {
        return std::unexpected(checked.error());
    }
    return std::optional<CadCheckSpec>(std::move(*checked));
}

} // namespace

Retention retentionOf(const JobSpec& spec) {
    const bool figuresOnly = spec.detail == ResultDetail::Figures;
    // The comparison, the CAD check, axes.csv and layers.csv read the samples after the figures
    // are taken; a CL output reads the new tool axes.
    const bool samplesRead =
        !figuresOnly || spec.compare || checksCad(spec) || !spec.outputDir.empty();
    const bool stagesProgram =
        figuresOnly && !spec.outputProgram.empty() && StagedFile::isStageable(spec.outputProgram);
    return {.inputTextInMemory = !figuresOnly || spec.demo,
            .inputTextAfterRewrite = spec.demo, // demo_blade.nc
            .inputSamples = samplesRead,
            .layerCurves = samplesRead,
            .newToolAxes = samplesRead || !spec.outputCl.empty(),
            .writtenText = !stagesProgram};
}

Result<JobResult> runJob(const JobSpec& spec, ProgressSink& progress, const CancelToken& cancel) {
    return runJob(spec, progress, cancel, {});
}

Result<JobResult> runJob(const JobSpec& spec, ProgressSink& progress, const CancelToken& cancel,
                         const OriginalReadyHook& originalReady) {
    // The job's execution context: every parallel loop of its stages, and every task it starts
    // (runAsync), runs on the job's thread count.
    ThreadCountScope threads(spec.parameters.threads);
    const auto start = std::chrono::steady_clock::now();
    // Before anything runs: outputs that would overwrite each other or an input.
    if (auto refused = refuseSharedPaths(spec); !refused) {
        return std::unexpected(refused.error());
    }
    auto read = readStage(spec, retentionOf(spec), progress, cancel);
    if (!read) {
        return read;
    }
    JobResult& result = *read;
    auto cadSpec = cadSpecOf(spec, result);
    if (!cadSpec) {
        return std::unexpected(cadSpec.error());
    }
    if (auto status = analyseStage(result, spec, progress, cancel); !status) {
        return std::unexpected(status.error());
    }
    // Declared after the result, whose input it reads: an early return waits for its T2 first.
    InputAtScheduling input = handOverInput(result, spec, cancel);
    if (originalReady) {
        originalReady(result);
    }
    if (auto status = checkCancelled(cancel); !status) {
        return std::unexpected(status.error());
    }
    if (auto status = checkTilt(result, spec, progress); !status) {
        return std::unexpected(status.error());
    }
    if (spec.reschedule) {
        if (auto status = rescheduleInto(result, spec, progress, input, cancel); !status) {
            return std::unexpected(status.error());
        }
    }
    waitForInputT2(result, input.timeOptimal);
    // A T2 cut short by the token is none, not a path the limits cannot move along.
    if (auto status = checkCancelled(cancel); !status) {
        return std::unexpected(status.error());
    }
    if (auto status = evaluateStage(result, spec, *cadSpec, progress, cancel); !status) {
        return std::unexpected(status.error());
    }
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    progress.progress(1.0, "done");
    return read;
}

} // namespace bladeaxis::job
