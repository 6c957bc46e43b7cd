// stratamesh-cli hybrid MODEL [PARAMETERS: hybridParamTable()] -o OUT.(vtu|msh) [--report R.json]
//     [--json] [--cavity-poly PLC.poly] [--surface-remesh S.ml] [--overwrite]
// A hybrid tet/prism/pyramid mesh (thesis ch. 5, core/hybrid/hybrid_mesher.h): prisms where
// Voronoi edges cross thin layers, tets from TetGen elsewhere, checked by the mixed-mesh checker.
// Nothing is written and the exit status is 1 when no valid mesh could be made; every output is
// planned before the run (io/output_plan.h).
#include "cli_output.h"
#include "command_args.h"
#include "common/error.h"
#include "hybrid/cell_quality.h"
#include "hybrid/hybrid_mesher.h"
#include "io/mesh_writer.h"
#include "io/model_reader.h"
#include "io/output_plan.h"
#include "param_json.h"
#include "params/param_tables.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>

#include <filesystem>

namespace stratamesh::cli {

namespace {

QJsonObject typesJson(const std::array<TypeQuality, 3> &byType)
{
    QJsonObject q;
    for (CellType t : {CellType::Tet, CellType::Pyramid, CellType::Prism}) {
        const TypeQuality &s = byType[static_cast<int>(t)];
        QJsonObject o{{"cells", static_cast<qint64>(s.cells)}};
        if (s.cells > 0) {
            o["min_dihedral_deg"] = s.minDihedral;
            o["max_dihedral_deg"] = s.maxDihedral;
            o["mean_min_dihedral_deg"] = s.meanMinDihedral;
        }
        if (t == CellType::Tet)
            o["slivers"] = static_cast<qint64>(s.slivers);
        q[cellTypeName(t)] = o;
    }
    return q;
}

QJsonObject qualityJson(const VolumeMesh &mesh)
{
    return typesJson(qualityByType(mesh));
}

// Cells and quality per type, region by region (the thin layers are where prisms should win).
QJsonArray regionsJson(const VolumeMesh &mesh)
{
    const auto byRegion = qualityByRegionAndType(mesh);
    QJsonArray regions;
    for (std::size_t r = 0; r < byRegion.size(); ++r)
        regions.append(QJsonObject{{"name", QString::fromStdString(mesh.regionNames[r])},
                                   {"quality", typesJson(byRegion[r])}});
    return regions;
}

QJsonObject cutVertexJson(const VertexDualCells &v)
{
    return {{"candidates", static_cast<qint64>(v.cut.candidates)},
            {"no_region", static_cast<qint64>(v.cut.noRegion)},
            {"many_points", static_cast<qint64>(v.cut.manyPoints)},
            {"split", static_cast<qint64>(v.cut.split)},
            {"undefined_chosen", static_cast<qint64>(v.cut.undefinedChosen)},
            {"split_tets_kept", static_cast<qint64>(v.cutSplitKept)},
            {"rejected_shape", static_cast<qint64>(v.cut.rejectedShape)},
            {"rejected_surface", static_cast<qint64>(v.cut.rejectedSurface)},
            {"beside_sliver", static_cast<qint64>(v.cut.besideSliver)},
            {"rejected_crossing", static_cast<qint64>(v.cutRejectedCrossing)},
            {"kept", static_cast<qint64>(v.cutKept)}};
}

QJsonObject countsJson(const std::map<std::string, std::size_t> &counts)
{
    QJsonObject o;
    for (const auto &[key, n] : counts)
        o[QString::fromStdString(key)] = static_cast<qint64>(n);
    return o;
}

} // namespace

int runHybrid(CommandArgs &args)
{
    HybridParams params;
    args.params(hybridParamTable(), params);
    // The TetGen input of the last fill, for `tetgen -d`.
    const std::optional<QString> cavityPoly = args.option(QStringLiteral("--cavity-poly"));
    // The surface remesh the cells stand on, for `tetmesh` to mesh the same surfaces (§5.5).
    const std::optional<QString> surfaceRemesh = args.option(QStringLiteral("--surface-remesh"));
    const bool json = args.flag(QStringLiteral("--json"));
    const std::optional<QString> output = args.option(QStringLiteral("-o"));
    const std::optional<QString> reportPath = args.option(QStringLiteral("--report"));
    const bool overwrite = args.flag(QStringLiteral("--overwrite"));
    const QString path = args.positional(QStringLiteral("MODEL"));
    args.finish();
    if (output) {
        const QString ext = QFileInfo(*output).suffix().toLower();
        if (ext != "vtu" && ext != "msh")
            throw UsageError(
                QStringLiteral("the output must be a .vtu or .msh file, not '%1'").arg(*output));
    }

    if (surfaceRemesh && !isExportFile(surfaceRemesh->toStdString()))
        throw UsageError(QStringLiteral("--surface-remesh: no model format has the extension of "
                                        "'%1' (.ml, .ts, .vtp, .msh, .gm…)")
                             .arg(*surfaceRemesh));
    OutputPlan plan({path.toStdString()}, overwrite);
    if (output)
        plan.add(output->toStdString(), "mesh");
    if (reportPath)
        plan.add(reportPath->toStdString(), "report");
    if (surfaceRemesh)
        plan.add(surfaceRemesh->toStdString(), "surface remesh");
    // The engine writes the PLC while it runs: into a scratch folder, moved into place by the plan.
    QTemporaryDir scratch;
    if (cavityPoly) {
        plan.add(cavityPoly->toStdString(), "PLC file");
        if (!scratch.isValid())
            throw FileError(cavityPoly->toStdString(), 0, "cannot create a scratch folder");
        params.cavityPolyPath = scratch.filePath(QStringLiteral("cavity.poly")).toStdString();
    }

    const Model model = readModel(path.toStdString());
    const HybridResult r = buildHybridMesh(model, params);
    const VolumeMesh &m = r.mesh;
    const bool valid = m.hasCells() && r.validity.valid();
    if (valid && output)
        plan.write(output->toStdString(),
                   [&](const std::string &temporary) { exportVolumeMesh(m, temporary); });
    else if (output)
        plan.discard(output->toStdString());
    if (cavityPoly && QFileInfo::exists(QString::fromStdString(params.cavityPolyPath)))
        plan.write(cavityPoly->toStdString(), [&](const std::string &temporary) {
            std::filesystem::copy_file(params.cavityPolyPath, temporary,
                                       std::filesystem::copy_options::overwrite_existing);
        });
    else if (cavityPoly)
        plan.discard(cavityPoly->toStdString());
    if (surfaceRemesh && r.surfaceRemesh)
        plan.write(surfaceRemesh->toStdString(),
                   [&](const std::string &temporary) { exportModel(*r.surfaceRemesh, temporary); });
    else if (surfaceRemesh)
        plan.discard(surfaceRemesh->toStdString());

    const HybridTimings &t = r.timings;
    const QJsonObject report{
        {"file", path},
        {"output_file", valid && output ? *output : QString()},
        {"parameters", paramsToJson(hybridParamTable(), params)},
        {"tets", static_cast<qint64>(m.countCells(CellType::Tet))},
        {"prisms", static_cast<qint64>(m.countCells(CellType::Prism))},
        {"pyramids", static_cast<qint64>(m.countCells(CellType::Pyramid))},
        {"points", static_cast<qint64>(m.points.size())},
        {"invalid_found", static_cast<qint64>(r.invalidFound)},
        {"repaired", static_cast<qint64>(r.repaired)},
        {"valid", valid},
        {"message", QString::fromStdString(r.message)},
        {"origin", QJsonObject{{"segment_dual_cells", static_cast<qint64>(r.segmentDualKept)},
                               {"transition_pyramids", static_cast<qint64>(r.transitionPyramids)},
                               {"lowered_pyramids", static_cast<qint64>(r.loweredPyramids)},
                               {"fill_tets", static_cast<qint64>(r.fillTets)},
                               {"candidates", static_cast<qint64>(r.segmentDual.candidates)},
                               {"rejected_shape", static_cast<qint64>(r.segmentDual.rejectedShape)},
                               {"rejected_thick", static_cast<qint64>(r.segmentDual.rejectedThick)},
                               {"rejected_taken", static_cast<qint64>(r.segmentDual.rejectedTaken)},
                               {"rejected_quad_on_surface",
                                static_cast<qint64>(r.segmentDual.rejectedQuadOnSurface)},
                               {"vertex_dual_cells", static_cast<qint64>(r.vertexDualKept)},
                               {"vertex_dual",
                                QJsonObject{
                                    {"candidates", static_cast<qint64>(r.vertexDual.candidates)},
                                    {"rejected_shape",
                                     static_cast<qint64>(r.vertexDual.rejectedShape)},
                                    {"rejected_near_surface",
                                     static_cast<qint64>(r.vertexDual.rejectedNearSurface)},
                                    {"rejected_near_cells",
                                     static_cast<qint64>(r.vertexDual.rejectedNearCells)},
                                    {"rejected_outside",
                                     static_cast<qint64>(r.vertexDual.rejectedOutside)},
                                    {"cut", cutVertexJson(r.vertexDual)}}},
                               {"cut_vertex_dual_cells", static_cast<qint64>(r.cutVertexDualKept)},
                               {"repair_rounds", r.repairRounds},
                               {"fell_back_to_tetgen", r.fellBackToTetgen}}},
        {"repair_log",
         [&] {
             QJsonArray a;
             for (const std::string &line : r.repairLog)
                 a.append(QString::fromStdString(line));
             return a;
         }()},
        {"remesh", QJsonObject{{"sites", r.remeshSites},
                               {"valid", r.remeshValid},
                               {"retried", r.remeshRetried},
                               {"first_problems",
                                countsJson(r.firstRemeshProblems)},
                               {"problems",
                                countsJson(r.remeshProblems)}}},
        {"tetgen_outcome", tetgenOutcomeName(r.tetgenOutcome)},
        {"max_quad_warp_deg", r.validity.maxQuadWarpDegrees},
        {"quality", qualityJson(m)},
        {"regions", regionsJson(m)},
        {"time_s", t.totalSeconds},
        {"stages_s", QJsonObject{{"cvt", t.cvtSeconds},
                                 {"surface_sites", t.surfaceSitesSeconds},
                                 {"remesh", t.remeshSeconds},
                                 {"cells", t.cellsSeconds},
                                 {"fill", t.fillSeconds},
                                 {"check", t.checkSeconds}}}};
    if (reportPath)
        plan.writeText(reportPath->toStdString(), [&](std::ostream &o) {
            o << QJsonDocument(report).toJson(QJsonDocument::Indented).toStdString();
        });
    plan.commit();
    if (json)
        printJson(report);
    else
        out() << QStringLiteral("%1 tets, %2 prisms, %3 pyramids; %4 (%5 invalid found, %6 "
                                "repaired) in %7 s\n")
                     .arg(m.countCells(CellType::Tet))
                     .arg(m.countCells(CellType::Prism))
                     .arg(m.countCells(CellType::Pyramid))
                     .arg(valid ? QStringLiteral("valid") : QStringLiteral("NOT valid"))
                     .arg(r.invalidFound)
                     .arg(r.repaired)
                     .arg(t.totalSeconds, 0, 'f', 2);
    return valid ? 0 : 1;
}

} // namespace stratamesh::cli
