// Intersections of segments and triangles of the model with one convex cell (thesis §3.3.2: the
// model elements met by a Voronoi cell). A point counts as inside when it is within the cell's
// tolerance of it, so elements touching a cell face meet both cells sharing it.
#pragma once

#include "complexity/convex_polyhedron.h"

#include <vector>

namespace stratamesh {

bool segmentMeetsCell(const Vec3 &a, const Vec3 &b, const ConvexPolyhedron &cell);
bool triangleMeetsCell(const Vec3 &a, const Vec3 &b, const Vec3 &c, const ConvexPolyhedron &cell);

// The part of a convex polygon inside the cell (Sutherland–Hodgman over the cell's planes);
// empty when they do not meet.
std::vector<Vec3> clipPolygonToCell(std::vector<Vec3> polygon, const ConvexPolyhedron &cell);

} // namespace stratamesh
