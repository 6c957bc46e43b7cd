#include "model/region_shells.h"

#include "common/union_find.h"
#include "model/region_volume.h"
#include "model/surface_edges.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

namespace stratamesh {

namespace {
struct EdgeUse {
    long long key;
    int triangle; // global triangle index
    int apex;     // global id of the vertex opposite the edge
    bool forward; // the triangle runs the edge from its smaller to its larger global id
};

// Node of a triangle side: 2·triangle for the positive side (the normal's), +1 for the negative.
int sideNode(int triangle, bool positive)
{
    return 2 * triangle + (positive ? 0 : 1);
}

} // namespace

RegionShells analyseRegionShells(const Model &model)
{
    RegionShells result;
    const int regionCount = static_cast<int>(model.regions.size());
    if (regionCount == 0)
        return result;
    // Owner of each surface side: a region, the Universe (regionCount) or -1 when unknown.
    std::vector<std::array<int, 2>> sideOwner(model.surfaces.size(), {-1, -1});
    for (int r = 0; r <= regionCount; ++r) {
        const std::vector<RegionSide> &sides =
            r < regionCount ? model.regions[r].boundaries : model.universe;
        for (const RegionSide &side : sides)
            if (side.surface >= 0 && side.surface < static_cast<int>(model.surfaces.size()))
                sideOwner[side.surface][side.positive ? 0 : 1] = r;
    }
    std::vector<int> firstTriangle(model.surfaces.size() + 1, 0);
    for (std::size_t s = 0; s < model.surfaces.size(); ++s)
        firstTriangle[s + 1] =
            firstTriangle[s] + static_cast<int>(model.surfaces[s].triangles.size());
    const int triangleCount = firstTriangle.back();
    std::vector<int> surfaceOf(triangleCount);
    std::vector<EdgeUse> uses;
    uses.reserve(3 * static_cast<std::size_t>(triangleCount));
    for (std::size_t s = 0; s < model.surfaces.size(); ++s) {
        const std::vector<int> &g = model.surfaceVertexToGlobal[s];
        const std::vector<Triangle> &triangles = model.surfaces[s].triangles;
        for (std::size_t t = 0; t < triangles.size(); ++t) {
            const int id = firstTriangle[s] + static_cast<int>(t);
            surfaceOf[id] = static_cast<int>(s);
            for (int k = 0; k < 3; ++k) {
                const int a = g[triangles[t][k]], b = g[triangles[t][(k + 1) % 3]];
                const int w = g[triangles[t][(k + 2) % 3]];
                if (a != b && w != a && w != b)
                    uses.push_back({edgeKey(a, b), id, w, a < b});
            }
        }
    }
    std::sort(uses.begin(), uses.end(), [](const EdgeUse &x, const EdgeUse &y) {
        return x.key != y.key ? x.key < y.key : x.triangle < y.triangle;
    });

    auto ownerOf = [&](int node) {
        const int t = node / 2;
        return sideOwner[surfaceOf[t]][node % 2];
    };
    UnionFind shells(2 * triangleCount);
    // Triangle b follows a counter-clockwise about the edge: the side of a that faces increasing
    // angles (its positive side when it runs the edge forward, its normal being d × v) and the
    // side of b that faces back see one wedge of space.
    auto link = [&](long long key, const EdgeUse &a, const EdgeUse &b) {
        const int up = sideNode(a.triangle, a.forward);
        const int down = sideNode(b.triangle, !b.forward);
        const int ownerUp = ownerOf(up), ownerDown = ownerOf(down);
        if (ownerUp >= 0 && ownerDown >= 0 && ownerUp != ownerDown)
            result.folds.push_back(
                {key, surfaceOf[a.triangle], surfaceOf[b.triangle], ownerUp, ownerDown});
        shells.join(up, down);
    };
    std::vector<std::pair<double, const EdgeUse *>> around;
    for (std::size_t i = 0; i < uses.size();) {
        std::size_t j = i;
        while (j < uses.size() && uses[j].key == uses[i].key)
            ++j;
        const long long key = uses[i].key;
        if (j - i == 2) {
            // Two triangles (an edge inside a surface, most of them): each faces the other on
            // both wedges, whatever the angle between them; the angle only orders the folds as
            // the general case below does.
            const Vec3 p = model.vertices[edgeKeyFirst(key)];
            const Vec3 d = (model.vertices[edgeKeySecond(key)] - p).normalized();
            Vec3 v0 = model.vertices[uses[i].apex] - p, v1 = model.vertices[uses[i + 1].apex] - p;
            v0 -= v0.dot(d) * d;
            v1 -= v1.dot(d) * d;
            if (v0.squaredNorm() == 0.0 || v1.squaredNorm() == 0.0) {
                i = j;
                continue;
            }
            const Vec3 e1 = v0.normalized(), e2 = d.cross(e1);
            const std::size_t first = std::atan2(v1.dot(e2), v1.dot(e1)) < 0.0 ? 1 : 0;
            for (std::size_t k = 0; k < 2; ++k)
                link(key, uses[i + (first + k) % 2], uses[i + (first + k + 1) % 2]);
            i = j;
            continue;
        }
        const Vec3 p = model.vertices[edgeKeyFirst(key)];
        const Vec3 d = (model.vertices[edgeKeySecond(key)] - p).normalized();
        // The half-planes of the triangles, as angles about d from the first one.
        around.clear();
        Vec3 e1 = Vec3::Zero(), e2 = Vec3::Zero();
        bool flat = false;
        for (std::size_t u = i; u < j && !flat; ++u) {
            Vec3 v = model.vertices[uses[u].apex] - p;
            v -= v.dot(d) * d;
            if (v.squaredNorm() == 0.0)
                flat = true; // a degenerate triangle: degenerate_triangle says so
            else if (u == i) {
                e1 = v.normalized();
                e2 = d.cross(e1);
            }
            around.push_back({std::atan2(v.dot(e2), v.dot(e1)), &uses[u]});
        }
        if (!flat) {
            std::sort(around.begin(), around.end(),
                      [](const auto &x, const auto &y) { return x.first < y.first; });
            for (std::size_t k = 0; k < around.size(); ++k)
                link(key, *around[k].second, *around[(k + 1) % around.size()].second);
        }
        i = j;
    }

    // Volume of each shell, counted for the region on its sides (positive for a region's outer
    // shell, negative for a cavity in it), and the shells of each region. Each shell's cones
    // start from a vertex of its own: from one point for the whole model, the rounding of cones
    // the size of the model hid pockets of a few cubic metres that TetGen meshes as regions
    // without a seed (modelA5 remeshed with pinned features: 5.1 m³, under the old limit of
    // 1e-12 × diagonal³ = 7.3 m³). A shell counts when its volume is more than rounding of its
    // own cones.
    std::vector<double> volume(2 * static_cast<std::size_t>(triangleCount), 0.0);
    std::vector<double> magnitude(volume.size(), 0.0);
    std::vector<int> owner(volume.size(), -1);
    std::vector<int> refSurface(volume.size(), -1);
    std::vector<Vec3> ref(volume.size(), Vec3::Zero());
    for (int t = 0; t < triangleCount; ++t) {
        const Surface &surface = model.surfaces[surfaceOf[t]];
        const Triangle &tri = surface.triangles[t - firstTriangle[surfaceOf[t]]];
        for (bool positive : {true, false}) {
            const int node = sideNode(t, positive);
            const int root = shells.find(node);
            if (refSurface[root] < 0) {
                refSurface[root] = surfaceOf[t];
                ref[root] = surface.vertices[tri[0]];
            }
            const double cone = triangleConeVolume(surface, tri, ref[root]);
            volume[root] += positive ? -cone : cone;
            magnitude[root] += std::abs(cone);
            if (ownerOf(node) >= 0)
                owner[root] = ownerOf(node);
        }
    }
    std::vector<std::vector<int>> pieces(regionCount);
    for (int root = 0; root < 2 * triangleCount; ++root)
        if (shells.find(root) == root && owner[root] >= 0 && owner[root] < regionCount
            && volume[root] > 1e-9 * magnitude[root])
            pieces[owner[root]].push_back(root);
    // The largest piece of a region is the region; each smaller one is a pocket.
    std::map<int, std::size_t> pocketOf;
    for (int r = 0; r < regionCount; ++r) {
        std::sort(pieces[r].begin(), pieces[r].end(),
                  [&](int x, int y) { return volume[x] > volume[y]; });
        for (std::size_t k = 1; k < pieces[r].size(); ++k) {
            pocketOf[pieces[r][k]] = result.pockets.size();
            result.pockets.push_back({r, volume[pieces[r][k]], {}, Vec3::Zero()});
        }
    }
    if (pocketOf.empty())
        return result;
    for (int t = 0; t < triangleCount; ++t)
        for (bool positive : {true, false}) {
            const auto it = pocketOf.find(shells.find(sideNode(t, positive)));
            if (it == pocketOf.end())
                continue;
            RegionPocket &pocket = result.pockets[it->second];
            const int s = surfaceOf[t];
            const Surface &surface = model.surfaces[s];
            const Triangle &tri = surface.triangles[t - firstTriangle[s]];
            pocket.sides.push_back({s, t - firstTriangle[s], positive});
            pocket.centre +=
                (surface.vertices[tri[0]] + surface.vertices[tri[1]] + surface.vertices[tri[2]])
                / 3.0;
        }
    for (RegionPocket &pocket : result.pockets)
        pocket.centre /= static_cast<double>(std::max<std::size_t>(1, pocket.sides.size()));
    return result;
}

std::vector<int> vertexSurfaceCounts(const Model &model)
{
    std::vector<int> counts(model.vertices.size(), 0);
    for (const std::vector<int> &g : model.surfaceVertexToGlobal)
        for (int v : std::set<int>(g.begin(), g.end()))
            ++counts[v];
    return counts;
}

bool flipKeepsShells(const Model &model, int s, const std::vector<int> &counts, int a, int b)
{
    int c = -1, d = -1;
    for (const Triangle &tri : model.surfaces[s].triangles)
        for (int k = 0; k < 3; ++k) {
            if (tri[k] == a && tri[(k + 1) % 3] == b)
                c = tri[(k + 2) % 3];
            else if (tri[k] == b && tri[(k + 1) % 3] == a)
                d = tri[(k + 2) % 3];
        }
    if (c < 0 || d < 0)
        return false;
    const std::vector<int> &g = model.surfaceVertexToGlobal[s];
    auto own = [&](int v) { return counts[g[v]] == 1; };
    for (const auto &[x, y] : {std::pair{a, b}, {c, d}, {a, c}, {c, b}, {b, d}, {d, a}})
        if (!own(x) && !own(y))
            return false;
    return true;
}

} // namespace stratamesh
