// Restriction domains built in code for the Voronoi and CVT tests (no files).
#pragma once

#include "voronoi/restriction_domain.h"

#include <cmath>
#include <map>
#include <random>
#include <utility>

namespace stratamesh::test {

// Appends a triangulated surface to the domain (points are not shared with other surfaces).
inline void appendSurface(RestrictionDomain &d, const std::vector<Vec3> &points,
                          const std::vector<Triangle> &tris)
{
    const int offset = static_cast<int>(d.points.size());
    const int surface = d.surfaceCount++;
    d.points.insert(d.points.end(), points.begin(), points.end());
    for (const Triangle &t : tris) {
        d.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
        d.triangleSurface.push_back(surface);
    }
}

// Icosahedron subdivided `level` times and projected on the sphere.
inline void icosphere(int level, double radius, const Vec3 &center, std::vector<Vec3> &pts,
                      std::vector<Triangle> &tris)
{
    const double g = (1.0 + std::sqrt(5.0)) / 2.0;
    pts = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
           {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    tris = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
            {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
            {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (Vec3 &p : pts)
        p.normalize();
    for (int l = 0; l < level; ++l) {
        std::map<std::pair<int, int>, int> mid;
        const auto midpoint = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            const auto it = mid.find(key);
            if (it != mid.end())
                return it->second;
            pts.push_back((pts[a] + pts[b]).normalized());
            return mid[key] = static_cast<int>(pts.size()) - 1;
        };
        std::vector<Triangle> next;
        for (const Triangle &t : tris) {
            const int a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]), c = midpoint(t[2], t[0]);
            next.push_back({t[0], a, c});
            next.push_back({t[1], b, a});
            next.push_back({t[2], c, b});
            next.push_back({a, b, c});
        }
        tris.swap(next);
    }
    for (Vec3 &p : pts)
        p = center + radius * p;
}

inline RestrictionDomain sphereDomain(int level, double radius = 1.0)
{
    RestrictionDomain d;
    std::vector<Vec3> pts;
    std::vector<Triangle> tris;
    icosphere(level, radius, Vec3::Zero(), pts, tris);
    appendSurface(d, pts, tris);
    finalizeDomain(d);
    return d;
}

// n×n squares of [x0, x0 + size]² at height z, two triangles each (alternating diagonals).
inline void gridSquare(int n, double size, double z, std::vector<Vec3> &pts,
                       std::vector<Triangle> &tris, double x0 = 0.0)
{
    pts.clear();
    tris.clear();
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            pts.push_back({x0 + size * i / n, x0 + size * j / n, z});
    const auto id = [n](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            if ((i + j) % 2 == 0) {
                tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
                tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
            } else {
                tris.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
                tris.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
            }
        }
}

// The unit square [0,1]² (z = 0) meshed by an n×n grid, with its border as one closed line.
inline RestrictionDomain squareDomain(int n, bool withBorder = true)
{
    RestrictionDomain d;
    std::vector<Vec3> pts;
    std::vector<Triangle> tris;
    gridSquare(n, 1.0, 0.0, pts, tris);
    appendSurface(d, pts, tris);
    if (withBorder) {
        std::vector<int> loop;
        for (int i = 0; i < n; ++i)
            loop.push_back(i); // bottom, left to right
        for (int j = 0; j < n; ++j)
            loop.push_back(j * (n + 1) + n); // right, upwards
        for (int i = n; i > 0; --i)
            loop.push_back(n * (n + 1) + i); // top, right to left
        for (int j = n; j > 0; --j)
            loop.push_back(j * (n + 1)); // left, downwards
        for (std::size_t k = 0; k < loop.size(); ++k) {
            d.segments.push_back({loop[k], loop[(k + 1) % loop.size()]});
            d.segmentLine.push_back(0);
        }
    }
    finalizeDomain(d);
    return d;
}

// Two parallel unit squares at z = 0 and z = gap.
inline RestrictionDomain parallelPlanesDomain(int n, double gap)
{
    RestrictionDomain d;
    std::vector<Vec3> pts;
    std::vector<Triangle> tris;
    gridSquare(n, 1.0, 0.0, pts, tris);
    appendSurface(d, pts, tris);
    gridSquare(n, 1.0, gap, pts, tris);
    appendSurface(d, pts, tris);
    finalizeDomain(d);
    return d;
}

// Two concentric spheres.
inline RestrictionDomain nestedSpheresDomain(int level, double inner, double outer)
{
    RestrictionDomain d;
    std::vector<Vec3> pts;
    std::vector<Triangle> tris;
    icosphere(level, outer, Vec3::Zero(), pts, tris);
    appendSurface(d, pts, tris);
    icosphere(level, inner, Vec3::Zero(), pts, tris);
    appendSurface(d, pts, tris);
    finalizeDomain(d);
    return d;
}

inline std::vector<Vec3> randomPointsInBox(int n, const Vec3 &lo, const Vec3 &hi, unsigned seed)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Vec3> r;
    for (int i = 0; i < n; ++i)
        r.push_back(lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(hi - lo));
    return r;
}

} // namespace stratamesh::test
