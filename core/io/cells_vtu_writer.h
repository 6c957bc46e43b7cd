// VTK export of convex cells with integer cell data: the Voronoi cells of the local complexity
// measures coloured by their element counts (thesis Fig 3.7), for ParaView or the GUI.
#pragma once

#include "complexity/convex_polyhedron.h"
#include "complexity/local_complexity.h"

#include <string>
#include <vector>

namespace stratamesh {

struct CellIntArray {
    std::string name;
    std::vector<int> values; // one per cell
};

// An unstructured grid (.vtu, binary XML) of VTK_POLYHEDRON cells, points in double precision,
// each cell with its own points; empty cells are left out and the "CellId" array keeps the index
// of each written cell. Writes through a temporary file (atomic). Throws InputError when an array
// does not have one value per cell, FileError when the file cannot be written.
void writeCellsVtu(const std::string &path, const std::vector<ConvexPolyhedron> &cells,
                   const std::vector<CellIntArray> &arrays);

// The cells of a local complexity run with arrays corners, lines, surfaces, regions, total.
void writeLocalComplexityVtu(const std::string &path, const LocalComplexity &local);

} // namespace stratamesh
