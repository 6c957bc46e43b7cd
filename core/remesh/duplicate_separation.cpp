#include "remesh/duplicate_separation.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <memory>

namespace stratamesh {

namespace {

using K = CGAL::Simple_cartesian<double>;
using TriangleList = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, TriangleList::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

K::Point_3 cg(const Vec3 &v) { return K::Point_3(v.x(), v.y(), v.z()); }

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

} // namespace

DuplicateSeparation separateDuplicateTriangles(EditableSoup &soup, const Model &input)
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
    for (const auto &[key, tris] : bySet) {
        if (tris.size() < 2)
            continue;
        ++result.duplicateGroups;
        std::vector<int> seenSurfaces;
        for (int t : tris) {
            const OutputTriangle tri = soup.triangle(t);
            if (std::find(seenSurfaces.begin(), seenSurfaces.end(), tri.surface) != seenSurfaces.end()) {
                soup.removeTriangle(t);
                ++result.removedTriangles;
                continue;
            }
            seenSurfaces.push_back(tri.surface);
            if (tri.surface < 0 || tri.surface >= static_cast<int>(input.surfaces.size()))
                continue;
            const SurfaceTree &st = treeOf(trees, input, tri.surface);
            if (!st.tree)
                continue;
            const Vec3 centroid = (soup.position(tri.v[0]) + soup.position(tri.v[1]) + soup.position(tri.v[2])) / 3.0;
            const Vec3 n = soup.normal(t).normalized();
            const K::Point_3 q = st.tree->closest_point(cg(centroid));
            const Vec3 target = centroid + n * n.dot(Vec3(q.x(), q.y(), q.z()) - centroid);
            OutputPoint p;
            p.position = target;
            p.origin = PointOrigin::Surface;
            p.surfaces = {tri.surface};
            const int v = soup.addPoint(p);
            soup.removeTriangle(t);
            for (int k = 0; k < 3; ++k)
                soup.addTriangle({tri.v[k], tri.v[(k + 1) % 3], v}, tri.surface);
            ++result.splitTriangles;
        }
    }
    return result;
}

} // namespace stratamesh
