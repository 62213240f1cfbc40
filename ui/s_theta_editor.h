#pragma once
// The S-theta editor of one layer: raw channel and monotone hull as bands, the original
// theta(S), the key points, the polyline and the smoothed theta(S). Dragging a key point
// re-smooths the layer live through core's resmoothLayer (a preview); an edit the core refuses
// (not monotone, outside the hull) is shown in red and not applied. A finished edit (drag
// released, key point added or deleted) is published with keyPointsEdited; the main window
// makes it one undo step of the job and re-runs the job with it.

#include "core/scheduling/schedule.h"
#include "core/scheduling/schedule_parameters.h"

#include <QStringList>
#include <QWidget>
#include <optional>
#include <vector>

namespace bladeaxis::ui {

class SThetaEditor final : public QWidget {
    Q_OBJECT

  public:
    explicit SThetaEditor(QWidget* parent = nullptr);

    // `number` is the layer's number as the layer table shows it, for the messages.
    void setLayer(const scheduling::LayerResult& layer,
                  const scheduling::ScheduleParameters& parameters, std::size_t number);
    void clearLayer();
    const std::optional<scheduling::LayerResult>& layer() const { return m_layer; }
    // Widget position of polyline vertex `index` (for tests and tooltips).
    QPointF vertexPosition(std::size_t index) const;
    QString refusal() const { return m_refusal; }
    // The message the strip above the plot shows: the refusal with its layer, or what is pending.
    QString message() const;
    // The legend's entries, drawn above the plot in this order.
    QStringList legendNames() const;
    // The data rectangle: the legend and the message strip are above it, never on it.
    QRectF plotArea() const { return m_plotArea; }
    // The legend's strip and the message's (empty without a message), in widget coordinates.
    double legendHeight() const { return m_legendHeight; }
    // The message strip is kept whether or not a message is shown, so that the plot does not
    // move when one appears; it grows only for a message longer than its reserved lines.
    QRectF messageRect() const { return m_messageRect; }
    // The hover readout at a widget position: S, scheduled and original theta, the channel.
    QString readoutAt(QPointF position) const;
    // Re-smooths with these vertices; false (and the reason in refusal()) when refused.
    bool applyVertices(const std::vector<Vec2>& vertices);
    // Shown while the job re-runs with changed layer settings, which the editor cannot preview.
    void setPending(const QString& message);

  signals:
    // Every accepted re-smoothing, also during a drag.
    void layerEdited();
    // A finished edit: the polyline before and after (S, theta relative to the layer).
    void keyPointsEdited(const std::vector<Vec2>& before, const std::vector<Vec2>& after,
                         const QString& description);

  protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;

  private:
    QPointF toWidget(double s, double theta) const;
    Vec2 fromWidget(QPointF point) const;
    std::optional<std::size_t> vertexNear(QPointF point) const;
    void finishEdit(std::vector<Vec2> before, std::vector<Vec2> after, const QString& text);
    void paintAxes(QPainter& painter) const;
    void paintLegend(QPainter& painter) const;
    void paintBands(QPainter& painter) const;
    void paintCurves(QPainter& painter) const;
    void paintMessages(QPainter& painter) const;
    void relayout();

    std::optional<scheduling::LayerResult> m_layer;
    scheduling::ScheduleParameters m_parameters;
    double m_thetaLow = 0.0, m_thetaHigh = 1.0;
    std::optional<std::size_t> m_dragged;
    std::vector<Vec2> m_dragStart;
    QString m_refusal;
    QString m_pending;
    std::size_t m_layerNumber = 0;
    double m_legendHeight = 0.0;
    QRectF m_messageRect, m_plotArea; // relayout()
};

} // namespace bladeaxis::ui
