#include "model/unused_vertices.h"

namespace stratamesh {

int dropUnusedVertices(Surface &surface)
{
    std::vector<int> newId(surface.vertices.size(), -1);
    for (const Triangle &t : surface.triangles)
        for (int v : t)
            newId[v] = 0;
    int kept = 0;
    for (std::size_t v = 0; v < newId.size(); ++v)
        if (newId[v] == 0) {
            surface.vertices[kept] = surface.vertices[v];
            newId[v] = kept++;
        }
    const int removed = static_cast<int>(surface.vertices.size()) - kept;
    if (removed == 0)
        return 0;
    surface.vertices.resize(kept);
    for (Triangle &t : surface.triangles)
        for (int &v : t)
            v = newId[v];
    return removed;
}

} // namespace stratamesh
