#include "study_gather.h"

#include "study_task.h"

#include "common/error.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QSaveFile>

#include <cmath>

namespace stratamesh::study {

namespace {

QJsonObject readJson(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(file.readAll()).object();
}

// "a.b.c" inside nested objects; undefined when a key is missing.
QJsonValue at(const QJsonObject &object, const QString &dotted)
{
    QJsonValue v = object;
    for (const QString &key : dotted.split(QLatin1Char('.'))) {
        if (!v.isObject())
            return QJsonValue(QJsonValue::Undefined);
        v = v.toObject().value(key);
    }
    return v;
}

// Output column → where it is read from: file of the task folder and key path inside it.
struct Source {
    const char *column;
    const char *file;
    const char *key;
};

constexpr Source kSources[] = {
    {"remesh_sites", "remesh.json", "refinement.initial_sites"},
    {"remesh_final_sites", "remesh.json", "refinement.final_sites"},
    {"input_vertices", "remesh.json", "input.mesh.vertices"},
    {"input_triangles", "remesh.json", "input.mesh.triangles"},
    {"vertices", "remesh.json", "output.mesh.vertices"},
    {"triangles", "remesh.json", "output.mesh.triangles"},
    {"mean_quality", "remesh.json", "output.mesh.mean_quality"},
    {"min_angle_deg", "remesh.json", "output.mesh.min_angle_deg"},
    {"pct_angle_below_30", "remesh.json", "output.mesh.pct_triangles_angle_below_30"},
    {"hausdorff_pct_bbox", "remesh.json", "hausdorff_pct_bbox"},
    {"valid", "remesh.json", "output.validity.valid"},
    {"topology_edits", "remesh.json", "topology_edits.total"},
    {"tetgen_outcome", "tetmesh.json", "outcome"},
    {"tets", "tetmesh.json", "tets"},
    {"min_dihedral_deg", "tetmesh.json", "min_dihedral_deg"},
    {"max_dihedral_deg", "tetmesh.json", "max_dihedral_deg"},
    {"slivers", "tetmesh.json", "slivers"},
    {"geometric_complexity", "complexity.json", "global.geometric.total"},
};

QString csvField(const QJsonValue &v)
{
    QString text;
    if (v.isBool())
        text = v.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    else if (v.isDouble())
        text = QString::number(v.toDouble(), 'g', 10);
    else if (v.isString())
        text = v.toString();
    if (text.contains(QLatin1Char(',')) || text.contains(QLatin1Char('"'))
        || text.contains(QLatin1Char('\n')))
        text = QLatin1Char('"') + QString(text).replace(QLatin1Char('"'), QStringLiteral("\"\""))
               + QLatin1Char('"');
    return text;
}

void write(const QString &path, const QByteArray &bytes)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) < 0 || !file.commit())
        throw FileError(path.toStdString(), 0, "cannot write: " + file.errorString().toStdString());
}

} // namespace

GatheredStudy gatherStudy(const Study &study, const std::vector<StudyTask> &tasks)
{
    GatheredStudy g;
    g.columns << QStringLiteral("task") << QStringLiteral("model") << QStringLiteral("status");
    QStringList parameterColumns;
    for (const QString &step : study.steps)
        for (const GridAxis &axis : study.axes(step))
            parameterColumns << step + QLatin1Char('.') + axis.key;
    g.columns << parameterColumns;
    for (const Source &s : kSources)
        if (study.steps.contains(QString::fromLatin1(s.file).section(QLatin1Char('.'), 0, 0)))
            g.columns << QString::fromLatin1(s.column);
    for (const QString &step : study.steps)
        g.columns << step + QStringLiteral("_s");
    g.columns << QStringLiteral("total_s") << QStringLiteral("failed_step")
              << QStringLiteral("error") << QStringLiteral("folder");

    struct ModelSummary {
        int tasks = 0, ok = 0, failed = 0, pending = 0;
        double bestQuality = -1.0;
        QString bestTask;
    };
    std::map<QString, ModelSummary> perModel;
    for (const StudyTask &task : tasks) {
        const TaskStatus status = readTaskStatus(task);
        QJsonObject row{
            {QStringLiteral("task"), task.id},
            {QStringLiteral("model"), QFileInfo(task.model).fileName()},
            {QStringLiteral("status"), taskStateName(status.state)},
            {QStringLiteral("failed_step"), status.failedStep},
            {QStringLiteral("error"), status.error},
            {QStringLiteral("folder"), QDir(study.outputDir).relativeFilePath(task.folder)}};
        for (const auto &[step, point] : task.options)
            for (const auto &[key, value] : point)
                row.insert(step + QLatin1Char('.') + key, value);
        std::map<QString, QJsonObject> files;
        for (const Source &s : kSources) {
            const QString file = QString::fromLatin1(s.file);
            if (!g.columns.contains(QString::fromLatin1(s.column)))
                continue;
            if (!files.count(file))
                files[file] = readJson(QDir(task.folder).filePath(file));
            const QJsonValue v = at(files[file], QString::fromLatin1(s.key));
            if (!v.isUndefined())
                row.insert(QString::fromLatin1(s.column), v);
        }
        const QJsonObject times = status.json.value(QStringLiteral("times")).toObject();
        for (const QString &step : study.steps)
            if (times.contains(step + QStringLiteral("_s")))
                row.insert(step + QStringLiteral("_s"), times.value(step + QStringLiteral("_s")));
        if (status.json.contains(QStringLiteral("total_s")))
            row.insert(QStringLiteral("total_s"), status.json.value(QStringLiteral("total_s")));
        g.rows.append(row);

        ModelSummary &m = perModel[QFileInfo(task.model).fileName()];
        ++m.tasks;
        (status.state == TaskState::Ok       ? m.ok
         : status.state == TaskState::Failed ? m.failed
                                             : m.pending)++;
        const double q = row.value(QStringLiteral("mean_quality")).toDouble(-1.0);
        if (status.state == TaskState::Ok && q > m.bestQuality) {
            m.bestQuality = q;
            m.bestTask = QString::number(task.id);
        }
    }
    for (const auto &[model, m] : perModel) {
        QJsonObject o{{QStringLiteral("tasks"), m.tasks},
                      {QStringLiteral("ok"), m.ok},
                      {QStringLiteral("failed"), m.failed},
                      {QStringLiteral("pending"), m.pending}};
        if (m.bestQuality >= 0.0) {
            o.insert(QStringLiteral("best_mean_quality"), m.bestQuality);
            o.insert(QStringLiteral("best_mean_quality_task"), m.bestTask.toInt());
        }
        g.summary.insert(model, o);
    }
    return g;
}

QStringList writeGathered(const Study &study, const GatheredStudy &gathered)
{
    if (!QDir().mkpath(study.outputDir))
        throw FileError(study.outputDir.toStdString(), 0, "cannot create the output folder");
    QByteArray csv = gathered.columns.join(QLatin1Char(',')).toUtf8() + '\n';
    for (const QJsonValue &r : gathered.rows) {
        QStringList fields;
        for (const QString &c : gathered.columns)
            fields << csvField(r.toObject().value(c));
        csv += fields.join(QLatin1Char(',')).toUtf8() + '\n';
    }
    const QString csvPath = QDir(study.outputDir).filePath(QStringLiteral("study.csv"));
    const QString jsonPath = QDir(study.outputDir).filePath(QStringLiteral("study.json"));
    const QJsonObject json{
        {QStringLiteral("study"), study.path},
        {QStringLiteral("name"), study.name},
        {QStringLiteral("columns"), QJsonArray::fromStringList(gathered.columns)},
        {QStringLiteral("rows"), gathered.rows},
        {QStringLiteral("summary"), gathered.summary}};
    write(csvPath, csv);
    write(jsonPath, QJsonDocument(json).toJson(QJsonDocument::Indented));
    return {csvPath, jsonPath};
}

} // namespace stratamesh::study
