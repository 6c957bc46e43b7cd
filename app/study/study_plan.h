// The tasks of a study: every model × every point of the steps' grids, in a fixed order, so a
// task's number is stable (it is the Slurm array index) as long as the study file is unchanged.
#pragma once

#include "study_file.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <vector>

namespace stratamesh::study {

struct StudyTask {
    int id = 0;
    QString model;  // absolute path
    QString folder; // absolute: study output / "0003-modelA1-sites5000"
    // Per step, the grid point's options as (key, value) in axis order.
    std::vector<std::pair<QString, std::vector<std::pair<QString, QJsonValue>>>> options;

    // Command-line arguments of a step's options: {"--sites", "5000", "--adaptive"}.
    QStringList arguments(const QString &step) const;
    // {"model": ..., "id": ..., "folder": ..., "parameters": {"remesh": {"sites": 5000}}}
    QJsonObject toJson() const;
};

// Refuses studies beyond kMaxStudyTasks (a typo in a grid must not create a million folders).
inline constexpr int kMaxStudyTasks = 100000;

std::vector<StudyTask> planTasks(const Study &study);

// The value as the command line spells it (numbers without a trailing ".0").
QString optionText(const QJsonValue &value);

} // namespace stratamesh::study
