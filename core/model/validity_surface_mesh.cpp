// Per-surface mesh checks: non_manifold_edge, degenerate_triangle, duplicate_triangle,
// inconsistent_orientation. Degeneracy is exact (CGAL predicates on the stored doubles).
#include "common/translate_noop.h"
#include "model/validity_checks.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>

namespace stratamesh::validity_detail {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

Kernel::Point_3 toPoint(const Vec3 &p)
{
    return {p.x(), p.y(), p.z()};
}

Vec3 centroid(const Surface &s, const Triangle &t)
{
    return (s.vertices[t[0]] + s.vertices[t[1]] + s.vertices[t[2]]) / 3.0;
}

void checkNonManifold(const CheckInput &in, ProblemSink &sink)
{
    for (const SurfaceEdge &e : in.edges)
        if (e.triangles > 2) {
            const Surface &s = in.model.surfaces[e.surface];
            sink.add(validity_check::nonManifoldEdge, {s.name}, edgeMidpoint(in.model, e.key),
                     {QT_TRANSLATE_NOOP("stratamesh::Core",
                                        "an edge of surface %1 has %2 triangles around it"),
                      {s.name, std::to_string(e.triangles)}});
        }
}

void checkDegenerate(const CheckInput &in, ProblemSink &sink)
{
    const Model &model = in.model;
    for (std::size_t si = 0; si < model.surfaces.size(); ++si) {
        const Surface &s = model.surfaces[si];
        const std::vector<int> &g = model.surfaceVertexToGlobal[si];
        for (std::size_t ti = 0; ti < s.triangles.size(); ++ti) {
            const Triangle &t = s.triangles[ti];
            const char *why = nullptr;
            if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
                why = QT_TRANSLATE_NOOP("stratamesh::Core",
                                        "triangle %1 of %2 uses one vertex twice");
            else if (g[t[0]] == g[t[1]] || g[t[1]] == g[t[2]] || g[t[0]] == g[t[2]])
                why = QT_TRANSLATE_NOOP("stratamesh::Core",
                                        "triangle %1 of %2 has two corners at the same position");
            else if (CGAL::collinear(toPoint(s.vertices[t[0]]), toPoint(s.vertices[t[1]]),
                                     toPoint(s.vertices[t[2]])))
                why = QT_TRANSLATE_NOOP("stratamesh::Core",
                                        "triangle %1 of %2 has zero area (collinear corners)");
            if (why)
                sink.add(validity_check::degenerateTriangle, {s.name}, centroid(s, t),
                         {why, {std::to_string(ti), s.name}});
        }
    }
}

void checkDuplicates(const CheckInput &in, ProblemSink &sink)
{
    const Model &model = in.model;
    struct Entry {
        std::array<int, 3> key;
        int surface;
        int triangle;
    };
    std::vector<Entry> entries;
    entries.reserve(model.triangleCount());
    for (std::size_t si = 0; si < model.surfaces.size(); ++si) {
        const std::vector<int> &g = model.surfaceVertexToGlobal[si];
        const auto &tris = model.surfaces[si].triangles;
        for (std::size_t ti = 0; ti < tris.size(); ++ti) {
            std::array<int, 3> key{g[tris[ti][0]], g[tris[ti][1]], g[tris[ti][2]]};
            std::sort(key.begin(), key.end());
            if (key[0] != key[1] && key[1] != key[2])
                entries.push_back({key, static_cast<int>(si), static_cast<int>(ti)});
        }
    }
    std::sort(entries.begin(), entries.end(), [](const Entry &a, const Entry &b) {
        return a.key != b.key
                   ? a.key < b.key
                   : std::make_pair(a.surface, a.triangle) < std::make_pair(b.surface, b.triangle);
    });
    for (std::size_t i = 1; i < entries.size(); ++i) {
        if (entries[i].key != entries[i - 1].key)
            continue;
        std::size_t first = i - 1;
        while (first > 0 && entries[first - 1].key == entries[i].key)
            --first;
        const Surface &a = model.surfaces[entries[first].surface];
        const Surface &b = model.surfaces[entries[i].surface];
        const Vec3 c = (model.vertices[entries[i].key[0]] + model.vertices[entries[i].key[1]]
                        + model.vertices[entries[i].key[2]])
                       / 3.0;
        std::vector<std::string> names{a.name};
        if (&a != &b)
            names.push_back(b.name);
        sink.add(validity_check::duplicateTriangle, names, c,
                 {QT_TRANSLATE_NOOP(
                      "stratamesh::Core",
                      "triangle %1 of %2 lies on the same three points as triangle %3 of %4"),
                  {std::to_string(entries[i].triangle), b.name,
                   std::to_string(entries[first].triangle), a.name}});
    }
}

void checkOrientation(const CheckInput &in, ProblemSink &sink)
{
    struct HalfEdge {
        long long key; // local vertex ids
        bool forward;
    };
    std::vector<HalfEdge> halfEdges;
    for (const Surface &s : in.model.surfaces) {
        halfEdges.clear();
        for (const Triangle &t : s.triangles)
            for (int i = 0; i < 3; ++i)
                if (t[i] != t[(i + 1) % 3])
                    halfEdges.push_back({edgeKey(t[i], t[(i + 1) % 3]), t[i] < t[(i + 1) % 3]});
        std::sort(halfEdges.begin(), halfEdges.end(),
                  [](const HalfEdge &a, const HalfEdge &b) { return a.key < b.key; });
        for (std::size_t i = 0; i < halfEdges.size();) {
            std::size_t j = i;
            while (j < halfEdges.size() && halfEdges[j].key == halfEdges[i].key)
                ++j;
            if (j - i == 2 && halfEdges[i].forward == halfEdges[i + 1].forward) {
                const Vec3 mid = 0.5
                                 * (s.vertices[edgeKeyFirst(halfEdges[i].key)]
                                    + s.vertices[edgeKeySecond(halfEdges[i].key)]);
                sink.add(validity_check::inconsistentOrientation, {s.name}, mid,
                         {QT_TRANSLATE_NOOP("stratamesh::Core",
                                            "two triangles of surface %1 run their common edge the "
                                            "same way (flipped normals)"),
                          {s.name}});
            }
            i = j;
        }
    }
}

} // namespace

void checkSurfaceMeshes(const CheckInput &in, ProblemSink &sink)
{
    checkNonManifold(in, sink);
    checkDegenerate(in, sink);
    checkDuplicates(in, sink);
    checkOrientation(in, sink);
}

} // namespace stratamesh::validity_detail
