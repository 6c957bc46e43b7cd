// stratamesh-cli study: the plan, clear errors for bad study files, a local run that records a
// broken model's failure while the other tasks finish, and resumption after a fix or a kill.
#include "cli_runner.h"
#include "test_files.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QThread>
#include <QtTest>

#include <csignal>

using namespace stratamesh::test;

namespace {

// Task folders that hold a status.json, by folder name → finished_at.
QMap<QString, QString> finishedTasks(const QString &output)
{
    QMap<QString, QString> done;
    for (const QString &folder : QDir(output).entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        const QJsonObject s = readJson(QDir(output).filePath(folder + "/status.json"));
        if (!s.isEmpty())
            done.insert(folder, s.value("finished_at").toString());
    }
    return done;
}

} // namespace

class TestCliStudy : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // A small layered box: a task (remesh + tetmesh) takes about a second.
        const CliRun made = runCli({"synthetic", "layered", "--horizons", "2", "--edge-length",
                                    "80", "-o", m_dir.filePath("layers.ml")});
        QVERIFY2(made.exitCode == 0, qPrintable(made.err));
    }

    void planListsEveryModelAndGridPoint()
    {
        QFile::copy(m_dir.filePath("layers.ml"), m_dir.filePath("plan_a.ml"));
        QFile::copy(m_dir.filePath("layers.ml"), m_dir.filePath("plan_b.ml"));
        const QString study = m_dir.filePath("plan.smstudy");
        writeText(study, R"({"schema_version": 1, "models": ["plan_*.ml"],
            "steps": ["tetmesh", "remesh"],
            "grid": {"remesh": {"sites": [100, 150, 200], "seed": [1, 2]},
                     "tetmesh": {"quality": [1.414]}},
            "output": "plan_out"})");
        const CliRun run = runCli({"study", study, "--plan"});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        const QJsonObject plan = QJsonDocument::fromJson(run.out.toUtf8()).object();
        QCOMPARE(plan.value("steps").toArray(), (QJsonArray{"remesh", "tetmesh"}));
        const QJsonArray tasks = plan.value("tasks").toArray();
        QCOMPARE(tasks.size(), 2 * 3 * 2);
        QSet<QString> folders;
        QSet<QString> points;
        for (int i = 0; i < tasks.size(); ++i) {
            const QJsonObject t = tasks[i].toObject();
            QCOMPARE(t.value("id").toInt(), i);
            folders.insert(t.value("folder").toString());
            const QJsonObject remesh = t.value("parameters").toObject().value("remesh").toObject();
            points.insert(t.value("model").toString() + "|"
                          + QString::number(remesh.value("sites").toInt()) + "|"
                          + QString::number(remesh.value("seed").toInt()));
        }
        QCOMPARE(folders.size(), tasks.size());
        QCOMPARE(points.size(), tasks.size());
        QVERIFY(tasks[0].toObject().value("model").toString().endsWith("plan_a.ml"));
        QVERIFY(tasks[6].toObject().value("model").toString().endsWith("plan_b.ml"));
        // The plan is the same every time: the task number is the Slurm array index.
        QCOMPARE(runCli({"study", study, "--plan"}).out, run.out);
    }

    void badStudiesNameFileLineAndCause_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("expected");
        const QByteArray ok = R"("models": ["layers.ml"], "steps": ["remesh"], "output": "o")";
        QTest::newRow("not json") << QByteArray("{\"schema_version\": 1,\n\"models\": [,\n")
                                  << "bad.smstudy:2:";
        QTest::newRow("newer schema") << "{\"schema_version\": 7, " + ok + "}"
                                      << "newer StrataMesh";
        QTest::newRow("unknown key") << "{\"schema_version\": 1, \"modles\": 1, " + ok + "}"
                                     << "unknown key 'modles'";
        QTest::newRow("unknown step")
            << QByteArray(R"({"schema_version": 1, "models": ["layers.ml"], "steps": ["mesh"],
                "output": "o"})")
            << "unknown step 'mesh'";
        QTest::newRow("option the step lacks")
            << "{\"schema_version\": 1, \"grid\": {\"remesh\": {\"sitez\": [1]}}, " + ok + "}"
            << "stratamesh-cli remesh has no option --sitez";
        QTest::newRow("option the study sets")
            << "{\"schema_version\": 1, \"grid\": {\"remesh\": {\"o\": [\"x.ml\"]}}, " + ok + "}"
            << "the study sets --o itself";
        QTest::newRow("value out of range")
            << "{\"schema_version\": 1, \"grid\": {\"remesh\": {\"sites\": [100, 2]}}, " + ok + "}"
            << "grid.remesh.sites: is 2, outside [4,";
        QTest::newRow("text for a number")
            << "{\"schema_version\": 1, \"grid\": {\"remesh\": {\"sites\": [\"many\"]}}, " + ok
                   + "}"
            << "--sites takes a number, not 'many'";
        QTest::newRow("number for a switch")
            << "{\"schema_version\": 1, \"grid\": {\"remesh\": {\"adaptive\": [1]}}, " + ok + "}"
            << "--adaptive is on or off";
        QTest::newRow("missing model")
            << QByteArray(R"({"schema_version": 1, "models": ["nowhere.ml"], "steps": ["remesh"],
                "output": "o"})")
            << "model 'nowhere.ml' not found";
        QTest::newRow("glob without match")
            << QByteArray(R"({"schema_version": 1, "models": ["none_*.ml"], "steps": ["remesh"],
                "output": "o"})")
            << "matches no file";
    }

    void badStudiesNameFileLineAndCause()
    {
        QFETCH(QByteArray, text);
        QFETCH(QString, expected);
        const QString study = m_dir.filePath("bad.smstudy");
        writeText(study, text);
        const CliRun run = runCli({"study", study, "--plan"});
        QCOMPARE(run.exitCode, 1);
        QVERIFY2(run.err.contains("bad.smstudy"), qPrintable(run.err));
        QVERIFY2(run.err.contains(expected), qPrintable(run.err));
        QVERIFY(!QDir(m_dir.filePath("o")).exists());
    }

    void brokenModelFailsAloneAndAFixCompletesTheStudy()
    {
        QFile::copy(m_dir.filePath("layers.ml"), m_dir.filePath("run_good.ml"));
        writeText(m_dir.filePath("run_broken.ts"), "GOCAD TSurf 1\nHEADER {\nname:x\n}\n"
                                                   "VRTX 1 0 0 0\nVRTX 2 1 0 0\nTRGL 1 2 9\nEND\n");
        const QString study = m_dir.filePath("run.smstudy");
        writeText(study, R"({"schema_version": 1, "models": ["run_good.ml", "run_broken.ts"],
            "steps": ["remesh", "tetmesh"], "grid": {"remesh": {"sites": [100, 150]}},
            "output": "run_out"})");
        const CliRun first = runCli({"study", study, "--run", "--jobs", "2"});
        QCOMPARE(first.exitCode, 1);
        QVERIFY2(first.out.contains("2 ok, 2 failed"), qPrintable(first.out + first.err));

        const QJsonObject table = readJson(m_dir.filePath("run_out/study.json"));
        const QJsonArray rows = table.value("rows").toArray();
        QCOMPARE(rows.size(), 4);
        for (const QJsonValue &v : rows) {
            const QJsonObject row = v.toObject();
            if (row.value("model").toString() == "run_good.ml") {
                QCOMPARE(row.value("status").toString(), QString("ok"));
                QCOMPARE(row.value("valid").toBool(), true);
                QCOMPARE(row.value("tetgen_outcome").toString(), QString("ok"));
                QVERIFY(row.value("tets").toInt() > 0);
                QVERIFY(row.value("vertices").toInt() > 0);
            } else {
                QCOMPARE(row.value("status").toString(), QString("failed"));
                QCOMPARE(row.value("failed_step").toString(), QString("remesh"));
                // The reader's own error: file, line, cause.
                QVERIFY2(row.value("error").toString().contains("run_broken.ts:7"),
                         qPrintable(row.value("error").toString()));
            }
        }
        QFile csv(m_dir.filePath("run_out/study.csv"));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        QCOMPARE(csv.readAll().count('\n'), 5);
        const QMap<QString, QString> before = finishedTasks(m_dir.filePath("run_out"));

        // Fix the model: the next run does only the two failed tasks.
        QFile::remove(m_dir.filePath("run_broken.ts"));
        const CliRun convert =
            runCli({"convert", m_dir.filePath("layers.ml"), m_dir.filePath("run_broken.ts")});
        QVERIFY2(convert.exitCode == 0, qPrintable(convert.err));
        const CliRun second = runCli({"study", study, "--run", "--jobs", "2"});
        QVERIFY2(second.exitCode == 0, qPrintable(second.err));
        QVERIFY2(second.out.contains("2 ok, 0 failed, 2 already done"), qPrintable(second.out));
        const QMap<QString, QString> after = finishedTasks(m_dir.filePath("run_out"));
        QCOMPARE(after.size(), 4);
        int unchanged = 0;
        for (auto it = before.cbegin(); it != before.cend(); ++it)
            unchanged += after.value(it.key()) == it.value();
        QCOMPARE(unchanged, 2);
        const QJsonObject status =
            QJsonDocument::fromJson(runCli({"study", study, "--status"}).out.toUtf8()).object();
        QCOMPARE(status.value("done").toInt(), 4);
        QCOMPARE(status.value("failed").toInt(), 0);
    }

    void killedRunRestartsWithOnlyTheMissingTasks()
    {
        const QString study = m_dir.filePath("kill.smstudy");
        writeText(study, R"({"schema_version": 1, "models": ["layers.ml"],
            "steps": ["remesh", "tetmesh"], "grid": {"remesh": {"sites": [100, 120, 140, 160, 180]}},
            "output": "kill_out"})");
        const QString output = m_dir.filePath("kill_out");
        QProcess run;
        run.start(QStringLiteral(STRATAMESH_CLI_PATH), {"study", study, "--run", "--jobs", "1"});
        QVERIFY(run.waitForStarted());
        QTRY_VERIFY_WITH_TIMEOUT(!finishedTasks(output).isEmpty(), 120000);
        ::kill(static_cast<pid_t>(run.processId()), SIGKILL);
        QVERIFY(run.waitForFinished());
        QThread::msleep(1500);
        const QMap<QString, QString> before = finishedTasks(output);
        QVERIFY2(before.size() < 5, "the run was not killed half-way");
        // The task that was running died with its parent: nothing finishes behind our back.
        QThread::msleep(3000);
        QCOMPARE(finishedTasks(output), before);

        const CliRun restart = runCli({"study", study, "--run", "--jobs", "2"});
        QVERIFY2(restart.exitCode == 0, qPrintable(restart.err));
        QVERIFY2(restart.out.contains(QStringLiteral("%1 ok, 0 failed, %2 already done")
                                          .arg(5 - before.size())
                                          .arg(before.size())),
                 qPrintable(restart.out));
        const QMap<QString, QString> after = finishedTasks(output);
        QCOMPARE(after.size(), 5);
        for (auto it = before.cbegin(); it != before.cend(); ++it)
            QCOMPARE(after.value(it.key()), it.value());
    }

private:
    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TestCliStudy)
#include "test_cli_study.moc"
