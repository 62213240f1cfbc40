#pragma once
// Numbers as a person reads them: in the desktop's language, thousands always grouped
// ("1,408,372"; the C locale, which omits the separator by default, groups too).

#include <QLocale>
#include <QString>

namespace bladeaxis::ui {

inline QString groupedNumber(double value, int decimals) {
    QLocale locale;
    locale.setNumberOptions(locale.numberOptions() & ~QLocale::OmitGroupSeparator);
    return locale.toString(value, 'f', decimals);
}

} // namespace bladeaxis::ui
