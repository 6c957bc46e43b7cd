// Installs StrataMesh's and Qt's own translations for a language (or the system locale).
#pragma once

#include <QString>

namespace stratamesh {

// language: "fr", "en" or empty for the system's UI languages. Returns the language in use.
QString installTranslations(const QString &language);

} // namespace stratamesh
