// A study (.smstudy): models × parameter grids × chained steps, described in one JSON file so a
// sweep or an ensemble is reproducible, resumable, and can run here or as a Slurm job array.
#pragma once

#include <QJsonValue>
#include <QString>
#include <QStringList>

#include <functional>
#include <utility>
#include <vector>

namespace stratamesh::study {

// The newest schema this build reads; a newer file is refused rather than half understood.
inline constexpr int kStudySchemaVersion = 1;

// One grid axis: a stratamesh-cli option of a step ("sites" → --sites) and the values it takes.
struct GridAxis {
    QString key;
    std::vector<QJsonValue> values;
};

struct Study {
    QString path;       // absolute path of the .smstudy file
    QString name;       // "name", or the file's base name
    QStringList models; // absolute, sorted, globs expanded
    QStringList steps;  // in execution order: complexity, remesh, tetmesh
    QString outputDir;  // absolute; one folder per task below it
    // Per step, its axes sorted by key (JSON objects have no order), which fixes the task order.
    std::vector<std::pair<QString, std::vector<GridAxis>>> grid;

    const std::vector<GridAxis> &axes(const QString &step) const;
};

// The steps a study may chain, in the order they run.
const QStringList &knownSteps();

// True when stratamesh-cli's command `step` has the option `flag` ("--sites").
using OptionCheck = std::function<bool(const QString &step, const QString &flag)>;
// Why `value` makes no sense for the option (its range, from the parameter table), or empty.
using ValueCheck =
    std::function<QString(const QString &step, const QString &flag, const QJsonValue &value)>;

// Reads and checks a study file; FileError names the file, the line where there is one, and
// the cause (unknown key or step, an option the step does not have, a value out of the option's
// range, a model matching no file).
Study readStudy(const QString &path, const OptionCheck &hasOption,
                const ValueCheck &checkValue = {});

} // namespace stratamesh::study
