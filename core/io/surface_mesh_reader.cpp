#include "io/surface_mesh_reader.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/coordinate_bound.h"
#include "io/formats.h"
#include "io/gocad_model_builder.h"
#include "io/number_text.h"

// GCC 12 reports a false -Wmaybe-uninitialized inside OpenMesh's property containers (a
// value-initialized VectorT); it is raised while inlining, so it is silenced for this file.
#pragma GCC diagnostic push
#if defined(__GNUC__) && !defined(__clang__) // clang has no such warning group
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

namespace stratamesh {

namespace {

struct DoubleTraits : public OpenMesh::DefaultTraits {
    typedef OpenMesh::Vec3d Point;
};
using ReaderMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

// The file as read here, not by OpenMesh's OBJ/OFF readers: they parse coordinates as float
// (1 600 649.31 comes back as 1 600 649.25), skip unparsable vertex lines, shifting every later
// index, and read OFF as a stream of words, so a vertex line with extra words turns a coordinate
// into a face size and a huge one into gigabytes of handles. OpenMesh only builds the surface
// from these faces, to refuse the non-manifold ones.
struct FileScan {
    std::vector<Vec3> points;
    std::vector<int> corners;           // every face's vertex indices, from 0, one after another
    std::vector<std::size_t> faceStart; // where each face's corners begin, then corners.size()
    std::vector<int> faceLine;          // each face's line in the file
    std::size_t triangles = 0;          // a polygon of k corners gives k - 2 triangles

    void beginFace(int line)
    {
        faceStart.push_back(corners.size());
        faceLine.push_back(line);
    }
};

std::vector<std::string_view> splitWords(std::string_view line)
{
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i])))
            ++i;
        const std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i])))
            ++i;
        if (i > start)
            words.push_back(line.substr(start, i - start));
    }
    return words;
}

// The line without its comment and end-of-line characters.
std::string_view content(const std::string &line)
{
    std::string_view s(line);
    s = s.substr(0, s.find('#'));
    while (!s.empty() && (s.back() == '\r' || s.back() == '\n'))
        s.remove_suffix(1);
    return s;
}

Vec3 readPoint(const std::vector<std::string_view> &w, std::size_t first, const std::string &path,
               int line)
{
    if (w.size() < first + 3)
        throw FileError(path, line,
                        QT_TRANSLATE_NOOP("stratamesh::Core", "a vertex needs three coordinates"));
    Vec3 p;
    for (int k = 0; k < 3; ++k) {
        const std::string_view token = w[first + k];
        if (!parseDouble(token, p[k]))
            throw FileError(path, line,
                            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                          "coordinate '%1' is not a number"),
                                        {std::string(token)}});
        if (MessageText problem = coordinateProblem(p[k]); !problem.pattern.empty())
            throw FileError(path, line,
                            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "coordinate '%1' %2"),
                                        {std::string(token)},
                                        {std::move(problem)}});
    }
    return p;
}

// OpenMesh skips a face with a bad index after printing a warning; the scan names its line.
// "v", "v/vt", "v//vn" and "v/vt/vn" forms; a negative index counts back from the last vertex
// defined so far. Returns the index, a positive one to be checked once all vertices are known.
long long checkObjIndex(std::string_view token, std::size_t vertices, const std::string &path,
                        int line)
{
    const std::string_view index = token.substr(0, token.find('/'));
    long long v = 0;
    if (!parseInt(index, v))
        throw FileError(
            path, line,
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "face vertex '%1' is not an index"),
                        {std::string(token)}});
    if (v == 0 || v < -static_cast<long long>(vertices))
        throw FileError(
            path, line,
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "face uses vertex %1 (numbered from 1, or back from -1)"),
                        {std::to_string(v)}});
    return v;
}

FileScan scanObj(std::istream &in, const std::string &path)
{
    FileScan scan;
    std::string text;
    std::pair<long long, int> largest{0, 0}; // the largest face index and its line
    for (int line = 1; std::getline(in, text); ++line) {
        const auto w = splitWords(content(text));
        if (w.empty())
            continue;
        if (w[0] == "v") {
            scan.points.push_back(readPoint(w, 1, path, line));
        } else if (w[0] == "f") {
            if (w.size() < 4)
                throw FileError(
                    path, line,
                    QT_TRANSLATE_NOOP("stratamesh::Core", "a face needs at least three vertices"));
            scan.beginFace(line);
            for (std::size_t k = 1; k < w.size(); ++k) {
                const long long v = checkObjIndex(w[k], scan.points.size(), path, line);
                if (v > largest.first)
                    largest = {v, line};
                // An index past the vertices fails once they are all known, naming both.
                scan.corners.push_back(v > std::numeric_limits<int>::max() ? -1
                                       : v > 0                             ? int(v - 1)
                                               : int(scan.points.size() + v));
            }
            scan.triangles += w.size() - 3;
        }
    }
    if (largest.first > static_cast<long long>(scan.points.size()))
        throw FileError(
            path, largest.second,
            MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core", "face uses vertex %1, the file defines %2"),
                {std::to_string(largest.first), std::to_string(scan.points.size())}});
    scan.faceStart.push_back(scan.corners.size());
    return scan;
}

FileScan scanOff(std::istream &in, const std::string &path)
{
    FileScan scan;
    int line = 0;
    std::vector<std::string_view> w;
    std::string keep; // backing store for w
    auto nextWords = [&]() {
        while (std::getline(in, keep)) {
            ++line;
            w = splitWords(content(keep));
            if (!w.empty())
                return true;
        }
        return false;
    };
    if (!nextWords())
        throw FileError(path, 0, QT_TRANSLATE_NOOP("stratamesh::Core", "empty file"));
    std::string header(w[0]);
    std::transform(header.begin(), header.end(), header.begin(),
                   [](unsigned char c) { return char(std::toupper(c)); });
    if (header.size() < 3 || header.compare(header.size() - 3, 3, "OFF") != 0)
        throw FileError(
            path, line,
            QT_TRANSLATE_NOOP("stratamesh::Core", "not an OFF file: the first word is not OFF"));
    if (header.find('4') != std::string::npos)
        throw FileError(path, line,
                        QT_TRANSLATE_NOOP("stratamesh::Core", "only 3D OFF files are supported"));
    std::size_t countsAt = 1;
    if (w.size() > 1 && (w[1] == "BINARY" || w[1] == "binary"))
        throw FileError(
            path, line,
            QT_TRANSLATE_NOOP("stratamesh::Core", "binary OFF files are not supported"));
    if (w.size() < 3) {
        if (!nextWords())
            throw FileError(path, line,
                            QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "file ends before the vertex and face counts"));
        countsAt = 0;
    }
    long long nv = 0, nf = 0;
    if (w.size() < countsAt + 2)
        throw FileError(
            path, line,
            QT_TRANSLATE_NOOP("stratamesh::Core", "expected the vertex and face counts"));
    if (!parseInt(w[countsAt], nv) || !parseInt(w[countsAt + 1], nf) || nv < 0 || nf < 0)
        throw FileError(path, line,
                        QT_TRANSLATE_NOOP("stratamesh::Core", "invalid vertex and face counts"));
    for (long long i = 0; i < nv; ++i) {
        if (!nextWords())
            throw FileError(path, line,
                            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                          "file ends after %1 of %2 vertices"),
                                        {std::to_string(i), std::to_string(nv)}});
        scan.points.push_back(readPoint(w, 0, path, line));
    }
    for (long long i = 0; i < nf; ++i) {
        if (!nextWords())
            throw FileError(
                path, line,
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "file ends after %1 of %2 faces"),
                            {std::to_string(i), std::to_string(nf)}});
        long long k = 0;
        if (!parseInt(w[0], k) || k < 3)
            throw FileError(
                path, line,
                QT_TRANSLATE_NOOP("stratamesh::Core", "a face needs at least three vertices"));
        if (k > static_cast<long long>(w.size()) - 1)
            throw FileError(
                path, line,
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "a face of %1 vertices lists %2"),
                            {std::to_string(k), std::to_string(w.size() - 1)}});
        scan.beginFace(line);
        for (long long j = 1; j <= k; ++j) {
            long long v = 0;
            if (!parseInt(w[std::size_t(j)], v) || v < 0 || v >= nv)
                throw FileError(
                    path, line,
                    MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                  "face vertex '%1' is not an index from 0 to %2"),
                                {std::string(w[std::size_t(j)]), std::to_string(nv - 1)}});
            scan.corners.push_back(int(v)); // v < nv, and nv vertices were read
        }
        scan.triangles += std::size_t(k - 2);
    }
    scan.faceStart.push_back(scan.corners.size());
    return scan;
}

} // namespace

Model readSurfaceMesh(const std::string &path)
{
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw FileError(path, 0,
                        QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "cannot open the file (missing or not a regular file)"));
    const std::string ext = fileExtension(path);
    if (ext != ".obj" && ext != ".off")
        throw FileError(path, 0, QT_TRANSLATE_NOOP("stratamesh::Core", "not an OBJ or OFF file"));

    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw FileError(path, 0, QT_TRANSLATE_NOOP("stratamesh::Core", "cannot open the file"));
    const FileScan scan = ext == ".obj" ? scanObj(in, path) : scanOff(in, path);
    if (scan.triangles == 0)
        throw FileError(path, 0, QT_TRANSLATE_NOOP("stratamesh::Core", "no triangle in the file"));

    // OpenMesh refuses a triangle that would make an edge carry three faces, or two faces run
    // the same way along it; its file readers would cut the surface there instead.
    ReaderMesh mesh;
    mesh.reserve(scan.points.size(), 3 * scan.triangles, scan.triangles);
    for (const Vec3 &p : scan.points)
        mesh.add_vertex(ReaderMesh::Point(p.x(), p.y(), p.z()));
    std::vector<int> index(scan.points.size(), -1); // file vertex -> surface vertex
    Surface s;
    s.name = gocadFileStem(path);
    s.featureName = s.name;
    s.sourceObject = s.name;
    s.triangles.reserve(scan.triangles);
    const std::size_t faces = scan.faceLine.size();
    std::vector<int> sorted;
    for (std::size_t f = 0; f < faces; ++f) {
        const int *c = scan.corners.data() + scan.faceStart[f];
        const std::size_t k = scan.faceStart[f + 1] - scan.faceStart[f];
        const int line = scan.faceLine[f];
        sorted.assign(c, c + k); // sorted, as a face may list thousands of corners
        std::sort(sorted.begin(), sorted.end());
        if (const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
            twice != sorted.end())
            throw FileError(
                path, line,
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "the face uses vertex %1 twice (a degenerate face)"),
                            {std::to_string(*twice + 1)}});
        for (std::size_t i = 1; i + 1 < k; ++i) { // a fan, as OpenMesh's readers split polygons
            const int t[3] = {c[0], c[i], c[i + 1]};
            if (!mesh.add_face(OpenMesh::VertexHandle(t[0]), OpenMesh::VertexHandle(t[1]),
                               OpenMesh::VertexHandle(t[2]))
                     .is_valid())
                throw FileError(
                    path, line,
                    QT_TRANSLATE_NOOP("stratamesh::Core",
                                      "non-manifold faces: this face shares an edge with two other "
                                      "faces, or runs along it the same way as its neighbour"));
            s.triangles.push_back(Triangle{t[0], t[1], t[2]});
        }
    }
    // Only the vertices faces use, in file order, so isolated points do not become surface
    // vertices.
    for (const Triangle &t : s.triangles)
        for (const int v : t)
            index[std::size_t(v)] = 0;
    for (std::size_t v = 0; v < index.size(); ++v) {
        if (index[v] < 0)
            continue;
        index[v] = int(s.vertices.size());
        const Vec3 &p = scan.points[v];
        s.vertices.emplace_back(p.x() + 0.0, p.y() + 0.0, p.z() + 0.0);
    }
    for (Triangle &t : s.triangles)
        for (int &v : t)
            v = index[std::size_t(v)];

    Model model;
    model.name = s.name;
    model.surfaces.push_back(std::move(s));
    return model;
}

} // namespace stratamesh

#pragma GCC diagnostic pop
