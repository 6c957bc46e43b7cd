// Segment-dual cells (thesis §5.3.2, Fig 5.3, Table 5.1 "edge part with 2 intersections"): a
// Voronoi edge of sites A, B, C crossing two surfaces bounding one region has a restricted Voronoi
// vertex on each, dual to a remesh triangle with points of A, B, C on each surface. The cell
// between the two triangles links the points of the same site: a prism, or a pyramid / tet where
// a site has one point shared by both surfaces (a contact line), as in the thesis.
//
// Here the Voronoi edge is found from its two dual triangles (same site triple on two surfaces of
// one region, each facing the other on the region's side), which is the same edge when each
// restricted cell component gives one point (§5.2). Cells are kept only when well shaped
// (positive corners, quads within the warp bound, no quad face lying on a surface) and thin (height
// at most thinRatio times the mean edge of their triangles); each remesh triangle bounds at most
// one cell.
#pragma once

#include "mesh/volume_mesh.h"
#include "model/model.h"

#include <cstddef>
#include <vector>

namespace stratamesh {

struct SegmentDualParams {
    double thinRatio = 1.5;
    double maxQuadWarpDegrees = 30.0;
};

struct SegmentDualCells {
    std::vector<Cell> cells;               // node ids index Model::vertices of the remeshed model
    std::vector<int> region;               // of each cell (index in Model::regions)
    std::size_t candidates = 0;            // triangle pairs with one site triple in a region
    std::size_t rejectedShape = 0;         // inverted, flat or warped (thesis §5.4 "invalid")
    std::size_t rejectedThick = 0;         // above the thin ratio: left to the tets
    std::size_t rejectedQuadOnSurface = 0; // a quad face half on a remesh triangle (box, fault)
    std::size_t rejectedTaken = 0;         // a triangle already used by a better cell
};

// `remesh` has topology (global vertices); pointSite[v] is the site of Model::vertices[v].
SegmentDualCells buildSegmentDualCells(const Model &remesh, const std::vector<int> &pointSite,
                                       const SegmentDualParams &params);

// The site of each point: the nearest one (each point lies in its restricted Voronoi cell).
std::vector<int> nearestSites(const std::vector<Vec3> &points, const std::vector<Vec3> &sites);

} // namespace stratamesh
