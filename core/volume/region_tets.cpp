#include "volume/region_tets.h"

namespace stratamesh {

std::vector<RegionTets> regionTets(const VolumeMesh &mesh)
{
    std::vector<RegionTets> result(mesh.regionNames.size());
    for (std::size_t c = 0; c < mesh.cells.size() && c < mesh.cellRegion.size(); ++c) {
        const int r = mesh.cellRegion[c];
        if (mesh.cells[c].type != CellType::Tet || r < 0 || r >= static_cast<int>(result.size()))
            continue;
        ++result[r].tets;
        result[r].volume += signedVolume(mesh, mesh.cells[c]);
    }
    return result;
}

} // namespace stratamesh
