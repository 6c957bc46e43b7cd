// What a finished study task left in its folder, read back for viewing: the input model's path,
// the remeshed model's path and the remesh ledger from its report (no recomputation).
#pragma once

#include "remesh/simplification_ledger.h"

#include <QJsonObject>
#include <QString>

namespace stratamesh::study {

struct TaskResult {
    int id = -1;
    QString folder;
    QString input;  // the task's model
    QString output; // remeshed.ml, empty when the study has no remesh step or it failed
    QJsonObject remeshReport;
    SimplificationLedger ledger;
};

// `studyTable` is a gathered study.json; `row` one of its rows. FileError when the task folder
// or its task.json is missing (a moved study folder names what it looked for).
TaskResult readTaskResult(const QString &studyTable, const QJsonObject &row);

// The ledger of a remesh report, as `stratamesh-cli remesh --report` wrote it; FileError for a
// record whose kind this build does not know.
SimplificationLedger ledgerFromJson(const QJsonArray &records, const QString &file);

} // namespace stratamesh::study
