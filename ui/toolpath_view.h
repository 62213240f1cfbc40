#pragma once
// 3D view of the blade and the toolpath with VTK. Debian's VTK Qt module is built against Qt5,
// so VTK renders off-screen in its own context and the image is painted by this plain Qt6
// widget (docs/architecture.md). VTK types stay in the .cpp file. Everything drawn comes
// from a job::DisplayScene (core): the view computes no geometry itself.
//
// The widget is the rendered frame, with the legend in a band on its right (the camera fits
// the part beside it, so the legend never covers the part), above a strip of its own controls
// ("Axes shown").

#include "core/job/display_scene.h"

#include <QColor>
#include <QImage>
#include <QPointF>
#include <QStringList>
#include <QWidget>
#include <memory>
#include <optional>
#include <vector>

class QLabel;
class QPainter;
class QSpinBox;

namespace bladeaxis::ui {

class ToolpathView final : public QWidget {
    Q_OBJECT

  public:
    enum class Colouring {
        Layer,          // alternating colours per layer; the selected layer highlighted
        ASpeed,         // |dA/dt| of the re-scheduled program (the original's without one)
        OriginalASpeed, // |dA/dt| of the original program
    };

    // One line of the legend: what a colour drawn in the frame means, and how its sample is
    // drawn beside the text.
    struct LegendEntry {
        enum class Swatch {
            Line,          // a line of `colour`
            ThickLine,     // a thick line of `colour` (the selected layer)
            ThickSpeed,    // a thick line in the speed colours (the selected layer by speed)
            Palette,       // the alternating layer colours
            DimmedPalette, // the same, dimmed (the layers that are not selected)
            ColourBar,     // the speed colour map with its range
            Area,          // a lit surface or solid of `colour`
        };
        QString text;
        QColor colour;
        Swatch swatch = Swatch::Line;
    };

    // Tool axes drawn by default, per set: enough to read the orientation along every layer,
    // few enough that the blade stays visible.
    static constexpr int kDefaultMaxAxes = 400;

    explicit ToolpathView(QWidget* parent = nullptr);
    ~ToolpathView() override;

    // Blade surface, toolpath, tool-axis glyphs and layer sections; the camera is reset to the
    // isometric view when the scene has no predecessor.
    void showScene(const job::DisplayScene& scene);
    const job::DisplayScene& scene() const;

    // Program line, time and A of every record of the cutting pass, for positionReadout();
    // from the re-scheduled program when the job has one.
    void setTimeline(const job::JobResult& result);

    void setSelectedLayer(int layer);
    int selectedLayer() const { return m_selected; }
    // The layer whose records include pass record `passIndex`; -1 when none does.
    int layerOfRecord(std::size_t passIndex) const;
    void setColouring(Colouring colouring);
    Colouring colouring() const { return m_colouring; }
    // The original axes are off by default: drawn beside the re-scheduled ones at the same
    // points they double the lines and hide the blade; turn them on to compare.
    void setOriginalAxesVisible(bool visible);
    bool originalAxesVisible() const;
    void setRescheduledAxesVisible(bool visible);
    bool rescheduledAxesVisible() const;
    void setSurfaceVisible(bool visible);

    // At most `maxAxes` tool axes of each set: one every axisStride() records of the pass.
    void setAxisDensity(int maxAxes);
    int axisDensity() const { return m_maxAxes; }
    std::size_t axisStride() const;
    // Tool axes drawn in the frame, of every set shown.
    std::size_t drawnAxisCount() const;
    QSpinBox* axisDensityBox() const { return m_densityBox; }

    // What each colour in the frame means, in the order the legend lists it.
    std::vector<LegendEntry> legend() const;
    QStringList legendEntries() const;
    // The title of the speed colour bar; empty when the path is coloured by layer.
    QString colourBarTitle() const;
    // The colour the path is drawn with at drawn point `point` (index into scene().tips).
    QColor pathColourAt(std::size_t point) const;

    // Shows the tool (ball of `radius` mm and shank) at record `record` of the cutting pass
    // (the drawn point nearest to it when the scene is decimated).
    void setToolRadius(double radius);
    void showToolAt(std::size_t record);
    bool toolVisible() const;

    // "line 1234 · t = 12.34 s · A = −152.3°" at pass record `passIndex`: the program line,
    // the time from the start of the pass at the programmed feed and A, as the axis-motion
    // plots show them; empty without a timeline for this scene.
    QString positionReadout(std::size_t passIndex) const;
    // The same at the tool shown; empty when no tool is shown.
    QString positionReadout() const;

    // Where the drawn point of pass record `passIndex` appears in the widget with the current
    // camera; nullopt when the scene has no such point.
    std::optional<QPointF> widgetPositionOf(std::size_t passIndex);

    // Renders now and returns the frame with its legend band (also what paintEvent shows).
    QImage renderFrame();
    // The part of the frame the blade is drawn in (left of the legend band), frame pixels.
    QRect sceneArea() const;

  signals:
    // A click (press and release without a drag) on the toolpath: the pass record picked.
    void pointPicked(std::size_t passIndex);
    // positionReadout() changed: the tool moved, was hidden or the timeline changed.
    void positionReadoutChanged(const QString& readout);

  public slots:
    void viewFront();     // looking along +y: x to the right, z up
    void viewTop();       // looking down -z: x to the right, y up
    void viewSide();      // looking along -x, i.e. along the rotary axis: the sections
    void viewIsometric(); // from (+x, -y, +z)
    void fitView();       // the whole scene in the frame, direction kept
    void resetView();     // isometric and fitted

  protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    // Forwarded to VTK's trackball camera style: left drag rotates, right drag zooms, middle
    // drag pans, the wheel zooms. A left click without a drag picks a toolpath point.
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

  private:
    struct Timeline {
        std::vector<int> line;        // source line per pass record
        std::vector<double> seconds;  // from the start of the pass, per pass record
        std::vector<double> aDegrees; // per pass record
    };

    QWidget* buildControlStrip();
    void placeControlStrip();
    QSize renderSize() const;
    void syncViewport();
    int legendWidth(int frameWidth) const;
    void forward(QMouseEvent* event, unsigned long vtkEvent);
    std::optional<std::size_t> pickAt(QPointF position);
    std::optional<std::size_t> drawnPointOf(std::size_t passIndex) const;
    void lookFrom(const double direction[3], const double viewUp[3]);
    void updateGlyphs();
    void updatePathColours();
    void updateSelectedPath();
    void updateSection();
    void updateDensityHint();
    void emitReadout();
    void paintLegend(QImage& frame);
    int paintColourBar(QPainter& painter, const QString& title, const QRect& row) const;
    void paintAxesMarker(QPainter& painter, QPointF origin) const;

    struct Scene;
    std::unique_ptr<Scene> m_vtk;
    Colouring m_colouring = Colouring::Layer;
    int m_selected = -1;
    int m_maxAxes = kDefaultMaxAxes;
    std::optional<std::size_t> m_toolRecord; // pass record of the tool shown
    Timeline m_timeline;
    // The program's letters of the rotary table and of the axis along it (MachineModel::letter
    // of the roles A and X), so the readout and the legend say "B = ..." on a table-B machine.
    QChar m_tableLetter = QLatin1Char('A');
    QChar m_alongLetter = QLatin1Char('x');
    QPointF m_pressPosition;
    QWidget* m_strip = nullptr;
    QSpinBox* m_densityBox = nullptr;
    QLabel* m_densityHint = nullptr;
};

} // namespace bladeaxis::ui
