// stratamesh-bench [--case a|b|complexity|remesh|hybrid|all] [--data-dir DIR] [--iterations N]
// [--threads N] [--alpha A]
//                  [--neighbours delaunay|nearest|both] [--repeat N]
// Prints the Voronoi engine figures of issue 3: (a) modelA5 at 5000 sites, (b) a generated
// surface of 1,000,000 triangles at 30,000 sites, 100 iterations each by default, with the
// Delaunay neighbours and with the k nearest ones (same diagram, voronoi_neighbours.h); and the
// complexity section (issue 5: Tables 3.2-3.4 beside the thesis, 10,000 cells on modelA5).
// The hybrid section (issue 19): modelA1 at 5000 sites, the share of each stage.
// --repeat N runs cases (a), (b), our remesh and the hybrid mesh N times and prints the spread of
// their timings.
#include "bench_cases.h"
#include "bench_complexity.h"
#include "bench_hybrid.h"
#include "bench_remesh.h"

#include "io/model_reader.h"
#include "model/topology.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <utility>
#include <vector>

using namespace stratamesh;

namespace {

void print(const bench::BenchResult &r)
{
    std::printf("%s\n", r.name.c_str());
    std::printf("  input             %zu triangles, %zu line segments\n", r.triangles, r.segments);
    std::printf("  sites             %d\n", r.sites);
    std::printf("  iterations        %d (%d energy evaluations)\n", r.iterations, r.evaluations);
    std::printf("  energy            %.6g -> %.6g\n", r.firstEnergy, r.lastEnergy);
    std::printf("  setup             %.3f s (read, topology, domain, sampling)\n", r.setupSeconds);
    std::printf("  optimisation      %.3f s total\n", r.totalSeconds);
    std::printf("  RVD integration   %.3f s, %.2f ms per evaluation\n", r.rvdSeconds,
                1e3 * r.rvdSeconds / std::max(1, r.evaluations));
    std::printf("  neighbours        %.3f s, %.2f ms per evaluation, %d searches (other "
                "evaluations reused the lists)\n",
                r.delaunaySeconds, 1e3 * r.delaunaySeconds / std::max(1, r.evaluations),
                r.neighbourSearches);
    std::printf("  final symbolic RVD %.3f s\n", r.finalRvdSeconds);
    std::printf("  peak memory       %.0f MB\n", r.peakRssMb);
    std::printf("  threads           %d\n", r.threads);
    std::fflush(stdout);
}

template <class Run>
void runRepeated(int repeat, Run &&run)
{
    std::vector<double> seconds;
    for (int r = 0; r < repeat; ++r) {
        const bench::BenchResult result = run();
        print(result);
        seconds.push_back(result.totalSeconds);
    }
    bench::printSpread("optimisation", seconds);
}

} // namespace

int main(int argc, char **argv)
{
    // The data folder: --data-dir, else STRATAMESH_DATA_DIR, else the one configured by CMake.
    const char *environment = std::getenv("STRATAMESH_DATA_DIR");
    std::string which = "all", dataDir = environment ? environment : STRATAMESH_BENCH_DATA_DIR,
                neighbours = "both";
    int iterations = 100, threads = 0, repeat = 1;
    double alpha = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "stratamesh-bench: %s needs a value\n", a.c_str());
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--case")
            which = value();
        else if (a == "--data-dir")
            dataDir = value();
        else if (a == "--iterations")
            iterations = std::atoi(value().c_str());
        else if (a == "--threads")
            threads = std::atoi(value().c_str());
        else if (a == "--alpha")
            alpha = std::atof(value().c_str());
        else if (a == "--neighbours")
            neighbours = value();
        else if (a == "--repeat")
            repeat = std::max(1, std::atoi(value().c_str()));
        else {
            std::fprintf(
                stderr,
                "usage: stratamesh-bench [--case a|b|complexity|remesh|hybrid|all] [--data-dir "
                "DIR] "
                "[--iterations N] "
                "[--threads N] [--alpha A] [--neighbours delaunay|nearest|both] [--repeat N]\n");
            return 2;
        }
    }
    std::vector<std::pair<NeighbourSearch, std::string>> searches;
    if (neighbours == "delaunay" || neighbours == "both")
        searches.emplace_back(NeighbourSearch::Delaunay, "Delaunay neighbours");
    if (neighbours == "nearest" || neighbours == "both")
        searches.emplace_back(NeighbourSearch::NearestNeighbours, "k-nearest neighbours");
    if (searches.empty()) {
        std::fprintf(stderr, "stratamesh-bench: --neighbours takes delaunay, nearest or both\n");
        return 2;
    }
    try {
        if (which == "a" || which == "all") {
            const auto start = std::chrono::steady_clock::now();
            const std::string path = dataDir + "/modelA5.ml";
            const Model model = recoverTopology(readModel(path));
            const RestrictionDomain domain = makeRestrictionDomain(model);
            const double setup =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            for (const auto &[search, label] : searches)
                runRepeated(repeat, [&] {
                    return bench::runCase("(a) modelA5, 5000 sites, " + label, domain, 5000,
                                          iterations, alpha, threads, search, setup);
                });
        }
        if (which == "b" || which == "all") {
            const auto start = std::chrono::steady_clock::now();
            const RestrictionDomain domain = bench::generatedSurface(1000000);
            const double setup =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            for (const auto &[search, label] : searches)
                runRepeated(repeat, [&] {
                    return bench::runCase("(b) generated surface, 30000 sites, " + label, domain,
                                          30000, iterations, alpha, threads, search, setup);
                });
        }
        if ((which == "complexity" || which == "all")
            && bench::runComplexityBench(dataDir, threads) != 0)
            return 1;
        if ((which == "remesh" || which == "all")
            && bench::runRemeshBench(dataDir, threads, iterations, repeat) != 0)
            return 1;
        if ((which == "hybrid" || which == "all")
            && bench::runHybridBench(dataDir, threads, repeat) != 0)
            return 1;
    } catch (const std::exception &e) {
        std::fprintf(stderr, "stratamesh-bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
