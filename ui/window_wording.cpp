#include "ui/window_wording.h"

#include <QObject>
#include <QRegularExpression>
#include <array>

namespace bladeaxis::ui {
namespace {

// "the Angle unit box in the Job settings panel (View > Job settings)".
QString inJobSettings(const char* control) {
    return QObject::tr("\"%1\" in the %2 panel (View > %2), then \"%3\"")
        .arg(QString::fromUtf8(control), QString::fromUtf8(controls::kJobSettings),
             QString::fromUtf8(controls::kApply));
}

struct Rewording {
    QRegularExpression pattern;
    QString replacement;
};

// The batch's advice, as the core words it, and what the window says instead. The most specific
// phrases first; the last ones catch an option named any other way.
const std::array<Rewording, 12>& rewordings() {
    static const std::array<Rewording, 12> kRewordings{{
        {QRegularExpression(QStringLiteral(R"(give --angle-unit rad)")),
         QObject::tr("choose \"radians\" under %1").arg(inJobSettings(controls::kAngleUnit))},
        {QRegularExpression(QStringLiteral(R"(give --angle-unit deg\|rad \(job key angle_unit\))")),
         QObject::tr("choose the unit under %1").arg(inJobSettings(controls::kAngleUnit))},
        {QRegularExpression(QStringLiteral(R"(--angle-unit rad does not apply)")),
         QObject::tr("\"radians\" under %1 does not apply")
             .arg(QString::fromUtf8(controls::kAngleUnit))},
        {QRegularExpression(QStringLiteral(R"(allow it with --b-tolerance-deg)")),
         QObject::tr("allow it with a larger %1").arg(inJobSettings(controls::kBTolerance))},
        {QRegularExpression(QStringLiteral(R"(--channel-tolerance-deg accepts a larger distance)")),
         QObject::tr("a larger %1 accepts a larger distance")
             .arg(inJobSettings(controls::kChannelTolerance))},
        {QRegularExpression(QStringLiteral(R"(\(use --force to write it anyway\))")),
         QObject::tr("(to write it anyway, review the points on the %1 tab and tick \"%2\")")
             .arg(QString::fromUtf8(controls::kReviewTab),
                  QString::fromUtf8(controls::kAcknowledge))},
        {QRegularExpression(QStringLiteral(R"(give --tool-radius)")),
         QObject::tr("type the ball radius in the tool bar's \"%1\" box")
             .arg(QString::fromUtf8(controls::kToolRadius))},
        {QRegularExpression(QStringLiteral(R"(--tool-radius(?: \(job file: tool_radius_mm\))?)")),
         QObject::tr("the tool bar's \"%1\"").arg(QString::fromUtf8(controls::kToolRadius))},
        {QRegularExpression(QStringLiteral(R"(--b-tolerance-deg)")),
         inJobSettings(controls::kBTolerance)},
        {QRegularExpression(QStringLiteral(R"(--channel-tolerance-deg)")),
         inJobSettings(controls::kChannelTolerance)},
        {QRegularExpression(QStringLiteral(R"(--angle-unit(?: deg\|rad| rad| deg)?)")),
         inJobSettings(controls::kAngleUnit)},
        {QRegularExpression(QStringLiteral(R"(--force)")),
         QObject::tr("\"%1\" on the %2 tab")
             .arg(QString::fromUtf8(controls::kAcknowledge),
                  QString::fromUtf8(controls::kReviewTab))},
    }};
    return kRewordings;
}

} // namespace

QString windowWording(const QString& message) {
    QString worded = message;
    for (const Rewording& rewording : rewordings()) {
        worded.replace(rewording.pattern, rewording.replacement);
    }
    return worded;
}

QString windowWording(const Error& error) {
    return windowWording(QString::fromStdString(error.toString()));
}

} // namespace bladeaxis::ui
