// The include order of the core folders that docs/ARCHITECTURE.md states ("a folder includes
// only folders below it"), read from the sources: e.g. core/voronoi must not include core/quality.
// Folders this list does not know (added later) are not checked, nor are includes of them.
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>
#include <QtTest>

#include <map>
#include <set>

namespace {

const std::map<QString, std::set<QString>> &allowed()
{
    static const std::map<QString, std::set<QString>> layers{
        {"common", {}},
        {"model", {"common"}},
        {"mesh", {"common", "model"}},
        {"voronoi", {"common", "model"}},
        {"cvt", {"common", "model", "voronoi"}},
        {"quality", {"common", "model", "voronoi"}},
        {"complexity", {"common", "model"}},
        {"io", {"common", "model", "mesh", "complexity"}},
        {"remesh", {"common", "model", "voronoi", "cvt", "quality", "complexity"}},
        {"volume", {"common", "model", "mesh", "io", "quality"}},
    };
    return layers;
}

} // namespace

class TestCoreLayers : public QObject {
    Q_OBJECT

private slots:
    void foldersIncludeOnlyTheLayersBelow()
    {
        const QDir core(QStringLiteral(QT_TESTCASE_SOURCEDIR "/../../core"));
        QVERIFY2(core.exists(QStringLiteral("voronoi")), qPrintable(core.absolutePath()));
        const QRegularExpression include(QStringLiteral("^#include \"([a-z_]+)/"),
                                         QRegularExpression::MultilineOption);
        int files = 0, checked = 0;
        QStringList violations;
        for (const auto &[folder, below] : allowed()) {
            QDirIterator it(core.filePath(folder), {QStringLiteral("*.h"), QStringLiteral("*.cpp")},
                            QDir::Files, QDirIterator::Subdirectories);
            while (it.hasNext()) {
                const QString path = it.next();
                QFile file(path);
                QVERIFY(file.open(QIODevice::ReadOnly));
                ++files;
                const QString text = QString::fromUtf8(file.readAll());
                for (auto m = include.globalMatch(text); m.hasNext();) {
                    const QString target = m.next().captured(1);
                    if (target == folder || !allowed().count(target))
                        continue;
                    ++checked;
                    if (!below.count(target))
                        violations << core.relativeFilePath(path) + QStringLiteral(" includes ")
                                          + target + QStringLiteral("/");
                }
            }
        }
        QVERIFY(files > 100 && checked > 100); // the sources were found and read
        QVERIFY2(violations.isEmpty(), qPrintable(violations.join(QStringLiteral("; "))));
    }
};

QTEST_APPLESS_MAIN(TestCoreLayers)
#include "test_core_layers.moc"
