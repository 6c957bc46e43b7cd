// The counts a legacy .vtk file declares (POINTS, CELLS, POLYGONS, CELL_DATA, array sizes), read
// by our own scan before VTK's reader runs: VTK allocates whatever a header claims and reads a
// short section without a word, so each count is checked against the file's size first and
// against what VTK read afterwards, with the line that declared it.
#pragma once

#include <string>

namespace stratamesh {

struct VtkLegacyCount {
    long long value = -1; // -1: not declared
    int line = 0;
};

struct VtkLegacyCounts {
    VtkLegacyCount points;
    VtkLegacyCount cells;     // CELLS (unstructured grid) or the sum of the poly data sections
    VtkLegacyCount cellTypes; // CELL_TYPES
    VtkLegacyCount cellData;  // CELL_DATA
    VtkLegacyCount pointData; // POINT_DATA
};

// Scans the file; throws FileError(path, line, cause) for a dataset type we do not read, a
// negative count, or a count the file is too small to hold.
VtkLegacyCounts scanVtkLegacyCounts(const std::string &path);

// Throws FileError naming the declaring line when VTK read a different number of points or cells.
void checkVtkLegacyCounts(const std::string &path, const VtkLegacyCounts &declared,
                          long long points, long long cells);

} // namespace stratamesh
