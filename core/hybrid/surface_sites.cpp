#include "hybrid/surface_sites.h"

#include "voronoi/restricted_voronoi.h"
#include "voronoi/restriction_domain.h"

namespace stratamesh {

SurfaceSitesResult optimizeSurfaceSites(const Model &model, std::vector<Vec3> sites, int iterations,
                                        Progress &progress)
{
    SurfaceSitesResult out;
    const RestrictionDomain domain = makeRestrictionDomain(model);
    for (int it = 0; it < iterations; ++it) {
        progress.tick(double(it) / iterations, "sites on the surfaces (§5.2)");
        const RestrictedVoronoiDiagram rvd = computeRestrictedVoronoi(domain, sites);
        out.moved = 0;
        for (std::size_t s = 0; s < sites.size(); ++s)
            if (rvd.cells[s].area > 0.0) {
                sites[s] = rvd.cells[s].centroid;
                ++out.moved;
            }
        ++out.iterations;
    }
    out.sites = std::move(sites);
    return out;
}

} // namespace stratamesh
