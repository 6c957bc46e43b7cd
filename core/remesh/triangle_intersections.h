// Intersecting triangles of a triangle soup with shared vertex ids (thesis §4.4.5: the Euclidean
// distance approximates the geodesic one, so output triangles may cross). Candidate pairs come
// from CGAL's box intersection (Zomorodian & Edelsbrunner 2000); each pair is decided with CGAL's
// exact predicates. Triangles that share a vertex or an edge intersect only when they overlap
// beyond it, as in CGAL::Polygon_mesh_processing::self_intersections.
#pragma once

#include "model/model.h"

#include <array>
#include <utility>
#include <vector>

namespace stratamesh {

// Pairs (i < j) of intersecting triangles. Exactly degenerate triangles (collinear corners) are
// skipped here; `degenerate` (optional) receives them.
std::vector<std::pair<int, int>> findIntersectingTriangles(const std::vector<Vec3> &points,
                                                           const std::vector<Triangle> &triangles,
                                                           std::vector<int> *degenerate = nullptr);

// Exact test for one pair, sharing vertices by id as above.
bool trianglesIntersect(const std::vector<Vec3> &points, const Triangle &a, const Triangle &b);

} // namespace stratamesh
