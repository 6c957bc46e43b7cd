#include "remesh/duplicate_separation.h"

#include "common/translate_noop.h"
#include "quality/triangle_quality.h"
#include "remesh/intersection_repair.h"
#include "remesh/mesh_cleanup.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <memory>

namespace stratamesh {

namespace {

constexpr double kSliverQuality = 0.1;

using K = CGAL::Simple_cartesian<double>;
using TriangleList = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, TriangleList::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

K::Point_3 cg(const Vec3 &v)
{
    return K::Point_3(v.x(), v.y(), v.z());
}

struct SurfaceTree {
    TriangleList triangles;
    std::unique_ptr<Tree> tree;
};

const SurfaceTree &treeOf(std::map<int, SurfaceTree> &cache, const Model &input, int surface)
{
    auto it = cache.find(surface);
    if (it != cache.end())
        return it->second;
    SurfaceTree &st = cache[surface];
    const Surface &s = input.surfaces[surface];
    for (const Triangle &t : s.triangles) {
        K::Triangle_3 tri(cg(s.vertices[t[0]]), cg(s.vertices[t[1]]), cg(s.vertices[t[2]]));
        if (!tri.is_degenerate())
            st.triangles.push_back(tri);
    }
    if (!st.triangles.empty()) {
        st.tree = std::make_unique<Tree>(st.triangles.begin(), st.triangles.end());
        st.tree->accelerate_distance_queries();
    }
    return st;
}

Vec3 closestPoint(const SurfaceTree &st, const Vec3 &x)
{
    const K::Point_3 q = st.tree->closest_point(cg(x));
    return Vec3(q.x(), q.y(), q.z());
}

// Last resort when the surfaces meet under the whole triangle (their closest points on their
// common line): each copy's vertex goes off the triangle's centroid along its normal, towards the
// nearest vertex of its surface off the lines, by at most a quarter of the triangle's smallest
// altitude, so each fan stays a fan and the copies differ.
std::vector<Vec3> offsetTowardsSurfaces(const Model &input, const std::vector<int> &surfaces,
                                        const Vec3 &a, const Vec3 &b, const Vec3 &c,
                                        const std::vector<char> &onLine)
{
    const Vec3 normal = (b - a).cross(c - a);
    const double area2 = normal.norm();
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    if (!(area2 > 0.0) || !(longest > 0.0))
        return {};
    const Vec3 n = normal / area2;
    const double limit = 0.25 * area2 / longest; // a quarter of the smallest altitude
    const Vec3 centroid = (a + b + c) / 3.0;
    std::vector<double> heights;
    for (int surface : surfaces) {
        const Surface &s = input.surfaces[surface];
        double bestDistance = std::numeric_limits<double>::max();
        double height = 0.0;
        for (std::size_t v = 0; v < s.vertices.size(); ++v) {
            if (input.hasTopology() && onLine[input.surfaceVertexToGlobal[surface][v]])
                continue;
            const double d = (s.vertices[v] - centroid).squaredNorm();
            if (d < bestDistance) {
                bestDistance = d;
                height = std::clamp(n.dot(s.vertices[v] - centroid), -limit, limit);
            }
        }
        // Equal heights (or none found) are spread so that no two copies coincide.
        for (double h : heights)
            if (std::abs(h - height) < 1e-6 * limit)
                height = std::clamp(height + (height > 0 ? -0.25 : 0.25) * limit, -limit, limit);
        heights.push_back(height);
    }
    std::vector<Vec3> targets;
    for (double h : heights)
        targets.push_back(centroid + h * n);
    for (std::size_t i = 0; i < targets.size(); ++i)
        for (std::size_t j = i + 1; j < targets.size(); ++j)
            if (targets[i] == targets[j])
                return {};
    return targets;
}

// A duplicated sliver (a cap or needle shared by two surfaces, Fig 4.9 along two contacts at
// once) would only give slivers again when split: its shortest edge is collapsed instead, which
// removes all its copies together and keeps every contact sealed (Algorithm 4.4).
bool collapseSliver(EditableSoup &soup, const Model &input, int t, SimplificationLedger &ledger)
{
    if (soup.quality(t) >= kSliverQuality)
        return false;
    const OutputTriangle tri = soup.triangle(t);
    int e = 0;
    for (int k = 1; k < 3; ++k)
        if ((soup.position(tri.v[(k + 1) % 3]) - soup.position(tri.v[k])).squaredNorm()
            < (soup.position(tri.v[(e + 1) % 3]) - soup.position(tri.v[e])).squaredNorm())
            e = k;
    int u = tri.v[e], w = tri.v[(e + 1) % 3];
    // The vertex that may move least stays: corners over line vertices over interior ones.
    const auto rank = [&](int v) { return static_cast<int>(soup.vertexClass(v)); };
    if (rank(u) > rank(w))
        std::swap(u, w);
    const Vec3 target = rank(u) == rank(w) && rank(w) < static_cast<int>(VertexClass::Fixed)
                            ? Vec3(0.5 * (soup.position(u) + soup.position(w)))
                            : soup.position(w);
    const double moved = (soup.position(u) - target).norm();
    LedgerRecord r;
    r.kind = LedgerKind::DegenerateContactTriangle;
    r.inputs = inputEntitiesOf(soup, input, {tri.v[0], tri.v[1], tri.v[2]});
    r.outputs = {vertexRef(w)};
    r.position = target;
    r.size = moved;
    r.sizeMeaning = "distance";
    setNote(r, {QT_TRANSLATE_NOOP(
                    "stratamesh::Core",
                    "sliver shared by two surfaces: its shortest edge collapsed (Alg 4.4)"),
                {}});
    if (!soup.collapse(u, w, target, 0.0))
        return false;
    ledger.push_back(r);
    return true;
}

} // namespace

DuplicateSeparation separateDuplicateTriangles(EditableSoup &soup, const Model &input,
                                               SimplificationLedger &ledger)
{
    DuplicateSeparation result;
    std::map<std::array<int, 3>, std::vector<int>> bySet;
    for (int t = 0; t < soup.triangleCapacity(); ++t) {
        if (!soup.alive(t))
            continue;
        std::array<int, 3> key = soup.triangle(t).v;
        std::sort(key.begin(), key.end());
        bySet[key].push_back(t);
    }
    std::map<int, SurfaceTree> trees;
    std::vector<char> onLine(input.vertices.size(), 0);
    for (const Line &l : input.lines)
        for (int v : l.vertices)
            onLine[v] = 1;
    for (const auto &[key, tris] : bySet) {
        if (tris.size() < 2)
            continue;
        ++result.duplicateGroups;
        std::vector<int> copies, surfaces;
        for (int t : tris) {
            const int surface = soup.triangle(t).surface;
            if (std::find(surfaces.begin(), surfaces.end(), surface) != surfaces.end()
                || surface < 0 || surface >= static_cast<int>(input.surfaces.size())
                || !treeOf(trees, input, surface).tree) {
                soup.removeTriangle(t); // an exact copy inside one surface
                ++result.removedTriangles;
                continue;
            }
            copies.push_back(t);
            surfaces.push_back(surface);
        }
        if (copies.size() < 2)
            continue;
        if (collapseSliver(soup, input, copies.front(), ledger)) {
            ++result.collapsedSlivers; // every copy went with its shortest edge
            continue;
        }
        const OutputTriangle first = soup.triangle(copies.front());
        const Vec3 a = soup.position(first.v[0]), b = soup.position(first.v[1]),
                   c = soup.position(first.v[2]);
        const Vec3 centroid = (a + b + c) / 3.0;
        // Where each surface is under the triangle, along its normal through a few interior
        // points; keep the point whose fans are the best shaped among those that separate the
        // copies (then the farthest apart), so the copies come apart even when the surfaces meet
        // along one of the triangle's lines, without slivers.
        const Vec3 n = (b - a).cross(c - a).normalized();
        const double tiny = 1e-9 * std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
        struct Candidate {
            double shape, separation;
            std::vector<Vec3> targets;
        };
        std::vector<Candidate> candidates;
        std::vector<Vec3> probes{centroid};
        for (const Vec3 &corner : {a, b, c})
            for (double f : {0.25, 0.5})
                probes.push_back(centroid + f * (corner - centroid));
        for (const Vec3 &probe : probes) {
            Candidate cand{1.0, std::numeric_limits<double>::max(), {}};
            for (int surface : surfaces)
                cand.targets.push_back(
                    probe + n * n.dot(closestPoint(treeOf(trees, input, surface), probe) - probe));
            for (std::size_t i = 0; i < cand.targets.size(); ++i) {
                for (std::size_t j = i + 1; j < cand.targets.size(); ++j)
                    cand.separation =
                        std::min(cand.separation, (cand.targets[i] - cand.targets[j]).norm());
                cand.shape = std::min({cand.shape, triangleQuality(a, b, cand.targets[i]),
                                       triangleQuality(b, c, cand.targets[i]),
                                       triangleQuality(c, a, cand.targets[i])});
            }
            if (cand.separation > tiny)
                candidates.push_back(std::move(cand));
        }
        std::sort(candidates.begin(), candidates.end(), [](const Candidate &x, const Candidate &y) {
            return x.shape != y.shape ? x.shape > y.shape : x.separation > y.separation;
        });
        if (candidates.empty()) {
            std::vector<Vec3> forced = offsetTowardsSurfaces(input, surfaces, a, b, c, onLine);
            ++result.forced;
            if (forced.empty()) {
                ++result.unseparated;
                continue;
            }
            candidates.push_back({0.0, 0.0, std::move(forced)});
        }
        // The best-shaped split that crosses nothing around it (else the one crossing least).
        std::vector<std::array<int, 3>> copyCorners;
        for (int t : copies)
            copyCorners.push_back(soup.triangle(t).v);
        // Splits are tried in place and undone (the copies come back as new triangles; the
        // vertices of an undone split stay unused and are dropped with the result).
        auto split = [&](const Candidate &cand) {
            std::vector<int> added;
            for (std::size_t i = 0; i < copies.size(); ++i) {
                OutputPoint p;
                p.position = cand.targets[i];
                p.origin = PointOrigin::Surface;
                p.surfaces = {surfaces[i]};
                const int v = soup.addPoint(p);
                soup.removeTriangle(copies[i]);
                for (int k = 0; k < 3; ++k)
                    soup.addTriangle({copyCorners[i][k], copyCorners[i][(k + 1) % 3], v},
                                     surfaces[i]);
                added.push_back(v);
            }
            return added;
        };
        auto undo = [&](const std::vector<int> &added) {
            for (std::size_t i = 0; i < copies.size(); ++i) {
                const std::vector<int> fan = soup.vertexTriangles(added[i]);
                for (int t : fan)
                    soup.removeTriangle(t);
                copies[i] = soup.addTriangle(copyCorners[i], surfaces[i]);
            }
        };
        int leastCrossings = std::numeric_limits<int>::max();
        std::size_t chosen = 0;
        for (std::size_t c = 0; c < candidates.size(); ++c) {
            const std::vector<int> added = split(candidates[c]);
            const int crossings = intersectionsAroundVertices(soup, added);
            if (crossings == 0) {
                leastCrossings = 0;
                break;
            }
            undo(added);
            if (crossings < leastCrossings) {
                leastCrossings = crossings;
                chosen = c;
            }
        }
        if (leastCrossings > 0)
            split(candidates[chosen]);
        result.splitTriangles += static_cast<int>(copies.size());
    }
    return result;
}

} // namespace stratamesh
