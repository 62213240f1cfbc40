#include "app/batch/batch_runner.h"

#include "app/batch/exit_codes.h"
#include "core/base/file_io.h"

#include <filesystem>
#include <ostream>

namespace bladeaxis::app {

namespace {

// Progress is silent in batch; warnings go to standard error as they come.
class BatchProgress final : public ProgressSink {
  public:
    explicit BatchProgress(std::ostream& err, bool quiet) : m_err(err), m_quiet(quiet) {}
    void progress(double, std::string_view) override {}
    void warning(std::string_view message) override {
        if (!m_quiet) {
            m_err << "warning: " << message << '\n';
        }
    }

  private:
    std::ostream& m_err;
    bool m_quiet;
};

int fail(const Error& error, std::ostream& err) {
    err << "bladeaxis: " << error.toString() << '\n';
    return exitCodeFor(error);
}

int runGenerate(const BatchOptions& options, std::ostream& out, std::ostream& err) {
    auto machine = job::loadMachine(options.job);
    if (!machine) {
        return fail(machine.error(), err);
    }
    auto generated = job::generateProgram(options.generate, *machine);
    if (!generated) {
        return fail(generated.error(), err);
    }
    if (auto status = writeFileAtomically(options.generateOutput, generated->text); !status) {
        return fail(status.error(), err);
    }
    if (!options.quiet) {
        out << "wrote " << options.generateOutput.string() << '\n';
    }
    return kExitOk;
}

int runAnalyse(const BatchOptions& options, std::ostream& out, std::ostream& err) {
    BatchProgress progress(err, options.quiet);
    CancelToken cancel;
    auto result = job::runJob(options.job, progress, cancel);
    if (!result) {
        return fail(result.error(), err);
    }
    if (auto status = job::writeJobOutputs(options.job, *result); !status) {
        return fail(status.error(), err);
    }
    if (options.printJson) {
        out << job::reportJsonText(*result);
    } else if (!options.quiet) {
        out << job::formatSummary(*result);
        if (!options.job.outputDir.empty()) {
            out << "outputs      " << options.job.outputDir.string() << '\n';
        }
    }
    return kExitOk;
}

int runReproduce(const BatchOptions& options, std::ostream& out, std::ostream& err) {
    BatchProgress progress(err, options.quiet);
    CancelToken cancel;
    auto result = job::runReproduction(options.reproduction, progress, cancel);
    if (!result) {
        return fail(result.error(), err);
    }
    const auto& folder = options.job.outputDir;
    if (!folder.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(folder, ec);
        const std::pair<const char*, std::string> files[] = {
            {"reproduce.json", job::reproductionJsonText(*result)},
            {"reproduce.csv", job::reproductionCsv(*result)}};
        for (const auto& [name, text] : files) {
            if (auto status = writeFileAtomically(folder / name, text); !status) {
                return fail(status.error(), err);
            }
        }
    }
    if (!options.quiet) {
        out << job::reproductionSummary(*result);
    }
    return kExitOk;
}

} // namespace

int runBatch(const BatchOptions& options, std::ostream& out, std::ostream& err) {
    switch (options.mode) {
    case BatchOptions::Mode::Help:
        out << options.helpText;
        return kExitOk;
    case BatchOptions::Mode::Version:
        out << "bladeaxis " << BLADEAXIS_VERSION << '\n';
        return kExitOk;
    case BatchOptions::Mode::Generate:
        return runGenerate(options, out, err);
    case BatchOptions::Mode::Analyse:
        return runAnalyse(options, out, err);
    case BatchOptions::Mode::Reproduce:
        return runReproduce(options, out, err);
    }
    return kExitInternal;
}

int runBatchCommandLine(const std::vector<std::string>& arguments, std::ostream& out,
                        std::ostream& err) {
    auto options = parseBatchOptions(arguments);
    if (!options) {
        err << "bladeaxis: " << options.error().message << "\nRun with --help for usage.\n";
        return kExitUsage;
    }
    return runBatch(*options, out, err);
}

} // namespace bladeaxis::app
