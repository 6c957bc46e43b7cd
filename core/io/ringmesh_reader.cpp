#include "io/ringmesh_reader.h"

#include "common/error.h"
#include "io/geogram_mesh.h"
#include "io/ringmesh_entities.h"
#include "io/zip_archive.h"
#include "mesh/model_conversion.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <unordered_map>
#include <unordered_set>

namespace stratamesh {

namespace {

const char *const kNoName = "No_name";

std::string entryName(GmEntityType type, std::size_t i)
{
    return std::string(gmEntityTypeName(type)) + "_" + std::to_string(i) + ".geogram";
}

std::string fileStem(const std::string &path)
{
    const std::size_t slash = path.find_last_of('/');
    std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    const std::size_t dot = base.find_last_of('.');
    return dot == std::string::npos || dot == 0 ? base : base.substr(0, dot);
}

// Bit patterns, so that -0.0 and 0.0 stay apart as they do in the files.
struct PointKey {
    std::uint64_t x, y, z;
    bool operator==(const PointKey &o) const { return x == o.x && y == o.y && z == o.z; }
};
struct PointKeyHash {
    std::size_t operator()(const PointKey &k) const
    {
        return std::hash<std::uint64_t>()(k.x * 0x9e3779b97f4a7c15ull ^ k.y * 0xc2b2ae3d27d4eb4full
                                          ^ k.z);
    }
};
PointKey keyOf(const Vec3 &p)
{
    PointKey k;
    std::memcpy(&k.x, &p.x(), 8);
    std::memcpy(&k.y, &p.y(), 8);
    std::memcpy(&k.z, &p.z(), 8);
    return k;
}

class GmArchive {
public:
    explicit GmArchive(const std::string &path) : m_path(path), m_zip(path)
    {
        m_entities =
            parseGmMeshEntities(m_zip.read("mesh_entities.txt"), where("mesh_entities.txt"));
        // RINGMesh always writes it, but the meshes are usable without it.
        if (m_zip.contains("geological_entities.txt"))
            m_geology = parseGmGeologicalEntities(m_zip.read("geological_entities.txt"), m_entities,
                                                  where("geological_entities.txt"));
        checkEntries();
    }

    const std::string &path() const { return m_path; }
    std::string where(const std::string &entry) const { return m_path + ":" + entry; }
    const GmMeshEntities &entities() const { return m_entities; }
    const std::vector<GmGeologicalEntity> &geology() const { return m_geology; }
    bool has(GmEntityType type, std::size_t i) const { return m_zip.contains(entryName(type, i)); }

    GeogramFile geogram(GmEntityType type, std::size_t i) const
    {
        const std::string entry = entryName(type, i);
        if (!m_zip.contains(entry))
            throw FileError(where(entry), 0,
                            "entry missing from the archive (mesh_entities.txt lists "
                                + std::string(gmEntityTypeName(type)) + " " + std::to_string(i)
                                + ")");
        return readGeogramFile(m_zip.read(entry), where(entry));
    }

private:
    // Every Type_i.geogram must name an entity of mesh_entities.txt.
    void checkEntries() const
    {
        for (const std::string &name : m_zip.names()) {
            const std::size_t underscore = name.find('_');
            const std::size_t dot = name.rfind(".geogram");
            if (underscore == std::string::npos || dot == std::string::npos
                || dot <= underscore + 1)
                continue;
            const std::string type = name.substr(0, underscore);
            const std::string digits = name.substr(underscore + 1, dot - underscore - 1);
            if (!std::all_of(digits.begin(), digits.end(),
                             [](unsigned char c) { return std::isdigit(c); }))
                continue;
            for (int t = 0; t < kGmEntityTypes; ++t) {
                const std::size_t count = m_entities.entities[t].size();
                if (type == gmEntityTypeName(GmEntityType(t))
                    && (digits.size() > 9 || std::stoul(digits) >= count))
                    throw FileError(where(name), 0,
                                    "no such entity: mesh_entities.txt says 'Nb " + type + " "
                                        + std::to_string(count) + "'");
            }
        }
    }

    std::string m_path;
    ZipReader m_zip;
    GmMeshEntities m_entities;
    std::vector<GmGeologicalEntity> m_geology;
};

std::string patchName(const std::string &object, std::size_t patchCount, std::size_t k)
{
    return patchCount == 1 ? object : object + "_" + std::to_string(k + 1);
}

void makeSurfaceNamesUnique(Model &model)
{
    std::unordered_set<std::string> used;
    for (Surface &s : model.surfaces) {
        if (used.insert(s.name).second)
            continue;
        for (int j = 2;; ++j) {
            std::string candidate = s.name + "_" + std::to_string(j);
            if (used.insert(candidate).second) {
                s.name = std::move(candidate);
                break;
            }
        }
    }
}

std::vector<RegionSide> sides(const std::vector<GmSignedId> &ids)
{
    std::vector<RegionSide> out;
    for (const GmSignedId &s : ids)
        out.push_back({s.id, s.positive});
    return out;
}

// Corners hold one point, lines a chain of edges: anything else is a damaged file.
void checkCornersAndLines(const GmArchive &gm)
{
    for (std::size_t i = 0; i < gm.entities().of(GmEntityType::Corner).size(); ++i) {
        const std::string where = gm.where(entryName(GmEntityType::Corner, i));
        const std::size_t n = geogramPoints(gm.geogram(GmEntityType::Corner, i), where).size();
        if (n != 1)
            throw FileError(where, 0, "a corner has one vertex, this one has " + std::to_string(n));
    }
    for (std::size_t i = 0; i < gm.entities().of(GmEntityType::Line).size(); ++i) {
        const std::string where = gm.where(entryName(GmEntityType::Line, i));
        const GeogramFile file = gm.geogram(GmEntityType::Line, i);
        const std::size_t n = geogramPoints(file, where).size();
        const std::size_t edges = geogramEdges(file, n, where).size();
        if (n < 2 || edges + 1 != n)
            throw FileError(where, 0,
                            "a line is a chain of edges, this one has " + std::to_string(n)
                                + " vertices and " + std::to_string(edges) + " edges");
    }
}

Model buildModel(const GmArchive &gm)
{
    const GmMeshEntities &e = gm.entities();
    Model model;
    model.name = e.name.empty() ? fileStem(gm.path()) : e.name;
    const std::vector<GmMeshEntity> &surfaces = e.of(GmEntityType::Surface);
    model.surfaces.resize(surfaces.size());
    std::vector<char> named(surfaces.size(), 0);
    for (const GmGeologicalEntity &g : gm.geology()) {
        if (g.type == "Interface") {
            for (std::size_t k = 0; k < g.children.size(); ++k) {
                const int s = g.children[k];
                if (named[s]) // a surface in two interfaces keeps the first
                    continue;
                named[s] = 1;
                Surface &surface = model.surfaces[s];
                surface.name = surfaces[s].name != kNoName
                                   ? surfaces[s].name
                                   : patchName(g.name, g.children.size(), k);
                surface.featureName = g.name;
                surface.sourceObject = g.name;
                surface.type = featureTypeFromGocad(g.feature);
            }
        } else if (g.type == "Layer") {
            model.layers.push_back({g.name, g.children});
        }
    }
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
        Surface &surface = model.surfaces[s];
        if (!named[s]) {
            surface.name =
                surfaces[s].name != kNoName ? surfaces[s].name : "Surface_" + std::to_string(s);
            surface.featureName = surface.sourceObject = surface.name;
        }
        if (surface.type == FeatureType::Unknown && !surfaces[s].feature.empty())
            surface.type = featureTypeFromGocad(surfaces[s].feature);
        const std::string where = gm.where(entryName(GmEntityType::Surface, s));
        const GeogramFile file = gm.geogram(GmEntityType::Surface, s);
        surface.vertices = geogramPoints(file, where);
        surface.triangles = geogramTriangles(file, surface.vertices.size(), where);
        if (surface.triangles.empty())
            throw FileError(where, 0, "surface without facets");
    }
    makeSurfaceNamesUnique(model);
    const std::vector<GmMeshEntity> &regions = e.of(GmEntityType::Region);
    for (std::size_t r = 0; r < regions.size(); ++r)
        model.regions.push_back(
            {regions[r].name != kNoName ? regions[r].name : "Region_" + std::to_string(r),
             sides(regions[r].sides)});
    model.universe = sides(e.universe);
    return model;
}

} // namespace

bool isRingMeshFile(const std::string &path)
{
    if (path.size() < 3)
        return false;
    std::string ext = path.substr(path.size() - 3);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".gm";
}

bool hasRingMeshRegionMeshes(const std::string &path)
{
    const ZipReader zip(path);
    return std::any_of(zip.names().begin(), zip.names().end(),
                       [](const std::string &n) { return n.rfind("Region_", 0) == 0; });
}

Model readRingMeshModel(const std::string &path)
{
    const GmArchive gm(path);
    checkCornersAndLines(gm);
    return buildModel(gm);
}

VolumeMesh readRingMeshVolume(const std::string &path)
{
    const GmArchive gm(path);
    checkCornersAndLines(gm);
    VolumeMesh mesh = meshFromModel(buildModel(gm));
    std::unordered_map<PointKey, int, PointKeyHash> pointIndex;
    for (std::size_t p = 0; p < mesh.points.size(); ++p)
        pointIndex.emplace(keyOf(mesh.points[p]), int(p));
    for (std::size_t r = 0; r < gm.entities().of(GmEntityType::Region).size(); ++r) {
        if (!gm.has(GmEntityType::Region, r))
            continue; // RINGMesh writes no file for a region without a mesh
        const std::string where = gm.where(entryName(GmEntityType::Region, r));
        const GeogramFile file = gm.geogram(GmEntityType::Region, r);
        const std::vector<Vec3> points = geogramPoints(file, where);
        std::vector<int> toMesh(points.size());
        for (std::size_t v = 0; v < points.size(); ++v) {
            const auto [it, inserted] =
                pointIndex.emplace(keyOf(points[v]), int(mesh.points.size()));
            if (inserted)
                mesh.points.push_back(points[v]);
            toMesh[v] = it->second;
        }
        for (Cell cell : geogramCells(file, points.size(), where)) {
            for (int k = 0; k < cell.size(); ++k)
                cell.nodes[k] = toMesh[cell.nodes[k]];
            mesh.cells.push_back(cell);
            mesh.cellRegion.push_back(int(r));
        }
    }
    return mesh;
}

} // namespace stratamesh
