// stratamesh-cli project: a project file's runs as JSON (parameters, sizes, validity, review
// progress), read from the .smproj only; a newer schema, malformed JSON and a missing file are
// refused with exit status 1 and a message naming the file and the cause.
#include "cli_runner.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using stratamesh::test::runCli;

namespace {

void writeFile(const QString &path, const QByteArray &bytes)
{
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(bytes);
}

QJsonObject run(int id, int sites, int triangles, bool valid, const QJsonArray &review)
{
    return QJsonObject{
        {QStringLiteral("id"), id},
        {QStringLiteral("folder"), QStringLiteral("run-%1").arg(id, 3, 10, QLatin1Char('0'))},
        {QStringLiteral("parameters"),
         QJsonObject{{QStringLiteral("sites"), sites}, {QStringLiteral("iterations"), 20}}},
        {QStringLiteral("figures"), QJsonObject{{QStringLiteral("sites"), sites + 3},
                                                {QStringLiteral("vertices"), triangles / 2},
                                                {QStringLiteral("triangles"), triangles},
                                                {QStringLiteral("valid"), valid},
                                                {QStringLiteral("hausdorff_pct_bbox"), 1.5},
                                                {QStringLiteral("mean_quality"), 0.8},
                                                {QStringLiteral("ledger_records"), 4}}},
        {QStringLiteral("review"), QJsonObject{{QStringLiteral("records"), review}}}};
}

} // namespace

class TestCliProject : public QObject {
    Q_OBJECT
private slots:
    void listsRunsAndReviewProgress()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        writeFile(dir.filePath(QStringLiteral("model.ml")), "GOCAD Model3d 1\n");
        QDir(dir.path()).mkpath(QStringLiteral("study_runs/run-001"));
        const QJsonArray review{
            QJsonObject{{QStringLiteral("record"), 0}, {QStringLiteral("verdict"), "accepted"}},
            QJsonObject{{QStringLiteral("record"), 2}, {QStringLiteral("verdict"), "flagged"}},
            QJsonObject{{QStringLiteral("record"), 3},
                        {QStringLiteral("verdict"), "open"},
                        {QStringLiteral("note"), "look again"}}};
        const QJsonObject project{
            {QStringLiteral("schema"), 1},
            {QStringLiteral("input"), QJsonObject{{QStringLiteral("path"), "model.ml"}}},
            {QStringLiteral("runs"),
             QJsonArray{run(1, 150, 400, true, review), run(2, 300, 800, false, {})}},
            {QStringLiteral("shown_run"), 1}};
        const QString path = dir.filePath(QStringLiteral("study.smproj"));
        writeFile(path, QJsonDocument(project).toJson());

        const auto result = runCli({QStringLiteral("project"), path});
        QVERIFY2(result.finished && result.exitCode == 0, qPrintable(result.err));
        const QJsonObject out = QJsonDocument::fromJson(result.out.toUtf8()).object();
        QCOMPARE(out.value("schema").toInt(), 2); // what this version reads the file as
        QCOMPARE(out.value("shown_run").toInt(), 2);
        QVERIFY(out.value("input").toObject().value("found").toBool());
        const QJsonArray runs = out.value("runs").toArray();
        QCOMPARE(runs.size(), 2);
        const QJsonObject first = runs[0].toObject();
        QCOMPARE(first.value("id").toInt(), 1);
        QCOMPARE(first.value("sites").toInt(), 153);
        QCOMPARE(first.value("triangles").toInt(), 400);
        QCOMPARE(first.value("vertices").toInt(), 200);
        QVERIFY(first.value("valid").toBool());
        QVERIFY(first.value("folder_found").toBool());
        // The complete parameters: the ones given and the table's defaults for the others.
        QCOMPARE(first.value("parameters").toObject().value("sites").toInt(), 150);
        QVERIFY(first.value("parameters").toObject().contains("d_resolution"));
        // A note alone is not a review.
        QCOMPARE(first.value("review").toObject().value("reviewed").toInt(), 2);
        QCOMPARE(first.value("review").toObject().value("total").toInt(), 4);
        const QJsonObject second = runs[1].toObject();
        QVERIFY(!second.value("valid").toBool());
        QVERIFY(!second.value("folder_found").toBool());
        QCOMPARE(second.value("review").toObject().value("reviewed").toInt(), 0);
    }

    void refusesANewerSchema()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("future.smproj"));
        writeFile(path, R"({"schema": 99, "input": {"path": "m.ml"}, "runs": []})");
        const auto result = runCli({QStringLiteral("project"), path});
        QVERIFY(result.finished);
        QCOMPARE(result.exitCode, 1);
        QVERIFY2(result.err.contains(QStringLiteral("future.smproj")), qPrintable(result.err));
        QVERIFY2(result.err.contains(QStringLiteral("schema 99")), qPrintable(result.err));
        QVERIFY2(result.err.contains(QStringLiteral("schema 2")), qPrintable(result.err));
    }

    void refusesMalformedJson()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("broken.smproj"));
        writeFile(path, R"({"schema": 1, "runs": [)");
        const auto result = runCli({QStringLiteral("project"), path});
        QVERIFY(result.finished);
        QCOMPARE(result.exitCode, 1);
        QVERIFY2(result.err.contains(QStringLiteral("broken.smproj")), qPrintable(result.err));
        QVERIFY2(result.err.contains(QStringLiteral("not valid JSON")), qPrintable(result.err));
    }

    void refusesAMissingFile()
    {
        const auto result =
            runCli({QStringLiteral("project"), QStringLiteral("/nowhere/x.smproj")});
        QVERIFY(result.finished);
        QCOMPARE(result.exitCode, 1);
        QVERIFY2(result.err.contains(QStringLiteral("x.smproj")), qPrintable(result.err));
    }
};

QTEST_GUILESS_MAIN(TestCliProject)
#include "test_cli_project.moc"
