// Reading back what json_report.h writes, for the results a project keeps in its run folders:
// the simplification ledger, a validity report and the Hausdorff figures of a remesh report.
// A value missing or of the wrong type is a FileError naming `file` and the key.
#pragma once

#include "model/validity.h"
#include "quality/hausdorff.h"
#include "remesh/simplification_ledger.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QString>

namespace stratamesh {

SimplificationLedger ledgerFromJson(const QJsonArray &records, const QString &file);
ValidityReport validityFromJson(const QJsonObject &json, const QString &file);
// The `hausdorff` block of a remesh report (and its hausdorff_pct_bbox); the per-vertex distances
// are not in a report and stay empty.
HausdorffResult hausdorffFromReport(const QJsonObject &report, const QString &file);

} // namespace stratamesh
