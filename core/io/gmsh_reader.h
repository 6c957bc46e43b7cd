// Gmsh MSH 2.2 and 4.1 ASCII input (formats.md §2) into the exchange mesh.
//
// Groups: in a dimension where the file has physical groups, each physical group is a region
// (3D), surface (2D) or line (1D), named by $PhysicalNames ("region_<tag>" etc. otherwise) and
// ordered by tag; elements outside any group are untagged (-1). In a dimension without physical
// groups, each geometric entity is a group. Region sides come from the bounding surfaces of
// MSH 4.1 volume entities (+ = surface normal points out of the volume). Points (type 15) are
// corners. Other element types (quads, hexahedra, higher order) and binary files are errors.
#pragma once

#include "mesh/volume_mesh.h"

#include <string>

namespace stratamesh {

// Throws FileError("file:line: cause") on anything it cannot read faithfully.
VolumeMesh readGmsh(const std::string &path);

} // namespace stratamesh
