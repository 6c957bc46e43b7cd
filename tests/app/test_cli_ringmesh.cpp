// stratamesh-cli on RINGMesh GeoModels: info reads .gm like .ml, convert writes .gm and reads it
// back with the same counts and volumes, a volume-meshed .gm converts with its tets, and a broken
// archive exits 1 with the archive and entry on stderr; convert notes what a format drops.
#include "cli_runner.h"
#include "io/zip_archive.h"
#include "support/test_data.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using stratamesh::test::CliRun;
using stratamesh::test::runCli;

namespace {

QJsonObject jsonOf(const CliRun &r)
{
    return QJsonDocument::fromJson(r.out.toUtf8()).object();
}

} // namespace

class TestCliRingMesh : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void infoOnAllVersions_data()
    {
        QTest::addColumn<QString>("file");
        QTest::newRow("version 0") << "modelA1_version0.gm";
        QTest::newRow("version 1") << "modelA1_version1.gm";
        QTest::newRow("version 2") << "modelA1_version2.gm";
    }

    void infoOnAllVersions()
    {
        QFETCH(QString, file);
        STRATAMESH_REQUIRE_DATA(path, file);
        const CliRun r = runCli({"info", path, "--json"});
        QVERIFY2(r.finished && r.exitCode == 0, qPrintable(r.err));
        const QJsonObject report = jsonOf(r);
        const QJsonObject noBox = report["counts"].toObject()["without_box"].toObject();
        QCOMPARE(noBox["regions"].toInt(), 4);
        QCOMPARE(noBox["surfaces"].toInt(), 3);
        QCOMPARE(noBox["lines"].toInt(), 0);
        QCOMPARE(noBox["corners"].toInt(), 0);
        QCOMPARE(report["mesh"].toObject()["triangles"].toInt(), 7932);
        QVERIFY(report["validity"].toObject()["valid"].toBool());
    }

    void convertToGmAndBack()
    {
        STRATAMESH_REQUIRE_DATA(ml, "modelA1.ml");
        const QString gm = m_dir.filePath("modelA1.gm");
        const CliRun w = runCli({"convert", ml, gm});
        QVERIFY2(w.finished && w.exitCode == 0, qPrintable(w.err));
        QVERIFY2(w.out.contains("RINGMesh GeoModel"), qPrintable(w.out));
        const CliRun a = runCli({"info", ml, "--json"});
        const CliRun b = runCli({"info", gm, "--json"});
        QVERIFY2(b.finished && b.exitCode == 0, qPrintable(b.err));
        QCOMPARE(jsonOf(b)["counts"].toObject(), jsonOf(a)["counts"].toObject());
        QCOMPARE(jsonOf(b)["regions"].toArray(), jsonOf(a)["regions"].toArray());
        // And on to Gocad again.
        const QString back = m_dir.filePath("back.ml");
        const CliRun c = runCli({"convert", gm, back});
        QVERIFY2(c.finished && c.exitCode == 0, qPrintable(c.err));
        QCOMPARE(jsonOf(runCli({"info", back, "--json"}))["regions"].toArray(),
                 jsonOf(a)["regions"].toArray());
    }

    // convert says what the output's format does not keep, in the words of the format table.
    void convertNotesWhatTheFormatDrops()
    {
        STRATAMESH_REQUIRE_DATA(ml, "modelA1.ml");
        const CliRun msh = runCli({"convert", ml, m_dir.filePath("drops.msh"), "--json"});
        QVERIFY2(msh.finished && msh.exitCode == 0, qPrintable(msh.err));
        QCOMPARE(jsonOf(msh)["format_drops"].toArray(), QJsonArray({"feature types"}));
        const CliRun gm = runCli({"convert", ml, m_dir.filePath("drops.gm"), "--json"});
        QCOMPARE(jsonOf(gm)["format_drops"].toArray(), QJsonArray());
        const CliRun ts = runCli({"convert", ml, m_dir.filePath("drops.ts")});
        QVERIFY2(ts.out.contains("note: Gocad TSurf does not keep: regions\n"), qPrintable(ts.out));
    }

    void volumeMeshedKeepsTets()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA1_volume_meshed.gm");
        const QString vtu = m_dir.filePath("tets.vtu");
        const CliRun r = runCli({"convert", path, vtu, "--json"});
        QVERIFY2(r.finished && r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(jsonOf(r)["counts"].toObject()["cells"].toInt(), 13510);
        const QString gm = m_dir.filePath("tets.gm");
        const CliRun g = runCli({"convert", vtu, gm, "--json"});
        QVERIFY2(g.finished && g.exitCode == 0, qPrintable(g.err));
        const CliRun back = runCli({"convert", gm, m_dir.filePath("again.vtu"), "--json"});
        QCOMPARE(jsonOf(back)["counts"].toObject()["cells"].toInt(), 13510);
    }

    // The acceptance check: remeshing the .gm gives what remeshing the .ml gives.
    void remeshMatchesGocad()
    {
        STRATAMESH_REQUIRE_DATA(gm, "modelA1_version2.gm");
        STRATAMESH_REQUIRE_DATA(ml, "modelA1.ml");
        QJsonObject outputs[2];
        const QString inputs[2] = {gm, ml};
        for (int i = 0; i < 2; ++i) {
            const QString report = m_dir.filePath(QString("remesh%1.json").arg(i));
            const CliRun r =
                runCli({"remesh", inputs[i], "--sites", "1000", "-o",
                        m_dir.filePath(QString("remesh%1.ml").arg(i)), "--report", report});
            QVERIFY2(r.finished && r.exitCode == 0, qPrintable(r.err));
            QFile f(report);
            QVERIFY(f.open(QIODevice::ReadOnly));
            outputs[i] = QJsonDocument::fromJson(f.readAll()).object()["output"].toObject();
        }
        QVERIFY(outputs[0]["validity"].toObject()["valid"].toBool());
        QCOMPARE(outputs[0]["counts"].toObject(), outputs[1]["counts"].toObject());
        const QJsonObject a = outputs[0]["mesh"].toObject(), b = outputs[1]["mesh"].toObject();
        for (const char *key :
             {"mean_quality", "min_angle_deg", "pct_triangles_angle_below_30", "triangles"}) {
            const double x = a[key].toDouble(), y = b[key].toDouble();
            qInfo("%s: .gm %g, .ml %g", key, x, y);
            QVERIFY2(std::abs(x - y) <= 0.02 * std::abs(y), key);
        }
    }

    // A GeoModel whose stated lines disagree with its surfaces is reported invalid, named.
    void infoNamesFileTopologyMismatch()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA1_version2.gm");
        const QString damaged = m_dir.filePath("damaged.gm");
        {
            const stratamesh::ZipReader in(path.toStdString());
            stratamesh::ZipWriter out(damaged.toStdString());
            for (const std::string &name : in.names()) {
                std::string bytes = in.read(name);
                if (name == "mesh_entities.txt") {
                    const std::string from = "\nboundary 0 1 2 7 \n"; // Surface 0 forgets Line 7
                    QVERIFY(bytes.find(from) != std::string::npos);
                    bytes.replace(bytes.find(from), from.size(), "\nboundary 0 1 2 \n");
                }
                out.add(name, bytes);
            }
            out.close();
        }
        const CliRun r = runCli({"info", damaged, "--json"});
        QVERIFY2(r.finished && r.exitCode == 0, qPrintable(r.err));
        const QJsonObject validity = jsonOf(r)["validity"].toObject();
        QVERIFY(!validity["valid"].toBool());
        QCOMPARE(validity["counts"].toObject()["file_topology"].toInt(), 1);
        const QJsonObject problem = validity["problems"].toArray().first().toObject();
        QCOMPARE(problem["check"].toString(), QString("file_topology"));
        QVERIFY2(problem["message"].toString().startsWith("Line 7 ("),
                 qPrintable(problem["message"].toString()));
    }

    void brokenArchive()
    {
        const QString path = m_dir.filePath("broken.gm");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QByteArray(4096, 'x'));
        f.close();
        const CliRun r = runCli({"info", path});
        QVERIFY(r.finished);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(path) && r.err.contains("zip"), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliRingMesh)
#include "test_cli_ringmesh.moc"
