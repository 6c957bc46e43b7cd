// Voronoi cells of sites clipped to a box (thesis §1.1.1; used by the volumetric CVT of §3.5.2).
//
// Delaunay neighbours (CGAL Delaunay_triangulation_3) give the bisector planes of each cell; the
// box is clipped by them, nearest neighbour first. Each cell is computed on its own, in parallel,
// so the result does not depend on the number of threads.
#pragma once

#include "common/progress.h"
#include "complexity/convex_polyhedron.h"

#include <vector>

namespace stratamesh {

// Cell i is the part of box closer to sites[i] than to any other site; a face between cells i
// and j carries tag j, a box face a negative boxSideTag(). Throws InputError on duplicate or
// non-finite sites.
std::vector<ConvexPolyhedron> clippedVoronoiCells(const std::vector<Vec3> &sites, const Box3 &box,
                                                  Progress &progress = Progress::none());

} // namespace stratamesh
