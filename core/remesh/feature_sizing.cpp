#include "remesh/feature_sizing.h"

#include "common/error.h"
#include "complexity/segment_tree.h"
#include "complexity/triangle_tree.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <nanoflann.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace stratamesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

Kernel::Point_3 cgal(const Vec3 &p)
{
    return {p.x(), p.y(), p.z()};
}

// What each model vertex belongs to: a corner, else a line, else the surfaces holding it.
struct VertexFeatures {
    std::vector<int> corner;                      // corner index or -1
    std::vector<int> line;                        // line index or -1 (corners: -1)
    std::vector<std::vector<int>> surfaces;       // surfaces holding the vertex, sorted
    std::vector<std::vector<int>> surfaceCorners; // per surface: corners on its boundary, sorted
};

VertexFeatures classify(const Model &model)
{
    VertexFeatures f;
    const std::size_t n = model.vertices.size();
    f.corner.assign(n, -1);
    f.line.assign(n, -1);
    f.surfaces.resize(n);
    for (std::size_t c = 0; c < model.corners.size(); ++c)
        f.corner[model.corners[c].vertex] = static_cast<int>(c);
    for (std::size_t l = 0; l < model.lines.size(); ++l)
        for (int v : model.lines[l].vertices)
            if (f.corner[v] < 0 && f.line[v] < 0)
                f.line[v] = static_cast<int>(l);
    for (std::size_t s = 0; s < model.surfaces.size(); ++s)
        for (int g : model.surfaceVertexToGlobal[s])
            if (f.surfaces[g].empty() || f.surfaces[g].back() != static_cast<int>(s))
                f.surfaces[g].push_back(static_cast<int>(s));
    for (auto &list : f.surfaces) {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    f.surfaceCorners.resize(model.surfaces.size());
    for (std::size_t c = 0; c < model.corners.size(); ++c)
        for (int s : f.surfaces[model.corners[c].vertex])
            f.surfaceCorners[s].push_back(static_cast<int>(c));
    return f;
}

bool contains(const std::vector<int> &sorted, int value)
{
    return std::binary_search(sorted.begin(), sorted.end(), value);
}

// Features sharing a corner meet there: near it they are close without being a small feature.
// They count only where they run at less than asin(α) from each other, in a wedge that needles
// would fill.
struct SharedCorners {
    const Model &model;
    double alpha;
    // Distance d from p to a feature whose corners are `theirs`, or +inf when it shares a corner
    // c with `mine` and d ≥ α·|p − c|.
    double counted(double d, const Vec3 &p, const std::vector<int> &mine,
                   const std::vector<int> &theirs) const
    {
        for (int c : theirs)
            if (c >= 0 && std::find(mine.begin(), mine.end(), c) != mine.end()
                && d >= alpha * (p - model.vertices[model.corners[c].vertex]).norm())
                return kInfinity;
        return d;
    }
};

std::vector<int> lineCorners(const Line &line)
{
    std::vector<int> out;
    for (int c : line.corners)
        if (c >= 0)
            out.push_back(c);
    return out;
}

// The local feature size of every vertex, searched within `reach` (+inf beyond).
std::vector<double> featureDistances(const Model &model, const VertexFeatures &f, double reach,
                                     double alpha, Progress &progress)
{
    std::vector<int> allLines(model.lines.size()), allSurfaces(model.surfaces.size());
    std::iota(allLines.begin(), allLines.end(), 0);
    std::iota(allSurfaces.begin(), allSurfaces.end(), 0);
    const SegmentTree segments(model, allLines);
    const TriangleTree triangles(model, allSurfaces);
    std::vector<std::vector<int>> cornersOfLine(model.lines.size());
    for (std::size_t l = 0; l < model.lines.size(); ++l)
        cornersOfLine[l] = lineCorners(model.lines[l]);
    const SharedCorners shared{model, alpha};

    std::vector<double> lfs(model.vertices.size(), kInfinity);
    const std::size_t n = model.vertices.size();
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t v) {
        // Surface-interior vertices away from every line cannot be close to a foreign corner or
        // line unless one lies within reach: the box query below finds them all the same.
        const Vec3 &p = model.vertices[v];
        const int corner = f.corner[v];
        const int line = f.line[v];
        // The corners of this vertex's own feature, for the floor near shared corners.
        std::vector<int> mine;
        if (corner >= 0)
            mine.push_back(corner);
        else if (line >= 0)
            mine = cornersOfLine[line];
        else
            for (int s : f.surfaces[v])
                mine.insert(mine.end(), f.surfaceCorners[s].begin(), f.surfaceCorners[s].end());
        double best = kInfinity;
        // Only features nearer than the best so far can lower it, and they meet this box (the
        // search box of a line vertex on a model split to 1/64 of the edge length near close
        // features listed thousands of triangles: 60 % of a remesh with pinned features).
        auto searchBox = [&] {
            const double r = std::min(reach, best);
            return Box3(p - Vec3::Constant(r), p + Vec3::Constant(r));
        };
        // Corners.
        for (std::size_t c = 0; c < model.corners.size(); ++c) {
            if (static_cast<int>(c) == corner)
                continue;
            const Vec3 &q = model.vertices[model.corners[c].vertex];
            if ((q - p).cwiseAbs().maxCoeff() > reach)
                continue;
            if (line >= 0
                && std::find(cornersOfLine[line].begin(), cornersOfLine[line].end(),
                             static_cast<int>(c))
                       != cornersOfLine[line].end())
                continue;
            if (corner < 0 && line < 0) {
                bool onBoundary = false;
                for (int s : f.surfaces[v])
                    onBoundary = onBoundary || contains(f.surfaceCorners[s], static_cast<int>(c));
                if (onBoundary)
                    continue;
            }
            best = std::min(best, (q - p).norm());
        }
        // Line segments.
        int lastLine = -1;
        bool skipLine = false;
        for (const SegmentRef &ref : segments.segmentsInBox(searchBox())) {
            if (ref.line != lastLine) {
                lastLine = ref.line;
                const Line &other = model.lines[ref.line];
                if (corner >= 0)
                    skipLine = std::find(other.corners.begin(), other.corners.end(), corner)
                               != other.corners.end();
                else if (line >= 0)
                    skipLine = ref.line == line;
                else {
                    skipLine = false;
                    for (int s : f.surfaces[v])
                        skipLine = skipLine || contains(model.surfaces[s].lines, ref.line);
                }
            }
            if (skipLine)
                continue;
            const auto [a, b] = lineSegment(model.lines[ref.line], ref.segment);
            const double d = std::sqrt(CGAL::squared_distance(
                cgal(p), Kernel::Segment_3(cgal(model.vertices[a]), cgal(model.vertices[b]))));
            if (d < best)
                best = std::min(best, shared.counted(d, p, mine, cornersOfLine[ref.line]));
        }
        // Surface triangles, for corners and line vertices only.
        if (corner >= 0 || line >= 0) {
            int lastSurface = -1;
            bool skipSurface = false;
            for (const TriangleRef &ref : triangles.trianglesInBox(searchBox())) {
                if (ref.surface != lastSurface) {
                    lastSurface = ref.surface;
                    skipSurface = corner >= 0 ? contains(f.surfaces[v], ref.surface)
                                              : contains(model.lines[line].surfaces, ref.surface);
                }
                if (skipSurface)
                    continue;
                const Surface &s = model.surfaces[ref.surface];
                const Triangle &t = s.triangles[ref.triangle];
                const auto &global = model.surfaceVertexToGlobal[ref.surface];
                const double d = std::sqrt(CGAL::squared_distance(
                    cgal(p), Kernel::Triangle_3(cgal(model.vertices[global[t[0]]]),
                                                cgal(model.vertices[global[t[1]]]),
                                                cgal(model.vertices[global[t[2]]]))));
                if (d < best)
                    best =
                        std::min(best, shared.counted(d, p, mine, f.surfaceCorners[ref.surface]));
            }
        }
        lfs[v] = best;
    });
    progress.tick(1.0);
    return lfs;
}

struct PointCloud {
    const std::vector<Vec3> &points;
    std::size_t kdtree_get_point_count() const { return points.size(); }
    double kdtree_get_pt(std::size_t i, std::size_t d) const { return points[i][d]; }
    template <class Box>
    bool kdtree_get_bbox(Box &) const
    {
        return false;
    }
};
using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>,
                                                   PointCloud, 3, std::size_t>;

// h(p) = min over q of h(q) + g·|p − q|, from the vertices smaller than h0.
void grade(const std::vector<Vec3> &points, double h0, double g, std::vector<double> &h)
{
    std::vector<std::size_t> sources;
    for (std::size_t v = 0; v < h.size(); ++v)
        if (h[v] < h0)
            sources.push_back(v);
    if (sources.empty() || !(g > 0.0))
        return;
    // Smallest first: a source already graded below its own size by a smaller one adds nothing.
    std::sort(sources.begin(), sources.end(),
              [&h](std::size_t a, std::size_t b) { return h[a] < h[b]; });
    PointCloud cloud{points};
    KdTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    const std::vector<double> raw = h;
    std::vector<std::pair<std::size_t, double>> found;
    nanoflann::SearchParams unsorted;
    unsorted.sorted = false;
    for (std::size_t s : sources) {
        if (h[s] < raw[s])
            continue; // a smaller source reaches everything this one would
        const double radius = (h0 - h[s]) / g;
        found.clear();
        tree.radiusSearch(points[s].data(), radius * radius, found, unsorted);
        for (const auto &item : found) {
            const double candidate = h[s] + g * std::sqrt(item.second);
            if (candidate < h[item.first])
                h[item.first] = candidate;
        }
    }
}

} // namespace

std::vector<double> localFeatureSizes(const Model &model, double reach, double wedgeSine,
                                      Progress &progress)
{
    if (!model.hasTopology())
        throw InputError("feature sizing: the model has no topology");
    return featureDistances(model, classify(model), reach, wedgeSine, progress);
}

FeatureSizing sizingFromLfs(const Model &model, std::vector<double> lfs,
                            const FeatureSizingParams &params)
{
    if (!(params.edgeLength > 0.0) || !std::isfinite(params.edgeLength))
        throw InputError("feature sizing: the edge length must be positive");
    const double h0 = params.edgeLength;
    const double kappa = params.lfsFactor > 0.0 ? params.lfsFactor : 1.0;
    const double hMin = std::clamp(params.minEdgeLength, 0.0, h0);
    FeatureSizing out;
    out.lfs = std::move(lfs);
    out.size.assign(model.vertices.size(), h0);
    out.smallestLfs = kInfinity;
    for (std::size_t v = 0; v < out.lfs.size() && v < out.size.size(); ++v) {
        const double d = out.lfs[v];
        if (!std::isfinite(d))
            continue;
        out.smallestLfs = std::min(out.smallestLfs, d);
        // Features the user asked to merge keep the cells that merge them.
        if (params.dResolution > 0.0 && d < params.dResolution)
            continue;
        out.size[v] = std::clamp(kappa * d, hMin, h0);
    }
    grade(model.vertices, h0, params.gradation, out.size);
    for (double h : out.size)
        out.refinedVertices += h < h0 ? 1 : 0;
    // ∫ sqrt(ρ) dA with ρ = (h0/h)⁴ interpolated linearly, as the CVT sees it: vertices and
    // centroid.
    double area = 0.0, weighted = 0.0;
    for (std::size_t s = 0; s < model.surfaces.size(); ++s) {
        const auto &global = model.surfaceVertexToGlobal[s];
        for (const Triangle &t : model.surfaces[s].triangles) {
            const Vec3 &a = model.vertices[global[t[0]]], &b = model.vertices[global[t[1]]],
                       &c = model.vertices[global[t[2]]];
            const double a2 = 0.5 * (b - a).cross(c - a).norm();
            double mean = 0.0, root = 0.0;
            for (int k = 0; k < 3; ++k) {
                const double rho = std::pow(h0 / out.size[global[t[k]]], 4);
                mean += rho / 3.0;
                root += std::sqrt(rho) / 6.0;
            }
            weighted += a2 * (root + 0.5 * std::sqrt(mean));
            area += a2;
        }
    }
    out.siteFactor = area > 0.0 ? std::max(1.0, weighted / area) : 1.0;
    return out;
}

FeatureSizing computeFeatureSizing(const Model &model, const FeatureSizingParams &params,
                                   Progress &progress)
{
    if (!(params.edgeLength > 0.0) || !std::isfinite(params.edgeLength))
        throw InputError("feature sizing: the edge length must be positive");
    const double kappa = params.lfsFactor > 0.0 ? params.lfsFactor : 1.0;
    Progress search(progress, 0.0, 0.8, "local feature size");
    std::vector<double> lfs =
        localFeatureSizes(model, params.edgeLength / kappa, params.wedgeSine, search);
    progress.tick(0.8, "grading");
    FeatureSizing out = sizingFromLfs(model, std::move(lfs), params);
    progress.tick(1.0);
    return out;
}

std::vector<double> sizingDensity(const FeatureSizing &sizing, double edgeLength)
{
    std::vector<double> rho(sizing.size.size(), 1.0);
    for (std::size_t v = 0; v < rho.size(); ++v)
        rho[v] = std::pow(edgeLength / sizing.size[v], 4);
    return rho;
}

} // namespace stratamesh
