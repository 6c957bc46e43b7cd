#include "bench_cases.h"

#include "cvt/cvt_optimizer.h"
#include "cvt/initial_sampling.h"
#include "voronoi/restricted_voronoi.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace stratamesh::bench {

RestrictionDomain generatedSurface(int triangles)
{
    const int n = std::max(1, static_cast<int>(std::lround(std::sqrt(triangles / 2.0))));
    RestrictionDomain d;
    d.points.reserve(static_cast<std::size_t>(n + 1) * (n + 1));
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const double x = double(i) / n, y = double(j) / n;
            d.points.push_back(
                {x, y, 0.1 * std::sin(6 * x) * std::cos(4 * y) + 0.03 * std::sin(17 * x * y)});
        }
    const auto id = [n](int i, int j) { return j * (n + 1) + i; };
    d.triangles.reserve(2 * static_cast<std::size_t>(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            d.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            d.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    d.triangleSurface.assign(d.triangles.size(), 0);
    finalizeDomain(d);
    return d;
}

double peakRssMb()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024.0; // kilobytes on Linux
}

void printSpread(const char *what, std::vector<double> seconds)
{
    if (seconds.size() < 2)
        return;
    std::sort(seconds.begin(), seconds.end());
    const std::size_t n = seconds.size();
    const double median = n % 2 ? seconds[n / 2] : 0.5 * (seconds[n / 2 - 1] + seconds[n / 2]);
    std::printf("  %s over %zu runs: min %.3f s, median %.3f s, max %.3f s\n", what, n,
                seconds.front(), median, seconds.back());
    std::fflush(stdout);
}

BenchResult runCase(const std::string &name, const RestrictionDomain &domain, int sites,
                    int iterations, double alpha, int threads, NeighbourSearch search,
                    double setupSeconds)
{
    BenchResult r;
    r.name = name;
    r.triangles = domain.triangles.size();
    r.segments = domain.segments.size();
    r.sites = sites;
    const auto start = std::chrono::steady_clock::now();
    const std::vector<Vec3> initial = sampleSurfaces(domain, sites, 1);
    r.setupSeconds =
        setupSeconds
        + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CvtParams params;
    params.iterations = iterations;
    params.alpha = alpha;
    params.threads = threads;
    params.neighbourSearch = search;
    const CvtResult cvt = optimizeCvt(domain, initial, params);
    r.iterations = cvt.iterations;
    r.evaluations = cvt.evaluations;
    r.totalSeconds = cvt.totalSeconds;
    r.rvdSeconds = cvt.rvdSeconds;
    r.delaunaySeconds = cvt.delaunaySeconds;
    r.neighbourSearches = cvt.neighbourSearches;
    r.threads = cvt.threads;
    r.firstEnergy = cvt.initialEnergy;
    r.lastEnergy = cvt.energy.empty() ? cvt.initialEnergy : cvt.energy.back();
    const auto rvdStart = std::chrono::steady_clock::now();
    const RestrictedVoronoiDiagram rvd =
        computeRestrictedVoronoi(domain, cvt.sites, Progress::none(), search);
    r.finalRvdSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - rvdStart).count();
    r.peakRssMb = peakRssMb();
    return r;
}

} // namespace stratamesh::bench
