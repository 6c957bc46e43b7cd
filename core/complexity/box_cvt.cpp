#include "complexity/box_cvt.h"

#include "common/error.h"
#include "complexity/clipped_voronoi.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace stratamesh {

std::vector<Vec3> randomSitesInBox(const Box3 &box, int count, std::uint64_t seed)
{
    // mt19937_64's output is fixed by the standard; the distributions of <random> are not.
    std::mt19937_64 rng(seed);
    auto unit = [&rng]() { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
    std::vector<Vec3> sites(static_cast<std::size_t>(std::max(count, 0)));
    const Vec3 lo = box.min();
    const Vec3 size = box.sizes();
    for (Vec3 &s : sites) {
        const double x = unit();
        const double y = unit();
        const double z = unit();
        s = lo + Vec3(x * size.x(), y * size.y(), z * size.z());
    }
    return sites;
}

double cvtEnergy(const std::vector<Vec3> &sites, const std::vector<ConvexPolyhedron> &cells)
{
    return tbb::parallel_deterministic_reduce(
        tbb::blocked_range<std::size_t>(0, sites.size(), 512), 0.0,
        [&](const tbb::blocked_range<std::size_t> &r, double sum) {
            for (std::size_t i = r.begin(); i != r.end(); ++i)
                sum += cells[i].secondMoment(sites[i]);
            return sum;
        },
        [](double a, double b) { return a + b; });
}

BoxCvt runBoxCvt(const Box3 &box, const BoxCvtParams &params, Progress &progress)
{
    if (params.sites < 1)
        throw InputError("volumetric CVT: the number of cells must be at least 1, got "
                         + std::to_string(params.sites));
    if (box.isEmpty() || !(box.sizes().prod() > 0.0) || !box.sizes().allFinite())
        throw InputError("volumetric CVT: the box has no volume");
    BoxCvt result;
    result.box = box;
    result.sites = randomSitesInBox(box, params.sites, params.seed);
    const double cellSize = std::cbrt(box.sizes().prod() / params.sites);
    const int steps = std::max(params.iterations, 0);
    for (int step = 0;; ++step) {
        progress.tick(static_cast<double>(step) / (steps + 1), "volumetric CVT");
        result.cells = clippedVoronoiCells(result.sites, box);
        result.energy.push_back(cvtEnergy(result.sites, result.cells));
        if (step == steps)
            break;
        std::vector<double> moves(result.sites.size(), 0.0);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, result.sites.size(), 512),
                          [&](const tbb::blocked_range<std::size_t> &r) {
                              for (std::size_t i = r.begin(); i != r.end(); ++i) {
                                  if (result.cells[i].empty())
                                      continue;
                                  const Vec3 g = result.cells[i].centroid();
                                  moves[i] = (g - result.sites[i]).norm();
                                  result.sites[i] = g;
                              }
                          });
        ++result.iterations;
        if (*std::max_element(moves.begin(), moves.end()) < params.tolerance * cellSize) {
            result.cells = clippedVoronoiCells(result.sites, box);
            result.energy.push_back(cvtEnergy(result.sites, result.cells));
            break;
        }
    }
    progress.tick(1.0, "volumetric CVT");
    return result;
}

} // namespace stratamesh
