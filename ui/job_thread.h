#pragma once
// Runs core/job's runJob off the GUI thread. Progress is marshalled to the GUI thread as a
// queued signal, so widgets are only touched there.

#include "core/base/progress.h"
#include "core/job/display_scene.h"
#include "core/job/job.h"

#include <QThread>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

namespace bladeaxis::ui {

class JobThread final : public QThread {
    Q_OBJECT

  public:
    explicit JobThread(job::JobSpec spec, QObject* parent = nullptr);

    void requestCancel() { m_cancel.requestCancel(); }
    // Valid once finished() was emitted; moved out, so call once.
    Result<job::JobResult> takeResult();
    // What the 3D and section views draw, built off the GUI thread with the result.
    job::DisplayScene takeScene() { return std::move(m_scene); }
    // The program as read, for the 3D view while the job goes on; valid after originalReady.
    job::DisplayScene takeOriginalScene();
    // The input's text as read, for the NC listing: the job frees its own copy once it has
    // rewritten the program. Valid once finished() was emitted; moved out, so call once.
    std::string takeProgramText() { return std::move(m_programText); }

  signals:
    void progressed(double fraction, QString stage);
    void warned(QString message);
    // The program is read and its original motion analysed (takeOriginalScene).
    void originalReady();

  protected:
    void run() override;

  private:
    job::JobSpec m_spec;
    CancelToken m_cancel;
    std::optional<Result<job::JobResult>> m_result;
    job::DisplayScene m_scene;
    std::mutex m_originalMutex;
    job::DisplayScene m_originalScene;
    std::string m_programText; // written on the job's thread before finished()
};

} // namespace bladeaxis::ui
