#include "project_file.h"

#include "common/error.h"
#include "param_json.h"
#include "params/param_tables.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>

namespace stratamesh {

namespace {

[[noreturn]] void fail(const QString &file, const QString &cause)
{
    throw FileError(file.toStdString(), 0, cause.toStdString());
}

QJsonObject figuresJson(const ProjectRunFigures &f)
{
    return QJsonObject{{QStringLiteral("sites"), f.sites},
                       {QStringLiteral("vertices"), f.vertices},
                       {QStringLiteral("triangles"), f.triangles},
                       {QStringLiteral("valid"), f.valid},
                       {QStringLiteral("hausdorff_pct_bbox"), f.hausdorffPctBbox},
                       {QStringLiteral("mean_quality"), f.meanQuality},
                       {QStringLiteral("ledger_records"), f.ledgerRecords}};
}

ProjectRunFigures figuresFromJson(const QJsonObject &o)
{
    ProjectRunFigures f;
    f.sites = o.value(QLatin1String("sites")).toInt();
    f.vertices = o.value(QLatin1String("vertices")).toInteger();
    f.triangles = o.value(QLatin1String("triangles")).toInteger();
    f.valid = o.value(QLatin1String("valid")).toBool();
    f.hausdorffPctBbox = o.value(QLatin1String("hausdorff_pct_bbox")).toDouble();
    f.meanQuality = o.value(QLatin1String("mean_quality")).toDouble();
    f.ledgerRecords = o.value(QLatin1String("ledger_records")).toInt();
    return f;
}

} // namespace

QString projectRunsFolder(const QString &projectPath)
{
    const QFileInfo info(projectPath);
    return info.absoluteDir().filePath(info.completeBaseName() + QStringLiteral("_runs"));
}

QString runFolderName(int id)
{
    return QStringLiteral("run-%1").arg(id, 3, 10, QLatin1Char('0'));
}

bool isProjectFile(const QString &path)
{
    return path.endsWith(QLatin1String(".smproj"), Qt::CaseInsensitive);
}

QJsonObject projectToJson(const ProjectFile &project, const QString &projectPath)
{
    QJsonArray runs;
    for (const ProjectRun &run : project.runs)
        runs.append(QJsonObject{
            {QStringLiteral("id"), run.id},
            {QStringLiteral("folder"), run.folder},
            {QStringLiteral("parameters"), paramsToJson(remeshParamTable(), run.params)},
            {QStringLiteral("figures"), figuresJson(run.figures)},
            {QStringLiteral("review"), run.review}});
    const QDir dir = QFileInfo(projectPath).absoluteDir();
    QJsonObject input;
    if (project.inputIsSample)
        input.insert(QStringLiteral("sample"), true);
    else
        input.insert(QStringLiteral("path"), dir.relativeFilePath(project.inputPath));
    QJsonObject json{
        {QStringLiteral("schema"), kProjectSchema},
        {QStringLiteral("input"), input},
        {QStringLiteral("runs_folder"), QFileInfo(projectRunsFolder(projectPath)).fileName()},
        {QStringLiteral("runs"), runs},
        {QStringLiteral("shown_run"), project.shownRun}};
    if (!project.view.isEmpty())
        json.insert(QStringLiteral("view"), project.view);
    return json;
}

ProjectFile projectFromJson(const QJsonObject &json, const QString &projectPath)
{
    const QJsonValue schema = json.value(QLatin1String("schema"));
    if (!schema.isDouble())
        fail(projectPath, QStringLiteral("not a StrataMesh project: no schema number"));
    if (schema.toInt() > kProjectSchema)
        fail(projectPath,
             QStringLiteral("written by a newer StrataMesh (project schema %1); this version reads "
                            "schema %2 at most")
                 .arg(schema.toInt())
                 .arg(kProjectSchema));
    if (schema.toInt() < 1)
        fail(projectPath, QStringLiteral("unknown project schema %1").arg(schema.toInt()));

    ProjectFile project;
    const QJsonObject input = json.value(QLatin1String("input")).toObject();
    project.inputIsSample = input.value(QLatin1String("sample")).toBool();
    if (!project.inputIsSample) {
        const QString path = input.value(QLatin1String("path")).toString();
        if (path.isEmpty())
            fail(projectPath, QStringLiteral("input: no model path"));
        project.inputPath =
            QDir::cleanPath(QFileInfo(projectPath).absoluteDir().absoluteFilePath(path));
    }
    const QJsonArray runs = json.value(QLatin1String("runs")).toArray();
    for (qsizetype i = 0; i < runs.size(); ++i) {
        const QJsonObject o = runs[i].toObject();
        ProjectRun run;
        run.id = o.value(QLatin1String("id")).toInt();
        run.folder = o.value(QLatin1String("folder")).toString();
        if (run.id <= 0 || run.folder.isEmpty() || run.folder.contains(QLatin1Char('/'))
            || run.folder.startsWith(QLatin1Char('.')))
            fail(projectPath, QStringLiteral("run %1: no id or folder").arg(i + 1));
        run.params.sites = 0; // the file says which of sites and edge_length was asked
        paramsFromJson(remeshParamTable(), o.value(QLatin1String("parameters")).toObject(),
                       run.params, projectPath);
        // Schema 1 wrote the default d_resolution as 0, which now asks for no simplification.
        if (schema.toInt() < 2 && run.params.dResolution == 0.0)
            run.params.dResolution = kAutoDResolution;
        run.figures = figuresFromJson(o.value(QLatin1String("figures")).toObject());
        run.review = o.value(QLatin1String("review")).toObject();
        project.runs.push_back(std::move(run));
    }
    project.shownRun = json.value(QLatin1String("shown_run")).toInt(-1);
    if (project.shownRun < -1 || project.shownRun >= int(project.runs.size()))
        fail(projectPath, QStringLiteral("shown_run %1 is not a run").arg(project.shownRun));
    project.view = json.value(QLatin1String("view")).toObject();
    return project;
}

ProjectFile readProjectFile(const QString &projectPath)
{
    QFile file(projectPath);
    if (!file.exists())
        fail(projectPath, QStringLiteral("no such project file"));
    if (!file.open(QIODevice::ReadOnly))
        fail(projectPath, QStringLiteral("cannot read: %1").arg(file.errorString()));
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &error);
    if (error.error != QJsonParseError::NoError)
        fail(projectPath, QStringLiteral("not valid JSON: %1 at byte %2")
                              .arg(error.errorString())
                              .arg(error.offset));
    if (!doc.isObject())
        fail(projectPath, QStringLiteral("not valid JSON: the project is not a JSON object"));
    return projectFromJson(doc.object(), projectPath);
}

int reviewedCount(const QJsonObject &review)
{
    int n = 0;
    for (const QJsonValue &v : review.value(QLatin1String("records")).toArray()) {
        const QString verdict = v.toObject().value(QLatin1String("verdict")).toString();
        if (verdict == QLatin1String("accepted") || verdict == QLatin1String("flagged"))
            ++n;
    }
    return n;
}

} // namespace stratamesh
