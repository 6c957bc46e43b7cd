#include "io/surface_mesh_writer.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/atomic_file.h"
#include "io/formats.h"
#include "io/number_text.h"

// GCC 12 reports a false -Wmaybe-uninitialized inside OpenMesh's property containers while
// inlining (as in surface_mesh_reader.cpp); silenced for this file.
#pragma GCC diagnostic push
#if defined(__GNUC__) && !defined(__clang__) // clang has no such warning group
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
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

// Binary STL through OpenMesh (32-bit floats by the format's definition). OpenMesh stores
// manifold meshes only: a non-manifold surface is refused rather than silently trimmed.
void writeStl(const Surface &s, const std::string &path)
{
    DoubleTriMesh mesh;
    std::vector<DoubleTriMesh::VertexHandle> handles;
    handles.reserve(s.vertices.size());
    for (const Vec3 &p : s.vertices)
        handles.push_back(mesh.add_vertex(DoubleTriMesh::Point(p.x(), p.y(), p.z())));
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
        const Triangle &tri = s.triangles[t];
        if (!mesh.add_face(handles[tri[0]], handles[tri[1]], handles[tri[2]]).is_valid())
            throw InputError(MessageText{
                QT_TRANSLATE_NOOP(
                    "stratamesh::Core",
                    "surface '%1' is not manifold at triangle %2: OpenMesh cannot store it as STL"),
                {s.name, std::to_string(t)}});
    }
    writeFileAtomically(path, [&](const std::string &temporary) {
        if (!OpenMesh::IO::write_mesh(mesh, temporary, OpenMesh::IO::Options::Binary))
            throw FileError(
                path, 0,
                QT_TRANSLATE_NOOP("stratamesh::Core", "OpenMesh could not write the file"));
    });
}

} // namespace

bool isSurfaceMeshFile(const std::string &path)
{
    const FileFormat *format = findFormat(path);
    return format != nullptr && format->holds == FormatHolds::SingleSurface;
}

void writeSurfaceMesh(const Model &model, const std::string &path, int surface)
{
    if (!isSurfaceMeshFile(path))
        throw FileError(
            path, 0,
            MessageText{QT_TRANSLATE_NOOP(
                            "stratamesh::Core",
                            "unknown surface mesh extension '%1' (use .obj, .off, .stl or .ply)"),
                        {fileExtension(path)}});
    if (surface < 0) {
        if (model.surfaces.size() != 1)
            throw InputError(MessageText{
                QT_TRANSLATE_NOOP(
                    "stratamesh::Core",
                    "an %1 file holds one surface and the model '%2' has %3: choose one"),
                {fileExtension(path), model.name, std::to_string(model.surfaces.size())}});
        surface = 0;
    }
    if (surface >= static_cast<int>(model.surfaces.size()))
        throw InputError(MessageText{
            QT_TRANSLATE_NOOP("stratamesh::Core", "surface %1 does not exist (the model has %2)"),
            {std::to_string(surface), std::to_string(model.surfaces.size())}});
    const Surface &s = model.surfaces[surface];
    if (s.triangles.empty())
        throw InputError(MessageText{
            QT_TRANSLATE_NOOP("stratamesh::Core", "surface '%1' has no triangle"), {s.name}});
    for (const Vec3 &p : s.vertices)
        if (!p.allFinite())
            throw InputError(MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core", "surface '%1' has a non-finite coordinate"),
                {s.name}});
    for (std::size_t t = 0; t < s.triangles.size(); ++t)
        for (int v : s.triangles[t])
            if (v < 0 || v >= static_cast<int>(s.vertices.size()))
                throw InputError(
                    MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                  "surface '%1': triangle %2 uses vertex %3 of %4"),
                                {s.name, std::to_string(t), std::to_string(v),
                                 std::to_string(s.vertices.size())}});
    const std::string ext = fileExtension(path);
    if (ext == ".stl") {
        writeStl(s, path);
        return;
    }
    // OpenMesh 9 writes (and reads) OBJ, OFF and PLY coordinates as 32-bit floats whatever the
    // mesh traits: these three plain formats are written here with exact doubles instead.
    writeTextFileAtomically(path, [&](std::ostream &out) {
        auto point = [&](const Vec3 &p) {
            writeDouble(out, p.x());
            out << ' ';
            writeDouble(out, p.y());
            out << ' ';
            writeDouble(out, p.z());
            out << '\n';
        };
        std::string name = s.name;
        for (char &c : name)
            if (c == '\n' || c == '\r')
                c = ' ';
        if (ext == ".obj") {
            out << "# StrataMesh surface\no " << (name.empty() ? "surface" : name) << '\n';
            for (const Vec3 &p : s.vertices) {
                out << "v ";
                point(p);
            }
            for (const Triangle &t : s.triangles)
                out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
        } else if (ext == ".off") {
            out << "OFF\n" << s.vertices.size() << ' ' << s.triangles.size() << " 0\n";
            for (const Vec3 &p : s.vertices)
                point(p);
            for (const Triangle &t : s.triangles)
                out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
        } else {
            out << "ply\nformat ascii 1.0\ncomment StrataMesh surface " << name
                << "\nelement vertex " << s.vertices.size()
                << "\nproperty double x\nproperty double y\nproperty double z\nelement face "
                << s.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
            for (const Vec3 &p : s.vertices)
                point(p);
            for (const Triangle &t : s.triangles)
                out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
        }
    });
}

} // namespace stratamesh
