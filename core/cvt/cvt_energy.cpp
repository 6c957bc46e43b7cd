#include "cvt/cvt_energy.h"

#include "common/error.h"
#include "voronoi/voronoi_neighbours.h"

#include <chrono>
#include <cmath>

namespace stratamesh {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

double CvtEvaluation::gradientNorm() const
{
    double s = 0;
    for (const Vec3 &g : gradient)
        s += g.squaredNorm();
    return std::sqrt(s);
}

CvtEvaluation evaluateCvtEnergy(const RestrictionDomain &domain, const std::vector<Vec3> &sites,
                                double alpha, CellIntegralsWorkspace &workspace,
                                NeighbourSearch search)
{
    if (!(alpha >= 0 && alpha <= 1))
        throw InputError("alpha must be in [0, 1], got " + std::to_string(alpha));
    CvtEvaluation r;
    auto start = std::chrono::steady_clock::now();
    const VoronoiNeighbours delaunay = search == NeighbourSearch::NearestNeighbours
                                           ? VoronoiNeighbours(sites, workspace.neighbourReuse)
                                           : VoronoiNeighbours(sites, search);
    r.delaunaySeconds = secondsSince(start);
    start = std::chrono::steady_clock::now();
    CellIntegralsOptions options;
    options.boundary = alpha > 0;
    r.cells = integrateCells(domain, delaunay, options, workspace);
    r.rvdSeconds = secondsSince(start);

    r.cvtEnergy = r.cells.totalEnergy();
    r.boundaryEnergy = r.cells.boundaryEnergy;
    r.energy = (1 - alpha) * r.cvtEnergy + alpha * r.boundaryEnergy;
    r.gradient.resize(sites.size());
    for (std::size_t i = 0; i < sites.size(); ++i) {
        // ∫ρ(s_i − y) · 2 = 2 m_i (s_i − g_i)
        r.gradient[i] = -2.0 * (1 - alpha) * r.cells.moment[i];
        if (alpha > 0)
            r.gradient[i] += alpha * r.cells.boundaryGradient[i];
    }
    return r;
}

} // namespace stratamesh
