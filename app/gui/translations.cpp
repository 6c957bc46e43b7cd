#include "translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

namespace stratamesh {

QString installTranslations(const QString &language)
{
    QLocale locale = language.isEmpty() ? QLocale::system() : QLocale(language);
    // Embedded by qt_add_translations under :/i18n. English has a file too, for its plural forms.
    auto *ours = new QTranslator(qApp);
    if (!ours->load(locale, QStringLiteral("stratamesh"), QStringLiteral("_"),
                    QStringLiteral(":/i18n"))) {
        locale = QLocale(QLocale::English);
        if (!ours->load(locale, QStringLiteral("stratamesh"), QStringLiteral("_"),
                        QStringLiteral(":/i18n"))) {
            delete ours;
            return QStringLiteral("en");
        }
    }
    // One language at a time: a later call replaces what an earlier one installed.
    static QTranslator *installed = nullptr, *installedQt = nullptr;
    for (QTranslator **t : {&installed, &installedQt}) {
        if (*t)
            QCoreApplication::removeTranslator(*t);
        delete *t;
        *t = nullptr;
    }
    installed = ours;
    QCoreApplication::installTranslator(ours);
    QLocale::setDefault(locale);
    if (locale.language() == QLocale::English)
        return QStringLiteral("en");
    // Qt's own strings (file dialog buttons, About Qt) when the system has them.
    auto *qt = new QTranslator(qApp);
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        installedQt = qt;
        QCoreApplication::installTranslator(qt);
    } else {
        delete qt;
    }
    return locale.name().left(2);
}

} // namespace stratamesh
