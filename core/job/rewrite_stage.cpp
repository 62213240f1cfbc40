// The stages of a re-scheduling that turn the schedule into machine axes and a written program,
// and read that program back (reschedule.h).

#include "core/job/rewrite_stage.h"

#include "core/base/free_storage.h"
#include "core/io/cl/apt.h"
#include "core/io/nc/gcode.h"
#include "core/job/reschedule.h"
#include "core/kinematics/kinematics.h"

#include <algorithm>

namespace bladeaxis::job {

namespace {

using toolpath::ClRecord;

// The rewrite of a G-code pass; a program programmed as the tool tip is written with the tip in
// the workpiece frame (TRAORI, M128), not the machine's X Y Z.
Result<std::string> rewriteGcode(const PassToRewrite& pass, const io::nc::GcodeProgram& gcode,
                                 std::span<const kinematics::MachineAxes> axes,
                                 const io::nc::RewriteStreams& streams) {
    if (!pass.toolTip) {
        return io::nc::rewriteGcodePass(gcode, pass.passFirst, axes, *pass.machine, streams);
    }
    std::vector<kinematics::MachineAxes> words(axes.begin(), axes.end());
    for (kinematics::MachineAxes& word : words) {
        const Vec3 tip = kinematics::forwardKinematics(pass.machine->chain, word).tip;
        word.x = tip.x();
        word.y = tip.y();
        word.z = tip.z();
    }
    return io::nc::rewriteGcodePass(gcode, pass.passFirst, words, *pass.machine, streams);
}

// How a G-code rewrite reads its input and where it writes: a consumed text gives back its pages
// as the rewrite passes them (they read as zeros afterwards, so only a consumed one); a staged
// program takes the text in pieces of a few megabytes, each a point where a cancelled job stops.
io::nc::RewriteStreams streamsOf(const PassToRewrite& pass, const RewriteTarget& target,
                                 const CancelToken& cancel) {
    io::nc::RewriteStreams streams;
    io::LoadedProgram& program = *pass.program;
    if (!target.keepInputText) {
        streams.rewrittenUpTo = [&program](std::size_t textEnd, std::size_t blockEnd) {
            program.releaseRewriteSourcesBefore(textEnd, blockEnd);
        };
    }
    if (target.staged != nullptr) {
        streams.writtenPiece = [&staged = *target.staged, &cancel](std::string_view piece) {
            if (auto status = checkCancelled(cancel); !status) {
                return status;
            }
            return staged.append(piece);
        };
    }
    streams.textFile = program.textFile;
    return streams;
}

Result<std::string> rewriteAnyFormat(const PassToRewrite& pass,
                                     std::span<const kinematics::MachineAxes> axes,
                                     const scheduling::ScheduleResult& schedule,
                                     const RewriteTarget& target, const CancelToken& cancel) {
    const io::LoadedProgram& program = *pass.program;
    if (const auto* gcode = std::get_if<io::nc::GcodeProgram>(&program.document)) {
        return rewriteGcode(pass, *gcode, axes, streamsOf(pass, target, cancel));
    }
    std::vector<ClRecord> records = program.path().records;
    std::ranges::copy(rescheduledRecords(pass.records(), schedule, pass.toolRadius, {}),
                      records.begin() + static_cast<std::ptrdiff_t>(pass.passFirst));
    io::toProgramFrame(records, *pass.machine);
    if (const auto* table = std::get_if<io::table::TableProgram>(&program.document)) {
        return io::table::rewritePointTable(*table, records);
    }
    return io::cl::rewriteApt(std::get<io::cl::AptProgram>(program.document), records);
}

// A CL or table rewrite arrives whole: a staged one goes to its file here and is freed.
Result<std::string> stageWhole(std::string text, StagedFile& staged) {
    if (auto appended = staged.append(text); !appended) {
        return std::unexpected(appended.error());
    }
    freeStorage(text);
    return std::string();
}

// The written text is read back as a stream: each record is compared with the input's as it
// is read and then dropped, so the check never holds a second program (about 140 bytes per
// record) beside the first.
Result<WrittenProgram> readBack(const PassToRewrite& pass, std::string_view text, bool keepFeeds,
                                const io::nc::TextReadUpTo& readUpTo, const CancelToken& cancel) {
    const toolpath::Toolpath& original = pass.program->path();
    const std::size_t passEnd = pass.passFirst + pass.passCount;
    WrittenProgram written;
    if (keepFeeds) {
        written.passFeeds.reserve(pass.passCount);
    }
    const auto compare = [&](std::size_t first, std::span<const ClRecord> records) {
        const std::size_t begin = std::max(first, pass.passFirst);
        const std::size_t end =
            std::min({first + records.size(), passEnd, original.records.size()});
        for (std::size_t i = begin; i < end; ++i) {
            const ClRecord& reread = records[i - first];
            const double deviation = (toolpath::ballCentre(reread, pass.toolRadius) -
                                      toolpath::ballCentre(original.records[i], pass.toolRadius))
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
                                          pass.program->format(), *pass.machine,
                                          pass.program->options, compare, readUpTo);
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

} // namespace

std::span<const ClRecord> PassToRewrite::records() const {
    return std::span(program->path().records).subspan(passFirst, passCount);
}

scheduling::ScheduleSamples scheduleSamplesOf(std::span<const ClRecord> pass, double toolRadius) {
    // The records' tips and axes, read where they are: the scheduling makes each ball centre
    // as toolpath::ballCentre does.
    return {.points = scheduling::Vec3Run(pass, &ClRecord::tip),
            .axes = scheduling::Vec3Run(pass, &ClRecord::axis),
            .toolRadius = toolRadius,
            .pointsAreTips = true};
}

Result<std::vector<kinematics::MachineAxes>>
newMachineAxes(const PassToRewrite& pass, const scheduling::ScheduleResult& schedule,
               const CancelToken& cancel) {
    const analysis::PathSamples samples =
        rescheduledSamples(pass.records(), schedule, pass.toolRadius, {});
    // The poses are made as the IK reads them: an array of them (48 bytes per record) would
    // stand beside the schedule and the new axes, where read-schedule-write's memory peaks.
    const auto poseAt = [&samples](std::size_t i) {
        return kinematics::ToolPose{samples.tip(i), samples.toolAxis(i)};
    };
    auto solved = kinematics::inverseKinematicsAlong(pass.machine->chain, samples.size(), poseAt,
                                                     pass.startA, &cancel);
    if (!solved) {
        return std::unexpected(solved.error()); // Cancelled
    }
    if (solved->failedIndex) {
        Error error = solved->failure;
        error.where = {pass.program->path().sourceFile, pass.records()[*solved->failedIndex].line,
                       0};
        return std::unexpected(error);
    }
    return std::move(solved->axes);
}

Result<std::string> rewriteProgram(const PassToRewrite& pass,
                                   std::span<const kinematics::MachineAxes> axes,
                                   const scheduling::ScheduleResult& schedule,
                                   const RewriteTarget& target, const CancelToken& cancel) {
    auto text = rewriteAnyFormat(pass, axes, schedule, target, cancel);
    if (!target.keepInputText) {
        // Also after a failed rewrite, which may have given back part of the text already.
        pass.program->releaseRewriteSources();
    }
    if (!text || target.staged == nullptr || text->empty()) {
        return text;
    }
    return stageWhole(std::move(*text), *target.staged);
}

Result<WrittenProgram> readBackWritten(const PassToRewrite& pass, std::string_view text,
                                       const StagedFile* staged, bool keepFeeds,
                                       const CancelToken& cancel) {
    if (staged == nullptr) {
        return readBack(pass, text, keepFeeds, {}, cancel);
    }
    // Mapped from the staged file with its pages given back as the reader passes them (a
    // shared file mapping reads dropped pages again from the file).
    auto mapped = staged->mapText();
    if (!mapped) {
        return std::unexpected(mapped.error());
    }
    const io::nc::TextReadUpTo giveBack = [&mapped](std::size_t offset) {
        mapped->releaseBefore(offset);
    };
    return readBack(pass, mapped->text(), keepFeeds, giveBack, cancel);
}

} // namespace bladeaxis::job
