#include "cvt/initial_sampling.h"

#include "common/error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace stratamesh {

std::vector<Vec3> sampleSurfaces(const RestrictionDomain &domain, int count, std::uint64_t seed)
{
    if (count < 1)
        throw InputError("the number of sites must be at least 1, got " + std::to_string(count));
    const std::size_t nt = domain.triangles.size();
    std::vector<double> cumulative(nt);
    double total = 0;
    for (std::size_t t = 0; t < nt; ++t) {
        const Triangle &tri = domain.triangles[t];
        const Vec3 &a = domain.points[tri[0]], &b = domain.points[tri[1]],
                   &c = domain.points[tri[2]];
        double w = 0.5 * (b - a).cross(c - a).norm();
        if (!domain.density.empty())
            w *= (domain.density[tri[0]] + domain.density[tri[1]] + domain.density[tri[2]]) / 3.0;
        total += w;
        cumulative[t] = total;
    }
    if (!(total > 0))
        throw InputError("cannot place sites: the surfaces have no area");

    std::mt19937_64 rng(seed);
    const auto uniform = [&rng] { return static_cast<double>(rng() >> 11) * 0x1p-53; }; // [0, 1)
    std::vector<Vec3> sites;
    sites.reserve(count);
    for (int i = 0; i < count; ++i) {
        const double pick = uniform() * total;
        const std::size_t t = std::min<std::size_t>(
            nt - 1,
            static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), pick)
                                     - cumulative.begin()));
        const Triangle &tri = domain.triangles[t];
        // Uniform in the triangle: fold the unit square onto it.
        double u = uniform(), v = uniform();
        if (u + v > 1) {
            u = 1 - u;
            v = 1 - v;
        }
        const Vec3 &a = domain.points[tri[0]];
        sites.push_back(a + u * (domain.points[tri[1]] - a) + v * (domain.points[tri[2]] - a));
    }
    return sites;
}

} // namespace stratamesh
