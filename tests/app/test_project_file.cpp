// Project files without a window: a .smproj written and read back keeps every parameter, figure,
// review and the input's relative path; a ledger and a validity report read back as written; a
// newer schema, malformed JSON, a bad shown run and an unknown ledger kind are refused naming the
// file and the cause.
#include "common/error.h"
#include "json_report.h"
#include "json_report_read.h"
#include "project_file.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest>

using namespace stratamesh;

namespace {

QString errorOf(const std::function<void()> &f)
{
    try {
        f();
    } catch (const FileError &e) {
        return QString::fromStdString(e.what());
    }
    return QString();
}

} // namespace

class TestProjectFile : public QObject {
    Q_OBJECT
private slots:
    void roundTrip()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("a/study.smproj"));
        QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("a")));
        ProjectFile project;
        project.inputPath = dir.filePath(QStringLiteral("models/m.ml"));
        ProjectRun run;
        run.id = 2;
        run.folder = runFolderName(2);
        run.params.sites = 0;
        run.params.edgeLength = 12.5;
        run.params.dResolution = 3.0;
        run.params.adaptive = true;
        run.params.seed = 77;
        run.figures = {480, 300, 596, false, 0.75, 0.81, 9};
        run.review = QJsonObject{{QStringLiteral("records"),
                                  QJsonArray{QJsonObject{{QStringLiteral("record"), 4},
                                                         {QStringLiteral("verdict"), "flagged"}}}}};
        project.runs.push_back(run);
        project.shownRun = 0;
        const QJsonObject json = projectToJson(project, path);
        QCOMPARE(json.value("schema").toInt(), kProjectSchema);
        QCOMPARE(json.value("input").toObject().value("path").toString(),
                 QStringLiteral("../models/m.ml"));
        QCOMPARE(json.value("runs_folder").toString(), QStringLiteral("study_runs"));
        QCOMPARE(run.folder, QStringLiteral("run-002"));

        const ProjectFile back = projectFromJson(json, path);
        QCOMPARE(back.inputPath, project.inputPath);
        QCOMPARE(back.runs.size(), std::size_t(1));
        const ProjectRun &r = back.runs.front();
        QCOMPARE(r.id, 2);
        QCOMPARE(r.params.sites, 0);
        QCOMPARE(r.params.edgeLength, 12.5);
        QCOMPARE(r.params.dResolution, 3.0);
        QVERIFY(r.params.adaptive);
        QCOMPARE(r.params.seed, 77u);
        QCOMPARE(r.figures.triangles, qint64(596));
        QVERIFY(!r.figures.valid);
        QCOMPARE(r.figures.ledgerRecords, 9);
        QCOMPARE(reviewedCount(r.review), 1);
        QCOMPARE(back.shownRun, 0);
        QCOMPARE(projectRunsFolder(path), dir.filePath(QStringLiteral("a/study_runs")));
    }

    // Schema 1 wrote the default d_resolution as 0; from schema 2, 0 asks for no simplification
    // and the default is automatic.
    void oldDefaultDResolutionReadAsAutomatic()
    {
        const QString path = QStringLiteral("/tmp/x.smproj");
        auto dResolutionRead = [&](int schema, double written) {
            const QJsonObject run{{QStringLiteral("id"), 1},
                                  {QStringLiteral("folder"), runFolderName(1)},
                                  {QStringLiteral("parameters"),
                                   QJsonObject{{QStringLiteral("sites"), 500},
                                               {QStringLiteral("d_resolution"), written}}}};
            const QJsonObject json{
                {QStringLiteral("schema"), schema},
                {QStringLiteral("input"), QJsonObject{{QStringLiteral("path"), "m.ml"}}},
                {QStringLiteral("runs"), QJsonArray{run}}};
            return projectFromJson(json, path).runs.at(0).params.dResolution;
        };
        QCOMPARE(dResolutionRead(1, 0.0), kAutoDResolution);
        QCOMPARE(dResolutionRead(1, 2.5), 2.5);
        QCOMPARE(dResolutionRead(kProjectSchema, 0.0), 0.0);
        QCOMPARE(dResolutionRead(kProjectSchema, kAutoDResolution), kAutoDResolution);
        QCOMPARE(RemeshParams{}.dResolution, kAutoDResolution);
    }

    void refusals()
    {
        const QString path = QStringLiteral("/tmp/x.smproj");
        QString e = errorOf([&] {
            projectFromJson(QJsonObject{{QStringLiteral("schema"), 7}}, path);
        });
        QVERIFY2(e.contains("x.smproj") && e.contains("schema 7")
                     && e.contains(QStringLiteral("schema %1").arg(kProjectSchema)),
                 qPrintable(e));
        e = errorOf([&] { projectFromJson(QJsonObject{}, path); });
        QVERIFY2(e.contains("no schema"), qPrintable(e));
        e = errorOf([&] {
            projectFromJson(QJsonObject{{QStringLiteral("schema"), 1},
                                        {QStringLiteral("input"),
                                         QJsonObject{{QStringLiteral("path"), "m.ml"}}},
                                        {QStringLiteral("shown_run"), 3}},
                            path);
        });
        QVERIFY2(e.contains("shown_run 3"), qPrintable(e));
        QTemporaryDir dir;
        const QString broken = dir.filePath(QStringLiteral("broken.smproj"));
        QFile file(broken);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("{\"schema\": 1,");
        file.close();
        e = errorOf([&] { readProjectFile(broken); });
        QVERIFY2(e.contains("broken.smproj") && e.contains("not valid JSON"), qPrintable(e));
    }

    void ledgerAndValidityReadBack()
    {
        SimplificationLedger ledger(2);
        ledger[0].kind = LedgerKind::CloseFeatureMerge;
        ledger[0].inputs = {{EntityKind::Surface, 3, "fault_1"}, {EntityKind::Line, 1, "l1"}};
        ledger[0].outputs = {{EntityKind::Vertex, 17, ""}};
        ledger[0].position = Vec3(1.5, -2.0, 3.25);
        ledger[0].size = 0.4;
        ledger[0].sizeMeaning = "distance";
        ledger[0].note = "merged";
        ledger[1].kind = LedgerKind::LineLost;
        ledger[1].cause = 0;
        const SimplificationLedger back = ledgerFromJson(toJson(ledger), QStringLiteral("l.json"));
        QCOMPARE(back.size(), std::size_t(2));
        QCOMPARE(back[0].kind, LedgerKind::CloseFeatureMerge);
        QCOMPARE(back[0].inputs.size(), std::size_t(2));
        QCOMPARE(back[0].inputs[1].kind, EntityKind::Line);
        QCOMPARE(back[0].inputs[0].name, std::string("fault_1"));
        QCOMPARE(back[0].outputs[0].id, 17);
        QCOMPARE(back[0].position, ledger[0].position);
        QCOMPARE(back[0].size, 0.4);
        QCOMPARE(back[0].sizeMeaning, std::string("distance"));
        QCOMPARE(back[1].kind, LedgerKind::LineLost);
        QCOMPARE(back[1].cause, 0);

        QJsonArray bad = toJson(ledger);
        QJsonObject record = bad[0].toObject();
        record.insert(QStringLiteral("kind"), QStringLiteral("teleport"));
        bad[0] = record;
        const QString e = errorOf([&] { ledgerFromJson(bad, QStringLiteral("l.json")); });
        QVERIFY2(e.contains("l.json") && e.contains("teleport"), qPrintable(e));

        ValidityReport report;
        report.valid = false;
        report.problems.push_back({"intersection", {"h1", "h2"}, Vec3(1, 2, 3), "crossing", {}});
        report.counts["intersection"] = 5;
        const ValidityReport v = validityFromJson(toJson(report), QStringLiteral("r.json"));
        QVERIFY(!v.valid);
        QCOMPARE(v.problems.size(), std::size_t(1));
        QCOMPARE(v.problems[0].entities.size(), std::size_t(2));
        QCOMPARE(v.problems[0].message, std::string("crossing"));
        QCOMPARE(v.count("intersection"), std::size_t(5));
    }
};

QTEST_GUILESS_MAIN(TestProjectFile)
#include "test_project_file.moc"
