#include "json_report.h"

#include <QJsonArray>

namespace stratamesh::cli {

QJsonObject toJson(const MeshStatistics &s)
{
    return QJsonObject{
        {QStringLiteral("vertices"), static_cast<qint64>(s.vertices)},
        {QStringLiteral("triangles"), static_cast<qint64>(s.triangles)},
        {QStringLiteral("min_angle_deg"), s.minAngleDeg},
        {QStringLiteral("pct_triangles_angle_below_30"), s.pctTrianglesAngleBelow30},
        {QStringLiteral("mean_quality"), s.meanQuality},
        {QStringLiteral("area"), s.area},
        {QStringLiteral("bbox_diagonal"), s.bboxDiagonal},
    };
}

QJsonObject toJson(const Histogram &h)
{
    QJsonArray edges;
    for (double e : h.edges())
        edges.append(e);
    QJsonArray counts;
    for (std::size_t c : h.counts())
        counts.append(static_cast<qint64>(c));
    return QJsonObject{
        {QStringLiteral("edges"), edges},
        {QStringLiteral("counts"), counts},
        {QStringLiteral("below"), static_cast<qint64>(h.below())},
        {QStringLiteral("above"), static_cast<qint64>(h.above())},
        {QStringLiteral("total"), static_cast<qint64>(h.total())},
    };
}

} // namespace stratamesh::cli
