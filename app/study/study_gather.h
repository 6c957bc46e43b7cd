// One table of every task of a study (the Table-4.2 columns of the remesh, the TetGen outcome,
// times and errors), and a summary per model; written as CSV and JSON in the study's output.
#pragma once

#include "study_plan.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QStringList>

namespace stratamesh::study {

struct GatheredStudy {
    QStringList columns;
    QJsonArray rows;     // one object per task, keys = columns
    QJsonObject summary; // model file name → {tasks, ok, failed, pending, ...}
};

GatheredStudy gatherStudy(const Study &study, const std::vector<StudyTask> &tasks);

// study.csv and study.json in the study's output folder, each written atomically; returns the
// two paths.
QStringList writeGathered(const Study &study, const GatheredStudy &gathered);

} // namespace stratamesh::study
