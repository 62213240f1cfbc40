#pragma once
// 3D view of the blade and the toolpath with VTK. Debian's VTK Qt module is built against Qt5,
// so VTK renders off-screen in its own context and the image is painted by this plain Qt6
// widget (docs/architecture.md). VTK types stay in the .cpp file. Everything drawn comes
// from a job::DisplayScene (core): the view computes no geometry itself.

#include "core/job/display_scene.h"
#include "core/scheduling/schedule.h"

#include <QImage>
#include <QWidget>
#include <memory>

namespace bladeaxis::ui {

class ToolpathView final : public QWidget {
    Q_OBJECT

  public:
    enum class Colouring {
        Layer,          // a hue per layer, the selected layer in red
        ASpeed,         // |dA/dt| of the re-scheduled program (the original's without one)
        OriginalASpeed, // |dA/dt| of the original program
    };

    explicit ToolpathView(QWidget* parent = nullptr);
    ~ToolpathView() override;

    // Blade surface, toolpath, tool-axis glyphs and layer sections; the camera is reset to the
    // isometric view when the scene has no predecessor.
    void showScene(const job::DisplayScene& scene);
    const job::DisplayScene& scene() const;

    // Compatibility with the view before showScene: the re-scheduled tips and axes alone (no
    // blade, no original axes). Prefer showScene(job::buildDisplayScene(result)).
    void setSchedule(const scheduling::ScheduleResult& schedule);

    void setSelectedLayer(int layer);
    void setColouring(Colouring colouring);
    Colouring colouring() const { return m_colouring; }
    void setOriginalAxesVisible(bool visible);
    void setRescheduledAxesVisible(bool visible);
    void setSurfaceVisible(bool visible);

    // Shows the tool (ball of `radius` mm and shank) at record `record` of the cutting pass
    // (the drawn point nearest to it when the scene is decimated).
    void setToolRadius(double radius);
    void showToolAt(std::size_t record);

    // Renders now and returns the frame with its legend and axes marker (also what paintEvent
    // shows).
    QImage renderFrame();

  public slots:
    void viewFront();     // looking along +y: x to the right, z up
    void viewTop();       // looking down -z: x to the right, y up
    void viewSide();      // looking along -x, i.e. along the rotary axis: the sections
    void viewIsometric(); // from (+x, -y, +z)
    void fitView();       // the whole scene in the frame, direction kept
    void resetView();     // isometric and fitted

  protected:
    void paintEvent(QPaintEvent* event) override;
    // Forwarded to VTK's trackball camera style: left drag rotates, right drag zooms, middle
    // drag pans, the wheel zooms.
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

  private:
    void forward(QMouseEvent* event, unsigned long vtkEvent);
    void lookFrom(const double direction[3], const double viewUp[3]);
    void updatePathColours();
    void updateSection();
    void paintOverlay(QImage& frame);

    struct Scene;
    std::unique_ptr<Scene> m_vtk;
    Colouring m_colouring = Colouring::Layer;
    int m_selected = -1;
};

} // namespace bladeaxis::ui
