// The edges of all surfaces indexed by their global vertices: the common ground of topology
// recovery (line edges) and validity checks (free borders, non-manifold edges).
#pragma once

#include "model/model.h"

#include <utility>
#include <vector>

namespace stratamesh {

// Key of the undirected edge {a, b} between two vertex ids.
inline long long edgeKey(int a, int b)
{
    return a < b ? (static_cast<long long>(a) << 32) | static_cast<unsigned>(b)
                 : (static_cast<long long>(b) << 32) | static_cast<unsigned>(a);
}
inline int edgeKeyFirst(long long key)
{
    return static_cast<int>(key >> 32);
}
inline int edgeKeySecond(long long key)
{
    return static_cast<int>(key & 0xffffffffLL);
}

// Key of the unoriented triangle {a, b, c}: its vertex ids in increasing order.
inline Triangle sortedTriangle(int a, int b, int c)
{
    Triangle k{a, b, c};
    if (k[0] > k[1])
        std::swap(k[0], k[1]);
    if (k[1] > k[2])
        std::swap(k[1], k[2]);
    if (k[0] > k[1])
        std::swap(k[0], k[1]);
    return k;
}

// One distinct local edge of one surface (local vertex ids), mapped to its global vertices.
struct SurfaceEdge {
    long long key; // edgeKey of the two global vertices
    int surface;
    int triangles; // triangles of this surface around the local edge: 1 on its border
};

// All distinct local edges of all surfaces, sorted by key then surface. Local edges whose two
// vertices share one position (zero length) are left out. Requires surfaceVertexToGlobal.
std::vector<SurfaceEdge> surfaceEdges(const Model &model);

// The entries of `edges` (sorted as above) with the given key, as [first, last).
std::pair<std::vector<SurfaceEdge>::const_iterator, std::vector<SurfaceEdge>::const_iterator>
edgesWithKey(const std::vector<SurfaceEdge> &edges, long long key);

} // namespace stratamesh
