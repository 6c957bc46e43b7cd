// Running one task of a study, and reading back what a task folder says about it. A task runs
// each step as its own stratamesh-cli process, so a crash or an out-of-memory in one task is
// that task's recorded failure and never the study's.
#pragma once

#include "study_plan.h"

#include <QJsonObject>
#include <QProcess>
#include <QString>

namespace stratamesh::study {

enum class TaskState { Pending, Ok, Failed };

struct TaskStatus {
    TaskState state = TaskState::Pending;
    QString failedStep; // empty unless Failed
    QString error;      // the step's last error line
    QJsonObject json;   // status.json as written
};

// File names inside a task folder.
inline constexpr const char *kTaskFile = "task.json";
inline constexpr const char *kStatusFile = "status.json";
inline constexpr const char *kRemeshedModel = "remeshed.ml";

// Runs every step of the study for this task with `cli` (the stratamesh-cli executable), then
// writes status.json last, atomically: a task without it did not finish and is pending.
TaskStatus runTask(const Study &study, const StudyTask &task, const QString &cli);

TaskStatus readTaskStatus(const StudyTask &task);

QString taskStateName(TaskState state);

// Starts children so that they die with their parent: a killed study leaves no orphan task
// running into a restarted one.
void dieWithParent(QProcess &process);

} // namespace stratamesh::study
