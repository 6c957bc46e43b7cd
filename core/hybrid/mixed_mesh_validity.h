// Validity of a mixed tet/pyramid/prism mesh (beyond thesis ch. 5, whose meshes were "not valid in
// the general case", §5.4/§5.6.1): what a finite-element code needs from a conformal mesh.
//   - every cell of positive volume, at every corner (cornerTets() of cell_faces.h);
//   - quad faces planar enough (warp between the two triangles of either diagonal split) and not
//     twisted (a split whose two triangles face opposite ways);
//   - every face shared by at most two cells, with the same nodes and opposite orientations, and
//     no triangle face lying on half of a neighbour's quad (non-conformal);
//   - faces on the boundary of the cells, and faces between two regions, are triangles of the
//     surface remesh (VolumeMesh::triangles), and every remesh triangle is a face of a cell;
//   - each cell in one region, and the cell volumes of a region summing to its volume.
// With positive corners and exactly matched faces the cells cover each region once (the degree
// of the map is one), so these checks together also exclude overlaps.
#pragma once

#include "mesh/volume_mesh.h"

#include <cstddef>
#include <string>
#include <vector>

namespace stratamesh {

struct MixedMeshCheckParams {
    double maxQuadWarpDegrees = 30.0;
    // Empty, or the expected volume of each region (model/region_volume.h).
    std::vector<double> regionVolumes;
    double volumeRelativeTolerance = 1e-6; // of the total expected volume
};

struct MixedMeshValidity {
    std::size_t nonPositiveCells = 0;    // a corner tet of volume <= 0
    std::size_t warpedQuads = 0;         // quad faces warped more than the bound (not twisted)
    std::size_t twistedQuads = 0;        // bow-tie quads
    std::size_t overSharedFaces = 0;     // faces of three or more cells
    std::size_t sameSidedFaces = 0;      // a face shared with the same orientation: overlap
    std::size_t nonConformalFaces = 0;   // a triangle face on half a quad face
    std::size_t boundaryOffSurface = 0;  // a face of one cell only that is not a remesh triangle
    std::size_t interfaceOffSurface = 0; // a face between two regions that is not one either
    std::size_t surfaceWithoutCell = 0;  // remesh triangles that are no cell face
    std::size_t cellsWithoutRegion = 0;
    std::size_t regionsWithWrongVolume = 0;
    double maxQuadWarpDegrees = 0.0;   // over all quad faces (twisted ones count as 180)
    std::vector<double> regionVolumes; // sum of the cell volumes of each region
    std::vector<int> invalidCells;     // sorted: cells involved in any local problem
    std::string firstProblem;          // one line for the user; empty when valid

    bool valid() const { return firstProblem.empty(); }
};

// Throws InputError when the mesh itself is inconsistent (validateMesh of volume_mesh.h) or when
// regionVolumes is neither empty nor one value per region.
MixedMeshValidity checkMixedMesh(const VolumeMesh &mesh, const MixedMeshCheckParams &params = {});

// Warp of a quad in degrees: the larger angle between the normals of the two triangles of each
// diagonal split; above 90 the quad is twisted.
double quadWarpDegrees(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d);

} // namespace stratamesh
