// Reading the exchange meshes by extension, through the table of formats.h: Gocad TSolid (.so),
// Gmsh (.msh), VTK (.vtu, .vtk, .vtp), RINGMesh (.gm: its region meshes), and single surfaces in
// STL or PLY. Surface-only files give a mesh without cells; readMeshAsModel() turns any of them
// into a surface model (as readModel() does for the formats that hold volume meshes).
#pragma once

#include "mesh/volume_mesh.h"
#include "model/model.h"

#include <string>

namespace stratamesh {

// True for .so, .msh, .vtu, .vtk, .vtp (case-insensitive): the formats that may hold cells
// (FormatHolds::VolumeMesh).
bool isVolumeMeshFile(const std::string &path);
// True for every extension readVolumeMesh() knows: the above plus .stl, .ply and .gm (RINGMesh:
// its surfaces, and the tets of its meshed regions).
bool isMeshReaderFile(const std::string &path);

// Throws FileError for an unknown extension or unreadable content (file, line and cause).
VolumeMesh readVolumeMesh(const std::string &path);

// The surfaces and regions of such a file as a Model (modelFromMesh): no topology, cells dropped.
Model readMeshAsModel(const std::string &path);

} // namespace stratamesh
