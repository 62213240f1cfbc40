#pragma once
// The main window: choose a program (G-code or CL) with a machine file and tool radius, or the
// built-in demo; run the job in the background; list the layers of the result.

#include "core/job/job.h"

#include <QMainWindow>
#include <optional>

class QDoubleSpinBox;
class QLabel;
class QMenu;
class QProgressBar;
class QPushButton;
class QSlider;
class QTableWidget;

namespace bladeaxis::ui {

class JobThread;
class ProfilePlots;
class SThetaEditor;
class ToolpathView;

class MainWindow final : public QMainWindow {
    Q_OBJECT

  public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    void runDemo();
    void runProgram(const QString& programPath);
    void setMachineFile(const QString& machinePath);
    bool isRunning() const { return m_thread != nullptr; }
    const job::JobSpec& spec() const { return m_spec; }
    // The last successful result; empty before the first job finishes.
    const std::optional<job::JobResult>& result() const { return m_result; }
    QTableWidget* layerTable() const { return m_layers; }
    SThetaEditor* editor() const { return m_editor; }
    ProfilePlots* plots() const { return m_plots; }
    ToolpathView* view3d() const { return m_view3d; }
    QSlider* toolSlider() const { return m_toolSlider; }
    void setDarkPalette(bool dark);
    int selectedLayer() const;
    // Writes the re-scheduled program of the last result exactly as `--batch -o` would (through
    // core's writeJobOutputs, which refuses when a check failed).
    Status exportProgram(const QString& path);
    void selectLayer(int layer);

  signals:
    void jobFinished(bool succeeded);
    void layerSelected(int layer);

  protected:
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

  private:
    void buildActions();
    void buildStatusBar();
    void startJob(job::JobSpec spec);
    void onJobFinished();
    void showLayers();
    void showSelectedLayer(int layer);
    void rememberRecent(const QString& path);
    void rebuildRecentMenu();
    void openProgramDialog();
    void openMachineDialog();
    void exportProgramDialog();

    job::JobSpec m_spec;
    std::optional<job::JobResult> m_result;
    QString m_machinePath;
    JobThread* m_thread = nullptr;
    QTableWidget* m_layers = nullptr;
    SThetaEditor* m_editor = nullptr;
    ProfilePlots* m_plots = nullptr;
    ToolpathView* m_view3d = nullptr;
    QSlider* m_toolSlider = nullptr;
    QDoubleSpinBox* m_toolRadius = nullptr;
    QProgressBar* m_progress = nullptr;
    QPushButton* m_cancel = nullptr;
    QLabel* m_machineLabel = nullptr;
    QMenu* m_recentMenu = nullptr;
};

} // namespace bladeaxis::ui
