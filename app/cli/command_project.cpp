// stratamesh-cli project PROJECT.smproj
// Lists a project's runs as JSON: id, folder, parameters, sites, vertices, triangles, valid,
// Hausdorff, mean Q, and the review progress (records accepted or flagged out of the ledger's);
// whether the input model and each run's folder are where the project says. Reads the .smproj
// only (project_file.h): nothing is remeshed or measured.
#include "cli_output.h"
#include "command_args.h"
#include "param_json.h"
#include "params/param_tables.h"
#include "project_file.h"
#include "project_runs.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>

namespace stratamesh::cli {

int runProject(CommandArgs &args)
{
    const QString path = args.positional(QStringLiteral("PROJECT"));
    args.finish();
    const ProjectFile project = readProjectFile(path);
    QJsonArray runs;
    for (const ProjectRun &run : project.runs) {
        const ProjectRunFigures &f = run.figures;
        runs.append(QJsonObject{
            {QStringLiteral("id"), run.id},
            {QStringLiteral("folder"), run.folder},
            {QStringLiteral("folder_found"),
             QFileInfo(runFolderPaths(path, run.folder).folder).isDir()},
            {QStringLiteral("parameters"), paramsToJson(remeshParamTable(), run.params)},
            {QStringLiteral("sites"), f.sites},
            {QStringLiteral("vertices"), f.vertices},
            {QStringLiteral("triangles"), f.triangles},
            {QStringLiteral("valid"), f.valid},
            {QStringLiteral("hausdorff_pct_bbox"), f.hausdorffPctBbox},
            {QStringLiteral("mean_quality"), f.meanQuality},
            {QStringLiteral("review"),
             QJsonObject{{QStringLiteral("reviewed"), reviewedCount(run.review)},
                         {QStringLiteral("total"), f.ledgerRecords}}}});
    }
    QJsonObject input;
    if (project.inputIsSample) {
        input.insert(QStringLiteral("sample"), true);
    } else {
        input.insert(QStringLiteral("path"), project.inputPath);
        input.insert(QStringLiteral("found"), QFileInfo::exists(project.inputPath));
    }
    printJson(QJsonObject{{QStringLiteral("file"), path},
                          {QStringLiteral("schema"), kProjectSchema},
                          {QStringLiteral("input"), input},
                          {QStringLiteral("shown_run"),
                           project.shownRun >= 0 ? project.runs[project.shownRun].id : 0},
                          {QStringLiteral("runs"), runs}});
    return 0;
}

} // namespace stratamesh::cli
