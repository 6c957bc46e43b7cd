// Local connectivity measure of the thesis (§3.3.2, §3.5.2, Table 3.4, Fig 3.7): for each cell of
// a volumetric Voronoi diagram, the number of model elements it meets.
//
// Exactly what is counted (box elements never are, as in the thesis: when the box is the model's
// bounding box, cells are clipped to it and box surfaces only touch them):
// - corners: inner corners whose nearest site is the cell's (a corner on a shared face counts
// once);
// - lines: per inner line, the pieces of the polyline inside the cell; two consecutive segments
//   meeting the cell belong to one piece when their common vertex is in the cell;
// - surfaces: per inner surface, the connected pieces of its triangles inside the cell; two
//   triangles are connected when they share an edge (by local vertex ids) that meets the cell, or
//   a vertex inside the cell;
// - regions: when some surface meets the cell, the union of the regions incident to those
//   surfaces, box surfaces included (a region met by a cell either crosses its boundary there or
//   contains it; box surfaces matter when the model does not fill its bounding box); otherwise
//   the one region containing the cell's site (ray casting, once per group of such cells sharing
//   faces; faces are found by their tags, see clipped_voronoi.h). Cells outside every region
//   count 0.
// A point within the cell tolerance of a cell counts as inside: elements lying exactly on a face
// meet both cells sharing it.
#pragma once

#include "common/progress.h"
#include "complexity/convex_polyhedron.h"
#include "model/model.h"

#include <vector>

namespace stratamesh {

struct CellElementCounts {
    int corners = 0;
    int lines = 0;
    int surfaces = 0;
    int regions = 0;
    int total() const { return corners + lines + surfaces + regions; }
};

// cells[i] is the Voronoi cell of sites[i]; a face tag j >= 0 names the cell across it. Requires
// topology (throws InputError otherwise). Parallel over cells; the result does not depend on the
// number of threads.
std::vector<CellElementCounts> countElementsInCells(const Model &model,
                                                    const std::vector<Vec3> &sites,
                                                    const std::vector<ConvexPolyhedron> &cells,
                                                    Progress &progress = Progress::none());

} // namespace stratamesh
