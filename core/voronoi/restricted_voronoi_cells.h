// Connected components of the restricted cells on surfaces and lines, and the per-cell summary
// of RestrictedVoronoiDiagram (thesis §1.2.1, Fig 1.8; used by Alg. 4.2 and Table 3.4).
#pragma once

#include "voronoi/restricted_voronoi.h"

namespace stratamesh {

// Fills polygons[].component, linePieces[].component, surfaceComponents, lineComponents and
// cells from the polygons, pieces and cornerSites. Two polygons of one cell are connected when
// they share an edge of their surface (same surface-local edge, domain.edgeIds); two pieces of
// one cell when they are consecutive along their line (closed lines wrap around).
void buildRestrictedCells(const RestrictionDomain &domain, RestrictedVoronoiDiagram &rvd);

} // namespace stratamesh
