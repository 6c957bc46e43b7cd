// The faces of a mixed-mesh cell (tet, pyramid, prism) as polygons oriented with their right-hand
// normal out of the cell, and the corner tets whose volumes must all be positive for the cell to
// be well shaped. Node order is the one of volume_mesh.h (Gmsh's).
#pragma once

#include "mesh/volume_mesh.h"

#include <array>
#include <vector>

namespace stratamesh {

// A triangle (size 3, nodes[3] = -1) or a quad (size 4).
struct CellFace {
    std::array<int, 4> nodes{-1, -1, -1, -1};
    int size = 3;
    bool isQuad() const { return size == 4; }
};

// Tet: 4 triangles; pyramid: the base quad then 4 triangles; prism: 2 triangles then 3 quads.
std::vector<CellFace> outwardFaces(const Cell &cell);

// Node sets of the tets at each corner of the cell (a corner and its edge neighbours, ordered so
// that a well-shaped cell gives positive volumes): 1 for a tet, 4 for a pyramid (both diagonal
// splits of the base), 6 for a prism. A cell with a non-positive corner tet is inverted or
// degenerate at that corner even when its total volume is positive.
std::vector<std::array<int, 4>> cornerTets(const Cell &cell);

// The sorted node ids of a face: the key under which neighbouring cells find a shared face.
std::array<int, 4> faceKey(const CellFace &face);

} // namespace stratamesh
