#include "ui/job_settings_panel.h"

#include "core/base/units.h"
#include "core/job/parameter_schema.h"
#include "ui/window_wording.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>
#include <cmath>

namespace bladeaxis::ui {
namespace {

// The combo's data for the unit read from the file or its values (no --angle-unit).
constexpr int kAutoUnit = -1;
const QString kCustomPreset = QStringLiteral("custom");

int unitIndexOf(const std::optional<io::AngleUnit>& unit) {
    return !unit ? kAutoUnit : static_cast<int>(*unit);
}

QDoubleSpinBox* degreeBox(QWidget* parent, double maximum, int decimals, const QString& name) {
    auto* box = new QDoubleSpinBox(parent);
    box->setObjectName(name);
    box->setRange(std::pow(10.0, -decimals), maximum);
    box->setDecimals(decimals);
    box->setSuffix(QStringLiteral(" °"));
    box->setKeyboardTracking(false);
    return box;
}

// Whether the box shows `radians` (in degrees, as rounded to its decimals): then the spec's
// exact value is kept rather than the box's rounding of it.
bool shows(const QDoubleSpinBox& box, double radians) {
    const double scale = std::pow(10.0, box.decimals());
    return std::abs(box.value() - std::round(units::radToDeg(radians) * scale) / scale) <
           0.5 / scale;
}

} // namespace

JobSettingsPanel::JobSettingsPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("jobSettingsPanel"));
    auto* form = new QFormLayout;
    m_angleUnit = new QComboBox(this);
    m_angleUnit->setObjectName(QStringLiteral("angleUnit"));
    m_angleUnit->addItem(tr("from the file"), kAutoUnit);
    m_angleUnit->addItem(tr("degrees"), static_cast<int>(io::AngleUnit::Degrees));
    m_angleUnit->addItem(tr("radians"), static_cast<int>(io::AngleUnit::Radians));
    m_angleUnit->setToolTip(tr("The unit of the program's rotary words (A, B): from a post header "
                               "such as (ANGLES IN DEGREES) or the values, or as chosen here "
                               "(the batch's --angle-unit)"));
    m_bTolerance = degreeBox(this, 10.0, 4, QStringLiteral("bTolerance"));
    m_bTolerance->setToolTip(tr("How far B may vary along the pass and still count as a fixed "
                                "head: noise of the post-processor within it is snapped to the "
                                "median (the batch's --b-tolerance-deg)"));
    m_channelTolerance = degreeBox(this, 180.0, 2, QStringLiteral("channelTolerance"));
    m_channelTolerance->setToolTip(tr("How far the program's orientation may lie outside the "
                                      "feasible channel before the program is refused as another "
                                      "machine's (the batch's --channel-tolerance-deg)"));
    m_preset = new QComboBox(this);
    m_preset->setObjectName(QStringLiteral("preset"));
    m_preset->addItem(tr("best (corrected rules)"), QStringLiteral("best"));
    m_preset->addItem(tr("faithful (the paper's rules)"), QStringLiteral("faithful"));
    m_preset->setToolTip(tr("The method's parameter set (the batch's --preset); a job file's own "
                            "parameters show as \"custom\""));
    form->addRow(tr("%1:").arg(QString::fromUtf8(controls::kAngleUnit)), m_angleUnit);
    form->addRow(tr("%1:").arg(QString::fromUtf8(controls::kBTolerance)), m_bTolerance);
    form->addRow(tr("%1:").arg(QString::fromUtf8(controls::kChannelTolerance)), m_channelTolerance);
    form->addRow(tr("%1:").arg(QString::fromUtf8(controls::kPreset)), m_preset);
    m_apply = new QPushButton(QString::fromUtf8(controls::kApply), this);
    m_apply->setObjectName(QStringLiteral("applyJobSettings"));
    m_apply->setToolTip(tr("Run the program on screen, or the one that just failed, with these "
                           "settings"));
    m_note = new QLabel(tr("The tolerances and the preset stay for the next programs, the angle "
                           "unit belongs to one program; a job file brings its own."),
                        this);
    m_note->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_apply);
    layout->addWidget(m_note);
    layout->addStretch(1);
    connect(m_apply, &QPushButton::clicked, this, &JobSettingsPanel::applyRequested);
    connect(m_angleUnit, &QComboBox::currentIndexChanged, this, &JobSettingsPanel::updateApply);
    connect(m_preset, &QComboBox::currentIndexChanged, this, &JobSettingsPanel::updateApply);
    connect(m_bTolerance, &QDoubleSpinBox::valueChanged, this, &JobSettingsPanel::updateApply);
    connect(m_channelTolerance, &QDoubleSpinBox::valueChanged, this,
            &JobSettingsPanel::updateApply);
    showSpec(job::JobSpec{});
}

void JobSettingsPanel::showSpec(const job::JobSpec& spec) {
    m_shown = spec;
    const QSignalBlocker unitBlock(m_angleUnit), bBlock(m_bTolerance),
        channelBlock(m_channelTolerance), presetBlock(m_preset);
    m_angleUnit->setCurrentIndex(m_angleUnit->findData(unitIndexOf(spec.read.angleUnit)));
    m_bTolerance->setValue(units::radToDeg(spec.check.tiltToleranceRad));
    m_channelTolerance->setValue(units::radToDeg(spec.check.channelToleranceRad));
    const QString preset = QString::fromStdString(spec.presetName);
    const int custom = m_preset->findData(kCustomPreset);
    if (preset == kCustomPreset && custom < 0) {
        m_preset->addItem(tr("custom (the job file's)"), kCustomPreset);
    } else if (preset != kCustomPreset && custom >= 0) {
        m_preset->removeItem(custom);
    }
    m_preset->setCurrentIndex(std::max(0, m_preset->findData(preset)));
    updateApply();
}

job::JobSpec JobSettingsPanel::applyTo(job::JobSpec spec) const {
    const int unit = m_angleUnit->currentData().toInt();
    spec.read.angleUnit =
        unit == kAutoUnit ? std::nullopt : std::optional(static_cast<io::AngleUnit>(unit));
    // Only a value the box does not show replaces the spec's: the box rounds to its decimals.
    if (!shows(*m_bTolerance, spec.check.tiltToleranceRad)) {
        spec.check.tiltToleranceRad = units::degToRad(m_bTolerance->value());
    }
    if (!shows(*m_channelTolerance, spec.check.channelToleranceRad)) {
        spec.check.channelToleranceRad = units::degToRad(m_channelTolerance->value());
    }
    const std::string preset = m_preset->currentData().toString().toStdString();
    if (preset != spec.presetName && QString::fromStdString(preset) != kCustomPreset) {
        if (auto parameters = job::presetParameters(preset)) {
            spec.parameters = *parameters;
            spec.presetName = preset;
        }
    }
    return spec;
}

bool JobSettingsPanel::differsFrom(const job::JobSpec& spec) const {
    const job::JobSpec applied = applyTo(spec);
    return applied.read.angleUnit != spec.read.angleUnit ||
           applied.check.tiltToleranceRad != spec.check.tiltToleranceRad ||
           applied.check.channelToleranceRad != spec.check.channelToleranceRad ||
           applied.presetName != spec.presetName;
}

void JobSettingsPanel::updateApply() {
    m_apply->setEnabled(differsFrom(m_shown));
}

} // namespace bladeaxis::ui
