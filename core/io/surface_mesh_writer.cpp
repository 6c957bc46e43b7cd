#include "io/surface_mesh_writer.h"

#include "common/error.h"
#include "io/atomic_file.h"

// GCC 12 reports a false -Wmaybe-uninitialized inside OpenMesh's property containers while
// inlining (as in surface_mesh_reader.cpp); silenced for this file.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cctype>

namespace stratamesh {

namespace {

struct DoubleTraits : public OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d; // the default float points would round coordinates
    using Normal = OpenMesh::Vec3d;
};
using DoubleTriMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

std::string lowerExtension(const std::string &path)
{
    const std::size_t slash = path.find_last_of('/');
    const std::size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return {};
    std::string ext = path.substr(dot);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

} // namespace

bool isSurfaceMeshFile(const std::string &path)
{
    const std::string ext = lowerExtension(path);
    return ext == ".obj" || ext == ".off" || ext == ".stl" || ext == ".ply";
}

void writeSurfaceMesh(const Model &model, const std::string &path, int surface)
{
    if (!isSurfaceMeshFile(path))
        throw FileError(path, 0, "unknown surface mesh extension '" + lowerExtension(path) +
                                     "' (use .obj, .off, .stl or .ply)");
    if (surface < 0) {
        if (model.surfaces.size() != 1)
            throw InputError("an " + lowerExtension(path) + " file holds one surface and the model '" + model.name +
                             "' has " + std::to_string(model.surfaces.size()) + ": choose one");
        surface = 0;
    }
    if (surface >= static_cast<int>(model.surfaces.size()))
        throw InputError("surface " + std::to_string(surface) + " does not exist (the model has " +
                         std::to_string(model.surfaces.size()) + ")");
    const Surface &s = model.surfaces[surface];
    if (s.triangles.empty())
        throw InputError("surface '" + s.name + "' has no triangle");
    DoubleTriMesh mesh;
    std::vector<DoubleTriMesh::VertexHandle> handles;
    handles.reserve(s.vertices.size());
    for (const Vec3 &p : s.vertices) {
        if (!p.allFinite())
            throw InputError("surface '" + s.name + "' has a non-finite coordinate");
        handles.push_back(mesh.add_vertex(DoubleTriMesh::Point(p.x(), p.y(), p.z())));
    }
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
        const Triangle &tri = s.triangles[t];
        for (int v : tri)
            if (v < 0 || v >= static_cast<int>(handles.size()))
                throw InputError("surface '" + s.name + "': triangle " + std::to_string(t) + " uses vertex " +
                                 std::to_string(v) + " of " + std::to_string(handles.size()));
        if (!mesh.add_face(handles[tri[0]], handles[tri[1]], handles[tri[2]]).is_valid())
            throw InputError("surface '" + s.name + "' is not manifold at triangle " + std::to_string(t) +
                             ": it cannot be stored as " + lowerExtension(path));
    }
    const bool stl = lowerExtension(path) == ".stl";
    writeFileAtomically(path, [&](const std::string &temporary) {
        // Binary STL is the common form; ASCII for the others so 17 digits keep doubles exact.
        const OpenMesh::IO::Options options = stl ? OpenMesh::IO::Options::Binary : OpenMesh::IO::Options::Default;
        if (!OpenMesh::IO::write_mesh(mesh, temporary, options, 17))
            throw FileError(path, 0, "OpenMesh could not write the file");
    });
}

} // namespace stratamesh
