#include "hybrid/segment_dual_cells.h"

#include "hybrid/cell_faces.h"
#include "hybrid/mixed_mesh_validity.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

namespace stratamesh {

namespace {

struct SurfaceTriangle {
    int surface;
    std::array<int, 3> nodes; // global ids, ordered by increasing site
    Vec3 normal;              // of the triangle as stored in the surface (not re-ordered)
    Vec3 centroid;
    double meanEdge;
};

struct Candidate {
    double height;
    int region;
    int t1, t2;
    Cell cell;
};

bool wellShaped(const std::vector<Vec3> &p, const Cell &cell, double maxWarp)
{
    for (const auto &t : cornerTets(cell))
        if (!(tetVolume(p[t[0]], p[t[1]], p[t[2]], p[t[3]]) > 0.0))
            return false;
    for (const CellFace &f : outwardFaces(cell))
        if (f.isQuad()
            && quadWarpDegrees(p[f.nodes[0]], p[f.nodes[1]], p[f.nodes[2]], p[f.nodes[3]])
                   > maxWarp)
            return false;
    return true;
}

// The cell between the triangles a (bottom) and b (top), node k of each from the same site; a
// shared point makes a pyramid (apex) or a tet. Oriented positively when it can be.
bool makeCell(const std::vector<Vec3> &p, const std::array<int, 3> &a, const std::array<int, 3> &b,
              Cell &out)
{
    std::vector<int> shared, distinct;
    for (int k = 0; k < 3; ++k)
        (a[k] == b[k] ? shared : distinct).push_back(k);
    if (shared.size() == 3)
        return false;
    Cell c;
    if (shared.empty())
        c = Cell::prism(a[0], a[1], a[2], b[0], b[1], b[2]);
    else if (shared.size() == 1) {
        const int i = distinct[0], j = distinct[1];
        c = Cell::pyramid(a[i], a[j], b[j], b[i], a[shared[0]]);
    } else {
        const int i = distinct[0];
        c = Cell::tet(a[shared[0]], a[shared[1]], a[i], b[i]);
    }
    double volume = 0.0;
    for (const auto &t : cornerTets(c))
        volume += tetVolume(p[t[0]], p[t[1]], p[t[2]], p[t[3]]);
    if (volume < 0) {
        if (c.type == CellType::Prism) {
            std::swap(c.nodes[1], c.nodes[2]);
            std::swap(c.nodes[4], c.nodes[5]);
        } else if (c.type == CellType::Pyramid) {
            std::swap(c.nodes[1], c.nodes[3]);
        } else {
            std::swap(c.nodes[0], c.nodes[1]);
        }
    }
    out = c;
    return true;
}

} // namespace

std::vector<int> nearestSites(const std::vector<Vec3> &points, const std::vector<Vec3> &sites)
{
    std::vector<int> out(points.size(), -1);
    for (std::size_t i = 0; i < points.size(); ++i) {
        double best = 1e300;
        for (std::size_t s = 0; s < sites.size(); ++s) {
            const double d = (points[i] - sites[s]).squaredNorm();
            if (d < best) {
                best = d;
                out[i] = static_cast<int>(s);
            }
        }
    }
    return out;
}

SegmentDualCells buildSegmentDualCells(const Model &remesh, const std::vector<int> &pointSite,
                                       const SegmentDualParams &params)
{
    SegmentDualCells out;
    const std::vector<Vec3> &p = remesh.vertices;
    std::vector<SurfaceTriangle> triangles;
    std::map<std::array<int, 3>, std::vector<int>> bySites;
    for (std::size_t s = 0; s < remesh.surfaces.size(); ++s) {
        const Surface &surface = remesh.surfaces[s];
        for (const Triangle &t : surface.triangles) {
            std::array<int, 3> g;
            for (int k = 0; k < 3; ++k)
                g[k] = remesh.surfaceVertexToGlobal[s][t[k]];
            const Vec3 n = (p[g[1]] - p[g[0]]).cross(p[g[2]] - p[g[0]]);
            std::sort(g.begin(), g.end(),
                      [&](int x, int y) { return pointSite[x] < pointSite[y]; });
            const std::array<int, 3> key{pointSite[g[0]], pointSite[g[1]], pointSite[g[2]]};
            if (key[0] == key[1] || key[1] == key[2] || key[0] < 0)
                continue; // two points of one site: no Voronoi edge (§5.3.2 degenerate)
            const double edge = ((p[g[0]] - p[g[1]]).norm() + (p[g[1]] - p[g[2]]).norm()
                                 + (p[g[2]] - p[g[0]]).norm())
                                / 3.0;
            bySites[key].push_back(static_cast<int>(triangles.size()));
            triangles.push_back(
                {static_cast<int>(s), g, n, (p[g[0]] + p[g[1]] + p[g[2]]) / 3.0, edge});
        }
    }
    // The side of region r on surface s: +1 when r lies where the normal points, -1, or 0.
    auto side = [&](int region, int surface) {
        int sgn = 0;
        for (const RegionSide &rs : remesh.regions[region].boundaries)
            if (rs.surface == surface)
                sgn += rs.positive ? 1 : -1;
        return sgn;
    };
    // A quad face with half of it on a remesh triangle (a prism's side on the box or a fault):
    // the surface has a triangle where the cell has a quad, which no conformal mesh allows.
    std::set<std::array<int, 3>> surfaceKeys;
    for (const SurfaceTriangle &t : triangles) {
        std::array<int, 3> k = t.nodes;
        std::sort(k.begin(), k.end());
        surfaceKeys.insert(k);
    }
    for (std::size_t s = 0; s < remesh.surfaces.size(); ++s)
        for (const Triangle &t : remesh.surfaces[s].triangles) {
            std::array<int, 3> k;
            for (int i = 0; i < 3; ++i)
                k[i] = remesh.surfaceVertexToGlobal[s][t[i]];
            std::sort(k.begin(), k.end());
            surfaceKeys.insert(k);
        }
    auto quadOnSurface = [&](const Cell &cell) {
        for (const CellFace &f : outwardFaces(cell)) {
            if (!f.isQuad())
                continue;
            for (int k = 0; k < 4; ++k) {
                std::array<int, 3> half{f.nodes[k], f.nodes[(k + 1) % 4], f.nodes[(k + 2) % 4]};
                std::sort(half.begin(), half.end());
                if (surfaceKeys.count(half))
                    return true;
            }
        }
        return false;
    };
    std::vector<Candidate> candidates;
    for (const auto &[key, list] : bySites)
        for (std::size_t i = 0; i < list.size(); ++i)
            for (std::size_t j = i + 1; j < list.size(); ++j) {
                const SurfaceTriangle &a = triangles[list[i]], &b = triangles[list[j]];
                if (a.surface == b.surface)
                    continue;
                const Vec3 ab = b.centroid - a.centroid;
                for (int r : remesh.surfaces[a.surface].regions) {
                    const int sa = side(r, a.surface), sb = side(r, b.surface);
                    if (sa == 0 || sb == 0)
                        continue;
                    // Each triangle faces the other on the region's side: the segment between
                    // them crosses no other boundary of r there.
                    if (sa * a.normal.dot(ab) <= 0.0 || sb * b.normal.dot(-ab) <= 0.0)
                        continue;
                    ++out.candidates;
                    Cell cell;
                    if (!makeCell(p, a.nodes, b.nodes, cell)
                        || !wellShaped(p, cell, params.maxQuadWarpDegrees)) {
                        ++out.rejectedShape;
                        continue;
                    }
                    if (quadOnSurface(cell)) {
                        ++out.rejectedQuadOnSurface;
                        continue;
                    }
                    const double height = ab.norm();
                    if (height > params.thinRatio * 0.5 * (a.meanEdge + b.meanEdge)) {
                        ++out.rejectedThick;
                        continue;
                    }
                    candidates.push_back({height, r, list[i], list[j], cell});
                }
            }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate &x, const Candidate &y) {
        return std::tie(x.height, x.t1, x.t2) < std::tie(y.height, y.t1, y.t2);
    });
    std::vector<char> used(triangles.size(), 0);
    for (const Candidate &c : candidates) {
        if (used[c.t1] || used[c.t2]) {
            ++out.rejectedTaken;
            continue;
        }
        used[c.t1] = used[c.t2] = 1;
        out.cells.push_back(c.cell);
        out.region.push_back(c.region);
    }
    return out;
}

} // namespace stratamesh
