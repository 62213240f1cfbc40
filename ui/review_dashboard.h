#pragma once
// The first page after a job (issue 38, "the review desk"): what the batch prints, on one page.
// Before and after: A reversals, peak A velocity and acceleration, each cycle time beside the
// model it assumes (constant feed T1, look-ahead T2 grid-converged, block-by-block as LinuxCNC
// 2.9 plans), the axis that limits the feed; the checks (channel clearance, ball centres kept);
// gouges and collisions, every point listed; every warning with the line or layer it names.
// Every figure is read from the JobResult (the batch's), none is computed here.
//
// An output that gouges or collides is refused by export until the engineer ticks the
// acknowledgement under the listed points (the batch's --force); a new result clears the tick.

#include "core/job/job.h"

#include <QWidget>

class QCheckBox;
class QLabel;
class QTableWidget;

namespace bladeaxis::ui {

class ReviewDashboard final : public QWidget {
    Q_OBJECT

  public:
    // The columns of the figures table.
    enum FigureColumn { kFigure, kOriginal, kRescheduled, kChange, kModel, kFigureColumns };
    // The columns of the gouge/collision list.
    enum IssueColumn {
        kIssueLayer,
        kIssuePoint,
        kIssueLine,
        kIssueKind,
        kIssueDepth,
        kIssueInput,
        kIssueColumns
    };
    // The warnings table: where (line or layer) and the text.
    enum WarningColumn { kWarningWhere, kWarningText, kWarningColumns };
    // Item data roles: a number cell's value in the unit shown; a figure row's key (column 0).
    static constexpr int kValueRole = Qt::UserRole;
    static constexpr int kKeyRole = Qt::UserRole + 1;
    // A warning row's layer (int) when it names one.
    static constexpr int kLayerRole = Qt::UserRole + 2;

    explicit ReviewDashboard(QWidget* parent = nullptr);

    void setResult(const job::JobResult& result);
    void clear();

    // The figures table's row of a key: "reversals", "peak_velocity", "peak_acceleration",
    // "t1", "t2", "block_time", "limiting_axis", "channel_clearance", "ball_centres",
    // "gouges_collisions"; -1 when the result has no such figure.
    int rowOf(const QString& key) const;
    QTableWidget* figures() const { return m_figures; }
    QTableWidget* warnings() const { return m_warnings; }
    QTableWidget* clearanceIssues() const { return m_issues; }
    QCheckBox* acknowledgeBox() const { return m_acknowledge; }
    QLabel* headline() const { return m_headline; }
    // Gouge and collision points of the output program (0 without a clearance check).
    int clearanceIssueCount() const;
    // True when nothing gouges or collides, or the engineer ticked the acknowledgement.
    bool clearanceAcknowledged() const;

  signals:
    // A warning or a gouge naming a layer was activated: select it everywhere.
    void layerRequested(int layer);
    void acknowledgementChanged(bool acknowledged);

  private:
    void showFigures(const job::JobResult& result);
    void showCycleTimes(const job::JobResult& result);
    void showChecks(const job::JobResult& result);
    void showWarnings(const job::JobResult& result);
    void showClearanceIssues(const job::JobResult& result);
    int addFigure(const QString& key, const QString& name, const QString& model);

    QLabel* m_headline = nullptr;
    QTableWidget* m_figures = nullptr;
    QLabel* m_warningsTitle = nullptr;
    QTableWidget* m_warnings = nullptr;
    QLabel* m_issuesTitle = nullptr;
    QTableWidget* m_issues = nullptr;
    QCheckBox* m_acknowledge = nullptr;
};

} // namespace bladeaxis::ui
