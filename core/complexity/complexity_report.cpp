#include "complexity/complexity_report.h"

#include "params/param_tables.h"

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
    report.geometric = geometricComplexity(model, params.geometric, progress);
    lap("geometric");
    for (int n : params.cells) {
        LocalComplexityParams local;
        local.cells = n;
        local.seed = params.seed;
        local.iterations = params.iterations;
        report.local.push_back(localComplexity(model, local, progress));
        report.timings.emplace_back("local_" + std::to_string(n) + "_cvt",
                                    report.local.back().cvtSeconds);
        report.timings.emplace_back("local_" + std::to_string(n) + "_count",
                                    report.local.back().countSeconds);
        start = std::chrono::steady_clock::now();
    }
    return report;
}

} // namespace stratamesh
