#pragma once
// Axis-motion plots against time at the programmed feed: A position, velocity and acceleration
// and the X, Y, Z velocities, one curve per method (original dashed), each method on its own
// time axis (its own duration). By default the original and the exported (re-scheduled) program
// are drawn, the exported one marked; a checkbox legend shows the other methods on demand. The
// machine's velocity and acceleration limits are drawn as lines (±limit) where it has them.

#include "core/analysis/axis_profile.h"
#include "core/compare/compare.h"
#include "core/kinematics/machine_model.h"

#include <QStringList>
#include <QWidget>
#include <array>
#include <optional>
#include <utility>
#include <vector>

class QCheckBox;
class QHBoxLayout;
class QScrollArea;

namespace bladeaxis::ui {

namespace detail {
class PlotCanvas;
}

class ProfilePlots final : public QWidget {
    Q_OBJECT

  public:
    // The quantities plotted, one plot each, in this order.
    enum Quantity { APosition, AVelocity, AAcceleration, XVelocity, YVelocity, ZVelocity };
    static constexpr int kQuantityCount = 6;

    // One method's curves in display units (deg, deg/s, deg/s², mm/s) against its time (s).
    struct Curve {
        QString method;
        std::vector<double> time;
        std::array<std::vector<double>, kQuantityCount> values;
        bool dashed = false;
        bool visible = true;
    };

    explicit ProfilePlots(QWidget* parent = nullptr);

    // A job without a comparison: the original and, when there is one, the re-scheduled path.
    void setProfiles(const analysis::AxisProfile& original,
                     const std::optional<analysis::AxisProfile>& rescheduled);
    // Every method of the comparison (original, quaternion, stheta-faithful, stheta-best,
    // optimal-qp and optimal-lp when present). Shown: the original and `exported` (the program
    // Export writes), unless the user chose otherwise for a method (kept across results).
    void setComparison(const compare::Comparison& comparison,
                       const QString& exported = QStringLiteral("stheta-best"));
    // The method whose program Export writes: drawn thicker and marked in the legend.
    void setExportedMethod(const QString& method);
    QString exportedMethod() const { return m_exported; }
    // The machine's limits drawn on the plots, in display units: A velocity (deg/s), A
    // acceleration (deg/s²), X/Y/Z velocity (mm/s); a limit <= 0 (unlimited) draws nothing.
    void setMachineLimits(const kinematics::MachineModel& machine);
    // The limit line of a quantity (display units), none when the machine has none.
    std::optional<double> limitOf(Quantity quantity) const { return m_limits[quantity]; }
    // The log axis's floor (deg/s²) for the visible curves: four decades below the highest
    // visible peak, never below 1. Quiet stretches of a smooth schedule sit at their own level
    // instead of plunging to a fixed floor.
    double accelerationLogFloor() const;
    // log10 |A acceleration| of a method as the log plot draws it over `columns` pixel
    // columns: the upper envelope (the largest |a| of each column), floored.
    std::vector<double> logAccelerationEnvelope(const QString& method, int columns) const;
    // One more curve over what is shown (e.g. the re-scheduled path after a layer edit, next to
    // a comparison computed before it); replaces a curve of the same name.
    void addProfile(const QString& method, const analysis::AxisProfile& profile);
    void clear();

    QStringList methods() const;
    bool isMethodVisible(const QString& method) const;
    void setMethodVisible(const QString& method, bool visible);
    const std::vector<Curve>& curves() const { return m_curves; }
    // Every visible method's value of `quantity` at `time` (s), one line each, with units: the
    // readout shown when the mouse hovers a plot.
    QString valuesAt(double time, Quantity quantity) const;

    // The program's letter of each axis role (X Y Z A B role order, MachineModel::letter): the
    // titles name the axes as the program does ("B velocity" on a table-B machine).
    void setAxisLetters(const std::array<char, 5>& letters);
    // A plot's title with its unit, e.g. "A velocity [deg/s]".
    QString quantityTitle(Quantity quantity) const;
    QString logAccelerationTitle() const;

    // A acceleration as |a| on a logarithmic axis (default): the original's spikes and a smooth
    // schedule's few hundred deg/s² are both readable, where a linear axis scaled to the spikes
    // shows the new schedule as a flat line.
    void setAccelerationLogScale(bool logScale);
    bool accelerationLogScale() const { return m_logAcceleration; }
    // A time span (s) tinted in every plot, e.g. the selected layer on the re-scheduled time
    // axis; nullopt clears it.
    void setHighlightedSpan(std::optional<std::pair<double, double>> seconds, const QString& label);
    std::optional<std::pair<double, double>> highlightedSpan() const { return m_span; }
    QString highlightedSpanLabel() const { return m_spanLabel; }

    // The selected point's time (s, on the exported program's time axis): a solid line in every
    // plot; nullopt clears it. A click (without a drag) on a plot says its time (timeClicked).
    void setMarkedTime(std::optional<double> seconds);
    std::optional<double> markedTime() const { return m_marked; }

    // The time span shown (s), none for the whole pass: the wheel zooms it about the mouse, a
    // left drag pans it, "Fit" shows the whole pass again. Kept within the pass.
    void setTimeWindow(std::optional<std::pair<double, double>> seconds);
    std::optional<std::pair<double, double>> timeWindow() const { return m_timeWindow; }
    // factor < 1 zooms in; the time `aroundSeconds` stays where it is.
    void zoomTime(double factor, double aroundSeconds);
    void panTime(double seconds);
    void fitTime();

    // The colour of a method's curves, readable on a light or dark background.
    static QColor methodColour(const QString& method, bool darkBackground);

  signals:
    void methodVisibilityChanged(const QString& method, bool visible);
    // A left click without a drag on a plot, at `seconds` on its time axis.
    void timeClicked(double seconds);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void setCurves(std::vector<Curve> curves);
    void rebuildLegend();
    void refreshLegendIcons();

    std::vector<Curve> m_curves;
    std::array<char, 5> m_letters{'X', 'Y', 'Z', 'A', 'B'};
    // Methods the user showed or hid, kept across results; the others follow the default pair.
    std::vector<std::pair<QString, bool>> m_chosen;
    QString m_exported = QStringLiteral("re-scheduled");
    std::array<std::optional<double>, kQuantityCount> m_limits{};
    QScrollArea* m_legendArea = nullptr;
    QHBoxLayout* m_legend = nullptr;
    std::vector<QCheckBox*> m_boxes;
    QCheckBox* m_logBox = nullptr;
    bool m_logAcceleration = true;
    std::optional<std::pair<double, double>> m_span;
    std::optional<double> m_marked;
    std::optional<std::pair<double, double>> m_timeWindow;
    QString m_spanLabel;
    detail::PlotCanvas* m_canvas = nullptr;
};

} // namespace bladeaxis::ui
