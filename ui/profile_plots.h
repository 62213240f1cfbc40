#pragma once
// Before/after plots of the machine-axis motion: A position, velocity and acceleration against
// time (original dashed, re-scheduled solid) and the X, Y, Z velocities.

#include "core/analysis/axis_profile.h"

#include <QWidget>
#include <optional>

namespace bladeaxis::ui {

class ProfilePlots final : public QWidget {
    Q_OBJECT

  public:
    explicit ProfilePlots(QWidget* parent = nullptr);
    void setProfiles(const analysis::AxisProfile& original,
                     const std::optional<analysis::AxisProfile>& rescheduled);

  protected:
    void paintEvent(QPaintEvent* event) override;

  private:
    std::optional<analysis::AxisProfile> m_original, m_rescheduled;
};

} // namespace bladeaxis::ui
