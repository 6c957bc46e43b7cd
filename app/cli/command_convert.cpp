// stratamesh-cli convert IN OUT [--msh-version 4.1|2.2] [--save-all] [--surface N] [--json]
//     [--overwrite]:
// one exchange format to another, both chosen by extension (core/io/mesh_writer.h lists them).
// OUT is planned before IN is read (io/output_plan.h); OUT = IN only with --overwrite.
// Volume meshes (.so, .msh, .vtu, .vtk, .vtp) keep their cells; surface models get their topology
// recovered first so that lines, corners and Gocad BSTONE/BORDER are written too. A note (and
// "format_drops" in JSON) says what OUT's format does not keep, from the table File > Export… uses.
#include "cli_output.h"
#include "command_args.h"
#include "common/error.h"
#include "io/formats.h"
#include "io/mesh_reader.h"
#include "io/mesh_writer.h"
#include "io/model_reader.h"
#include "io/output_plan.h"
#include "io/ringmesh_reader.h"
#include "mesh/model_conversion.h"
#include "model/topology.h"

#include <QFileInfo>
#include <QJsonArray>

#include <algorithm>

namespace stratamesh::cli {

namespace {

// A cell-less mesh goes to these as a model with its topology recovered (lines, corners, BSTONE).
bool isModelFormat(const QString &path)
{
    const FileFormat *format = findFormat(path.toStdString());
    return format != nullptr && format->holds != FormatHolds::VolumeMesh;
}

} // namespace

int runConvert(CommandArgs &args)
{
    const bool json = args.flag(QStringLiteral("--json"));
    const bool overwrite = args.flag(QStringLiteral("--overwrite"));
    ExportOptions options;
    options.gmsh.saveAll = args.flag(QStringLiteral("--save-all"));
    if (const auto version = args.option(QStringLiteral("--msh-version"))) {
        if (*version == QLatin1String("4.1"))
            options.gmsh.version = GmshWriteOptions::Version::V41;
        else if (*version == QLatin1String("2.2"))
            options.gmsh.version = GmshWriteOptions::Version::V22;
        else
            throw UsageError(
                QStringLiteral("--msh-version must be 4.1 or 2.2, not '%1'").arg(*version));
    }
    options.surface = args.intOption(QStringLiteral("--surface"), -1, -1, 1 << 30);
    const QString in = args.positional(QStringLiteral("input file"));
    const QString output = args.positional(QStringLiteral("output file"));
    args.finish();
    if (!isExportFile(output.toStdString()))
        throw UsageError(
            QStringLiteral("cannot tell the output format of '%1' (use %2)")
                .arg(output, QString::fromStdString(extensionList(FormatUse::Export))));
    OutputPlan plan({in.toStdString()}, overwrite);
    plan.add(output.toStdString(), "output");

    ExportReport report;
    QJsonObject counts;
    ExportData written = ExportData::SurfaceModel; // what the output's losses are measured on
    // A GeoModel without region meshes is a B-Rep: read it whole (universe, layers, features).
    const bool brepGeoModel =
        isRingMeshFile(in.toStdString()) && !hasRingMeshRegionMeshes(in.toStdString());
    if (isMeshReaderFile(in.toStdString()) && !brepGeoModel) {
        const VolumeMesh mesh = readVolumeMesh(in.toStdString());
        // As readModel refuses a model without triangles: a mesh of nodes only is not converted
        // into an empty file that reads back as "nothing" (test_cli_malformed_memory).
        if (mesh.cells.empty() && mesh.triangles.empty())
            throw FileError(in.toStdString(), 0,
                            "empty model: no volume cell and no surface triangle; nothing written");
        counts = QJsonObject{{"points", qint64(mesh.points.size())},
                             {"cells", qint64(mesh.cells.size())},
                             {"triangles", qint64(mesh.triangles.size())},
                             {"edges", qint64(mesh.edges.size())},
                             {"regions", qint64(mesh.regionNames.size())},
                             {"surfaces", qint64(mesh.surfaces.size())}};
        if (mesh.hasCells())
            written = std::any_of(mesh.cells.begin(), mesh.cells.end(),
                                  [](const Cell &c) { return c.type != CellType::Tet; })
                          ? ExportData::HybridMesh
                          : ExportData::TetMesh;
        plan.write(output.toStdString(), [&](const std::string &temporary) {
            if (!mesh.hasCells() && isModelFormat(output))
                report = exportModel(recoverTopology(modelFromMesh(mesh)), temporary, options);
            else
                report = exportVolumeMesh(mesh, temporary, options);
        });
    } else {
        const Model model = recoverTopology(readModel(in.toStdString()));
        counts = QJsonObject{{"points", qint64(model.vertices.size())},
                             {"cells", 0},
                             {"triangles", qint64(model.triangleCount())},
                             {"lines", qint64(model.lines.size())},
                             {"regions", qint64(model.regions.size())},
                             {"surfaces", qint64(model.surfaces.size())}};
        plan.write(output.toStdString(), [&](const std::string &temporary) {
            report = exportModel(model, temporary, options);
        });
    }
    plan.commit();
    // The same words File > Export… warns with, from the same table.
    QStringList drops;
    for (const FormatLoss loss : formatLosses(*findFormat(output.toStdString()), written))
        if (loss != FormatLoss::OtherSurfaces || counts.value("surfaces").toInteger() > 1)
            drops << QString::fromStdString(describe(loss));

    if (json) {
        printJson(QJsonObject{{"input", in},
                              {"output", output},
                              {"format", QString::fromStdString(report.format)},
                              {"counts", counts},
                              {"untagged_elements_skipped", qint64(report.untaggedSkipped)},
                              {"cells_dropped", qint64(report.cellsDropped)},
                              {"format_drops", QJsonArray::fromStringList(drops)}});
    } else {
        QTextStream &s = cli::out();
        s << "wrote " << output << " (" << QString::fromStdString(report.format)
          << "): " << counts.value("triangles").toInteger() << " triangles, "
          << counts.value("cells").toInteger() << " cells, " << counts.value("regions").toInteger()
          << " regions\n";
        if (report.untaggedSkipped > 0)
            s << "note: " << report.untaggedSkipped
              << " elements without a region, surface or line were left out (as Gmsh does); "
                 "--save-all keeps them\n";
        if (report.cellsDropped > 0)
            s << "note: " << report.cellsDropped
              << " volume cells are not part of this format and were left out\n";
        if (!drops.isEmpty())
            s << "note: " << QString::fromStdString(report.format)
              << " does not keep: " << drops.join(QStringLiteral(", ")) << '\n';
    }
    return 0;
}

} // namespace stratamesh::cli
