#include "volume/plc.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "model/topology.h"
#include "volume/region_winding.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

namespace stratamesh {

namespace {

// Enough candidates to get past a few unlucky rays (through an edge, into a thin sliver of the
// region) while keeping the cost at a few passes over the model's triangles per region.
constexpr int kSeedCandidates = 8;

struct Ray {
    Vec3 origin;
    Vec3 direction; // unit
};

// Möller–Trumbore ray/triangle distance, or nothing when the ray misses or runs in the plane.
std::optional<double> hitDistance(const Ray &ray, const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    const Vec3 e1 = b - a, e2 = c - a;
    const Vec3 p = ray.direction.cross(e2);
    const double det = e1.dot(p);
    const double scale = e1.norm() * e2.norm();
    if (!(std::abs(det) > 1e-14 * scale))
        return std::nullopt;
    const Vec3 s = ray.origin - a;
    const double u = s.dot(p) / det;
    if (u < 0.0 || u > 1.0)
        return std::nullopt;
    const Vec3 q = s.cross(e1);
    const double v = ray.direction.dot(q) / det;
    if (v < 0.0 || u + v > 1.0)
        return std::nullopt;
    return e2.dot(q) / det;
}

// Distance to the first triangle of the model hit by the ray, skipping the one it starts from.
double firstHit(const Model &model, const Ray &ray, int startSurface, int startTriangle,
                double minDistance)
{
    double best = std::numeric_limits<double>::infinity();
    for (int s = 0; s < static_cast<int>(model.surfaces.size()); ++s) {
        const Surface &surface = model.surfaces[s];
        for (int t = 0; t < static_cast<int>(surface.triangles.size()); ++t) {
            if (s == startSurface && t == startTriangle)
                continue;
            const Triangle &tri = surface.triangles[t];
            const auto d = hitDistance(ray, surface.vertices[tri[0]], surface.vertices[tri[1]],
                                       surface.vertices[tri[2]]);
            if (d && *d > minDistance && *d < best)
                best = *d;
        }
    }
    return best;
}

double modelDiagonal(const Model &model)
{
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max());
    Vec3 hi = Vec3::Constant(std::numeric_limits<double>::lowest());
    for (const Surface &s : model.surfaces)
        for (const Vec3 &p : s.vertices) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
    return lo.x() <= hi.x() ? (hi - lo).norm() : 0.0;
}

} // namespace

PlcRegion regionSeed(const Model &model, int region)
{
    const Region &r = model.regions.at(region);
    struct Candidate {
        int surface, triangle;
        bool positive;
        double area;
    };
    std::vector<Candidate> candidates;
    for (const RegionSide &side : r.boundaries) {
        if (side.surface < 0 || side.surface >= static_cast<int>(model.surfaces.size()))
            throw InputError(
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "region %1 lists surface %2 which does not exist"),
                            {r.name, std::to_string(side.surface)}});
        const Surface &s = model.surfaces[side.surface];
        for (int t = 0; t < static_cast<int>(s.triangles.size()); ++t) {
            const Triangle &tri = s.triangles[t];
            const double area = (s.vertices[tri[1]] - s.vertices[tri[0]])
                                    .cross(s.vertices[tri[2]] - s.vertices[tri[0]])
                                    .norm();
            if (area > 0.0)
                candidates.push_back({side.surface, t, side.positive, area});
        }
    }
    // Largest first: their centroids are farthest from edges, so rays rarely graze a neighbour.
    const std::size_t keep = std::min<std::size_t>(candidates.size(), kSeedCandidates);
    std::partial_sort(candidates.begin(), candidates.begin() + keep, candidates.end(),
                      [](const Candidate &a, const Candidate &b) { return a.area > b.area; });

    const double minDistance = 1e-12 * modelDiagonal(model);
    PlcRegion best;
    best.name = r.name;
    best.attribute = region + 1;
    bool found = false;
    auto tryCandidate = [&](const Candidate &c) {
        const Surface &s = model.surfaces[c.surface];
        const Triangle &tri = s.triangles[c.triangle];
        const Vec3 &a = s.vertices[tri[0]], &b = s.vertices[tri[1]], &d = s.vertices[tri[2]];
        Vec3 normal = (b - a).cross(d - a).normalized();
        if (!c.positive)
            normal = -normal;
        const Ray ray{(a + b + d) / 3.0, normal};
        const double hit = firstHit(model, ray, c.surface, c.triangle, minDistance);
        if (!std::isfinite(hit) || hit / 2.0 <= best.clearance)
            return;
        const Vec3 seed = ray.origin + 0.5 * hit * ray.direction;
        if (std::abs(regionWindingNumber(model, region, seed) - 1.0) > 1e-3)
            return;
        best.seed = seed;
        best.clearance = hit / 2.0;
        found = true;
    };
    for (std::size_t i = 0; i < keep; ++i)
        tryCandidate(candidates[i]);
    // Fall back to every other triangle, stopping at the first that works.
    for (std::size_t i = keep; i < candidates.size() && !found; ++i)
        tryCandidate(candidates[i]);
    if (!found)
        throw InputError(
            MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "no point strictly inside region %1 was found (is its "
                                          "boundary closed and consistently oriented?)"),
                        {r.name}});
    return best;
}

Plc buildPlc(const Model &input)
{
    if (input.surfaces.empty())
        throw InputError(MessageText{
            QT_TRANSLATE_NOOP("stratamesh::Core", "the model has no surface to tetrahedralise"),
            {}});
    const Model model = input.hasTopology() ? input : recoverTopology(input);

    Plc plc;
    // Only the points of some triangle, in their order: TetGen crashes on a free point lying on
    // a facet.
    std::vector<int> pointOf(model.vertices.size(), -1);
    for (int s = 0; s < static_cast<int>(model.surfaces.size()); ++s)
        for (const Triangle &t : model.surfaces[s].triangles)
            for (int v : t)
                pointOf[model.surfaceVertexToGlobal[s][v]] = 0;
    for (std::size_t v = 0; v < pointOf.size(); ++v)
        if (pointOf[v] == 0) {
            pointOf[v] = static_cast<int>(plc.points.size());
            plc.points.push_back(model.vertices[v]);
        }
    plc.facets.reserve(model.triangleCount());
    plc.facetMarkers.reserve(model.triangleCount());
    for (int s = 0; s < static_cast<int>(model.surfaces.size()); ++s) {
        const Surface &surface = model.surfaces[s];
        const std::vector<int> &toGlobal = model.surfaceVertexToGlobal[s];
        for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
            const Triangle &local = surface.triangles[t];
            const Triangle g{toGlobal[local[0]], toGlobal[local[1]], toGlobal[local[2]]};
            // TetGen reads such a facet as a segment and may crash on it.
            if (g[0] == g[1] || g[1] == g[2] || g[0] == g[2])
                throw InputError(MessageText{
                    QT_TRANSLATE_NOOP("stratamesh::Core",
                                      "surface %1: triangle %2 has two corners at the same point"),
                    {surface.name, std::to_string(t)}});
            plc.facets.push_back({pointOf[g[0]], pointOf[g[1]], pointOf[g[2]]});
            plc.facetMarkers.push_back(s + 1);
        }
    }
    plc.regions.reserve(model.regions.size());
    for (int r = 0; r < static_cast<int>(model.regions.size()); ++r)
        plc.regions.push_back(regionSeed(model, r));
    return plc;
}

} // namespace stratamesh
