// The restricted Delaunay triangulation (RDT), dual of the restricted Voronoi diagram (thesis
// §1.2.3, Fig 1.5 and 1.9): one triangle (i, j, k) per restricted Voronoi vertex "triangle ∩
// Voronoi edge (i, j, k)", one edge (i, j) per restricted Voronoi vertex "line segment ∩
// bisector(i, j)". A diagnostic mesh over the sites: after a CVT its triangles are close to
// equilateral (quality/restricted_delaunay_quality.h measures them). The remesher (thesis ch. 4)
// builds the real output from the RVD components.
#pragma once

#include "voronoi/restricted_voronoi.h"

#include <array>
#include <vector>

namespace stratamesh {

struct RestrictedDelaunay {
    std::vector<Vec3> vertices;                // the sites
    std::vector<Triangle> triangles;           // site triples, oriented like the input triangle
    std::vector<int> triangleSurface;          // one triangle per (surface, triple)
    std::vector<std::array<int, 2>> lineEdges; // site pairs (i < j), one per (line, pair)
    std::vector<int> lineEdgeLine;
};

RestrictedDelaunay restrictedDelaunay(const RestrictionDomain &domain,
                                      const RestrictedVoronoiDiagram &rvd);

} // namespace stratamesh
