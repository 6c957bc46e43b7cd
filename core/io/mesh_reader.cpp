#include "io/mesh_reader.h"

#include "common/error.h"
#include "io/gmsh_reader.h"
#include "io/ringmesh_reader.h"
#include "io/stl_ply_reader.h"
#include "io/tsolid_reader.h"
#include "io/vtk_reader.h"
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

} // namespace

bool isVolumeMeshFile(const std::string &path)
{
    const std::string ext = lowerExtension(path);
    return ext == ".so" || ext == ".msh" || ext == ".vtu" || ext == ".vtk" || ext == ".vtp";
}

bool isMeshReaderFile(const std::string &path)
{
    const std::string ext = lowerExtension(path);
    return isVolumeMeshFile(path) || ext == ".stl" || ext == ".ply" || ext == ".gm";
}

VolumeMesh readVolumeMesh(const std::string &path)
{
    const std::string ext = lowerExtension(path);
    if (ext == ".so")
        return readGocadTSolid(path);
    if (ext == ".msh")
        return readGmsh(path);
    if (ext == ".vtu" || ext == ".vtk" || ext == ".vtp")
        return readVtk(path);
    if (ext == ".stl" || ext == ".ply")
        return readStlOrPly(path);
    if (ext == ".gm")
        return readRingMeshVolume(path);
    throw FileError(path, 0,
                    "unknown mesh file extension '" + ext
                        + "' (use .so, .msh, .vtu, .vtk, .vtp, .stl, .ply or .gm)");
}

Model readMeshAsModel(const std::string &path)
{
    return modelFromMesh(readVolumeMesh(path));
}

} // namespace stratamesh
