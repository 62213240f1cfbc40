#include "ui/layer_settings_panel.h"

#include "core/base/units.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>

namespace bladeaxis::ui {
namespace {

// The spin boxes show "job" at their minimum, one step below the smallest real value.
constexpr double kMarginJob = -0.5; // deg
constexpr double kLeadJob = 0.0;    // rho; real values start at 0.02 (docs/method.md §3.4)
constexpr int kJobIndex = 0;        // the combo boxes' "job" entry

QString marginTip() {
    return LayerSettingsPanel::tr(
        "Margin m: how far the new orientation keeps from the edge of the channel (where the "
        "shank would touch the blade) before the one-way hull is built; larger is safer, smaller "
        "leaves more room to smooth");
}

} // namespace

LayerSettingsPanel::LayerSettingsPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    m_title = new QLabel(tr("Layer –"), this);
    layout->addWidget(m_title);

    m_preset = new QComboBox(this);
    m_preset->addItems({tr("job"), tr("best"), tr("faithful")});
    m_preset->setToolTip(tr("This layer's rules: the job's, the corrected 'best' or the paper's "
                            "'faithful' (margin, lead, key points, corners)"));
    layout->addWidget(new QLabel(tr("Preset"), this));
    layout->addWidget(m_preset);

    m_margin = new QDoubleSpinBox(this);
    m_margin->setRange(kMarginJob, 45.0);
    m_margin->setSingleStep(0.5);
    m_margin->setDecimals(2);
    m_margin->setSuffix(tr(" °"));
    m_margin->setSpecialValueText(tr("job"));
    m_margin->setToolTip(marginTip());
    layout->addWidget(new QLabel(tr("Margin"), this));
    layout->addWidget(m_margin);

    m_epsilon = new QComboBox(this);
    m_epsilon->addItems({tr("job"), tr("exact"), tr("paper")});
    m_epsilon->setToolTip(tr("How large the rounded corners between the key-point segments may "
                             "be: 'exact' grows each corner while the curve stays in the channel "
                             "(smoother); 'paper' uses the original paper's fixed rule"));
    layout->addWidget(new QLabel(tr("ε rule"), this));
    layout->addWidget(m_epsilon);

    m_lead = new QDoubleSpinBox(this);
    m_lead->setRange(kLeadJob, 0.45);
    m_lead->setSingleStep(0.01);
    m_lead->setDecimals(3);
    m_lead->setSpecialValueText(tr("job"));
    m_lead->setToolTip(tr("Share ρ of the layer, at each end, over which the orientation eases "
                          "into the junction with the next layer; 'job' lets the job choose it"));
    layout->addWidget(new QLabel(tr("Lead ρ"), this));
    layout->addWidget(m_lead);

    m_reset = new QPushButton(tr("Reset layer"), this);
    m_reset->setToolTip(tr("Drop every change of this layer (settings and key points)"));
    layout->addWidget(m_reset);
    layout->addStretch(1);

    connect(m_preset, &QComboBox::currentIndexChanged, this, &LayerSettingsPanel::publish);
    connect(m_epsilon, &QComboBox::currentIndexChanged, this, &LayerSettingsPanel::publish);
    connect(m_margin, &QDoubleSpinBox::editingFinished, this, &LayerSettingsPanel::publish);
    connect(m_lead, &QDoubleSpinBox::editingFinished, this, &LayerSettingsPanel::publish);
    connect(m_reset, &QPushButton::clicked, this, [this] {
        if (m_layer >= 0) {
            emit resetRequested(m_layer);
        }
    });
    clearLayer();
}

void LayerSettingsPanel::setLayer(int layer, const scheduling::LayerOverride* current,
                                  const scheduling::ScheduleParameters& job) {
    const QSignalBlocker blockPreset(m_preset), blockMargin(m_margin), blockEpsilon(m_epsilon),
        blockLead(m_lead);
    m_layer = layer;
    m_title->setText(tr("Layer %1").arg(layer));
    const bool has = current != nullptr;
    m_preset->setCurrentIndex(!has || !current->preset                       ? kJobIndex
                              : *current->preset == scheduling::Preset::Best ? 1
                                                                             : 2);
    m_margin->setValue(has && current->marginRad ? units::radToDeg(*current->marginRad)
                                                 : kMarginJob);
    m_epsilon->setCurrentIndex(!has || !current->epsilonRule                             ? kJobIndex
                               : *current->epsilonRule == scheduling::EpsilonRule::Exact ? 1
                                                                                         : 2);
    m_lead->setValue(has && current->leadFraction ? *current->leadFraction : kLeadJob);
    m_margin->setToolTip(marginTip() +
                         tr("; the job's: %1°").arg(units::radToDeg(job.marginRad), 0, 'f', 2));
    setEnabled(true);
}

void LayerSettingsPanel::clearLayer() {
    m_layer = -1;
    m_title->setText(tr("Layer –"));
    setEnabled(false);
}

std::optional<scheduling::LayerOverride> LayerSettingsPanel::settings() const {
    if (m_layer < 0) {
        return std::nullopt;
    }
    scheduling::LayerOverride change;
    change.layer = static_cast<std::size_t>(m_layer);
    if (m_preset->currentIndex() != kJobIndex) {
        change.preset =
            m_preset->currentIndex() == 1 ? scheduling::Preset::Best : scheduling::Preset::Faithful;
    }
    if (m_margin->value() > kMarginJob) {
        change.marginRad = units::degToRad(m_margin->value());
    }
    if (m_epsilon->currentIndex() != kJobIndex) {
        change.epsilonRule = m_epsilon->currentIndex() == 1 ? scheduling::EpsilonRule::Exact
                                                            : scheduling::EpsilonRule::Paper;
    }
    if (m_lead->value() > kLeadJob) {
        change.leadFraction = m_lead->value();
    }
    const bool any = change.preset || change.marginRad || change.epsilonRule || change.leadFraction;
    return any ? std::optional(change) : std::nullopt;
}

void LayerSettingsPanel::publish() {
    if (m_layer >= 0) {
        emit settingsChanged(m_layer, settings());
    }
}

} // namespace bladeaxis::ui
