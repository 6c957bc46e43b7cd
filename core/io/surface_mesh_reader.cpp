#include "io/surface_mesh_reader.h"

#include "common/error.h"
#include "io/gocad_model_builder.h"

// GCC 12 reports a false -Wmaybe-uninitialized inside OpenMesh's property containers (a
// value-initialized VectorT); it is raised while inlining, so it is silenced for this file.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <cmath>
#include <filesystem>

namespace stratamesh {

namespace {

struct DoubleTraits : public OpenMesh::DefaultTraits {
    // Gocad-scale coordinates (1 600 649.31) lose digits in float.
    typedef OpenMesh::Vec3d Point;
};
using ReaderMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

} // namespace

Model readSurfaceMesh(const std::string &path)
{
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw FileError(path, 0, "cannot open the file (missing or not a regular file)");

    ReaderMesh mesh;
    OpenMesh::IO::Options options;
    if (!OpenMesh::IO::read_mesh(mesh, path, options))
        throw FileError(path, 0, "OpenMesh could not read this file as a surface mesh");
    if (mesh.n_faces() == 0)
        throw FileError(path, 0, "no triangle in the file");

    Surface s;
    s.name = gocadFileStem(path);
    s.featureName = s.name;
    s.sourceObject = s.name;
    // Only the vertices used by faces, in file order, so isolated points do not become surface
    // vertices.
    std::vector<int> index(mesh.n_vertices(), -1);
    for (const auto f : mesh.faces())
        for (const auto v : mesh.fv_range(f))
            index[v.idx()] = 0;
    for (const auto v : mesh.vertices()) {
        if (index[v.idx()] < 0)
            continue;
        const auto &p = mesh.point(v);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            throw FileError(path, 0, "vertex " + std::to_string(v.idx() + 1) + " has a non-finite coordinate");
        index[v.idx()] = int(s.vertices.size());
        s.vertices.emplace_back(p[0] + 0.0, p[1] + 0.0, p[2] + 0.0);
    }
    s.triangles.reserve(mesh.n_faces());
    for (const auto f : mesh.faces()) {
        Triangle t{};
        int k = 0;
        for (const auto v : mesh.fv_range(f))
            t[k++] = index[v.idx()];
        s.triangles.push_back(t);
    }

    Model model;
    model.name = s.name;
    model.surfaces.push_back(std::move(s));
    return model;
}

} // namespace stratamesh

#pragma GCC diagnostic pop
