// Statistics of the numbers of elements per cell (thesis Table 3.4): quantiles, maximum, mean and
// variation coefficient.
#pragma once

#include <vector>

namespace stratamesh {

struct CountStatistics {
    int cells = 0;
    int q10 = 0;
    int q50 = 0;
    int q90 = 0;
    int max = 0;
    double mean = 0.0;
    double varCoeff = 0.0; // sample standard deviation / mean (0 when the mean is 0)
};

// Quantiles by nearest rank: Qp = the ceil(p·n)-th smallest value, so every quantile is one of
// the counts (the thesis prints integers). Empty input gives all zeros.
CountStatistics countStatistics(std::vector<int> values);

// Sample standard deviation (n − 1) over the mean; 0 for fewer than two values or a zero mean.
// Thesis §3.3.1 (its footnote says "mean over standard deviation"; its Table 3.3 is std/mean).
double variationCoefficient(const std::vector<double> &values);

} // namespace stratamesh
