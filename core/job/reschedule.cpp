#include "core/job/reschedule.h"

#include "core/analysis/time_optimal.h"
#include "core/base/free_storage.h"
#include "core/base/number_io.h"
#include "core/base/units.h"
#include "core/io/cl/apt.h"
#include "core/io/nc/gcode.h"
#include "core/kinematics/kinematics.h"
#include "core/kinematics/travel_limits.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>

namespace bladeaxis::job {

namespace {

using toolpath::ClRecord;

std::span<const ClRecord> passOf(const RescheduleInput& input) {
    return std::span(input.program->path().records).subspan(input.passFirst, input.passCount);
}

// The pass as the scheduling reads it: every centre and axis from its record, when needed, so
// that no copy of them stands beside the plane path (48 bytes per record).
scheduling::ScheduleInput scheduleInputOf(const RescheduleInput& input) {
    scheduling::ScheduleInput schedule;
    schedule.toolRadius = input.toolRadius;
    const std::span<const ClRecord> pass = passOf(input);
    schedule.centreAgain = [pass, radius = input.toolRadius](std::size_t i) {
        return toolpath::ballCentre(pass[i], radius);
    };
    schedule.axisAgain = [pass](std::size_t i) { return pass[i].axis; };
    schedule.readCount = pass.size();
    schedule.planePathMade = input.planePathMade;
    schedule.layersSplit = input.layersSplit;
    return schedule;
}

// IK of the new poses with A unwrapped from the original A of the first record, so the new
// program starts where the old one did and A stays continuous.
Result<std::vector<kinematics::MachineAxes>> newMachineAxes(const RescheduleInput& input,
                                                            const RescheduleOutcome& outcome,
                                                            const CancelToken& cancel) {
    const analysis::PathSamples samples = rescheduledSamples(passOf(input), outcome);
    // The poses are made as the IK reads them: an array of them (48 bytes per record) would
    // stand beside the schedule and the new axes, where read-schedule-write's memory peaks.
    const auto poseAt = [&samples](std::size_t i) {
        return kinematics::ToolPose{samples.tip(i), samples.toolAxis(i)};
    };
    auto solved =
        kinematics::inverseKinematicsAlong(input.machine->chain, samples.size(), poseAt,
                                           input.startA, input.parameters.threads, &cancel);
    if (solved.cancelled) {
        return std::unexpected(checkCancelled(cancel).error()); // the job's own Cancelled
    }
    if (solved.failedIndex) {
        Error error = solved.failure;
        error.where = {input.program->path().sourceFile, passOf(input)[*solved.failedIndex].line,
                       0};
        return std::unexpected(error);
    }
    return std::move(solved.axes);
}

Result<std::string> rewriteProgram(const RescheduleInput& input, const RescheduleOutcome& outcome,
                                   const CancelToken& cancel) {
    const std::span<const kinematics::MachineAxes> passAxes = *outcome.axes;
    const auto& all = input.program->path().records;
    io::nc::RewriteStreams streams;
    // Pages given back read as zeros: only a program released after the rewrite may lose them.
    if (input.rewritten) {
        streams.rewrittenUpTo = input.rewrittenUpTo;
    }
    // A staged program takes the G-code as it is written (keepWritten appends the rest).
    // Each piece (a few megabytes) is where a cancelled job stops writing: the staged file is
    // then discarded, as after any failure.
    if (input.stagedProgram) {
        streams.writtenPiece = [&staged = *input.stagedProgram, &cancel](std::string_view piece) {
            if (auto status = checkCancelled(cancel); !status) {
                return status;
            }
            return staged.append(piece);
        };
    }
    streams.textFile = input.program->textFile;
    if (const auto* gcode = std::get_if<io::nc::GcodeProgram>(&input.program->document)) {
        if (!io::programsToolTip(*input.program, input.passFirst, input.passCount)
                 .value_or(false)) {
            return io::nc::rewriteGcodePass(*gcode, input.passFirst, passAxes, *input.machine,
                                            streams);
        }
        // Tool-tip programming writes the tip in the workpiece frame, not the machine's X Y Z.
        std::vector<kinematics::MachineAxes> words(passAxes.begin(), passAxes.end());
        for (kinematics::MachineAxes& axes : words) {
            const Vec3 tip = kinematics::forwardKinematics(input.machine->chain, axes).tip;
            axes.x = tip.x();
            axes.y = tip.y();
            axes.z = tip.z();
        }
        return io::nc::rewriteGcodePass(*gcode, input.passFirst, words, *input.machine, streams);
    }
    std::vector<ClRecord> records = all;
    std::ranges::copy(rescheduledRecords(passOf(input), outcome),
                      records.begin() + static_cast<std::ptrdiff_t>(input.passFirst));
    io::toProgramFrame(records, *input.machine);
    if (const auto* table = std::get_if<io::table::TableProgram>(&input.program->document)) {
        return io::table::rewritePointTable(*table, records);
    }
    return io::cl::rewriteApt(std::get<io::cl::AptProgram>(input.program->document), records);
}

// The written program as read back: how far its ball centres are from the input's, and the
// tip feed of each pass record as the control will run it.
struct WrittenProgram {
    double maxCentreDeviationMm = 0.0;
    int maxCentreDeviationLine = 0;
    std::vector<double> passFeeds; // mm/s, when asked for (keepFeeds)
};

// The written text is read back as a stream: each record is compared with the input's as it
// is read and then dropped, so the check never holds a second program (about 140 bytes per
// record) beside the first.
Result<WrittenProgram> readBackWritten(const RescheduleInput& input, std::string_view text,
                                       bool keepFeeds, const io::nc::TextReadUpTo& readUpTo,
                                       const CancelToken& cancel) {
    const toolpath::Toolpath& original = input.program->path();
    const std::size_t passEnd = input.passFirst + input.passCount;
    WrittenProgram written;
    if (keepFeeds) {
        written.passFeeds.reserve(input.passCount);
    }
    const auto compare = [&](std::size_t first, std::span<const ClRecord> records) {
        const std::size_t begin = std::max(first, input.passFirst);
        const std::size_t end =
            std::min({first + records.size(), passEnd, original.records.size()});
        for (std::size_t i = begin; i < end; ++i) {
            const ClRecord& reread = records[i - first];
            const double deviation = (toolpath::ballCentre(reread, input.toolRadius) -
                                      toolpath::ballCentre(original.records[i], input.toolRadius))
                                         .norm();
            if (deviation > written.maxCentreDeviationMm) {
                written.maxCentreDeviationMm = deviation;
                written.maxCentreDeviationLine = original.records[i].line;
            }
            if (keepFeeds) {
                written.passFeeds.push_back(reread.feed);
            }
        }
        return checkCancelled(cancel); // every few thousand records
    };
    auto count = io::streamProgramRecords(text, original.sourceFile + " (re-scheduled)",
                                          input.program->format(), *input.machine,
                                          input.program->options, compare, readUpTo);
    if (!count && count.error().code == ErrorCode::Cancelled) {
        return std::unexpected(count.error());
    }
    if (!count) {
        Error error = count.error();
        error.code = ErrorCode::Internal;
        error.message = "the re-scheduled program does not read back: " + error.message;
        return std::unexpected(error);
    }
    if (*count != original.records.size()) {
        return makeError(ErrorCode::Internal, "the re-scheduled program has " +
                                                  std::to_string(*count) + " records, the input " +
                                                  std::to_string(original.records.size()));
    }
    return written;
}

// The written program from memory, or mapped from its staged file with its pages given back
// as the reader passes them (a shared file mapping reads dropped pages again from the file).
Result<WrittenProgram> readBackWritten(const RescheduleInput& input,
                                       const RescheduleOutcome& outcome, bool keepFeeds,
                                       const CancelToken& cancel) {
    if (!outcome.stagedProgram) {
        return readBackWritten(input, outcome.programText, keepFeeds, {}, cancel);
    }
    auto mapped = outcome.stagedProgram->mapText();
    if (!mapped) {
        return std::unexpected(mapped.error());
    }
    const io::nc::TextReadUpTo giveBack = [&mapped](std::size_t offset) {
        mapped->releaseBefore(offset);
    };
    return readBackWritten(input, mapped->text(), keepFeeds, giveBack, cancel);
}

// The written program goes into the outcome, or to the staged file when the job gives one: the
// rewrite has streamed G-code there already, other formats arrive whole and are freed here.
Status keepWritten(const RescheduleInput& input, std::string text, RescheduleOutcome& outcome) {
    if (!input.stagedProgram) {
        outcome.programText = std::move(text);
        return {};
    }
    if (auto staged = input.stagedProgram->append(text); !staged) {
        return staged;
    }
    freeStorage(text);
    outcome.stagedProgram = input.stagedProgram;
    return {};
}

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

// With input.releaseNewToolAxes the schedule's new tool axes are freed once the analysis has
// made its path parameter: the re-read check beside it never reads them.
// Runs beside the rewrite and the re-read check: a cancelled job waits for it before it ends,
// so it stops between its stages too.
Result<NewMotion> analyseNewMotion(const RescheduleInput& input, RescheduleOutcome& outcome,
                                   const CancelToken& cancel) {
    analysis::PathSamples samples = rescheduledSamples(passOf(input), outcome);
    if (input.releaseNewToolAxes) {
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
    NewMotion motion{std::move(*profile), {}, std::nullopt, {}, {}};
    motion.constantFeed = analysis::constantFeedTime(motion.profile, *input.machine, false);
    if (auto status = checkCancelled(cancel); !status) {
        return std::unexpected(status.error());
    }
    motion.blockByBlock = analysis::blockByBlockTime(*outcome.axes, samples, *input.machine);
    motion.interpolation =
        kinematics::interpolationDeviation(*outcome.axes, input.machine->chain, outcome.toolRadius);
    motion.timeOptimal =
        analysis::convergedTimeOptimalOrNone(motion.profile, *input.machine, &cancel);
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
    if (input.machine->aMode != kinematics::RotaryMode::Modulo) {
        return {};
    }
    constexpr double kHalfTurnRad = units::kPi - 1e-6;
    const std::vector<kinematics::MachineAxes>& axes = *outcome.axes;
    for (std::size_t i = 1; i < axes.size(); ++i) {
        const double step = std::abs(axes[i].a - axes[i - 1].a);
        if (step >= kHalfTurnRad) {
            const std::string table(1, input.machine->letter(kinematics::AxisId::A));
            return makeError(
                ErrorCode::CheckFailed,
                "the re-scheduled " + table + " steps by " + formatFixed(units::radToDeg(step), 3) +
                    " deg in one block: a modulo " + table + " axis would turn the short way",
                {input.program->path().sourceFile, passOf(input)[i].line, 0});
        }
    }
    return {};
}

// The written program must stay inside the machine's travel: a new orientation moves the linear
// axes too (the ball centre is kept, the pivot is not), so a program inside its travel can be
// re-scheduled out of it.
Status checkTravel(const RescheduleInput& input, const RescheduleOutcome& outcome) {
    const auto excess = kinematics::firstTravelExcess(*outcome.axes, *input.machine);
    if (!excess) {
        return {};
    }
    return makeError(ErrorCode::CheckFailed,
                     "the re-scheduled block would drive " +
                         kinematics::describe(*excess, *input.machine) + " of the machine '" +
                         input.machine->name +
                         "'; nothing was written. Check that the machine file is the machine the "
                         "program runs on and that the program's zero is where the machine "
                         "expects it, or narrow the channel (--margin-deg) so the tool tilts less",
                     {input.program->path().sourceFile, passOf(input)[excess->index].line, 0});
}

} // namespace

Status checkCancelled(const CancelToken& cancel) {
    if (cancel.isCancelled()) {
        return makeError(ErrorCode::Cancelled, "the job was cancelled");
    }
    return {};
}

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
                                                   const RescheduleOutcome& outcome) {
    std::vector<ClRecord> records(pass.begin(), pass.end());
    const analysis::PathSamples samples = rescheduledSamples(pass, outcome);
    for (std::size_t i = 0; i < records.size(); ++i) {
        records[i].tip = samples.tip(i);
        records[i].axis = samples.toolAxis(i);
        records[i].feed = samples.feed(i);
        records[i].axes.reset();
    }
    return records;
}

analysis::PathSamples rescheduledSamples(std::span<const ClRecord> pass,
                                         const RescheduleOutcome& outcome) {
    return {.records = pass,
            .toolAxes = outcome.schedule.newAxes,
            .keptCentreRadius = outcome.toolRadius,
            .feeds = outcome.passFeeds};
}

Result<RescheduleOutcome> reschedule(const RescheduleInput& input, const CancelToken& cancel) {
    if (!(input.toolRadius > 0.0)) {
        return makeError(ErrorCode::InvalidArgument,
                         "the ball radius is not known: give --tool-radius");
    }
    StageClock clock;
    const auto startStage = [&input](double done, std::string_view stage) {
        if (input.stageStarted) {
            input.stageStarted(done, stage);
        }
    };
    startStage(0.0, "re-scheduling the tool orientation");
    auto schedule =
        scheduling::schedule(scheduleInputOf(input), input.parameters, &cancel, input.layerEdits);
    if (!schedule) {
        Error error = schedule.error();
        if (error.where.empty()) {
            error.where = {input.program->path().sourceFile};
        }
        return std::unexpected(error);
    }
    RescheduleOutcome outcome = outcomeFrom(std::move(*schedule));
    outcome.toolRadius = input.toolRadius;
    if (input.scheduled) {
        input.scheduled(outcome.schedule);
    }
    outcome.stageSeconds.schedule = clock.lap();
    if (auto status = checkCancelled(cancel); !status) {
        return std::unexpected(status.error());
    }
    startStage(0.28, "computing the new machine axes");
    auto axes = newMachineAxes(input, outcome, cancel);
    if (!axes) {
        return std::unexpected(axes.error());
    }
    outcome.axes = std::make_shared<const std::vector<kinematics::MachineAxes>>(std::move(*axes));
    outcome.stageSeconds.kinematics = clock.lap();
    if (auto status = checkCancelled(cancel); !status) {
        return std::unexpected(status.error());
    }
    // The analysis describes the program actually written. Its feeds are the input's unless
    // the pass is in inverse time (G93), where the same F over a new tip chord is a new tip
    // speed: then the analysis waits for the written program's feeds. Otherwise it needs only
    // the new axes, and runs (with the machining times) beside the re-read check, which uses
    // one thread, and beside the rewrite too unless the input's text is released after it.
    // With the release it starts after the rewrite: the profile it makes (about 110 bytes per
    // record while it runs) would otherwise stand beside the input's text and the written one
    // at the rewrite's end, where a job's memory peaks (a million-block job: 670-690 MB
    // beside the rewrite, 593-614 MB after it, with the schedule's tips still kept).
    const bool feedsFromWritten = input.analysis.blockTimes;
    const bool analyseAtOnce = input.analyseNewMotion && !feedsFromWritten;
    const auto startAnalysis = [&] {
        return std::async(analyseAtOnce ? std::launch::async : std::launch::deferred,
                          [&] { return analyseNewMotion(input, outcome, cancel); });
    };
    std::future<Result<NewMotion>> analysed;
    if (!input.rewritten) {
        analysed = startAnalysis();
    }
    startStage(0.35, "writing the re-scheduled program");
    auto text = rewriteProgram(input, outcome, cancel);
    if (input.rewritten) {
        // Also after a failed rewrite, which may have given back part of the text already.
        input.rewritten();
    }
    if (!text) {
        return std::unexpected(text.error());
    }
    if (auto kept = keepWritten(input, std::move(*text), outcome); !kept) {
        return std::unexpected(kept.error());
    }
    if (input.rewritten) {
        analysed = startAnalysis();
    }
    outcome.stageSeconds.rewrite = clock.lap();
    if (auto status = checkCancelled(cancel); !status) {
        return std::unexpected(status.error());
    }
    if (input.verifyByRereading || feedsFromWritten) {
        startStage(0.68, "reading the written program back to check it");
    }
    auto written = input.verifyByRereading || feedsFromWritten
                       ? readBackWritten(input, outcome, feedsFromWritten, cancel)
                       : Result<WrittenProgram>(WrittenProgram{});
    outcome.stageSeconds.verify = clock.lap();
    if (!written) {
        return std::unexpected(written.error());
    }
    outcome.maxCentreDeviationMm = written->maxCentreDeviationMm;
    outcome.maxCentreDeviationLine = written->maxCentreDeviationLine;
    if (feedsFromWritten) {
        outcome.passFeeds = std::move(written->passFeeds);
    }
    if (auto status = checkOutcome(outcome, input.program->path().sourceFile); !status) {
        return std::unexpected(status.error());
    }
    if (auto status = checkModuloSteps(input, outcome); !status) {
        return std::unexpected(status.error());
    }
    if (auto status = checkTravel(input, outcome); !status) {
        return std::unexpected(status.error());
    }
    if (input.analyseNewMotion) {
        startStage(0.98, "analysing the new axis motion");
        auto motion = analysed.get();
        if (!motion) {
            return std::unexpected(motion.error());
        }
        outcome.profile = std::move(motion->profile);
        outcome.constantFeed = motion->constantFeed;
        outcome.timeOptimal = motion->timeOptimal;
        outcome.blockByBlock = motion->blockByBlock;
        outcome.interpolation = motion->interpolation;
    }
    outcome.stageSeconds.analysis = clock.lap(); // what the analysis added after the check
    return outcome;
}

} // namespace bladeaxis::job
