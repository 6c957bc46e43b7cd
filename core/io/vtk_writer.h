// VTK output through VTK's IO modules (formats.md §5.1): XML unstructured grid (.vtu, binary,
// compressed), legacy unstructured grid (.vtk, file version 4.2, binary) and XML poly data
// (.vtp, surfaces only). Points are doubles; cells follow VTK node order (prisms remapped
// [0,2,1,3,5,4] from ours, formats.md §2.5), so VTK computes positive volumes.
//
// One grid holds cells, then triangles, then line edges, then corner vertices (.vtp: vertices,
// lines, triangles: VTK's poly data order). Cell data (-1 where it does not apply):
//   RegionId, SurfaceId, LineId (int), CellType (VTK cell type code, unsigned char),
//   <qualityName> (double, NaN off cells) when the mesh has a per-cell quality.
// Field data: MeshName, RegionNames, SurfaceNames, SurfaceFeatures, SurfaceTypes, LineNames,
// QualityName (UTF-8 bytes in an unsigned char array, each name ended by '\n': meshio and other
// readers reject VTK string arrays), ZPositiveDepth (int) and RegionSides (int: per region, the
// count of its sides then ±(surface+1), + when the region lies on the side the normal points to).
#pragma once

#include "mesh/volume_mesh.h"

#include <string>

namespace stratamesh {

enum class VtkFileKind { Vtu, LegacyVtk, Vtp };

// Writes atomically. Throws InputError for an invalid mesh or cells in a .vtp, FileError when VTK
// or the file system fails (the message says why).
void writeVtk(const VolumeMesh &mesh, const std::string &path, VtkFileKind kind);

} // namespace stratamesh
