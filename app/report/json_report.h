// Core results as JSON objects, one function per result type, so that every command report (and
// later the GUI's project files) names the same fields the same way (snake_case keys). Shared by
// stratamesh-cli and the GUI in the stratamesh_report library.
#pragma once

#include "model/model_counts.h"
#include "model/validity.h"
#include "quality/histogram.h"
#include "quality/mesh_statistics.h"
#include "remesh/ledger_reconciliation.h"
#include "remesh/simplification_ledger.h"
#include "remesh/surface_remesher.h"

#include <QJsonArray>
#include <QJsonObject>

namespace stratamesh {

QJsonArray toJson(const Vec3 &v);
// vertices, triangles, min_angle_deg, pct_triangles_angle_below_30, mean_quality, area,
// bbox_diagonal.
QJsonObject toJson(const MeshStatistics &statistics);
// edges (n + 1 numbers), counts (n), below, above, total.
QJsonObject toJson(const Histogram &histogram);
// regions, surfaces, lines, corners.
QJsonObject toJson(const EntityCounts &counts);
// all, without_box: each as above.
QJsonObject toJson(const ModelCounts &counts);
// valid, problems[] (check, entities, position, message), counts (per check).
QJsonObject toJson(const ValidityReport &report);
// One object per record: kind, inputs, outputs (kind, id, name), position, size, size_meaning,
// note, cause.
QJsonArray toJson(const SimplificationLedger &ledger);
// surfaces, lines, corners (input, lost, created, output, balanced), balanced.
QJsonObject toJson(const LedgerBalance &balance);
// total and surfaces/lines/corners/surface_parts lost and created.
QJsonObject toJson(const TopologyEdits &edits);

} // namespace stratamesh
