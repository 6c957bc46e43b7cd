// VTK input: .vtu and .vtp through VTK's XML readers, legacy .vtk (unstructured grid or poly data)
// through our parser (vtk_legacy_reader.h).
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

// Throws FileError naming the file (and the line, or VTK's complaint) when it cannot be read.
VolumeMesh readVtk(const std::string &path);

} // namespace stratamesh
