#include "project_runs.h"

#include "common/error.h"
#include "io/mesh_writer.h"
#include "io/model_reader.h"
#include "io/output_plan.h"
#include "json_report.h"
#include "json_report_read.h"
#include "model/model_counts.h"
#include "model/topology.h"
#include "param_json.h"
#include "quality/mesh_statistics.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>

namespace stratamesh {

namespace {

[[noreturn]] void fail(const QString &file, const QString &cause)
{
    throw FileError(file.toStdString(), 0, cause.toStdString());
}

void writeJson(OutputPlan &plan, const QString &path, const QJsonDocument &doc)
{
    plan.writeText(path.toStdString(), [&](std::ostream &o) {
        o << doc.toJson(QJsonDocument::Indented).toStdString();
    });
}

} // namespace

RunFolderPaths runFolderPaths(const QString &projectPath, const QString &folder)
{
    const QDir runs(projectRunsFolder(projectPath));
    RunFolderPaths p;
    p.folder = runs.filePath(folder);
    const QDir dir(p.folder);
    p.model = dir.filePath(QStringLiteral("output.ml"));
    p.report = dir.filePath(QStringLiteral("report.json"));
    p.ledger = dir.filePath(QStringLiteral("ledger.json"));
    return p;
}

void writeProject(const QString &projectPath, const ProjectFile &project,
                  const std::vector<RunContent> &runs, const QString &inputPath)
{
    if (runs.size() != project.runs.size())
        throw std::logic_error("writeProject: one content per run");
    // Run files may be written again over themselves (Save after Save): overwrite, but never the
    // input model.
    OutputPlan plan({inputPath.toStdString()}, true);
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const RunFolderPaths paths = runFolderPaths(projectPath, project.runs[i].folder);
        if (!runs[i].output) {
            if (!QFileInfo::exists(paths.model))
                fail(paths.model, QStringLiteral("missing: the run's folder was moved"));
            continue;
        }
        if (!QDir().mkpath(paths.folder))
            fail(paths.folder, QStringLiteral("cannot create the run folder"));
        plan.add(paths.model.toStdString(), "run model");
        plan.add(paths.report.toStdString(), "run report");
        plan.add(paths.ledger.toStdString(), "run ledger");
        plan.write(paths.model.toStdString(),
                   [&](const std::string &temporary) { exportModel(*runs[i].output, temporary); });
        writeJson(plan, paths.report, QJsonDocument(runs[i].report));
        writeJson(plan, paths.ledger, QJsonDocument(toJson(*runs[i].ledger)));
    }
    plan.add(projectPath.toStdString(), "project");
    writeJson(plan, projectPath, QJsonDocument(projectToJson(project, projectPath)));
    plan.commit();
}

RunRead readRunFolder(const QString &projectPath, const ProjectRun &run)
{
    const RunFolderPaths paths = runFolderPaths(projectPath, run.folder);
    if (!QFileInfo(paths.folder).isDir())
        fail(paths.folder,
             QStringLiteral("run %1's folder is missing (was the folder %2 moved or renamed? It "
                            "must stay beside %3)")
                 .arg(run.id)
                 .arg(QFileInfo(projectRunsFolder(projectPath)).fileName(),
                      QFileInfo(projectPath).fileName()));
    for (const QString &file : {paths.model, paths.report, paths.ledger})
        if (!QFileInfo::exists(file))
            fail(file, QStringLiteral("missing from run %1's folder").arg(run.id));
    RunRead read;
    read.output = recoverTopology(readModel(paths.model.toStdString()));
    read.report = readJsonObject(paths.report);
    QFile ledgerFile(paths.ledger);
    if (!ledgerFile.open(QIODevice::ReadOnly))
        fail(paths.ledger, QStringLiteral("cannot read: %1").arg(ledgerFile.errorString()));
    QJsonParseError error;
    const QJsonDocument ledger = QJsonDocument::fromJson(ledgerFile.readAll(), &error);
    if (error.error != QJsonParseError::NoError || !ledger.isArray())
        fail(paths.ledger,
             QStringLiteral("not a JSON list of ledger records: %1")
                 .arg(error.error != QJsonParseError::NoError ? error.errorString()
                                                              : QStringLiteral("not a list")));
    read.ledger = ledgerFromJson(ledger.array(), paths.ledger);
    return read;
}

ModelComparison restoredComparison(const Model &input, const Model &output,
                                   const QJsonObject &report, const QString &file)
{
    ModelComparison c = compareModels(input, output, hausdorffFromReport(report, file));
    const QJsonObject timings = report.value(QLatin1String("timings")).toObject();
    c.output.samplingSeconds = timings.value(QLatin1String("sampling_s")).toDouble();
    c.output.meshSeconds = timings.value(QLatin1String("mesh_s")).toDouble();
    const QJsonObject refinement = report.value(QLatin1String("refinement")).toObject();
    c.output.resolution = std::to_string(refinement.value(QLatin1String("final_sites")).toInt());
    return c;
}

} // namespace stratamesh
