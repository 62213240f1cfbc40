#pragma once
// The settings of the selected layer the engineer may change on their own (spec §2.5, §3.4,
// §5.4): preset, margin, epsilon rule and lead fraction. Each control starts at "job", the
// job's value; a change is published as the layer's override (without key points: new settings
// re-schedule the layer from scratch).

#include "core/scheduling/layer_overrides.h"

#include <QWidget>
#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace bladeaxis::ui {

class LayerSettingsPanel final : public QWidget {
    Q_OBJECT

  public:
    explicit LayerSettingsPanel(QWidget* parent = nullptr);

    // Shows the layer's settings: its override's where it has one, "job" elsewhere.
    void setLayer(int layer, const scheduling::LayerOverride* current,
                  const scheduling::ScheduleParameters& job);
    void clearLayer();
    // The override the controls describe (settings only); nullopt when all say "job".
    std::optional<scheduling::LayerOverride> settings() const;

    QComboBox* presetBox() const { return m_preset; }
    QDoubleSpinBox* marginBox() const { return m_margin; }
    QComboBox* epsilonBox() const { return m_epsilon; }
    QDoubleSpinBox* leadBox() const { return m_lead; }

  signals:
    void settingsChanged(int layer, const std::optional<scheduling::LayerOverride>& settings);
    void resetRequested(int layer);

  private:
    void publish();

    int m_layer = -1;
    QLabel* m_title = nullptr;
    QComboBox* m_preset = nullptr;
    QDoubleSpinBox* m_margin = nullptr;
    QComboBox* m_epsilon = nullptr;
    QDoubleSpinBox* m_lead = nullptr;
    QPushButton* m_reset = nullptr;
};

} // namespace bladeaxis::ui
