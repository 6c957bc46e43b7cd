// Output faces dual to the restricted Voronoi diagram (thesis §4.4.1–4.4.2, Fig 4.3–4.5,
// Algorithm 4.3 step 3):
//  - one triangle per RVD vertex shared by three restricted cells (a triangle ∩ Voronoi edge),
//    joining the points of the three surface pieces around it;
//  - one polygon per Voronoi facet arc whose two ends see different points of one piece — the
//    Voronoi edges and facets meeting lines twice of Fig 4.5c–d — triangulated.
// Where a surface piece has two points (it touches two line components), each vertex of its
// boundary is attached to one of them: the line's own point along a line, and along the chain
// of Voronoi arcs between two lines the nearer one, with a single switch; the arc where the
// switch happens is the one that becomes a polygon.
//
// Orientation: facets follow their input triangle, so going around an RVD vertex through the
// supports of the incoming polygon edges visits the three cells counter-clockwise; the output
// triangles keep the input surface's orientation, which keeps region sides valid.
#pragma once

#include "common/progress.h"

#include "remesh/output_points.h"

namespace stratamesh {

struct DualFaceCounts {
    int vertexTriangles = 0;    // duals of RVD vertices
    int arcPolygons = 0;        // duals of arcs with two points on a side
    int collapsedFaces = 0;     // duals with fewer than three distinct points (after merges)
    int incompleteVertices = 0; // RVD vertices not seen by exactly three facets (should be 0)
};

// Triangles (tagged with their input surface) over the points of `points`.
std::vector<OutputTriangle> buildDualFaces(const RestrictionDomain &domain,
                                           const RestrictedVoronoiDiagram &cells,
                                           const CellComponents &components,
                                           const CellPoints &points, DualFaceCounts &counts,
                                           Progress &progress = Progress::none());

} // namespace stratamesh
