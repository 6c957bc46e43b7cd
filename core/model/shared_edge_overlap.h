// Do two triangles with a common edge overlap beyond it? Only when they are coplanar and fold
// onto the same side of the edge. The validity report and the remesher's intersection repair
// ask it for every adjacent pair their box search returns, so it must be exact and cheap.
#pragma once

#include "model/model.h"

namespace stratamesh {

// Triangles (u, v, a) and (u, v, b): exact (CGAL predicates on the stored doubles).
bool sharedEdgeTrianglesOverlap(const Vec3 &u, const Vec3 &v, const Vec3 &a, const Vec3 &b);

} // namespace stratamesh
