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
    // (RescheduleInput::stagedProgram); writeJobOutputs commits it.
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

struct RescheduleInput {
    const io::LoadedProgram* program = nullptr;
    const kinematics::MachineModel* machine = nullptr;
    std::size_t passFirst = 0;
    std::size_t passCount = 0;
    double startA = 0.0; // rad, the input's A at the pass's first record: the new A starts there
    double toolRadius = 0.0;
    scheduling::ScheduleParameters parameters;
    std::vector<scheduling::LayerOverride> layerEdits; // the engineer's edits of single layers
    analysis::AxisProfileOptions analysis;
    // Both on in every job; the benchmarks switch them off to time read-schedule-write alone.
    bool verifyByRereading = true;
    bool analyseNewMotion = true;
    // Free the schedule's new tool axes (24 bytes per record) once the new motion's analysis has
    // read them: for a job whose outputs were all written by the rewrite (nothing makes the
    // re-scheduled records afterwards: CL output, the CAD check, the comparison, the display).
    bool releaseNewToolAxes = false;
    // Called once the scheduling has made its plane path (ScheduleInput::planePathMade).
    std::function<void()> planePathMade;
    // Called once the pass is split into layers, before the scheduling's memory peaks, with the
    // layers' input ranges relative to the pass (ScheduleInput::layersSplit): a job takes the
    // input's motion per layer here and may release the input's samples.
    std::function<void(std::span<const scheduling::LayerBounds>)> layersSplit;
    // Called once the schedule is made, before the inverse kinematics, with the schedule the
    // outcome keeps. Nothing of the re-scheduling reads the layers' per-sample curves after this
    // (the new motion is made from the new tool axes), so a job checks the input's orientation
    // against the channel here and may release them (scheduling::releaseLayerSamples) before
    // the new motion is made and analysed.
    std::function<void(scheduling::ScheduleResult&)> scheduled;
    // Called once the program is rewritten (or its rewrite failed), before it is read back: the
    // rewrite was the last reader of the input's text, and a job frees it here
    // (releaseRewriteSources). Nothing of the re-scheduling reads the program's text after this.
    std::function<void()> rewritten;
    // Called as a G-code rewrite goes with how far it has read the input (see
    // io::nc::RewrittenUpTo): a job that frees the text once rewritten gives those pages back at
    // once (releaseRewriteSourcesBefore), so that the text read and the text written do not
    // stand side by side at the rewrite's end, where read-schedule-write's memory peaks.
    // Ignored without `rewritten`: the pages given back read as zeros.
    io::nc::RewrittenUpTo rewrittenUpTo;
    // Where the rewritten program goes instead of memory: its text is appended here and freed,
    // and the re-read check reads it back from the file, mapped, giving its pages back as it
    // goes. A million-block program's text (65 bytes per record) then does not stand beside the
    // new motion's analysis, where a job's memory peaks. Null: kept in programText.
    std::shared_ptr<StagedFile> stagedProgram;
    // Called as each stage of the re-scheduling starts, on the calling thread, with the share
    // of the re-scheduling done before it and what the stage does ("writing the re-scheduled
    // program"): a job shows it as its progress. The shares are those of a five-million-block
    // program, whose re-scheduling takes about 3 s.
    std::function<void(double done, std::string_view stage)> stageStarted;
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

// ErrorCode::Cancelled once the token is set. A job checks it between its stages, each a second
// or more on millions of blocks, so that an interrupt takes effect at the next stage.
Status checkCancelled(const CancelToken& cancel);

Result<RescheduleOutcome> reschedule(const RescheduleInput& input, const CancelToken& cancel);

// The re-scheduled pass as records: each input record of the pass with its new tip and tool
// axis, its feed as written, and no machine axes. Made on demand (CL output, the CAD check): a
// job does not keep a second copy of every record.
std::vector<toolpath::ClRecord> rescheduledRecords(std::span<const toolpath::ClRecord> pass,
                                                   const RescheduleOutcome& outcome);

// The re-scheduled pass as the axis analysis reads it: the input records lend their lines (and
// feeds, unless the written program gives new ones), the schedule its poses.
analysis::PathSamples rescheduledSamples(std::span<const toolpath::ClRecord> pass,
                                         const RescheduleOutcome& outcome);

} // namespace bladeaxis::job
