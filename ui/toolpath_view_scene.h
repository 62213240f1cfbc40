#pragma once
// What the three files of the 3D view share (toolpath_view.cpp: the scene; _overlay.cpp: the
// legend band painted over the frame; _picking.cpp: the mouse): the VTK objects of the scene
// and the colours, so that the legend names exactly the colours drawn.

#include "core/job/display_scene.h"
#include "ui/toolpath_view.h"

#include <QColor>
#include <QString>
#include <array>
#include <vtkActor.h>
#include <vtkCellPicker.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkLineSource.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

namespace bladeaxis::ui {

// A drawn item: its data, mapper and actor.
struct Drawn {
    vtkNew<vtkPolyData> data;
    vtkNew<vtkPolyDataMapper> mapper;
    vtkNew<vtkActor> actor;

    Drawn() {
        mapper->SetInputData(data);
        actor->SetMapper(mapper);
    }
};

struct ToolpathView::Scene {
    vtkNew<vtkRenderWindow> window;
    vtkNew<vtkRenderer> renderer;
    // selectedPath: the selected layer again, thicker, over the path.
    Drawn surface, path, selectedPath, originalGlyphs, rescheduledGlyphs, section;
    vtkNew<vtkGenericRenderWindowInteractor> interactor;
    vtkNew<vtkInteractorStyleTrackballCamera> style;
    vtkNew<vtkCellPicker> picker;
    vtkNew<vtkSphereSource> ball;
    vtkNew<vtkPolyDataMapper> ballMapper;
    vtkNew<vtkActor> ballActor;
    vtkNew<vtkLineSource> shank;
    vtkNew<vtkPolyDataMapper> shankMapper;
    vtkNew<vtkActor> shankActor;
    job::DisplayScene scene;
    double toolRadius = 4.0;
    double speedScale = 0.0; // rad/s at the top of the colour bar
    bool hasData = false;
};

namespace detail {

// The colours of the frame, chosen so that no two meanings share one: the layer palette keeps
// away from the axes' cyan and orange, the section's yellow, the highlight's pink and the tool's
// silver; the speed map runs from blue through magenta to red, away from all but the pink,
// which it never meets (by speed, the selected layer is drawn thicker, not pink).
inline constexpr QRgb kRescheduledAxisRgb = qRgb(77, 230, 255);
inline constexpr QRgb kOriginalAxisRgb = qRgb(255, 153, 51);
inline constexpr QRgb kSelectedRgb = qRgb(255, 60, 190);
inline constexpr QRgb kSectionRgb = qRgb(255, 235, 51);
inline constexpr QRgb kToolRgb = qRgb(214, 217, 224);
inline constexpr QRgb kSurfaceRgb = qRgb(158, 168, 184);
inline constexpr std::array<QRgb, 3> kLayerPalette = {qRgb(70, 190, 90), qRgb(70, 110, 235),
                                                      qRgb(160, 100, 235)};
inline constexpr QRgb kBackgroundRgb = qRgb(31, 31, 36);
inline constexpr QRgb kLegendBackgroundRgb = qRgb(40, 40, 46);
inline constexpr QRgb kTextRgb = qRgb(230, 230, 230);

QColor layerColour(std::size_t layer);
QColor dimmedLayerColour(std::size_t layer);
QColor speedColour(double fraction);
QString signedNumber(double value, int decimals);

} // namespace detail
} // namespace bladeaxis::ui
