#include "ui/job_thread.h"

#include "core/base/execution.h"
#include "core/base/memory_policy.h"

#include <string>
#include <utility>

namespace bladeaxis::ui {
namespace {

// Emits signals from the worker thread; Qt queues them to the receivers' (GUI) thread.
class SignalProgressSink final : public ProgressSink {
  public:
    explicit SignalProgressSink(JobThread& thread) : m_thread(thread) {}
    void progress(double fraction, std::string_view stage) override {
        emit m_thread.progressed(
            fraction, QString::fromUtf8(stage.data(), static_cast<qsizetype>(stage.size())));
    }
    void warning(std::string_view message) override {
        emit m_thread.warned(
            QString::fromUtf8(message.data(), static_cast<qsizetype>(message.size())));
    }

  private:
    JobThread& m_thread;
};

} // namespace

JobThread::JobThread(job::JobSpec spec, QObject* parent)
    : QThread(parent), m_spec(std::move(spec)) {}

void JobThread::run() {
    // The whole thread runs under the job's thread count: runJob sets it for itself, and the 3D
    // view's scenes made here (the CAD blade's sections) use it too.
    const ThreadCountScope threads(m_spec.parameters.threads);
    // The jobs before this one freed their small blocks into the C library's arenas; they go
    // back to the system, so that this job's memory starts where a fresh process's would.
    returnFreedHeapToTheSystem();
    SignalProgressSink sink(*this);
    auto showOriginal = [this](const job::JobResult& partial) {
        m_programText = partial.programText(); // before the rewrite releases it
        job::DisplayScene scene = job::buildDisplayScene(partial);
        {
            const std::lock_guard lock(m_originalMutex);
            m_originalScene = std::move(scene);
        }
        emit originalReady();
    };
    m_result.emplace(job::runJob(m_spec, sink, m_cancel, showOriginal));
    if (*m_result) {
        sink.progress(1.0, "preparing the 3D view");
        m_scene = job::buildDisplayScene(**m_result);
    }
}

job::DisplayScene JobThread::takeOriginalScene() {
    const std::lock_guard lock(m_originalMutex);
    return std::move(m_originalScene);
}

Result<job::JobResult> JobThread::takeResult() {
    if (!m_result) {
        return std::unexpected(cancelledError()); // the job ended before it had a result
    }
    Result<job::JobResult> result = std::move(*m_result);
    m_result.reset();
    return result;
}

} // namespace bladeaxis::ui
