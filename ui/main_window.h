#pragma once
// The main window: choose a program (G-code or CL) with a machine file and tool radius, a saved
// job, or the built-in demo; run the job in the background; review it (layer list, S-theta
// editor with the layer's section, axis-motion plots, comparison table, 3D view); edit single
// layers (every edit is one undo step of the job, and the job re-runs with it); export the
// program, the CL data, the report and the job. The window computes nothing itself: it builds a
// JobSpec and shows the JobResult of core/job.

#include "core/job/display_scene.h"
#include "core/job/job.h"

#include <QMainWindow>
#include <QUndoStack>
#include <array>
#include <cstddef>
#include <optional>
#include <string>

class QAction;
class QDockWidget;
class QDoubleSpinBox;
class QLabel;
class QMenu;
class QProgressBar;
class QPushButton;
class QSlider;
class QTabWidget;
class QTableWidget;
class QToolBar;

namespace bladeaxis::ui {

// The About box's text: version, revision and the libraries built with and running.
QString aboutText();

// The machine files shipped with BladeAxis (installed, or the source tree's resources/machines).
QStringList shippedMachineFiles();

class ComparisonSummary;
class ComparisonTable;
class JobSettingsPanel;
class JobThread;
class LayerSettingsPanel;
class NcListing;
class ProfilePlots;
class ReviewDashboard;
class SectionView;
class SThetaEditor;
class ToolpathView;

class MainWindow final : public QMainWindow {
    Q_OBJECT

  public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Start a new job; refused (nothing changes, the undo history included) while a job runs.
    // A new program starts without the previous program's typed radius and blade CAD.
    void runDemo();
    void runProgram(const QString& programPath);
    // Stops the running job; the window keeps (and shows again) the previous result.
    void cancelJob();
    // Before the window replaces or closes a job with unsaved layer edits: asks to save them
    // (Save / Discard / Cancel); true when the caller may go on. The menu, drop and close paths
    // ask; the programmatic runProgram/runDemo/openJob do not.
    bool confirmDiscardEdits();
    // Before the menu, drop and recent-file paths replace the job: confirmDiscardEdits, then,
    // while a job runs, offers to cancel it (and waits for it to stop); true when the caller may
    // start the new job.
    bool readyForNewJob();
    // Reads a job file (docs/job-file.md), edits included, and runs it.
    Status openJob(const QString& jobPath);
    // The status line after opening a job: the outputs it names, written only on export.
    QString jobOpenedMessage(const QString& jobPath) const;
    // Saves the current job, with the layer edits, as a job file: `jobPath` with the suffix
    // ".bladeaxis.json" (jobFilePath). Refused with nothing loaded.
    Status saveJob(const QString& jobPath);
    // `path` ending in ".bladeaxis.json": "blade" and "blade.json" become "blade.bladeaxis.json".
    static QString jobFilePath(const QString& path);
    QAction* saveJobAction() const { return m_saveJob; }
    // The machine for this and the next jobs; empty is the built-in one. A file that does not
    // load is refused (its error returned) and the machine in use is kept.
    Status setMachineFile(const QString& machinePath);
    // Blade CAD (STEP/IGES) of the program on screen: the job re-runs with it at once (clearance
    // check, sections, 3D surface). With no program shown it waits for the next program opened.
    // It belongs to that program: opening another program detaches it. Empty clears it.
    // Refused while a job runs.
    void setBladeCad(const QString& cadPath, const cad::AxisRotationPlacement& placement = {});
    void clearBladeCad() { setBladeCad(QString()); }
    QString bladeCadPath() const { return m_cadPath; }
    QAction* clearCadAction() const { return m_clearCad; }
    bool isRunning() const { return m_thread != nullptr; }
    // True while the job re-runs (or will re-run) with edits the last result does not have.
    bool editsPending() const { return m_thread != nullptr || m_reapplyQueued; }
    const job::JobSpec& spec() const { return m_spec; }
    // The last successful result; empty before the first job finishes.
    const std::optional<job::JobResult>& result() const { return m_result; }
    QUndoStack* undoStack() { return &m_undo; }
    QTableWidget* layerTable() const { return m_layers; }
    SThetaEditor* editor() const { return m_editor; }
    LayerSettingsPanel* layerSettings() const { return m_layerSettings; }
    SectionView* sectionView() const { return m_section; }
    ProfilePlots* plots() const { return m_plots; }
    // The Comparison page: the compact view with its recommendation, and the full table on
    // demand ("Full table").
    ComparisonTable* comparisonTable() const { return m_comparison; }
    ComparisonSummary* comparisonSummary() const { return m_comparisonSummary; }
    // The first page after a job: the batch's figures, warnings and clearance points.
    ReviewDashboard* dashboard() const { return m_dashboard; }
    QTabWidget* pages() const { return m_tabs; }
    // The dock with the settings the error dialogs name (angle unit, B and channel tolerance,
    // preset); View > Job settings.
    JobSettingsPanel* jobSettings() const { return m_jobSettings; }
    QDockWidget* jobSettingsDock() const { return m_jobSettingsDock; }
    // Runs the program on screen, or the one whose job just failed, with the Job settings
    // panel's values (its "Apply and re-run").
    void applyJobSettings();
    ToolpathView* view3d() const { return m_view3d; }
    QSlider* toolSlider() const { return m_toolSlider; }
    // The tool bar's ball radius of the program on screen: 0 ("from file") uses the radius the
    // program states. A value typed there is this program's only: a new program starts from
    // file again, and nothing of it is remembered across sessions.
    QDoubleSpinBox* toolRadiusBox() const { return m_toolRadius; }
    // Beside the radius: where the radius of the job on screen comes from ("from the program
    // (CUTTER/TLDATA)", "typed", "from the job file", ...), and the conflict when a given
    // radius disagrees with the program's.
    QLabel* toolRadiusSourceLabel() const { return m_radiusSource; }
    // The strip above the views that shows an unresolved radius conflict (hidden otherwise).
    QWidget* radiusConflictBanner() const { return m_radiusBanner; }
    // A given radius (typed, asked, job file) disagrees with the one the program states
    // (job::toolRadiusDisagrees, the batch's rule) and the engineer has not confirmed it: the
    // program and CL exports are refused until it is resolved.
    bool radiusConflictUnresolved() const;
    // The two ways to resolve it: re-run with the program's radius, or keep the given one for
    // this program (as the batch's --tool-radius does, with its warning).
    void useProgramToolRadius();
    void confirmGivenToolRadius();
    // The NC listing dock (View > NC listing): the original or re-scheduled program's text.
    NcListing* listing() const { return m_listing; }
    QDockWidget* listingDock() const { return m_listingDock; }
    // Selects record `record` of the program (index into its records) everywhere: its block in
    // the listing and, for a record of the cutting pass, its layer, the tool slider and the tool
    // in the 3D view, and the plots' time line. The listing's blocks, the 3D pick and a plot
    // click select through it.
    void selectRecord(std::size_t record);
    // The record selected last (listing, 3D pick, tool slider, plot click or selectRecord);
    // none after a new program.
    std::optional<std::size_t> selectedRecord() const { return m_selectedRecord; }
    void setDarkPalette(bool dark);
    int selectedLayer() const;
    void selectLayer(int layer);
    // Write the re-scheduled program / CL data / report folder of the last result exactly as
    // `--batch` would (through core's writeJobOutputs, which refuses when a check failed or the
    // tool gouges or collides); refused while edits are still being applied. An output that
    // gouges or collides is written only once the engineer ticked the acknowledgement on the
    // Review dashboard (the batch's --force), after seeing every point.
    Status exportProgram(const QString& path);
    Status exportClData(const QString& path);
    Status exportReport(const QString& folder);
    // File > Export program / CL data after the file dialog: with an unresolved radius conflict,
    // asks which radius (the program's re-runs the job, export again after it); when the
    // clearance check refuses the output, says so and shows the Review page, where the points
    // are listed and the acknowledgement is.
    void exportProgramTo(const QString& path);
    // "<input>_rescheduled.<ext>" beside the input (the demo's in the working folder), and the
    // file-dialog filter of the input's format; empty before the first result.
    QString suggestedExportPath() const;
    QString exportFilter() const;
    // Enabled only when there is a result to export (a program needs a re-scheduled one).
    QAction* exportProgramAction() const { return m_exportProgram; }
    QAction* exportClAction() const { return m_exportCl; }
    QAction* exportReportAction() const { return m_exportReport; }
    void exportClDataTo(const QString& path);
    // Sets (or with nullopt removes) the override of a layer, shows `preview` key points in the
    // editor at once when the layer is shown, and re-runs the job. Used by the undo commands.
    void setLayerOverride(std::size_t layer, const std::optional<scheduling::LayerOverride>& change,
                          const std::vector<Vec2>& preview);

  signals:
    void jobFinished(bool succeeded);
    void layerSelected(int layer);

  protected:
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;
    void closeEvent(QCloseEvent* event) override;

  private:
    // Where the spec's tool radius came from, with the spec it belongs to.
    enum class RadiusOrigin { Program, Typed, Asked, JobFile };
    struct RadiusChoice {
        RadiusOrigin origin = RadiusOrigin::Program;
        bool conflictConfirmed = false; // the engineer keeps a given radius the program contradicts
    };

    QWidget* buildEditorPage();
    QWidget* build3dPage();
    void buildFileMenu();
    void buildEditMenu();
    void buildViewMenu();
    void buildHelpMenu();
    void buildListingDock();
    // The listing of the result on screen; `programText` is the input's text as read.
    void showListing(std::string programText, bool newProgram);
    // The pass index of program record `record`; none outside the cutting pass.
    std::optional<std::size_t> passIndexOf(std::size_t record) const;
    // The tool slider moved: the tool, the listing and the plots' mark follow.
    void showPassRecord(std::size_t passIndex);
    // The listing's block and the plots' time line of the selected record.
    void markSelectedRecord(std::size_t record);
    // The profile the plots mark times on: the exported program's (the original's without one).
    const analysis::AxisProfile& plottedProfile() const;
    static std::optional<double> timeOfPassRecord(const analysis::AxisProfile& profile,
                                                  std::size_t passIndex);
    // The pass record of the analysed sample nearest `seconds`; none without samples.
    static std::optional<std::size_t> passRecordAtTime(const analysis::AxisProfile& profile,
                                                       double seconds);
    // A click on a plot: selects the record at that time of the exported program.
    void selectPlottedTime(double seconds);
    // A layer selected in the table: the listing shows its first block, unless the selected
    // block is one of the layer's (pass records first..last).
    void showLayerInListing(std::size_t first, std::size_t last);
    void buildToolBar();
    void buildStatusBar();
    void restoreSettings();
    // `radius`: where the new spec's radius comes from (kept when not given: a re-run).
    void startJob(job::JobSpec spec, bool reapply, std::optional<RadiusChoice> radius = {});
    // Opening another program: the CAD attached to the one on screen is not its CAD.
    void detachBladeCad();
    void onJobFinished();
    void showResult(job::DisplayScene scene);
    void showLayers();
    // Names the rotary table by the program's letter (B on a table-B machine) in the layer
    // table's headers, the plots and the colouring actions.
    void showAxisLetters(const kinematics::MachineModel& machine);
    void setLayerHeaders(QChar table);
    void showLayerRow(int row, const report::LayerMotion& motion);
    void rerunWith(job::JobSpec spec, const QString& message,
                   std::optional<RadiusChoice> radius = {});
    void rerunWithToolRadius();
    void rerunWithMachine();
    // The tool bar's radius box and the label beside it, the conflict strip, and the CAD label,
    // from the job on screen.
    void showToolRadius();
    void showBladeCad();
    // Asks about an unresolved radius conflict before an export: true to go on.
    bool resolveRadiusConflictForExport();
    // Cancels the running job and waits for it; its outcome is handled at once.
    void stopRunningJob();
    void fillMachineMenu();
    // After a re-run for an edit: marks the peak-A cell of a layer whose figure moved, saying
    // why (its own edit, or a neighbour's edit moving the junction they share).
    void explainLayerChange(int row, const report::LayerMotion& now,
                            const report::LayerMotion& before);
    void showSelectedLayer(int layer);
    void requestReapply();
    void reapplyEdits();
    void onKeyPointsEdited(const std::vector<Vec2>& before, const std::vector<Vec2>& after,
                           const QString& description);
    void onLayerSettingsChanged(int layer,
                                const std::optional<scheduling::LayerOverride>& settings);
    void onLayerReset(int layer);
    void pushLayerEdit(std::size_t layer, std::optional<scheduling::LayerOverride> after,
                       std::vector<Vec2> beforePreview, std::vector<Vec2> afterPreview,
                       const QString& description);
    const scheduling::LayerOverride* overrideOf(std::size_t layer) const;
    Status refuseWhilePending() const;
    void rememberRecent(const QString& path);
    void rebuildRecentMenu();
    void openProgramDialog();
    void openMachineDialog();
    void openCadDialog();
    void openJobDialog();
    void saveJobDialog();
    void updateExportActions();
    static bool needsToolRadius(const Error& error);
    // Asks for the ball radius a program does not state and runs it again with it.
    void askToolRadiusAndRetry(job::JobSpec spec, const QString& program);
    // "blade.nc[*] - BladeAxis": the program shown, modified while the undo stack holds edits
    // not saved in a job file.
    void updateTitle();
    void exportProgramDialog();
    void exportClDialog();
    void exportReportDialog();
    void reportOutcome(const Status& status, const QString& done, const QString& refusedTitle);
    // The Review page and Job settings dock, and their part in a job's life.
    QWidget* buildReviewPage();
    QWidget* buildComparisonPage();
    // The comparison's name of the program Export writes: the job's preset's schedule
    // (stheta-best, stheta-faithful) until a layer is edited, then "edited".
    QString exportedMethod() const;
    void buildJobSettingsDock();
    void showReview(bool newProgram);
    // An error as the dialogs show it: worded for the window (window_wording.h).
    void showJobError(const Error& error);
    // After a refused export: the Review page when the refusal is the clearance check's.
    void showRefusalSource(const Status& status);

    job::JobSpec m_spec;
    job::JobSpec m_specBeforeJob; // restored when a new job fails or is cancelled
    // The last new job started (not a re-run for edits), kept when it fails so that the Job
    // settings can run it again; with the radius choice it started with.
    job::JobSpec m_lastAttempt;
    RadiusChoice m_lastAttemptRadius;
    bool m_lastAttemptFailed = false;
    RadiusChoice m_radius;
    RadiusChoice m_radiusBeforeJob;
    quint64 m_jobGeneration = 0; // a job's finished signal is handled only while it is current
    std::optional<job::JobResult> m_result;
    job::DisplayScene m_scene;
    QString m_machinePath;
    QString m_pendingRecent; // the program of the running job: recent once it has read
    QAction* m_exportProgram = nullptr;
    QAction* m_exportCl = nullptr;
    QAction* m_exportReport = nullptr;
    QAction* m_saveJob = nullptr;
    QAction* m_clearCad = nullptr;
    QString m_cadPath;
    cad::AxisRotationPlacement m_cadPlacement;
    QUndoStack m_undo;
    JobThread* m_thread = nullptr;
    bool m_threadIsReapply = false;
    std::vector<report::LayerMotion> m_layerMotion; // the layer table's figures, for the next run
    bool m_reapplyQueued = false;
    int m_keepSelection = -1;
    QTableWidget* m_layers = nullptr;
    SThetaEditor* m_editor = nullptr;
    LayerSettingsPanel* m_layerSettings = nullptr;
    SectionView* m_section = nullptr;
    ProfilePlots* m_plots = nullptr;
    ComparisonTable* m_comparison = nullptr;
    ReviewDashboard* m_dashboard = nullptr;
    ComparisonSummary* m_comparisonSummary = nullptr;
    QTabWidget* m_tabs = nullptr;
    JobSettingsPanel* m_jobSettings = nullptr;
    QDockWidget* m_jobSettingsDock = nullptr;
    ToolpathView* m_view3d = nullptr;
    QSlider* m_toolSlider = nullptr;
    NcListing* m_listing = nullptr;
    QDockWidget* m_listingDock = nullptr;
    std::optional<std::size_t> m_selectedRecord; // program record index
    QToolBar* m_view3dBar = nullptr;             // the View menu's 3D actions, above the 3D view
    QDoubleSpinBox* m_toolRadius = nullptr;
    QLabel* m_radiusSource = nullptr;
    QWidget* m_radiusBanner = nullptr;
    QLabel* m_radiusBannerText = nullptr;
    QProgressBar* m_progress = nullptr;
    QPushButton* m_cancel = nullptr;
    QLabel* m_machineLabel = nullptr;
    QLabel* m_cadLabel = nullptr;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_machineMenu = nullptr;
    QAction* m_compareAction = nullptr;
    QAction* m_optimumAction = nullptr;
    QAction* m_darkAction = nullptr;
    std::array<QAction*, 2> m_speedColourings{}; // by the table's speed, re-scheduled, original
    QChar m_tableLetter = QLatin1Char('A');      // the program's letter of the rotary table
};

} // namespace bladeaxis::ui
