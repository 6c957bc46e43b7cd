#include "remesh/site_sampling.h"

#include "common/error.h"
#include "voronoi/cell_integrals.h"
#include "voronoi/site_delaunay.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>

namespace stratamesh {

std::vector<Vec3> sampleSites(const RestrictionDomain &domain, int n, unsigned seed)
{
    if (n <= 0)
        throw InputError("the number of sites must be positive");
    std::vector<double> cumulative;
    cumulative.reserve(domain.triangles.size());
    double total = 0.0;
    for (const Triangle &t : domain.triangles) {
        const Vec3 &a = domain.points[t[0]], &b = domain.points[t[1]], &c = domain.points[t[2]];
        double w = 0.5 * (b - a).cross(c - a).norm();
        if (!domain.density.empty())
            w *= (domain.density[t[0]] + domain.density[t[1]] + domain.density[t[2]]) / 3.0;
        total += w;
        cumulative.push_back(total);
    }
    if (!(total > 0.0))
        throw InputError("cannot place sites: the model has no surface area");
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<Vec3> sites;
    sites.reserve(n);
    for (int i = 0; i < n; ++i) {
        const double r = uniform(rng) * total;
        const std::size_t t = std::min<std::size_t>(
            std::lower_bound(cumulative.begin(), cumulative.end(), r) - cumulative.begin(), cumulative.size() - 1);
        double u = uniform(rng), v = uniform(rng);
        if (u + v > 1.0) {
            u = 1.0 - u;
            v = 1.0 - v;
        }
        const Triangle &tri = domain.triangles[t];
        sites.push_back(domain.points[tri[0]] + u * (domain.points[tri[1]] - domain.points[tri[0]]) +
                        v * (domain.points[tri[2]] - domain.points[tri[0]]));
    }
    return sites;
}

LloydResult lloydRelaxation(const RestrictionDomain &domain, std::vector<Vec3> sites, int iterations,
                            Progress &progress)
{
    LloydResult result;
    CellIntegralsWorkspace workspace;
    CellIntegralsOptions options;
    options.boundary = false;
    for (int it = 0; it <= iterations; ++it) {
        progress.tick(iterations > 0 ? double(it) / iterations : 1.0, "Lloyd relaxation");
        const SiteDelaunay delaunay(sites);
        const CellIntegrals in = integrateCells(domain, delaunay, options, workspace);
        result.energy.push_back(in.totalEnergy());
        if (it == iterations)
            break;
        for (std::size_t i = 0; i < sites.size(); ++i)
            if (in.mass[i] > 0.0)
                sites[i] += in.moment[i] / in.mass[i];
    }
    result.sites = std::move(sites);
    return result;
}

} // namespace stratamesh
