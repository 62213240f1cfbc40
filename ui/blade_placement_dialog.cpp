#include "ui/blade_placement_dialog.h"

#include "core/base/units.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QVBoxLayout>

namespace bladeaxis::ui {
namespace {

constexpr double kMaxAngleDeg = 360.0;
constexpr double kMaxShiftMm = 10'000.0; // a machine's work volume, with room to spare

QDoubleSpinBox* placementField(double maximum, int decimals, const QString& suffix, double value,
                               QWidget* parent) {
    auto* field = new QDoubleSpinBox(parent);
    field->setRange(-maximum, maximum);
    field->setDecimals(decimals);
    field->setSuffix(suffix);
    field->setValue(value);
    return field;
}

} // namespace

BladePlacementDialog::BladePlacementDialog(const cad::AxisRotationPlacement& initial,
                                           QWidget* parent)
    : QDialog(parent) {
    setWindowTitle(tr("Blade placement"));
    auto* form = new QFormLayout;
    const QString axes[] = {QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")};
    for (int k = 0; k < 3; ++k) {
        m_rotation.at(k) = placementField(kMaxAngleDeg, 6, tr(" °"),
                                          units::radToDeg(initial.rotationXyz[k]), this);
        m_rotation.at(k)->setToolTip(
            tr("Rotation of the CAD about the %1 axis of the workpiece frame; the rotations "
               "apply about X, then Y, then Z, before the translation (--cad-rotate-deg)")
                .arg(axes[k]));
        form->addRow(tr("Rotate about %1").arg(axes[k]), m_rotation.at(k));
    }
    for (int k = 0; k < 3; ++k) {
        m_translation.at(k) =
            placementField(kMaxShiftMm, 4, tr(" mm"), initial.translation[k], this);
        m_translation.at(k)->setToolTip(
            tr("Translation of the rotated CAD along %1 (--cad-translate)").arg(axes[k]));
        form->addRow(tr("Translate along %1").arg(axes[k]), m_translation.at(k));
    }
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
}

cad::AxisRotationPlacement BladePlacementDialog::placement() const {
    cad::AxisRotationPlacement result;
    for (int k = 0; k < 3; ++k) {
        result.rotationXyz[k] = units::degToRad(m_rotation.at(k)->value());
        result.translation[k] = m_translation.at(k)->value();
    }
    return result;
}

} // namespace bladeaxis::ui
