#pragma once
// The job's settings that the batch takes as options and a program may need before it can be
// read or accepted: the unit of the rotary words (--angle-unit), the tolerance of a fixed B
// (--b-tolerance-deg), how far the CAM orientation may lie outside the channel
// (--channel-tolerance-deg) and the preset (--preset). The error dialogs name these controls
// where the batch names its options (window_wording.h); "Apply and re-run" runs the program on
// screen, or the one that just failed, with them.

#include "core/job/job.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace bladeaxis::ui {

class JobSettingsPanel final : public QWidget {
    Q_OBJECT

  public:
    explicit JobSettingsPanel(QWidget* parent = nullptr);

    // Shows the settings of `spec` (the job on screen or starting); Apply is enabled once a
    // value differs from them.
    void showSpec(const job::JobSpec& spec);
    // `spec` with the panel's settings; a preset chosen here replaces the method's parameters
    // as --preset does (a job file's custom parameters are kept while "custom" stays chosen).
    job::JobSpec applyTo(job::JobSpec spec) const;
    bool differsFrom(const job::JobSpec& spec) const;

    QComboBox* angleUnitBox() const { return m_angleUnit; }
    QDoubleSpinBox* bToleranceBox() const { return m_bTolerance; }
    QDoubleSpinBox* channelToleranceBox() const { return m_channelTolerance; }
    QComboBox* presetBox() const { return m_preset; }
    QPushButton* applyButton() const { return m_apply; }

  signals:
    void applyRequested();

  private:
    void updateApply();

    job::JobSpec m_shown;
    QComboBox* m_angleUnit = nullptr;
    QDoubleSpinBox* m_bTolerance = nullptr;
    QDoubleSpinBox* m_channelTolerance = nullptr;
    QComboBox* m_preset = nullptr;
    QPushButton* m_apply = nullptr;
    QLabel* m_note = nullptr;
};

} // namespace bladeaxis::ui
