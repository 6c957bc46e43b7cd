#include "remesh/output_mesh.h"

#include <algorithm>
#include <iterator>

namespace stratamesh {

std::vector<int> OutputMesh::compact()
{
    std::vector<int> map(points.size(), -1);
    for (const OutputTriangle &t : triangles)
        for (int v : t.v)
            map[v] = 0;
    std::vector<OutputPoint> kept;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (map[i] < 0)
            continue;
        map[i] = static_cast<int>(kept.size());
        kept.push_back(std::move(points[i]));
    }
    points = std::move(kept);
    for (OutputTriangle &t : triangles)
        for (int &v : t.v)
            v = map[v];
    return map;
}

void mergeSortedIds(std::vector<int> &into, const std::vector<int> &from)
{
    std::vector<int> merged;
    merged.reserve(into.size() + from.size());
    std::set_union(into.begin(), into.end(), from.begin(), from.end(), std::back_inserter(merged));
    into = std::move(merged);
}

} // namespace stratamesh
