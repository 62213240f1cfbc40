#include "core/job/reschedule.h"

#include "core/analysis/time_optimal.h"
#include "core/base/execution.h"
#include "core/base/free_storage.h"
#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/io/cl/apt.h"
#include "core/io/nc/gcode.h"
#include "core/job/rewrite_stage.h"
#include "core/kinematics/kinematics.h"
#include "core/kinematics/travel_limits.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>

namespace bladeaxis::job {

namespace {

using toolpath::ClRecord;

RescheduleOutcome outcomeFrom(scheduling::ScheduleResult schedule) {
    RescheduleOutcome outcome;
    outcome.minChannelClearanceRad = std::numeric_limits<double>::infinity();
    for (const auto& layer : schedule.layers) {
        const bool kept =
            std::find(layer.flags.begin(), layer.flags.end(),
                      scheduling::LayerStatus::MonotoneInfeasible) != layer.flags.end();
        outcome.layersKeptOriginal += kept ? 1 : 0;
        if (!kept) {
            outcome.minChannelClearanceRad =
                std::min(outcome.minChannelClearanceRad, layer.minClearance);
        }
    }
    outcome.schedule = std::move(schedule);
    return outcome;
}

// The new program's axis motion and its machining times (T1 at constant feed, T2 under the
// machine's limits).
struct NewMotion {
    analysis::AxisProfile profile;
    analysis::ConstantFeedTime constantFeed;
    std::optional<analysis::ConvergedTime> timeOptimal;
    analysis::BlockPlannerTime blockByBlock;
    kinematics::InterpolationDeviation interpolation;
};

// Runs beside the rewrite and the re-read check: a cancelled job waits for it before it ends,
// so it stops between its stages too. Without input.keep.newToolAxes the schedule's new tool
// axes are freed once the analysis has read the poses: the re-read check beside it never reads
// them.
Result<NewMotion> analyseNewMotion(const RescheduleInput& input, RescheduleOutcome& outcome,
                                   const CancelToken& cancel) {
    analysis::PathSamples samples = rescheduledSamples(input.pass.records(), outcome);
    if (!input.keep.newToolAxes) {
        samples.posesRead = [&newAxes = outcome.schedule.newAxes] { freeStorage(newAxes); };
    }
    analysis::AxisProfileOptions options = input.analysis;
    options.cancel = &cancel;
    auto profile = analysis::analyseAxisMotion(outcome.axes, samples, options);
    if (!profile) {
        return std::unexpected(profile.error());
    }
    if (auto status = checkCancelled(cancel); !status) {
        return std::unexpected(status.error());
    }
    const kinematics::MachineModel& machine = *input.pass.machine;
    NewMotion motion{std::move(*profile), {}, std::nullopt, {}, {}};
    motion.constantFeed = analysis::constantFeedTime(motion.profile, machine, false);
    if (auto status = checkCancelled(cancel); !status) {
        return std::unexpected(status.error());
    }
    motion.blockByBlock = analysis::blockByBlockTime(*outcome.axes, samples, machine);
    if (auto status = checkCancelled(cancel); !status) {
        return std::unexpected(status.error());
    }
    motion.interpolation = kinematics::interpolationDeviation(*outcome.axes, machine.chain,
                                                              outcome.toolRadius, 3, &cancel);
    if (auto status = checkCancelled(cancel); !status) {
        return std::unexpected(status.error());
    }
    motion.timeOptimal = analysis::convergedTimeOptimalOrNone(motion.profile, machine, &cancel);
    if (auto status = checkCancelled(cancel); !status) { // T2 cut short: none, not a figure
        return std::unexpected(status.error());
    }
    return motion;
}

// Seconds since the previous lap (or construction).
class StageClock {
  public:
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double seconds = std::chrono::duration<double>(now - m_last).count();
        m_last = now;
        return seconds;
    }

  private:
    std::chrono::steady_clock::time_point m_last = std::chrono::steady_clock::now();
};

Status checkOutcome(const RescheduleOutcome& outcome, const std::string& file) {
    if (!outcome.schedule.check.passes()) {
        return makeError(
            ErrorCode::CheckFailed,
            "reconstruction check failed: " + scheduling::describeFailures(outcome.schedule.check) +
                "; nothing was written (please report this program)",
            {file});
    }
    if (outcome.minChannelClearanceRad < -1e-9) {
        return makeError(ErrorCode::CheckFailed,
                         "the new tool orientation leaves the feasible channel by " +
                             formatFixed(units::radToDeg(-outcome.minChannelClearanceRad), 4) +
                             " deg",
                         {file});
    }
    if (outcome.maxCentreDeviationMm > kCentreDeviationLimitMm) {
        return makeError(ErrorCode::CheckFailed,
                         "ball centres of the written program deviate by " +
                             formatFixed(outcome.maxCentreDeviationMm, 6) +
                             " mm from the input's here (limit " +
                             formatShortest(kCentreDeviationLimitMm) +
                             " mm); nothing was written. The usual cause is axis words with too "
                             "few decimals to hold the new ball centres: post the program with "
                             "at least 3 decimals",
                         {file, outcome.maxCentreDeviationLine, 0});
    }
    return {};
}

// §6.4: a modulo A axis moves the shortest way to each programmed angle, so a block whose A
// step reaches half a turn would rotate backwards (or either way). The continuous A of the new
// program must therefore step by less than 180 deg per block; a reversing half-turn in one
// block is never what the schedule meant.
Status checkModuloSteps(const RescheduleInput& input, const RescheduleOutcome& outcome) {
    if (input.pass.machine->aMode != kinematics::RotaryMode::Modulo) {
        return {};
    }
    constexpr double kHalfTurnRad = units::kPi - 1e-6;
    const std::vector<kinematics::MachineAxes>& axes = *outcome.axes;
    for (std::size_t i = 1; i < axes.size(); ++i) {
        const double step = std::abs(axes[i].a - axes[i - 1].a);
        if (step >= kHalfTurnRad) {
            const std::string table(1, input.pass.machine->letter(kinematics::AxisId::A));
            return makeError(
                ErrorCode::CheckFailed,
                "the re-scheduled " + table + " steps by " + formatFixed(units::radToDeg(step), 3) +
                    " deg in one block: a modulo " + table + " axis would turn the short way",
                {input.pass.program->path().sourceFile, input.pass.records()[i].line, 0});
        }
    }
    return {};
}

// The written program must stay inside the machine's travel: a new orientation moves the linear
// axes too (the ball centre is kept, the pivot is not), so a program inside its travel can be
// re-scheduled out of it.
Status checkTravel(const RescheduleInput& input, const RescheduleOutcome& outcome) {
    const kinematics::MachineModel& machine = *input.pass.machine;
    const auto excess = kinematics::firstTravelExcess(*outcome.axes, machine);
    if (!excess) {
        return {};
    }
    return makeError(
        ErrorCode::CheckFailed,
        "the re-scheduled block would drive " + kinematics::describe(*excess, machine) +
            " of the machine '" + machine.name +
            "'; nothing was written. Check that the machine file is the machine the "
            "program runs on and that the program's zero is where the machine "
            "expects it, or narrow the channel (--margin-deg) so the tool tilts less",
        {input.pass.program->path().sourceFile, input.pass.records()[excess->index].line, 0});
}

} // namespace

bool passIsBlockTimed(const io::LoadedProgram& program, std::size_t first, std::size_t count) {
    const auto* gcode = std::get_if<io::nc::GcodeProgram>(&program.document);
    if (gcode == nullptr) {
        return false;
    }
    for (std::size_t i = first; i < first + count && i < gcode->sources.size(); ++i) {
        if ((gcode->sources[i].flags & (io::nc::kInverseTime | io::nc::kCombinedFeed)) != 0) {
            return true;
        }
    }
    return false;
}

Result<std::string> RescheduleOutcome::writtenText() const {
    if (!stagedProgram) {
        return programText;
    }
    auto mapped = stagedProgram->mapText();
    if (!mapped) {
        return std::unexpected(mapped.error());
    }
    return std::string(mapped->text());
}

std::vector<toolpath::ClRecord> rescheduledRecords(std::span<const ClRecord> pass,
                                                   const scheduling::ScheduleResult& schedule,
                                                   double toolRadius,
                                                   std::span<const double> feeds) {
    std::vector<ClRecord> records(pass.begin(), pass.end());
    const analysis::PathSamples samples = rescheduledSamples(pass, schedule, toolRadius, feeds);
    for (std::size_t i = 0; i < records.size(); ++i) {
        records[i].tip = samples.tip(i);
        records[i].axis = samples.toolAxis(i);
        records[i].feed = samples.feed(i);
        records[i].axes.reset();
    }
    return records;
}

std::vector<toolpath::ClRecord> rescheduledRecords(std::span<const ClRecord> pass,
                                                   const RescheduleOutcome& outcome) {
    return rescheduledRecords(pass, outcome.schedule, outcome.toolRadius, outcome.passFeeds);
}

analysis::PathSamples rescheduledSamples(std::span<const ClRecord> pass,
                                         const scheduling::ScheduleResult& schedule,
                                         double toolRadius, std::span<const double> feeds) {
    return {.records = pass,
            .toolAxes = schedule.newAxes,
            .keptCentreRadius = toolRadius,
            .feeds = feeds};
}

analysis::PathSamples rescheduledSamples(std::span<const ClRecord> pass,
                                         const RescheduleOutcome& outcome) {
    return rescheduledSamples(pass, outcome.schedule, outcome.toolRadius, outcome.passFeeds);
}

namespace {

// The new motion's analysis runs beside the rewrite and the re-read check, which use one thread.
// Its feeds are the input's unless the pass is block-timed (G93), where the same F over a new
// tip chord is a new tip speed: then it waits for the written program's feeds. When the rewrite
// consumes the input's text it starts after it: the profile it makes (about 110 bytes per
// record while it runs) would otherwise stand beside the input's text and the written one at the
// rewrite's end, where a job's memory peaks (a million-block job: 670-690 MB beside the rewrite,
// 593-614 MB after it).
enum class AnalysisStart { BesideRewrite, AfterRewrite, AfterReadBack };

AnalysisStart analysisStartOf(const RescheduleInput& input) {
    if (input.analysis.blockTimes) {
        return AnalysisStart::AfterReadBack;
    }
    return input.keep.inputTextAfterRewrite ? AnalysisStart::BesideRewrite
                                            : AnalysisStart::AfterRewrite;
}

// The written program into the outcome (empty when staged).
Status writeInto(const RescheduleInput& input, RescheduleOutcome& outcome, StageClock& clock,
                 ProgressShare& progress, const CancelToken& cancel) {
    progress.report(0.35, "writing the re-scheduled program");
    const RewriteTarget target{.staged = input.stagedProgram.get(),
                               .keepInputText = input.keep.inputTextAfterRewrite};
    auto text = rewriteProgram(input.pass, *outcome.axes, outcome.schedule, target, cancel);
    if (!text) {
        return std::unexpected(text.error());
    }
    outcome.programText = std::move(*text);
    outcome.stagedProgram = input.stagedProgram;
    outcome.stageSeconds.rewrite = clock.lap();
    return checkCancelled(cancel);
}

Status readBackInto(const RescheduleInput& input, RescheduleOutcome& outcome, StageClock& clock,
                    ProgressShare& progress, const CancelToken& cancel) {
    progress.report(0.68, "reading the written program back to check it");
    const bool feedsFromWritten = input.analysis.blockTimes;
    auto written = readBackWritten(input.pass, outcome.programText, outcome.stagedProgram.get(),
                                   feedsFromWritten, cancel);
    outcome.stageSeconds.verify = clock.lap();
    if (!written) {
        return std::unexpected(written.error());
    }
    outcome.maxCentreDeviationMm = written->maxCentreDeviationMm;
    outcome.maxCentreDeviationLine = written->maxCentreDeviationLine;
    if (feedsFromWritten) {
        outcome.passFeeds = std::move(written->passFeeds);
    }
    return {};
}

Status checkWritten(const RescheduleInput& input, const RescheduleOutcome& outcome) {
    if (auto status = checkOutcome(outcome, input.pass.program->path().sourceFile); !status) {
        return status;
    }
    if (auto status = checkModuloSteps(input, outcome); !status) {
        return status;
    }
    return checkTravel(input, outcome);
}

void takeNewMotion(RescheduleOutcome& outcome, NewMotion motion) {
    outcome.profile = std::move(motion.profile);
    outcome.constantFeed = motion.constantFeed;
    outcome.timeOptimal = motion.timeOptimal;
    outcome.blockByBlock = motion.blockByBlock;
    outcome.interpolation = motion.interpolation;
}

} // namespace

Result<RescheduleOutcome> reschedule(scheduling::ScheduleResult schedule,
                                     const RescheduleInput& input, ProgressShare& progress,
                                     const CancelToken& cancel) {
    StageClock clock;
    RescheduleOutcome outcome = outcomeFrom(std::move(schedule));
    outcome.toolRadius = input.pass.toolRadius;
    progress.report(0.28, "computing the new machine axes");
    auto axes = newMachineAxes(input.pass, outcome.schedule, cancel);
    if (!axes) {
        return std::unexpected(axes.error());
    }
    outcome.axes = std::make_shared<const std::vector<kinematics::MachineAxes>>(std::move(*axes));
    outcome.stageSeconds.kinematics = clock.lap();
    if (auto status = checkCancelled(cancel); !status) {
        return std::unexpected(status.error());
    }
    // The future is declared after the outcome it writes to, so an early return waits for it.
    const AnalysisStart start = analysisStartOf(input);
    std::future<Result<NewMotion>> analysed;
    const auto startAnalysis = [&](std::launch policy) {
        analysed = runAsync(policy, [&] { return analyseNewMotion(input, outcome, cancel); });
    };
    if (start == AnalysisStart::BesideRewrite) {
        startAnalysis(std::launch::async);
    }
    if (auto status = writeInto(input, outcome, clock, progress, cancel); !status) {
        return std::unexpected(status.error());
    }
    if (start == AnalysisStart::AfterRewrite) {
        startAnalysis(std::launch::async);
    }
    if (auto status = readBackInto(input, outcome, clock, progress, cancel); !status) {
        return std::unexpected(status.error());
    }
    if (start == AnalysisStart::AfterReadBack) {
        startAnalysis(std::launch::deferred);
    }
    if (auto status = checkWritten(input, outcome); !status) {
        return std::unexpected(status.error());
    }
    progress.report(0.98, "analysing the new axis motion");
    auto motion = analysed.get();
    if (!motion) {
        return std::unexpected(motion.error());
    }
    takeNewMotion(outcome, std::move(*motion));
    outcome.stageSeconds.analysis = clock.lap(); // what the analysis added after the check
    return outcome;
}

} // namespace bladeaxis::job
