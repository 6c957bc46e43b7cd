#include "json_report_read.h"

#include "common/error.h"

#include <optional>

namespace stratamesh {

namespace {

[[noreturn]] void fail(const QString &file, const QString &what)
{
    throw FileError(file.toStdString(), 0, what.toStdString());
}

double number(const QJsonObject &o, const char *key, const QString &file, const QString &where)
{
    const QJsonValue v = o.value(QLatin1String(key));
    if (!v.isDouble())
        fail(file, QStringLiteral("%1: %2 is not a number").arg(where, QLatin1String(key)));
    return v.toDouble();
}

QString string(const QJsonObject &o, const char *key, const QString &file, const QString &where)
{
    const QJsonValue v = o.value(QLatin1String(key));
    if (!v.isString())
        fail(file, QStringLiteral("%1: %2 is not a string").arg(where, QLatin1String(key)));
    return v.toString();
}

Vec3 vec3(const QJsonValue &value, const QString &file, const QString &where)
{
    const QJsonArray a = value.toArray();
    if (!value.isArray() || a.size() != 3 || !a[0].isDouble() || !a[1].isDouble()
        || !a[2].isDouble())
        fail(file, QStringLiteral("%1: position is not 3 numbers").arg(where));
    return Vec3(a[0].toDouble(), a[1].toDouble(), a[2].toDouble());
}

std::optional<LedgerKind> ledgerKind(const QString &name)
{
    for (int k = 0; k <= int(kLastLedgerKind); ++k)
        if (name.toStdString() == ledgerKindName(LedgerKind(k)))
            return LedgerKind(k);
    return std::nullopt;
}

std::optional<EntityKind> entityKind(const QString &name)
{
    for (EntityKind k :
         {EntityKind::Surface, EntityKind::Line, EntityKind::Corner, EntityKind::Vertex})
        if (name.toStdString() == entityKindName(k))
            return k;
    return std::nullopt;
}

std::vector<EntityRef> refs(const QJsonValue &value, const QString &file, const QString &where)
{
    if (!value.isArray())
        fail(file, QStringLiteral("%1: not a list of entities").arg(where));
    std::vector<EntityRef> out;
    for (const QJsonValue &v : value.toArray()) {
        const QJsonObject o = v.toObject();
        const std::optional<EntityKind> kind = entityKind(string(o, "kind", file, where));
        if (!kind)
            fail(file, QStringLiteral("%1: unknown entity kind '%2'")
                           .arg(where, o.value(QLatin1String("kind")).toString()));
        out.push_back({*kind, int(number(o, "id", file, where)),
                       string(o, "name", file, where).toStdString()});
    }
    return out;
}

} // namespace

SimplificationLedger ledgerFromJson(const QJsonArray &records, const QString &file)
{
    SimplificationLedger ledger;
    ledger.reserve(std::size_t(records.size()));
    for (qsizetype i = 0; i < records.size(); ++i) {
        const QString where = QStringLiteral("ledger record %1").arg(i);
        if (!records[i].isObject())
            fail(file, QStringLiteral("%1 is not an object").arg(where));
        const QJsonObject o = records[i].toObject();
        LedgerRecord r;
        const QString kind = string(o, "kind", file, where);
        const std::optional<LedgerKind> k = ledgerKind(kind);
        if (!k)
            fail(file, QStringLiteral("%1: unknown kind '%2'").arg(where, kind));
        r.kind = *k;
        r.inputs = refs(o.value(QLatin1String("inputs")), file, where + QStringLiteral(" inputs"));
        r.outputs =
            refs(o.value(QLatin1String("outputs")), file, where + QStringLiteral(" outputs"));
        r.position = vec3(o.value(QLatin1String("position")), file, where);
        r.size = number(o, "size", file, where);
        r.sizeMeaning = string(o, "size_meaning", file, where).toStdString();
        r.note = string(o, "note", file, where).toStdString();
        r.cause = int(number(o, "cause", file, where));
        if (r.cause < -1 || r.cause >= records.size())
            fail(file, QStringLiteral("%1: cause %2 is not a record").arg(where).arg(r.cause));
        ledger.push_back(std::move(r));
    }
    return ledger;
}

ValidityReport validityFromJson(const QJsonObject &json, const QString &file)
{
    const QString where = QStringLiteral("validity");
    ValidityReport report;
    if (!json.value(QLatin1String("valid")).isBool())
        fail(file, QStringLiteral("validity: valid is not true or false"));
    report.valid = json.value(QLatin1String("valid")).toBool();
    for (const QJsonValue &v : json.value(QLatin1String("problems")).toArray()) {
        const QJsonObject o = v.toObject();
        ValidityProblem p;
        p.check = string(o, "check", file, where).toStdString();
        for (const QJsonValue &e : o.value(QLatin1String("entities")).toArray())
            p.entities.push_back(e.toString().toStdString());
        p.position = vec3(o.value(QLatin1String("position")), file, where);
        p.message = string(o, "message", file, where).toStdString();
        report.problems.push_back(std::move(p));
    }
    const QJsonObject counts = json.value(QLatin1String("counts")).toObject();
    for (auto it = counts.begin(); it != counts.end(); ++it)
        report.counts[it.key().toStdString()] = std::size_t(it.value().toInteger());
    return report;
}

HausdorffResult hausdorffFromReport(const QJsonObject &report, const QString &file)
{
    const QString where = QStringLiteral("hausdorff");
    const QJsonObject h = report.value(QLatin1String("hausdorff")).toObject();
    HausdorffResult r;
    r.aToB = number(h, "input_to_output", file, where);
    r.bToA = number(h, "output_to_input", file, where);
    r.symmetric = number(h, "symmetric", file, where);
    r.bboxDiagonal = number(h, "bbox_diagonal", file, where);
    // Older reports have no means.
    r.meanAToB = h.value(QLatin1String("mean_input_to_output")).toDouble();
    r.meanBToA = h.value(QLatin1String("mean_output_to_input")).toDouble();
    r.symmetricPctBbox = number(report, "hausdorff_pct_bbox", file, QStringLiteral("report"));
    return r;
}

} // namespace stratamesh
