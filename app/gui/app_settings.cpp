#include "app_settings.h"

#include <QCoreApplication>
#include <QDir>
#include <QSettings>
#include <QTemporaryDir>

namespace stratamesh {

namespace {

const QString kName = QStringLiteral("StrataMesh");

std::unique_ptr<QSettings> iniIn(const QString &dir)
{
    return std::make_unique<QSettings>(QDir(dir).filePath(QStringLiteral("StrataMesh.ini")),
                                       QSettings::IniFormat);
}

} // namespace

std::unique_ptr<QSettings> openSettings()
{
    const QString dir = qEnvironmentVariable("STRATAMESH_SETTINGS_DIR");
    if (!dir.isEmpty())
        return iniIn(dir);
    // Only the application (main.cpp names it) keeps the user's settings; any other program
    // driving the window, a test above all, starts from none and leaves none behind.
    if (QCoreApplication::organizationName() != kName) {
        static QTemporaryDir fresh;
        return iniIn(fresh.path());
    }
    return std::make_unique<QSettings>(QSettings::UserScope, kName, kName);
}

} // namespace stratamesh
