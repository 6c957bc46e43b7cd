#include "remesh/triangle_intersections.h"

#include "model/shared_edge_overlap.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace stratamesh {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P3 = K::Point_3;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int>;

P3 toCgal(const Vec3 &v)
{
    return P3(v.x(), v.y(), v.z());
}

bool isDegenerate(const std::vector<Vec3> &pts, const Triangle &t)
{
    return CGAL::collinear(toCgal(pts[t[0]]), toCgal(pts[t[1]]), toCgal(pts[t[2]]));
}

} // namespace

bool trianglesIntersect(const std::vector<Vec3> &pts, const Triangle &a, const Triangle &b)
{
    std::array<int, 3> sharedA{-1, -1, -1}; // for each corner of a, its index in b or -1
    int shared = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (a[i] == b[j]) {
                sharedA[i] = j;
                ++shared;
            }
    const K::Triangle_3 ta(toCgal(pts[a[0]]), toCgal(pts[a[1]]), toCgal(pts[a[2]]));
    const K::Triangle_3 tb(toCgal(pts[b[0]]), toCgal(pts[b[1]]), toCgal(pts[b[2]]));
    if (shared == 0)
        return CGAL::do_intersect(ta, tb);
    if (shared == 3)
        return true;
    if (shared == 1) {
        // They meet beyond the common vertex iff the edge opposite it in one crosses the other.
        int i = 0;
        while (sharedA[i] < 0)
            ++i;
        const int j = sharedA[i];
        const K::Segment_3 oppA(toCgal(pts[a[(i + 1) % 3]]), toCgal(pts[a[(i + 2) % 3]]));
        const K::Segment_3 oppB(toCgal(pts[b[(j + 1) % 3]]), toCgal(pts[b[(j + 2) % 3]]));
        return CGAL::do_intersect(oppA, tb) || CGAL::do_intersect(oppB, ta);
    }
    // A common edge: only coplanar triangles folded onto the same side overlap.
    int i = 0;
    while (sharedA[i] >= 0)
        ++i;
    int j = 0;
    while (j == sharedA[0] || j == sharedA[1] || j == sharedA[2])
        ++j;
    return sharedEdgeTrianglesOverlap(pts[a[(i + 1) % 3]], pts[a[(i + 2) % 3]], pts[a[i]],
                                      pts[b[j]]);
}

std::vector<std::pair<int, int>> findIntersectingTriangles(const std::vector<Vec3> &pts,
                                                           const std::vector<Triangle> &tris,
                                                           std::vector<int> *degenerate)
{
    std::vector<Box> boxes;
    boxes.reserve(tris.size());
    for (int t = 0; t < static_cast<int>(tris.size()); ++t) {
        if (isDegenerate(pts, tris[t])) {
            if (degenerate)
                degenerate->push_back(t);
            continue;
        }
        const auto bb = toCgal(pts[tris[t][0]]).bbox() + toCgal(pts[tris[t][1]]).bbox()
                        + toCgal(pts[tris[t][2]]).bbox();
        boxes.emplace_back(bb, t);
    }
    std::vector<std::pair<int, int>> candidates;
    auto report = [&](const Box &a, const Box &b) {
        candidates.emplace_back(std::min(a.info(), b.info()), std::max(a.info(), b.info()));
    };
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), report);
    // Deciding the pairs is most of the cost (adjacent triangles' boxes always overlap), and
    // each decision is independent: in parallel, collected in the candidates' order.
    std::vector<char> meets(candidates.size(), 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, candidates.size(), 1024),
                      [&](const tbb::blocked_range<std::size_t> &r) {
                          for (std::size_t c = r.begin(); c < r.end(); ++c)
                              meets[c] = trianglesIntersect(pts, tris[candidates[c].first],
                                                            tris[candidates[c].second]);
                      });
    std::vector<std::pair<int, int>> result;
    for (std::size_t c = 0; c < candidates.size(); ++c)
        if (meets[c])
            result.push_back(candidates[c]);
    std::sort(result.begin(), result.end());
    result.erase(std::unique(result.begin(), result.end()), result.end());
    return result;
}

} // namespace stratamesh
