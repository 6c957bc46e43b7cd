// Exporting a surface model or a volume mesh, the format chosen by the extension:
//   .ml  Gocad Model3d      .ts  Gocad TSurf        .so  Gocad TSolid (tets only)
//   .gm  RINGMesh GeoModel version 2 (surfaces, and the cells of a volume mesh per region)
//   .vtu VTK XML            .vtk VTK legacy 4.2     .vtp VTK poly data (surfaces only)
//   .msh Gmsh 4.1 or 2.2    .obj .off .stl .ply     one surface (OpenMesh)
// A model written as a mesh goes through meshFromModel(); a mesh written as a Gocad surface
// file or a single surface goes through modelFromMesh() (its cells are not part of those formats).
#pragma once

#include "io/gmsh_writer.h"
#include "mesh/volume_mesh.h"
#include "model/model.h"

#include <cstddef>
#include <string>

namespace stratamesh {

struct ExportOptions {
    GmshWriteOptions gmsh;
    int surface = -1; // .ts and single-surface formats: one surface (index), or all / the only one
};

struct ExportReport {
    std::string format;              // "Gmsh MSH 4.1", "Gocad Model3d", ...
    std::size_t untaggedSkipped = 0; // Gmsh elements without a group left out (see saveAll)
    std::size_t cellsDropped = 0;    // volume cells a surface format cannot hold
};

// True when the extension is one of the above.
bool isExportFile(const std::string &path);

// Both throw FileError for an unknown extension or a failed write, InputError when the data does
// not fit the format (cells in .vtp, no tets for .so, several surfaces for .obj...).
ExportReport exportModel(const Model &model, const std::string &path,
                         const ExportOptions &options = {});
ExportReport exportVolumeMesh(const VolumeMesh &mesh, const std::string &path,
                              const ExportOptions &options = {});

} // namespace stratamesh
