#include "io/stl_ply_reader.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/coordinate_bound.h"
#include "io/formats.h"
#include "io/number_text.h"
#include "io/stl_reader.h"
#include "io/text_cursor.h"

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
#include <fstream>

namespace stratamesh {

namespace {

struct DoubleTraits : public OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
};
using DoubleTriMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

VolumeMesh oneSurface(const std::string &path)
{
    VolumeMesh m;
    m.name = fileStem(path);
    m.surfaces.push_back({m.name, m.name, FeatureType::Unknown});
    return m;
}

struct PlyCounts {
    long long vertices = 0;
    long long faces = 0;
};

// The element counts of a binary PLY header, each refused unless the file's size can hold it
// (a vertex takes 3 bytes at least, a face 4) before OpenMesh reserves room for them.
PlyCounts binaryPlyCounts(const std::string &path)
{
    std::ifstream in(path, std::ios::binary);
    in.seekg(0, std::ios::end);
    const long long size = static_cast<long long>(in.tellg());
    in.seekg(0);
    PlyCounts counts;
    std::string line;
    for (int number = 1; std::getline(in, line) && line.rfind("end_header", 0) != 0; ++number) {
        if (line.rfind("element ", 0) != 0)
            continue;
        const std::size_t space = line.find(' ', 8);
        long long n = 0;
        if (space == std::string::npos || !parseInt(line.substr(space + 1), n) || n < 0)
            throw FileError(path, number,
                            QT_TRANSLATE_NOOP("stratamesh::Core", "bad element count"));
        const std::string name = line.substr(8, space - 8);
        if (n > size / (name == "face" ? 4 : 3))
            throw FileError(
                path, number,
                MessageText{
                    QT_TRANSLATE_NOOP(
                        "stratamesh::Core",
                        "element %1 declares %2 items, more than the file of %3 bytes can hold"),
                    {name, std::to_string(n), std::to_string(size)}});
        if (name == "vertex")
            counts.vertices = n;
        else if (name == "face")
            counts.faces = n;
    }
    return counts;
}

VolumeMesh readWithOpenMesh(const std::string &path)
{
    const PlyCounts declared = binaryPlyCounts(path);
    DoubleTriMesh mesh;
    OpenMesh::IO::Options options;
    if (!OpenMesh::IO::read_mesh(mesh, path, options))
        throw FileError(path, 0,
                        QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "OpenMesh could not read this file as a surface mesh"));
    // OpenMesh duplicates the vertices around a non-manifold edge and drops faces it cannot add:
    // either would change the surface silently.
    if (static_cast<long long>(mesh.n_vertices()) != declared.vertices)
        throw FileError(
            path, 0,
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "non-manifold faces: %1 vertices in the file, %2 after "
                                          "reading (save as ASCII PLY, which keeps them)"),
                        {std::to_string(declared.vertices), std::to_string(mesh.n_vertices())}});
    if (static_cast<long long>(mesh.n_faces()) < declared.faces)
        throw FileError(
            path, 0,
            MessageText{QT_TRANSLATE_NOOP(
                            "stratamesh::Core",
                            "%1 face(s) could not be added (degenerate or non-manifold faces)"),
                        {std::to_string(declared.faces - static_cast<long long>(mesh.n_faces()))}});
    VolumeMesh m = oneSurface(path);
    for (const auto v : mesh.vertices()) {
        const auto p = mesh.point(v);
        m.points.push_back({p[0], p[1], p[2]});
        if (MessageText problem = pointProblem(m.points.back()); !problem.pattern.empty())
            throw FileError(path, 0,
                            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                          "vertex %1 (numbered from 0): %2"),
                                        {std::to_string(v.idx())},
                                        {std::move(problem)}});
    }
    for (const auto f : mesh.faces()) {
        Triangle t;
        int k = 0;
        for (const auto v : mesh.fv_range(f))
            if (k < 3)
                t[k++] = v.idx();
        m.triangles.push_back(t);
        m.triangleSurface.push_back(0);
    }
    return m;
}

struct PlyProperty {
    std::string name;
    bool list = false;
};
struct PlyElement {
    std::string name;
    long long count = 0;
    std::vector<PlyProperty> properties;
};

VolumeMesh readAsciiPly(const std::string &path)
{
    TextCursor c(path);
    std::vector<PlyElement> elements;
    c.nextNonBlank("\"ply\"");
    for (;;) {
        c.nextNonBlank("end_header");
        const auto t = c.tokens();
        if (t[0] == "end_header")
            break;
        if (t[0] == "element") {
            if (t.size() < 3)
                c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "expected \"element NAME COUNT\""));
            // Each item takes a line of at least two bytes.
            const long long n = c.toCount(t[2], "the element count", 2);
            elements.push_back({std::string(t[1]), n, {}});
        } else if (t[0] == "property") {
            if (elements.empty())
                c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "property before any element"));
            const bool list = t.size() >= 5 && t[1] == "list";
            if (t.size() < 3)
                c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "expected \"property TYPE NAME\""));
            elements.back().properties.push_back({std::string(t.back()), list});
        }
    }
    VolumeMesh m = oneSurface(path);
    long long vertexCount = 0;
    for (const PlyElement &e : elements)
        if (e.name == "vertex")
            vertexCount = e.count;
    for (const PlyElement &e : elements) {
        int x = -1, y = -1, z = -1, indices = -1;
        for (std::size_t p = 0; p < e.properties.size(); ++p) {
            const std::string &n = e.properties[p].name;
            if (n == "x")
                x = static_cast<int>(p);
            else if (n == "y")
                y = static_cast<int>(p);
            else if (n == "z")
                z = static_cast<int>(p);
            else if (e.properties[p].list && (n == "vertex_indices" || n == "vertex_index"))
                indices = static_cast<int>(p);
        }
        for (long long i = 0; i < e.count; ++i) {
            c.nextNonBlank(e.name.c_str());
            const auto t = c.tokens();
            std::size_t k = 0;
            Vec3 point = Vec3::Zero();
            std::vector<int> face;
            for (std::size_t p = 0; p < e.properties.size(); ++p) {
                if (k >= t.size())
                    c.fail(MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                         "line too short for the properties of %1"),
                                       {e.name}});
                if (e.properties[p].list) {
                    const int n = c.toInt(t[k++], "a list length");
                    if (n < 0 || k + static_cast<std::size_t>(n) > t.size())
                        c.fail(
                            QT_TRANSLATE_NOOP("stratamesh::Core", "line too short for its list"));
                    for (int j = 0; j < n; ++j) {
                        const int v = c.toInt(t[k++], "a vertex index");
                        if (static_cast<int>(p) != indices)
                            continue;
                        if (v < 0 || v >= vertexCount)
                            c.fail(MessageText{
                                QT_TRANSLATE_NOOP("stratamesh::Core",
                                                  "face uses vertex %1 of %2 (numbered from 0)"),
                                {std::to_string(v), std::to_string(vertexCount)}});
                        face.push_back(v);
                    }
                } else {
                    const std::string_view token = t[k++];
                    if (static_cast<int>(p) == x || static_cast<int>(p) == y
                        || static_cast<int>(p) == z)
                        point[static_cast<int>(p) == x   ? 0
                              : static_cast<int>(p) == y ? 1
                                                         : 2] = c.toDouble(token, "a coordinate");
                }
            }
            if (e.name == "vertex") {
                if (x < 0 || y < 0 || z < 0)
                    c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "vertices without x, y and z"));
                if (MessageText problem = pointProblem(point); !problem.pattern.empty())
                    c.fail(MessageText{
                        QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "vertex %1 (numbered from 0, as faces index it): %2"),
                        {std::to_string(m.points.size())},
                        {std::move(problem)}});
                m.points.push_back(point);
            } else if (e.name == "face" && indices >= 0) {
                if (face.size() < 3)
                    c.fail(QT_TRANSLATE_NOOP("stratamesh::Core", "a face needs three vertices"));
                for (std::size_t j = 1; j + 1 < face.size(); ++j) { // fan for polygons
                    m.triangles.push_back({face[0], face[j], face[j + 1]});
                    m.triangleSurface.push_back(0);
                }
            }
        }
    }
    return m;
}

// The format a PLY header states ("ascii", "binary_little_endian", "binary_big_endian"); OpenMesh
// loops for a long time on a file whose header is not one, so it is checked first.
std::string plyFormat(const std::string &path)
{
    std::ifstream in(path, std::ios::binary);
    std::string line, format;
    int number = 0;
    auto next = [&] {
        if (!std::getline(in, line))
            return false;
        ++number;
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        return true;
    };
    if (!next() || line != "ply")
        throw FileError(
            path, 1,
            QT_TRANSLATE_NOOP("stratamesh::Core", "not a PLY file: the first line is not \"ply\""));
    while (next() && line != "end_header") {
        if (line.rfind("format ", 0) != 0)
            continue;
        format = line.substr(7, line.find(' ', 7) == std::string::npos ? std::string::npos
                                                                       : line.find(' ', 7) - 7);
        if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
            throw FileError(
                path, number,
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "unknown PLY format \"%1\""),
                            {format}});
    }
    if (line != "end_header")
        throw FileError(path, number,
                        QT_TRANSLATE_NOOP("stratamesh::Core", "the PLY header has no end_header"));
    if (format.empty())
        throw FileError(path, number,
                        QT_TRANSLATE_NOOP("stratamesh::Core", "the PLY header has no format line"));
    return format;
}

} // namespace

VolumeMesh readStlOrPly(const std::string &path)
{
    if (!std::ifstream(path).good())
        throw FileError(path, 0, QT_TRANSLATE_NOOP("stratamesh::Core", "cannot open the file"));
    std::string ext = path.substr(std::min(path.size(), path.find_last_of('.')));
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char ch) { return char(std::tolower(ch)); });
    VolumeMesh m = ext == ".stl"                ? readStl(path)
                   : plyFormat(path) == "ascii" ? readAsciiPly(path)
                                                : readWithOpenMesh(path);
    if (m.triangles.empty())
        throw FileError(path, 0, QT_TRANSLATE_NOOP("stratamesh::Core", "no triangle in the file"));
    try {
        validateMesh(m);
    } catch (const InputError &e) {
        throw FileError(path, 0, causeOf(e));
    }
    return m;
}

} // namespace stratamesh
