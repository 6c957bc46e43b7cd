// Entry point for reading a structural model from any supported file, by extension.
#pragma once

#include "model/model.h"

#include <string>

namespace stratamesh {

// .ml and .ts (Gocad), .gm (RINGMesh GeoModel), .obj and .off (single surface), and the volume
// meshes of mesh_reader.h
// (.so, .msh, .vtu, .vtk, .vtp: their surfaces and regions); the extension is case-insensitive.
// Returns the model without topology (call recoverTopology). Throws FileError naming the file
// for an unknown extension, a missing file, or malformed content (with its line).
Model readModel(const std::string &path);

// True when readModel() knows the extension of this path.
bool isReadableModelFile(const std::string &path);

} // namespace stratamesh
