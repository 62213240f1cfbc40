#pragma once
// The comparison at a glance (issue 38): one row per method with the figures a machinist
// decides on (A reversals, peak A velocity and acceleration, each cycle time, channel
// clearance), numbers grouped in thousands, the method names in a frozen column (the row
// header, which stays while the figures scroll sideways), and a recommendation stated in words
// with its rule. The full Table-2 (ComparisonTable) is shown on demand beside it. Every figure
// is the comparison's (core/compare), read, not recomputed.

#include "core/compare/compare.h"
#include "core/kinematics/machine_model.h"

#include <QWidget>

class QLabel;
class QTableWidget;

namespace bladeaxis::ui {

class ComparisonSummary final : public QWidget {
    Q_OBJECT

  public:
    // Item data roles: a cell's number in the column's unit; a header's column key.
    static constexpr int kValueRole = Qt::UserRole;
    static constexpr int kKeyRole = Qt::UserRole + 1;

    explicit ComparisonSummary(QWidget* parent = nullptr);

    // `exported`: the method Export writes; `planner`: the machine's controller model, whose
    // cycle time the recommendation weighs.
    void setComparison(const compare::Comparison& comparison, const QString& exported,
                       kinematics::Planner planner);
    void clear();

    QTableWidget* table() const { return m_table; }
    QLabel* recommendation() const { return m_recommendation; }
    // The recommended method, empty without a comparison.
    QString recommendedMethod() const { return m_recommended; }
    // The column of a key ("reversals", "peak_velocity", "peak_acceleration", "t1", "t2",
    // "block_time", "clearance"), -1 when absent; the row of a method, -1 when absent.
    int columnOf(const QString& key) const;
    int rowOf(const QString& method) const;

  private:
    void fillRow(int row, const compare::MethodResult& method);
    void recommend(const compare::Comparison& comparison, const QString& exported,
                   kinematics::Planner planner);

    QLabel* m_recommendation = nullptr;
    QTableWidget* m_table = nullptr;
    QString m_recommended;
};

} // namespace bladeaxis::ui
