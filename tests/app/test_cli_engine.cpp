// The engine's batch commands as a script would run them — `cvt`, `remesh` and `complexity` —
// on the real models: the JSON fields the issues name, values that follow from the thesis
// (Table 3.3 variation, energies going down), outputs that read back valid, and clear refusals.
#include "cli_runner.h"
#include "support/test_data.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using stratamesh::test::CliRun;
using stratamesh::test::runCli;

namespace {

QJsonObject parseObject(const QByteArray &text)
{
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(text, &error);
    if (error.error != QJsonParseError::NoError || !doc.isObject())
        return {};
    return doc.object();
}

QJsonObject runJson(const QStringList &arguments)
{
    const CliRun r = runCli(arguments);
    if (!r.finished || r.exitCode != 0) {
        qWarning("%s", qPrintable(r.err));
        return {};
    }
    return parseObject(r.out.toUtf8());
}

} // namespace

class TestCliEngine : public QObject {
    Q_OBJECT
private slots:
    void cvtReportsAndWritesSites()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA2.ml");
        QTemporaryDir dir;
        const QString xyz = dir.filePath(QStringLiteral("sites.xyz"));
        const QJsonObject r = runJson(
            {QStringLiteral("cvt"), path, QStringLiteral("--sites"), QStringLiteral("500"),
             QStringLiteral("--iterations"), QStringLiteral("15"), QStringLiteral("--seed"),
             QStringLiteral("3"), QStringLiteral("--json"), QStringLiteral("--sites-out"), xyz});
        QVERIFY(!r.isEmpty());
        QCOMPARE(r[QStringLiteral("sites")].toInt(), 500);
        QCOMPARE(r[QStringLiteral("iterations")].toInt(), 15);
        const QJsonArray energy = r[QStringLiteral("energy")].toArray();
        QCOMPARE(energy.size(), 15);
        QCOMPARE(r[QStringLiteral("gradient_norm")].toArray().size(), 15);
        // L-BFGS with a line search never accepts a step that raises the energy.
        QVERIFY(energy.first().toDouble() < r[QStringLiteral("initial_energy")].toDouble());
        for (int i = 1; i < energy.size(); ++i)
            QVERIFY2(energy[i].toDouble() <= energy[i - 1].toDouble(),
                     qPrintable(QString::number(i)));
        const QJsonObject rdt = r[QStringLiteral("rdt")].toObject();
        QVERIFY(rdt[QStringLiteral("triangles")].toInt()
                > 500); // about twice the sites on surfaces
        QVERIFY(rdt[QStringLiteral("mean_quality")].toDouble() > 0.5);
        QVERIFY(rdt[QStringLiteral("mean_quality")].toDouble() <= 1.0);
        const QJsonObject timings = r[QStringLiteral("timings")].toObject();
        for (const char *key : {"total_s", "rvd_s", "delaunay_s"})
            QVERIFY2(timings[QLatin1String(key)].toDouble(-1) >= 0, key);
        QVERIFY(timings[QStringLiteral("threads")].toInt() >= 1);
        QVERIFY(r[QStringLiteral("peak_rss_mb")].toDouble() > 0);

        QFile file(xyz);
        QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
        int lines = 0;
        while (!file.atEnd()) {
            const QList<QByteArray> parts = file.readLine().simplified().split(' ');
            QCOMPARE(parts.size(), 3);
            for (const QByteArray &p : parts) {
                bool ok = false;
                QVERIFY(std::isfinite(p.toDouble(&ok)) && ok);
            }
            ++lines;
        }
        QCOMPARE(lines, 500);
    }

    void cvtRefusesBadSites()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA1.ml");
        const CliRun r =
            runCli({QStringLiteral("cvt"), path, QStringLiteral("--sites"), QStringLiteral("-4")});
        QVERIFY(r.finished);
        QVERIFY(r.exitCode != 0);
        QVERIFY2(r.err.contains(QStringLiteral("--sites")), qPrintable(r.err));
    }

    void remeshWritesValidModelAndReport()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA1.ml");
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("remeshed.ml"));
        const QString report = dir.filePath(QStringLiteral("report.json"));
        const CliRun r =
            runCli({QStringLiteral("remesh"), path, QStringLiteral("--sites"),
                    QStringLiteral("1000"), QStringLiteral("--iterations"), QStringLiteral("30"),
                    QStringLiteral("-o"), out, QStringLiteral("--report"), report});
        QVERIFY2(r.finished && r.exitCode == 0, qPrintable(r.err));
        QFile reportFile(report);
        QVERIFY(reportFile.open(QIODevice::ReadOnly));
        const QJsonObject rep = parseObject(reportFile.readAll());
        QVERIFY(!rep.isEmpty());
        for (const char *side : {"input", "output"}) {
            const QJsonObject o = rep[QLatin1String(side)].toObject();
            QVERIFY2(o.contains(QStringLiteral("counts")) && o.contains(QStringLiteral("mesh")),
                     side);
            QVERIFY2(o[QStringLiteral("validity")][QStringLiteral("valid")].toBool(), side);
        }
        // Regions are what a simulator meshes: none may be lost.
        QCOMPARE(rep[QStringLiteral("output")][QStringLiteral("counts")]
                    [QStringLiteral("without_box")][QStringLiteral("regions")]
                        .toInt(),
                 4);
        const double hausdorff = rep[QStringLiteral("hausdorff_pct_bbox")].toDouble(-1);
        QVERIFY(hausdorff > 0 && hausdorff < 2.0);
        QCOMPARE(rep[QStringLiteral("energy")].toArray().size(), 30);
        QVERIFY(rep[QStringLiteral("histograms")].toObject().contains(QStringLiteral("quality")));
        for (const char *key : {"sampling_s", "mesh_s", "total_s"})
            QVERIFY2(rep[QStringLiteral("timings")][QLatin1String(key)].toDouble(-1) >= 0, key);
        for (const QJsonValue &record : rep[QStringLiteral("ledger")].toArray())
            QVERIFY(!record[QStringLiteral("kind")].toString().isEmpty());

        // What was written is what the report describes, and reads back valid.
        const QJsonObject info = runJson({QStringLiteral("info"), out, QStringLiteral("--json")});
        QVERIFY(!info.isEmpty());
        QVERIFY(info[QStringLiteral("validity")][QStringLiteral("valid")].toBool());
        QCOMPARE(info[QStringLiteral("counts")],
                 rep[QStringLiteral("output")][QStringLiteral("counts")]);
    }

    // Without refinement the modelA5 remesh at 1000 sites (seed 1) folds two surfaces over each
    // other at a low-angle contact, so TetGen would fill the space between them with the wrong
    // region: the CLI must not write it unless asked to.
    void remeshRefusesToWriteAnInvalidResult()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA5.ml");
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("remeshed.ml"));
        const QString report = dir.filePath(QStringLiteral("report.json"));
        const QStringList base{QStringLiteral("remesh"),
                               path,
                               QStringLiteral("--sites"),
                               QStringLiteral("1000"),
                               QStringLiteral("--seed"),
                               QStringLiteral("1"),
                               QStringLiteral("--refinement-rounds"),
                               QStringLiteral("0"),
                               QStringLiteral("-o"),
                               out,
                               QStringLiteral("--report"),
                               report};
        const CliRun refused = runCli(base);
        QVERIFY(refused.finished);
        QCOMPARE(refused.exitCode, 1);
        QVERIFY(!QFile::exists(out));
        QVERIFY(!QFile::exists(report));
        QVERIFY2(refused.err.contains(QStringLiteral("not valid"))
                     && refused.err.contains(QStringLiteral("folded_contact")),
                 qPrintable(refused.err));

        const CliRun allowed = runCli(base + QStringList{QStringLiteral("--allow-invalid")});
        QVERIFY2(allowed.finished && allowed.exitCode == 0, qPrintable(allowed.err));
        QVERIFY(QFile::exists(out));
        QFile reportFile(report);
        QVERIFY(reportFile.open(QIODevice::ReadOnly));
        const QJsonObject rep = parseObject(reportFile.readAll());
        QVERIFY(!rep[QStringLiteral("output")][QStringLiteral("validity")][QStringLiteral("valid")]
                     .toBool());
        QCOMPARE(rep[QStringLiteral("refinement")][QStringLiteral("rounds")].toInt(), 0);

        // With refinement (the default) the same run is valid and says how many sites it added.
        const CliRun refined =
            runCli({QStringLiteral("remesh"), path, QStringLiteral("--sites"),
                    QStringLiteral("1000"), QStringLiteral("--seed"), QStringLiteral("1"),
                    QStringLiteral("-o"), out, QStringLiteral("--report"), report});
        QVERIFY2(refined.finished && refined.exitCode == 0, qPrintable(refined.err));
        reportFile.close();
        QVERIFY(reportFile.open(QIODevice::ReadOnly));
        const QJsonObject again = parseObject(reportFile.readAll());
        QVERIFY(again[QStringLiteral("output")][QStringLiteral("validity")][QStringLiteral("valid")]
                    .toBool());
        const QJsonObject refinement = again[QStringLiteral("refinement")].toObject();
        QCOMPARE(refinement[QStringLiteral("initial_sites")].toInt(), 1000);
        QVERIFY(refinement[QStringLiteral("final_sites")].toInt() > 1000);
        QVERIFY(refinement[QStringLiteral("pockets_opened")].toInt(-1) >= 0);
        // The default d_resolution is automatic: nothing merged, strips under 0.4 edge lengths.
        const QJsonObject simplified = again[QStringLiteral("simplification")].toObject();
        QVERIFY(simplified[QStringLiteral("automatic")].toBool());
        QCOMPARE(simplified[QStringLiteral("merge_distance")].toDouble(-1), 0.0);
        const double edge = simplified[QStringLiteral("edge_length")].toDouble();
        QVERIFY(edge > 0.0);
        QVERIFY(qAbs(simplified[QStringLiteral("strip_width_limit")].toDouble() - 0.4 * edge)
                < 1e-9 * edge);
        QVERIFY(simplified.contains(QStringLiteral("pin_features")));
        QVERIFY(!simplified[QStringLiteral("pin_features")].toBool(true)); // only with D = 0
        // Sites were added, so a round ran; the kept one is among those run.
        const int run = refinement[QStringLiteral("rounds_run")].toInt(-1);
        QVERIFY(run >= 1);
        QVERIFY(refinement[QStringLiteral("rounds")].toInt(-1) <= run);
        const QJsonObject edits = again[QStringLiteral("topology_edits")].toObject();
        int sum = 0;
        for (const char *k :
             {"surfaces_lost", "surfaces_created", "lines_lost", "lines_created", "corners_lost",
              "corners_created", "surface_parts_lost", "surface_parts_created"})
            sum += edits[QLatin1String(k)].toInt(-1000);
        QCOMPARE(edits[QStringLiteral("total")].toInt(), sum);
        // The ledger adds up: input - lost + created = output for surfaces, lines and corners.
        const QJsonObject balance = again[QStringLiteral("ledger_balance")].toObject();
        QVERIFY(balance[QStringLiteral("balanced")].toBool());
        for (const char *k : {"surfaces", "lines", "corners"}) {
            const QJsonObject e = balance[QLatin1String(k)].toObject();
            QCOMPARE(e[QStringLiteral("input")].toInt() - e[QStringLiteral("lost")].toInt()
                         + e[QStringLiteral("created")].toInt(),
                     e[QStringLiteral("output")].toInt());
            QCOMPARE(e[QStringLiteral("output")].toInt(),
                     again[QStringLiteral("output")][QStringLiteral("counts")]
                          [QStringLiteral("all")][QLatin1String(k)]
                              .toInt());
        }
    }

    void remeshRefusesUnknownOutputFormat()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA1.ml");
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("remeshed.xyz"));
        const CliRun r = runCli({QStringLiteral("remesh"), path, QStringLiteral("--sites"),
                                 QStringLiteral("100"), QStringLiteral("-o"), out,
                                 QStringLiteral("--report"), dir.filePath("r.json")});
        QVERIFY(r.finished);
        QVERIFY(r.exitCode != 0);
        QVERIFY(!QFile::exists(out));
        QVERIFY2(!r.err.isEmpty(), "no message");
    }

    void complexityTablesAndCells()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA1.ml");
        QTemporaryDir dir;
        const QString vtu = dir.filePath(QStringLiteral("cells.vtu"));
        const QJsonObject r = runJson(
            {QStringLiteral("complexity"), path, QStringLiteral("--cells"), QStringLiteral("100"),
             QStringLiteral("--json"), QStringLiteral("--cells-vtk"), vtu});
        QVERIFY(!r.isEmpty());
        const QJsonObject global = r[QStringLiteral("global")].toObject();
        // Thesis Table 3.1 and 3.3 for modelA1.
        QCOMPARE(global[QStringLiteral("counts")][QStringLiteral("regions")].toInt(), 4);
        QCOMPARE(global[QStringLiteral("counts")][QStringLiteral("surfaces")].toInt(), 3);
        QVERIFY(std::abs(global[QStringLiteral("variation")][QStringLiteral("regions")].toDouble()
                         - 0.74)
                < 0.005);
        QVERIFY(std::abs(global[QStringLiteral("variation")][QStringLiteral("surfaces")].toDouble())
                < 0.005);
        for (const char *key : {"regions", "surfaces", "lines", "total"})
            QVERIFY2(global[QStringLiteral("geometric")][QLatin1String(key)].toDouble(-1) >= 0,
                     key);
        const QJsonArray local = r[QStringLiteral("local")].toArray();
        QCOMPARE(local.size(), 1);
        const QJsonObject cells = local[0].toObject();
        QCOMPARE(cells[QStringLiteral("cells")].toInt(), 100);
        const int q10 = cells[QStringLiteral("q10")].toInt(),
                  q50 = cells[QStringLiteral("q50")].toInt();
        const int q90 = cells[QStringLiteral("q90")].toInt(),
                  max = cells[QStringLiteral("max")].toInt();
        QVERIFY(1 <= q10 && q10 <= q50 && q50 <= q90 && q90 <= max);
        QVERIFY(r.contains(QStringLiteral("timings")));
        QFile file(vtu);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray head = file.read(4096);
        QVERIFY(head.contains("UnstructuredGrid"));
    }

    void complexityRefusesBadCells()
    {
        STRATAMESH_REQUIRE_DATA(path, "modelA1.ml");
        const CliRun r = runCli({QStringLiteral("complexity"), path, QStringLiteral("--cells"),
                                 QStringLiteral("10,x"), QStringLiteral("--json")});
        QVERIFY(r.finished);
        QVERIFY(r.exitCode != 0);
        QVERIFY2(r.err.contains(QStringLiteral("--cells")), qPrintable(r.err));
    }

    void missingModelIsNamed()
    {
        const QString missing = QStringLiteral("/nonexistent/model.ml");
        for (const QStringList &arguments :
             {QStringList{QStringLiteral("cvt"), missing, QStringLiteral("--sites"),
                          QStringLiteral("10")},
              QStringList{QStringLiteral("complexity"), missing, QStringLiteral("--cells"),
                          QStringLiteral("10")}}) {
            const CliRun r = runCli(arguments);
            QVERIFY(r.finished);
            QVERIFY(r.exitCode != 0);
            QVERIFY2(r.err.contains(QStringLiteral("/nonexistent/model.ml")), qPrintable(r.err));
        }
    }
};

QTEST_GUILESS_MAIN(TestCliEngine)
#include "test_cli_engine.moc"
