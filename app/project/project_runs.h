// The results of a project's runs, kept beside NAME.smproj in NAME_runs/run-001/: the output
// model (output.ml, Gocad), the run's report as stratamesh-cli remesh writes it (report.json) and
// its simplification ledger (ledger.json). Reopening a project reads them back: no remeshing.
#pragma once

#include "project_file.h"

#include "model/model.h"
#include "quality/model_comparison.h"
#include "remesh/simplification_ledger.h"

#include <QJsonObject>
#include <QString>

#include <vector>

namespace stratamesh {

struct RunFolderPaths {
    QString folder;
    QString model;  // output.ml
    QString report; // report.json
    QString ledger; // ledger.json
};
RunFolderPaths runFolderPaths(const QString &projectPath, const QString &folder);

// What one run writes; the pointers outlive the call. A null output: the run's folder already
// holds its files (saved there before), it is left as it is.
struct RunContent {
    const Model *output = nullptr;
    const SimplificationLedger *ledger = nullptr;
    QJsonObject report;
};

// Writes every run's folder, then the .smproj, through one OutputPlan (io/output_plan.h): each
// file goes to a temporary beside it, and nothing is renamed until all are written, the project
// file last; a failure leaves the previous files as they were. `runs` follows project.runs.
// `inputPath` is never overwritten. FileError on failure.
void writeProject(const QString &projectPath, const ProjectFile &project,
                  const std::vector<RunContent> &runs, const QString &inputPath);

struct RunRead {
    Model output; // with topology
    SimplificationLedger ledger;
    QJsonObject report;
};
// FileError naming the folder when it is missing (the project's runs folder moved or renamed),
// or the file that cannot be read.
RunRead readRunFolder(const QString &projectPath, const ProjectRun &run);

// The Table 4.2 comparison of a run read back, without the engine: the mesh statistics, counts
// and histograms are measured again on input and output (linear in their triangles); the
// Hausdorff distance (sampled, the costly part) and the timings come from the report.
ModelComparison restoredComparison(const Model &input, const Model &output,
                                   const QJsonObject &report, const QString &file);

} // namespace stratamesh
