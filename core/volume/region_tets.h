// Tets and tet volume of each region of a volume mesh: what the TetGen comparison reports beside
// the region volume of the B-Rep (model/region_volume.h), which they must equal.
#pragma once

#include "mesh/volume_mesh.h"

#include <cstddef>
#include <vector>

namespace stratamesh {

struct RegionTets {
    std::size_t tets = 0;
    double volume = 0.0; // sum of signed tet volumes
};

// One entry per region name; tets without a region are left out.
std::vector<RegionTets> regionTets(const VolumeMesh &mesh);

} // namespace stratamesh
