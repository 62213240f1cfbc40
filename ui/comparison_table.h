#pragma once
// The comparison table of issue 5 (the paper's Table 2 per method): one row per method, the
// columns of report::compareTable (per-axis peaks, A reductions against the quaternion
// baseline and the original, A reversals, T1, T2, gaps to the optimum, compute time), so the
// GUI shows exactly the numbers and formatting of report.html. Hover a method for its setting
// (the quaternion row lists the fairness rule's best setting per metric); the best value of a
// column is bold; Ctrl+C copies the selection (or the whole table) as CSV.

#include "core/compare/compare.h"
#include "core/report/compare_report.h"

#include <QTableWidget>

namespace bladeaxis::ui {

class ComparisonTable final : public QTableWidget {
    Q_OBJECT

  public:
    // Item data role holding the cell's number in the column's unit (a double); cells without
    // a number (the method name, a missing T2) hold none.
    static constexpr int kValueRole = Qt::UserRole;
    // Header item data role holding the column's key (report::CompareTableColumn::key).
    static constexpr int kKeyRole = Qt::UserRole + 1;

    explicit ComparisonTable(QWidget* parent = nullptr);

    void setComparison(const compare::Comparison& comparison);
    // Marks the method whose program Export writes (icon, tint, tooltip); the others unmarked.
    void setExportedMethod(const QString& method);
    // The marked row, -1 when none.
    int exportedRow() const { return m_exportedRow; }
    // Hides QTableWidget::clear: removes the rows and the columns.
    void clear();

    // The column showing a report::compareTable key, -1 when absent.
    int columnOf(const QString& key) const;
    // The selected cells (the whole table when nothing is selected) as CSV, header first.
    QString toCsv() const;
    void copyAsCsv() const;

  private:
    void markBest(int column, report::Better better);

    int m_exportedRow = -1;
};

} // namespace bladeaxis::ui
