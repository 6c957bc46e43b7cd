// Single surfaces from STL and PLY files as an exchange mesh with one surface (named after the
// file) and no region. ASCII PLY is parsed here so that double coordinates stay exact (OpenMesh 9
// reads them as floats), STL by stl_reader.h (welded, non-manifold edges kept); binary PLY goes
// through OpenMesh and is refused when OpenMesh changes its vertices or faces.
#pragma once

#include "mesh/volume_mesh.h"

#include <string>

namespace stratamesh {

// Throws FileError (with the line for ASCII PLY) when the file cannot be read or has no triangle.
VolumeMesh readStlOrPly(const std::string &path);

} // namespace stratamesh
