// stratamesh-cli tetmesh as a user runs it: a good model meshes and exports; an intersecting model,
// a triangle on two surfaces, a time limit and a helper killed from outside all end with exit
// status 1, the outcome on stderr and in the report, and never with a crash of the CLI.
#include "../core/volume/tetgen_test_models.h"
#include "cli_runner.h"
#include "io/gocad_writer.h"
#include "io/model_reader.h"
#include "test_files.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <thread>

using namespace stratamesh;
using namespace stratamesh::test;

namespace {

// The pid of a child of `parent` named stratamesh-tetgen (comm is cut at 15 characters), or 0.
int helperChild(qint64 parent)
{
    for (const QString &entry : QDir("/proc").entryList(QDir::Dirs)) {
        bool isPid = false;
        const int pid = entry.toInt(&isPid);
        if (!isPid)
            continue;
        QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
        if (!stat.open(QIODevice::ReadOnly))
            continue;
        const QString text = QString::fromLatin1(stat.readAll());
        const int close = text.lastIndexOf(')');
        const QString comm = text.mid(text.indexOf('(') + 1, close - text.indexOf('(') - 1);
        const QStringList rest = text.mid(close + 2).split(' ');
        if (comm.startsWith("stratamesh-tet") && rest.size() > 1 && rest[1].toLongLong() == parent)
            return pid;
    }
    return 0;
}

} // namespace

class TestCliTetmesh : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

    QString writeModel(const Model &m, const QString &name)
    {
        const QString path = m_dir.filePath(name);
        writeGocadModel3d(m, path.toStdString());
        return path;
    }

private slots:
    void goodModelMeshesAndExports()
    {
        const QString model = writeModel(twoRegionBox(), "box.ml");
        const QString report = m_dir.filePath("box.json");
        const QString vtu = m_dir.filePath("box.vtu");
        const CliRun run = runCli({"tetmesh", model, "-o", vtu, "--report", report});
        QVERIFY2(run.finished && run.exitCode == 0, qPrintable(run.err));
        QVERIFY(QFile::exists(vtu));
        const QJsonObject r = readJson(report);
        QCOMPARE(r["outcome"].toString(), QStringLiteral("ok"));
        QVERIFY(r["tets"].toInt() > 100);
        QVERIFY(r["points"].toInt() > 0);
        QVERIFY(r["min_dihedral_deg"].toDouble() > 0);
        QVERIFY(r["max_dihedral_deg"].toDouble() < 180);
        QVERIFY(r["mean_radius_ratio"].toDouble() >= 1);
        QVERIFY(r.contains("slivers") && r.contains("time_s"));
        QCOMPARE(r["histograms"]["min_dihedral_deg"]["total"].toInt(), r["tets"].toInt());
        const QJsonArray regions = r["regions"].toArray();
        QCOMPARE(regions.size(), 2);
        for (const QJsonValue &v : regions) {
            const QJsonObject region = v.toObject();
            QVERIFY(region["tets"].toInt() > 0);
            const double brep = region["brep_volume"].toDouble();
            QVERIFY(std::abs(region["volume"].toDouble() - brep) <= 1e-6 * brep);
            QVERIFY(!region["name"].toString().isEmpty());
        }
        for (const char *ext : {"msh", "so"}) {
            const QString out = m_dir.filePath(QStringLiteral("box.%1").arg(ext));
            const CliRun again = runCli({"tetmesh", model, "-o", out, "--json"});
            QVERIFY2(again.exitCode == 0, qPrintable(again.err));
            QVERIFY(QFile::exists(out));
            QCOMPARE(QJsonDocument::fromJson(again.out.toUtf8()).object()["outcome"].toString(),
                     QStringLiteral("ok"));
        }
    }

    void intersectingSurfacesAreInvalidInput()
    {
        const QString model = writeModel(selfIntersectingBox(), "pierced.ml");
        QVERIFY(readModel(model.toStdString()).surfaces.size()
                == selfIntersectingBox().surfaces.size());
        const QString report = m_dir.filePath("pierced.json");
        const CliRun run = runCli({"tetmesh", model, "--report", report});
        QVERIFY(run.finished);
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.err.contains("invalid_input") && run.err.contains("piercer"),
                 qPrintable(run.err));
        const QJsonObject r = readJson(report);
        QCOMPARE(r["outcome"].toString(), QStringLiteral("invalid_input"));
        QVERIFY(r["surfaces"].toArray().contains(QStringLiteral("piercer")));
        QCOMPARE(r["tets"].toInt(), 0);
    }

    void triangleOnTwoSurfacesIsInvalidInput()
    {
        const QString model = writeModel(duplicatedTriangleBox(), "copy.ml");
        const CliRun run = runCli({"tetmesh", model, "--json"});
        QVERIFY(run.finished);
        QCOMPARE(run.exitCode, 1);
        const QJsonObject r = QJsonDocument::fromJson(run.out.toUtf8()).object();
        QCOMPARE(r["outcome"].toString(), QStringLiteral("invalid_input"));
        QVERIFY(r["surfaces"].toArray().contains(QStringLiteral("copy")));
        QVERIFY2(r["message"].toString().contains("two surfaces"),
                 qPrintable(r["message"].toString()));
    }

    void timeLimitIsTimedOut()
    {
        const QString model = writeModel(twoRegionBox(), "slow.ml");
        QElapsedTimer clock;
        clock.start();
        const CliRun run = runCli({"tetmesh", model, "--max-volume", "2", "--refine-surfaces",
                                   "--time-limit", "1", "--json"});
        QVERIFY(run.finished);
        QCOMPARE(run.exitCode, 1);
        QVERIFY(clock.elapsed() < 30000);
        QVERIFY2(run.err.contains("timed_out"), qPrintable(run.err));
        QCOMPARE(QJsonDocument::fromJson(run.out.toUtf8()).object()["outcome"].toString(),
                 QStringLiteral("timed_out"));
    }

    void killedHelperIsKilled()
    {
        const QString model = writeModel(twoRegionBox(), "killed.ml");
        QProcess cli;
        cli.start(QStringLiteral(STRATAMESH_CLI_PATH), {"tetmesh", model, "--max-volume", "2",
                                                        "--refine-surfaces", "--time-limit", "50"});
        QVERIFY(cli.waitForStarted(10000));
        int helper = 0;
        for (int i = 0; i < 1000 && helper == 0 && cli.state() == QProcess::Running; ++i) {
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
            helper = helperChild(cli.processId());
        }
        QVERIFY2(helper > 0, "the helper started");
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        QCOMPARE(::kill(helper, SIGKILL), 0);
        QVERIFY(cli.waitForFinished(30000));
        QCOMPARE(cli.exitStatus(), QProcess::NormalExit);
        QCOMPARE(cli.exitCode(), 1);
        const QString err = QString::fromUtf8(cli.readAllStandardError());
        QVERIFY2(err.contains("killed") && err.contains("SIGKILL"), qPrintable(err));
    }

    void badArgumentsAreUsageErrors()
    {
        QCOMPARE(runCli({"tetmesh"}).exitCode, 2);
        QCOMPARE(runCli({"tetmesh", "x.ml", "--quality", "-1"}).exitCode, 2);
        QCOMPARE(runCli({"tetmesh", "x.ml", "-o", "out.ml"}).exitCode, 2);
        const CliRun missing = runCli({"tetmesh", m_dir.filePath("missing.ml")});
        QCOMPARE(missing.exitCode, 1);
    }
};

QTEST_GUILESS_MAIN(TestCliTetmesh)
#include "test_cli_tetmesh.moc"
