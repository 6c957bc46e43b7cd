#include "quality/histogram.h"

#include "common/error.h"

#include <algorithm>
#include <cmath>

namespace stratamesh {

Histogram::Histogram(std::vector<double> edges) : m_edges(std::move(edges))
{
    if (m_edges.size() < 2)
        throw InputError("histogram: at least two bin edges are needed");
    for (std::size_t i = 0; i < m_edges.size(); ++i) {
        if (!std::isfinite(m_edges[i]))
            throw InputError("histogram: bin edge " + std::to_string(i) + " is not finite");
        if (i > 0 && !(m_edges[i] > m_edges[i - 1]))
            throw InputError("histogram: bin edges must increase strictly (edge "
                             + std::to_string(i) + ")");
    }
    m_counts.assign(m_edges.size() - 1, 0);
}

Histogram Histogram::uniform(double low, double high, int binCount)
{
    if (binCount < 1)
        throw InputError("histogram: at least one bin is needed");
    std::vector<double> edges(static_cast<std::size_t>(binCount) + 1);
    for (int i = 0; i <= binCount; ++i)
        edges[static_cast<std::size_t>(i)] = low + (high - low) * i / binCount;
    edges.back() = high; // exact, whatever the rounding of the division
    return Histogram(std::move(edges));
}

void Histogram::add(double value)
{
    ++m_total;
    const int bin = binOf(value);
    if (bin == -1)
        ++m_below;
    else if (bin == -2)
        ++m_above;
    else
        ++m_counts[static_cast<std::size_t>(bin)];
}

int Histogram::binOf(double value) const
{
    if (!(value >= m_edges.front()))
        return -1;
    if (value > m_edges.back())
        return -2;
    // First edge strictly greater than value: its predecessor starts the bin.
    auto it = std::upper_bound(m_edges.begin(), m_edges.end(), value);
    std::size_t bin = static_cast<std::size_t>(it - m_edges.begin());
    bin = bin == 0 ? 0 : bin - 1;
    bin = std::min(bin, m_counts.size() - 1); // value == last edge
    return static_cast<int>(bin);
}

double Histogram::fraction(std::size_t bin) const
{
    return m_total == 0 ? 0.0
                        : static_cast<double>(m_counts.at(bin)) / static_cast<double>(m_total);
}

} // namespace stratamesh
