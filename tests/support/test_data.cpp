#include "support/test_data.h"

#include <QDir>
#include <QFileInfo>

namespace stratamesh::test {

QString dataDir()
{
    const QByteArray env = qgetenv("STRATAMESH_DATA_DIR");
    return QDir::cleanPath(env.isEmpty() ? QStringLiteral(STRATAMESH_DATA_DIR_DEFAULT)
                                         : QString::fromLocal8Bit(env));
}

QString dataFile(const QString &name)
{
    const QString path = QDir(dataDir()).filePath(name);
    if (QFileInfo::exists(path))
        return path;
    qWarning("\n*** STRATAMESH DATA MISSING: %s — tests that need it are SKIPPED ***\n",
             qPrintable(path));
    return {};
}

bool runningInCi()
{
    const QByteArray env = qgetenv("CI").trimmed().toLower();
    return env == "true" || env == "1" || env == "yes";
}

} // namespace stratamesh::test
