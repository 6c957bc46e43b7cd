// `stratamesh-cli info --json` on the real models: entity counts without the box are the thesis'
// Table 3.1 (design.md §4), triangle counts the input mesh facts of design.md §4.
#include "cli_runner.h"
#include "support/test_data.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using stratamesh::test::CliRun;
using stratamesh::test::runCli;

class TestCliInfo : public QObject {
    Q_OBJECT
private slots:
    void countsWithoutBox_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("regions");
        QTest::addColumn<int>("surfaces");
        QTest::addColumn<int>("lines");
        QTest::addColumn<int>("corners");
        QTest::addColumn<int>("triangles");
        QTest::newRow("A1") << QStringLiteral("modelA1.ml") << 4 << 3 << 0 << 0 << 7932;
        QTest::newRow("A2") << QStringLiteral("modelA2.ml") << 12 << 23 << 12 << 0 << 16346;
        QTest::newRow("A5") << QStringLiteral("modelA5.ml") << 12 << 31 << 30 << 10 << 14553;
    }

    void countsWithoutBox()
    {
        QFETCH(QString, file);
        QFETCH(int, regions);
        QFETCH(int, surfaces);
        QFETCH(int, lines);
        QFETCH(int, corners);
        QFETCH(int, triangles);
        STRATAMESH_REQUIRE_DATA(path, file);

        const CliRun r = runCli({QStringLiteral("info"), path, QStringLiteral("--json")});
        QVERIFY2(r.finished, qPrintable(r.err));
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QJsonParseError parseError;
        const QJsonDocument doc = QJsonDocument::fromJson(r.out.toUtf8(), &parseError);
        QVERIFY2(parseError.error == QJsonParseError::NoError,
                 qPrintable(parseError.errorString()));
        QVERIFY(doc.isObject());
        const QJsonObject report = doc.object();

        const QJsonObject noBox =
            report[QStringLiteral("counts")][QStringLiteral("without_box")].toObject();
        QCOMPARE(noBox[QStringLiteral("regions")].toInt(-1), regions);
        QCOMPARE(noBox[QStringLiteral("surfaces")].toInt(-1), surfaces);
        QCOMPARE(noBox[QStringLiteral("lines")].toInt(-1), lines);
        QCOMPARE(noBox[QStringLiteral("corners")].toInt(-1), corners);
        const QJsonObject all = report[QStringLiteral("counts")][QStringLiteral("all")].toObject();
        QVERIFY(all[QStringLiteral("surfaces")].toInt() > surfaces); // the box has surfaces
        QVERIFY(all[QStringLiteral("lines")].toInt() >= lines);
        QVERIFY(all[QStringLiteral("corners")].toInt() >= corners);

        const QJsonObject mesh = report[QStringLiteral("mesh")].toObject();
        QCOMPARE(mesh[QStringLiteral("triangles")].toInt(-1), triangles);
        QVERIFY(mesh[QStringLiteral("vertices")].toInt() > 0);
        const double minAngle = mesh[QStringLiteral("min_angle_deg")].toDouble(-1);
        QVERIFY(minAngle > 0.0 && minAngle <= 60.0);
        const double below30 = mesh[QStringLiteral("pct_triangles_angle_below_30")].toDouble(-1);
        QVERIFY(below30 >= 0.0 && below30 <= 100.0);
        const double q = mesh[QStringLiteral("mean_quality")].toDouble(-1);
        QVERIFY(q > 0.0 && q <= 1.0);
        QVERIFY(mesh[QStringLiteral("bbox_diagonal")].toDouble() > 0.0);

        // One entry per region, each with a name and a positive volume (Gocad side rule).
        const QJsonArray regionList = report[QStringLiteral("regions")].toArray();
        QCOMPARE(regionList.size(), all[QStringLiteral("regions")].toInt());
        for (const QJsonValue &region : regionList) {
            QVERIFY(!region[QStringLiteral("name")].toString().isEmpty());
            QVERIFY2(region[QStringLiteral("volume")].toDouble() > 0.0,
                     qPrintable(region[QStringLiteral("name")].toString()));
        }

        const QJsonObject validity = report[QStringLiteral("validity")].toObject();
        QVERIFY(validity[QStringLiteral("valid")].isBool());
        QVERIFY(validity[QStringLiteral("problems")].isArray());
        QCOMPARE(validity[QStringLiteral("valid")].toBool(),
                 validity[QStringLiteral("problems")].toArray().isEmpty());
        const QJsonObject timings = report[QStringLiteral("timings")].toObject();
        QVERIFY(timings[QStringLiteral("read_s")].toDouble(-1) >= 0.0);
        QVERIFY(timings[QStringLiteral("topology_s")].toDouble(-1) >= 0.0);
    }

    void a2NeedlesAreSeen()
    {
        // design.md §4: A2 has min angle ~5e-5° and ~73 % of triangles with an angle < 30°.
        STRATAMESH_REQUIRE_DATA(path, "modelA2.ml");
        const CliRun r = runCli({QStringLiteral("info"), QStringLiteral("--json"), path});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject mesh =
            QJsonDocument::fromJson(r.out.toUtf8()).object()[QStringLiteral("mesh")].toObject();
        QVERIFY(mesh[QStringLiteral("min_angle_deg")].toDouble(-1) < 1e-3);
        const double below30 = mesh[QStringLiteral("pct_triangles_angle_below_30")].toDouble(-1);
        QVERIFY2(below30 > 70.0 && below30 < 76.0, qPrintable(QString::number(below30)));
    }

    void textReportWithoutJson()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA1.ml");
        const CliRun r = runCli({QStringLiteral("info"), path});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains(QStringLiteral("7,932 triangles")), qPrintable(r.out));
        QVERIFY(r.out.contains(QStringLiteral("regions")));
        QVERIFY(!r.out.trimmed().startsWith(QLatin1Char('{')));
    }
};

QTEST_GUILESS_MAIN(TestCliInfo)
#include "test_cli_info.moc"
