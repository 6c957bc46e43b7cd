// Single triangulated surfaces from OBJ and OFF files, read through OpenMesh: a model with one
// surface (type Unknown, named after the file stem) and no regions; topology is not built here.
#pragma once

#include "model/model.h"

#include <string>

namespace stratamesh {

// Throws FileError when the file cannot be read, has no triangle or a non-finite coordinate.
// Polygons are split into triangles by OpenMesh.
Model readSurfaceMesh(const std::string &path);

} // namespace stratamesh
