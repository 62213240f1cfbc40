#pragma once
// The re-scheduling stage of a job: cutter centres of the cutting pass -> S-theta schedule ->
// new tips and axes -> machine axes (A continuous) -> rewritten program -> verification by
// re-reading it -> axis analysis of the new motion.

#include "core/analysis/axis_profile.h"
#include "core/analysis/block_planner.h"
#include "core/analysis/constant_feed.h"
#include "core/analysis/time_optimal.h"
#include "core/base/error.h"
#include "core/base/file_io.h"
#include "core/base/progress.h"
#include "core/io/nc/gcode_writer.h"
#include "core/io/program.h"
#include "core/job/progress_share.h"
#include "core/kinematics/interpolation_deviation.h"
#include "core/scheduling/schedule.h"

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace bladeaxis::job {

struct CuttingPass;

// The new tool axes are the schedule's (schedule.newAxes, one per pass record), and each new
// tip keeps its record's ball centre of radius toolRadius (tipOfBall); rescheduledSamples()
// gives the new poses as the analysis reads them, rescheduledRecords() as records where a
// writer wants records.
struct RescheduleOutcome {
    scheduling::ScheduleResult schedule;
    double toolRadius = 0.0; // mm, the ball whose centres the schedule keeps
    // Per pass record, A continuous; shared with the new motion's profile, which reads its
    // positions from them.
    analysis::SharedMachineAxes axes;
    // The tip feed of each pass record (mm/s) as the written program runs it, when that program
    // times its blocks anew (passIsBlockTimed); empty when the feeds are the input's.
    std::vector<double> passFeeds;
    analysis::AxisProfile profile; // axis motion of the new program
    analysis::ConstantFeedTime constantFeed;
    std::optional<analysis::ConvergedTime> timeOptimal; // T2 of the new motion, grid-converged
    analysis::BlockPlannerTime blockByBlock;            // the block-by-block model's time
    kinematics::InterpolationDeviation interpolation;   // between the new program's points
    // The whole rewritten program; empty when it was staged (stagedProgram).
    std::string programText;
    // The rewritten program written to its output file while the job ran, not yet in place
    // (Retention::writtenText false); writeJobOutputs commits it.
    std::shared_ptr<StagedFile> stagedProgram;
    // Verification (spec §6.5 and the acceptance): ball centres of the re-read output
    // against the input's, and the smallest distance of the new orientation to the raw channel.
    double maxCentreDeviationMm = 0.0;
    int maxCentreDeviationLine = 0; // the input line of the block where it is largest
    double minChannelClearanceRad = 0.0;
    std::size_t layersKeptOriginal = 0; // MonotoneInfeasible layers
    // Wall time of each stage, s: what a user waits for and what the benchmarks break down.
    struct StageSeconds {
        double schedule = 0.0, kinematics = 0.0, rewrite = 0.0, verify = 0.0, analysis = 0.0;
    } stageSeconds;

    // The rewritten program's text, from memory or read back from its staged file.
    Result<std::string> writtenText() const;
};

// What a job keeps of what its stages make, decided once from the outputs it was asked for
// (retentionOf): everything else is freed as soon as it has been read for the last time.
struct Retention {
    // The input's text in memory while the job runs. Without it a G-code program read from a
    // file is read again from there by its rewrite (61 bytes per block less while it is
    // scheduled).
    bool inputTextInMemory = true;
    // The input's text and where each block's words stand in it, after the rewrite (a demo's
    // demo_blade.nc reads it). Without it the rewrite consumes them: it gives back their pages
    // as it passes them and frees them at its end (61 + 24 bytes per block).
    bool inputTextAfterRewrite = true;
    // The input's per-sample motion (the profile's samples, 16 bytes per record and moving
    // axis, and the pass's machine axes but A, 40 bytes) once its figures are taken.
    bool inputSamples = true;
    // The schedule's per-layer curves (72 bytes per record) once the input's orientation is
    // checked against them.
    bool layerCurves = true;
    // The schedule's new tool axes (24 bytes per record) once the new motion is analysed.
    bool newToolAxes = true;
    // The written program's text in memory; without it the rewrite appends it to the output
    // file's staged copy as it goes (65 bytes per block).
    bool writtenText = true;
};

// The input's cutting pass and what its rewrite needs to know of it.
struct PassToRewrite {
    io::LoadedProgram* program = nullptr; // a rewrite that does not keep the text consumes it
    const kinematics::MachineModel* machine = nullptr;
    std::size_t passFirst = 0;
    std::size_t passCount = 0;
    // Programmed as the tool tip in the workpiece frame (io::programsToolTip, asked once the
    // program is read: the answer needs the block sources a rewrite may consume).
    bool toolTip = false;
    double startA = 0.0; // rad, the input's A at the pass's first record: the new A starts there
    double toolRadius = 0.0; // mm, the ball whose centres the schedule keeps

    std::span<const toolpath::ClRecord> records() const;
};

struct RescheduleInput {
    PassToRewrite pass;
    analysis::AxisProfileOptions analysis; // of the new motion
    Retention keep;
    // The output file the written program is staged to (keep.writtenText false).
    std::shared_ptr<StagedFile> stagedProgram;
};

// Largest ball-centre deviation accepted when the written program is read back: the program's
// own number precision (4 decimals) moves centres by well under this.
constexpr double kCentreDeviationLimitMm = 5e-3;

// True when a block of the pass is timed by its F rather than by its tip chord: inverse time
// (G93), or G94 on a control that reads F over the combined axis move (machine file
// "feed_per_minute": "combined_axes"). Then a new tip chord at the block's time is a new tip
// speed. The job then sets
// AxisProfileOptions::blockTimes for both analyses, and reschedule() takes the re-scheduled
// program's feeds from the written program read back.
bool passIsBlockTimed(const io::LoadedProgram& program, std::size_t first, std::size_t count);

// The pass as the scheduling reads it: each record's ball centre and tool axis, read when
// needed, so that no copy of them stands beside the plane path (48 bytes per record).
scheduling::ScheduleSamples scheduleSamplesOf(std::span<const toolpath::ClRecord> pass,
                                              double toolRadius);

// The stages after the scheduling, each one's values in and out; reschedule runs them all.
//
// The machine axes of the new poses, A unwrapped from the input's first A so that the new
// program starts where the old one did and A stays continuous.
Result<std::vector<kinematics::MachineAxes>>
newMachineAxes(const PassToRewrite& pass, const scheduling::ScheduleResult& schedule,
               const CancelToken& cancel);

// Where a rewrite's text goes: whole into the returned string, or in pieces of a few megabytes
// to a staged output file (the string is then empty), checking the token between pieces.
struct RewriteTarget {
    StagedFile* staged = nullptr;
    // Whether the input's text outlives the rewrite; a rewrite that consumes it gives back its
    // pages as it passes them and frees it (and the block sources) at its end, also on failure.
    bool keepInputText = true;
};
Result<std::string> rewriteProgram(const PassToRewrite& pass,
                                   std::span<const kinematics::MachineAxes> axes,
                                   const scheduling::ScheduleResult& schedule,
                                   const RewriteTarget& target, const CancelToken& cancel);

// Everything after the scheduling: the new machine axes, the rewritten program (staged or in
// memory), its verification by re-reading it, the new motion's analysis (beside the rewrite
// and the re-read) and the checks a written program must pass (channel, centres, modulo steps,
// travel). The progress share hears each stage start.
Result<RescheduleOutcome> reschedule(scheduling::ScheduleResult schedule,
                                     const RescheduleInput& input, ProgressShare& progress,
                                     const CancelToken& cancel);

// The re-scheduled pass as records: each input record of the pass with its new tip and tool
// axis, its feed as written (`feeds`, or the input's when empty), and no machine axes. Made on
// demand (CL output, the CAD check): a job does not keep a second copy of every record.
std::vector<toolpath::ClRecord> rescheduledRecords(std::span<const toolpath::ClRecord> pass,
                                                   const scheduling::ScheduleResult& schedule,
                                                   double toolRadius,
                                                   std::span<const double> feeds);
std::vector<toolpath::ClRecord> rescheduledRecords(std::span<const toolpath::ClRecord> pass,
                                                   const RescheduleOutcome& outcome);

// The re-scheduled pass as the axis analysis reads it: the input records lend their lines (and
// feeds, unless the written program gives new ones), the schedule its poses.
analysis::PathSamples rescheduledSamples(std::span<const toolpath::ClRecord> pass,
                                         const scheduling::ScheduleResult& schedule,
                                         double toolRadius, std::span<const double> feeds);
analysis::PathSamples rescheduledSamples(std::span<const toolpath::ClRecord> pass,
                                         const RescheduleOutcome& outcome);

} // namespace bladeaxis::job
