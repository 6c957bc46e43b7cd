#include "app_settings.h"

#include <QDir>
#include <QSettings>

namespace stratamesh {

std::unique_ptr<QSettings> openSettings()
{
    const QString dir = qEnvironmentVariable("STRATAMESH_SETTINGS_DIR");
    if (!dir.isEmpty())
        return std::make_unique<QSettings>(QDir(dir).filePath(QStringLiteral("StrataMesh.ini")),
                                           QSettings::IniFormat);
    return std::make_unique<QSettings>(QSettings::UserScope, QStringLiteral("StrataMesh"),
                                       QStringLiteral("StrataMesh"));
}

} // namespace stratamesh
