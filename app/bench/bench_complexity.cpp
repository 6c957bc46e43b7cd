#include "bench_complexity.h"

#include "complexity/complexity_report.h"
#include "io/model_reader.h"
#include "model/topology.h"

#include <tbb/global_control.h>
#include <tbb/info.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <exception>
#include <memory>
#include <vector>

namespace stratamesh::bench {

namespace {

// The thesis's published values (Pellerin 2014, Tables 3.2, 3.3, 3.4) for A1, A2, A5.
struct ThesisTables {
    std::array<double, 4> geometric; // regions, surfaces, lines, total
    std::array<double, 4> variation; // regions, surfaces, lines, total
    // per 100, 1000, 10000 cells: Q10, Q50, Q90, max, mean, var. coeff.
    std::array<std::array<double, 6>, 3> local;
};

const ThesisTables kThesis[3] = {
    {{0.13, 0.03, 0.00, 0.16},
     {0.74, 0.00, 0.00, 0.74},
     {{{1, 5, 7, 7, 4.300, 0.547}, {1, 1, 5, 7, 2.500, 0.751}, {1, 1, 3, 5, 1.688, 0.728}}}},
    {{0.59, 3.21, 0.01, 3.81},
     {0.76, 0.93, 0.01, 1.71},
     {{{1, 5, 11, 15, 5.950, 0.630}, {1, 3, 7, 15, 3.137, 0.814}, {1, 1, 3, 11, 1.910, 0.788}}}},
    {{1.19, 9.30, 4.01, 14.50},
     {1.08, 1.74, 0.82, 3.64},
     {{{1, 5, 11, 30, 5.510, 0.775}, {1, 3, 6, 22, 2.950, 0.858}, {1, 1, 3, 19, 1.840, 0.795}}}},
};
const char *kModels[3] = {"modelA1", "modelA2", "modelA5"};

double since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void printGlobal(const std::vector<ComplexityReport> &reports)
{
    const char *rows[4] = {"regions", "surfaces", "lines", "total"};
    std::printf("  Table 3.2  geometric complexity C_t+C_f+C_e+C_a (h 100 m, alpha 20 deg): ours "
                "(thesis)\n");
    std::printf("  %-10s %16s %16s %16s\n", "", kModels[0], kModels[1], kModels[2]);
    for (int r = 0; r < 4; ++r) {
        std::printf("  %-10s", rows[r]);
        for (std::size_t m = 0; m < reports.size(); ++m) {
            const GeometricComplexity &g = reports[m].geometric;
            const double ours[4] = {g.regionsTotal, g.surfacesTotal, g.linesTotal, g.total()};
            std::printf("    %6.2f (%5.2f)", ours[r], kThesis[m].geometric[r]);
        }
        std::printf("\n");
    }
    std::printf(
        "\n  Table 3.3  variation coefficient of element sizes (std/mean): ours (thesis)\n");
    std::printf("  %-10s %16s %16s %16s\n", "", kModels[0], kModels[1], kModels[2]);
    for (int r = 0; r < 4; ++r) {
        std::printf("  %-10s", rows[r]);
        for (std::size_t m = 0; m < reports.size(); ++m) {
            const SizeVariation &v = reports[m].variation;
            const double ours[4] = {v.regions, v.surfaces, v.lines, v.total};
            std::printf("    %6.2f (%5.2f)", ours[r], kThesis[m].variation[r]);
        }
        std::printf("\n");
    }
}

void printLocal(const std::vector<ComplexityReport> &reports)
{
    const char *rows[6] = {"Q10", "Q50", "Q90", "max", "mean", "var.coeff"};
    std::printf("\n  Table 3.4  elements per cell: ours (thesis)\n");
    for (std::size_t n = 0; n < reports.front().local.size(); ++n) {
        std::printf("  %d cells\n", static_cast<int>(reports.front().local[n].counts.size()));
        for (int r = 0; r < 6; ++r) {
            std::printf("    %-10s", rows[r]);
            for (std::size_t m = 0; m < reports.size(); ++m) {
                const CountStatistics &s = reports[m].local[n].statistics;
                const double ours[6] = {double(s.q10), double(s.q50), double(s.q90),
                                        double(s.max), s.mean,        s.varCoeff};
                if (r < 4)
                    std::printf("   %5.0f (%5.0f)", ours[r], kThesis[m].local[n][r]);
                else
                    std::printf("   %5.3f (%5.3f)", ours[r], kThesis[m].local[n][r]);
            }
            std::printf("\n");
        }
    }
}

} // namespace

int runComplexityBench(const std::string &dataDir, int threads)
{
    std::unique_ptr<tbb::global_control> limit;
    if (threads > 0)
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      threads);
    const int used = static_cast<int>(
        tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
    std::printf(
        "complexity (thesis ch. 3), box excluded, seed 1, 30 Lloyd iterations, %d threads\n\n",
        used);
    try {
        std::vector<ComplexityReport> reports;
        std::vector<double> seconds;
        for (const char *name : kModels) {
            const auto start = std::chrono::steady_clock::now();
            const Model model = recoverTopology(readModel(dataDir + "/" + name + ".ml"));
            reports.push_back(computeComplexity(model, ComplexityParams{}));
            seconds.push_back(since(start));
        }
        printGlobal(reports);
        printLocal(reports);

        std::printf("\n  timings (s)\n");
        for (std::size_t m = 0; m < reports.size(); ++m) {
            std::printf("    %-8s total %.2f:", kModels[m], seconds[m]);
            for (const auto &[stage, s] : reports[m].timings)
                std::printf(" %s %.2f", stage.c_str(), s);
            std::printf("\n");
        }
        const LocalComplexity &a5 = reports.back().local.back();
        std::printf(
            "  modelA5, %d cells: CVT %.2f s (%d Lloyd iterations) + counts %.2f s = %.2f s "
            "(target <= 20 s on 2 cores)\n",
            static_cast<int>(a5.counts.size()), a5.cvtSeconds, a5.cvt.iterations, a5.countSeconds,
            a5.cvtSeconds + a5.countSeconds);
        std::fflush(stdout);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "stratamesh-bench: complexity: %s\n", e.what());
        return 1;
    }
    return 0;
}

} // namespace stratamesh::bench
