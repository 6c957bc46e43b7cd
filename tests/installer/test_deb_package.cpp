// The .deb holds both executables, the core library, the desktop entry, the icons and the license,
// declares its Debian dependencies, and its executables run from an unpacked tree (dpkg -x) with
// no LD_LIBRARY_PATH.
#include "common/version.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

namespace {

struct Run {
    int exitCode = -1;
    QString out;
    QString err;
};

Run run(const QString &program, const QStringList &arguments, int timeoutMs = 600000)
{
    QProcess process;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("LD_LIBRARY_PATH")); // the unpacked binaries must not need it
    process.setProcessEnvironment(env);
    process.start(program, arguments);
    Run r;
    if (!process.waitForStarted(10000) || !process.waitForFinished(timeoutMs)
        || process.exitStatus() != QProcess::NormalExit) {
        process.kill();
        r.err = QStringLiteral("%1 did not run to its end: %2").arg(program, process.errorString());
        return r;
    }
    r.exitCode = process.exitCode();
    r.out = QString::fromUtf8(process.readAllStandardOutput());
    r.err = QString::fromUtf8(process.readAllStandardError());
    return r;
}

} // namespace

class TestDebPackage : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(m_work.isValid());
        const QString packageDir = m_work.filePath(QStringLiteral("package"));
        const Run cpack =
            run(QStringLiteral(STRATAMESH_CPACK),
                {QStringLiteral("-G"), QStringLiteral("DEB"), QStringLiteral("--config"),
                 QStringLiteral(STRATAMESH_BINARY_DIR "/CPackConfig.cmake"), QStringLiteral("-B"),
                 packageDir});
        QVERIFY2(cpack.exitCode == 0, qPrintable(cpack.out + cpack.err));
        const QStringList debs = QDir(packageDir).entryList({QStringLiteral("stratamesh_*.deb")});
        QVERIFY2(debs.size() == 1, qPrintable(debs.join(QLatin1Char(' '))));
        m_deb = QDir(packageDir).filePath(debs.first());
        QVERIFY2(debs.first().startsWith(QStringLiteral("stratamesh_" STRATAMESH_VERSION "_")),
                 qPrintable(debs.first()));

        m_root = m_work.filePath(QStringLiteral("root"));
        const Run unpack = run(QStringLiteral("dpkg"), {QStringLiteral("-x"), m_deb, m_root});
        QVERIFY2(unpack.exitCode == 0, qPrintable(unpack.err));
    }

    void holdsItsFiles()
    {
        QStringList expected{
            QStringLiteral("usr/bin/stratamesh-cli"),
            QStringLiteral("usr/bin/stratamesh-tetgen"), // TetGen's process (tetmesh)
            QStringLiteral("usr/lib/libstratamesh_core.so.0"),
            QStringLiteral("usr/share/applications/stratamesh.desktop"),
            QStringLiteral("usr/share/icons/hicolor/scalable/apps/stratamesh.svg"),
            QStringLiteral("usr/share/icons/hicolor/256x256/apps/stratamesh.png"),
            QStringLiteral("usr/share/doc/stratamesh/copyright"),
        };
        if (STRATAMESH_HAS_GUI)
            expected << QStringLiteral("usr/bin/stratamesh");
        for (const QString &file : expected)
            QVERIFY2(QFile::exists(QDir(m_root).filePath(file)), qPrintable(file));
        // A runtime package carries no development link (that belongs in a -dev package).
        QVERIFY(!QFileInfo::exists(
            QDir(m_root).filePath(QStringLiteral("usr/lib/libstratamesh_core.so"))));

        QFile license(QDir(m_root).filePath(QStringLiteral("usr/share/doc/stratamesh/copyright")));
        QVERIFY(license.open(QIODevice::ReadOnly));
        QVERIFY(license.readAll().contains("GNU AFFERO GENERAL PUBLIC LICENSE"));
        QFile desktop(
            QDir(m_root).filePath(QStringLiteral("usr/share/applications/stratamesh.desktop")));
        QVERIFY(desktop.open(QIODevice::ReadOnly));
        const QByteArray entry = desktop.readAll();
        QVERIFY(entry.contains("\nExec=stratamesh "));
        QVERIFY(entry.contains("\nIcon=stratamesh\n"));
    }

    void declaresDependencies()
    {
        // From dpkg-shlibdeps: the Qt and VTK runtime packages the binaries link to.
        const Run depends = run(QStringLiteral("dpkg-deb"),
                                {QStringLiteral("--field"), m_deb, QStringLiteral("Depends")});
        QCOMPARE(depends.exitCode, 0);
        QVERIFY2(depends.out.contains(QStringLiteral("libqt6core6")), qPrintable(depends.out));
        QVERIFY2(depends.out.contains(QStringLiteral("libvtk9")), qPrintable(depends.out));
        QVERIFY2(!depends.out.contains(QStringLiteral("stratamesh")), qPrintable(depends.out));
    }

    void unpackedCliRunsAsIs()
    {
        const QString cli = QDir(m_root).filePath(QStringLiteral("usr/bin/stratamesh-cli"));
        const Run version = run(cli, {QStringLiteral("--version")});
        QVERIFY2(version.exitCode == 0, qPrintable(version.err));
        QCOMPARE(version.out.trimmed(), QStringLiteral("stratamesh-cli " STRATAMESH_VERSION));

        // The library it loads is the unpacked one, found through RUNPATH $ORIGIN/../lib.
        const Run elf = run(QStringLiteral("readelf"), {QStringLiteral("-d"), cli});
        QVERIFY2(elf.out.contains(QStringLiteral("$ORIGIN/../lib")), qPrintable(elf.out));
        QVERIFY(!elf.out.contains(QStringLiteral(STRATAMESH_BINARY_DIR)));

        // A whole command through the core library: one square made of two triangles.
        const QString model = m_work.filePath(QStringLiteral("square.ts"));
        QFile file(model);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("GOCAD TSurf 1\nHEADER {\nname:square\n}\nTFACE\n"
                   "VRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 1 1 0\nVRTX 4 0 1 0\n"
                   "TRGL 1 2 3\nTRGL 1 3 4\nEND\n");
        file.close();
        const Run info = run(cli, {QStringLiteral("info"), QStringLiteral("--json"), model});
        QVERIFY2(info.exitCode == 0, qPrintable(info.err));
        QVERIFY2(info.out.contains(QStringLiteral("\"triangles\": 2")), qPrintable(info.out));
    }

    void unpackedGuiStarts()
    {
        if (!STRATAMESH_HAS_GUI)
            QSKIP("built without the GUI (STRATAMESH_BUILD_GUI=OFF)");
        const QString gui = QDir(m_root).filePath(QStringLiteral("usr/bin/stratamesh"));
        const Run version = run(gui, {QStringLiteral("--version"), QStringLiteral("-platform"),
                                      QStringLiteral("offscreen")});
        QVERIFY2(version.exitCode == 0, qPrintable(version.err));
        QVERIFY2(version.out.contains(QStringLiteral(STRATAMESH_VERSION)), qPrintable(version.out));
    }

private:
    QTemporaryDir m_work;
    QString m_deb;
    QString m_root;
};

QTEST_GUILESS_MAIN(TestDebPackage)
#include "test_deb_package.moc"
