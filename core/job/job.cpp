#include "core/job/job.h"

#include "core/analysis/axis_profile.h"
#include "core/analysis/block_planner.h"
#include "core/analysis/time_optimal.h"
#include "core/analysis/time_optimal_sweep.h"
#include "core/base/file_io.h"
#include "core/base/free_storage.h"
#include "core/base/number_io.h"
#include "core/blade/presets.h"
#include "core/cad/blade_surface.h"
#include "core/geometry/angles.h"
#include "core/job/demo_program.h"
#include "core/job/job_stages.h"
#include "core/job/output_paths.h"
#include "core/job/tool_radius.h"
#include "core/kinematics/kinematics.h"
#include "core/kinematics/machine_file.h"
#include "core/kinematics/travel_limits.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>

namespace bladeaxis::job {

namespace {

using toolpath::ClRecord;
using toolpath::MotionKind;

} // namespace

Result<kinematics::MachineModel> loadMachine(const JobSpec& spec) {
    if (spec.machineFile.empty()) {
        return kinematics::defaultBladeMachine();
    }
    auto machine = kinematics::loadMachineFile(spec.machineFile);
    if (!machine && (machine.error().code == ErrorCode::FileNotFound ||
                     machine.error().code == ErrorCode::FileUnreadable)) {
        // A missing machine file is a machine-file problem for the user (exit code 4).
        Error error = machine.error();
        error.code = ErrorCode::MachineFile;
        error.message = "cannot read the machine file: " + error.message;
        return std::unexpected(error);
    }
    return machine;
}

namespace {

CuttingPass longestFeedRun(const std::vector<ClRecord>& records) {
    CuttingPass best;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= records.size(); ++i) {
        const bool feed = i < records.size() && records[i].motion == MotionKind::Feed;
        if (feed) {
            continue;
        }
        if (i - start > best.count) {
            best = {start, i - start};
        }
        start = i + 1;
    }
    return best;
}

// Machine axes of the pass with A continuous: G-code gives them (modulo A is unwrapped),
// CL data goes through the inverse kinematics with A unwrapped record to record. A program in
// tool-tip programming (TRAORI, M128) gives the tip in the workpiece frame: its machine axes,
// the ones that move and that the analysis is about, come from the inverse kinematics too, on
// the programmed A's branch.
Result<std::vector<kinematics::MachineAxes>> passAxes(std::span<const ClRecord> pass,
                                                      const kinematics::MachineModel& machine,
                                                      bool toolTip, const std::string& file) {
    std::vector<kinematics::MachineAxes> axes;
    axes.reserve(pass.size());
    double previousA = 0.0;
    for (const ClRecord& record : pass) {
        if (record.axes && !toolTip) {
            kinematics::MachineAxes value = *record.axes;
            if (!axes.empty() && machine.aMode == kinematics::RotaryMode::Modulo) {
                value.a = geometry::unwrapNear(value.a, previousA);
            }
            axes.push_back(value);
        } else {
            double reference = previousA;
            if (record.axes) {
                reference =
                    axes.empty() ? record.axes->a : geometry::unwrapNear(record.axes->a, previousA);
            }
            auto value =
                kinematics::inverseKinematics(machine.chain, {record.tip, record.axis}, reference);
            if (!value) {
                Error error = value.error();
                error.where = {file, record.line, 0};
                return std::unexpected(error);
            }
            axes.push_back(*value);
        }
        previousA = axes.back().a;
    }
    return axes;
}

} // namespace

// The program read and parsed: the document keeps the one copy of the text the writer needs,
// or without keep.inputTextInMemory none (the rewrite reads the file again).
Result<io::LoadedProgram> loadInput(const JobSpec& spec, const Retention& keep,
                                    const kinematics::MachineModel& machine,
                                    std::optional<double>& toolRadius, const io::ReadWatch& watch) {
    if (spec.demo) {
        auto demo = demoProgram(machine);
        if (!demo) {
            return std::unexpected(demo.error());
        }
        toolRadius = demo->toolRadius;
        return io::parseProgram(demo->text, kDemoProgramName, io::ProgramFormat::Gcode, machine);
    }
    if (spec.program.empty()) {
        return makeError(ErrorCode::InvalidArgument, "no input program given (or use --demo)");
    }
    if (spec.programText) {
        return io::readProgramText(*spec.programText, spec.program, machine, spec.read, watch);
    }
    // The file as it was before and after its text was read: the same file, unchanged, is the
    // one a dropped text can be read again from.
    std::optional<FileSnapshot> before;
    if (!keep.inputTextInMemory) {
        if (auto snapshot = snapshotOf(spec.program)) {
            before = std::move(*snapshot);
        }
    }
    // The text read is the parsed program's own: no copy of it stands beside the records.
    auto program = io::loadProgram(spec.program, machine, spec.read, watch);
    if (program && before) {
        if (const auto after = snapshotOf(spec.program); after && after->sameFileAs(*before)) {
            program->dropTextKeptInItsFile(*after);
        }
    }
    return program;
}

Status analyse(JobResult& result, const JobSpec& spec, const CancelToken& cancel) {
    const auto& records = result.program.path().records;
    result.pass = longestFeedRun(records);
    if (result.pass.count < 2) {
        return makeError(ErrorCode::Parse,
                         "expected at least two consecutive feed moves, found " +
                             std::to_string(result.pass.count),
                         {result.program.path().sourceFile});
    }
    const std::span<const ClRecord> pass(records.data() + result.pass.first, result.pass.count);
    const std::optional<bool> toolTip =
        io::programsToolTip(result.program, result.pass.first, result.pass.count);
    if (!toolTip) {
        return makeError(ErrorCode::Parse,
                         "tool-tip programming (TRAORI / M128 / FUNCTION TCPM) is switched on or "
                         "off inside the cutting pass: expected it in the same state for every "
                         "move of the pass",
                         {result.program.path().sourceFile, pass.front().line, 0});
    }
    result.pass.toolTip = *toolTip;
    auto axes = passAxes(pass, result.machine, *toolTip, result.program.path().sourceFile);
    if (!axes) {
        return std::unexpected(axes.error());
    }
    result.axes = std::make_shared<const std::vector<kinematics::MachineAxes>>(std::move(*axes));
    if (const auto excess = kinematics::firstTravelExcess(*result.axes, result.machine)) {
        result.warnings.push_back(
            result.program.path().sourceFile + ":" + std::to_string(pass[excess->index].line) +
            ": the input program drives " + kinematics::describe(*excess, result.machine) +
            " of the machine '" + result.machine.name +
            "' (is the machine file the machine it runs on?)");
    }
    analysis::AxisProfileOptions options = spec.analysis;
    options.filterSeriesBytesAtOnce = kFilterSeriesBytesAtOnce;
    options.blockTimes = passIsBlockTimed(result.program, result.pass.first, result.pass.count);
    options.cancel = &cancel;
    if (result.toolRadius) {
        options.toolRadius = *result.toolRadius;
    }
    auto profile = analysis::analyseAxisMotion(result.axes, {.records = pass}, options);
    if (!profile) {
        return std::unexpected(profile.error());
    }
    result.original = std::move(*profile);
    result.constantFeed = analysis::constantFeedTime(result.original, result.machine, false);
    // The models after the profile each take a few tenths of a second on millions of blocks:
    // a cancelled job stops between them.
    if (auto status = checkCancelled(cancel); !status) {
        return status;
    }
    result.blockByBlock =
        analysis::blockByBlockTime(*result.axes, {.records = pass}, result.machine);
    if (auto status = checkCancelled(cancel); !status) {
        return status;
    }
    if (result.toolRadius) {
        result.originalInterpolation = kinematics::interpolationDeviation(
            *result.axes, result.machine.chain, *result.toolRadius, 3, &cancel);
    }
    if (auto status = checkCancelled(cancel); !status) { // a cut-short deviation is no figure
        return status;
    }
    result.originalLostMotion = analysis::lostMotion(result.original, result.machine);
    return {};
}

namespace {

// A CAD model is placed in the program's workpiece frame; on a machine whose table turns about
// Y the engine's frame is that one turned a quarter turn about Z (MachineModel::toEngineFrame).
cad::Placement placementInEngineFrame(const cad::Placement& placement,
                                      const kinematics::MachineModel& machine) {
    const Mat3 toEngine = machine.engineFrameRotation();
    return {toEngine * placement.rotation, toEngine * placement.translation};
}

Result<cad::CadShape> bladeShape(const JobSpec& spec, const kinematics::MachineModel& machine) {
    if (!spec.cad.file.empty()) {
        return cad::readCadFile(
            spec.cad.file, placementInEngineFrame(cad::toPlacement(spec.cad.placement), machine));
    }
    auto blade = blade::demoBlade(); // the demo program was generated on it
    if (!blade) {
        return std::unexpected(blade.error());
    }
    return cad::makeBladeSurface(*blade);
}

} // namespace

// Why the file gave no radius, in the words of its format.
std::string radiusSourceHint(io::ProgramFormat format) {
    return format == io::ProgramFormat::Gcode
               ? "the G-code states no ball end in a header comment such as (T1 D=8. CR=4.) or "
                 "(ball end R=4 mm)"
               : "the CL data has no CUTTER or TLDATA statement";
}

// The radius the job uses: the command line's (or job file's) over the file's, with a warning
// when they differ (toolRadiusConflict, the rule the window applies too), since the channel and
// every ball centre depend on it.
std::optional<double> jobToolRadius(const JobSpec& spec, std::optional<double> generated,
                                    const io::LoadedProgram& program,
                                    std::vector<std::string>& warnings) {
    if (std::string conflict = toolRadiusConflict(spec.toolRadius, program); !conflict.empty()) {
        warnings.push_back(std::move(conflict));
    }
    return spec.toolRadius ? spec.toolRadius : generated ? generated : program.path().toolRadius;
}

// The largest ball a blade finishing job plausibly uses, with a wide margin: a radius beyond it
// is a typo or a unit slip (1e12, a diameter in micrometres) whose ball centres lie metres off
// the part, and every figure computed from them would be nonsense.
constexpr double kMaxToolRadiusMm = 500.0;

Status checkToolRadius(std::optional<double> radius, const toolpath::Toolpath& path) {
    if (!radius || (*radius > 0.0 && *radius <= kMaxToolRadiusMm)) {
        return {};
    }
    return makeError(ErrorCode::InvalidArgument,
                     "a ball radius of " + formatShortest(*radius) +
                         " mm is not a ball-end cutter: expected more than 0 and at most " +
                         formatShortest(kMaxToolRadiusMm) +
                         " mm (--tool-radius, job key tool_radius_mm, or the file's CUTTER)",
                     {path.sourceFile});
}

bool checksCad(const JobSpec& spec) {
    return !spec.cad.file.empty() || spec.demo;
}

// The check's spec with the tool it will use, validated before any scheduling: a tool the check
// cannot model would otherwise stop the job only after the whole schedule was computed.
Result<CadCheckSpec> cadCheckSpec(const JobSpec& spec, std::optional<double> toolRadius) {
    if (!toolRadius || !(*toolRadius > 0.0)) {
        return makeError(ErrorCode::InvalidArgument,
                         "the clearance check needs the ball radius: give --tool-radius");
    }
    CadCheckSpec checked = spec.cad;
    // The tool's taper is the one the channel was built for (spec §2.3).
    auto tool = jobTool(spec.cad.tool, *toolRadius, spec.parameters.taperHalfAngleRad);
    if (!tool) {
        return std::unexpected(tool.error());
    }
    checked.tool = *tool;
    return checked;
}

Status cadCheckInto(JobResult& result, const JobSpec& spec, const CadCheckSpec& cadSpec,
                    ProgressSink& progress) {
    auto shape = bladeShape(spec, result.machine);
    if (!shape) {
        return std::unexpected(shape.error());
    }
    CuttingPassView view;
    view.original =
        std::span(result.program.path().records).subspan(result.pass.first, result.pass.count);
    view.sourceFile = result.program.path().sourceFile;
    std::vector<toolpath::ClRecord> rescheduled;
    if (result.rescheduled) {
        rescheduled = rescheduledRecords(view.original, *result.rescheduled);
        view.rescheduled = rescheduled;
        // Layers share their junction sample; the clearance report wants a partition.
        const auto& layers = result.rescheduled->schedule.layers;
        for (std::size_t k = 0; k < layers.size(); ++k) {
            const std::size_t last =
                k + 1 < layers.size() ? layers[k + 1].first - 1 : layers[k].last;
            view.layers.emplace_back(layers[k].first, last);
        }
    }
    const std::string source =
        spec.cad.file.empty() ? "demo blade surface" : spec.cad.file.filename().string();
    auto checked = runCadCheck(cadSpec, *shape, source, *result.toolRadius, view);
    if (!checked) {
        return std::unexpected(checked.error());
    }
    result.cadCheck = std::move(*checked);
    if (result.rescheduled) {
        std::vector<Vec3> centres;
        for (const auto& record : view.original) {
            centres.push_back(toolpath::ballCentre(record, *result.toolRadius));
        }
        auto sections =
            compareConcaveExits(*shape, result.rescheduled->schedule, centres, *result.toolRadius);
        if (!sections) {
            return std::unexpected(sections.error());
        }
        result.cadCheck->sections = std::move(*sections);
    }
    const auto& inputIssues = result.cadCheck->original.issues;
    if (!inputIssues.empty()) {
        result.warnings.push_back(
            "the input program's tool already gouges or collides with " + source + " at " +
            std::to_string(inputIssues.size()) +
            " CL points (first: " + cad::describe(inputIssues.front(), view.sourceFile) +
            "); re-scheduling keeps the ball centres, so their gouges stay");
        // Now, not only in the summary: a refused export prints no summary.
        progress.warning(result.warnings.back());
    }
    return {};
}

namespace {

// The pass, its axes, the radius and the analysis every method is evaluated with.
compare::EvaluationContext evaluationContext(const JobResult& result, const JobSpec& spec) {
    compare::EvaluationContext context;
    context.pass =
        std::span(result.program.path().records).subspan(result.pass.first, result.pass.count);
    context.originalAxes = *result.axes;
    context.toolRadius = result.toolRadius.value_or(0.0);
    context.machine = &result.machine;
    context.analysis = spec.analysis;
    context.analysis.toolRadius = context.toolRadius;
    return context;
}

} // namespace

Status compareInto(JobResult& result, const JobSpec& spec, const CancelToken& cancel) {
    if (!result.toolRadius || !(*result.toolRadius > 0.0)) {
        return makeError(ErrorCode::InvalidArgument,
                         "the ball radius is not known: give --tool-radius (" +
                             radiusSourceHint(result.program.format()) + ")");
    }
    const compare::EvaluationContext context = evaluationContext(result, spec);
    compare::CompareOptions options;
    options.best = spec.parameters;
    options.optimum = spec.compareOptimum;
    // The job's schedule: same centres, same parameters; an edited one is not the preset's.
    if (result.rescheduled && spec.layerEdits.empty()) {
        options.bestSchedule = &result.rescheduled->schedule;
        options.bestScheduleSeconds = result.rescheduled->stageSeconds.schedule;
    }
    if (spec.sweepLimits) {
        options.sweepFactors = analysis::defaultRotarySweepFactors();
    }
    auto comparison = compare::compareMethods(context, options, cancel);
    if (!comparison) {
        Error error = comparison.error();
        if (error.where.file.empty()) {
            error.where.file = result.program.path().sourceFile;
        }
        return std::unexpected(error);
    }
    result.comparison = std::move(*comparison);
    return {};
}

// The program's letters of the table and the tilt and the tilt's sign, for the program checks'
// messages.
RotaryLetters rotaryLetters(const kinematics::MachineModel& machine) {
    return {machine.letter(kinematics::AxisId::A), machine.letter(kinematics::AxisId::B),
            machine.programWord(kinematics::AxisId::B).sign};
}

namespace {

std::span<ClRecord> mutablePass(JobResult& result) {
    return std::span(result.program.mutablePath().records)
        .subspan(result.pass.first, result.pass.count);
}

AngleWordsRead angleWordsRead(const io::LoadedProgram& program, const io::ReadOptions& read) {
    if (program.format() != io::ProgramFormat::Gcode) {
        return AngleWordsRead::NoAngleWords;
    }
    if (!read.angleUnit) {
        return AngleWordsRead::Inferred;
    }
    return *read.angleUnit == io::AngleUnit::Radians ? AngleWordsRead::GivenRadians
                                                     : AngleWordsRead::GivenDegrees;
}

// A refusal of the re-scheduling turned into an analysis's warning: the figures that follow
// describe the program as read.
std::string analysisOnlyNote(const Error& refusal) {
    std::string note = refusal.toString();
    if (note.ends_with(". Nothing was written")) {
        note.resize(note.size() - std::string_view(". Nothing was written").size());
    }
    return note + "; the analysis's figures take the program as read";
}

} // namespace

// The four-axis condition on B before scheduling: a re-scheduling job refuses a varying tilt
// (nothing would be right about the written program), an analysis only reports it. Noise within
// the tolerance is snapped to the median after the original motion was analysed, so the
// figures of the original describe the program as written.
Status checkTilt(JobResult& result, const JobSpec& spec, ProgressSink& progress) {
    const std::string& file = result.program.path().sourceFile;
    const RotaryLetters letters = rotaryLetters(result.machine);
    auto tilt = checkConstantTilt(mutablePass(result), file, spec.check, letters);
    if (!tilt) {
        if (spec.reschedule || spec.compare) {
            return std::unexpected(tilt.error());
        }
        result.warnings.push_back(tilt.error().toString());
        progress.warning(result.warnings.back());
        return {};
    }
    const bool knownRadius = result.toolRadius && *result.toolRadius > 0.0;
    if (!knownRadius && (spec.reschedule || spec.compare)) {
        return {}; // the re-scheduling refuses an unknown radius with its own message
    }
    // An analysis alone reports figures for what it read, so it warns where a re-scheduling
    // refuses: a pass that does not turn is most often radians read as degrees. Without a
    // radius the tips turn as the ball centres do.
    if (auto helical = checkHelical(mutablePass(result), result.toolRadius.value_or(0.0), file,
                                    letters, angleWordsRead(result.program, spec.read));
        !helical) {
        if (spec.reschedule || spec.compare) {
            return helical;
        }
        result.warnings.push_back(analysisOnlyNote(helical.error()));
        progress.warning(result.warnings.back());
    }
    if (!knownRadius) {
        return {};
    }
    tilt->snappedRecords = snapTilt(mutablePass(result), tilt->medianRad, *result.toolRadius);
    if (const std::string note = describeSnap(*tilt, file, letters); !note.empty()) {
        result.warnings.push_back(note);
        progress.warning(note);
    }
    return {};
}

Status appendEditedMethod(JobResult& result, const JobSpec& spec) {
    if (!result.comparison) {
        return {};
    }
    std::vector<compare::MethodResult>& methods = result.comparison->methods;
    std::erase_if(methods, [](const compare::MethodResult& method) {
        return method.method == kEditedMethod;
    });
    if (!result.rescheduled || spec.layerEdits.empty()) {
        return {}; // the edits were undone: no edited row any more
    }
    compare::EvaluationContext context = evaluationContext(result, spec);
    context.reference = &result.comparison->reference;
    auto edited = compare::evaluateMethod(
        context, kEditedMethod,
        std::to_string(spec.layerEdits.size()) + " layer(s) edited over the job's preset",
        result.rescheduled->schedule.newAxes, result.rescheduled->stageSeconds.schedule);
    if (!edited) {
        return std::unexpected(edited.error());
    }
    methods.push_back(std::move(*edited));
    return {};
}

} // namespace bladeaxis::job
