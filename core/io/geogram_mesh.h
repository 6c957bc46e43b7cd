// Meshes inside Geogram GeoFiles, as geogram's mesh_io.cpp stores them (attribute sets
// "GEO::Mesh::vertices", "GEO::Mesh::edges", "GEO::Mesh::facets" + "GEO::Mesh::facet_corners",
// "GEO::Mesh::cells" + "GEO::Mesh::cell_corners"). Simplicial meshes have no facet_ptr / cell_ptr
// / cell_type attributes: facet f uses corners 3f..3f+2, cell c corners 4c..4c+3.
#pragma once

#include "io/geogram_file.h"
#include "mesh/volume_mesh.h"
#include "model/model.h"

#include <array>
#include <string>
#include <vector>

namespace stratamesh {

// Each throws FileError(where, cause) when an attribute is missing, has the wrong type, or refers
// to items that do not exist (vertex ids, corner ranges, counts that disagree).
std::vector<Vec3> geogramPoints(const GeogramFile &file, const std::string &where);
std::vector<std::array<int, 2>> geogramEdges(const GeogramFile &file, std::size_t vertexCount,
                                             const std::string &where);
// Polygons are split into fans around their first corner.
std::vector<Triangle> geogramTriangles(const GeogramFile &file, std::size_t vertexCount,
                                       const std::string &where);
// Tets, prisms and pyramids (geogram cell types 0, 2, 3; same node order as VolumeMesh).
std::vector<Cell> geogramCells(const GeogramFile &file, std::size_t vertexCount,
                               const std::string &where);

// GeoFiles of one entity mesh. Triangles get their corner_adjacent_facet (geogram keeps the facet
// across the edge from each corner to the next; 0xffffffff on a border), cells their types.
GeogramFile geogramPointMesh(const std::vector<Vec3> &points);
GeogramFile geogramLineMesh(const std::vector<Vec3> &points,
                            const std::vector<std::array<int, 2>> &edges);
GeogramFile geogramSurfaceMesh(const std::vector<Vec3> &points,
                               const std::vector<Triangle> &triangles);
GeogramFile geogramVolumeMesh(const std::vector<Vec3> &points, const std::vector<Cell> &cells);

} // namespace stratamesh
