// The Delaunay neighbour lists of VoronoiNeighbours (see voronoi_neighbours.h): CGAL
// Delaunay_triangulation_3 with exact predicates, plus every pair of each degenerate
// (cospherical, or cocircular on the hull) cluster. Internal to core/voronoi.
#pragma once

#include "model/model.h"

#include <vector>

namespace stratamesh::detail {

struct DelaunayLists {
    std::vector<char> hidden; // duplicates of a lower-index site
    std::vector<int> offsets; // CSR, unsorted neighbours
    std::vector<int> neighbours;
    int dimension = -1; // affine dimension of the sites
};

DelaunayLists delaunayNeighbourLists(const std::vector<Vec3> &sites);

} // namespace stratamesh::detail
