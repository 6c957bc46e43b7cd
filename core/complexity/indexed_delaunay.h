// A CGAL Delaunay triangulation of sites whose vertices carry their site index, for the callers
// that walk its tets (clipped Voronoi cells, vertex-dual hybrid cells).
#pragma once

#include "model/model.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <utility>
#include <vector>

namespace stratamesh::indexed_delaunay {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<int, Kernel>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;

inline Kernel::Point_3 cgal(const Vec3 &p)
{
    return {p.x(), p.y(), p.z()};
}

// Duplicate sites keep one vertex (the caller compares number_of_vertices() with the sites).
inline Delaunay triangulate(const std::vector<Vec3> &sites)
{
    std::vector<std::pair<Kernel::Point_3, int>> points;
    points.reserve(sites.size());
    for (std::size_t i = 0; i < sites.size(); ++i)
        points.emplace_back(cgal(sites[i]), static_cast<int>(i));
    return Delaunay(points.begin(), points.end());
}

} // namespace stratamesh::indexed_delaunay
