#include "core/api/bladeaxis.h"

#include "core/base/exit_codes.h"
#include "core/base/version.h"
#include "core/job/job.h"
#include "core/job/job_file.h"

#include <algorithm>

namespace bladeaxis::api {

struct JobOutcome::State {
    job::JobSpec spec;
    job::JobResult result;
};

namespace {

// Forwards the job's progress and warnings to the plug-in's callbacks, when it gave them.
class CallbackSink final : public ProgressSink {
  public:
    explicit CallbackSink(const Callbacks& callbacks) : m_callbacks(callbacks) {}
    void progress(double fraction, std::string_view stage) override {
        if (m_callbacks.progress) {
            m_callbacks.progress(fraction, stage);
        }
    }
    void warning(std::string_view message) override {
        if (m_callbacks.warning) {
            m_callbacks.warning(message);
        }
    }

  private:
    const Callbacks& m_callbacks;
};

Result<JobOutcome> run(job::JobSpec spec, const Callbacks& callbacks) {
    CallbackSink sink(callbacks);
    const CancelToken neverCancelled;
    auto result = job::runJob(spec, sink, callbacks.cancel ? *callbacks.cancel : neverCancelled);
    if (!result) {
        return std::unexpected(result.error());
    }
    return JobOutcome(std::make_shared<const JobOutcome::State>(
        JobOutcome::State{std::move(spec), std::move(*result)}));
}

LayerCurve curveOf(const scheduling::LayerResult& layer) {
    LayerCurve curve;
    curve.firstRecord = layer.first;
    curve.lastRecord = layer.last;
    curve.s = layer.s;
    curve.thetaOriginal = layer.thetaOriginal;
    curve.thetaRescheduled = layer.theta;
    curve.thetaMin = layer.thetaMin;
    curve.thetaMax = layer.thetaMax;
    curve.junctionAngleRad = layer.junctionAngle;
    curve.keptOriginal =
        std::ranges::find(layer.flags, scheduling::LayerStatus::MonotoneInfeasible) !=
        layer.flags.end();
    return curve;
}

} // namespace

JobOutcome::JobOutcome(std::shared_ptr<const State> state) : m_state(std::move(state)) {}

std::string JobOutcome::reportJson() const {
    return job::reportJsonText(m_state->result, &m_state->spec);
}

std::string JobOutcome::summary() const {
    return job::formatSummary(m_state->result);
}

std::vector<std::string> JobOutcome::warnings() const {
    return m_state->result.warnings;
}

bool JobOutcome::rescheduled() const {
    return m_state->result.rescheduled.has_value();
}

std::vector<LayerCurve> JobOutcome::layers() const {
    std::vector<LayerCurve> curves;
    if (const auto& outcome = m_state->result.rescheduled) {
        for (const scheduling::LayerResult& layer : outcome->schedule.layers) {
            curves.push_back(curveOf(layer));
        }
    }
    return curves;
}

Result<std::string> JobOutcome::programText() const {
    if (!rescheduled()) {
        return makeError(ErrorCode::InvalidArgument,
                         "the job only analysed the program: there is no re-scheduled program");
    }
    return m_state->result.rescheduled->writtenText();
}

Status JobOutcome::writeProgram(const std::filesystem::path& path) const {
    // Only the program: the same checks as the job's own outputs (collision refusal, never
    // over an input, atomic), without the other outputs the job names.
    job::JobSpec programOnly = m_state->spec;
    programOnly.outputProgram = path;
    programOnly.outputCl.clear();
    programOnly.outputDir.clear();
    return job::writeJobOutputs(programOnly, m_state->result);
}

Status JobOutcome::writeOutputs() const {
    return job::writeJobOutputs(m_state->spec, m_state->result);
}

Result<JobOutcome> runJobFile(const std::filesystem::path& jobFile, const Callbacks& callbacks) {
    job::JobSpec spec;
    if (auto status = job::readJobFile(jobFile, spec); !status) {
        return std::unexpected(status.error());
    }
    return run(std::move(spec), callbacks);
}

Result<JobOutcome> runJobJson(std::string_view jobJson, const std::filesystem::path& baseDirectory,
                              const Callbacks& callbacks) {
    // The job is read as if it were a file in baseDirectory, so its paths resolve (and are
    // confined) there; the name appears in messages only.
    job::JobSpec spec;
    if (auto status = job::parseJobJson(jobJson, baseDirectory / "job.json", spec); !status) {
        return std::unexpected(status.error());
    }
    spec.jobFile.clear();
    return run(std::move(spec), callbacks);
}

int exitCodeFor(const Error& error) {
    return bladeaxis::exitCodeFor(error);
}

std::string_view version() {
    return projectVersion();
}

} // namespace bladeaxis::api
