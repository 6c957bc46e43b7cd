// Surface vertices that no triangle uses. A re-triangulation that drops a vertex (the fan centre
// of a pocket opened without it, pocket_repair.h) leaves it in the surface; after topology
// recovery it is a global point of no surface, lying on the surface it left. TetGen, given such a
// point in a PLC, throws from its boundary recovery (modelA2 remeshed at 1000 sites with its
// strips removed onto a line: two such points, "terminate called after throwing int").
#pragma once

#include "model/model.h"

namespace stratamesh {

// Removes the vertices no triangle of `surface` uses and renumbers its triangles (the order of
// the kept vertices is kept). Returns how many were removed. The model's topology, if any, is out
// of date afterwards when this returns more than 0.
int dropUnusedVertices(Surface &surface);

} // namespace stratamesh
