#include "complexity/count_statistics.h"

#include <algorithm>
#include <cmath>

namespace stratamesh {

namespace {
int nearestRank(const std::vector<int> &sorted, int percent)
{
    const std::size_t n = sorted.size();
    // ceil(p n / 100) in integers, so 10 % of 100 values is exactly the 10th.
    std::size_t rank = (static_cast<std::size_t>(percent) * n + 99) / 100;
    rank = std::max<std::size_t>(rank, 1);
    return sorted[rank - 1];
}
} // namespace

CountStatistics countStatistics(std::vector<int> values)
{
    CountStatistics s;
    s.cells = static_cast<int>(values.size());
    if (values.empty())
        return s;
    std::sort(values.begin(), values.end());
    s.q10 = nearestRank(values, 10);
    s.q50 = nearestRank(values, 50);
    s.q90 = nearestRank(values, 90);
    s.max = values.back();
    s.varCoeff = variationCoefficient(std::vector<double>(values.begin(), values.end()));
    double sum = 0.0;
    for (int v : values)
        sum += v;
    s.mean = sum / values.size();
    return s;
}

double variationCoefficient(const std::vector<double> &values)
{
    const std::size_t n = values.size();
    if (n < 2)
        return 0.0;
    double mean = 0.0;
    for (double v : values)
        mean += v;
    mean /= n;
    if (mean == 0.0)
        return 0.0;
    double squares = 0.0;
    for (double v : values)
        squares += (v - mean) * (v - mean);
    return std::sqrt(squares / (n - 1)) / std::abs(mean);
}

} // namespace stratamesh
