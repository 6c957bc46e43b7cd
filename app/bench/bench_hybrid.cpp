#include "bench_hybrid.h"

#include "bench_cases.h"

#include "hybrid/hybrid_mesher.h"
#include "io/model_reader.h"
#include "model/topology.h"

#include <tbb/global_control.h>
#include <tbb/info.h>

#include <cstdio>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace stratamesh::bench {

namespace {

void printStages(const HybridTimings &t)
{
    const double total = t.totalSeconds > 0.0 ? t.totalSeconds : 1.0;
    const std::pair<const char *, double> stages[] = {{"box CVT", t.cvtSeconds},
                                                      {"surface remesh", t.remeshSeconds},
                                                      {"thesis cells", t.cellsSeconds},
                                                      {"TetGen fill", t.fillSeconds},
                                                      {"mixed-mesh check", t.checkSeconds}};
    double listed = 0.0;
    for (const auto &[name, seconds] : stages) {
        std::printf("    %-18s %7.2f s  %5.1f %%\n", name, seconds, 100.0 * seconds / total);
        listed += seconds;
    }
    std::printf("    %-18s %7.2f s  %5.1f %%\n", "other", t.totalSeconds - listed,
                100.0 * (t.totalSeconds - listed) / total);
}

} // namespace

int runHybridBench(const std::string &dataDir, int threads, int repeat)
{
    try {
        std::unique_ptr<tbb::global_control> limit;
        if (threads > 0)
            limit = std::make_unique<tbb::global_control>(
                tbb::global_control::max_allowed_parallelism, threads);
        const Model input = recoverTopology(readModel(dataDir + "/modelA1.ml"));
        HybridParams params;
        params.sites = 5000;
        std::printf("hybrid: modelA1, %d sites, %d threads (target < 20 s)\n", params.sites,
                    threads > 0 ? threads : tbb::info::default_concurrency());
        std::vector<double> totals;
        std::size_t firstCells = 0;
        for (int r = 0; r < repeat; ++r) {
            const HybridResult result = buildHybridMesh(input, params);
            const VolumeMesh &m = result.mesh;
            if (r == 0) {
                firstCells = m.cells.size();
                std::printf("  %zu cells: %zu tets, %zu prisms, %zu pyramids; %s; %zu segment-dual "
                            "and %zu vertex-dual cells kept, %zu invalid found, %zu repaired\n",
                            m.cells.size(), m.countCells(CellType::Tet),
                            m.countCells(CellType::Prism), m.countCells(CellType::Pyramid),
                            result.validity.valid() ? "valid" : "NOT valid", result.segmentDualKept,
                            result.vertexDualKept, result.invalidFound, result.repaired);
            } else if (m.cells.size() != firstCells) {
                throw std::runtime_error("run " + std::to_string(r + 1)
                                         + " gave another mesh than the first");
            }
            std::printf("  run %d: %.2f s\n", r + 1, result.timings.totalSeconds);
            printStages(result.timings);
            totals.push_back(result.timings.totalSeconds);
        }
        printSpread("hybrid", totals);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "stratamesh-bench: hybrid: %s\n", e.what());
        return 1;
    }
    return 0;
}

} // namespace stratamesh::bench
