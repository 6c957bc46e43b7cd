// Core results as JSON objects for command reports, one function per result type, so every
// command names the same fields the same way (snake_case keys).
#pragma once

#include "quality/histogram.h"
#include "quality/mesh_statistics.h"

#include <QJsonObject>

namespace stratamesh::cli {

// vertices, triangles, min_angle_deg, pct_triangles_angle_below_30, mean_quality, area,
// bbox_diagonal.
QJsonObject toJson(const MeshStatistics &statistics);
// edges (n + 1 numbers), counts (n), below, above, total.
QJsonObject toJson(const Histogram &histogram);

} // namespace stratamesh::cli
