#include "model/surface_edges.h"

#include <algorithm>

namespace stratamesh {

std::vector<SurfaceEdge> surfaceEdges(const Model &model)
{
    std::vector<SurfaceEdge> edges;
    edges.reserve(model.triangleCount() * 2);
    std::vector<long long> local;
    for (std::size_t s = 0; s < model.surfaces.size(); ++s) {
        local.clear();
        for (const Triangle &t : model.surfaces[s].triangles)
            for (int i = 0; i < 3; ++i)
                if (t[i] != t[(i + 1) % 3])
                    local.push_back(edgeKey(t[i], t[(i + 1) % 3]));
        std::sort(local.begin(), local.end());
        const std::vector<int> &toGlobal = model.surfaceVertexToGlobal[s];
        for (std::size_t i = 0; i < local.size();) {
            std::size_t j = i;
            while (j < local.size() && local[j] == local[i])
                ++j;
            const int a = toGlobal[edgeKeyFirst(local[i])];
            const int b = toGlobal[edgeKeySecond(local[i])];
            if (a != b)
                edges.push_back({edgeKey(a, b), static_cast<int>(s), static_cast<int>(j - i)});
            i = j;
        }
    }
    std::sort(edges.begin(), edges.end(), [](const SurfaceEdge &x, const SurfaceEdge &y) {
        return x.key != y.key ? x.key < y.key : x.surface < y.surface;
    });
    return edges;
}

std::pair<std::vector<SurfaceEdge>::const_iterator, std::vector<SurfaceEdge>::const_iterator>
edgesWithKey(const std::vector<SurfaceEdge> &edges, long long key)
{
    return std::equal_range(
        edges.begin(), edges.end(), SurfaceEdge{key, 0, 0},
        [](const SurfaceEdge &x, const SurfaceEdge &y) { return x.key < y.key; });
}

} // namespace stratamesh
