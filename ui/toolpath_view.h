#pragma once
// 3D view of the toolpath with VTK. Debian's VTK Qt module is built against Qt5, so VTK renders
// off-screen in its own context and the image is painted by this plain Qt6 widget
// (docs/product.md, approach 2). VTK types stay in the .cpp file.

#include "core/scheduling/schedule.h"

#include <QImage>
#include <QWidget>
#include <memory>

namespace bladeaxis::ui {

class ToolpathView final : public QWidget {
    Q_OBJECT

  public:
    explicit ToolpathView(QWidget* parent = nullptr);
    ~ToolpathView() override;

    // Tips coloured by layer, the re-scheduled tool axes as short glyphs.
    void setSchedule(const scheduling::ScheduleResult& schedule);
    void setSelectedLayer(int layer);
    // Shows the tool (ball of `radius` mm and shank) at path sample `sample`.
    void setToolRadius(double radius);
    void showToolAt(std::size_t sample);
    // Renders now and returns the frame (also what paintEvent shows).
    QImage renderFrame();

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

    struct Scene;
    std::unique_ptr<Scene> m_scene;
};

} // namespace bladeaxis::ui
