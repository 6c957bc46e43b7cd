#include "mesh/volume_mesh.h"

#include "common/error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace stratamesh {

const char *cellTypeName(CellType type)
{
    switch (type) {
    case CellType::Tet:
        return "tet";
    case CellType::Pyramid:
        return "pyramid";
    case CellType::Prism:
        return "prism";
    }
    return "cell";
}

std::size_t VolumeMesh::countCells(CellType type) const
{
    return static_cast<std::size_t>(std::count_if(
        cells.begin(), cells.end(), [type](const Cell &c) { return c.type == type; }));
}

namespace {

void require(bool ok, const std::string &what)
{
    if (!ok)
        throw InputError("invalid mesh: " + what);
}

void checkGroupIds(const std::vector<int> &ids, std::size_t count, const char *element,
                   const char *group)
{
    for (std::size_t i = 0; i < ids.size(); ++i)
        require(ids[i] >= -1 && ids[i] < static_cast<int>(count),
                std::string(element) + " " + std::to_string(i) + " has " + group + " "
                    + std::to_string(ids[i]) + " (there are " + std::to_string(count) + ")");
}

} // namespace

double tetVolume(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d)
{
    return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

void validateMesh(const VolumeMesh &m)
{
    const int n = static_cast<int>(m.points.size());
    for (std::size_t i = 0; i < m.points.size(); ++i)
        require(m.points[i].allFinite(),
                "point " + std::to_string(i) + " has a non-finite coordinate");
    require(m.cellRegion.size() == m.cells.size(), "cellRegion size differs from the cell count");
    require(m.cellQuality.empty() || m.cellQuality.size() == m.cells.size(),
            "cellQuality size differs from the cell count");
    require(m.regionBoundaries.empty() || m.regionBoundaries.size() == m.regionNames.size(),
            "regionBoundaries size differs from the region count");
    require(m.triangleSurface.size() == m.triangles.size(),
            "triangleSurface size differs from the triangle count");
    require(m.edgeLine.size() == m.edges.size(), "edgeLine size differs from the edge count");
    for (std::size_t c = 0; c < m.cells.size(); ++c) {
        const Cell &cell = m.cells[c];
        for (int k = 0; k < cell.size(); ++k) {
            require(cell.nodes[k] >= 0 && cell.nodes[k] < n,
                    std::string(cellTypeName(cell.type)) + " " + std::to_string(c) + " uses point "
                        + std::to_string(cell.nodes[k]) + " of " + std::to_string(n));
            for (int j = 0; j < k; ++j)
                require(cell.nodes[j] != cell.nodes[k], std::string(cellTypeName(cell.type)) + " "
                                                            + std::to_string(c) + " repeats point "
                                                            + std::to_string(cell.nodes[k]));
        }
    }
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
        for (int v : m.triangles[t])
            require(v >= 0 && v < n, "triangle " + std::to_string(t) + " uses point "
                                         + std::to_string(v) + " of " + std::to_string(n));
    for (std::size_t e = 0; e < m.edges.size(); ++e)
        for (int v : m.edges[e])
            require(v >= 0 && v < n, "edge " + std::to_string(e) + " uses point "
                                         + std::to_string(v) + " of " + std::to_string(n));
    for (int v : m.corners)
        require(v >= 0 && v < n,
                "corner uses point " + std::to_string(v) + " of " + std::to_string(n));
    checkGroupIds(m.cellRegion, m.regionNames.size(), "cell", "region");
    checkGroupIds(m.triangleSurface, m.surfaces.size(), "triangle", "surface");
    checkGroupIds(m.edgeLine, m.lineNames.size(), "edge", "line");
    for (std::size_t r = 0; r < m.regionBoundaries.size(); ++r)
        for (const RegionSide &s : m.regionBoundaries[r])
            require(s.surface >= 0 && s.surface < static_cast<int>(m.surfaces.size()),
                    "region " + std::to_string(r) + " is bounded by surface "
                        + std::to_string(s.surface) + " (there are "
                        + std::to_string(m.surfaces.size()) + ")");
}

double signedVolume(const VolumeMesh &mesh, const Cell &cell)
{
    auto p = [&](int k) -> const Vec3 & { return mesh.points[cell.nodes[k]]; };
    // Cone from o over the quad a b c d (outward), the mean of both diagonal splits.
    auto quadCone = [&](const Vec3 &o, int a, int b, int c, int d) {
        return 0.5
               * (tetVolume(p(a), p(c), p(b), o) + tetVolume(p(a), p(d), p(c), o)
                  + tetVolume(p(a), p(d), p(b), o) + tetVolume(p(b), p(d), p(c), o));
    };
    switch (cell.type) {
    case CellType::Tet:
        return tetVolume(p(0), p(1), p(2), p(3));
    case CellType::Pyramid:
        // From the apex only the base counts; its outward order is 0 3 2 1.
        return quadCone(p(4), 0, 3, 2, 1);
    case CellType::Prism: {
        // From node 0 the bottom counts nothing (a warped quad through 0 still does).
        const Vec3 &o = p(0);
        return tetVolume(p(3), p(5), p(4), o) + quadCone(o, 0, 1, 4, 3) + quadCone(o, 1, 2, 5, 4)
               + quadCone(o, 2, 0, 3, 5);
    }
    }
    return 0.0;
}

std::vector<Triangle> outwardTriangleFaces(const Cell &c)
{
    const auto &n = c.nodes;
    switch (c.type) {
    case CellType::Tet:
        return {{n[0], n[2], n[1]}, {n[0], n[1], n[3]}, {n[0], n[3], n[2]}, {n[1], n[2], n[3]}};
    case CellType::Pyramid:
        return {{n[0], n[1], n[4]}, {n[1], n[2], n[4]}, {n[2], n[3], n[4]}, {n[3], n[0], n[4]}};
    case CellType::Prism:
        return {{n[0], n[2], n[1]}, {n[3], n[4], n[5]}};
    }
    return {};
}

namespace {

// Same cyclic order (a rotation of the other)?
bool sameCycle(const Triangle &a, const Triangle &b)
{
    for (int r = 0; r < 3; ++r)
        if (a[0] == b[r] && a[1] == b[(r + 1) % 3] && a[2] == b[(r + 2) % 3])
            return true;
    return false;
}

Triangle sortedTriangle(Triangle t)
{
    std::sort(t.begin(), t.end());
    return t;
}

} // namespace

std::vector<std::vector<RegionSide>> regionSidesFromCells(const VolumeMesh &mesh)
{
    // Sorted face -> (region, outward face) of each cell face; a face has at most two cells.
    std::map<Triangle, std::vector<std::pair<int, Triangle>>> faces;
    std::set<Triangle> wanted;
    for (const Triangle &t : mesh.triangles)
        wanted.insert(sortedTriangle(t));
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
        const int region = mesh.cellRegion[c];
        if (region < 0)
            continue;
        for (const Triangle &f : outwardTriangleFaces(mesh.cells[c])) {
            const Triangle key = sortedTriangle(f);
            if (wanted.count(key))
                faces[key].emplace_back(region, f);
        }
    }
    std::vector<std::set<std::pair<int, bool>>> sides(mesh.regionNames.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const int surface = mesh.triangleSurface[t];
        if (surface < 0)
            continue;
        auto it = faces.find(sortedTriangle(mesh.triangles[t]));
        if (it == faces.end())
            continue;
        for (const auto &[region, outward] : it->second)
            sides[region].insert({surface, !sameCycle(outward, mesh.triangles[t])});
    }
    std::vector<std::vector<RegionSide>> out(sides.size());
    for (std::size_t r = 0; r < sides.size(); ++r)
        for (const auto &[surface, positive] : sides[r])
            out[r].push_back({surface, positive});
    return out;
}

void dropUnusedPoints(VolumeMesh &mesh)
{
    std::vector<int> map(mesh.points.size(), -1);
    for (const Cell &c : mesh.cells)
        for (int k = 0; k < c.size(); ++k)
            map[c.nodes[k]] = 0;
    for (const Triangle &t : mesh.triangles)
        for (int v : t)
            map[v] = 0;
    for (const auto &e : mesh.edges)
        map[e[0]] = map[e[1]] = 0;
    for (int v : mesh.corners)
        map[v] = 0;
    std::vector<Vec3> kept;
    for (std::size_t i = 0; i < map.size(); ++i)
        if (map[i] == 0) {
            map[i] = static_cast<int>(kept.size());
            kept.push_back(mesh.points[i]);
        }
    if (kept.size() == mesh.points.size())
        return;
    mesh.points = std::move(kept);
    for (Cell &c : mesh.cells)
        for (int k = 0; k < c.size(); ++k)
            c.nodes[k] = map[c.nodes[k]];
    for (Triangle &t : mesh.triangles)
        for (int &v : t)
            v = map[v];
    for (auto &e : mesh.edges)
        e = {map[e[0]], map[e[1]]};
    for (int &v : mesh.corners)
        v = map[v];
}

} // namespace stratamesh
