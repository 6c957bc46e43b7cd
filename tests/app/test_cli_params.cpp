// stratamesh-cli and the parameter tables: every table option is in the usage and --help, values
// out of a table range are refused with the range, the README's option list is the generated
// one, and `remesh --params REPORT.json` repeats the reported run bit for bit.
#include "cli_runner.h"
#include "support/test_data.h"
#include "test_files.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using stratamesh::test::CliRun;
using stratamesh::test::readAll;
using stratamesh::test::readJson;
using stratamesh::test::runCli;

class TestCliParams : public QObject {
    Q_OBJECT
private slots:
    void helpListsEveryTableOption_data()
    {
        QTest::addColumn<QString>("command");
        QTest::addColumn<QStringList>("flags");
        QTest::newRow("remesh")
            << QStringLiteral("remesh")
            << QStringList{"--sites",      "--edge-length", "--d-resolution",      "--strip-factor",
                           "--iterations", "--seed",        "--refinement-rounds", "--adaptive",
                           "--merge-all"};
        QTest::newRow("complexity")
            << QStringLiteral("complexity")
            << QStringList{"--h", "--alpha", "--cells", "--seed", "--iterations"};
        QTest::newRow("tetmesh") << QStringLiteral(
            "tetmesh") << QStringList{"--quality",      "--max-volume",      "--time-limit",
                                      "--memory-limit", "--refine-surfaces", "--no-merge"};
        QTest::newRow("cvt") << QStringLiteral("cvt")
                             << QStringList{"--iterations", "--alpha", "--lloyd"};
    }

    void helpListsEveryTableOption()
    {
        QFETCH(QString, command);
        QFETCH(QStringList, flags);
        const CliRun r = runCli({command, QStringLiteral("--help")});
        QVERIFY(r.finished);
        QCOMPARE(r.exitCode, 0);
        const QString usage = r.out.section(QLatin1Char('\n'), 0, 0);
        for (const QString &flag : flags) {
            // Once in the usage line, once as the head of its help block.
            QVERIFY2(usage.contains(flag + QLatin1Char(' ')) || usage.contains(flag + ']'),
                     qPrintable(flag + QStringLiteral(" not in ") + usage));
            QVERIFY2(r.out.contains(QStringLiteral("\n  ") + flag), qPrintable(flag));
        }
        QVERIFY(r.out.contains(QStringLiteral("Range ")));
    }

    // The ranges of the table, before any file is read: exit status 2 and the range.
    void outOfRangeValuesAreRefused_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("message");
        QTest::newRow("remesh sites")
            << QStringList{"remesh", "m.ml", "--sites", "2", "-o", "o.ml"}
            << QStringLiteral("--sites expects an integer in [4, 10000000] or 0, got '2'");
        QTest::newRow("remesh strip factor")
            << QStringList{"remesh",         "m.ml", "--sites", "100",
                           "--strip-factor", "1.5",  "-o",      "o.ml"}
            << QStringLiteral("--strip-factor expects a number in [0, 1]");
        // The CLI took 1e-9..1e12 and the dialog 0.001..1e9: both read the table now.
        QTest::newRow("complexity h")
            << QStringList{"complexity", "m.ml", "--h", "1e-6"}
            << QStringLiteral("--h expects a number in [0.001, 1000000000000] m");
        QTest::newRow("complexity cells")
            << QStringList{"complexity", "m.ml", "--cells", "100,0"}
            << QStringLiteral("--cells expects integers in [1, 1000000]");
        QTest::newRow("tetmesh quality") << QStringList{"tetmesh", "m.ml", "--quality", "-1"}
                                         << QStringLiteral("--quality expects a number in [0, ");
        QTest::newRow("cvt alpha") << QStringList{"cvt", "m.ml", "--sites", "10", "--alpha", "2"}
                                   << QStringLiteral("--alpha expects a number in [0, 1], got '2'");
    }

    void outOfRangeValuesAreRefused()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, message);
        const CliRun r = runCli(arguments);
        QVERIFY(r.finished);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
    }

    // The README's option list is what `help --markdown` prints from the tables.
    void readmeOptionListIsGenerated()
    {
        const CliRun r = runCli({QStringLiteral("help"), QStringLiteral("--markdown")});
        QVERIFY(r.finished);
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains(QStringLiteral("`--merge-all`")));
        const QString readme = QString::fromUtf8(readAll(QStringLiteral(STRATAMESH_README)));
        const QString begin = QStringLiteral("<!-- options: stratamesh-cli help --markdown -->\n");
        const QString end = QStringLiteral("<!-- end of options -->");
        const qsizetype from = readme.indexOf(begin);
        const qsizetype to = readme.indexOf(end);
        QVERIFY2(from >= 0 && to > from, "README.md has no generated option list");
        const QString section = readme.mid(from + begin.size(), to - from - begin.size());
        QCOMPARE(section.trimmed(), r.out.trimmed());
    }

    void remeshFromItsReportIsTheSameRun()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA1.ml");
        QTemporaryDir dir;
        const QString first = dir.filePath(QStringLiteral("first.ml"));
        const QString report = dir.filePath(QStringLiteral("first.json"));
        // Not the defaults, so that a parameter the report forgot would change the result.
        const CliRun run =
            runCli({"remesh", path, "--edge-length", "1100", "--iterations", "12", "--seed", "7",
                    "--strip-factor", "0.3", "--merge-all", "--refinement-rounds", "1",
                    "--allow-invalid", "-o", first, "--report", report});
        QVERIFY2(run.finished && run.exitCode == 0, qPrintable(run.err));
        const QJsonObject parameters = readJson(report)[QStringLiteral("parameters")].toObject();
        QCOMPARE(parameters[QStringLiteral("merge_all")].toBool(), true);
        QCOMPARE(parameters[QStringLiteral("strip_factor")].toDouble(), 0.3);
        QCOMPARE(parameters[QStringLiteral("edge_length")].toDouble(), 1100.0);
        QVERIFY(parameters[QStringLiteral("sites")].toInt() > 100); // derived from the length

        const QString second = dir.filePath(QStringLiteral("second.ml"));
        const QString secondReport = dir.filePath(QStringLiteral("second.json"));
        const CliRun again = runCli({"remesh", "--params", report, path, "--allow-invalid", "-o",
                                     second, "--report", secondReport});
        QVERIFY2(again.finished && again.exitCode == 0, qPrintable(again.err));
        const QByteArray a = readAll(first), b = readAll(second);
        QVERIFY(!a.isEmpty());
        QVERIFY2(a == b, "the rerun from the report wrote another model");
        QCOMPARE(readJson(secondReport)[QStringLiteral("parameters")].toObject(), parameters);

        // A flag given with --params overrides the file's value.
        const QString third = dir.filePath(QStringLiteral("third.ml"));
        const QString thirdReport = dir.filePath(QStringLiteral("third.json"));
        const CliRun overridden =
            runCli({"remesh", "--params", report, "--iterations", "3", "--sites", "300", path,
                    "--allow-invalid", "-o", third, "--report", thirdReport});
        QVERIFY2(overridden.finished && overridden.exitCode == 0, qPrintable(overridden.err));
        const QJsonObject p3 = readJson(thirdReport)[QStringLiteral("parameters")].toObject();
        QCOMPARE(p3[QStringLiteral("iterations")].toInt(), 3);
        QCOMPARE(p3[QStringLiteral("sites")].toInt(), 300);
        QCOMPARE(p3[QStringLiteral("edge_length")].toDouble(), 0.0);
        QCOMPARE(p3[QStringLiteral("seed")].toInt(), 7);
        QCOMPARE(p3[QStringLiteral("merge_all")].toBool(), true);
        QVERIFY(readAll(third) != a);
    }

    void badParamsFileIsNamed()
    {
        QTemporaryDir dir;
        const QString bad = dir.filePath(QStringLiteral("bad.json"));
        QFile file(bad);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"parameters": {"sites": 2, "iterations": 10}})");
        file.close();
        const CliRun r =
            runCli({"remesh", "--params", bad, dir.filePath("m.ml"), "-o", dir.filePath("o.ml")});
        QVERIFY(r.finished);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(bad)
                     && r.err.contains(QStringLiteral("sites is 2, outside [4, "
                                                      "10000000] or 0")),
                 qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliParams)
#include "test_cli_params.moc"
