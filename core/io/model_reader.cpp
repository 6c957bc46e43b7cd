#include "io/model_reader.h"

#include "common/error.h"
#include "io/gocad_reader.h"
#include "io/mesh_reader.h"
#include "io/ringmesh_reader.h"
#include "io/surface_mesh_reader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace stratamesh {

namespace {

std::string lowerExtension(const std::string &path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

} // namespace

bool isReadableModelFile(const std::string &path)
{
    const std::string ext = lowerExtension(path);
    return ext == ".ml" || ext == ".ts" || ext == ".obj" || ext == ".off" || ext == ".gm"
           || isVolumeMeshFile(path);
}

Model readModel(const std::string &path)
{
    const std::string ext = lowerExtension(path);
    if (!isReadableModelFile(path))
        throw FileError(
            path, 0,
            "unknown model file extension '" + ext
                + "' (expected .ml, .ts, .gm, .obj, .off, .so, .msh, .vtu, .vtk or .vtp)");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw FileError(path, 0, "cannot open the file (missing or not a regular file)");
    Model model;
    if (ext == ".ml" || ext == ".ts")
        model = readGocadFile(path);
    else if (ext == ".obj" || ext == ".off")
        model = readSurfaceMesh(path);
    else if (ext == ".gm")
        model = readRingMeshModel(path);
    else
        model = readMeshAsModel(path); // volume meshes: their surfaces and regions, cells dropped
    // An empty model would open as a "valid" one with nothing in it.
    const bool empty = std::all_of(model.surfaces.begin(), model.surfaces.end(),
                                   [](const Surface &s) { return s.triangles.empty(); });
    if (empty)
        throw FileError(path, 0,
                        "the file holds no surface triangle (an empty model; volume cells alone "
                        "give no surface)");
    return model;
}

} // namespace stratamesh
