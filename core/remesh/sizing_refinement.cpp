#include "remesh/sizing_refinement.h"

#include <algorithm>
#include <functional>
#include <map>
#include <utility>

namespace stratamesh {

namespace {

using Edge = std::pair<int, int>;

Edge key(int a, int b)
{
    return a < b ? Edge{a, b} : Edge{b, a};
}

bool nearAny(const Vec3 &p, const std::vector<Vec3> &targets, double radius2)
{
    if (targets.empty())
        return true;
    for (const Vec3 &t : targets)
        if ((p - t).squaredNorm() <= radius2)
            return true;
    return false;
}

// Splits the marked edges of one surface; `split` maps a global edge to its new global vertex.
void splitSurface(Model &model, int s, const std::map<Edge, int> &split)
{
    Surface &surface = model.surfaces[s];
    std::vector<int> &toGlobal = model.surfaceVertexToGlobal[s];
    std::map<int, int> local; // new global vertex → local vertex of this surface
    auto localOf = [&](int global) {
        auto [it, added] = local.emplace(global, static_cast<int>(surface.vertices.size()));
        if (added) {
            surface.vertices.push_back(model.vertices[global]);
            toGlobal.push_back(global);
        }
        return it->second;
    };
    std::vector<Triangle> out;
    out.reserve(surface.triangles.size());
    // The longest marked edge first, then the halves again: each half holds the other marked
    // edges whole.
    std::function<void(const Triangle &)> divide = [&](const Triangle &t) {
        int best = -1;
        double longest = -1.0;
        for (int k = 0; k < 3; ++k) {
            const int a = toGlobal[t[k]], b = toGlobal[t[(k + 1) % 3]];
            if (split.count(key(a, b)) == 0)
                continue;
            const double length = (model.vertices[a] - model.vertices[b]).squaredNorm();
            if (length > longest) {
                longest = length;
                best = k;
            }
        }
        if (best < 0) {
            out.push_back(t);
            return;
        }
        const int x = t[best], y = t[(best + 1) % 3], z = t[(best + 2) % 3];
        const int m = localOf(split.at(key(toGlobal[x], toGlobal[y])));
        divide({x, m, z});
        divide({m, y, z});
    };
    for (const Triangle &t : surface.triangles)
        divide(t);
    surface.triangles = std::move(out);
}

void splitLine(Line &line, const std::map<Edge, int> &split)
{
    const std::size_t n = line.vertices.size();
    if (n < 2)
        return;
    std::vector<int> out;
    out.reserve(n);
    const std::size_t segments = line.closed ? n : n - 1;
    for (std::size_t i = 0; i < n; ++i) {
        out.push_back(line.vertices[i]);
        if (i < segments) {
            auto it = split.find(key(line.vertices[i], line.vertices[(i + 1) % n]));
            if (it != split.end())
                out.push_back(it->second);
        }
    }
    line.vertices = std::move(out);
}

} // namespace

SizedModel refineToSize(const Model &model, const FeatureSizingParams &params,
                        const std::vector<Vec3> &targets, double radius, int passes)
{
    SizedModel out{model, {}, {}, static_cast<int>(model.vertices.size())};
    const double reach = params.edgeLength / (params.lfsFactor > 0.0 ? params.lfsFactor : 1.0);
    const double r2 = radius * radius;
    for (int pass = 0;; ++pass) {
        Model &m = out.model;
        out.size = sizingFromLfs(m, localFeatureSizes(m, reach, params.wedgeSine), params).size;
        if (pass >= passes)
            break;
        std::map<Edge, int> split;
        for (std::size_t s = 0; s < m.surfaces.size(); ++s)
            for (const Triangle &t : m.surfaces[s].triangles)
                for (int k = 0; k < 3; ++k) {
                    const int a = m.surfaceVertexToGlobal[s][t[k]];
                    const int b = m.surfaceVertexToGlobal[s][t[(k + 1) % 3]];
                    const Vec3 &pa = m.vertices[a], &pb = m.vertices[b];
                    const double h = std::min(out.size[a], out.size[b]);
                    if ((pa - pb).squaredNorm() > h * h && nearAny(0.5 * (pa + pb), targets, r2))
                        split.emplace(key(a, b), -1);
                }
        if (split.empty())
            break;
        for (auto &[edge, vertex] : split) {
            vertex = static_cast<int>(m.vertices.size());
            m.vertices.push_back(0.5 * (m.vertices[edge.first] + m.vertices[edge.second]));
            out.parents.push_back({edge.first, edge.second});
        }
        for (std::size_t s = 0; s < m.surfaces.size(); ++s)
            splitSurface(m, static_cast<int>(s), split);
        for (Line &line : m.lines)
            splitLine(line, split);
    }
    return out;
}

std::vector<double> extendToAdded(const SizedModel &sized, std::vector<double> field)
{
    if (field.empty())
        return field;
    field.resize(sized.firstAdded);
    for (const std::array<int, 2> &p : sized.parents)
        field.push_back(0.5 * (field[p[0]] + field[p[1]]));
    return field;
}

} // namespace stratamesh
