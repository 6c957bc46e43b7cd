// Gocad TSolid (.so) output of a tetrahedral mesh (formats.md §1.7): one TVOLUME per region
// (vertices shared with an earlier TVOLUME written as ATOMs), then a MODEL section with one
// SURFACE per geological feature, one TFACE per mesh surface (triangles by vertex id) and one
// MODEL_REGION side per region. Surface names and types, which the MODEL section cannot hold,
// go in HEADER keys "*tface*<k>*name:" and "*tface*<k>*type:" that other readers ignore.
// z is negated for ZPOSITIVE Depth, node order kept (the tets then read back positive).
#pragma once

#include "mesh/volume_mesh.h"

#include <string>

namespace stratamesh {

// Throws InputError when the mesh has no tet or has pyramids/prisms (TSolid holds tets only).
void writeGocadTSolid(const VolumeMesh &mesh, const std::string &path);

} // namespace stratamesh
