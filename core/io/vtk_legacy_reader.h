// Legacy VTK files (.vtk) read by our own parser rather than VTK's legacy reader, which
// dereferences null pointers and reads out of bounds on malformed files (fuzz_vtk_legacy).
//
// What it reads is what StrataMesh read through VTK 9.1: versions up to 4.2 (CELLS as "count id
// id ...") and 5.1 (OFFSETS and CONNECTIVITY, vtktypeint64 or vtktypeint32), ASCII or BINARY
// (big-endian), DATASET UNSTRUCTURED_GRID or POLYDATA, POINTS of any numeric type, CELL_DATA and
// POINT_DATA attributes (SCALARS with their LOOKUP_TABLE, COLOR_SCALARS, VECTORS, NORMALS,
// TENSORS, TEXTURE_COORDINATES, GLOBAL_IDS, PEDIGREE_IDS, EDGE_FLAGS, FIELD arrays, string arrays
// too) and the data set's FIELD arrays, with VTK's meaning: the first SCALARS (VECTORS...) of a
// section is kept, a later array replaces an array of its name, poly data cells are numbered
// vertices, lines, polygons then strips, each typed by its size as vtkPolyData types it.
//
// It refuses rather than guesses: a count the rest of the file cannot hold (before anything is
// sized by it), values short of or beyond a declared count, a section given twice, geometry after
// the data, a coordinate that is not finite or beyond ±1e15, a cell whose type StrataMesh does not
// exchange, whose point-id count its type does not have or which uses a point the file lacks.
// Each refusal is a FileError naming the line that causes it.
#pragma once

#include "io/vtk_legacy_arrays.h"

#include <string>
#include <vector>

namespace stratamesh {

struct VtkLegacyData {
    std::vector<double> points;              // x, y, z of each point
    std::vector<int> cellTypes;              // VTK cell type of each cell
    std::vector<long long> offsets{0};       // cell c uses connectivity[offsets[c], offsets[c+1])
    std::vector<long long> connectivity;     // point ids, each within the points
    std::vector<VtkLegacyArray> cellArrays;  // the CELL_DATA arrays, one per name
    std::vector<VtkLegacyArray> fieldArrays; // the data set's FIELD arrays, one per name
};

VtkLegacyData readVtkLegacy(const std::string &path);

} // namespace stratamesh
