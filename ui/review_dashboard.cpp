#include "ui/review_dashboard.h"

#include "core/base/units.h"
#include "core/job/cycle_time_models.h"
#include "ui/number_text.h"
#include "ui/window_wording.h"

#include <QCheckBox>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QRegularExpression>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

namespace bladeaxis::ui {
namespace {

using kinematics::AxisId;

QTableWidgetItem* textItem(const QString& text) {
    auto* item = new QTableWidgetItem(text);
    item->setFlags(item->flags() & ~Qt::ItemIsEditable);
    return item;
}

// Grouped as the desktop's language groups it ("1,408,372"), the value kept for tests.
QTableWidgetItem* numberItem(double value, int decimals, const QString& unit = {}) {
    QString text = groupedNumber(value, decimals);
    if (!unit.isEmpty()) {
        text += QLatin1Char(' ') + unit;
    }
    auto* item = textItem(text);
    item->setData(ReviewDashboard::kValueRole, value);
    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    return item;
}

// "61.3 % lower" / "12.0 % higher"; empty when there is nothing to compare.
QString changeText(double before, double after, const QString& lower, const QString& higher) {
    if (!(std::abs(before) > 0.0) || !std::isfinite(before) || !std::isfinite(after)) {
        return {};
    }
    const double relative = 100.0 * (before - after) / before;
    return QStringLiteral("%1 % %2").arg(QLocale().toString(std::abs(relative), 'f', 1),
                                         relative >= 0.0 ? lower : higher);
}

QString bindingText(const analysis::ConstantFeedTime& time, const kinematics::MachineModel& m) {
    using Binding = analysis::ConstantFeedTime::Binding;
    const QChar letter = QLatin1Char(m.letter(time.bindingAxis));
    switch (time.binding) {
    case Binding::Velocity:
        return ReviewDashboard::tr("%1 velocity").arg(letter);
    case Binding::Acceleration:
        return ReviewDashboard::tr("%1 acceleration").arg(letter);
    case Binding::Jerk:
        return ReviewDashboard::tr("%1 jerk").arg(letter);
    case Binding::Programmed:
        break;
    }
    return ReviewDashboard::tr("the feed (%1 nearest)").arg(letter);
}

// The model the peaks assume (docs/figures.md): the default's controller filter, or the method.
QString derivativeModel(const analysis::AxisProfile& profile) {
    if (profile.method == analysis::DerivativeMethod::Filtered) {
        return ReviewDashboard::tr("at the programmed feed, a controller smoothing each axis over "
                                   "%1 ms (docs/figures.md)")
            .arg(QLocale().toString(profile.filterSeconds * 1000.0, 'g', 3));
    }
    return ReviewDashboard::tr("at the programmed feed, derivatives by %1 (docs/figures.md)")
        .arg(QString::fromUtf8(analysis::nameOf(profile.method)));
}

QString thisMachine(const job::JobResult& result, kinematics::Planner model) {
    return result.machine.controller.planner == model ? ReviewDashboard::tr(" — this machine's")
                                                      : QString();
}

// Where a warning points: "line 120" for "blade.nc:120: ...", "layer 7" for "layer 7: ...".
struct WarningPlace {
    QString text;
    int layer = -1;
};

WarningPlace placeOf(const QString& warning) {
    // "dir/blade.nc:120:" or "dir/blade.nc:" at a word's start: the program's line, or the file.
    static const QRegularExpression kLine(
        QStringLiteral(R"((?:^|\s)(?:[^\s:]*/)?([\w.+-]+\.\w+)(?::(\d+))?:)"));
    static const QRegularExpression kLayer(QStringLiteral(R"(\blayers? (\d+))"));
    WarningPlace place;
    if (const auto line = kLine.match(warning); line.hasMatch()) {
        place.text = line.captured(2).isEmpty()
                         ? line.captured(1)
                         : ReviewDashboard::tr("line %1").arg(line.captured(2));
    }
    if (const auto layer = kLayer.match(warning); layer.hasMatch()) {
        place.layer = layer.captured(1).toInt();
        const QString layerText = ReviewDashboard::tr("layer %1").arg(place.layer);
        place.text =
            place.text.isEmpty() ? layerText : place.text + QStringLiteral(", ") + layerText;
    }
    return place;
}

QTableWidget* table(int columns, const QStringList& headers, const QString& name, QWidget* parent) {
    auto* widget = new QTableWidget(0, columns, parent);
    widget->setObjectName(name);
    widget->setHorizontalHeaderLabels(headers);
    widget->verticalHeader()->setVisible(false);
    widget->horizontalHeader()->setStretchLastSection(true);
    widget->setSelectionBehavior(QAbstractItemView::SelectRows);
    widget->setEditTriggers(QAbstractItemView::NoEditTriggers);
    widget->setWordWrap(true);
    return widget;
}

QLabel* title(const QString& text, QWidget* parent) {
    auto* label = new QLabel(text, parent);
    QFont font = label->font();
    font.setBold(true);
    label->setFont(font);
    return label;
}

} // namespace

ReviewDashboard::ReviewDashboard(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("reviewDashboard"));
    m_headline = new QLabel(tr("Run a job to review it here"), this);
    m_headline->setObjectName(QStringLiteral("dashboardHeadline"));
    m_headline->setWordWrap(true);
    m_figures = table(kFigureColumns,
                      {tr("Figure"), tr("Original"), tr("Re-scheduled"), tr("Change"),
                       tr("Model / what it assumes")},
                      QStringLiteral("dashboardFigures"), this);
    m_figures->setSelectionMode(QAbstractItemView::NoSelection);
    // The figures as narrow as they read, the model's words wrapped in the rest of the width.
    for (int column = kFigure; column < kModel; ++column) {
        m_figures->horizontalHeader()->setSectionResizeMode(column, QHeaderView::ResizeToContents);
    }
    m_figures->horizontalHeader()->setSectionResizeMode(kModel, QHeaderView::Stretch);
    m_figures->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_figures->setVerticalScrollMode(QAbstractItemView::ScrollPerPixel);
    connect(m_figures->horizontalHeader(), &QHeaderView::sectionResized, m_figures,
            [this] { m_figures->resizeRowsToContents(); });
    m_warningsTitle = title(tr("Warnings"), this);
    m_warnings = table(kWarningColumns, {tr("Where"), tr("Warning")},
                       QStringLiteral("dashboardWarnings"), this);
    m_warnings->setToolTip(tr("Every warning of the job; double-click one that names a layer to "
                              "select the layer"));
    connect(m_warnings, &QTableWidget::cellDoubleClicked, this, [this](int row, int) {
        const int layer = m_warnings->item(row, kWarningWhere)->data(kLayerRole).toInt();
        if (layer >= 0) {
            emit layerRequested(layer);
        }
    });
    m_issuesTitle = title(tr("Gouges and collisions"), this);
    m_issues = table(
        kIssueColumns,
        {tr("Layer"), tr("Point"), tr("Line"), tr("Kind"), tr("Depth [mm]"), tr("Input program")},
        QStringLiteral("dashboardClearanceIssues"), this);
    m_issues->setToolTip(tr("Every CL point of the output where the tool gouges the blade or the "
                            "shank or holder collides: layer, point of the cutting pass "
                            "(1 first), program line, depth; double-click to select the layer"));
    connect(m_issues, &QTableWidget::cellDoubleClicked, this, [this](int row, int) {
        emit layerRequested(m_issues->item(row, kIssueLayer)->data(kValueRole).toInt());
    });
    m_acknowledge = new QCheckBox(QString::fromUtf8(controls::kAcknowledge), this);
    m_acknowledge->setObjectName(QStringLiteral("acknowledgeClearance"));
    m_acknowledge->setToolTip(tr("Export refuses an output that gouges or collides until you tick "
                                 "this, having reviewed the points above (the batch's --force)"));
    connect(m_acknowledge, &QCheckBox::toggled, this, &ReviewDashboard::acknowledgementChanged);

    auto* lower = new QWidget(this);
    auto* lowerLayout = new QVBoxLayout(lower);
    lowerLayout->setContentsMargins(0, 0, 0, 0);
    lowerLayout->addWidget(m_warningsTitle);
    lowerLayout->addWidget(m_warnings, 1);
    lowerLayout->addWidget(m_issuesTitle);
    lowerLayout->addWidget(m_issues, 1);
    lowerLayout->addWidget(m_acknowledge);
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_figures);
    split->addWidget(lower);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_headline);
    layout->addWidget(split, 1);
    clear();
}

void ReviewDashboard::clear() {
    m_figures->setRowCount(0);
    m_warnings->setRowCount(0);
    m_issues->setRowCount(0);
    m_headline->setText(tr("Run a job to review it here"));
    m_warningsTitle->setText(tr("Warnings"));
    m_issuesTitle->setVisible(false);
    m_issues->setVisible(false);
    const QSignalBlocker block(m_acknowledge);
    m_acknowledge->setChecked(false);
    m_acknowledge->setVisible(false);
}

void ReviewDashboard::setResult(const job::JobResult& result) {
    clear();
    const QChar table = QLatin1Char(result.machine.letter(AxisId::A));
    if (result.rescheduled) {
        m_headline->setText(
            tr("%1 reversals %2 → %3 (%4 layers, %5 kept their original orientation). Figures "
               "from the job, as the batch prints them.")
                .arg(table)
                .arg(result.original.aReversals.count)
                .arg(result.rescheduled->profile.aReversals.count)
                .arg(result.rescheduled->schedule.layers.size())
                .arg(result.rescheduled->layersKeptOriginal));
    } else {
        m_headline->setText(tr("The program analysed, not re-scheduled."));
    }
    m_figures->setColumnHidden(kRescheduled, !result.rescheduled);
    m_figures->setColumnHidden(kChange, !result.rescheduled);
    showFigures(result);
    showCycleTimes(result);
    showChecks(result);
    m_figures->resizeRowsToContents();
    showWarnings(result);
    showClearanceIssues(result);
}

int ReviewDashboard::addFigure(const QString& key, const QString& name, const QString& model) {
    const int row = m_figures->rowCount();
    m_figures->insertRow(row);
    auto* nameItem = textItem(name);
    nameItem->setData(kKeyRole, key);
    m_figures->setItem(row, kFigure, nameItem);
    m_figures->setItem(row, kModel, textItem(model));
    return row;
}

void ReviewDashboard::showFigures(const job::JobResult& result) {
    const QChar table = QLatin1Char(result.machine.letter(AxisId::A));
    const analysis::AxisProfile& before = result.original;
    const analysis::AxisProfile* after =
        result.rescheduled ? &result.rescheduled->profile : nullptr;
    int row = addFigure(QStringLiteral("reversals"), tr("%1 reversals").arg(table),
                        tr("direction changes of %1 along the cutting pass").arg(table));
    m_figures->setItem(row, kOriginal, numberItem(before.aReversals.count, 0));
    if (after) {
        m_figures->setItem(row, kRescheduled, numberItem(after->aReversals.count, 0));
        m_figures->setItem(
            row, kChange,
            textItem(QLocale().toString(after->aReversals.count - before.aReversals.count)));
    }
    const std::array<std::tuple<QString, QString, QString, double analysis::AxisSeries::*, int>, 2>
        peaks{{{QStringLiteral("peak_velocity"), tr("Peak %1 velocity").arg(table),
                QStringLiteral("°/s"), &analysis::AxisSeries::peakVelocity, 1},
               {QStringLiteral("peak_acceleration"), tr("Peak %1 acceleration").arg(table),
                QStringLiteral("°/s²"), &analysis::AxisSeries::peakAcceleration, 0}}};
    for (const auto& [key, name, unit, member, decimals] : peaks) {
        row = addFigure(key, name, derivativeModel(before));
        const double was = units::radToDeg(before.axis(AxisId::A).*member);
        m_figures->setItem(row, kOriginal, numberItem(was, decimals, unit));
        if (after) {
            const double now = units::radToDeg(after->axis(AxisId::A).*member);
            m_figures->setItem(row, kRescheduled, numberItem(now, decimals, unit));
            m_figures->setItem(row, kChange,
                               textItem(changeText(was, now, tr("lower"), tr("higher"))));
        }
    }
}

void ReviewDashboard::showCycleTimes(const job::JobResult& result) {
    const job::RescheduleOutcome* outcome = result.rescheduled ? &*result.rescheduled : nullptr;
    const auto times = [&](int row, double was, std::optional<double> now) {
        m_figures->setItem(row, kOriginal, numberItem(was, 1, QStringLiteral("s")));
        if (now) {
            m_figures->setItem(row, kRescheduled, numberItem(*now, 1, QStringLiteral("s")));
            m_figures->setItem(row, kChange,
                               textItem(changeText(was, *now, tr("shorter"), tr("longer"))));
        }
    };
    int row = addFigure(QStringLiteral("t1"), tr("T1, constant feed"),
                        tr("constant feed — %1").arg(QString::fromUtf8(job::kConstantFeedModel)));
    times(row, result.constantFeed.time,
          outcome ? std::optional(outcome->constantFeed.time) : std::nullopt);
    if (result.timeOptimal) {
        const auto grid = [](const analysis::ConvergedTime& t2) {
            return tr("%1 steps per block, last change %2 %")
                .arg(t2.subdivisions)
                .arg(QLocale().toString(100.0 * t2.lastChange, 'f', 2));
        };
        QString grids = tr("original %1").arg(grid(*result.timeOptimal));
        if (outcome && outcome->timeOptimal) {
            grids += tr("; re-scheduled %1").arg(grid(*outcome->timeOptimal));
        }
        row = addFigure(QStringLiteral("t2"), tr("T2, look-ahead"),
                        tr("look-ahead — %1 (%2)%3")
                            .arg(QString::fromUtf8(job::kLookAheadModel), grids,
                                 thisMachine(result, kinematics::Planner::LookAhead)));
        times(row, result.timeOptimal->time,
              outcome && outcome->timeOptimal ? std::optional(outcome->timeOptimal->time)
                                              : std::nullopt);
    }
    if (result.blockByBlock.time > 0.0) {
        row = addFigure(QStringLiteral("block_time"), tr("Block time, block-by-block"),
                        tr("block-by-block — %1%2")
                            .arg(QString::fromUtf8(job::kBlockByBlockModel),
                                 thisMachine(result, kinematics::Planner::BlockByBlock)));
        times(row, result.blockByBlock.time,
              outcome && outcome->blockByBlock.time > 0.0
                  ? std::optional(outcome->blockByBlock.time)
                  : std::nullopt);
    }
    row = addFigure(QStringLiteral("limiting_axis"), tr("Limiting axis"),
                    tr("the axis whose limit sets T1's feed"));
    m_figures->setItem(row, kOriginal, textItem(bindingText(result.constantFeed, result.machine)));
    m_figures->item(row, kOriginal)
        ->setToolTip(tr("the limit that sets T1's feed; \"the feed\": "
                        "the programmed feed, with the axis nearest "
                        "its limit"));
    if (outcome) {
        m_figures->setItem(row, kRescheduled,
                           textItem(bindingText(outcome->constantFeed, result.machine)));
    }
}

void ReviewDashboard::showChecks(const job::JobResult& result) {
    if (result.rescheduled) {
        const job::RescheduleOutcome& outcome = *result.rescheduled;
        int row = addFigure(QStringLiteral("channel_clearance"), tr("Channel clearance"),
                            tr("smallest distance of the new orientation from the raw feasible "
                               "channel's edge"));
        if (std::isfinite(outcome.minChannelClearanceRad)) {
            m_figures->setItem(row, kRescheduled,
                               numberItem(units::radToDeg(outcome.minChannelClearanceRad), 3,
                                          QStringLiteral("°")));
        } else {
            m_figures->setItem(row, kRescheduled,
                               textItem(tr("not applicable: no layer re-scheduled")));
        }
        row =
            addFigure(QStringLiteral("ball_centres"), tr("Ball-centre check"),
                      tr("the written program read back, every ball centre against the "
                         "input's (limit %1 µm)")
                          .arg(QLocale().toString(job::kCentreDeviationLimitMm * 1000.0, 'f', 0)));
        auto* deviation =
            numberItem(outcome.maxCentreDeviationMm * 1000.0, 2, QStringLiteral("µm"));
        if (outcome.maxCentreDeviationLine > 0) {
            deviation->setToolTip(tr("largest at line %1").arg(outcome.maxCentreDeviationLine));
        }
        m_figures->setItem(row, kRescheduled, deviation);
        m_figures->setItem(row, kChange,
                           textItem(outcome.maxCentreDeviationMm <= job::kCentreDeviationLimitMm
                                        ? tr("kept")
                                        : tr("NOT kept")));
    }
    const int row =
        addFigure(QStringLiteral("gouges_collisions"), tr("Gouges and collisions"),
                  result.cadCheck ? tr("CL points where the ball gouges or the shank or holder "
                                       "collides with %1")
                                        .arg(QString::fromStdString(result.cadCheck->source))
                                  : tr("not checked: no blade CAD given (File > Blade CAD)"));
    if (result.cadCheck) {
        m_figures->setItem(
            row, kOriginal,
            numberItem(static_cast<double>(result.cadCheck->original.issues.size()), 0));
        if (result.cadCheck->rescheduled) {
            auto* count =
                numberItem(static_cast<double>(result.cadCheck->rescheduled->issues.size()), 0);
            if (!result.cadCheck->rescheduled->issues.empty()) {
                count->setForeground(QColor(200, 40, 40));
            }
            m_figures->setItem(row, kRescheduled, count);
        }
    }
}

void ReviewDashboard::showWarnings(const job::JobResult& result) {
    m_warnings->setRowCount(static_cast<int>(result.warnings.size()));
    for (int row = 0; row < m_warnings->rowCount(); ++row) {
        const QString text =
            windowWording(QString::fromStdString(result.warnings[static_cast<std::size_t>(row)]));
        const WarningPlace place = placeOf(text);
        auto* where = textItem(place.text.isEmpty() ? QStringLiteral("—") : place.text);
        where->setData(kLayerRole, place.layer);
        m_warnings->setItem(row, kWarningWhere, where);
        m_warnings->setItem(row, kWarningText, textItem(text));
    }
    m_warningsTitle->setText(result.warnings.empty()
                                 ? tr("Warnings: none")
                                 : tr("Warnings: %1").arg(result.warnings.size()));
    m_warnings->resizeColumnToContents(kWarningWhere);
    m_warnings->resizeRowsToContents();
}

void ReviewDashboard::showClearanceIssues(const job::JobResult& result) {
    if (!result.cadCheck || !result.cadCheck->rescheduled) {
        return;
    }
    const cad::ClearanceReport& report = *result.cadCheck->rescheduled;
    const auto layerOf = [&report](std::size_t record) {
        for (std::size_t k = 0; k < report.layers.size(); ++k) {
            if (record >= report.layers[k].first && record <= report.layers[k].last) {
                return static_cast<int>(k);
            }
        }
        return -1;
    };
    m_issues->setRowCount(static_cast<int>(report.issues.size()));
    for (int row = 0; row < m_issues->rowCount(); ++row) {
        const cad::ClearanceIssue& issue = report.issues[static_cast<std::size_t>(row)];
        m_issues->setItem(row, kIssueLayer, numberItem(layerOf(issue.record), 0));
        m_issues->setItem(row, kIssuePoint, numberItem(static_cast<double>(issue.record) + 1.0, 0));
        m_issues->setItem(row, kIssueLine, numberItem(issue.line, 0));
        m_issues->setItem(row, kIssueKind, textItem(QString::fromUtf8(cad::toString(issue.kind))));
        m_issues->setItem(row, kIssueDepth, numberItem(issue.depth, 3));
        m_issues->setItem(row, kIssueInput,
                          textItem(job::inputIssueLike(*result.cadCheck, issue) != nullptr
                                       ? tr("has it too")
                                       : tr("introduced by the re-scheduling")));
    }
    const bool any = !report.issues.empty();
    m_issuesTitle->setText(
        tr("Gouges and collisions of the output: %1 points; export is refused "
           "until you tick the box below")
            .arg(QLocale().toString(static_cast<qlonglong>(report.issues.size()))));
    m_issuesTitle->setVisible(any);
    m_issues->setVisible(any);
    m_acknowledge->setVisible(any);
    m_issues->resizeColumnsToContents();
}

int ReviewDashboard::rowOf(const QString& key) const {
    for (int row = 0; row < m_figures->rowCount(); ++row) {
        if (m_figures->item(row, kFigure)->data(kKeyRole).toString() == key) {
            return row;
        }
    }
    return -1;
}

int ReviewDashboard::clearanceIssueCount() const {
    return m_issues->rowCount();
}

bool ReviewDashboard::clearanceAcknowledged() const {
    return m_issues->rowCount() == 0 || m_acknowledge->isChecked();
}

} // namespace bladeaxis::ui
