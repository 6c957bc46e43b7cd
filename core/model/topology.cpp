#include "model/topology.h"

#include "common/error.h"
#include "model/surface_edges.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <unordered_map>

namespace stratamesh {

namespace {

// Exact-position hashing: -0.0 and 0.0 compare equal, so they must hash alike.
struct PositionHash {
    std::size_t operator()(const Vec3 &p) const
    {
        std::size_t h = 0;
        for (int i = 0; i < 3; ++i) {
            const double c = p[i] == 0.0 ? 0.0 : p[i];
            h ^= std::hash<double>()(c) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
        }
        return h;
    }
};

struct PositionEqual {
    bool operator()(const Vec3 &a, const Vec3 &b) const
    {
        return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
    }
};

void buildGlobalVertices(Model &model)
{
    std::unordered_map<Vec3, int, PositionHash, PositionEqual> index;
    index.reserve(model.triangleCount() + 16);
    model.vertices.clear();
    model.surfaceVertexToGlobal.assign(model.surfaces.size(), {});
    for (std::size_t s = 0; s < model.surfaces.size(); ++s) {
        const Surface &surface = model.surfaces[s];
        std::vector<int> &toGlobal = model.surfaceVertexToGlobal[s];
        toGlobal.resize(surface.vertices.size());
        for (std::size_t v = 0; v < surface.vertices.size(); ++v) {
            const Vec3 &p = surface.vertices[v];
            if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
                throw InputError("surface " + surface.name + ": vertex " + std::to_string(v)
                                 + " has a non-finite coordinate");
            auto [it, inserted] = index.emplace(p, static_cast<int>(model.vertices.size()));
            if (inserted)
                model.vertices.push_back(p);
            toGlobal[v] = it->second;
        }
        for (std::size_t t = 0; t < surface.triangles.size(); ++t)
            for (int v : surface.triangles[t])
                if (v < 0 || static_cast<std::size_t>(v) >= surface.vertices.size())
                    throw InputError("surface " + surface.name + ": triangle " + std::to_string(t)
                                     + " uses vertex " + std::to_string(v) + " of "
                                     + std::to_string(surface.vertices.size()));
    }
}

struct LineEdge {
    int a, b;
    int incidence; // id of its sorted incident-surface set
};

struct LineEdgeGraph {
    std::vector<LineEdge> edges;
    std::vector<std::vector<int>> incidences; // by id
    std::vector<int> offset;                  // CSR: line edges around each global vertex
    std::vector<int> around;
};

LineEdgeGraph buildLineEdges(const Model &model)
{
    const std::vector<SurfaceEdge> records = surfaceEdges(model);
    LineEdgeGraph g;
    std::map<std::vector<int>, int> incidenceId;
    std::vector<int> surfaces;
    for (std::size_t i = 0; i < records.size();) {
        std::size_t j = i;
        bool border = false;
        surfaces.clear();
        for (; j < records.size() && records[j].key == records[i].key; ++j) {
            border = border || records[j].triangles == 1;
            if (surfaces.empty() || surfaces.back() != records[j].surface)
                surfaces.push_back(records[j].surface);
        }
        if (border || surfaces.size() >= 2) {
            auto [it, inserted] =
                incidenceId.emplace(surfaces, static_cast<int>(g.incidences.size()));
            if (inserted)
                g.incidences.push_back(surfaces);
            g.edges.push_back(
                {edgeKeyFirst(records[i].key), edgeKeySecond(records[i].key), it->second});
        }
        i = j;
    }
    g.offset.assign(model.vertices.size() + 1, 0);
    for (const LineEdge &e : g.edges) {
        ++g.offset[e.a + 1];
        ++g.offset[e.b + 1];
    }
    for (std::size_t v = 0; v < model.vertices.size(); ++v)
        g.offset[v + 1] += g.offset[v];
    g.around.resize(g.offset.back());
    std::vector<int> fill(g.offset.begin(), g.offset.end() - 1);
    for (std::size_t e = 0; e < g.edges.size(); ++e) {
        g.around[fill[g.edges[e].a]++] = static_cast<int>(e);
        g.around[fill[g.edges[e].b]++] = static_cast<int>(e);
    }
    return g;
}

bool isCornerVertex(const LineEdgeGraph &g, int v)
{
    const int degree = g.offset[v + 1] - g.offset[v];
    if (degree == 0)
        return false;
    if (degree != 2)
        return true;
    return g.edges[g.around[g.offset[v]]].incidence != g.edges[g.around[g.offset[v] + 1]].incidence;
}

int otherEnd(const LineEdge &e, int v)
{
    return e.a == v ? e.b : e.a;
}

void buildLinesAndCorners(Model &model)
{
    const LineEdgeGraph g = buildLineEdges(model);
    model.lines.clear();
    model.corners.clear();

    std::vector<int> cornerOf(model.vertices.size(), -1);
    for (int v = 0; v < static_cast<int>(model.vertices.size()); ++v)
        if (isCornerVertex(g, v)) {
            cornerOf[v] = static_cast<int>(model.corners.size());
            model.corners.push_back({v, {}});
        }

    std::vector<char> used(g.edges.size(), 0);
    auto newLine = [&](int firstEdge) -> Line & {
        Line line;
        line.name = "line_" + std::to_string(model.lines.size());
        line.surfaces = g.incidences[g.edges[firstEdge].incidence];
        model.lines.push_back(std::move(line));
        return model.lines.back();
    };

    // Open lines: walk from every corner along each unused line edge until the next corner.
    for (std::size_t c = 0; c < model.corners.size(); ++c) {
        const int start = model.corners[c].vertex;
        for (int k = g.offset[start]; k < g.offset[start + 1]; ++k) {
            int e = g.around[k];
            if (used[e])
                continue;
            Line &line = newLine(e);
            line.vertices.push_back(start);
            int current = start;
            while (true) {
                used[e] = 1;
                current = otherEnd(g.edges[e], current);
                line.vertices.push_back(current);
                if (cornerOf[current] >= 0)
                    break;
                // A non-corner line vertex has exactly two line edges.
                const int first = g.around[g.offset[current]];
                e = first == e ? g.around[g.offset[current] + 1] : first;
            }
            line.corners = {static_cast<int>(c), cornerOf[current]};
        }
    }

    // What remains are cycles through vertices that are not corners: closed lines.
    for (std::size_t e0 = 0; e0 < g.edges.size(); ++e0) {
        if (used[e0])
            continue;
        int e = static_cast<int>(e0);
        Line &line = newLine(e);
        line.closed = true;
        const int start = g.edges[e].a;
        int current = start;
        line.vertices.push_back(start);
        while (true) {
            used[e] = 1;
            current = otherEnd(g.edges[e], current);
            if (current == start)
                break;
            line.vertices.push_back(current);
            const int first = g.around[g.offset[current]];
            e = first == e ? g.around[g.offset[current] + 1] : first;
        }
    }

    for (std::size_t l = 0; l < model.lines.size(); ++l) {
        const Line &line = model.lines[l];
        for (int s : line.surfaces)
            model.surfaces[s].lines.push_back(static_cast<int>(l));
        if (!line.closed) {
            model.corners[line.corners[0]].lines.push_back(static_cast<int>(l));
            if (line.corners[1] != line.corners[0])
                model.corners[line.corners[1]].lines.push_back(static_cast<int>(l));
        }
    }
    for (Corner &c : model.corners)
        std::sort(c.lines.begin(), c.lines.end());
}

void linkRegions(Model &model)
{
    const int n = static_cast<int>(model.surfaces.size());
    auto checkSide = [&](const std::string &owner, const RegionSide &side) {
        if (side.surface < 0 || side.surface >= n)
            throw InputError(owner + " lists surface " + std::to_string(side.surface)
                             + " but the model has " + std::to_string(n) + " surfaces");
    };
    for (const RegionSide &side : model.universe)
        checkSide("the Universe", side);
    for (std::size_t r = 0; r < model.regions.size(); ++r)
        for (const RegionSide &side : model.regions[r].boundaries) {
            checkSide("region " + model.regions[r].name, side);
            std::vector<int> &regions = model.surfaces[side.surface].regions;
            if (std::find(regions.begin(), regions.end(), static_cast<int>(r)) == regions.end())
                regions.push_back(static_cast<int>(r));
        }
    for (Surface &s : model.surfaces)
        std::sort(s.regions.begin(), s.regions.end());
}

} // namespace

Model recoverTopology(Model model)
{
    for (Surface &s : model.surfaces) {
        s.lines.clear();
        s.regions.clear();
    }
    buildGlobalVertices(model);
    buildLinesAndCorners(model);
    linkRegions(model);
    return model;
}

} // namespace stratamesh
