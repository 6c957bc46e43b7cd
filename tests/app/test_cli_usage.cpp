// Exit statuses and messages of stratamesh-cli for good and bad command lines and bad files:
// 0 success, 1 error naming the file (and line), 2 bad usage; never a crash.
#include "cli_runner.h"
#include "common/version.h"

#include <QTemporaryDir>
#include <QtTest>

using stratamesh::test::CliRun;
using stratamesh::test::runCli;

class TestCliUsage : public QObject {
    Q_OBJECT
private slots:
    void version()
    {
        const CliRun r = runCli({QStringLiteral("--version")});
        QVERIFY(r.finished);
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out.trimmed(), QStringLiteral("stratamesh-cli " STRATAMESH_VERSION));
    }

    void helpListsCommands()
    {
        const CliRun r = runCli({QStringLiteral("--help")});
        QVERIFY(r.finished);
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains(QStringLiteral("info MODEL [--json]")), qPrintable(r.out));

        const CliRun sub = runCli({QStringLiteral("info"), QStringLiteral("--help")});
        QCOMPARE(sub.exitCode, 0);
        QVERIFY(sub.out.startsWith(QStringLiteral("usage: stratamesh-cli info MODEL")));
    }

    void badUsage_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("message");
        QTest::newRow("nothing") << QStringList{}
                                 << QStringLiteral("usage: stratamesh-cli COMMAND");
        QTest::newRow("unknown command") << QStringList{QStringLiteral("frobnicate")}
                                         << QStringLiteral("unknown command 'frobnicate'");
        QTest::newRow("missing model")
            << QStringList{QStringLiteral("info")} << QStringLiteral("missing MODEL");
        QTest::newRow("unknown option")
            << QStringList{QStringLiteral("info"), QStringLiteral("--jsn"), QStringLiteral("a.ml")}
            << QStringLiteral("unknown option --jsn");
        QTest::newRow("extra argument")
            << QStringList{QStringLiteral("info"), QStringLiteral("a.ml"), QStringLiteral("b.ml")}
            << QStringLiteral("unexpected argument 'b.ml'");
    }

    void badUsage()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, message);
        const CliRun r = runCli(arguments);
        QVERIFY(r.finished);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
    }

    void missingFileNamesIt()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("no_such_model.ml"));
        for (const QStringList &extra : {QStringList{}, QStringList{QStringLiteral("--json")}}) {
            const CliRun r = runCli(QStringList{QStringLiteral("info"), path} + extra);
            QVERIFY(r.finished);
            QCOMPARE(r.exitCode, 1);
            QVERIFY2(r.err.startsWith(QStringLiteral("stratamesh-cli: error: ") + path),
                     qPrintable(r.err));
            QVERIFY(r.out.isEmpty());
        }
    }

    void unknownExtensionNamesTheFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("model.xyz"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("1 2 3\n");
        file.close();
        const CliRun r = runCli({QStringLiteral("info"), path});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(path), qPrintable(r.err));
    }

    void malformedFileNamesTheLine()
    {
        // Line 5 has a coordinate that is not a number.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("broken.ts"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("GOCAD TSurf 1\n"
                   "HEADER {\nname:broken\n}\n"
                   "VRTX 1 0 zero 0\n"
                   "VRTX 2 1 0 0\n"
                   "VRTX 3 0 1 0\n"
                   "TRGL 1 2 3\n"
                   "END\n");
        file.close();
        const CliRun r = runCli({QStringLiteral("info"), QStringLiteral("--json"), path});
        QVERIFY(r.finished);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.startsWith(QStringLiteral("stratamesh-cli: error: ") + path
                                  + QStringLiteral(":5: ")),
                 qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliUsage)
#include "test_cli_usage.moc"
