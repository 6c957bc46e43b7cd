// stratamesh-cli tetmesh MODEL [PARAMETERS: tetgenParamTable()] [-o OUT.(vtu|vtk|msh|so)]
//     [--msh-version 4.1|2.2]
//     [--report R.json] [--json] [--poly PLC.poly] [--overwrite]
// A TetGen comparison mesh of a model (thesis §5.2): TetGen runs in its helper process
// (core/volume/tetgen_runner.h), so an abort, a crash, a time-out or an exhausted memory limit is
// reported as the outcome, in the report and with exit status 1, never as a crash of this tool.
// Every output is planned before the run (io/output_plan.h); a run that gives no mesh still
// writes its report and PLC, and leaves an existing -o file as it was.
#include "cli_output.h"
#include "command_args.h"
#include "common/error.h"
#include "hybrid/cell_quality.h"
#include "io/formats.h"
#include "io/mesh_writer.h"
#include "io/model_reader.h"
#include "io/output_plan.h"
#include "json_report.h"
#include "model/topology.h"
#include "param_json.h"
#include "params/param_tables.h"
#include "volume/plc.h"
#include "volume/tetgen_comparison.h"
#include "volume/tetgen_poly_writer.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>

#include <iostream>

namespace stratamesh::cli {

namespace {

QJsonArray stringArray(const std::vector<std::string> &items)
{
    QJsonArray a;
    for (const std::string &s : items)
        a.append(QString::fromStdString(s));
    return a;
}

// Per region, with the dihedral range and slivers, as `hybrid --report` gives them: the two
// meshes of one model compare region by region (thin layers against the rest).
QJsonArray regionsJson(const Model &model, const TetmeshSide &side)
{
    const auto quality = qualityByRegionAndType(side.result.mesh);
    QJsonArray regions;
    for (std::size_t r = 0; r < model.regions.size(); ++r) {
        QJsonObject o{{"name", QString::fromStdString(model.regions[r].name)},
                      {"tets", static_cast<qint64>(side.regions[r].tets)},
                      {"volume", side.regions[r].volume},
                      {"brep_volume", side.brepVolumes[r]}};
        if (r < quality.size() && quality[r][int(CellType::Tet)].cells > 0) {
            const TypeQuality &q = quality[r][int(CellType::Tet)];
            o["min_dihedral_deg"] = q.minDihedral;
            o["max_dihedral_deg"] = q.maxDihedral;
            o["mean_min_dihedral_deg"] = q.meanMinDihedral;
            o["slivers"] = static_cast<qint64>(q.slivers);
        }
        regions.append(o);
    }
    return regions;
}

} // namespace

int runTetmesh(CommandArgs &args)
{
    TetgenParams params;
    args.params(tetgenParamTable(), params);
    const bool json = args.flag(QStringLiteral("--json"));
    const bool overwrite = args.flag(QStringLiteral("--overwrite"));
    ExportOptions exportOptions;
    if (const auto version = args.option(QStringLiteral("--msh-version"))) {
        if (*version == QLatin1String("4.1"))
            exportOptions.gmsh.version = GmshWriteOptions::Version::V41;
        else if (*version == QLatin1String("2.2"))
            exportOptions.gmsh.version = GmshWriteOptions::Version::V22;
        else
            throw UsageError(
                QStringLiteral("--msh-version must be 4.1 or 2.2, not '%1'").arg(*version));
    }
    const std::optional<QString> output = args.option(QStringLiteral("-o"));
    const std::optional<QString> reportPath = args.option(QStringLiteral("--report"));
    const std::optional<QString> polyPath = args.option(QStringLiteral("--poly"));
    const QString path = args.positional(QStringLiteral("MODEL"));
    args.finish();
    if (output && !isFileFor(output->toStdString(), FormatUse::WriteVolumeMesh))
        throw UsageError(
            QStringLiteral("the output must be a %1 file, not '%2'")
                .arg(QString::fromStdString(extensionList(FormatUse::WriteVolumeMesh)), *output));
    OutputPlan plan({path.toStdString()}, overwrite);
    if (output)
        plan.add(output->toStdString(), "mesh");
    if (reportPath)
        plan.add(reportPath->toStdString(), "report");
    if (polyPath)
        plan.add(polyPath->toStdString(), "PLC file");

    QElapsedTimer clock;
    clock.start();
    const Model model = recoverTopology(readModel(path.toStdString()));
    // The exact PLC, to reproduce a failure with the tetgen executable.
    if (polyPath)
        plan.write(polyPath->toStdString(), [&](const std::string &temporary) {
            writeTetgenPoly(buildPlc(model), temporary);
        });
    TetmeshSide side = tetmeshModel(model, params);
    const TetgenResult &result = side.result;
    const VolumeQualityStatistics &quality = side.quality;
    const bool ok = result.outcome == TetgenOutcome::Ok;
    if (ok && output)
        plan.write(output->toStdString(), [&](const std::string &temporary) {
            exportVolumeMesh(result.mesh, temporary, exportOptions);
        });
    else if (output)
        plan.discard(output->toStdString());

    const QJsonObject report{
        {"file", path},
        {"output_file", output ? *output : QString()},
        {"outcome", tetgenOutcomeName(result.outcome)},
        {"message", QString::fromStdString(result.message)},
        {"last_output", QString::fromStdString(result.lastOutput)},
        {"surfaces", stringArray(result.surfaces)},
        {"switches", QString::fromStdString(result.switches)},
        {"parameters", paramsToJson(tetgenParamTable(), params)},
        {"input", QJsonObject{{"points", static_cast<qint64>(model.vertices.size())},
                              {"triangles", static_cast<qint64>(model.triangleCount())},
                              {"regions", static_cast<qint64>(model.regions.size())}}},
        {"tets", static_cast<qint64>(quality.tets)},
        {"points", static_cast<qint64>(ok ? result.mesh.points.size() : 0)},
        {"regions", regionsJson(model, side)},
        {"tets_located_by_centroid", static_cast<qint64>(result.tetsLocatedByCentroid)},
        {"tets_without_region", static_cast<qint64>(result.tetsWithoutRegion)},
        {"min_dihedral_deg", quality.minDihedralDeg},
        {"max_dihedral_deg", quality.maxDihedralDeg},
        {"mean_radius_ratio", quality.meanRadiusRatio},
        {"max_radius_ratio", quality.maxRadiusRatio},
        {"mean_aspect_ratio", quality.meanAspectRatio},
        {"slivers", static_cast<qint64>(quality.slivers)},
        {"pct_slivers", quality.tets > 0 ? 100.0 * quality.slivers / quality.tets : 0.0},
        {"histograms", QJsonObject{{"min_dihedral_deg", toJson(quality.minDihedral)},
                                   {"max_dihedral_deg", toJson(quality.maxDihedral)},
                                   {"inverse_radius_ratio", toJson(quality.inverseRadiusRatio)}}},
        {"time_s", result.seconds},
        {"total_time_s", clock.elapsed() / 1000.0},
    };
    if (reportPath)
        plan.writeText(reportPath->toStdString(), [&](std::ostream &o) {
            o << QJsonDocument(report).toJson(QJsonDocument::Indented).toStdString();
        });
    plan.commit();
    if (json) {
        printJson(report);
    } else if (ok) {
        QTextStream &o = out();
        o << "tetrahedralised " << QFileInfo(path).fileName() << " with -"
          << result.switches.c_str() << ": " << quality.tets << " tets, "
          << result.mesh.points.size() << " points in " << QString::number(result.seconds, 'f', 2)
          << " s\n"
          << "  dihedral angles " << QString::number(quality.minDihedralDeg, 'g', 4) << "° to "
          << QString::number(quality.maxDihedralDeg, 'g', 4) << "°, " << quality.slivers
          << " slivers (< 5°), mean radius ratio "
          << QString::number(quality.meanRadiusRatio, 'f', 3) << '\n';
        if (output)
            o << "  wrote " << *output << '\n';
    }
    if (!ok) {
        out().flush();
        std::cerr << "stratamesh-cli tetmesh: " << tetgenOutcomeName(result.outcome) << ": "
                  << result.message << std::endl;
        return 1;
    }
    return 0;
}

} // namespace stratamesh::cli
