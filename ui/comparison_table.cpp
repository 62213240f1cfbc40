#include "ui/comparison_table.h"

#include "core/report/compare_report.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QHeaderView>
#include <QStyle>
#include <algorithm>
#include <optional>
#include <set>

namespace bladeaxis::ui {

namespace {

// The report's ASCII spellings, as a screen can show them.
QString screenText(const std::string& text) {
    QString screen = QString::fromStdString(text);
    screen.replace(QStringLiteral("^2"), QStringLiteral("²"));
    screen.replace(QStringLiteral("theta''"), QStringLiteral("θ''")); // not "stheta-best"
    return screen;
}

// Two short lines instead of one long one: "A peak acc." over "(deg/s²)".
QString headerText(const std::string& header) {
    QString text = screenText(header);
    text.replace(QStringLiteral(" ("), QStringLiteral("\n("));
    text.replace(QStringLiteral(" vs "), QStringLiteral("\nvs "));
    text.replace(QStringLiteral(" / "), QStringLiteral("\n/ "));
    return text;
}

QString csvField(const QString& text) {
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"')) &&
        !text.contains(QLatin1Char('\n'))) {
        return text;
    }
    QString quoted = text;
    quoted.replace(QStringLiteral("\""), QStringLiteral("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

QTableWidgetItem* cellItem(const report::CompareTableCell& cell, bool numeric) {
    auto* item = new QTableWidgetItem(screenText(cell.text));
    item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
    if (cell.value) {
        item->setData(ComparisonTable::kValueRole, *cell.value);
    }
    if (!cell.note.empty()) {
        item->setToolTip(screenText(cell.note));
    }
    if (numeric) {
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    }
    return item;
}

} // namespace

ComparisonTable::ComparisonTable(QWidget* parent) : QTableWidget(parent) {
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setSelectionMode(QAbstractItemView::ExtendedSelection);
    setAlternatingRowColors(true);
    verticalHeader()->setVisible(false);
    horizontalHeader()->setDefaultAlignment(Qt::AlignCenter);
    setToolTip(tr("Every method on the same ball centres, evaluated the same way as report.html; "
                  "hover a method for its setting"));
    auto* copy = new QAction(tr("Copy as CSV"), this);
    copy->setShortcut(QKeySequence::Copy);
    copy->setShortcutContext(Qt::WidgetShortcut);
    connect(copy, &QAction::triggered, this, &ComparisonTable::copyAsCsv);
    addAction(copy);
    setContextMenuPolicy(Qt::ActionsContextMenu);
}

void ComparisonTable::setComparison(const compare::Comparison& comparison) {
    clear();
    if (comparison.methods.empty()) {
        return;
    }
    const report::CompareTable table = report::compareTable(comparison);
    setColumnCount(static_cast<int>(table.columns.size()));
    setRowCount(static_cast<int>(table.rows.size()));
    for (std::size_t column = 0; column < table.columns.size(); ++column) {
        const report::CompareTableColumn& definition = table.columns[column];
        auto* header = new QTableWidgetItem(headerText(definition.header));
        header->setData(kKeyRole, QString::fromStdString(definition.key));
        header->setToolTip(screenText(definition.description));
        setHorizontalHeaderItem(static_cast<int>(column), header);
    }
    for (std::size_t row = 0; row < table.rows.size(); ++row) {
        for (std::size_t column = 0; column < table.columns.size(); ++column) {
            setItem(static_cast<int>(row), static_cast<int>(column),
                    cellItem(table.rows[row][column], column > 0));
        }
    }
    for (std::size_t column = 0; column < table.columns.size(); ++column) {
        markBest(static_cast<int>(column), table.columns[column].better);
    }
    resizeColumnsToContents();
}

void ComparisonTable::setExportedMethod(const QString& method) {
    m_exportedRow = -1;
    const QString note = tr("Export writes this program. ");
    for (int row = 0; row < rowCount(); ++row) {
        QTableWidgetItem* name = item(row, 0);
        const bool exported = name->text() == method;
        name->setIcon(exported ? style()->standardIcon(QStyle::SP_DialogSaveButton) : QIcon());
        QString tip = name->toolTip();
        tip.remove(note);
        name->setToolTip(exported ? note + tip : tip);
        for (int column = 0; column < columnCount(); ++column) {
            QColor tint = palette().color(QPalette::Highlight);
            tint.setAlpha(40);
            item(row, column)->setBackground(exported ? QBrush(tint) : QBrush());
        }
        m_exportedRow = exported ? row : m_exportedRow;
    }
}

void ComparisonTable::markBest(int column, report::Better better) {
    if (better == report::Better::Neither) {
        return;
    }
    std::optional<double> best;
    for (int row = 0; row < rowCount(); ++row) {
        const QVariant value = item(row, column)->data(kValueRole);
        if (value.isValid()) {
            const double number = value.toDouble();
            if (!best || (better == report::Better::Lower ? number < *best : number > *best)) {
                best = number;
            }
        }
    }
    for (int row = 0; best && row < rowCount(); ++row) {
        QTableWidgetItem* cell = item(row, column);
        const QVariant value = cell->data(kValueRole);
        if (value.isValid() && value.toDouble() == *best) { // ties are all best
            QFont font = cell->font();
            font.setBold(true);
            cell->setFont(font);
        }
    }
}

void ComparisonTable::clear() {
    QTableWidget::clear();
    setRowCount(0);
    setColumnCount(0);
}

int ComparisonTable::columnOf(const QString& key) const {
    for (int column = 0; column < columnCount(); ++column) {
        const QTableWidgetItem* header = horizontalHeaderItem(column);
        if (header != nullptr && header->data(kKeyRole).toString() == key) {
            return column;
        }
    }
    return -1;
}

QString ComparisonTable::toCsv() const {
    std::set<int> rows, columns;
    for (const QModelIndex& index : selectedIndexes()) {
        rows.insert(index.row());
        columns.insert(index.column());
    }
    if (rows.empty()) {
        for (int row = 0; row < rowCount(); ++row) {
            rows.insert(row);
        }
        for (int column = 0; column < columnCount(); ++column) {
            columns.insert(column);
        }
    }
    auto line = [&](auto textAt) {
        QStringList fields;
        for (int column : columns) {
            fields << csvField(textAt(column));
        }
        return fields.join(QLatin1Char(',')) + QLatin1Char('\n');
    };
    QString csv = line([this](int column) {
        const QTableWidgetItem* header = horizontalHeaderItem(column);
        return header != nullptr ? header->text().replace(QLatin1Char('\n'), QLatin1Char(' '))
                                 : QString();
    });
    for (int row : rows) {
        csv += line([this, row](int column) {
            const QTableWidgetItem* cell = item(row, column);
            return cell != nullptr ? cell->text() : QString();
        });
    }
    return csv;
}

void ComparisonTable::copyAsCsv() const {
    QApplication::clipboard()->setText(toCsv());
}

} // namespace bladeaxis::ui
