#include "app/batch/batch_runner.h"

#include "app/batch/error_json.h"
#include "app/batch/exit_codes.h"
#include "core/base/file_io.h"
#include "core/base/output_set.h"
#include "core/base/version.h"
#include "core/job/cad_check.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <istream>
#include <iterator>
#include <ostream>
#include <signal.h>
#include <unistd.h>

namespace bladeaxis::app {

namespace {

// Warnings go to standard error as they come; with `showProgress` the running stage too, as
// one line rewritten in place ("  70% comparing with the other methods"), cleared at the end,
// before each warning and before an error (endLine), which would otherwise be printed over it.
class BatchProgress final : public ProgressSink {
  public:
    BatchProgress(std::ostream& err, bool quiet, bool showProgress = false)
        : m_err(err), m_quiet(quiet), m_showProgress(showProgress && !quiet) {}
    ~BatchProgress() override { clearLine(); }
    BatchProgress(const BatchProgress&) = delete;
    BatchProgress& operator=(const BatchProgress&) = delete;

    void progress(double fraction, std::string_view stage) override {
        if (!m_showProgress) {
            return;
        }
        if (fraction >= 1.0) {
            clearLine();
            return;
        }
        const int percent = static_cast<int>(std::lround(100.0 * std::clamp(fraction, 0.0, 1.0)));
        m_err << "\r"
              << (percent < 10    ? "  "
                  : percent < 100 ? " "
                                  : "")
              << percent << "% " << stage << "\x1b[K" << std::flush;
        m_lineShown = true;
    }
    void warning(std::string_view message) override {
        if (!m_quiet) {
            clearLine();
            m_err << "warning: " << message << '\n';
        }
    }

    void endLine() { clearLine(); }

  private:
    void clearLine() {
        if (m_lineShown) {
            m_err << "\r\x1b[K" << std::flush;
            m_lineShown = false;
        }
    }

    std::ostream& m_err;
    bool m_quiet;
    bool m_showProgress;
    bool m_lineShown = false;
};

// Ctrl+C (SIGINT) or a polite kill (SIGTERM) cancels a batch run like the GUI's Cancel, in
// every phase: the handler is installed for the whole process before the arguments are read
// (installBatchInterruptHandlers, from main) and stays until it ends, so a signal at start-up,
// during generation or at exit never ends the process by the signal. A signal that comes before
// a run's token exists is kept (g_interruptPending) and cancels the run as soon as it starts.
// The run stops at its next check and exits 7 with nothing written; once its outputs are in
// place, a signal is too late to undo them and the run ends as it would have. The handler only
// stores to lock-free atomics, which is async-signal-safe.
std::atomic<bool> g_interruptPending{false};
std::atomic<CancelToken*> g_interruptTarget{nullptr};

extern "C" void cancelOnSignal(int) {
    g_interruptPending.store(true);
    if (CancelToken* token = g_interruptTarget.load()) {
        token->requestCancel();
    }
}

void setInterruptHandlers(struct sigaction* previousInt, struct sigaction* previousTerm) {
    struct sigaction action {};
    action.sa_handler = cancelOnSignal;
    sigemptyset(&action.sa_mask);
    ::sigaction(SIGINT, &action, previousInt);
    ::sigaction(SIGTERM, &action, previousTerm);
}

class InterruptCancels {
  public:
    explicit InterruptCancels(CancelToken& token) {
        g_interruptTarget.store(&token);
        setInterruptHandlers(&m_previousInt, &m_previousTerm);
        if (g_interruptPending.exchange(false)) { // came before this run had a token
            token.requestCancel();
        }
    }
    InterruptCancels(const InterruptCancels&) = delete;
    InterruptCancels& operator=(const InterruptCancels&) = delete;
    ~InterruptCancels() {
        ::sigaction(SIGINT, &m_previousInt, nullptr);
        ::sigaction(SIGTERM, &m_previousTerm, nullptr);
        g_interruptTarget.store(nullptr);
    }

  private:
    struct sigaction m_previousInt {};
    struct sigaction m_previousTerm {};
};

Error cancelledError() {
    return Error{ErrorCode::Cancelled, "interrupted: nothing was written", {}, {}};
}

// Standard output carries what a script reads (the program, CL data, or --json's report);
// standard error every message for a person, the progress line included.
struct Streams {
    std::ostream& out;
    std::ostream& err;
    BatchProgress& progress;
    bool jsonErrors = false; // --json: a refusal is also a JSON object on standard output
};

int fail(const Error& error, const Streams& io) {
    io.progress.endLine();
    io.err << "bladeaxis: " << error.toString() << '\n';
    const ExitCode code = exitCodeFor(error);
    if (io.jsonErrors) {
        io.out << errorJsonText(error, code) << std::flush;
    }
    return code;
}

// A stream that did not take the whole of what was written (a full disk, /dev/full, a reader that
// closed the pipe): the output is cut mid-block, which must not pass for a finished job.
Error streamFailure(const std::string& what) {
    return Error{ErrorCode::WriteFailed,
                 "standard output did not take all of " + what +
                     " (the disk is full or the reader closed it): what it holds is cut short",
                 {},
                 {}};
}

// `--generate -` writes the program to standard output, like `-o -`.
int runGenerate(const BatchOptions& options, const CancelToken& cancel, const Streams& io) {
    auto machine = job::loadMachine(options.job);
    if (!machine) {
        return fail(machine.error(), io);
    }
    auto generated = job::generateProgram(options.generate, *machine);
    if (!generated) {
        return fail(generated.error(), io);
    }
    if (cancel.isCancelled()) { // the generation does not stop early; its program is not written
        return fail(cancelledError(), io);
    }
    if (options.generateOutput == "-") {
        io.out << generated->text << std::flush;
        return io.out ? kExitOk : fail(streamFailure("the generated program"), io);
    }
    const std::filesystem::path inputs[] = {options.job.machineFile};
    if (auto status = writeFileAtomically(options.generateOutput, generated->text, inputs);
        !status) {
        return fail(status.error(), io);
    }
    if (!options.quiet) {
        io.out << "wrote " << options.generateOutput.string() << '\n';
    }
    return kExitOk;
}

// Refused before anything is written: the tool of a program or CL data going to standard
// output gouges or collides (without --force). A file output is refused by writeJobOutputs;
// a stream output is not a file it writes, so the same refusal is made here.
Status refuseCollidingStreamOutput(const job::JobSpec& spec, const job::JobResult& result) {
    if (!result.cadCheck || !result.rescheduled) {
        return {};
    }
    return job::refuseIfColliding(*result.cadCheck, result.program.path().sourceFile,
                                  spec.cad.force);
}

// The program or the CL data, whichever `-` names (the options allow one of them at most).
Status writeStreamOutput(const job::JobResult& result, bool program, std::ostream& out) {
    if (!result.rescheduled) {
        return makeError(ErrorCode::InvalidArgument,
                         "an output program needs re-scheduling; it was not run");
    }
    std::string clText;
    if (!program) {
        auto text = job::rescheduledClText(result);
        if (!text) {
            return std::unexpected(text.error());
        }
        clText = std::move(*text);
    }
    out << (program ? result.rescheduled->programText : clText) << std::flush;
    if (!out) {
        return std::unexpected(
            streamFailure(program ? "the re-scheduled program" : "the re-scheduled CL data"));
    }
    return {};
}

// A program named `-` is read from standard input, and `-o -` (or `--cl-output -`) writes the
// re-scheduled program (or CL data) to standard output; the summary then goes to standard
// error. The options refuse two things on standard output (--json with either). The stream
// output goes out only once every other output is written, so a refused or failed job leaves
// standard output empty.
int runAnalyse(const BatchOptions& options, CancelToken& cancel, std::istream& in,
               const Streams& io) {
    job::JobSpec spec = options.job;
    if (!spec.demo && spec.program == "-") {
        auto text = readStandardInput(in);
        if (!text) {
            return fail(text.error(), io);
        }
        spec.programText = std::move(*text);
        spec.program = "stdin";
    }
    const bool programToStdout = spec.outputProgram == "-";
    const bool clToStdout = spec.outputCl == "-";
    if (programToStdout) {
        spec.outputProgram.clear();
    }
    // Nothing reads the result after its outputs are written but the summary: the job keeps what
    // those outputs need and frees the rest (job::retentionOf). CL data to the standard output
    // are made from the result once the job has run.
    spec.detail = clToStdout ? job::ResultDetail::PerSample : job::ResultDetail::Figures;
    if (clToStdout) {
        spec.outputCl.clear();
    }
    std::ostream& summary = programToStdout || clToStdout ? io.err : io.out;
    auto result = job::runJob(spec, io.progress, cancel);
    if (cancel.isCancelled()) {
        return fail(cancelledError(), io);
    }
    if (!result) {
        return fail(result.error(), io);
    }
    const bool toStdout = programToStdout || clToStdout;
    if (auto refused = toStdout ? refuseCollidingStreamOutput(spec, *result) : Status{}; !refused) {
        return fail(refused.error(), io);
    }
    // Checks the token last before the outputs are moved into place: after that the run ends
    // as it would have, its outputs whole.
    if (auto status = job::writeJobOutputs(spec, *result, &cancel); !status) {
        return fail(status.error(), io);
    }
    if (toStdout) {
        if (auto status = writeStreamOutput(*result, programToStdout, io.out); !status) {
            return fail(status.error(), io);
        }
    }
    if (options.printJson) {
        // The same report.json as --out writes (the spec names the preset and the edited layers).
        io.out << job::reportJsonText(*result, &options.job) << std::flush;
        if (!io.out) {
            return fail(streamFailure("the JSON report"), io);
        }
    } else if (!options.quiet) {
        io.progress.endLine();
        summary << job::formatSummary(*result);
        if (!options.job.outputDir.empty()) {
            summary << "outputs      " << options.job.outputDir.string() << '\n';
        }
    }
    return kExitOk;
}

// Both files or neither, and no folder of this run's left empty (as a job's outputs).
Status writeReproduction(const std::filesystem::path& folder,
                         const job::ReproductionResult& result) {
    if (folder.empty()) {
        return {};
    }
    auto created = CreatedFolder::create(folder);
    if (!created) {
        return std::unexpected(created.error());
    }
    OutputSet outputs;
    for (const auto& [name, text] : {std::pair{"reproduce.json", job::reproductionJsonText(result)},
                                     std::pair{"reproduce.csv", job::reproductionCsv(result)}}) {
        if (auto status = outputs.add(folder / name, text); !status) {
            return status;
        }
    }
    if (auto status = outputs.publish(); !status) {
        return status;
    }
    created->keep();
    return {};
}

int runReproduce(const BatchOptions& options, const CancelToken& cancel, const Streams& io) {
    auto result = job::runReproduction(options.reproduction, io.progress, cancel);
    if (cancel.isCancelled()) {
        return fail(cancelledError(), io);
    }
    if (!result) {
        return fail(result.error(), io);
    }
    if (auto status = writeReproduction(options.job.outputDir, *result); !status) {
        return fail(status.error(), io);
    }
    if (!options.quiet) {
        io.progress.endLine();
        io.out << job::reproductionSummary(*result);
    }
    return kExitOk;
}

// A command line that asks for JSON (--json anywhere) gets its refusal as JSON too, even when
// the rest of it could not be read.
bool asksForJson(const std::vector<std::string>& arguments) {
    const auto end = std::ranges::find(arguments, "--");
    return std::find(arguments.begin(), end, "--json") != end;
}

} // namespace

Result<std::string> readStandardInput(std::istream& in, std::size_t limit) {
    std::string text;
    std::array<char, 1 << 16> chunk{};
    while (in.read(chunk.data(), chunk.size()) || in.gcount() > 0) {
        const auto got = static_cast<std::size_t>(in.gcount());
        if (text.size() + got > limit) {
            return std::unexpected(io::nc::programTooLarge("stdin"));
        }
        if (text.size() + got > text.capacity()) { // doubling, but never past the cap
            text.reserve(std::min(limit, std::max(2 * text.capacity(), text.size() + got)));
        }
        text.append(chunk.data(), got);
    }
    return text;
}

void installBatchInterruptHandlers() {
    setInterruptHandlers(nullptr, nullptr);
}

int runBatch(const BatchOptions& options, std::ostream& out, std::ostream& err, std::istream& in) {
    CancelToken cancel;
    InterruptCancels interrupts(cancel);
    BatchProgress progress(err, options.quiet, options.progress);
    const Streams io{out, err, progress, options.printJson};
    if (cancel.isCancelled()) { // a signal before the run started
        return fail(cancelledError(), io);
    }
    switch (options.mode) {
    case BatchOptions::Mode::Help:
        out << options.helpText;
        return kExitOk;
    case BatchOptions::Mode::ManPage:
        out << options.manPageText;
        return kExitOk;
    case BatchOptions::Mode::Version:
        out << "bladeaxis " << projectVersion() << " (revision " << projectRevision()
            << ")\nbuilt with " << BLADEAXIS_LIBRARIES << '\n';
        return kExitOk;
    case BatchOptions::Mode::Generate:
        return runGenerate(options, cancel, io);
    case BatchOptions::Mode::Analyse:
        return runAnalyse(options, cancel, in, io);
    case BatchOptions::Mode::Reproduce:
        return runReproduce(options, cancel, io);
    }
    return kExitInternal;
}

int runBatchCommandLine(const std::vector<std::string>& arguments, std::ostream& out,
                        std::ostream& err, std::istream& in) {
    auto options = parseBatchOptions(arguments);
    if (!options) {
        // A job file's error names its file and line (the command line's have no place).
        const SourceLocation& where = options.error().where;
        err << "bladeaxis: " << (where.empty() ? "" : where.toString() + ": ")
            << options.error().message << "\nRun with --help for usage.\n";
        if (asksForJson(arguments)) {
            out << errorJsonText(options.error(), kExitUsage) << std::flush;
        }
        return kExitUsage;
    }
    // On a terminal the running stage is shown unless asked not to (--no-progress, -q).
    if (&err == &std::cerr && isatty(STDERR_FILENO) == 1 && !options->quiet &&
        !options->noProgress) {
        options->progress = true;
    }
    return runBatch(*options, out, err, in);
}

} // namespace bladeaxis::app
