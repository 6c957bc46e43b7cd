// Exporting a surface model or a volume mesh, the format chosen by the extension (formats.h):
//   .ml  Gocad Model3d      .ts  Gocad TSurf        .so  Gocad TSolid (tets only)
//   .gm  RINGMesh GeoModel version 2 (surfaces, and the cells of a volume mesh per region)
//   .vtu VTK XML            .vtk VTK legacy 4.2     .vtp VTK poly data (surfaces only)
//   .msh Gmsh 4.1 or 2.2    .obj .off .stl .ply     one surface (OpenMesh)
// A model written as a mesh goes through meshFromModel(); a mesh written as a Gocad surface
// file or a single surface goes through modelFromMesh() (its cells are not part of those formats).
#pragma once

#include "io/formats.h"
#include "mesh/volume_mesh.h"
#include "model/model.h"

#include <string>

namespace stratamesh {

// ExportOptions and ExportReport are declared in formats.h, whose table these dispatch through.

// True when the extension is one of the above.
bool isExportFile(const std::string &path);

// Both throw FileError for an unknown extension or a failed write, InputError when the data does
// not fit the format (cells in .vtp, no tets for .so, several surfaces for .obj...).
ExportReport exportModel(const Model &model, const std::string &path,
                         const ExportOptions &options = {});
ExportReport exportVolumeMesh(const VolumeMesh &mesh, const std::string &path,
                              const ExportOptions &options = {});

} // namespace stratamesh
