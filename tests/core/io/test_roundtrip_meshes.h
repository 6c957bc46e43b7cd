// Shared by the exchange-format tests: a small hybrid mesh built in code (tets, pyramids, prisms,
// two regions, surfaces, a line, corners) and comparisons that report the first difference.
// Comparisons are exact (==) on doubles: every format must give back the very same numbers.
#pragma once

#include "mesh/volume_mesh.h"
#include "model/model.h"

#include <QProcess>
#include <QStandardPaths>
#include <QString>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>

namespace stratamesh::test {

// Column [0,1]² × [0,1] of two prisms (region "lower"), then the cube [0,1]² × [1,2] (region
// "upper") split from its centre into five pyramids (four sides and top) and two tets (on the
// two triangles of the interface z = 1). Coordinates carry digits that float would lose.
// Surfaces: "bottom" (z = 0, normals down), "interface" (z = 1, normals up, feature "H1",
// horizon); line "contact" around the interface; its four corners. Every cell is positive.
inline VolumeMesh hybridMesh()
{
    VolumeMesh m;
    m.name = "hybrid test";
    const double e = 1e-9 / 3.0; // breaks float round trips
    m.points = {
        {0, 0, 0},           {1 + e, 0, 0}, {1 + e, 1, 0}, {0, 1 - e, 0}, // 0-3 bottom
        {0, 0, 1},           {1 + e, 0, 1}, {1 + e, 1, 1}, {0, 1 - e, 1}, // 4-7 interface
        {0, 0, 2},           {1 + e, 0, 2}, {1 + e, 1, 2}, {0, 1 - e, 2}, // 8-11 top
        {0.5, 0.5, 1.5 + e},                                              // 12 centre
    };
    m.regionNames = {"lower", "upper"};
    // Prisms: bottom triangle normal points up, towards the top triangle (Gmsh order).
    m.cells.push_back(Cell::prism(0, 1, 3, 4, 5, 7));
    m.cells.push_back(Cell::prism(1, 2, 3, 5, 6, 7));
    // Pyramids: base normal towards the apex (the centre).
    m.cells.push_back(Cell::pyramid(4, 8, 9, 5, 12));   // side y = 0
    m.cells.push_back(Cell::pyramid(5, 9, 10, 6, 12));  // side x = 1
    m.cells.push_back(Cell::pyramid(6, 10, 11, 7, 12)); // side y = 1
    m.cells.push_back(Cell::pyramid(7, 11, 8, 4, 12));  // side x = 0
    m.cells.push_back(Cell::pyramid(8, 11, 10, 9, 12)); // top
    // Tets on the interface triangles (4,5,7) and (5,6,7), apex above.
    m.cells.push_back(Cell::tet(4, 5, 7, 12));
    m.cells.push_back(Cell::tet(5, 6, 7, 12));
    m.cellRegion = {0, 0, 1, 1, 1, 1, 1, 1, 1};
    m.cellQuality = {0.5, 0.25, 1.0 / 3.0, 0.7, 0.71, 0.72, 0.9, 1e-12, 0.125};
    m.qualityName = "scaled jacobian";
    m.surfaces = {{"bottom", "box", FeatureType::Boundary},
                  {"interface", "H1", FeatureType::Horizon}};
    m.triangles = {{0, 3, 1}, {1, 3, 2}, {4, 5, 7}, {5, 6, 7}};
    m.triangleSurface = {0, 0, 1, 1};
    m.lineNames = {"contact"};
    m.edges = {{4, 5}, {5, 6}, {6, 7}, {7, 4}};
    m.edgeLine = {0, 0, 0, 0};
    m.corners = {4, 5, 6, 7};
    return m;
}

inline std::string text(const Vec3 &p)
{
    std::ostringstream s;
    s.precision(17);
    s << '(' << p.x() << ' ' << p.y() << ' ' << p.z() << ')';
    return s.str();
}

// Elements as (group name, node coordinates in order): independent of point numbering and
// element order, exact on coordinates.
using Element = std::pair<std::string, std::vector<std::array<double, 3>>>;

template <class Nodes>
Element element(const VolumeMesh &m, const std::string &group, const Nodes &nodes, int count)
{
    Element e{group, {}};
    for (int k = 0; k < count; ++k) {
        const Vec3 &p = m.points[nodes[k]];
        e.second.push_back({p.x(), p.y(), p.z()});
    }
    return e;
}

inline std::string groupName(const std::vector<std::string> &names, int id)
{
    return id < 0 ? std::string("<untagged>") : names[id];
}

inline std::multiset<Element> cellsOf(const VolumeMesh &m, CellType type)
{
    std::multiset<Element> out;
    for (std::size_t c = 0; c < m.cells.size(); ++c)
        if (m.cells[c].type == type)
            out.insert(element(m, groupName(m.regionNames, m.cellRegion[c]), m.cells[c].nodes,
                               m.cells[c].size()));
    return out;
}

inline std::multiset<Element> trianglesOf(const VolumeMesh &m)
{
    std::vector<std::string> names;
    for (const MeshSurface &s : m.surfaces)
        names.push_back(s.name);
    std::multiset<Element> out;
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
        out.insert(element(m, groupName(names, m.triangleSurface[t]), m.triangles[t], 3));
    return out;
}

inline std::multiset<Element> edgesOf(const VolumeMesh &m)
{
    std::multiset<Element> out;
    for (std::size_t e = 0; e < m.edges.size(); ++e)
        out.insert(element(m, groupName(m.lineNames, m.edgeLine[e]), m.edges[e], 2));
    return out;
}

// Region sides by names: region -> {(surface name, positive)}.
inline std::map<std::string, std::set<std::pair<std::string, bool>>>
namedSides(const std::vector<std::string> &regions,
           const std::vector<std::vector<RegionSide>> &sides,
           const std::vector<std::string> &surfaces)
{
    std::map<std::string, std::set<std::pair<std::string, bool>>> out;
    for (std::size_t r = 0; r < sides.size() && r < regions.size(); ++r)
        for (const RegionSide &s : sides[r])
            out[regions[r]].insert({surfaces[s.surface], s.positive});
    return out;
}

struct MeshCompare {
    bool surfaceMetadata = true; // feature names and types (formats without them: false)
    bool regionSides = true;
    bool lines = true;
    bool quality = true;
    bool pointCount = true;
};

// Empty when b holds the same mesh as a; otherwise the first difference.
inline std::string compareMeshes(const VolumeMesh &a, const VolumeMesh &b,
                                 const MeshCompare &what = {})
{
    if (what.pointCount && a.points.size() != b.points.size())
        return "point count " + std::to_string(a.points.size()) + " vs "
               + std::to_string(b.points.size());
    if (a.regionNames != b.regionNames)
        return "region names differ";
    for (CellType t : {CellType::Tet, CellType::Pyramid, CellType::Prism})
        if (cellsOf(a, t) != cellsOf(b, t))
            return std::string(cellTypeName(t)) + "s differ (count "
                   + std::to_string(a.countCells(t)) + " vs " + std::to_string(b.countCells(t))
                   + ", or coordinates, node order or regions)";
    if (a.surfaces.size() != b.surfaces.size())
        return "surface count " + std::to_string(a.surfaces.size()) + " vs "
               + std::to_string(b.surfaces.size());
    for (std::size_t s = 0; s < a.surfaces.size(); ++s) {
        if (a.surfaces[s].name != b.surfaces[s].name)
            return "surface " + std::to_string(s) + " named " + a.surfaces[s].name + " vs "
                   + b.surfaces[s].name;
        if (what.surfaceMetadata
            && (a.surfaces[s].featureName != b.surfaces[s].featureName
                || a.surfaces[s].type != b.surfaces[s].type))
            return "surface " + a.surfaces[s].name + ": feature name or type differs";
    }
    if (trianglesOf(a) != trianglesOf(b))
        return "triangles differ (count " + std::to_string(a.triangles.size()) + " vs "
               + std::to_string(b.triangles.size()) + ", or coordinates, order or surfaces)";
    if (what.lines) {
        if (a.lineNames != b.lineNames)
            return "line names differ";
        if (edgesOf(a) != edgesOf(b))
            return "edges differ";
        std::multiset<std::string> ca, cb;
        for (int c : a.corners)
            ca.insert(text(a.points[c]));
        for (int c : b.corners)
            cb.insert(text(b.points[c]));
        if (ca != cb)
            return "corners differ";
    }
    if (what.regionSides) {
        std::vector<std::string> sa, sb;
        for (const MeshSurface &s : a.surfaces)
            sa.push_back(s.name);
        for (const MeshSurface &s : b.surfaces)
            sb.push_back(s.name);
        if (namedSides(a.regionNames, a.regionBoundaries, sa)
            != namedSides(b.regionNames, b.regionBoundaries, sb))
            return "region sides differ";
    }
    if (what.quality) {
        std::multiset<std::pair<Element, double>> qa, qb;
        for (std::size_t c = 0; c < a.cellQuality.size(); ++c)
            qa.insert({element(a, "", a.cells[c].nodes, a.cells[c].size()), a.cellQuality[c]});
        for (std::size_t c = 0; c < b.cellQuality.size(); ++c)
            qb.insert({element(b, "", b.cells[c].nodes, b.cells[c].size()), b.cellQuality[c]});
        if (qa != qb || a.qualityName != b.qualityName)
            return "cell quality differs";
    }
    return {};
}

struct ModelCompare {
    bool featureNames = true;
    bool types = true;
    bool regions = true;
};

// Surfaces matched by name; triangles compared in order by the coordinates of their corners.
inline std::string compareModels(const Model &a, const Model &b, const ModelCompare &what = {})
{
    if (a.surfaces.size() != b.surfaces.size())
        return "surface count " + std::to_string(a.surfaces.size()) + " vs "
               + std::to_string(b.surfaces.size());
    std::map<std::string, const Surface *> byName;
    for (const Surface &s : b.surfaces)
        byName[s.name] = &s;
    for (const Surface &sa : a.surfaces) {
        auto it = byName.find(sa.name);
        if (it == byName.end())
            return "surface " + sa.name + " is missing";
        const Surface &sb = *it->second;
        if (what.featureNames && sa.featureName != sb.featureName)
            return "surface " + sa.name + ": feature " + sa.featureName + " vs " + sb.featureName;
        if (what.types && sa.type != sb.type)
            return "surface " + sa.name + ": type differs";
        if (sa.vertices.size() != sb.vertices.size())
            return "surface " + sa.name + ": vertex count " + std::to_string(sa.vertices.size())
                   + " vs " + std::to_string(sb.vertices.size());
        if (sa.triangles.size() != sb.triangles.size())
            return "surface " + sa.name + ": triangle count differs";
        for (std::size_t t = 0; t < sa.triangles.size(); ++t)
            for (int k = 0; k < 3; ++k) {
                const Vec3 &pa = sa.vertices[sa.triangles[t][k]],
                           &pb = sb.vertices[sb.triangles[t][k]];
                if (!(pa == pb))
                    return "surface " + sa.name + ", triangle " + std::to_string(t) + ": "
                           + text(pa) + " vs " + text(pb);
            }
    }
    if (what.regions) {
        auto names = [](const Model &m) {
            std::vector<std::string> out;
            for (const Surface &s : m.surfaces)
                out.push_back(s.name);
            return out;
        };
        auto sides = [&](const Model &m) {
            std::vector<std::string> regionNames;
            std::vector<std::vector<RegionSide>> list;
            for (const Region &r : m.regions) {
                regionNames.push_back(r.name);
                list.push_back(r.boundaries);
            }
            return namedSides(regionNames, list, names(m));
        };
        if (a.regions.size() != b.regions.size())
            return "region count " + std::to_string(a.regions.size()) + " vs "
                   + std::to_string(b.regions.size());
        if (sides(a) != sides(b))
            return "region names or sides differ";
    }
    return {};
}

// /usr/bin/python3 first: a pyenv python on PATH may not see Debian's python3-meshio.
inline QString pythonWithMeshio()
{
    for (const QString &candidate :
         {QStringLiteral("/usr/bin/python3"), QStandardPaths::findExecutable("python3")}) {
        if (candidate.isEmpty())
            continue;
        QProcess p;
        p.start(candidate, {"-c", "import meshio"});
        if (p.waitForFinished(60000) && p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0)
            return candidate;
    }
    return {};
}

} // namespace stratamesh::test
