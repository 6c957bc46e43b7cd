// stratamesh-cli hybrid as a user runs it: modelA1 at 1000 sites gives a valid mesh (our mixed-mesh
// checker, in the report) whose .vtu and .msh hold the reported cell counts; a bad output
// extension is a usage error that writes nothing.
#include "cli_runner.h"
#include "io/mesh_reader.h"
#include "support/test_data.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;
using namespace stratamesh::test;

class TestCliHybrid : public QObject {
    Q_OBJECT

private slots:
    void modelA1IsValid()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA1.ml");
        QTemporaryDir dir;
        for (const QString &ext : {QStringLiteral("vtu"), QStringLiteral("msh")}) {
            const QString out = dir.filePath("a1." + ext), report = dir.filePath("a1.json");
            const CliRun run =
                runCli({"hybrid", path, "--sites", "1000", "-o", out, "--report", report}, 600000);
            QVERIFY2(run.finished && run.exitCode == 0, qPrintable(run.err));
            QFile f(report);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const QJsonObject r = QJsonDocument::fromJson(f.readAll()).object();
            for (const char *key : {"tets", "prisms", "pyramids", "invalid_found", "repaired",
                                    "valid", "quality", "time_s"})
                QVERIFY2(r.contains(key), key);
            QVERIFY(r["valid"].toBool());
            const qint64 tets = r["tets"].toInteger(), prisms = r["prisms"].toInteger(),
                         pyramids = r["pyramids"].toInteger();
            QVERIFY(tets > 1000);
            const VolumeMesh m = readVolumeMesh(out.toStdString());
            QCOMPARE(qint64(m.countCells(CellType::Tet)), tets);
            QCOMPARE(qint64(m.countCells(CellType::Prism)), prisms);
            QCOMPARE(qint64(m.countCells(CellType::Pyramid)), pyramids);
            for (const Cell &c : m.cells)
                QVERIFY(signedVolume(m, c) > 0.0);
        }
    }

    void badOutputIsAUsageError()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA1.ml");
        QTemporaryDir dir;
        const QString out = dir.filePath("a1.stl");
        const CliRun run = runCli({"hybrid", path, "--sites", "100", "-o", out});
        QVERIFY(run.finished);
        QVERIFY(run.exitCode != 0);
        QVERIFY(run.err.contains(".vtu or .msh"));
        QVERIFY(!QFile::exists(out));
    }
};

QTEST_GUILESS_MAIN(TestCliHybrid)
#include "test_cli_hybrid.moc"
