#pragma once
// The placement of the blade CAD relative to the rotary axis, asked when a CAD file is opened:
// rotations about the X, Y and Z axes of the workpiece frame in degrees (applied in that order)
// and then a translation in mm, the same as --cad-rotate-deg and --cad-translate.

#include "core/cad/cad_files.h"

#include <QDialog>
#include <array>

class QDoubleSpinBox;

namespace bladeaxis::ui {

class BladePlacementDialog final : public QDialog {
    Q_OBJECT

  public:
    explicit BladePlacementDialog(const cad::AxisRotationPlacement& initial,
                                  QWidget* parent = nullptr);

    // What the fields say, angles converted to rad.
    cad::AxisRotationPlacement placement() const;
    QDoubleSpinBox* rotationField(int axis) const { return m_rotation.at(axis); }
    QDoubleSpinBox* translationField(int axis) const { return m_translation.at(axis); }

  private:
    std::array<QDoubleSpinBox*, 3> m_rotation{};
    std::array<QDoubleSpinBox*, 3> m_translation{};
};

} // namespace bladeaxis::ui
