#include "io/mesh_writer.h"

#include "common/error.h"
#include "io/gocad_writer.h"
#include "io/ringmesh_writer.h"
#include "io/surface_mesh_writer.h"
#include "io/tsolid_writer.h"
#include "io/vtk_writer.h"
#include "mesh/model_conversion.h"

#include <algorithm>
#include <cctype>

namespace stratamesh {

namespace {

std::string lowerExtension(const std::string &path)
{
    const std::size_t slash = path.find_last_of('/');
    const std::size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return {};
    std::string ext = path.substr(dot);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

[[noreturn]] void unknownExtension(const std::string &path)
{
    throw FileError(
        path, 0,
        "unknown output extension '" + lowerExtension(path)
            + "' (use .ml, .ts, .gm, .so, .vtu, .vtk, .vtp, .msh, .obj, .off, .stl or .ply)");
}

std::string gmshName(const GmshWriteOptions &o)
{
    return o.version == GmshWriteOptions::Version::V41 ? "Gmsh MSH 4.1" : "Gmsh MSH 2.2";
}

// Formats that store meshes, shared by both entry points.
bool writeAsMesh(const VolumeMesh &mesh, const std::string &path, const ExportOptions &options,
                 ExportReport &report)
{
    const std::string ext = lowerExtension(path);
    if (ext == ".msh") {
        report.format = gmshName(options.gmsh);
        report.untaggedSkipped = writeGmsh(mesh, path, options.gmsh).untaggedSkipped;
    } else if (ext == ".vtu") {
        report.format = "VTK XML unstructured grid";
        writeVtk(mesh, path, VtkFileKind::Vtu);
    } else if (ext == ".vtk") {
        report.format = "VTK legacy 4.2";
        writeVtk(mesh, path, VtkFileKind::LegacyVtk);
    } else if (ext == ".vtp") {
        report.format = "VTK XML poly data";
        writeVtk(mesh, path, VtkFileKind::Vtp);
    } else if (ext == ".so") {
        report.format = "Gocad TSolid";
        writeGocadTSolid(mesh, path);
    } else if (ext == ".gm" && mesh.hasCells()) {
        report.format = "RINGMesh GeoModel";
        writeRingMeshVolume(mesh, path);
    } else {
        return false;
    }
    return true;
}

bool writeAsModel(const Model &model, const std::string &path, const ExportOptions &options,
                  ExportReport &report)
{
    const std::string ext = lowerExtension(path);
    if (ext == ".ml") {
        report.format = "Gocad Model3d";
        writeGocadModel3d(model, path);
    } else if (ext == ".ts") {
        report.format = "Gocad TSurf";
        writeGocadTSurf(model, path, options.surface);
    } else if (ext == ".gm") {
        report.format = "RINGMesh GeoModel";
        writeRingMeshModel(model, path);
    } else if (isSurfaceMeshFile(path)) {
        report.format = "surface mesh " + ext;
        writeSurfaceMesh(model, path, options.surface);
    } else {
        return false;
    }
    return true;
}

} // namespace

bool isExportFile(const std::string &path)
{
    const std::string ext = lowerExtension(path);
    return ext == ".ml" || ext == ".ts" || ext == ".gm" || ext == ".so" || ext == ".vtu"
           || ext == ".vtk" || ext == ".vtp" || ext == ".msh" || isSurfaceMeshFile(path);
}

ExportReport exportModel(const Model &model, const std::string &path, const ExportOptions &options)
{
    ExportReport report;
    if (writeAsModel(model, path, options, report))
        return report;
    if (lowerExtension(path) == ".so")
        throw InputError("a TSolid holds tetrahedra: the surface model '" + model.name
                         + "' has none (build a volume mesh first)");
    if (isExportFile(path) && writeAsMesh(meshFromModel(model), path, options, report))
        return report;
    unknownExtension(path);
}

ExportReport exportVolumeMesh(const VolumeMesh &mesh, const std::string &path,
                              const ExportOptions &options)
{
    ExportReport report;
    if (writeAsMesh(mesh, path, options, report))
        return report;
    if (isExportFile(path) && writeAsModel(modelFromMesh(mesh), path, options, report)) {
        report.cellsDropped = mesh.cells.size();
        return report;
    }
    unknownExtension(path);
}

} // namespace stratamesh
