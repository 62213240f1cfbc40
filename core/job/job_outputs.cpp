#include "core/analysis/lost_motion.h"
#include "core/base/file_io.h"
#include "core/base/number_io.h"
#include "core/base/output_set.h"
#include "core/base/units.h"
#include "core/base/version.h"
#include "core/io/cl/apt_writer.h"
#include "core/io/program.h"
#include "core/job/cycle_time_models.h"
#include "core/job/demo_program.h"
#include "core/job/job.h"
#include "core/job/output_paths.h"
#include "core/report/analysis_report.h"
#include "core/report/compare_report.h"
#include "core/report/schedule_report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <limits>
#include <string_view>

namespace bladeaxis::job {

namespace {

// The program's letter for an axis role ("B" for the table of a table-B machine): every text a
// person reads names the axis as the program and the machine's panel do.
std::string letterOf(const kinematics::MachineModel& machine, kinematics::AxisId axis) {
    return std::string(1, machine.letter(axis));
}

// "backlash     A 0.005 deg: 16 -> 0 reversals, 0.080 -> 0.000 deg lost motion", one line per
// axis with play (before only when nothing was re-scheduled).
std::string lostMotionSummary(const JobResult& result) {
    const auto& before = result.originalLostMotion;
    const auto after = result.rescheduled
                           ? analysis::lostMotion(result.rescheduled->profile, result.machine)
                           : std::vector<analysis::LostMotion>{};
    std::string text;
    for (std::size_t i = 0; i < before.size(); ++i) {
        const kinematics::AxisId axis = before[i].axis;
        const auto shown = [axis](double value, int decimals) {
            return formatFixed(report::toReportUnit(axis, value), decimals);
        };
        const std::string unit = std::string(" ") + report::unitOf(axis);
        text += "backlash     " + letterOf(result.machine, axis) + " " +
                shown(before[i].backlash, 4) + unit + ": " + std::to_string(before[i].reversals);
        if (i < after.size()) {
            text += " -> " + std::to_string(after[i].reversals);
        }
        text += " reversals, " + shown(before[i].lostMotion, 3);
        if (i < after.size()) {
            text += " -> " + shown(after[i].lostMotion, 3);
        }
        text += unit + " lost motion\n";
    }
    return text;
}

namespace fs = std::filesystem;

nlohmann::json inputJson(const JobResult& result) {
    const toolpath::Toolpath& path = result.program.path();
    nlohmann::json json;
    json["file"] = fs::path(path.sourceFile).filename().string();
    json["format"] = io::toString(result.program.format());
    if (const auto dialect = result.program.dialect()) {
        json["dialect"] = io::toString(*dialect);
    }
    json["records"] = path.records.size();
    json["analysed_records"] = result.pass.count;
    if (result.pass.count > 0) {
        json["first_line"] = path.records[result.pass.first].line;
        json["last_line"] = path.records[result.pass.first + result.pass.count - 1].line;
    }
    return json;
}

std::vector<int> passLines(const JobResult& result) {
    std::vector<int> lines;
    const auto& records = result.program.path().records;
    for (std::size_t i = 0; i < result.pass.count; ++i) {
        lines.push_back(records[result.pass.first + i].line);
    }
    return lines;
}

} // namespace

Result<std::string> rescheduledClText(const JobResult& result) {
    if (!result.rescheduled) {
        return makeError(ErrorCode::InvalidArgument,
                         "CL output needs re-scheduling; it was not run");
    }
    if (result.rescheduled->schedule.newAxes.size() != result.pass.count) {
        return makeError(ErrorCode::Internal,
                         "the re-scheduled tool axes were released once the job had written its "
                         "program: run the job with the CL output it writes");
    }
    toolpath::Toolpath path = result.program.path();
    const auto pass =
        std::span(result.program.path().records).subspan(result.pass.first, result.pass.count);
    std::ranges::copy(rescheduledRecords(pass, *result.rescheduled),
                      path.records.begin() + static_cast<std::ptrdiff_t>(result.pass.first));
    io::toProgramFrame(path.records, result.machine);
    io::cl::AptEmitOptions options;
    options.toolRadius = result.toolRadius;
    options.comments = {"re-scheduled by BladeAxis from " +
                        fs::path(path.sourceFile).filename().string()};
    return io::cl::emitApt(path, options);
}

namespace {

// The re-scheduled program's side of the layers' motion, from its profile (which every job
// keeps); the input's side was taken by the job when the layers were known.
std::vector<report::LayerAxisMotion> layerMotionAfter(const RescheduleOutcome& outcome) {
    return report::layerAxisMotion(scheduling::layerBounds(outcome.schedule), outcome.profile,
                                   *outcome.axes);
}

} // namespace

std::vector<report::LayerMotion> layerMotionOf(const JobResult& result) {
    if (!result.rescheduled) {
        return {};
    }
    const std::vector<report::LayerAxisMotion> after = layerMotionAfter(*result.rescheduled);
    return report::layerMotion(
        {.before = result.layerMotionBefore, .after = after, .sourceLines = {}});
}

namespace {

// Every cycle-time estimate of one program, each with the controller model it assumes, and which
// of them the machine file names as its control's ("machine_model").
nlohmann::json cycleTimesJson(const analysis::ConstantFeedTime& constantFeed,
                              const std::optional<analysis::ConvergedTime>& lookAhead,
                              const analysis::BlockPlannerTime& blockByBlock,
                              const kinematics::MachineModel& machine) {
    nlohmann::json json;
    json["machine_model"] = kinematics::plannerName(machine.controller.planner);
    json["constant_feed"] = {{"time_s", constantFeed.time}, {"model", kConstantFeedModel}};
    if (lookAhead) {
        json["look_ahead"] = {{"time_s", lookAhead->time},
                              {"model", kLookAheadModel},
                              {"grid_steps_per_block", lookAhead->subdivisions},
                              {"last_grid_change", lookAhead->lastChange},
                              {"converged", lookAhead->converged}};
    }
    json["block_by_block"] = {{"time_s", blockByBlock.time},
                              {"model", kBlockByBlockModel},
                              {"blocks", blockByBlock.blocks}};
    return json;
}

nlohmann::json rescheduledJson(const JobResult& result, const JobSpec* spec) {
    const RescheduleOutcome& outcome = *result.rescheduled;
    nlohmann::json json;
    if (spec != nullptr) {
        json["preset"] = spec->presetName;
        if (!spec->layerEdits.empty()) { // a reviewer sees which layers an engineer changed
            nlohmann::json edited = nlohmann::json::array();
            for (const scheduling::LayerOverride& edit : spec->layerEdits) {
                edited.push_back(edit.layer);
            }
            json["edited_layers"] = edited;
        }
    }
    json["analysis"] = report::analysisJson(outcome.profile, outcome.constantFeed);
    json["analysis"]["lost_motion"] =
        report::lostMotionJson(analysis::lostMotion(outcome.profile, result.machine));
    json["reductions"] = report::reductionsJson(result.original, outcome.profile);
    const double before = result.constantFeed.time;
    const double after = outcome.constantFeed.time;
    json["t1_reduction"] = before > 0.0 ? (before - after) / before : 0.0;
    if (outcome.timeOptimal) {
        json["analysis"]["time_optimal_s"] = outcome.timeOptimal->time;
        if (result.timeOptimal) {
            json["t2_reduction"] =
                (result.timeOptimal->time - outcome.timeOptimal->time) / result.timeOptimal->time;
        }
    }
    json["analysis"]["cycle_times"] = cycleTimesJson(outcome.constantFeed, outcome.timeOptimal,
                                                     outcome.blockByBlock, result.machine);
    if (result.blockByBlock.time > 0.0) {
        json["block_by_block_reduction"] =
            (result.blockByBlock.time - outcome.blockByBlock.time) / result.blockByBlock.time;
    }
    json["checks"] = {
        {"max_centre_deviation_mm", outcome.maxCentreDeviationMm},
        {"max_interpolation_deviation_mm", outcome.interpolation.maxMm},
        {"max_reconstruction_error_mm", outcome.schedule.check.maxCentreErrorMm},
        {"min_channel_clearance_deg", units::radToDeg(outcome.minChannelClearanceRad)},
        {"layers_kept_original", outcome.layersKeptOriginal},
        {"max_junction_gap_deg", units::radToDeg(outcome.schedule.check.maxJunctionGapRad)},
    };
    const std::vector<int> lines = passLines(result);
    const std::vector<report::LayerAxisMotion> motionAfter = layerMotionAfter(outcome);
    json["layers"] = report::layersJson(
        outcome.schedule,
        {.before = result.layerMotionBefore, .after = motionAfter, .sourceLines = lines});
    const auto& stages = outcome.stageSeconds;
    json["timing"] = {{"schedule_s", stages.schedule},
                      {"kinematics_s", stages.kinematics},
                      {"rewrite_s", stages.rewrite},
                      {"verify_s", stages.verify},
                      {"analysis_s", stages.analysis}};
    return json;
}

// Per layer (the schedule's layers, or revolutions without a schedule): the smallest clearance
// of each tool part and the number of issues, with the layer's source lines.
nlohmann::json clearanceLayersJson(const cad::ClearanceReport& report, std::span<const int> lines) {
    nlohmann::json layers = nlohmann::json::array();
    for (std::size_t k = 0; k < report.layers.size(); ++k) {
        const cad::LayerClearance& layer = report.layers[k];
        layers.push_back({{"layer", k},
                          {"first_record", layer.first},
                          {"last_record", layer.last},
                          {"first_line", layer.first < lines.size() ? lines[layer.first] : 0},
                          {"last_line", layer.last < lines.size() ? lines[layer.last] : 0},
                          {"min_ball_mm", layer.minimum.ball},
                          {"min_shank_mm", layer.minimum.shank},
                          {"min_holder_mm", layer.minimum.holder},
                          {"issues", layer.issues}});
    }
    return layers;
}

nlohmann::json clearanceSideJson(const cad::ClearanceReport& report, const std::string& file,
                                 std::span<const int> lines) {
    const cad::RecordClearance minimum = cad::minimumOf(report.records);
    nlohmann::json json{{"min_ball_mm", minimum.ball},
                        {"min_shank_mm", minimum.shank},
                        {"min_holder_mm", minimum.holder},
                        {"issues", report.issues.size()}};
    nlohmann::json first = nlohmann::json::array();
    for (std::size_t i = 0; i < std::min<std::size_t>(report.issues.size(), 10); ++i) {
        first.push_back(cad::describe(report.issues[i], file));
    }
    json["first_issues"] = first;
    json["layers"] = clearanceLayersJson(report, lines);
    return json;
}

nlohmann::json clearanceJson(const CadCheckResult& check, const std::string& file,
                             std::span<const int> lines) {
    nlohmann::json json{{"cad", check.source},
                        {"faces", check.faces},
                        {"triangles", check.triangles},
                        {"original", clearanceSideJson(check.original, file, lines)}};
    if (check.rescheduled) {
        json["rescheduled"] = clearanceSideJson(*check.rescheduled, file, lines);
        json["introduced_issues"] = introducedIssues(check).size();
    }
    json["sampling_error_mm"] = check.original.samplingError;
    json["concave_exits"] = nlohmann::json::array();
    for (const SectionComparison& section : check.sections) {
        nlohmann::json entry{{"base_point", section.basePoint},
                             {"x_mm", section.x},
                             {"toolpath_exit_deg", section.engineExitDeg},
                             {"toolpath_fallback", section.engineFallback},
                             {"cad_concave_runs", section.cadConcaveRuns},
                             {"difference_deg", section.differenceDeg}};
        if (section.cadExitDeg) {
            entry["cad_exit_deg"] = *section.cadExitDeg;
        }
        json["concave_exits"].push_back(entry);
    }
    return json;
}

bool lettersAreRoles(const kinematics::MachineModel& machine) {
    return std::ranges::all_of(kinematics::kAllAxes, [&machine](kinematics::AxisId axis) {
        return letterOf(machine, axis) == kinematics::axisName(axis);
    });
}

// The report's keys name the engine's axis roles; "axis_letters" maps each role to the
// program's letter, so that a consumer can label a table-B machine's figures as its operator
// reads them. Written only where a letter differs, so a table-A report is as it always was.
void addAxisLetters(nlohmann::json& json, const kinematics::MachineModel& machine) {
    if (lettersAreRoles(machine)) {
        return;
    }
    nlohmann::json letters = nlohmann::json::object();
    for (kinematics::AxisId axis : kinematics::kAllAxes) {
        letters[kinematics::axisName(axis)] = letterOf(machine, axis);
    }
    json["axis_letters"] = letters;
    json["machine_layout"] = kinematics::layoutName(machine.layout);
}

nlohmann::json reportJson(const JobResult& result, const JobSpec* spec) {
    nlohmann::json json;
    json["bladeaxis_version"] = projectVersion();
    json["bladeaxis_revision"] = projectRevision();
    json["input"] = inputJson(result);
    addAxisLetters(json, result.machine);
    json["machine"] = {
        {"name", result.machine.name},
        {"file", result.machine.sourceFile.empty() ? "(built-in)" : result.machine.sourceFile}};
    if (result.toolRadius) {
        json["tool_radius_mm"] = *result.toolRadius;
    }
    json["original"] = report::analysisJson(result.original, result.constantFeed);
    json["original"]["lost_motion"] = report::lostMotionJson(result.originalLostMotion);
    if (result.timeOptimal) {
        json["original"]["time_optimal_s"] = result.timeOptimal->time;
    }
    json["original"]["cycle_times"] = cycleTimesJson(result.constantFeed, result.timeOptimal,
                                                     result.blockByBlock, result.machine);
    if (result.originalInterpolation) {
        json["original"]["max_interpolation_deviation_mm"] = result.originalInterpolation->maxMm;
    }
    if (result.rescheduled) {
        json["rescheduled"] = rescheduledJson(result, spec);
    }
    if (result.cadCheck) {
        json["clearance"] =
            clearanceJson(*result.cadCheck, result.program.path().sourceFile, passLines(result));
    }
    json["warnings"] = result.warnings;
    json["timing"] = {{"job_s", result.seconds}};
    return json;
}

} // namespace

namespace {

// Refusals that need no file: checked before any output folder is made or file staged.
Status refuseOutputsOfThisResult(const JobSpec& spec, const JobResult& result) {
    if (!spec.outputProgram.empty() && !result.rescheduled) {
        return makeError(ErrorCode::InvalidArgument,
                         "an output program needs re-scheduling; it was not run",
                         {spec.outputProgram.string()});
    }
    const bool writesToolpath = !spec.outputProgram.empty() || !spec.outputCl.empty();
    if (writesToolpath && result.cadCheck && result.rescheduled) {
        return refuseIfColliding(*result.cadCheck, result.program.path().sourceFile,
                                 spec.cad.force);
    }
    return {};
}

Status stageOutputCl(const JobSpec& spec, const JobResult& result, OutputSet& outputs) {
    if (spec.outputCl.empty()) {
        return {};
    }
    auto text = rescheduledClText(result);
    if (!text) {
        Error error = text.error();
        error.where = {spec.outputCl.string()};
        return std::unexpected(error);
    }
    return outputs.add(spec.outputCl, *text);
}

// The re-scheduled program is published first: a report never describes a program that is not
// on disk. The input is never a target (the set refuses it, also through links).
Status stageOutputProgram(const JobSpec& spec, const JobResult& result, OutputSet& outputs) {
    if (spec.outputProgram.empty()) {
        return {};
    }
    if (result.rescheduled->stagedProgram) {
        outputs.adopt(result.rescheduled->stagedProgram);
        return {};
    }
    return outputs.add(spec.outputProgram, result.rescheduled->programText);
}

// The demo blade as real CAD, written through OpenCASCADE, so the demo's outputs include the
// surface the clearance check used (and the GUI or any CAD system can open it). OpenCASCADE
// writes only to a path: to a temporary beside the folder's files, taken into the set from there.
Status stageDemoCad(const JobSpec& spec, const JobResult& result, OutputSet& outputs) {
    if (!spec.demo || !result.cadCheck) {
        return {};
    }
    // Written in the program's workpiece frame, where a CAD file given with the program is read.
    cad::CadShape blade = result.cadCheck->blade;
    if (result.machine.turnsAboutY()) {
        const Mat3 toProgram = result.machine.engineFrameRotation().transpose();
        auto placed = cad::placedShape(blade, {toProgram, Vec3::Zero()});
        if (!placed) {
            return std::unexpected(placed.error());
        }
        blade = std::move(*placed);
    }
    const fs::path temporary = temporaryNameIn(spec.outputDir);
    Status written = cad::writeCadFile(blade, temporary, cad::CadFormat::Step);
    auto text = written ? readTextFile(temporary) : Result<std::string>(std::string());
    std::error_code ec;
    fs::remove(temporary, ec);
    if (!written || !text) {
        Error error = written ? text.error() : written.error();
        error.where = {(spec.outputDir / "demo_blade.step").string()};
        return std::unexpected(error);
    }
    return outputs.add(spec.outputDir / "demo_blade.step", *text);
}

Status stageComparison(const JobSpec& spec, const JobResult& result, OutputSet& outputs) {
    const compare::Comparison& comparison = *result.comparison;
    const std::string name = fs::path(result.program.path().sourceFile).filename().string();
    const std::pair<const char*, std::string> files[] = {
        {"compare.json", report::compareJson(comparison)
                                 .dump(2, ' ', false, nlohmann::json::error_handler_t::replace) +
                             "\n"},
        {"compare.csv", report::compareCsv(comparison)},
        {"report.html", report::compareHtml(comparison, name)}};
    for (const auto& [file, text] : files) {
        if (auto status = outputs.add(spec.outputDir / file, text); !status) {
            return status;
        }
    }
    return {};
}

// layers.csv with the written program's ball and shank clearance of each row's CL point (the
// first column is the record of the cutting pass).
std::string withClearanceColumns(const std::string& csv, const cad::ClearanceReport& clearance) {
    std::string out;
    out.reserve(csv.size() + csv.size() / 4);
    std::size_t begin = 0;
    for (std::size_t end = csv.find('\n'); end != std::string::npos;
         begin = end + 1, end = csv.find('\n', begin)) {
        const std::string_view row(csv.data() + begin, end - begin);
        out.append(row);
        if (begin == 0) {
            out += ",ball_clearance_mm,shank_clearance_mm\n";
            continue;
        }
        const auto record = parseNumber(row.substr(0, row.find(',')));
        const auto index = static_cast<std::size_t>(record.value_or(-1.0));
        if (record && index < clearance.records.size()) {
            out += ',' + formatShortest(clearance.records[index].ball) + ',' +
                   formatShortest(clearance.records[index].shank);
        } else {
            out += ",,";
        }
        out += '\n';
    }
    return out;
}

Status stageReportFolder(const JobSpec& spec, const JobResult& result, OutputSet& outputs) {
    if (spec.demo) {
        if (auto status = outputs.add(spec.outputDir / kDemoProgramName, result.programText());
            !status) {
            return status;
        }
        if (auto status = stageDemoCad(spec, result, outputs); !status) {
            return status;
        }
    }
    const auto records =
        std::span(result.program.path().records).subspan(result.pass.first, result.pass.count);
    if (auto status =
            outputs.add(spec.outputDir / "axes.csv", report::axesCsv(result.original, records));
        !status) {
        return status;
    }
    if (result.rescheduled) {
        std::string csv = report::layersCsv(result.rescheduled->schedule, passLines(result));
        if (result.cadCheck && result.cadCheck->rescheduled) {
            csv = withClearanceColumns(csv, *result.cadCheck->rescheduled);
        }
        if (auto status = outputs.add(spec.outputDir / "layers.csv", csv); !status) {
            return status;
        }
    }
    if (result.comparison) {
        if (auto status = stageComparison(spec, result, outputs); !status) {
            return status;
        }
    }
    return outputs.add(spec.outputDir / "report.json", reportJsonText(result, &spec));
}

// Every output staged, then all published or none: a job that cannot write one of its files
// leaves neither the others nor an output folder it made.
Status stageAndPublish(const JobSpec& spec, const JobResult& result, const CancelToken* cancel) {
    // Made first: the program's folder may lie in it (-o out/new.nc --out out/report).
    auto folder = CreatedFolder::create(spec.outputDir);
    if (!folder) {
        return std::unexpected(folder.error());
    }
    OutputSet outputs(protectedInputsOf(spec));
    if (auto status = stageOutputProgram(spec, result, outputs); !status) {
        return status;
    }
    if (auto status = stageOutputCl(spec, result, outputs); !status) {
        return status;
    }
    if (!spec.outputDir.empty()) {
        if (auto status = stageReportFolder(spec, result, outputs); !status) {
            return status;
        }
    }
    if (auto status = checkCancelled(cancel); !status) { // the last point where nothing is out
        return status;
    }
    if (auto status = outputs.publish(); !status) {
        return status;
    }
    folder->keep();
    return {};
}

} // namespace

std::vector<fs::path> protectedInputsOf(const JobSpec& spec) {
    std::vector<fs::path> inputs;
    for (const fs::path& input :
         {spec.demo ? fs::path() : spec.program, spec.machineFile, spec.cad.file, spec.jobFile}) {
        if (!input.empty()) {
            inputs.push_back(input);
        }
    }
    return inputs;
}

Status writeJobOutputs(const JobSpec& spec, const JobResult& result, const CancelToken* cancel) {
    // Refused before anything is written: a job that ran without an output folder (and so
    // released the samples these files are made of) given one only now.
    if (!spec.outputDir.empty() && (!result.kept.inputSamples || !result.kept.layerCurves)) {
        return makeError(ErrorCode::Internal,
                         "axes.csv and layers.csv need the samples the job released once it had "
                         "taken its figures: run it with the output folder it writes");
    }
    // Again here: the GUI and the API name their outputs after the job ran.
    if (auto refused = refuseSharedPaths(spec); !refused) {
        return refused;
    }
    if (auto refused = refuseOutputsOfThisResult(spec, result); !refused) {
        return refused;
    }
    return stageAndPublish(spec, result, cancel);
}

std::string reportJsonText(const JobResult& result, const JobSpec* spec) {
    return reportJson(result, spec).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) +
           "\n";
}

namespace {

// "(61.3% lower)", "(12.0% higher)", or, when the input's figure is about zero and a
// percentage would say nothing, "(the input's is about 0)".
std::string change(double before, double after, std::string_view lowerWord,
                   std::string_view higherWord) {
    const double scale = std::max(std::abs(before), std::abs(after));
    if (!(scale > 0.0)) {
        return "(unchanged)";
    }
    if (!(std::abs(before) > 1e-3 * scale)) {
        return "(the input's is about 0)";
    }
    const double relative = 100.0 * (before - after) / before;
    const bool lower = relative >= 0.0;
    return "(" + formatFixed(std::abs(relative), 1) + "% " +
           std::string(lower ? lowerWord : higherWord) + ")";
}

// "channel clearance >= 1.234 deg", or why there is no figure: every layer kept its original
// orientation, which the channel check does not apply to.
std::string clearanceText(const RescheduleOutcome& outcome) {
    if (!std::isfinite(outcome.minChannelClearanceRad)) {
        return "no layer re-scheduled, channel clearance not applicable";
    }
    return "channel clearance >= " +
           formatFixed(units::radToDeg(outcome.minChannelClearanceRad), 3) + " deg";
}

// One line per cycle-time model, each naming what it assumes; the machine file's model is
// marked "(this machine)".
std::string cycleTimeSummary(const JobResult& result, const RescheduleOutcome& outcome) {
    const kinematics::Planner planner = result.machine.controller.planner;
    const auto mark = [planner](kinematics::Planner model) {
        return model == planner ? " (this machine)" : "";
    };
    std::string text =
        "T1           " + formatFixed(result.constantFeed.time, 1) + " -> " +
        formatFixed(outcome.constantFeed.time, 1) + " s " +
        change(result.constantFeed.time, outcome.constantFeed.time, "shorter", "longer") +
        ", one constant feed set by the slowest point (a bound, not a control)\n";
    if (result.timeOptimal && outcome.timeOptimal) {
        text += "T2           " + formatFixed(result.timeOptimal->time, 1) + " -> " +
                formatFixed(outcome.timeOptimal->time, 1) + " s " +
                change(result.timeOptimal->time, outcome.timeOptimal->time, "shorter", "longer") +
                ", look-ahead time-optimal, grid-converged" + mark(kinematics::Planner::LookAhead) +
                "\n";
    }
    if (result.blockByBlock.time > 0.0 && outcome.blockByBlock.time > 0.0) {
        text += "block time   " + formatFixed(result.blockByBlock.time, 1) + " -> " +
                formatFixed(outcome.blockByBlock.time, 1) + " s " +
                change(result.blockByBlock.time, outcome.blockByBlock.time, "shorter", "longer") +
                ", block-by-block, no blending across rotary blocks (LinuxCNC 2.9)" +
                mark(kinematics::Planner::BlockByBlock) + "\n";
    }
    return text;
}

std::string rescheduledSummary(const JobResult& result) {
    using kinematics::AxisId;
    const RescheduleOutcome& outcome = *result.rescheduled;
    const auto& before = result.original;
    const auto& after = outcome.profile;
    const auto& a0 = before.axis(AxisId::A);
    const auto& a1 = after.axis(AxisId::A);
    const std::string table = letterOf(result.machine, AxisId::A);
    std::size_t flagged = 0;
    for (const auto& layer : outcome.schedule.layers) {
        flagged += scheduling::isFlagged(layer) ? 1 : 0;
    }
    std::string text = "re-scheduled " + std::to_string(outcome.schedule.layers.size()) +
                       " layers (" + std::to_string(flagged) + " flagged, " +
                       std::to_string(outcome.layersKeptOriginal) + " kept original)\n";
    text += table + " reversals  " + std::to_string(before.aReversals.count) + " -> " +
            std::to_string(after.aReversals.count) + "\n";
    text += table + " peak vel.  " + formatFixed(units::radToDeg(a0.peakVelocity), 1) + " -> " +
            formatFixed(units::radToDeg(a1.peakVelocity), 1) + " deg/s " +
            change(a0.peakVelocity, a1.peakVelocity, "lower", "higher") + "\n";
    text += table + " peak acc.  " + formatFixed(units::radToDeg(a0.peakAcceleration), 0) + " -> " +
            formatFixed(units::radToDeg(a1.peakAcceleration), 0) + " deg/s^2 " +
            change(a0.peakAcceleration, a1.peakAcceleration, "lower", "higher") + "\n";
    text += cycleTimeSummary(result, outcome);
    text += "checks       ball centres kept within " +
            formatFixed(outcome.maxCentreDeviationMm * 1000.0, 2) + " um after re-reading; " +
            clearanceText(outcome) + "\n";
    text += "between      ball centres within " +
            formatFixed(outcome.interpolation.maxMm * 1000.0, 1) + " um of the chords";
    if (result.originalInterpolation) {
        text +=
            " (original " + formatFixed(result.originalInterpolation->maxMm * 1000.0, 1) + " um)";
    }
    text += " as a control without tool-centre-point interpolation moves the axes\n";
    return text;
}

// "clearance    ball >= -0.007, shank >= 0.006, holder >= 5.000 mm against demo_blade.step
// (input 0 issues, output 0)": the written program's minima, or the input's without one.
std::string clearanceSummary(const CadCheckResult& check) {
    const cad::ClearanceReport& shown = check.rescheduled ? *check.rescheduled : check.original;
    const cad::RecordClearance minimum = cad::minimumOf(shown.records);
    std::string text = "clearance    ball >= " + formatFixed(minimum.ball, 3) +
                       ", shank >= " + formatFixed(minimum.shank, 3) +
                       ", holder >= " + formatFixed(minimum.holder, 3) + " mm against " +
                       check.source + " (input " + std::to_string(check.original.issues.size()) +
                       " issues";
    if (check.rescheduled) {
        text += ", output " + std::to_string(check.rescheduled->issues.size());
    }
    return text + ")\n";
}

std::string comparisonSummary(const compare::Comparison& comparison,
                              const kinematics::MachineModel& machine) {
    using kinematics::AxisId;
    const std::string table = letterOf(machine, AxisId::A);
    std::string text = "comparison   method            " + table + " rev.  " + table +
                       " peak acc. (deg/s^2)  T1 (s)\n";
    for (const compare::MethodResult& method : comparison.methods) {
        std::string name = method.method;
        name.resize(std::max<std::size_t>(name.size(), 18), ' ');
        std::string reversals = std::to_string(method.profile.aReversals.count);
        reversals.resize(std::max<std::size_t>(reversals.size(), 8), ' ');
        std::string peak =
            formatFixed(units::radToDeg(method.profile.axis(AxisId::A).peakAcceleration), 0);
        peak.resize(std::max<std::size_t>(peak.size(), 23), ' ');
        text += "             " + name + reversals + peak + formatFixed(method.t1.time, 1) + "\n";
    }
    for (const std::string& reason : comparison.missingFigures()) {
        text += "not computed " + reason + "\n";
    }
    return text;
}

} // namespace

std::string cycleTimeStatus(const JobResult& result) {
    const RescheduleOutcome* outcome = result.rescheduled ? &*result.rescheduled : nullptr;
    const auto times = [](double before, std::optional<double> after) {
        return formatFixed(before, 1) + (after ? " -> " + formatFixed(*after, 1) : "") + " s";
    };
    std::string blocks =
        "block-by-block " +
        times(result.blockByBlock.time,
              outcome ? std::optional<double>(outcome->blockByBlock.time) : std::nullopt);
    std::string lookAhead;
    if (result.timeOptimal) {
        lookAhead = "look-ahead T2 " + times(result.timeOptimal->time,
                                             outcome && outcome->timeOptimal
                                                 ? std::optional<double>(outcome->timeOptimal->time)
                                                 : std::nullopt);
    }
    if (result.machine.controller.planner == kinematics::Planner::BlockByBlock) {
        return blocks + " (this machine)" + (lookAhead.empty() ? "" : ", " + lookAhead);
    }
    return lookAhead.empty() ? blocks : lookAhead + " (this machine), " + blocks;
}

std::string formatSummary(const JobResult& result) {
    const analysis::AxisProfile& profile = result.original;
    auto number = [](double value, int decimals) { return formatFixed(value, decimals); };
    using kinematics::AxisId;
    const auto& a = profile.axes[static_cast<int>(AxisId::A)];
    std::string text;
    const auto dialect = result.program.dialect();
    text += "program      " + result.program.path().sourceFile + " (" +
            io::toString(result.program.format()) +
            (dialect && *dialect != io::NcDialect::Iso ? std::string(" ") + io::toString(*dialect)
                                                       : std::string()) +
            ", " + std::to_string(result.program.path().records.size()) + " records, " +
            std::to_string(result.pass.count) + " in the cutting pass)\n";
    text += "machine      " + result.machine.name + "\n";
    text += "path         " + number(profile.pathLength, 1) + " mm at " +
            number(units::perSecondToPerMinute(profile.feed), 0) + " mm/min, " +
            number(profile.cycleTime, 1) + " s\n";
    const std::string table = letterOf(result.machine, AxisId::A);
    text += table + " axis       " + std::to_string(profile.aReversals.count) +
            " reversals, travel " + number(units::radToDeg(profile.aReversals.travel), 1) +
            " deg (" + number(units::radToDeg(profile.aReversals.backwardTravel), 1) +
            " deg backwards)\n";
    text += table + " peaks      velocity " + number(units::radToDeg(a.peakVelocity), 1) +
            " deg/s, acceleration " + number(units::radToDeg(a.peakAcceleration), 0) + " deg/s^2\n";
    for (std::size_t word = 0; word < 3; ++word) { // X Y Z in the program's order
        const AxisId axis = result.machine.axisOfWord(word);
        const auto& series = profile.axes[static_cast<int>(axis)];
        text += letterOf(result.machine, axis) + " peaks      velocity " +
                number(series.peakVelocity, 1) + " mm/s, acceleration " +
                number(series.peakAcceleration, 0) + " mm/s^2\n";
    }
    text += "T1           " + number(result.constantFeed.time, 1) + " s at an achievable feed of " +
            number(units::perSecondToPerMinute(result.constantFeed.achievableFeed), 0) +
            " mm/min (bound by " + letterOf(result.machine, result.constantFeed.bindingAxis) +
            ")\n";
    if (result.rescheduled) {
        text += rescheduledSummary(result);
    }
    text += lostMotionSummary(result);
    if (result.comparison) {
        text += comparisonSummary(*result.comparison, result.machine);
    }
    if (result.cadCheck) {
        text += clearanceSummary(*result.cadCheck);
    }
    for (const std::string& warning : result.warnings) {
        text += "warning      " + warning + "\n";
    }
    return text;
}

} // namespace bladeaxis::job
