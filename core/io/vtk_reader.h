// VTK input through VTK's readers: .vtu, .vtp, legacy .vtk (unstructured grid or poly data).
//
// Files from our writer (vtk_writer.h) come back whole: groups, names, types, region sides,
// quality. Foreign files: tets, pyramids, wedges (remapped to our prism order), triangles,
// lines/polylines and vertices are taken; RegionId/SurfaceId/LineId cell arrays are used when
// present, otherwise all cells form one region and all triangles one surface named after the
// file. Other cell types (quads, hexahedra, polygons...) are errors.
#pragma once

#include "mesh/volume_mesh.h"

#include <string>

namespace stratamesh {

// Throws FileError naming the file and VTK's complaint when it cannot be read.
VolumeMesh readVtk(const std::string &path);

} // namespace stratamesh
