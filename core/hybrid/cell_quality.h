// Quality of mixed-mesh cells: dihedral angles between adjacent faces (quads with their mean
// normal), per cell and summarised per cell type, for the hybrid report and the comparison with
// TetGen meshes (thesis §5.1: "less elements of, a priori, better quality").
#pragma once

#include "mesh/volume_mesh.h"

#include <array>
#include <cstddef>
#include <vector>

namespace stratamesh {

struct DihedralRange {
    double minDegrees = 180.0;
    double maxDegrees = 0.0;
};

// Min and max interior dihedral angle of the cell over its edges.
DihedralRange cellDihedrals(const VolumeMesh &mesh, const Cell &cell);

struct TypeQuality {
    std::size_t cells = 0;
    double minDihedral = 180.0; // over the cells of the type; 180/0 when there is none
    double maxDihedral = 0.0;
    // Mean over the cells of each one's smallest dihedral: the bulk of the shapes, where min and
    // max only tell the worst cell.
    double meanMinDihedral = 0.0;
    std::size_t slivers = 0; // tets only: a dihedral below 5 or above 175 degrees
};

// Indexed by CellType (Tet, Pyramid, Prism).
std::array<TypeQuality, 3> qualityByType(const VolumeMesh &mesh);

// The same per region (one entry per VolumeMesh::regionNames; untagged cells are left out): the
// thesis's claim is about the thin layers, so the comparison with TetGen is made region by region.
std::vector<std::array<TypeQuality, 3>> qualityByRegionAndType(const VolumeMesh &mesh);

} // namespace stratamesh
