#include "complexity/clipped_voronoi.h"

#include "common/error.h"

#include "complexity/indexed_delaunay.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace stratamesh {

namespace {

using namespace indexed_delaunay;

std::vector<std::vector<int>> delaunayNeighbours(const std::vector<Vec3> &sites)
{
    for (std::size_t i = 0; i < sites.size(); ++i)
        if (!sites[i].allFinite())
            throw InputError("Voronoi cells: site " + std::to_string(i) + " is not finite");
    const Delaunay dt = triangulate(sites);
    if (dt.number_of_vertices() != sites.size())
        throw InputError("Voronoi cells: " + std::to_string(sites.size() - dt.number_of_vertices())
                         + " duplicate sites");
    std::vector<std::vector<int>> neighbours(sites.size());
    if (dt.dimension() == 3) {
        // The six edges of every finite tetrahedron: much cheaper than finite_edges(), which
        // circulates around each edge to visit it once; duplicates are removed below.
        for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
            for (int a = 0; a < 4; ++a) {
                for (int b = a + 1; b < 4; ++b) {
                    const int i = c->vertex(a)->info();
                    const int j = c->vertex(b)->info();
                    neighbours[i].push_back(j);
                    neighbours[j].push_back(i);
                }
            }
        }
        tbb::parallel_for(std::size_t(0), neighbours.size(), [&](std::size_t i) {
            std::sort(neighbours[i].begin(), neighbours[i].end());
            neighbours[i].erase(std::unique(neighbours[i].begin(), neighbours[i].end()),
                                neighbours[i].end());
        });
    } else {
        for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
            const int a = e->first->vertex(e->second)->info();
            const int b = e->first->vertex(e->third)->info();
            neighbours[a].push_back(b);
            neighbours[b].push_back(a);
        }
    }
    return neighbours;
}

ConvexPolyhedron cellOf(int i, const std::vector<Vec3> &sites, std::vector<int> &neighbours,
                        const ConvexPolyhedron &boxCell, ClipWorkspace &workspace)
{
    const Vec3 &s = sites[i];
    // Nearest first shrinks the cell fastest; the index breaks ties so the order is fixed.
    std::sort(neighbours.begin(), neighbours.end(), [&](int a, int b) {
        const double da = (sites[a] - s).squaredNorm();
        const double db = (sites[b] - s).squaredNorm();
        return da < db || (da == db && a < b);
    });
    ConvexPolyhedron cell = boxCell;
    // Security radius: a bisector at distance d/2 from the site cannot cut a cell whose vertices
    // all lie within d/2 of it, nor can any farther neighbour's (Lévy and Bao 2014 use the same).
    double radius2 = cell.maxSquaredDistance(s);
    for (int j : neighbours) {
        const double d2 = (sites[j] - s).squaredNorm();
        if (0.25 * d2 > radius2 * (1.0 + 1e-9))
            break;
        HalfSpace h;
        h.normal = sites[j] - s;
        h.offset = h.normal.dot(0.5 * (sites[j] + s));
        h.tag = j;
        if (cell.clip(h, workspace)) {
            if (cell.empty())
                break;
            radius2 = cell.maxSquaredDistance(s);
        }
    }
    return cell;
}

} // namespace

std::vector<ConvexPolyhedron> clippedVoronoiCells(const std::vector<Vec3> &sites, const Box3 &box,
                                                  Progress &progress)
{
    if (box.isEmpty() || !box.min().allFinite() || !box.max().allFinite())
        throw InputError("Voronoi cells: the box is empty or not finite");
    std::vector<std::vector<int>> neighbours = delaunayNeighbours(sites);
    const ConvexPolyhedron boxCell = ConvexPolyhedron::box(box);
    std::vector<ConvexPolyhedron> cells(sites.size());
    progress.tick(0.0, "Voronoi cells");
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, sites.size(), 256),
                      [&](const tbb::blocked_range<std::size_t> &range) {
                          ClipWorkspace workspace;
                          for (std::size_t i = range.begin(); i != range.end(); ++i)
                              cells[i] = cellOf(static_cast<int>(i), sites, neighbours[i], boxCell,
                                                workspace);
                      });
    progress.tick(1.0, "Voronoi cells");
    return cells;
}

} // namespace stratamesh
