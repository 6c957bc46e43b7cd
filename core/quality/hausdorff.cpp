#include "quality/hausdorff.h"

#include "common/error.h"
#include "model/bounding_box.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Geometry>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace stratamesh {

namespace {

using K = CGAL::Simple_cartesian<double>;
using CgalTriangle = K::Triangle_3;
using TriangleList = std::vector<CgalTriangle>;
using Primitive = CGAL::AABB_triangle_primitive<K, TriangleList::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

K::Point_3 toCgal(const Vec3 &v)
{
    return K::Point_3(v.x(), v.y(), v.z());
}

// Non-degenerate triangles only: CGAL's closest-point query has no meaning on a segment-like
// triangle, and a degenerate triangle adds nothing to a surface's point set that its
// neighbours' edges do not already hold.
struct ModelTree {
    TriangleList triangles;
    std::unique_ptr<Tree> tree;

    explicit ModelTree(const Model &model)
    {
        for (const Surface &s : model.surfaces)
            for (const Triangle &t : s.triangles) {
                CgalTriangle ct(toCgal(s.vertices[t[0]]), toCgal(s.vertices[t[1]]),
                                toCgal(s.vertices[t[2]]));
                if (!ct.is_degenerate())
                    triangles.push_back(ct);
            }
        if (triangles.empty())
            throw InputError("Hausdorff distance: model '" + model.name + "' has no triangle");
        tree = std::make_unique<Tree>(triangles.begin(), triangles.end());
        tree->accelerate_distance_queries();
    }

    double distance(const Vec3 &p) const { return std::sqrt(tree->squared_distance(toCgal(p))); }
};

double totalArea(const Model &m)
{
    double area = 0.0;
    for (const Surface &s : m.surfaces)
        for (const Triangle &t : s.triangles)
            area += 0.5
                    * (s.vertices[t[1]] - s.vertices[t[0]])
                          .cross(s.vertices[t[2]] - s.vertices[t[0]])
                          .norm();
    return area;
}

// Vertices plus, per triangle, a barycentric grid of level m with about `samples × area share`
// points (Metro's "similar triangles" sampling).
std::vector<Vec3> samplePoints(const Model &m, int samples)
{
    std::vector<Vec3> pts;
    const double area = totalArea(m);
    for (const Surface &s : m.surfaces) {
        pts.insert(pts.end(), s.vertices.begin(), s.vertices.end());
        for (const Triangle &t : s.triangles) {
            const Vec3 &a = s.vertices[t[0]], &b = s.vertices[t[1]], &c = s.vertices[t[2]];
            const double share = area > 0.0 ? 0.5 * (b - a).cross(c - a).norm() / area : 0.0;
            const double wanted = share * samples;
            const int level = std::max(1, static_cast<int>(std::ceil(std::sqrt(2.0 * wanted))));
            pts.push_back((a + b + c) / 3.0);
            if (level == 1)
                continue; // the corners are already in as vertices
            for (int i = 0; i <= level; ++i)
                for (int j = 0; i + j <= level; ++j)
                    pts.push_back(a + (b - a) * (double(i) / level)
                                  + (c - a) * (double(j) / level));
        }
    }
    return pts;
}

// Ticks from the TBB workers every 1024 points (0.1 s on modelA5 on a loaded machine), so a cancel
// acts quickly.
std::vector<double> parallelDistances(const ModelTree &tree, const std::vector<Vec3> &pts,
                                      Progress &progress = Progress::none(),
                                      const std::string &stage = {})
{
    std::vector<double> d(pts.size());
    ProgressCounter counter(progress, pts.size(), 1024, stage);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pts.size(), 1024),
                      [&](const tbb::blocked_range<std::size_t> &r) {
                          for (std::size_t i = r.begin(); i < r.end(); ++i)
                              d[i] = tree.distance(pts[i]);
                          counter.add(r.size());
                      });
    return d;
}

void maxAndMean(const std::vector<double> &d, double &maxOut, double &meanOut)
{
    maxOut = 0.0;
    double sum = 0.0;
    for (double v : d) {
        maxOut = std::max(maxOut, v);
        sum += v;
    }
    meanOut = d.empty() ? 0.0 : sum / static_cast<double>(d.size());
}

} // namespace

std::vector<double> distancesToModel(const Model &model, const std::vector<Vec3> &points)
{
    const ModelTree tree(model);
    return parallelDistances(tree, points);
}

HausdorffResult hausdorffDistance(const Model &a, const Model &b, const HausdorffParams &params,
                                  Progress &progress)
{
    HausdorffResult r;
    const ModelTree treeA(a);
    const ModelTree treeB(b);
    progress.tick(0.1, "Hausdorff distance: input to output");
    {
        Progress part(progress, 0.1, 0.5);
        maxAndMean(parallelDistances(treeB, samplePoints(a, params.samplesPerSide), part,
                                     "Hausdorff distance: input to output"),
                   r.aToB, r.meanAToB);
    }
    progress.tick(0.5, "Hausdorff distance: output to input");
    {
        Progress part(progress, 0.5, 0.9);
        maxAndMean(parallelDistances(treeA, samplePoints(b, params.samplesPerSide), part,
                                     "Hausdorff distance: output to input"),
                   r.bToA, r.meanBToA);
    }
    r.symmetric = std::max(r.aToB, r.bToA);
    r.bboxDiagonal = boundingBoxDiagonal(a);
    r.symmetricPctBbox = r.bboxDiagonal > 0.0 ? 100.0 * r.symmetric / r.bboxDiagonal : 0.0;
    progress.tick(0.9, "Hausdorff distance: per vertex");
    r.vertexDistanceBToA.reserve(b.surfaces.size());
    std::size_t total = 0, done = 0;
    for (const Surface &s : b.surfaces)
        total += s.vertices.size();
    for (const Surface &s : b.surfaces) {
        const double from = 0.9 + 0.1 * done / std::max<std::size_t>(total, 1);
        done += s.vertices.size();
        Progress part(progress, from, 0.9 + 0.1 * done / std::max<std::size_t>(total, 1));
        part.tick(0.0, "Hausdorff distance: per vertex");
        r.vertexDistanceBToA.push_back(
            parallelDistances(treeA, s.vertices, part, "Hausdorff distance: per vertex"));
    }
    progress.tick(1.0, "Hausdorff distance");
    return r;
}

} // namespace stratamesh
