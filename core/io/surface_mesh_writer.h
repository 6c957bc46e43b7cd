// One surface of a model as OBJ, OFF, STL or PLY through OpenMesh (format from the extension).
// These formats hold a single triangulated surface with no name or group; OBJ, OFF and PLY
// (ASCII, 17 significant digits) keep coordinates bit-exact, STL stores 32-bit floats by design.
#pragma once

#include "model/model.h"

#include <string>

namespace stratamesh {

// surface < 0 means "the only surface" (an error when the model has several). Throws InputError
// for a missing or non-manifold surface (OpenMesh stores manifold meshes only), FileError for an
// unknown extension or a failed write.
void writeSurfaceMesh(const Model &model, const std::string &path, int surface = -1);

// True for .obj, .off, .stl, .ply (case-insensitive).
bool isSurfaceMeshFile(const std::string &path);

} // namespace stratamesh
