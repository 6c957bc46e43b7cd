// Input and output of a remeshing counted in the same bins, as paired bars in % of the triangles
// (thesis §4.5 compares the distributions of min angle and quality Q). The histograms come from
// core/quality; this only draws them.
#pragma once

#include "quality/histogram.h"

#include <QChartView>

#include <optional>

class QBarSet;

namespace stratamesh {

class HistogramChart : public QChartView {
    Q_OBJECT
public:
    explicit HistogramChart(QWidget *parent = nullptr);

    // `decimals`: of the bin edge labels. Both histograms must have the same edges; otherwise,
    // or without input, the chart is cleared. Without output, the input is drawn alone.
    void setHistograms(const QString &title, const std::optional<Histogram> &input,
                       const std::optional<Histogram> &output, int decimals);
    // Names of the two bar sets in the legend for the next setHistograms(); empty: "Input" and
    // "Output".
    void setSeriesNames(const QString &input, const QString &output);

    int binCount() const { return m_binCount; }
    // Height of a bar in %, for tests; -1 out of range.
    double inputPercent(int bin) const;
    double outputPercent(int bin) const;
    // What hovering a bar shows: the bin's range and both counts, so that the worst bins,
    // too thin to see as bars, can still be read.
    QString barToolTip(int bin) const;
    // The histograms drawn (for the bins of a bar clicked).
    const std::optional<Histogram> &inputHistogram() const { return m_inputHistogram; }
    const std::optional<Histogram> &outputHistogram() const { return m_outputHistogram; }

signals:
    // A bar was clicked: `output` for the output's bar set. Selects the bin's elements.
    void barClicked(int bin, bool output);

private:
    QBarSet *m_input = nullptr;
    QBarSet *m_output = nullptr;
    std::optional<Histogram> m_inputHistogram;
    std::optional<Histogram> m_outputHistogram;
    int m_decimals = 0;
    int m_binCount = 0;
    QString m_inputName;
    QString m_outputName;
};

} // namespace stratamesh
