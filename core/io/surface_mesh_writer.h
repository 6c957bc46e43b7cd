// One surface of a model as OBJ, OFF, PLY or STL (format from the extension). These formats hold
// a single triangulated surface with no group. OBJ, OFF and ASCII PLY ("property double") are
// written here with the shortest text that reads back bit-exactly, because OpenMesh 9 writes and
// reads their coordinates as 32-bit floats whatever the mesh traits; binary STL, which stores
// floats by definition, goes through OpenMesh.
#pragma once

#include "model/model.h"

#include <string>

namespace stratamesh {

// surface < 0 means "the only surface" (an error when the model has several). Throws InputError
// for a missing or empty surface and for a non-manifold one in STL (OpenMesh stores manifold
// meshes only), FileError for an unknown extension or a failed write.
void writeSurfaceMesh(const Model &model, const std::string &path, int surface = -1);

// True for .obj, .off, .stl, .ply (case-insensitive).
bool isSurfaceMeshFile(const std::string &path);

} // namespace stratamesh
