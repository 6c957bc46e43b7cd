// Thickness part C_e of the geometric complexity of surfaces (thesis §3.3.1, Fig 3.3): the share
// of the surface's boundary where the surface is narrower than h (a sliver between two close
// lines, e.g. a fault strip between two cutoff lines of a small throw).
//
// How we measure it (the thesis leaves it open): from the midpoint of every border edge (an edge
// with one triangle, by local vertex ids; cuts inside the surface are borders too) we walk inside
// the surface, straight across triangles (the direction is unfolded over each crossed edge),
// perpendicular to the edge, until we reach a border again. The width there is the walked length;
// the edge is thin when it is below h. C_e = length of thin border edges / border length.
#pragma once

#include "model/model.h"

namespace stratamesh {

double surfaceThinShare(const Surface &surface, double h);

} // namespace stratamesh
