// Vertex-dual cells (thesis §5.3.3, Table 5.1 "vertex, 0 intersections → 1 cell"): a Voronoi
// vertex inside a region is dual to the Delaunay tet of the four sites whose cells meet there.
// Built where the four cells meet no surface (each is "1 interior vertex", its site), and where
// each cut cell gives one point on the vertex's side (cut_vertex_cells.h: tets linking sites and
// remesh points); the cells with 5–8 vertices (Fig 5.4, §5.4) are left to the constrained fill.
//
// Beyond the thesis, a tet is kept only when TetGen could not do better around it:
//   - its smallest dihedral angle is at least minDihedralDegrees (a CVT's Delaunay tets hold a
//     few slivers), and so are those of its face neighbours: a lone sliver left out would leave
//     a 4-point cavity that the fill can only close with the same sliver;
//   - the tet scaled by (1 + clearance) about its centroid meets no remesh triangle, so that the
//     fill between it and the surfaces is not a film of flat tets;
//   - its box, grown by the same clearance, meets no segment-dual cell's box (their transition
//     pyramids stand out of the thin layers).
#pragma once

#include "hybrid/cut_vertex_cells.h"
#include "mesh/volume_mesh.h"
#include "model/model.h"

#include <cstddef>
#include <vector>

namespace stratamesh {

struct VertexDualParams {
    double minDihedralDegrees = 15.0; // 180 turns the cells off
    double clearance = 0.5;           // of the tet's size, towards surfaces and thin-layer cells
    bool fillCutCells = false; // no tets of Voronoi vertices whose cells are cut: TetGen's instead
    // The transition pyramids the fill will stand on the thin-layer cells' free quads (apex height
    // over the square root of the quad area): cut-cell tets must not cross them either.
    double pyramidHeightRatio = 0.15;
};

struct VertexDualCells {
    std::vector<Vec3> points;      // the interior sites the cells use, in the order of their ids
    std::vector<Cell> cells;       // node ids: firstPointId + index in points
    std::vector<int> region;       // of each cell (index in Model::regions)
    std::size_t candidates = 0;    // Delaunay tets of four sites whose cells meet no surface
    std::size_t rejectedShape = 0; // below the dihedral bound, or beside such a tet
    std::size_t rejectedNearSurface = 0; // within the clearance of a remesh triangle
    std::size_t rejectedNearCells = 0;   // within the clearance of a segment-dual cell
    std::size_t rejectedOutside = 0;     // in no region of the model
    CutVertexStats cut;                  // the cut Voronoi vertices (cut_vertex_cells.h)
    std::size_t cutRejectedCrossing = 0; // cut-cell tets crossing a surface or another cell
    std::size_t cutKept = 0;             // of cells, the last ones
    std::size_t cutSplitKept = 0;        // of those, tets of cells split from their centroid
};

// `remesh` has topology; pointSite[v] is the site of Model::vertices[v]. The sites without a remesh
// point are taken as interior; the clearance test keeps their tets off the surfaces even when a
// cell met a surface too little to get a point. `segmentCells` index Model::vertices of `remesh`.
VertexDualCells buildVertexDualCells(const Model &remesh, const std::vector<Vec3> &sites,
                                     const std::vector<int> &pointSite,
                                     const std::vector<Cell> &segmentCells, int firstPointId,
                                     const VertexDualParams &params);

} // namespace stratamesh
