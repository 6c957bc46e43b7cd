// All the complexity measures of thesis chapter 3 for one model: counts (Table 3.1), geometric
// complexity (Table 3.2), size variation (Table 3.3) and local statistics for several numbers of
// cells (Table 3.4), with the time each took. Box elements are excluded throughout.
#pragma once

#include "common/progress.h"
#include "complexity/geometric_complexity.h"
#include "complexity/local_complexity.h"
#include "complexity/size_variation.h"
#include "model/model_counts.h"

#include <string>
#include <utility>
#include <vector>

namespace stratamesh {

// The most cells of one volumetric CVT (the `cells` range of complexityParamTable()).
inline constexpr int kMaxComplexityCells = 1000000;

struct ComplexityParams {
    GeometricParams geometric;
    std::vector<int> cells{100, 1000, 10000};
    std::uint64_t seed = 1;
    int iterations = 30;
};

struct ComplexityReport {
    EntityCounts counts; // without the box
    GeometricComplexity geometric;
    SizeVariation variation;
    std::vector<LocalComplexity> local; // one per ComplexityParams::cells, same order
    std::vector<std::pair<std::string, double>> timings; // stage, seconds
};

// Requires topology; throws InputError otherwise or on bad parameters.
ComplexityReport computeComplexity(const Model &model, const ComplexityParams &params,
                                   Progress &progress = Progress::none());

} // namespace stratamesh
