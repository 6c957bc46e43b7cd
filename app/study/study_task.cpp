#include "study_task.h"

#include "common/error.h"

#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QProcess>
#include <QSaveFile>
#include <QSysInfo>

#include <csignal>
#include <sys/prctl.h>
#include <unistd.h>

namespace stratamesh::study {

namespace {

void writeJson(const QString &path, const QJsonObject &object)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)
        || file.write(QJsonDocument(object).toJson(QJsonDocument::Indented)) < 0 || !file.commit())
        throw FileError(path.toStdString(), 0, "cannot write: " + file.errorString().toStdString());
}

QString lastLine(const QByteArray &text)
{
    const QList<QByteArray> lines = text.trimmed().split('\n');
    for (auto it = lines.crbegin(); it != lines.crend(); ++it)
        if (!it->trimmed().isEmpty())
            return QString::fromUtf8(it->trimmed());
    return {};
}

struct StepRun {
    bool ok = false;
    QString error;
    double seconds = 0.0;
};

// Runs `cli step args`, stdout to OUT (when given) and stderr to the step's log.
StepRun runStep(const QString &cli, const QString &step, const QStringList &args,
                const QString &folder, const QString &stdoutFile)
{
    QProcess process;
    dieWithParent(process);
    process.setWorkingDirectory(folder);
    process.setStandardErrorFile(QDir(folder).filePath(step + QStringLiteral(".log")));
    process.setStandardOutputFile(
        stdoutFile.isEmpty() ? QDir(folder).filePath(step + QStringLiteral(".out")) : stdoutFile);
    QElapsedTimer timer;
    timer.start();
    process.start(cli, QStringList{step} + args);
    StepRun run;
    if (!process.waitForStarted(-1)) {
        run.error = QStringLiteral("cannot start %1: %2").arg(cli, process.errorString());
        return run;
    }
    process.waitForFinished(-1);
    run.seconds = timer.nsecsElapsed() * 1e-9;
    if (process.exitStatus() == QProcess::CrashExit) {
        run.error = QStringLiteral("%1 crashed").arg(step);
        return run;
    }
    if (process.exitCode() != 0) {
        QFile log(QDir(folder).filePath(step + QStringLiteral(".log")));
        const QByteArray text = log.open(QIODevice::ReadOnly) ? log.readAll() : QByteArray();
        run.error = lastLine(text);
        if (run.error.isEmpty())
            run.error =
                QStringLiteral("%1 exited with status %2").arg(step).arg(process.exitCode());
        return run;
    }
    run.ok = true;
    return run;
}

} // namespace

void dieWithParent(QProcess &process)
{
    process.setChildProcessModifier([] { ::prctl(PR_SET_PDEATHSIG, SIGKILL); });
}

QString taskStateName(TaskState state)
{
    switch (state) {
    case TaskState::Ok:
        return QStringLiteral("ok");
    case TaskState::Failed:
        return QStringLiteral("failed");
    case TaskState::Pending:
        break;
    }
    return QStringLiteral("pending");
}

TaskStatus runTask(const Study &study, const StudyTask &task, const QString &cli)
{
    QDir folder(task.folder);
    if (!folder.mkpath(QStringLiteral(".")))
        throw FileError(task.folder.toStdString(), 0, "cannot create the task folder");
    QFile::remove(folder.filePath(QString::fromLatin1(kStatusFile)));
    QJsonObject description = task.toJson();
    description.insert(QStringLiteral("study"), study.path);
    description.insert(QStringLiteral("steps"), QJsonArray::fromStringList(study.steps));
    writeJson(folder.filePath(QString::fromLatin1(kTaskFile)), description);

    QElapsedTimer total;
    total.start();
    TaskStatus status;
    status.state = TaskState::Ok;
    QJsonObject times;
    QString input = task.model;
    for (const QString &step : study.steps) {
        QStringList args{input};
        args << task.arguments(step);
        QString stdoutFile;
        if (step == QLatin1String("complexity")) {
            args << QStringLiteral("--json");
            stdoutFile = folder.filePath(QStringLiteral("complexity.json"));
        } else if (step == QLatin1String("remesh")) {
            args << QStringLiteral("-o") << folder.filePath(QString::fromLatin1(kRemeshedModel))
                 << QStringLiteral("--report") << folder.filePath(QStringLiteral("remesh.json"));
        } else if (step == QLatin1String("tetmesh")) {
            args << QStringLiteral("-o") << folder.filePath(QStringLiteral("tetmesh.vtu"))
                 << QStringLiteral("--report") << folder.filePath(QStringLiteral("tetmesh.json"));
        }
        const StepRun run = runStep(cli, step, args, task.folder, stdoutFile);
        times.insert(step + QStringLiteral("_s"), run.seconds);
        if (!run.ok) {
            status.state = TaskState::Failed;
            status.failedStep = step;
            status.error = run.error;
            break;
        }
        if (step == QLatin1String("remesh"))
            input = folder.filePath(QString::fromLatin1(kRemeshedModel));
    }
    status.json = QJsonObject{{QStringLiteral("id"), task.id},
                              {QStringLiteral("status"), taskStateName(status.state)},
                              {QStringLiteral("failed_step"), status.failedStep},
                              {QStringLiteral("error"), status.error},
                              {QStringLiteral("times"), times},
                              {QStringLiteral("total_s"), total.nsecsElapsed() * 1e-9},
                              {QStringLiteral("host"), QSysInfo::machineHostName()},
                              {QStringLiteral("finished_at"),
                               QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs)}};
    writeJson(folder.filePath(QString::fromLatin1(kStatusFile)), status.json);
    return status;
}

TaskStatus readTaskStatus(const StudyTask &task)
{
    TaskStatus status;
    QFile file(QDir(task.folder).filePath(QString::fromLatin1(kStatusFile)));
    if (!file.open(QIODevice::ReadOnly))
        return status;
    const QJsonDocument doc = QJsonDocument::fromJson(file.readAll());
    if (!doc.isObject())
        return status; // unreadable: not finished
    status.json = doc.object();
    const QString state = status.json.value(QStringLiteral("status")).toString();
    if (state == QLatin1String("ok"))
        status.state = TaskState::Ok;
    else if (state == QLatin1String("failed"))
        status.state = TaskState::Failed;
    status.failedStep = status.json.value(QStringLiteral("failed_step")).toString();
    status.error = status.json.value(QStringLiteral("error")).toString();
    return status;
}

} // namespace stratamesh::study
