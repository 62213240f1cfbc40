#include "ui/toolpath_view.h"

#include "core/base/units.h"
#include "core/job/job.h"
#include "ui/toolpath_view_scene.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QSpinBox>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellPicker.h>
#include <vtkDoubleArray.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkLineSource.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

namespace bladeaxis::ui {

using namespace detail;

namespace {

void setColour(vtkProperty* property, QRgb rgb) {
    property->SetColor(qRed(rgb) / 255.0, qGreen(rgb) / 255.0, qBlue(rgb) / 255.0);
}

void appendRgb(vtkUnsignedCharArray* colours, const QColor& colour) {
    const unsigned char rgb[3] = {static_cast<unsigned char>(colour.red()),
                                  static_cast<unsigned char>(colour.green()),
                                  static_cast<unsigned char>(colour.blue())};
    colours->InsertNextTypedTuple(rgb);
}

vtkNew<vtkPoints> pointsOf(const std::vector<Vec3>& positions) {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(positions.size()));
    for (std::size_t i = 0; i < positions.size(); ++i) {
        points->SetPoint(static_cast<vtkIdType>(i), positions[i].data());
    }
    return points;
}

void fillSurface(vtkPolyData* data, const job::DisplayScene& scene) {
    vtkNew<vtkCellArray> triangles;
    for (const auto& t : scene.surface.triangles) {
        const vtkIdType ids[3] = {t[0], t[1], t[2]};
        triangles->InsertNextCell(3, ids);
    }
    vtkNew<vtkDoubleArray> normals;
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(static_cast<vtkIdType>(scene.surfaceNormals.size()));
    for (std::size_t i = 0; i < scene.surfaceNormals.size(); ++i) {
        normals->SetTypedTuple(static_cast<vtkIdType>(i), scene.surfaceNormals[i].data());
    }
    data->SetPoints(pointsOf(scene.surface.vertices));
    data->SetPolys(triangles);
    if (scene.surfaceNormals.size() == scene.surface.vertices.size()) {
        data->GetPointData()->SetNormals(normals);
    }
    data->Modified();
}

// The drawn points of layer k as one polyline, joined to the first point of the next layer so
// the path is unbroken.
void appendLayerLine(vtkCellArray* lines, const job::DisplayScene& scene, std::size_t k) {
    const job::DisplayLayer& layer = scene.layers[k];
    const std::size_t end = k + 1 < scene.layers.size() ? layer.lastPoint + 1 : layer.lastPoint;
    lines->InsertNextCell(static_cast<int>(end - layer.firstPoint + 1));
    for (std::size_t i = layer.firstPoint; i <= end; ++i) {
        lines->InsertCellPoint(static_cast<vtkIdType>(i));
    }
}

void fillPath(vtkPolyData* data, const job::DisplayScene& scene) {
    vtkNew<vtkCellArray> lines;
    for (std::size_t k = 0; k < scene.layers.size(); ++k) {
        appendLayerLine(lines, scene, k);
    }
    data->SetPoints(pointsOf(scene.tips));
    data->SetLines(lines);
    data->Modified();
}

// Drawn points that carry a tool axis: the first drawn point at or after every stride-th
// record, so that at most ceil(records / stride) axes are drawn whatever the decimation.
std::vector<std::size_t> axisPoints(const job::DisplayScene& scene, std::size_t stride) {
    std::vector<std::size_t> points;
    std::size_t next = 0;
    for (std::size_t i = 0; i < scene.record.size(); ++i) {
        if (scene.record[i] >= next) {
            points.push_back(i);
            next = scene.record[i] + stride;
        }
    }
    return points;
}

// Tool axes as lines from the ball centre: both orientations turn about the same centre, so
// the two sets show the re-scheduled rotation directly.
void fillGlyphs(vtkPolyData* data, const job::DisplayScene& scene, const std::vector<Vec3>& axes,
                const std::vector<std::size_t>& at, double length) {
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    if (axes.size() == scene.centres.size()) {
        for (const std::size_t i : at) {
            const Vec3 start = scene.centres[i];
            const Vec3 end = start + length * axes[i];
            const vtkIdType ids[2] = {points->InsertNextPoint(start.data()),
                                      points->InsertNextPoint(end.data())};
            lines->InsertNextCell(2, ids);
        }
    }
    data->SetPoints(points);
    data->SetLines(lines);
    data->Modified();
}

// Top of the colour bar: the 98th percentile of either program's speeds, so that the
// original's reversal spikes do not turn the whole re-scheduled path blue (faster is red).
double speedScaleOf(const job::DisplayScene& scene) {
    double scale = 0.0;
    for (const auto* speeds : {&scene.aSpeedOriginal, &scene.aSpeedRescheduled}) {
        if (speeds->empty()) {
            continue;
        }
        std::vector<double> sorted = *speeds;
        const auto rank =
            static_cast<std::ptrdiff_t>(0.98 * static_cast<double>(sorted.size() - 1));
        std::nth_element(sorted.begin(), sorted.begin() + rank, sorted.end());
        scale = std::max(scale, sorted[static_cast<std::size_t>(rank)]);
    }
    return scale;
}

// The time of pass record `record` on the profile's time axis: that of the sample covering it
// (a record merged into the sample before it moved nowhere, so it shares that time).
double secondsAt(const analysis::AxisProfile& profile, std::size_t record) {
    const auto& samples = profile.sampleRecord;
    const auto after = std::upper_bound(samples.begin(), samples.end(), record);
    const auto index =
        static_cast<std::size_t>(std::max<std::ptrdiff_t>(after - samples.begin() - 1, 0));
    return profile.timeAt(index);
}

} // namespace

namespace detail {

// Neighbouring layers differ in colour; three colours are enough for that and leave the
// other hues to the axes, the section and the highlight.
QColor layerColour(std::size_t layer) {
    return QColor(kLayerPalette[layer % kLayerPalette.size()]);
}

// Grey with a hint of the layer's colour: the layers that are not selected stay visible as
// texture on the blade without competing with the selected one.
QColor dimmedLayerColour(std::size_t layer) {
    return QColor::fromHsv(layerColour(layer).hsvHue(), 45, 125);
}

// Blue (slow) through magenta to red (fast).
QColor speedColour(double fraction) {
    const double clamped = std::clamp(fraction, 0.0, 1.0);
    const double hue = std::fmod((240.0 + 120.0 * clamped) / 360.0, 1.0);
    return QColor::fromHsvF(static_cast<float>(hue), 0.85F, 0.95F);
}

// "-152.3" with a typographic minus, and no "-0.0" for a value that rounds to zero.
QString signedNumber(double value, int decimals) {
    const double half = 0.5 * std::pow(10.0, -decimals);
    const double shown = std::abs(value) < half ? 0.0 : value;
    return QString::number(shown, 'f', decimals).replace(QLatin1Char('-'), QChar(0x2212));
}

} // namespace detail

ToolpathView::ToolpathView(QWidget* parent) : QWidget(parent), m_vtk(std::make_unique<Scene>()) {
    setMinimumSize(320, 240);
    setToolTip(tr("Blade and toolpath: left drag rotates, right drag or wheel zooms, middle "
                  "drag pans; a click on the toolpath selects its layer and moves the tool "
                  "there. The legend on the right names every colour"));
    Scene& vtk = *m_vtk;
    vtk.window->SetOffScreenRendering(1);
    // VTK asks for 8x multisampling by default; on Mesa's software renderer (Xvfb, remote
    // desktops) that costs ~35 ms of an 800x600 frame against ~5 ms without (bench_view).
    vtk.window->SetMultiSamples(0);
    vtk.window->AddRenderer(vtk.renderer);
    vtk.renderer->SetBackground(qRed(kBackgroundRgb) / 255.0, qGreen(kBackgroundRgb) / 255.0,
                                qBlue(kBackgroundRgb) / 255.0);

    setColour(vtk.surface.actor->GetProperty(), kSurfaceRgb);
    vtk.surface.actor->GetProperty()->SetSpecular(0.2);
    // The tips lie on the ball, just off the surface: push the surface back in depth.
    vtk.surface.mapper->SetResolveCoincidentTopologyToPolygonOffset();
    vtk.surface.mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(2.0, 4.0);
    vtk.section.mapper->SetRelativeCoincidentTopologyLineOffsetParameters(-2.0, -4.0);
    // The selected layer lies on the path it repeats: drawn in front of it.
    vtk.selectedPath.mapper->SetRelativeCoincidentTopologyLineOffsetParameters(-1.0, -2.0);
    vtk.surface.mapper->ScalarVisibilityOff();
    vtk.path.actor->GetProperty()->SetLineWidth(2.0);
    vtk.selectedPath.actor->GetProperty()->SetLineWidth(5.0);
    setColour(vtk.selectedPath.actor->GetProperty(), kSelectedRgb);
    for (Drawn* drawn : {&vtk.path, &vtk.selectedPath}) {
        drawn->actor->GetProperty()->LightingOff();
        drawn->mapper->SetColorModeToDirectScalars();
    }
    setColour(vtk.originalGlyphs.actor->GetProperty(), kOriginalAxisRgb);
    setColour(vtk.rescheduledGlyphs.actor->GetProperty(), kRescheduledAxisRgb);
    setColour(vtk.section.actor->GetProperty(), kSectionRgb);
    vtk.section.actor->GetProperty()->SetLineWidth(3.0);
    for (Drawn* drawn : {&vtk.originalGlyphs, &vtk.rescheduledGlyphs, &vtk.section}) {
        drawn->actor->GetProperty()->LightingOff();
        drawn->mapper->ScalarVisibilityOff();
    }
    vtk.originalGlyphs.actor->VisibilityOff();
    vtk.selectedPath.actor->VisibilityOff();
    for (Drawn* drawn : {&vtk.surface, &vtk.path, &vtk.selectedPath, &vtk.originalGlyphs,
                         &vtk.rescheduledGlyphs, &vtk.section}) {
        vtk.renderer->AddActor(drawn->actor);
    }

    vtk.ball->SetThetaResolution(24);
    vtk.ball->SetPhiResolution(16);
    vtk.ballMapper->SetInputConnection(vtk.ball->GetOutputPort());
    vtk.ballActor->SetMapper(vtk.ballMapper);
    setColour(vtk.ballActor->GetProperty(), kToolRgb);
    vtk.ballActor->GetProperty()->SetSpecular(0.4);
    vtk.shankMapper->SetInputConnection(vtk.shank->GetOutputPort());
    vtk.shankActor->SetMapper(vtk.shankMapper);
    setColour(vtk.shankActor->GetProperty(), kToolRgb);
    vtk.shankActor->GetProperty()->SetLineWidth(6.0);
    vtk.ballActor->VisibilityOff();
    vtk.shankActor->VisibilityOff();
    vtk.renderer->AddActor(vtk.ballActor);
    vtk.renderer->AddActor(vtk.shankActor);
    vtk.interactor->SetRenderWindow(vtk.window);
    vtk.interactor->SetInteractorStyle(vtk.style);
    // The widget repaints on every event; VTK must not try to render into a window of its own.
    vtk.interactor->EnableRenderOff();

    // Picking sees the blade too, so that a click finds the path point in front, not one
    // behind the blade that happens to lie nearer the ray.
    vtk.picker->PickFromListOn();
    vtk.picker->AddPickList(vtk.surface.actor);
    vtk.picker->AddPickList(vtk.path.actor);
    vtk.picker->AddPickList(vtk.selectedPath.actor);
    vtk.picker->SetTolerance(0.004);

    m_strip = buildControlStrip();
    placeControlStrip();
}

ToolpathView::~ToolpathView() = default;

QWidget* ToolpathView::buildControlStrip() {
    auto* strip = new QWidget(this);
    auto* layout = new QHBoxLayout(strip);
    layout->setContentsMargins(6, 3, 6, 3);
    auto* label = new QLabel(tr("Axes shown"), strip);
    m_densityBox = new QSpinBox(strip);
    m_densityBox->setRange(1, 20'000);
    m_densityBox->setSingleStep(50);
    m_densityBox->setValue(m_maxAxes);
    m_densityBox->setToolTip(tr("At most this many tool axes of each set are drawn, evenly "
                                "along the pass"));
    label->setBuddy(m_densityBox);
    connect(m_densityBox, &QSpinBox::valueChanged, this, &ToolpathView::setAxisDensity);
    m_densityHint = new QLabel(strip);
    auto* pickHint = new QLabel(tr("Click the toolpath to select a point"), strip);
    pickHint->setEnabled(false); // greyed: a hint, not a value
    layout->addWidget(label);
    layout->addWidget(m_densityBox);
    layout->addWidget(m_densityHint);
    layout->addStretch(1);
    layout->addWidget(pickHint);
    return strip;
}

// The strip is placed by hand under the frame: the frame is painted, not laid out, and a
// hidden view (the tests render without showing it) must have the same frame size.
void ToolpathView::placeControlStrip() {
    const int stripHeight = m_strip->sizeHint().height();
    m_strip->setGeometry(0, std::max(height() - stripHeight, 0), width(), stripHeight);
}

void ToolpathView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    placeControlStrip();
}

QSize ToolpathView::renderSize() const {
    return {std::max(width(), 16), std::max(height() - m_strip->sizeHint().height(), 16)};
}

// Wide enough for the usual entries on one or two lines (longer ones, a CAD file's name,
// wrap), and never more than 2/5 of the frame: the part keeps the rest.
int ToolpathView::legendWidth(int frameWidth) const {
    const int text = fontMetrics().horizontalAdvance(tr("re-scheduled tool axes"));
    return std::clamp(text + 52, 150, std::max(frameWidth * 2 / 5, 16));
}

QRect ToolpathView::sceneArea() const {
    const QSize size = renderSize();
    return {0, 0, size.width() - legendWidth(size.width()), size.height()};
}

// VTK renders the frame; its renderer keeps clear of the legend band, so fitting the camera
// fits the part beside the legend.
void ToolpathView::syncViewport() {
    const QSize size = renderSize();
    Scene& vtk = *m_vtk;
    vtk.window->SetSize(size.width(), size.height());
    vtk.interactor->SetSize(size.width(), size.height());
    const double sceneFraction =
        static_cast<double>(sceneArea().width()) / static_cast<double>(size.width());
    vtk.renderer->SetViewport(0.0, 0.0, sceneFraction, 1.0);
}

void ToolpathView::showScene(const job::DisplayScene& scene) {
    Scene& vtk = *m_vtk;
    const bool first = !vtk.hasData;
    vtk.scene = scene;
    if (scene.toolRadius > 0.0) {
        vtk.toolRadius = scene.toolRadius;
    }
    vtk.speedScale = speedScaleOf(scene);
    fillSurface(vtk.surface.data, scene);
    fillPath(vtk.path.data, scene);
    vtk.selectedPath.data->SetPoints(vtk.path.data->GetPoints());
    updateGlyphs();
    vtk.hasData = !scene.empty();
    vtk.ballActor->VisibilityOff();
    vtk.shankActor->VisibilityOff();
    m_toolRecord.reset();
    if (m_selected >= static_cast<int>(scene.layers.size())) {
        m_selected = -1;
    }
    updatePathColours();
    updateSelectedPath();
    updateSection();
    updateDensityHint();
    if (first) {
        resetView();
    } else {
        vtk.renderer->ResetCameraClippingRange();
    }
    emitReadout();
    update();
}

const job::DisplayScene& ToolpathView::scene() const {
    return m_vtk->scene;
}

void ToolpathView::setTimeline(const job::JobResult& result) {
    m_timeline = {};
    m_tableLetter = QLatin1Char(result.machine.letter(kinematics::AxisId::A));
    m_alongLetter = QChar(QLatin1Char(result.machine.letter(kinematics::AxisId::X))).toLower();
    const std::size_t first = result.pass.first, count = result.pass.count;
    const auto& records = result.program.path().records;
    const bool rescheduled = result.rescheduled.has_value();
    const auto& axes = rescheduled ? *result.rescheduled->axes : *result.axes;
    const auto& profile = rescheduled ? result.rescheduled->profile : result.original;
    if (records.size() >= first + count && axes.size() == count) {
        const bool timed = !profile.sampleRecord.empty(); // an analysed profile
        for (std::size_t i = 0; i < count; ++i) {
            m_timeline.line.push_back(records[first + i].line);
            m_timeline.aDegrees.push_back(units::radToDeg(axes[i].a));
            if (timed) {
                m_timeline.seconds.push_back(secondsAt(profile, i));
            }
        }
    }
    emitReadout();
}

void ToolpathView::setSelectedLayer(int layer) {
    m_selected =
        layer >= 0 && static_cast<std::size_t>(layer) < m_vtk->scene.layers.size() ? layer : -1;
    updatePathColours();
    updateSelectedPath();
    updateSection();
    update();
}

int ToolpathView::layerOfRecord(std::size_t passIndex) const {
    const auto& layers = m_vtk->scene.layers;
    for (std::size_t k = 0; k < layers.size(); ++k) {
        if (passIndex >= layers[k].firstRecord && passIndex <= layers[k].lastRecord) {
            return static_cast<int>(k);
        }
    }
    return -1;
}

void ToolpathView::setColouring(Colouring colouring) {
    m_colouring = colouring;
    updatePathColours();
    updateSelectedPath();
    update();
}

void ToolpathView::setOriginalAxesVisible(bool visible) {
    m_vtk->originalGlyphs.actor->SetVisibility(visible);
    update();
}

bool ToolpathView::originalAxesVisible() const {
    return m_vtk->originalGlyphs.actor->GetVisibility() != 0;
}

void ToolpathView::setRescheduledAxesVisible(bool visible) {
    m_vtk->rescheduledGlyphs.actor->SetVisibility(visible);
    update();
}

bool ToolpathView::rescheduledAxesVisible() const {
    return m_vtk->rescheduledGlyphs.actor->GetVisibility() != 0;
}

void ToolpathView::setSurfaceVisible(bool visible) {
    m_vtk->surface.actor->SetVisibility(visible);
    update();
}

void ToolpathView::setAxisDensity(int maxAxes) {
    m_maxAxes = std::max(maxAxes, 1);
    {
        const QSignalBlocker block(m_densityBox);
        m_densityBox->setValue(m_maxAxes);
    }
    updateGlyphs();
    updateDensityHint();
    update();
}

std::size_t ToolpathView::axisStride() const {
    const job::DisplayScene& scene = m_vtk->scene;
    const std::size_t records =
        std::max(scene.passRecords, scene.record.empty() ? 0 : scene.record.back() + 1);
    const auto cap = static_cast<std::size_t>(m_maxAxes);
    return std::max<std::size_t>((records + cap - 1) / cap, 1);
}

std::size_t ToolpathView::drawnAxisCount() const {
    std::size_t count = 0;
    for (const Drawn* glyphs : {&m_vtk->originalGlyphs, &m_vtk->rescheduledGlyphs}) {
        if (glyphs->actor->GetVisibility() != 0) {
            count += static_cast<std::size_t>(glyphs->data->GetNumberOfCells());
        }
    }
    return count;
}

void ToolpathView::updateGlyphs() {
    Scene& vtk = *m_vtk;
    const job::DisplayScene& scene = vtk.scene;
    const std::vector<std::size_t> at = axisPoints(scene, axisStride());
    // One ball radius: enough to read the direction, short enough that a few hundred axes
    // leave the blade visible between them.
    const double length = scene.toolRadius > 0.0 ? scene.toolRadius : 10.0;
    fillGlyphs(vtk.originalGlyphs.data, scene, scene.originalAxes, at, length);
    fillGlyphs(vtk.rescheduledGlyphs.data, scene, scene.rescheduledAxes, at, length);
}

void ToolpathView::updateDensityHint() {
    const std::size_t stride = axisStride();
    m_densityHint->setText(stride > 1 ? tr("1 in %1 points of the pass").arg(stride)
                                      : tr("at every point of the pass"));
}

void ToolpathView::updatePathColours() {
    Scene& vtk = *m_vtk;
    const job::DisplayScene& scene = vtk.scene;
    const std::vector<double>* speeds = nullptr;
    if (m_colouring == Colouring::ASpeed) {
        speeds = scene.aSpeedRescheduled.empty() ? &scene.aSpeedOriginal : &scene.aSpeedRescheduled;
    } else if (m_colouring == Colouring::OriginalASpeed) {
        speeds = &scene.aSpeedOriginal;
    }
    if (speeds != nullptr && speeds->size() != scene.tips.size()) {
        speeds = nullptr; // not analysed: fall back to the layers
    }
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetNumberOfComponents(3);
    colours->Allocate(static_cast<vtkIdType>(3 * scene.tips.size()));
    const double scale = vtk.speedScale > 0.0 ? vtk.speedScale : 1.0;
    for (std::size_t i = 0; i < scene.tips.size(); ++i) {
        const std::size_t layer = scene.layer[i];
        if (speeds != nullptr) {
            appendRgb(colours, speedColour((*speeds)[i] / scale));
        } else if (m_selected < 0) {
            appendRgb(colours, layerColour(layer));
        } else if (static_cast<int>(layer) == m_selected) {
            appendRgb(colours, QColor(kSelectedRgb));
        } else {
            appendRgb(colours, dimmedLayerColour(layer));
        }
    }
    vtk.path.data->GetPointData()->SetScalars(colours);
    vtk.path.data->Modified();
    vtk.selectedPath.data->GetPointData()->SetScalars(colours);
    vtk.selectedPath.data->Modified();
}

// By layer, the selected layer is drawn thick in the highlight colour; by speed, thick in its
// speed colours, so the speeds stay readable there too.
void ToolpathView::updateSelectedPath() {
    Scene& vtk = *m_vtk;
    vtkNew<vtkCellArray> lines;
    const bool selected = m_selected >= 0;
    if (selected) {
        appendLayerLine(lines, vtk.scene, static_cast<std::size_t>(m_selected));
    }
    vtk.selectedPath.data->SetLines(lines);
    vtk.selectedPath.data->Modified();
    vtk.selectedPath.mapper->SetScalarVisibility(m_colouring != Colouring::Layer);
    vtk.selectedPath.actor->SetVisibility(selected);
}

void ToolpathView::updateSection() {
    Scene& vtk = *m_vtk;
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    if (m_selected >= 0) {
        for (const cad::Polyline3& piece :
             vtk.scene.layers[static_cast<std::size_t>(m_selected)].section) {
            if (piece.points.size() < 2) {
                continue;
            }
            const vtkIdType first = points->GetNumberOfPoints();
            for (const Vec3& p : piece.points) {
                points->InsertNextPoint(p.data());
            }
            const auto count = static_cast<vtkIdType>(piece.points.size());
            lines->InsertNextCell(static_cast<int>(count + (piece.closed ? 1 : 0)));
            for (vtkIdType i = 0; i < count; ++i) {
                lines->InsertCellPoint(first + i);
            }
            if (piece.closed) {
                lines->InsertCellPoint(first);
            }
        }
    }
    vtk.section.data->SetPoints(points);
    vtk.section.data->SetLines(lines);
    vtk.section.data->Modified();
}

QColor ToolpathView::pathColourAt(std::size_t point) const {
    vtkDataArray* scalars = m_vtk->path.data->GetPointData()->GetScalars();
    auto* colours = vtkUnsignedCharArray::SafeDownCast(scalars);
    if (colours == nullptr || point >= static_cast<std::size_t>(colours->GetNumberOfTuples())) {
        return {};
    }
    unsigned char rgb[3] = {0, 0, 0};
    colours->GetTypedTuple(static_cast<vtkIdType>(point), rgb);
    return {rgb[0], rgb[1], rgb[2]};
}

void ToolpathView::setToolRadius(double radius) {
    m_vtk->toolRadius = radius > 0.0 ? radius : 4.0;
}

std::optional<std::size_t> ToolpathView::drawnPointOf(std::size_t passIndex) const {
    const job::DisplayScene& scene = m_vtk->scene;
    if (scene.empty() || passIndex > scene.record.back()) {
        return std::nullopt;
    }
    return static_cast<std::size_t>(
        std::lower_bound(scene.record.begin(), scene.record.end(), passIndex) -
        scene.record.begin());
}

void ToolpathView::showToolAt(std::size_t record) {
    Scene& vtk = *m_vtk;
    const job::DisplayScene& scene = vtk.scene;
    const std::optional<std::size_t> drawn = drawnPointOf(record);
    if (!drawn) {
        vtk.ballActor->VisibilityOff();
        vtk.shankActor->VisibilityOff();
        m_toolRecord.reset();
        emitReadout();
        update();
        return;
    }
    const Vec3 axis =
        scene.hasRescheduled() ? scene.rescheduledAxes[*drawn] : scene.originalAxes[*drawn];
    // The tip is the lowest point of the ball; its centre sits one radius up the tool axis.
    constexpr double kShankLengthMm = 40.0;
    const Vec3 centre = scene.tips[*drawn] + vtk.toolRadius * axis;
    const Vec3 top = centre + kShankLengthMm * axis;
    vtk.ball->SetCenter(centre.x(), centre.y(), centre.z());
    vtk.ball->SetRadius(vtk.toolRadius);
    vtk.shank->SetPoint1(centre.x(), centre.y(), centre.z());
    vtk.shank->SetPoint2(top.x(), top.y(), top.z());
    vtk.ballActor->VisibilityOn();
    vtk.shankActor->VisibilityOn();
    vtk.renderer->ResetCameraClippingRange();
    m_toolRecord = record;
    emitReadout();
    update();
}

bool ToolpathView::toolVisible() const {
    return m_vtk->ballActor->GetVisibility() != 0;
}

QString ToolpathView::positionReadout(std::size_t passIndex) const {
    const Timeline& t = m_timeline;
    if (t.line.size() != m_vtk->scene.passRecords || passIndex >= t.line.size()) {
        return {}; // no timeline, or one of another program
    }
    QStringList parts{tr("line %1").arg(t.line[passIndex])};
    if (passIndex < t.seconds.size()) {
        parts << tr("t = %1 s").arg(QString::number(t.seconds[passIndex], 'f', 2));
    }
    parts << tr("%1 = %2°").arg(m_tableLetter).arg(signedNumber(t.aDegrees[passIndex], 1));
    return parts.join(QStringLiteral(" · "));
}

QString ToolpathView::positionReadout() const {
    return m_toolRecord ? positionReadout(*m_toolRecord) : QString();
}

void ToolpathView::emitReadout() {
    emit positionReadoutChanged(positionReadout());
}

void ToolpathView::lookFrom(const double direction[3], const double viewUp[3]) {
    vtkCamera* camera = m_vtk->renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(direction[0], direction[1], direction[2]);
    camera->SetViewUp(viewUp[0], viewUp[1], viewUp[2]);
    fitView();
}

void ToolpathView::viewFront() {
    const double direction[3] = {0.0, -1.0, 0.0}, up[3] = {0.0, 0.0, 1.0};
    lookFrom(direction, up);
}

void ToolpathView::viewTop() {
    const double direction[3] = {0.0, 0.0, 1.0}, up[3] = {0.0, 1.0, 0.0};
    lookFrom(direction, up);
}

void ToolpathView::viewSide() {
    const double direction[3] = {1.0, 0.0, 0.0}, up[3] = {0.0, 0.0, 1.0};
    lookFrom(direction, up);
}

void ToolpathView::viewIsometric() {
    const double direction[3] = {1.0, -1.0, 1.0}, up[3] = {0.0, 0.0, 1.0};
    lookFrom(direction, up);
}

void ToolpathView::fitView() {
    syncViewport(); // the fit depends on the aspect of the area beside the legend
    m_vtk->renderer->ResetCamera();
    m_vtk->renderer->ResetCameraClippingRange();
    update();
}

void ToolpathView::resetView() {
    viewIsometric();
}

void ToolpathView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    if (!m_vtk->hasData) {
        const QRect frame(QPoint(0, 0), renderSize());
        painter.fillRect(frame, palette().base());
        painter.drawText(frame, Qt::AlignCenter, tr("Run a job to see the blade and the toolpath"));
        return;
    }
    painter.drawImage(0, 0, renderFrame());
}

} // namespace bladeaxis::ui
