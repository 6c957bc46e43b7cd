#include "mesh/model_conversion.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace stratamesh {

namespace {

// Exact-position key; +0 and -0 are the same position.
struct PositionKey {
    double x, y, z;
    bool operator==(const PositionKey &o) const { return x == o.x && y == o.y && z == o.z; }
};
struct PositionHash {
    std::size_t operator()(const PositionKey &k) const
    {
        auto h = [](double d) { return std::hash<double>()(d == 0.0 ? 0.0 : d); };
        return h(k.x) ^ (h(k.y) * 0x9e3779b97f4a7c15ULL) ^ (h(k.z) * 0xc2b2ae3d27d4eb4fULL);
    }
};
PositionKey keyOf(const Vec3 &p)
{
    return {p.x(), p.y(), p.z()};
}

} // namespace

VolumeMesh meshFromModel(const Model &model)
{
    VolumeMesh mesh;
    mesh.name = model.name;
    mesh.zPositiveDepth = model.zPositiveDepth;
    std::unordered_map<PositionKey, std::vector<int>, PositionHash> byPosition;
    for (std::size_t s = 0; s < model.surfaces.size(); ++s) {
        const Surface &surface = model.surfaces[s];
        mesh.surfaces.push_back({surface.name, surface.featureName, surface.type});
        std::vector<int> local(surface.vertices.size());
        std::unordered_set<int> usedHere;
        for (std::size_t v = 0; v < surface.vertices.size(); ++v) {
            std::vector<int> &candidates = byPosition[keyOf(surface.vertices[v])];
            int id = -1;
            for (int c : candidates)
                if (!usedHere.count(c)) {
                    id = c;
                    break;
                }
            if (id < 0) {
                id = static_cast<int>(mesh.points.size());
                mesh.points.push_back(surface.vertices[v]);
                candidates.push_back(id);
            }
            usedHere.insert(id);
            local[v] = id;
        }
        for (const Triangle &t : surface.triangles) {
            mesh.triangles.push_back({local[t[0]], local[t[1]], local[t[2]]});
            mesh.triangleSurface.push_back(static_cast<int>(s));
        }
    }
    for (const Region &region : model.regions) {
        mesh.regionNames.push_back(region.name);
        mesh.regionBoundaries.push_back(region.boundaries);
    }
    // Lines and corners index Model::vertices: find their point by position.
    auto pointOf = [&](int modelVertex) {
        auto it = byPosition.find(keyOf(model.vertices[modelVertex]));
        return it == byPosition.end() ? -1 : it->second.front();
    };
    const int nv = static_cast<int>(model.vertices.size());
    for (std::size_t l = 0; l < model.lines.size(); ++l) {
        const Line &line = model.lines[l];
        mesh.lineNames.push_back(line.name.empty() ? "line_" + std::to_string(l + 1) : line.name);
        const std::size_t n = line.vertices.size();
        const std::size_t segments = line.closed ? n : (n > 0 ? n - 1 : 0);
        for (std::size_t i = 0; i < segments; ++i) {
            const int a = line.vertices[i], b = line.vertices[(i + 1) % n];
            if (a < 0 || b < 0 || a >= nv || b >= nv)
                continue;
            const int pa = pointOf(a), pb = pointOf(b);
            if (pa >= 0 && pb >= 0 && pa != pb) {
                mesh.edges.push_back({pa, pb});
                mesh.edgeLine.push_back(static_cast<int>(l));
            }
        }
    }
    for (const Corner &corner : model.corners)
        if (corner.vertex >= 0 && corner.vertex < nv) {
            const int p = pointOf(corner.vertex);
            if (p >= 0)
                mesh.corners.push_back(p);
        }
    return mesh;
}

Model modelFromMesh(const VolumeMesh &mesh)
{
    Model model;
    model.name = mesh.name;
    model.zPositiveDepth = mesh.zPositiveDepth;
    const bool hasUntagged = std::find(mesh.triangleSurface.begin(), mesh.triangleSurface.end(), -1)
                             != mesh.triangleSurface.end();
    std::vector<std::vector<int>> trianglesOf(mesh.surfaces.size() + (hasUntagged ? 1 : 0));
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const int s = mesh.triangleSurface[t];
        trianglesOf[s < 0 ? mesh.surfaces.size() : static_cast<std::size_t>(s)].push_back(
            static_cast<int>(t));
    }
    for (std::size_t s = 0; s < trianglesOf.size(); ++s) {
        Surface surface;
        if (s < mesh.surfaces.size()) {
            surface.name = mesh.surfaces[s].name;
            surface.featureName = mesh.surfaces[s].featureName;
            surface.type = mesh.surfaces[s].type;
        } else {
            surface.name = surface.featureName = "untagged";
        }
        std::vector<int> used;
        for (int t : trianglesOf[s])
            used.insert(used.end(), mesh.triangles[t].begin(), mesh.triangles[t].end());
        std::sort(used.begin(), used.end());
        used.erase(std::unique(used.begin(), used.end()), used.end());
        std::unordered_map<int, int> local;
        for (int p : used) {
            local.emplace(p, static_cast<int>(surface.vertices.size()));
            surface.vertices.push_back(mesh.points[p]);
        }
        for (int t : trianglesOf[s]) {
            const Triangle &tri = mesh.triangles[t];
            surface.triangles.push_back({local[tri[0]], local[tri[1]], local[tri[2]]});
        }
        model.surfaces.push_back(std::move(surface));
    }
    for (std::size_t r = 0; r < mesh.regionNames.size(); ++r) {
        Region region;
        region.name = mesh.regionNames[r];
        if (r < mesh.regionBoundaries.size())
            region.boundaries = mesh.regionBoundaries[r];
        model.regions.push_back(std::move(region));
    }
    return model;
}

} // namespace stratamesh
