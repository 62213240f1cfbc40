#include "app/batch/batch_options.h"

#include "app/batch/man_page.h"
#include "app/subcommands.h"
#include "core/base/nearest_name.h"
#include "core/base/number_io.h"
#include "core/base/output_set.h"
#include "core/base/units.h"
#include "core/base/version.h"
#include "core/job/job_file.h"
#include "core/job/output_paths.h"
#include "core/job/parameter_schema.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace bladeaxis::app {

namespace {

constexpr const char* kExitCodeHelp = R"(
Exit codes:
  0  success
  1  internal error (a bug: please report it with the input)
  2  bad command line
  3  input program missing, unreadable or malformed (the message names file:line:column)
  4  machine file missing or invalid
  5  geometry the method cannot handle (NaN, unreachable pose, degenerate path,
     blade CAD that does not fit the program) or a failed output check (re-read
     verification, channel, modulo A step, gouge or collision without --force); a
     layer without a monotone path keeps its original orientation with a warning
  6  an output could not be written (inputs are never overwritten)
  7  cancelled (Ctrl+C or SIGTERM in batch: nothing is written))";

// Numbers are parsed with the project's locale-independent parser, not CLI11's.
struct NumberOption {
    std::string text;
    const char* name;
    bool positive;
};

Result<std::optional<double>> readNumber(const NumberOption& option) {
    if (option.text.empty()) {
        return std::optional<double>{};
    }
    const auto value = parseNumber(option.text);
    if (!value || (option.positive && !(*value > 0.0))) {
        return makeError(ErrorCode::InvalidArgument, std::string(option.name) + ": expected a " +
                                                         (option.positive ? "positive " : "") +
                                                         "number, got '" + option.text + "'");
    }
    return std::optional<double>{*value};
}

struct RawOptions {
    std::string program, machine, out, generate, feedReference = "tip", derivatives = "filter";
    std::string profile = "naca-high-camber", format = "gcode";
    std::string angleUnit, columns, dialect;
    NumberOption toolRadius{"", "--tool-radius", true};
    NumberOption feed{"", "--feed", true};
    NumberOption bTolerance{"", "--b-tolerance-deg", true};
    NumberOption channelTolerance{"", "--channel-tolerance-deg", true};
    NumberOption revolutions{"", "--revolutions", true};
    NumberOption pitch{"", "--pitch", true};
    NumberOption lead{"", "--lead-deg", false};
    NumberOption tilt{"", "--tilt-deg", false};
    NumberOption tolerance{"", "--tolerance", true};
    NumberOption filterMs{"", "--filter-ms", true};
    NumberOption stickOut{"", "--stick-out", true};
    NumberOption holderRadius{"", "--holder-radius", true};
    NumberOption holderLength{"", "--holder-length", true};
    std::string cad;
    std::vector<std::string> cadTranslate;
    std::vector<std::string> cadRotate;
    bool force = false;
    std::string outputProgram, outputCl, preset, jobFile;
    std::map<std::string, std::string> parameters; // schema key -> text, when given
    std::uint64_t seed = 1;
    bool seedGiven = false;
    bool batch = false, demo = false, json = false, quiet = false, version = false,
         progress = false, noProgress = false, manPage = false;
    bool analyseOnly = false;
    bool compare = false;
    bool sweep = false;
    bool noOptimum = false;
    bool reproduce = false;
    int blades = 36;
};

std::string optionName(const std::string& key) {
    std::string name = "--" + key;
    std::replace(name.begin(), name.end(), '_', '-');
    return name;
}

// One command-line option per entry of the parameter schema (docs/architecture.md, Conventions).

// A preset value as a person reads it: 12 significant digits, so that 30 deg held in radians
// shows as -30, not -29.999999999999996 (job files keep the exact value).
std::string forHelp(const std::string& value) {
    const auto number = parseNumber(value);
    if (!number || *number == 0.0 || !std::isfinite(*number)) {
        return value;
    }
    const double scale = std::pow(10.0, 11.0 - std::floor(std::log10(std::abs(*number))));
    return formatShortest(std::round(*number * scale) / scale);
}

// The value's type as CLI11 names it in --help (the values are read as text, which it would
// show as TEXT, and checked by the schema).
std::string helpTypeName(job::ParameterInfo::Kind kind) {
    switch (kind) {
    case job::ParameterInfo::Kind::Number:
        return "FLOAT";
    case job::ParameterInfo::Kind::Integer:
        return "INT";
    case job::ParameterInfo::Kind::Flag:
        return "BOOLEAN";
    case job::ParameterInfo::Kind::Choice:
        break;
    }
    return "TEXT";
}

void defineScheduleOptions(CLI::App& cli, RawOptions& raw) {
    auto* group = cli.add_option_group(
        "Scheduling", "Parameters of the S-theta re-scheduling (docs/method.md, docs/job-file.md)");
    group->add_option("-o,--output", raw.outputProgram,
                      "Write the re-scheduled program here; - writes it to standard output (the "
                      "summary then goes to standard error)");
    group->add_option("--cl-output", raw.outputCl,
                      "Also write the re-scheduled toolpath as CL data (APT) here; - writes it to "
                      "standard output (the summary then goes to standard error)");
    group->add_option("--preset", raw.preset, "faithful (the paper's rules) or best (default)")
        ->check(CLI::IsMember({"faithful", "best"}));
    group->add_option("--job", raw.jobFile,
                      "Job file (JSON, docs/job-file.md); options given here win");
    group->add_flag("--analyse-only", raw.analyseOnly,
                    "Analyse the program without re-scheduling it");
    group->add_flag("--compare", raw.compare,
                    "Also compare with the other methods: compare.json, compare.csv, report.html");
    group->add_flag("--sweep", raw.sweep,
                    "With --compare: machining times with the rotary-axis limits x0.5 ... x2");
    group->add_flag("--no-optimum", raw.noOptimum,
                    "With --compare: leave out the optimal schedules (slow on large programs)");
    for (const job::ParameterInfo& info : job::scheduleParameterSchema()) {
        std::string help = info.help;
        if (!info.unit.empty()) {
            help += " [" + info.unit + "]";
        }
        if (!info.choices.empty()) {
            help += " {";
            for (const std::string& choice : info.choices) {
                help += (help.back() == '{' ? "" : ",") + choice;
            }
            help += "}";
        }
        help += " (best: " + forHelp(info.get(scheduling::bestPreset())) +
                ", faithful: " + forHelp(info.get(scheduling::faithfulPreset())) + ")";
        group
            ->add_option_function<std::string>(
                optionName(info.key),
                [&raw, key = info.key](const std::string& value) { raw.parameters[key] = value; },
                help)
            ->type_name(helpTypeName(info.kind));
    }
}

void defineOptions(CLI::App& cli, RawOptions& raw) {
    cli.add_flag("--batch", raw.batch, "Run headless: no window, no display needed");
    cli.add_option("program", raw.program,
                   "NC program (G-code), CL data (APT/CLSF) or point table to analyse; - reads "
                   "standard input");
    cli.add_flag("--demo", raw.demo, "Use the built-in demo blade program");
    auto* cad = cli.add_option_group("Blade CAD", "Clearance check against the real blade");
    cad->add_option("--cad", raw.cad,
                    "Blade CAD (STEP or IGES) to check the tool against; an output program "
                    "that gouges or collides anywhere is refused (exit 5)");
    cad->add_option("--cad-translate", raw.cadTranslate,
                    "Move the CAD blade by X Y Z mm into the program's workpiece frame")
        ->expected(3)
        ->type_name("FLOAT");
    cad->add_option("--cad-rotate-deg", raw.cadRotate,
                    "Rotate the CAD blade by RX RY RZ degrees about the X, then Y, then Z axis "
                    "of the workpiece frame (x = rotary axis), before --cad-translate")
        ->expected(3)
        ->type_name("FLOAT");
    cad->add_option("--stick-out", raw.stickOut.text, "Tool tip to holder face, mm (default 50)")
        ->type_name("FLOAT");
    cad->add_option("--holder-radius", raw.holderRadius.text, "Holder radius, mm (default 20)")
        ->type_name("FLOAT");
    cad->add_option("--holder-length", raw.holderLength.text, "Holder length, mm (default 60)")
        ->type_name("FLOAT");
    cad->add_flag("--force", raw.force,
                  "Write the program even if the clearance check finds gouges or collisions");
    cli.add_option("--machine", raw.machine,
                   "Machine file (JSON); default: built-in blade machine");
    cli.add_option("--tool-radius", raw.toolRadius.text, "Ball radius R in mm (overrides the file)")
        ->type_name("FLOAT");
    cli.add_option("--angle-unit", raw.angleUnit,
                   "Unit of the A/B words of a G-code program: deg or rad (needed when the file "
                   "could be either; written programs keep it)")
        ->check(CLI::IsMember({"deg", "rad"}));
    cli.add_option("--dialect", raw.dialect,
                   "NC dialect of a G-code program: iso, sinumerik or heidenhain (default: from "
                   "the content, then the extension .mpf/.spf or .h)")
        ->check(CLI::IsMember({"iso", "sinumerik", "heidenhain"}));
    cli.add_option("--columns", raw.columns,
                   "Columns of a point table without a header line, e.g. x,y,z,i,j,k");
    cli.add_option("--b-tolerance-deg", raw.bTolerance.text,
                   "Largest deviation of B from its median that still counts as a four-axis "
                   "pass; B is then snapped to the median (default 0.01)");
    cli.add_option("--channel-tolerance-deg", raw.channelTolerance.text,
                   "Largest distance of the CAM orientation outside the feasible channel "
                   "(default 30)")
        ->type_name("FLOAT");
    cli.add_option("--out", raw.out, "Output folder for report.json, axes.csv and layers.csv");
    cli.add_option("--feed", raw.feed.text, "Evaluate at this constant feed, mm/min")
        ->type_name("FLOAT");
    cli.add_option("--feed-reference", raw.feedReference, "Path parameter: tip or centre")
        ->check(CLI::IsMember({"tip", "centre"}));
    cli.add_option(
           "--derivatives", raw.derivatives,
           "filter (default: a controller that smooths each axis over --filter-ms at the "
           "programmed feed, docs/figures.md), spline (through the points that carry motion), "
           "raw-spline (through every point) or fd (finite differences)")
        ->check(CLI::IsMember({"spline", "raw-spline", "fd", "filter"}));
    cli.add_option("--filter-ms", raw.filterMs.text,
                   "Smoothing time of --derivatives filter (the default figures' controller), ms "
                   "(default 8)")
        ->type_name("FLOAT");
    cli.add_flag("--json", raw.json,
                 "Print report.json to standard output instead of the summary, and a refusal as "
                 "a JSON error object; not with -o - or --cl-output -");
    cli.add_flag("-q,--quiet", raw.quiet, "Print nothing but errors");
    cli.add_flag("--progress", raw.progress,
                 "Show the running stage on standard error (the default when it is a terminal)");
    cli.add_flag("--no-progress", raw.noProgress,
                 "Never show the running stage, not even on a terminal");
    cli.add_flag("--version", raw.version, "Print the version and exit");
    // For the build, which installs its output as bladeaxis.1; not listed in --help.
    cli.add_flag("--man", raw.manPage, "Print the manual page (roff) and exit")->group("");
    auto* generate = cli.add_option_group("Generation", "Write a synthetic blade program");
    generate->add_option("--generate", raw.generate,
                         "Write a generated helical blade program here; - writes it to standard "
                         "output");
    generate
        ->add_option("--profile", raw.profile, "naca-high-camber, naca-weak, symmetric, turbine")
        ->check(CLI::IsMember({"naca-high-camber", "naca-weak", "symmetric", "turbine"}));
    generate->add_option("--format", raw.format, "gcode or apt")
        ->check(CLI::IsMember({"gcode", "apt"}));
    generate->add_option("--revolutions", raw.revolutions.text, "Number of revolutions")
        ->type_name("FLOAT");
    generate
        ->add_option("--pitch", raw.pitch.text, "Advance along the rotary axis per revolution, mm")
        ->type_name("FLOAT");
    generate->add_option("--lead-deg", raw.lead.text, "Lead angle of the original CAM orientation")
        ->type_name("FLOAT");
    generate->add_option("--tilt-deg", raw.tilt.text, "Fixed B tilt")->type_name("FLOAT");
    generate
        ->add_option("--tolerance", raw.tolerance.text, "Chordal tolerance on the ball centre, mm")
        ->type_name("FLOAT");
    generate->add_option("--seed", raw.seed, "Random seed (lead-angle noise, family members)");
    auto* study = cli.add_option_group("Reproduction", "The comparison on a synthetic family");
    study->add_flag("--reproduce", raw.reproduce,
                    "Compare every method on a seeded family of synthetic blades and print the "
                    "median and IQR of every reduction (reproduce.json, reproduce.csv in --out)");
    study->add_option("--blades", raw.blades, "Number of blades of the family (default 36)")
        ->check(CLI::Range(1, 1000));
    defineScheduleOptions(cli, raw);
}

// Job file first, then the preset, then single parameters: the most specific wins.
Status applySchedule(const RawOptions& raw, BatchOptions& options) {
    if (!raw.jobFile.empty()) {
        if (auto status = job::readJobFile(raw.jobFile, options.job); !status) {
            return status;
        }
    }
    if (!raw.preset.empty()) {
        auto preset = job::presetParameters(raw.preset);
        if (!preset) {
            return std::unexpected(preset.error());
        }
        options.job.parameters = *preset;
        options.job.presetName = raw.preset;
    }
    for (const auto& [key, text] : raw.parameters) {
        if (auto status = job::findParameter(key)->set(options.job.parameters, text); !status) {
            Error error = status.error();
            error.message = optionName(key) + error.message.substr(key.size());
            return std::unexpected(error);
        }
    }
    if (!raw.outputProgram.empty()) {
        options.job.outputProgram = raw.outputProgram;
    }
    if (!raw.outputCl.empty()) {
        options.job.outputCl = raw.outputCl;
    }
    // A flag given here wins; without it, the job file's analyse_only/compare stand.
    options.job.reschedule = options.job.reschedule && !raw.analyseOnly;
    options.job.compare = options.job.compare || raw.compare || raw.sweep;
    options.job.sweepLimits = raw.sweep;
    options.job.compareOptimum = options.job.compareOptimum && !raw.noOptimum;
    if (!options.job.reschedule &&
        (!options.job.outputProgram.empty() || !options.job.outputCl.empty())) {
        return makeError(
            ErrorCode::InvalidArgument,
            "analysing only (--analyse-only, or analyse_only in the job file) and an output "
            "program (--output, --cl-output, output_program) exclude each other");
    }
    return {};
}

Status applyNumbers(const RawOptions& raw, BatchOptions& options) {
    auto toolRadius = readNumber(raw.toolRadius);
    auto feed = readNumber(raw.feed);
    auto revolutions = readNumber(raw.revolutions);
    auto pitch = readNumber(raw.pitch);
    auto filterMs = readNumber(raw.filterMs);
    auto stickOut = readNumber(raw.stickOut);
    auto holderRadius = readNumber(raw.holderRadius);
    auto holderLength = readNumber(raw.holderLength);
    auto lead = readNumber(raw.lead);
    auto tilt = readNumber(raw.tilt);
    auto tolerance = readNumber(raw.tolerance);
    auto bTolerance = readNumber(raw.bTolerance);
    auto channelTolerance = readNumber(raw.channelTolerance);
    for (const auto* value :
         {&toolRadius, &feed, &revolutions, &pitch, &lead, &tilt, &tolerance, &filterMs, &stickOut,
          &holderRadius, &holderLength, &bTolerance, &channelTolerance}) {
        if (!value->has_value()) {
            return std::unexpected(value->error());
        }
    }
    if (*toolRadius) { // keeps a job file's radius unless the option is given
        options.job.toolRadius = *toolRadius;
    }
    if (*feed) {
        options.job.analysis.feedOverride = units::perMinuteToPerSecond(**feed);
        // CL data without FEDRAT (bare GOTO lists, point tables) is fed at the same feed.
        options.job.read.feedMmPerS = units::perMinuteToPerSecond(**feed);
    }
    if (*bTolerance) {
        options.job.check.tiltToleranceRad = units::degToRad(**bTolerance);
    }
    if (*channelTolerance) {
        options.job.check.channelToleranceRad = units::degToRad(**channelTolerance);
    }
    auto& tool = options.job.cad.tool;
    tool.stickOut = stickOut->value_or(tool.stickOut);
    tool.holderRadius = holderRadius->value_or(tool.holderRadius);
    tool.holderLength = holderLength->value_or(tool.holderLength);
    if (*filterMs) {
        options.job.analysis.filterSeconds = **filterMs / 1000.0;
    }
    options.generate.toolRadius = *toolRadius;
    options.generate.revolutions = *revolutions;
    options.generate.pitch = *pitch;
    options.generate.leadDeg = *lead;
    options.generate.tiltDeg = *tilt;
    options.generate.chordalTolerance = *tolerance;
    return {};
}

// X Y Z of a three-value option; empty when the option is not given (CLI11 takes three or none).
Result<std::optional<Vec3>> tripleOption(const std::vector<std::string>& texts,
                                         const std::string& option, const std::string& unit) {
    if (texts.empty()) {
        return std::nullopt;
    }
    Vec3 values = Vec3::Zero();
    for (std::size_t k = 0; k < texts.size() && k < 3; ++k) {
        auto value = parseNumber(texts[k]);
        if (!value) {
            return makeError(ErrorCode::InvalidArgument, option + ": expected three numbers (" +
                                                             unit + "), got '" + texts[k] + "'");
        }
        values[static_cast<Eigen::Index>(k)] = *value;
    }
    return values;
}

// The placement options replace the job file's values, each on its own.
Status applyCad(const RawOptions& raw, BatchOptions& options) {
    auto& cad = options.job.cad;
    if (!raw.cad.empty()) {
        cad.file = raw.cad;
    }
    cad.force = raw.force;
    auto translation = tripleOption(raw.cadTranslate, "--cad-translate", "mm");
    if (!translation) {
        return std::unexpected(translation.error());
    }
    auto rotation = tripleOption(raw.cadRotate, "--cad-rotate-deg", "degrees");
    if (!rotation) {
        return std::unexpected(rotation.error());
    }
    cad.placement.translation = translation->value_or(cad.placement.translation);
    if (*rotation) {
        cad.placement.rotationXyz = (*rotation)->unaryExpr(&units::degToRad);
    }
    return {};
}

// CLI11 takes the word after an option as its value even when that word is another option
// ("--generate --out DIR" would write a file named "--out"): a file name never starts with '-'
// here ("-" alone is standard input or output).
Status checkFileValues(const RawOptions& raw) {
    const std::pair<const char*, const std::string*> values[] = {
        {"--generate", &raw.generate},
        {"--out", &raw.out},
        {"--machine", &raw.machine},
        {"--output", &raw.outputProgram},
        {"--cl-output", &raw.outputCl},
        {"--job", &raw.jobFile},
        {"--cad", &raw.cad},
        {"--columns", &raw.columns},
    };
    for (const auto& [name, value] : values) {
        if (value->size() > 1 && value->front() == '-') {
            return makeError(ErrorCode::InvalidArgument,
                             std::string(name) + ": expected a value, got the option '" + *value +
                                 "' (give the value right after " + name + ")");
        }
    }
    return {};
}

// Standard output carries one thing a script reads, or the reader could not tell them apart:
// the program (-o -), the CL data (--cl-output -) or the JSON report (--json). Two of them are
// refused rather than one moved elsewhere silently. `--out` names a folder of three files,
// which standard output cannot hold.
Status refuseSharedStandardOutput(const RawOptions& raw) {
    if (raw.out == "-") {
        return makeError(ErrorCode::InvalidArgument,
                         "--out: names a folder for report.json, axes.csv and layers.csv, which "
                         "standard output (-) cannot hold; --json prints report.json there");
    }
    std::vector<std::string> users;
    for (const auto& [name, used] :
         {std::pair{"-o -", raw.outputProgram == "-"},
          std::pair{"--cl-output -", raw.outputCl == "-"}, std::pair{"--json", raw.json}}) {
        if (used) {
            users.emplace_back(name);
        }
    }
    if (users.size() < 2) {
        return {};
    }
    return makeError(ErrorCode::InvalidArgument,
                     users[0] + " and " + users[1] +
                         " would both write to standard output, where a reader could not tell "
                         "them apart; give one of them a file (--out DIR writes report.json)");
}

// Each path by the option that gave it, or by its key in the job file.
job::PathNames pathNamesOf(const RawOptions& raw) {
    const std::string inJob = " in " + raw.jobFile;
    const auto name = [&inJob](const std::string& given, const char* option, const char* key) {
        return given.empty() ? key + inJob : std::string(option);
    };
    return {.program = name(raw.program, "the program", "program"),
            .machine = name(raw.machine, "--machine", "machine"),
            .cad = name(raw.cad, "--cad", "cad"),
            .jobFile = "--job",
            .outputProgram = name(raw.outputProgram, "-o", "output_program"),
            .outputCl = name(raw.outputCl, "--cl-output", "output_cl"),
            .outputDir = name(raw.out, "--out", "output_dir")};
}

// Outputs that would overwrite each other or an input are refused before anything runs.
Status refuseSharedPaths(const RawOptions& raw, const BatchOptions& options) {
    switch (options.mode) {
    case BatchOptions::Mode::Generate: {
        const NamedPath outputs[] = {{"--generate", options.generateOutput}};
        const NamedPath inputs[] = {{"--machine", options.job.machineFile}};
        return refuseSharedFiles(outputs, inputs);
    }
    case BatchOptions::Mode::Analyse:
        return job::refuseSharedPaths(options.job, pathNamesOf(raw));
    default:
        return {};
    }
}

Result<BatchOptions> interpretOptions(const RawOptions& raw, std::string helpText);

Result<BatchOptions> interpret(const RawOptions& raw, std::string helpText) {
    auto options = interpretOptions(raw, std::move(helpText));
    if (options) {
        if (auto refused = refuseSharedPaths(raw, *options); !refused) {
            return std::unexpected(refused.error());
        }
    }
    return options;
}

Result<BatchOptions> interpretOptions(const RawOptions& raw, std::string helpText) {
    if (auto status = checkFileValues(raw); !status) {
        return std::unexpected(status.error());
    }
    if (auto status = refuseSharedStandardOutput(raw); !status) {
        return std::unexpected(status.error());
    }
    if (raw.progress && raw.noProgress) {
        return makeError(ErrorCode::InvalidArgument,
                         "--progress and --no-progress exclude each other");
    }
    BatchOptions options;
    options.helpText = std::move(helpText);
    if (raw.version) {
        options.mode = BatchOptions::Mode::Version;
        return options;
    }
    if (auto status = applySchedule(raw, options); !status) {
        return std::unexpected(status.error());
    }
    if (auto status = applyNumbers(raw, options); !status) {
        return std::unexpected(status.error());
    }
    // The command line wins over the job file: a program given here replaces the file's demo.
    if (!raw.program.empty()) {
        options.job.program = raw.program;
        options.job.demo = false;
    }
    options.job.demo = options.job.demo || raw.demo;
    if (auto status = applyCad(raw, options); !status) {
        return std::unexpected(status.error());
    }
    if (!raw.machine.empty()) {
        options.job.machineFile = raw.machine;
    }
    if (!raw.out.empty()) {
        options.job.outputDir = raw.out;
    }
    options.job.analysis.feedReference = raw.feedReference == "centre"
                                             ? analysis::FeedReference::Centre
                                             : analysis::FeedReference::Tip;
    // CLI11 has checked the name against the same list.
    options.job.analysis.method = analysis::derivativeMethodNamed(raw.derivatives)
                                      .value_or(analysis::DerivativeMethod::Filtered);
    if (!raw.dialect.empty()) { // CLI11 has checked the name
        options.job.read.dialect = raw.dialect == "sinumerik"    ? io::NcDialect::Sinumerik
                                   : raw.dialect == "heidenhain" ? io::NcDialect::Heidenhain
                                                                 : io::NcDialect::Iso;
    }
    if (!raw.angleUnit.empty()) { // CLI11 has checked it is deg or rad
        options.job.read.angleUnit =
            raw.angleUnit == "rad" ? io::AngleUnit::Radians : io::AngleUnit::Degrees;
    }
    if (!raw.columns.empty()) {
        options.job.read.tableColumns = raw.columns;
    }
    options.printJson = raw.json;
    options.quiet = raw.quiet;
    options.progress = raw.progress && !raw.quiet;
    options.noProgress = raw.noProgress;
    options.generate.profile = raw.profile;
    options.generate.format = raw.format;
    options.generate.seed = raw.seed;
    if (raw.reproduce) {
        options.mode = BatchOptions::Mode::Reproduce;
        options.reproduction.seed = raw.seedGiven ? raw.seed : options.reproduction.seed;
        options.reproduction.blades = raw.blades;
        options.reproduction.compare.best = options.job.parameters;
        return options;
    }
    if (!raw.generate.empty()) {
        options.mode = BatchOptions::Mode::Generate;
        options.generateOutput = raw.generate;
        return options;
    }
    if (raw.demo && !raw.program.empty()) {
        return makeError(ErrorCode::InvalidArgument, "give either a program or --demo, not both");
    }
    if (!options.job.demo && options.job.program.empty()) {
        return makeError(ErrorCode::InvalidArgument,
                         "expected a program to analyse, --demo, --job or --generate (see --help)");
    }
    return options;
}

// Every long option's name ("--tool-radius"), of the command and of its option groups, which
// CLI11 keeps as subcommands of their own.
void collectLongNames(const CLI::App& app, std::vector<std::string>& names) {
    for (const CLI::Option* option : app.get_options()) {
        for (const std::string& name : option->get_lnames()) {
            names.push_back("--" + name);
        }
    }
    for (const CLI::App* group : app.get_subcommands([](const CLI::App*) { return true; })) {
        collectLongNames(*group, names);
    }
}

// CLI11 reports an unknown option as the words it could not place, in an order of its own
// ("not expected: 3 --tool-radus"); the first unknown --word is named instead, with the
// option it most likely meant.
std::optional<std::string> unknownOptionMessage(const CLI::App& cli,
                                                const std::vector<std::string>& arguments) {
    std::vector<std::string> names;
    collectLongNames(cli, names);
    const std::vector<std::string_view> known(names.begin(), names.end());
    for (std::size_t index = 1; index < arguments.size() && arguments[index] != "--"; ++index) {
        const std::string& argument = arguments[index];
        const std::string name = argument.substr(0, argument.find('='));
        if (!name.starts_with("--") || std::ranges::find(known, name) != known.end()) {
            continue;
        }
        const auto nearest = nearestName(name, known);
        return "unknown option " + name +
               (nearest ? "; did you mean " + std::string(*nearest) + "?" : std::string());
    }
    return std::nullopt;
}

} // namespace

Result<BatchOptions> parseBatchOptions(const std::vector<std::string>& arguments) {
    CLI::App cli{"BladeAxis: monotone, smooth A-axis re-scheduling of four-axis blade programs\n"
                 "(section numbers \u00a7 refer to docs/method.md)",
                 "bladeaxis"};
    cli.footer(std::string(subcommandHelp()) + "\n" + kExitCodeHelp);
    RawOptions raw;
    defineOptions(cli, raw);
    std::vector<std::string> reversed(arguments.rbegin(), arguments.rend() - 1);
    try {
        cli.parse(reversed);
    } catch (const CLI::CallForHelp&) {
        BatchOptions options;
        options.mode = BatchOptions::Mode::Help;
        options.helpText = cli.help();
        return options;
    } catch (const CLI::ExtrasError& error) {
        return makeError(ErrorCode::InvalidArgument,
                         unknownOptionMessage(cli, arguments).value_or(error.what()));
    } catch (const CLI::ParseError& error) {
        return makeError(ErrorCode::InvalidArgument, error.what());
    }
    raw.seedGiven = cli.count("--seed") > 0;
    if (raw.manPage) {
        BatchOptions options;
        options.mode = BatchOptions::Mode::ManPage;
        options.manPageText = manPage(cli, {projectVersion(), subcommandHelp(), kExitCodeHelp});
        return options;
    }
    return interpret(raw, cli.help());
}

} // namespace bladeaxis::app
