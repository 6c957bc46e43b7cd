// STL files (ASCII and binary) as one surface, read here rather than by OpenMesh, which unwelds
// the corners around an edge of three or more facets ("complex edge") without a word: corners
// with the same coordinates become one vertex and every facet is kept, as for OBJ and OFF.
#pragma once

#include "mesh/volume_mesh.h"

#include <string>

namespace stratamesh {

// One surface named after the file; throws FileError (with the line for ASCII, the facet for
// binary) for a malformed or truncated file, a degenerate facet or an out-of-bound coordinate.
VolumeMesh readStl(const std::string &path);

} // namespace stratamesh
