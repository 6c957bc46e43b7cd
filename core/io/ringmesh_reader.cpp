#include "io/ringmesh_reader.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/formats.h"
#include "io/geogram_mesh.h"
#include "io/ringmesh_archive.h"
#include "io/surface_names.h"
#include "mesh/model_conversion.h"

#include <algorithm>
#include <unordered_map>

namespace stratamesh {

namespace {

const char *const kNoName = "No_name";

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
        const std::string where = gm.where(gmEntryName(GmEntityType::Corner, i));
        const std::size_t n = geogramPoints(gm.geogram(GmEntityType::Corner, i), where).size();
        if (n != 1)
            throw FileError(
                where, 0,
                MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "a corner has one vertex, this one has %1"),
                            {std::to_string(n)}});
    }
    for (std::size_t i = 0; i < gm.entities().of(GmEntityType::Line).size(); ++i) {
        const std::string where = gm.where(gmEntryName(GmEntityType::Line, i));
        const GeogramFile file = gm.geogram(GmEntityType::Line, i);
        const std::size_t n = geogramPoints(file, where).size();
        const std::size_t edges = geogramEdges(file, n, where).size();
        if (n < 2 || edges + 1 != n)
            throw FileError(
                where, 0,
                MessageText{
                    QT_TRANSLATE_NOOP(
                        "stratamesh::Core",
                        "a line is a chain of edges, this one has %1 vertices and %2 edges"),
                    {std::to_string(n), std::to_string(edges)}});
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
        const std::string where = gm.where(gmEntryName(GmEntityType::Surface, s));
        const GeogramFile file = gm.geogram(GmEntityType::Surface, s);
        surface.vertices = geogramPoints(file, where);
        surface.triangles = geogramTriangles(file, surface.vertices.size(), where);
        if (surface.triangles.empty())
            throw FileError(where, 0,
                            QT_TRANSLATE_NOOP("stratamesh::Core", "surface without facets"));
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
    return fileExtension(path) == ".gm";
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
        pointIndex.emplace(pointKey(mesh.points[p]), int(p));
    for (std::size_t r = 0; r < gm.entities().of(GmEntityType::Region).size(); ++r) {
        if (!gm.has(GmEntityType::Region, r))
            continue; // RINGMesh writes no file for a region without a mesh
        const std::string where = gm.where(gmEntryName(GmEntityType::Region, r));
        const GeogramFile file = gm.geogram(GmEntityType::Region, r);
        const std::vector<Vec3> points = geogramPoints(file, where);
        std::vector<int> toMesh(points.size());
        for (std::size_t v = 0; v < points.size(); ++v) {
            const auto [it, inserted] =
                pointIndex.emplace(pointKey(points[v]), int(mesh.points.size()));
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
