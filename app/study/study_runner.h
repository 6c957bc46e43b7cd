// Runs a study's unfinished tasks on this machine, N at a time, each as its own
// `stratamesh-cli study STUDY --task ID` process; finished tasks are skipped, so a killed run
// restarted later does only what is missing.
#pragma once

#include "study_task.h"

#include <functional>
#include <vector>

namespace stratamesh::study {

struct RunSummary {
    int skipped = 0; // already ok
    int ok = 0;
    int failed = 0;
};

using TaskDone = std::function<void(const StudyTask &, const TaskStatus &)>;

RunSummary runStudyLocally(const Study &study, const std::vector<StudyTask> &tasks, int jobs,
                           const QString &cli, const TaskDone &onDone);

} // namespace stratamesh::study
