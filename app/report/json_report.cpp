#include "json_report.h"

namespace stratamesh {

namespace {

QString text(const std::string &s)
{
    return QString::fromStdString(s);
}

QJsonArray refsJson(const std::vector<EntityRef> &refs)
{
    QJsonArray a;
    for (const EntityRef &r : refs)
        a.append(QJsonObject{{QStringLiteral("kind"), text(entityKindName(r.kind))},
                             {QStringLiteral("id"), r.id},
                             {QStringLiteral("name"), text(r.name)}});
    return a;
}

QJsonObject balanceJson(const EntityBalance &e)
{
    return QJsonObject{{QStringLiteral("input"), e.input},
                       {QStringLiteral("lost"), e.lost},
                       {QStringLiteral("created"), e.created},
                       {QStringLiteral("output"), e.output},
                       {QStringLiteral("balanced"), e.balanced()}};
}

} // namespace

QJsonArray toJson(const Vec3 &v)
{
    return QJsonArray{v.x(), v.y(), v.z()};
}

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

QJsonObject toJson(const EntityCounts &c)
{
    return QJsonObject{{QStringLiteral("regions"), c.regions},
                       {QStringLiteral("surfaces"), c.surfaces},
                       {QStringLiteral("lines"), c.lines},
                       {QStringLiteral("corners"), c.corners}};
}

QJsonObject toJson(const ModelCounts &c)
{
    return QJsonObject{{QStringLiteral("all"), toJson(c.all)},
                       {QStringLiteral("without_box"), toJson(c.withoutBox)}};
}

QJsonObject toJson(const ValidityReport &report)
{
    QJsonArray problems;
    for (const ValidityProblem &p : report.problems) {
        QJsonArray entities;
        for (const std::string &e : p.entities)
            entities.append(text(e));
        problems.append(QJsonObject{{QStringLiteral("check"), text(p.check)},
                                    {QStringLiteral("entities"), entities},
                                    {QStringLiteral("position"), toJson(p.position)},
                                    {QStringLiteral("message"), text(p.message)}});
    }
    QJsonObject counts;
    for (const auto &[check, count] : report.counts)
        counts.insert(text(check), static_cast<qint64>(count));
    return QJsonObject{{QStringLiteral("valid"), report.valid},
                       {QStringLiteral("problems"), problems},
                       {QStringLiteral("counts"), counts}};
}

QJsonArray toJson(const SimplificationLedger &ledger)
{
    QJsonArray a;
    for (const LedgerRecord &r : ledger)
        a.append(QJsonObject{{QStringLiteral("kind"), text(ledgerKindName(r.kind))},
                             {QStringLiteral("inputs"), refsJson(r.inputs)},
                             {QStringLiteral("outputs"), refsJson(r.outputs)},
                             {QStringLiteral("position"), toJson(r.position)},
                             {QStringLiteral("size"), r.size},
                             {QStringLiteral("size_meaning"), text(r.sizeMeaning)},
                             {QStringLiteral("note"), text(r.note)},
                             {QStringLiteral("cause"), r.cause}});
    return a;
}

QJsonObject toJson(const LedgerBalance &b)
{
    return QJsonObject{{QStringLiteral("surfaces"), balanceJson(b.surfaces)},
                       {QStringLiteral("lines"), balanceJson(b.lines)},
                       {QStringLiteral("corners"), balanceJson(b.corners)},
                       {QStringLiteral("balanced"), b.balanced()}};
}

QJsonObject toJson(const TopologyEdits &e)
{
    return QJsonObject{{QStringLiteral("total"), e.total()},
                       {QStringLiteral("surfaces_lost"), e.surfacesLost},
                       {QStringLiteral("surfaces_created"), e.surfacesCreated},
                       {QStringLiteral("lines_lost"), e.linesLost},
                       {QStringLiteral("lines_created"), e.linesCreated},
                       {QStringLiteral("corners_lost"), e.cornersLost},
                       {QStringLiteral("corners_created"), e.cornersCreated},
                       {QStringLiteral("surface_parts_lost"), e.surfacePartsLost},
                       {QStringLiteral("surface_parts_created"), e.surfacePartsCreated}};
}

} // namespace stratamesh
