#include "study_runner.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QProcess>
#include <QSaveFile>

#include <deque>
#include <memory>

namespace stratamesh::study {

namespace {

// A task process that died before writing its status (killed, out of memory) still ends as a
// recorded failure, so --gather shows it and --run retries it.
TaskStatus statusAfter(const StudyTask &task, const QProcess &process)
{
    TaskStatus status = readTaskStatus(task);
    if (status.state != TaskState::Pending)
        return status;
    status.state = TaskState::Failed;
    status.failedStep = QStringLiteral("task");
    status.error = process.exitStatus() == QProcess::CrashExit
                       ? QStringLiteral("the task process was killed or crashed")
                       : QStringLiteral("the task process exited with status %1 without a status")
                             .arg(process.exitCode());
    status.json = QJsonObject{{QStringLiteral("id"), task.id},
                              {QStringLiteral("status"), QStringLiteral("failed")},
                              {QStringLiteral("failed_step"), status.failedStep},
                              {QStringLiteral("error"), status.error}};
    QDir().mkpath(task.folder);
    QSaveFile file(QDir(task.folder).filePath(QString::fromLatin1(kStatusFile)));
    if (file.open(QIODevice::WriteOnly))
        file.write(QJsonDocument(status.json).toJson()), file.commit();
    return status;
}

} // namespace

RunSummary runStudyLocally(const Study &study, const std::vector<StudyTask> &tasks, int jobs,
                           const QString &cli, const TaskDone &onDone)
{
    RunSummary summary;
    std::deque<const StudyTask *> queue;
    for (const StudyTask &task : tasks) {
        if (readTaskStatus(task).state == TaskState::Ok)
            ++summary.skipped;
        else
            queue.push_back(&task);
    }
    struct Running {
        const StudyTask *task;
        std::unique_ptr<QProcess> process;
    };
    std::vector<Running> running;
    while (!queue.empty() || !running.empty()) {
        while (!queue.empty() && static_cast<int>(running.size()) < std::max(1, jobs)) {
            Running r{queue.front(), std::make_unique<QProcess>()};
            queue.pop_front();
            dieWithParent(*r.process);
            r.process->setProcessChannelMode(QProcess::ForwardedErrorChannel);
            r.process->setStandardOutputFile(QProcess::nullDevice());
            r.process->start(cli, {QStringLiteral("study"), study.path, QStringLiteral("--task"),
                                   QString::number(r.task->id)});
            r.process->waitForStarted(-1);
            running.push_back(std::move(r));
        }
        for (auto it = running.begin(); it != running.end();) {
            if (it->process->state() != QProcess::NotRunning && !it->process->waitForFinished(50)) {
                ++it;
                continue;
            }
            const TaskStatus status = statusAfter(*it->task, *it->process);
            (status.state == TaskState::Ok ? summary.ok : summary.failed)++;
            if (onDone)
                onDone(*it->task, status);
            it = running.erase(it);
        }
    }
    return summary;
}

} // namespace stratamesh::study
