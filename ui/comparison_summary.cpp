#include "ui/comparison_summary.h"

#include "core/base/units.h"
#include "core/job/job.h"
#include "ui/number_text.h"

#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QStyle>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <tuple>

namespace bladeaxis::ui {
namespace {

using kinematics::AxisId;

struct Column {
    const char* key;
    const char* header; // %1: the table's letter
    int decimals;
};

constexpr Column kColumns[] = {
    {"reversals", QT_TRANSLATE_NOOP("ComparisonSummary", "%1 rev."), 0},
    {"peak_velocity", QT_TRANSLATE_NOOP("ComparisonSummary", "Peak %1 vel.\n[°/s]"), 1},
    {"peak_acceleration", QT_TRANSLATE_NOOP("ComparisonSummary", "Peak %1 acc.\n[°/s²]"), 0},
    {"t1", QT_TRANSLATE_NOOP("ComparisonSummary", "T1 constant\nfeed [s]"), 1},
    {"t2", QT_TRANSLATE_NOOP("ComparisonSummary", "T2 look-\nahead [s]"), 1},
    {"block_time", QT_TRANSLATE_NOOP("ComparisonSummary", "Block time\nblock-by-block [s]"), 1},
    {"clearance", QT_TRANSLATE_NOOP("ComparisonSummary", "Channel\nclearance [°]"), 2},
};
constexpr int kColumnCount = static_cast<int>(std::size(kColumns));

QString grouped(double value, int decimals) {
    return groupedNumber(value, decimals);
}

// The cycle time of the machine's own controller model, T1 when that model has none.
double machineTime(const compare::MethodResult& method, kinematics::Planner planner) {
    if (planner == kinematics::Planner::BlockByBlock && method.blockByBlock.time > 0.0) {
        return method.blockByBlock.time;
    }
    if (planner == kinematics::Planner::LookAhead && method.t2) {
        return *method.t2;
    }
    return method.t1.time;
}

QString machineTimeName(const compare::MethodResult& method, kinematics::Planner planner) {
    if (planner == kinematics::Planner::BlockByBlock && method.blockByBlock.time > 0.0) {
        return ComparisonSummary::tr("block time (block-by-block, this machine's model)");
    }
    if (planner == kinematics::Planner::LookAhead && method.t2) {
        return ComparisonSummary::tr("T2 (look-ahead, this machine's model)");
    }
    return ComparisonSummary::tr("T1 (constant feed)");
}

} // namespace

ComparisonSummary::ComparisonSummary(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("comparisonSummary"));
    m_recommendation = new QLabel(this);
    m_recommendation->setObjectName(QStringLiteral("comparisonRecommendation"));
    m_recommendation->setWordWrap(true);
    m_recommendation->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_table = new QTableWidget(0, kColumnCount, this);
    m_table->setObjectName(QStringLiteral("comparisonSummaryTable"));
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setAlternatingRowColors(true);
    m_table->horizontalHeader()->setDefaultAlignment(Qt::AlignCenter);
    // The method names are the row headers: they stay in place while the figures scroll.
    m_table->verticalHeader()->setVisible(true);
    m_table->verticalHeader()->setDefaultAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    m_table->setToolTip(tr("Every method on the same ball centres (the comparison of report.html), "
                           "the figures a choice rests on; \"Full table\" shows every column"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_recommendation);
    layout->addWidget(m_table, 1);
    clear();
}

void ComparisonSummary::clear() {
    m_table->setRowCount(0);
    m_recommended.clear();
    m_recommendation->setText(
        tr("Run a job with Comparison on (Edit menu) to compare the methods here"));
}

void ComparisonSummary::setComparison(const compare::Comparison& comparison,
                                      const QString& exported, kinematics::Planner planner) {
    clear();
    const QChar table = QLatin1Char(comparison.letters[static_cast<std::size_t>(AxisId::A)]);
    for (int column = 0; column < kColumnCount; ++column) {
        QString text = tr(kColumns[column].header);
        if (text.contains(QStringLiteral("%1"))) {
            text = text.arg(table);
        }
        auto* header = new QTableWidgetItem(text);
        header->setData(kKeyRole, QString::fromLatin1(kColumns[column].key));
        m_table->setHorizontalHeaderItem(column, header);
    }
    m_table->setRowCount(static_cast<int>(comparison.methods.size()));
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const compare::MethodResult& method = comparison.methods[static_cast<std::size_t>(row)];
        const QString name = QString::fromStdString(method.method);
        auto* header = new QTableWidgetItem(name);
        if (name == exported) {
            header->setIcon(style()->standardIcon(QStyle::SP_DialogSaveButton));
            header->setToolTip(tr("Export writes this program"));
            QFont bold = header->font();
            bold.setBold(true);
            header->setFont(bold);
        } else {
            header->setToolTip(QString::fromStdString(method.setting));
        }
        m_table->setVerticalHeaderItem(row, header);
        fillRow(row, method);
    }
    m_table->resizeColumnsToContents();
    recommend(comparison, exported, planner);
}

void ComparisonSummary::fillRow(int row, const compare::MethodResult& method) {
    const analysis::AxisSeries& a = method.profile.axis(AxisId::A);
    const std::optional<double> values[kColumnCount] = {
        static_cast<double>(method.profile.aReversals.count),
        units::radToDeg(a.peakVelocity),
        units::radToDeg(a.peakAcceleration),
        method.t1.time,
        method.t2,
        method.blockByBlock.time > 0.0 ? std::optional(method.blockByBlock.time) : std::nullopt,
        units::radToDeg(method.channel.minClearance)};
    for (int column = 0; column < kColumnCount; ++column) {
        auto* item = new QTableWidgetItem(
            values[column] ? grouped(*values[column], kColumns[column].decimals) : tr("—"));
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        if (values[column]) {
            item->setData(kValueRole, *values[column]);
        } else if (column == columnOf(QStringLiteral("t2"))) {
            item->setToolTip(QString::fromStdString(method.t2Failure));
        }
        m_table->setItem(row, column, item);
    }
}

// Cycle times closer than this count as equal: they are models of a controller, not its
// measurement (the block-by-block and look-ahead models of one program differ by far more), and
// a few per cent of time is not worth several times the peak acceleration.
constexpr double kSameTime = 0.05;

// The rule, said with the recommendation: among the programs the window can export (the S-θ
// presets and the edited schedule) that stay inside the feasible channel, the fewest A
// reversals, then the shorter cycle time of this machine's controller model when the times
// differ by more than 5 %, else the lower peak A acceleration. The optimum and the quaternion
// baseline are references: the recommendation says how close the choice comes to the optimum.
void ComparisonSummary::recommend(const compare::Comparison& comparison, const QString& exported,
                                  kinematics::Planner planner) {
    const auto better = [planner](const compare::MethodResult& a, const compare::MethodResult& b) {
        if (a.profile.aReversals.count != b.profile.aReversals.count) {
            return a.profile.aReversals.count < b.profile.aReversals.count;
        }
        const double ta = machineTime(a, planner), tb = machineTime(b, planner);
        if (std::abs(ta - tb) > kSameTime * std::max(ta, tb)) {
            return ta < tb;
        }
        return a.profile.axis(AxisId::A).peakAcceleration <
               b.profile.axis(AxisId::A).peakAcceleration;
    };
    const auto exportable = [&exported](const std::string& method) {
        return method.starts_with("stheta-") || method == job::kEditedMethod ||
               QString::fromStdString(method) == exported;
    };
    const compare::MethodResult* best = nullptr;
    for (const compare::MethodResult& method : comparison.methods) {
        if (!exportable(method.method) || method.channel.minClearance < 0.0) {
            continue;
        }
        if (best == nullptr || better(method, *best)) {
            best = &method;
        }
    }
    const compare::MethodResult* original = comparison.find("original");
    if (best == nullptr || original == nullptr) {
        m_recommendation->setText(tr("No program the window can export stays inside the feasible "
                                     "channel: none is recommended"));
        return;
    }
    m_recommended = QString::fromStdString(best->method);
    const QChar table = QLatin1Char(comparison.letters[static_cast<std::size_t>(AxisId::A)]);
    const auto peak = [](const compare::MethodResult& m) {
        return grouped(units::radToDeg(m.profile.axis(AxisId::A).peakAcceleration), 0);
    };
    QString text =
        tr("<b>Recommended: %1</b> — %2 reversals %3 (original %4), %5 %6 s (original %7 s), "
           "peak %2 acceleration %8 °/s² (original %9 °/s²).")
            .arg(m_recommended, table)
            .arg(grouped(best->profile.aReversals.count, 0))
            .arg(grouped(original->profile.aReversals.count, 0))
            .arg(machineTimeName(*best, planner))
            .arg(grouped(machineTime(*best, planner), 1))
            .arg(grouped(machineTime(*original, planner), 1))
            .arg(peak(*best), peak(*original));
    if (m_recommended == exported) {
        text += tr(" Export writes it.");
    } else if (m_recommended.startsWith(QStringLiteral("stheta-"))) {
        text += tr(" Export writes %1; choose the preset \"%2\" in Job settings to export the "
                   "recommended one.")
                    .arg(exported, m_recommended.mid(7));
    } else {
        text += tr(" Export writes %1.").arg(exported);
    }
    for (const char* reference : {"optimal-qp", "optimal-lp"}) {
        if (const compare::MethodResult* optimum = comparison.find(reference)) {
            text += tr(" The optimum in the same channel (%1, a reference, not exported): %2 "
                       "%3 s, peak %4 °/s².")
                        .arg(QString::fromLatin1(reference), machineTimeName(*optimum, planner))
                        .arg(grouped(machineTime(*optimum, planner), 1))
                        .arg(peak(*optimum));
            break;
        }
    }
    m_recommendation->setText(text);
    m_recommendation->setToolTip(
        tr("The rule: among the programs the window can export that stay inside the feasible "
           "channel, the fewest %1 reversals, then the shorter cycle time of this machine's "
           "controller model when the times differ by more than 5 %, else the lower peak %1 "
           "acceleration")
            .arg(table));
}

int ComparisonSummary::columnOf(const QString& key) const {
    for (int column = 0; column < kColumnCount; ++column) {
        if (QLatin1String(kColumns[column].key) == key) {
            return column;
        }
    }
    return -1;
}

int ComparisonSummary::rowOf(const QString& method) const {
    for (int row = 0; row < m_table->rowCount(); ++row) {
        if (m_table->verticalHeaderItem(row)->text() == method) {
            return row;
        }
    }
    return -1;
}

} // namespace bladeaxis::ui
