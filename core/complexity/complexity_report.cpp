#include "complexity/complexity_report.h"

#include "params/param_tables.h"

#include <algorithm>
#include <chrono>

namespace stratamesh {

ComplexityReport computeComplexity(const Model &model, const ComplexityParams &params,
                                   Progress &progress)
{
    checkParams(complexityParamTable(), params);
    ComplexityReport report;
    auto start = std::chrono::steady_clock::now();
    auto lap = [&](const std::string &stage) {
        const auto now = std::chrono::steady_clock::now();
        report.timings.emplace_back(stage, std::chrono::duration<double>(now - start).count());
        start = now;
    };
    report.counts = countEntities(model).withoutBox;
    lap("counts");
    report.variation = sizeVariation(model);
    lap("variation");
    // Global measures 0–10 %, then each number of cells an equal share of the rest.
    {
        Progress geometric(progress, 0.0, 0.1);
        report.geometric = geometricComplexity(model, params.geometric, geometric);
    }
    lap("geometric");
    const double share = 0.9 / std::max<std::size_t>(params.cells.size(), 1);
    double at = 0.1;
    for (int n : params.cells) {
        Progress cells(progress, at, at + share);
        at += share;
        LocalComplexityParams local;
        local.cells = n;
        local.seed = params.seed;
        local.iterations = params.iterations;
        report.local.push_back(localComplexity(model, local, cells));
        report.timings.emplace_back("local_" + std::to_string(n) + "_cvt",
                                    report.local.back().cvtSeconds);
        report.timings.emplace_back("local_" + std::to_string(n) + "_count",
                                    report.local.back().countSeconds);
        start = std::chrono::steady_clock::now();
    }
    return report;
}

} // namespace stratamesh
