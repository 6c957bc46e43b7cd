// A histogram over fixed bin edges, so that the input and the output of a remeshing are counted in
// the same bins and compare bin by bin (thesis §4.5 compares min angle and quality Q).
#pragma once

#include <cstddef>
#include <vector>

namespace stratamesh {

class Histogram {
public:
    // Bins are [e0, e1), [e1, e2), ..., [e(n-1), en]: the last one is closed so that Q = 1 and
    // a 60° min angle are counted. Throws InputError unless there are >= 2 strictly increasing
    // finite edges.
    explicit Histogram(std::vector<double> edges);
    static Histogram uniform(double low, double high, int binCount);

    void add(double value);
    // The bin add() counts `value` in; -1 below the first edge (or NaN), -2 above the last. For
    // selecting the elements of one bar with exactly the bar's bins.
    int binOf(double value) const;

    const std::vector<double> &edges() const { return m_edges; }
    const std::vector<std::size_t> &counts() const { return m_counts; }
    std::size_t binCount() const { return m_counts.size(); }
    // Values outside [e0, en] (and NaN, counted as below) are kept apart, never clamped into a bin.
    std::size_t below() const { return m_below; }
    std::size_t above() const { return m_above; }
    std::size_t total() const { return m_total; }
    // Fraction of all added values in bin i (0 when nothing was added).
    double fraction(std::size_t bin) const;

private:
    std::vector<double> m_edges;
    std::vector<std::size_t> m_counts;
    std::size_t m_below = 0;
    std::size_t m_above = 0;
    std::size_t m_total = 0;
};

} // namespace stratamesh
