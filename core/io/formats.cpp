#include "io/formats.h"

#include "io/gmsh_reader.h"
#include "io/gocad_reader.h"
#include "io/gocad_writer.h"
#include "io/ringmesh_reader.h"
#include "io/ringmesh_writer.h"
#include "io/stl_ply_reader.h"
#include "io/surface_mesh_reader.h"
#include "io/surface_mesh_writer.h"
#include "io/tsolid_reader.h"
#include "io/tsolid_writer.h"
#include "io/vtk_reader.h"
#include "io/vtk_writer.h"
#include "mesh/model_conversion.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace stratamesh {

namespace {

using Options = ExportOptions;
using Report = ExportReport;

void writeMl(const Model &m, const std::string &p, const Options &, Report &r)
{
    r.format = "Gocad Model3d";
    writeGocadModel3d(m, p);
}

void writeTs(const Model &m, const std::string &p, const Options &o, Report &r)
{
    r.format = "Gocad TSurf";
    writeGocadTSurf(m, p, o.surface);
}

void writeGmModel(const Model &m, const std::string &p, const Options &, Report &r)
{
    r.format = "RINGMesh GeoModel";
    writeRingMeshModel(m, p);
}

void writeGmMesh(const VolumeMesh &m, const std::string &p, const Options &, Report &r)
{
    r.format = "RINGMesh GeoModel";
    writeRingMeshVolume(m, p);
}

void writeSurface(const Model &m, const std::string &p, const Options &o, Report &r)
{
    r.format = "surface mesh " + fileExtension(p);
    writeSurfaceMesh(m, p, o.surface);
}

void writeSo(const VolumeMesh &m, const std::string &p, const Options &, Report &r)
{
    r.format = "Gocad TSolid";
    writeGocadTSolid(m, p);
}

void writeMsh(const VolumeMesh &m, const std::string &p, const Options &o, Report &r)
{
    r.format = o.gmsh.version == GmshWriteOptions::Version::V41 ? "Gmsh MSH 4.1" : "Gmsh MSH 2.2";
    r.untaggedSkipped = writeGmsh(m, p, o.gmsh).untaggedSkipped;
}

void writeVtu(const VolumeMesh &m, const std::string &p, const Options &, Report &r)
{
    r.format = "VTK XML unstructured grid";
    writeVtk(m, p, VtkFileKind::Vtu);
}

void writeLegacyVtk(const VolumeMesh &m, const std::string &p, const Options &, Report &r)
{
    r.format = "VTK legacy 4.2";
    writeVtk(m, p, VtkFileKind::LegacyVtk);
}

void writeVtp(const VolumeMesh &m, const std::string &p, const Options &, Report &r)
{
    r.format = "VTK XML poly data";
    writeVtk(m, p, VtkFileKind::Vtp);
}

template <VolumeMesh (*read)(const std::string &)>
Model readAsModel(const std::string &path)
{
    return modelFromMesh(read(path));
}

// Field order: severalSurfaces, surfaceNames, featureTypes, regions, linesAndCorners,
// tetrahedra, pyramidsPrisms, exactCoordinates. test_formats.cpp checks each of them.
constexpr FormatKeeps kGocadModel3d{true, true, true, true, true, false, false, true};
constexpr FormatKeeps kGocadTSurf{true, true, true, false, true, false, false, true};
constexpr FormatKeeps kRingMesh{true, true, true, true, true, true, true, true};
constexpr FormatKeeps kTSolid{true, true, true, true, false, true, false, true};
constexpr FormatKeeps kGmsh{true, true, false, true, true, true, true, true};
constexpr FormatKeeps kVtkCells{true, true, true, true, true, true, true, true};
constexpr FormatKeeps kVtkPolyData{true, true, true, true, true, false, false, true};
constexpr FormatKeeps kExactSurface{false, false, false, false, false, false, false, true};
constexpr FormatKeeps kFloatSurface{false, false, false, false, false, false, false, false};

// Field order: gmsh, surface, allSurfaces.
constexpr FormatOptions kGmshOptions{true, false, false};
constexpr FormatOptions kAnySurfaces{false, true, true};
constexpr FormatOptions kOneSurface{false, true, false};

// The extension part of one dialog filter entry: "Gocad Model3d (*.ml)" → ".ml".
std::string filterExtension(const std::string &entry)
{
    const std::size_t open = entry.rfind("(*.");
    if (open == std::string::npos)
        return {};
    const std::size_t end = entry.find_first_of(" )", open + 2);
    return entry.substr(open + 2, end == std::string::npos ? std::string::npos : end - open - 2);
}

} // namespace

const std::vector<FileFormat> &fileFormats()
{
    // Built on first use: a reader called from another file's static initialiser still finds it.
    static const std::vector<FileFormat> formats{
        {".ml", "Gocad Model3d", FormatHolds::Model, kGocadModel3d, readGocadFile, nullptr, writeMl,
         nullptr, false},
        {".ts", "Gocad TSurf", FormatHolds::Model, kGocadTSurf, readGocadFile, nullptr, writeTs,
         nullptr, false, kAnySurfaces},
        {".gm", "RINGMesh GeoModel", FormatHolds::Model, kRingMesh, readRingMeshModel,
         readRingMeshVolume, writeGmModel, writeGmMesh, false},
        {".obj", "Wavefront OBJ", FormatHolds::SingleSurface, kExactSurface, readSurfaceMesh,
         nullptr, writeSurface, nullptr, false, kOneSurface},
        {".off", "Object File Format", FormatHolds::SingleSurface, kExactSurface, readSurfaceMesh,
         nullptr, writeSurface, nullptr, false, kOneSurface},
        {".so", "Gocad TSolid", FormatHolds::VolumeMesh, kTSolid, readAsModel<readGocadTSolid>,
         readGocadTSolid, nullptr, writeSo, true},
        {".msh", "Gmsh MSH", FormatHolds::VolumeMesh, kGmsh, readAsModel<readGmsh>, readGmsh,
         nullptr, writeMsh, false, kGmshOptions},
        {".vtu", "VTK XML unstructured grid", FormatHolds::VolumeMesh, kVtkCells,
         readAsModel<readVtk>, readVtk, nullptr, writeVtu, false},
        {".vtk", "VTK legacy", FormatHolds::VolumeMesh, kVtkCells, readAsModel<readVtk>, readVtk,
         nullptr, writeLegacyVtk, false},
        {".vtp", "VTK XML poly data", FormatHolds::VolumeMesh, kVtkPolyData, readAsModel<readVtk>,
         readVtk, nullptr, writeVtp, false},
        // readModel() has never read STL and PLY: readVolumeMesh() and convert do.
        {".stl", "STL", FormatHolds::SingleSurface, kFloatSurface, nullptr, readStlOrPly,
         writeSurface, nullptr, false, kOneSurface},
        {".ply", "Stanford PLY", FormatHolds::SingleSurface, kExactSurface, nullptr, readStlOrPly,
         writeSurface, nullptr, false, kOneSurface},
    };
    return formats;
}

std::string fileExtension(const std::string &path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

std::string fileStem(const std::string &path)
{
    return std::filesystem::path(path).stem().string();
}

const FileFormat *findFormat(const std::string &path)
{
    const std::string ext = fileExtension(path);
    for (const FileFormat &f : fileFormats())
        if (ext == f.extension)
            return &f;
    return nullptr;
}

bool formatServes(const FileFormat &f, FormatUse use)
{
    switch (use) {
    case FormatUse::ReadModel:
        return f.readsModel();
    case FormatUse::ReadVolumeMesh:
        return f.readsMesh();
    case FormatUse::WriteModel: // a remeshed or converted model has several surfaces
        return f.writes() && !f.needsCells && f.keeps.severalSurfaces;
    case FormatUse::WriteVolumeMesh:
        return f.writeMesh != nullptr && f.keeps.tetrahedra;
    case FormatUse::Export:
        return f.writes();
    }
    return false;
}

std::vector<const FileFormat *> formatsFor(FormatUse use)
{
    std::vector<const FileFormat *> out;
    for (const FileFormat &f : fileFormats())
        if (formatServes(f, use))
            out.push_back(&f);
    return out;
}

bool isFileFor(const std::string &path, FormatUse use)
{
    const FileFormat *f = findFormat(path);
    return f != nullptr && formatServes(*f, use);
}

std::string extensionList(FormatUse use)
{
    const std::vector<const FileFormat *> all = formatsFor(use);
    std::string out;
    for (std::size_t i = 0; i < all.size(); ++i)
        out += (i == 0 ? "" : i + 1 == all.size() ? " or " : ", ") + std::string(all[i]->extension);
    return out;
}

std::string fileDialogFilter(FormatUse use, const std::string &allFormatsLabel,
                             const std::string &allFilesLabel)
{
    std::vector<std::string> entries;
    std::string patterns;
    for (const FileFormat *f : formatsFor(use)) {
        patterns += (patterns.empty() ? "*" : " *") + std::string(f->extension);
        entries.push_back(std::string(f->name) + " (*" + f->extension + ")");
    }
    if (!allFormatsLabel.empty())
        entries.insert(entries.begin(), allFormatsLabel + " (" + patterns + ")");
    if (!allFilesLabel.empty())
        entries.push_back(allFilesLabel + " (*)");
    std::string out;
    for (const std::string &e : entries)
        out += (out.empty() ? "" : ";;") + e;
    return out;
}

std::string withFormatExtension(const std::string &path, FormatUse use,
                                const std::string &selectedFilter)
{
    if (isFileFor(path, use))
        return path;
    const std::string chosen = filterExtension(selectedFilter);
    if (!chosen.empty() && isFileFor("x" + chosen, use))
        return path + chosen;
    const std::vector<const FileFormat *> all = formatsFor(use);
    return all.empty() ? path : path + all.front()->extension;
}

ExportFit exportFit(const FileFormat &f, ExportData data)
{
    if (data == ExportData::SurfaceModel)
        return f.needsCells ? ExportFit::NeedsCells : ExportFit::Fits;
    if (f.writeMesh == nullptr || !f.keeps.tetrahedra)
        return ExportFit::DropsCells;
    if (data == ExportData::HybridMesh && !f.keeps.pyramidsPrisms)
        return ExportFit::DropsPyramidsPrisms;
    return ExportFit::Fits;
}

std::vector<FormatLoss> formatLosses(const FileFormat &f, ExportData data)
{
    if (!f.writes())
        return {};
    const FormatKeeps &k = f.keeps;
    std::vector<FormatLoss> out;
    if (!k.severalSurfaces)
        out.push_back(FormatLoss::OtherSurfaces);
    if (!k.surfaceNames)
        out.push_back(FormatLoss::SurfaceNames);
    if (!k.featureTypes)
        out.push_back(FormatLoss::FeatureTypes);
    if (!k.regions)
        out.push_back(FormatLoss::Regions);
    if (!k.linesAndCorners)
        out.push_back(FormatLoss::LinesAndCorners);
    if (data != ExportData::SurfaceModel && !k.tetrahedra)
        out.push_back(FormatLoss::VolumeCells);
    else if (data == ExportData::HybridMesh && !k.pyramidsPrisms)
        out.push_back(FormatLoss::PyramidsPrisms);
    if (!k.exactCoordinates)
        out.push_back(FormatLoss::DoublePrecision);
    return out;
}

std::string describe(FormatLoss loss)
{
    switch (loss) {
    case FormatLoss::OtherSurfaces:
        return "all surfaces but one";
    case FormatLoss::SurfaceNames:
        return "surface names";
    case FormatLoss::FeatureTypes:
        return "feature types";
    case FormatLoss::Regions:
        return "regions";
    case FormatLoss::LinesAndCorners:
        return "lines and corners";
    case FormatLoss::VolumeCells:
        return "volume cells";
    case FormatLoss::PyramidsPrisms:
        return "pyramids and prisms";
    case FormatLoss::DoublePrecision:
        return "double precision (coordinates as 32-bit floats)";
    }
    return {};
}

std::vector<std::string> whatFormatDrops(const std::string &path, bool volume)
{
    const FileFormat *f = findFormat(path);
    if (f == nullptr)
        return {};
    std::vector<std::string> out;
    for (const FormatLoss loss :
         formatLosses(*f, volume ? ExportData::HybridMesh : ExportData::SurfaceModel))
        out.push_back(describe(loss));
    return out;
}

} // namespace stratamesh
