#include "colour_map.h"

#include <vtkLookupTable.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace stratamesh {

namespace {

// Viridis sampled at 0, 1/8, …, 1 (matplotlib's _viridis_data); linear in between is within a
// few 1/255 of the full table.
constexpr std::array<std::array<double, 3>, 9> kViridis{{{0.267004, 0.004874, 0.329415},
                                                         {0.282623, 0.140926, 0.457517},
                                                         {0.253935, 0.265254, 0.529983},
                                                         {0.206756, 0.371758, 0.553117},
                                                         {0.163625, 0.471133, 0.558148},
                                                         {0.127568, 0.566949, 0.550556},
                                                         {0.134692, 0.658636, 0.517649},
                                                         {0.266941, 0.748751, 0.440573},
                                                         {0.993248, 0.906157, 0.143936}}};

std::array<double, 3> viridis(double t)
{
    t = std::clamp(t, 0.0, 1.0) * double(kViridis.size() - 1);
    const std::size_t i = std::min(std::size_t(t), kViridis.size() - 2);
    const double f = t - double(i);
    std::array<double, 3> c{};
    for (std::size_t k = 0; k < 3; ++k)
        c[k] = (1.0 - f) * kViridis[i][k] + f * kViridis[i + 1][k];
    return c;
}

} // namespace

vtkSmartPointer<vtkLookupTable> measureLookupTable(double low, double high, bool lowIsBad,
                                                   bool reverse)
{
    constexpr int n = 256;
    auto table = vtkSmartPointer<vtkLookupTable>::New();
    table->SetNumberOfTableValues(n);
    table->SetTableRange(low, high > low ? high : low + 1.0);
    // Viridis runs from dark (cool) to yellow (warm): the bad end takes yellow.
    const bool warmAtLow = lowIsBad != reverse;
    for (int i = 0; i < n; ++i) {
        const double t = double(i) / double(n - 1);
        const auto c = viridis(warmAtLow ? 1.0 - t : t);
        table->SetTableValue(i, c[0], c[1], c[2], 1.0);
    }
    table->SetNanColor(0.6, 0.6, 0.6, 1.0);
    return table;
}

} // namespace stratamesh
