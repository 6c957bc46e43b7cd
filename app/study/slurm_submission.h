// A study as one Slurm job array: each array task calls `stratamesh-cli study STUDY --task ID`,
// and a job depending on the array (afterany) gathers the table. Slurm schedules; we only
// describe tasks. Needs sbatch/squeue on this machine (Debian slurm-client) and a file system
// shared with the compute nodes.
#pragma once

#include "study_plan.h"

#include <QJsonArray>
#include <QString>

#include <map>
#include <vector>

namespace stratamesh::study {

struct SlurmOptions {
    QString partition;
    QString time;        // sbatch --time, e.g. 01:00:00
    QString memory;      // sbatch --mem, e.g. 4G
    int maxParallel = 0; // %K of --array; 0 = no limit
};

struct SlurmSubmission {
    QString arrayJob;
    QString gatherJob;
    std::vector<int> taskIds;
};

// "0-3,5,7-8": the ids as sbatch --array ranges.
QString arrayRanges(std::vector<int> ids);
// The inverse for squeue's "12_[3-5,7%2]" and "12_4" forms; empty for anything else.
std::vector<int> arrayIdsOf(const QString &squeueJobId);

// Writes the job scripts under OUTPUT/slurm, submits them, appends to
// OUTPUT/slurm/submissions.json. InputError when sbatch is missing or refuses.
SlurmSubmission submitToSlurm(const Study &study, const std::vector<int> &taskIds,
                              const SlurmOptions &options, const QString &cli);

// Every submission made so far for this study.
QJsonArray slurmSubmissions(const Study &study);

// Task id → Slurm state ("PENDING", "RUNNING", ...) for tasks still in squeue; empty when there
// is no squeue or nothing queued.
std::map<int, QString> queuedTasks(const Study &study, bool *squeueAvailable);

} // namespace stratamesh::study
