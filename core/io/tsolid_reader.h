// Gocad TSolid / LightTSolid (.so) input (formats.md §1.7) into the exchange mesh.
//
// Regions: one per TVOLUME name (LightTSolid: the "# CTETRA <region>" line after each TETRA).
// Vertices: an ATOM pointing to a vertex of an *earlier* TVOLUME is the same point (regions meet
// conformally); an ATOM into the same TVOLUME is a distinct point at the same position (a crack,
// as in solid_surf_inside.so). Surfaces: one per MODEL TFACE, feature = its SURFACE name, named
// "<SURFACE>" or "<SURFACE>_<i>" unless the HEADER key "*tface*<k>*name:" (our writer) names it.
// Region sides are recovered from the cells (regionSidesFromCells), not from MODEL_REGION.
// Coordinates come out z-up (z negated for ZPOSITIVE Depth).
#pragma once

#include "mesh/volume_mesh.h"

#include <string>

namespace stratamesh {

// Throws FileError("file:line: cause") for malformed content (unknown vertex ids, short lines...).
VolumeMesh readGocadTSolid(const std::string &path);

} // namespace stratamesh
