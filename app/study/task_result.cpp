#include "task_result.h"

#include "study_task.h"

#include "common/error.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>

namespace stratamesh::study {

namespace {

QJsonObject readObject(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw FileError(path.toStdString(), 0, "cannot open: " + file.errorString().toStdString());
    QJsonParseError error{};
    const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &error);
    if (error.error != QJsonParseError::NoError || !doc.isObject())
        throw FileError(path.toStdString(), 0, "not a JSON object");
    return doc.object();
}

std::vector<EntityRef> refsFromJson(const QJsonArray &array)
{
    std::vector<EntityRef> refs;
    for (const QJsonValue &v : array) {
        const QJsonObject o = v.toObject();
        EntityRef ref;
        const std::string kind = o.value(QStringLiteral("kind")).toString().toStdString();
        for (EntityKind k :
             {EntityKind::Surface, EntityKind::Line, EntityKind::Corner, EntityKind::Vertex})
            if (entityKindName(k) == kind)
                ref.kind = k;
        ref.id = o.value(QStringLiteral("id")).toInt(-1);
        ref.name = o.value(QStringLiteral("name")).toString().toStdString();
        refs.push_back(std::move(ref));
    }
    return refs;
}

} // namespace

SimplificationLedger ledgerFromJson(const QJsonArray &records, const QString &file)
{
    SimplificationLedger ledger;
    ledger.reserve(static_cast<std::size_t>(records.size()));
    for (const QJsonValue &v : records) {
        const QJsonObject o = v.toObject();
        const std::string kind = o.value(QStringLiteral("kind")).toString().toStdString();
        LedgerRecord r;
        bool known = false;
        for (int k = 0; k <= static_cast<int>(kLastLedgerKind); ++k)
            if (ledgerKindName(static_cast<LedgerKind>(k)) == kind) {
                r.kind = static_cast<LedgerKind>(k);
                known = true;
            }
        if (!known)
            throw FileError(file.toStdString(), 0,
                            "ledger record " + std::to_string(ledger.size()) + " has kind '" + kind
                                + "', unknown to this StrataMesh");
        r.inputs = refsFromJson(o.value(QStringLiteral("inputs")).toArray());
        r.outputs = refsFromJson(o.value(QStringLiteral("outputs")).toArray());
        const QJsonArray p = o.value(QStringLiteral("position")).toArray();
        if (p.size() == 3)
            r.position = Vec3(p[0].toDouble(), p[1].toDouble(), p[2].toDouble());
        r.size = o.value(QStringLiteral("size")).toDouble();
        r.sizeMeaning = o.value(QStringLiteral("size_meaning")).toString().toStdString();
        r.note = o.value(QStringLiteral("note")).toString().toStdString();
        r.cause = o.value(QStringLiteral("cause")).toInt(-1);
        ledger.push_back(std::move(r));
    }
    return ledger;
}

TaskResult readTaskResult(const QString &studyTable, const QJsonObject &row)
{
    TaskResult result;
    result.id = row.value(QStringLiteral("task")).toInt(-1);
    const QDir output = QFileInfo(studyTable).absoluteDir();
    result.folder = output.absoluteFilePath(row.value(QStringLiteral("folder")).toString());
    const QJsonObject task =
        readObject(QDir(result.folder).filePath(QString::fromLatin1(kTaskFile)));
    result.input = task.value(QStringLiteral("model")).toString();
    const QString remeshed = QDir(result.folder).filePath(QString::fromLatin1(kRemeshedModel));
    const QString report = QDir(result.folder).filePath(QStringLiteral("remesh.json"));
    if (QFileInfo::exists(remeshed) && QFileInfo::exists(report)) {
        result.output = remeshed;
        result.remeshReport = readObject(report);
        result.ledger =
            ledgerFromJson(result.remeshReport.value(QStringLiteral("ledger")).toArray(), report);
    }
    return result;
}

} // namespace stratamesh::study
