#include "model/region_volume.h"

#include "common/error.h"
#include "model/surface_edges.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace stratamesh {

namespace {

double coneVolume(const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    return a.dot(b.cross(c)) / 6.0;
}

} // namespace

double triangleConeVolume(const Surface &surface, const Triangle &t, const Vec3 &ref)
{
    return coneVolume(surface.vertices[t[0]] - ref, surface.vertices[t[1]] - ref,
                      surface.vertices[t[2]] - ref);
}

double surfaceConeVolume(const Surface &surface, const Vec3 &ref)
{
    double sum = 0.0;
    for (const Triangle &t : surface.triangles)
        sum += triangleConeVolume(surface, t, ref);
    return sum;
}

Vec3 volumeReferencePoint(const Model &model)
{
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max());
    Vec3 hi = Vec3::Constant(std::numeric_limits<double>::lowest());
    bool any = false;
    for (const Surface &s : model.surfaces)
        for (const Vec3 &p : s.vertices) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
            any = true;
        }
    return any ? Vec3(0.5 * (lo + hi)) : Vec3::Zero();
}

double sidesVolume(const Model &model, const std::vector<RegionSide> &sides)
{
    const Vec3 ref = volumeReferencePoint(model);
    double sum = 0.0;
    for (const RegionSide &side : sides) {
        if (side.surface < 0 || side.surface >= static_cast<int>(model.surfaces.size()))
            throw InputError("a region side lists surface " + std::to_string(side.surface)
                             + " which does not exist");
        // The normal points into the region on a positive side: outward is the opposite.
        const double v = surfaceConeVolume(model.surfaces[side.surface], ref);
        sum += side.positive ? -v : v;
    }
    return sum;
}

std::vector<double> regionVolumes(const Model &model)
{
    std::vector<double> volumes;
    volumes.reserve(model.regions.size());
    for (const Region &r : model.regions)
        volumes.push_back(sidesVolume(model, r.boundaries));
    return volumes;
}

double universeVolume(const Model &model)
{
    if (!model.universe.empty())
        return sidesVolume(model, model.universe);
    double sum = 0.0;
    for (double v : regionVolumes(model))
        sum += v;
    return -sum;
}

double enclosedVolume(const Model &model, const std::vector<int> &surfaces)
{
    if (!model.hasTopology())
        throw InputError("enclosedVolume needs the model topology (recoverTopology)");
    std::vector<std::array<int, 3>> tris;
    for (int s : surfaces) {
        if (s < 0 || s >= static_cast<int>(model.surfaces.size()))
            throw InputError("enclosedVolume: surface " + std::to_string(s) + " does not exist");
        const std::vector<int> &g = model.surfaceVertexToGlobal[s];
        for (const Triangle &t : model.surfaces[s].triangles) {
            const std::array<int, 3> gt{g[t[0]], g[t[1]], g[t[2]]};
            if (gt[0] != gt[1] && gt[1] != gt[2] && gt[0] != gt[2])
                tris.push_back(gt);
        }
    }
    struct HalfEdge {
        long long key;
        int triangle;
        bool forward; // a < b along the triangle's orientation
    };
    std::vector<HalfEdge> halfEdges;
    halfEdges.reserve(tris.size() * 3);
    for (std::size_t t = 0; t < tris.size(); ++t)
        for (int i = 0; i < 3; ++i) {
            const int a = tris[t][i], b = tris[t][(i + 1) % 3];
            halfEdges.push_back({edgeKey(a, b), static_cast<int>(t), a < b});
        }
    std::sort(halfEdges.begin(), halfEdges.end(),
              [](const HalfEdge &x, const HalfEdge &y) { return x.key < y.key; });

    // Neighbour across each edge, and whether both triangles run the edge the same way.
    std::vector<std::vector<std::pair<int, bool>>> neighbours(tris.size());
    for (std::size_t i = 0; i < halfEdges.size(); i += 2) {
        if (i + 1 >= halfEdges.size() || halfEdges[i + 1].key != halfEdges[i].key
            || (i + 2 < halfEdges.size() && halfEdges[i + 2].key == halfEdges[i].key)) {
            const long long key = halfEdges[i].key;
            const Vec3 &p = model.vertices[static_cast<std::size_t>(key >> 32)];
            throw InputError("the surfaces do not enclose a volume: an edge at ("
                             + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", "
                             + std::to_string(p.z())
                             + ") is not shared by exactly two of their triangles");
        }
        const HalfEdge &x = halfEdges[i], &y = halfEdges[i + 1];
        const bool same = x.forward == y.forward;
        neighbours[x.triangle].push_back({y.triangle, same});
        neighbours[y.triangle].push_back({x.triangle, same});
    }

    const Vec3 ref = volumeReferencePoint(model);
    std::vector<int> flip(tris.size(), -1);
    std::vector<int> stack;
    double total = 0.0;
    for (std::size_t seed = 0; seed < tris.size(); ++seed) {
        if (flip[seed] >= 0)
            continue;
        flip[seed] = 0;
        stack.push_back(static_cast<int>(seed));
        double shell = 0.0;
        while (!stack.empty()) {
            const int t = stack.back();
            stack.pop_back();
            const double v =
                coneVolume(model.vertices[tris[t][0]] - ref, model.vertices[tris[t][1]] - ref,
                           model.vertices[tris[t][2]] - ref);
            shell += flip[t] ? -v : v;
            for (auto [n, same] : neighbours[t]) {
                const int want = flip[t] ^ (same ? 1 : 0);
                if (flip[n] < 0) {
                    flip[n] = want;
                    stack.push_back(n);
                } else if (flip[n] != want) {
                    throw InputError(
                        "the surfaces do not enclose a volume: their union is not orientable");
                }
            }
        }
        total += std::abs(shell);
    }
    return total;
}

double boxEnclosedVolume(const Model &model)
{
    std::vector<int> box;
    for (std::size_t s = 0; s < model.surfaces.size(); ++s)
        if (model.surfaces[s].type == FeatureType::Boundary)
            box.push_back(static_cast<int>(s));
    if (box.empty())
        throw InputError("the model has no box (no surface of type boundary)");
    return enclosedVolume(model, box);
}

} // namespace stratamesh
