#include "histogram_chart.h"

#include <QBarCategoryAxis>
#include <QBarSeries>
#include <QBarSet>
#include <QChart>
#include <QLocale>
#include <QToolTip>
#include <QValueAxis>

#include <algorithm>

namespace stratamesh {

HistogramChart::HistogramChart(QWidget *parent) : QChartView(new QChart, parent)
{
    setRenderHint(QPainter::Antialiasing);
    chart()->legend()->setAlignment(Qt::AlignTop);
    chart()->setMargins(QMargins(2, 2, 2, 2));
    chart()->setBackgroundRoundness(0);
    // Room for the rotated bin labels: a shorter chart cuts them to an ellipsis.
    setMinimumHeight(220);
}

void HistogramChart::setHistograms(const QString &title, const std::optional<Histogram> &input,
                                   const std::optional<Histogram> &output, int decimals)
{
    QChart *c = chart();
    c->removeAllSeries();
    for (QAbstractAxis *axis : c->axes()) {
        c->removeAxis(axis);
        delete axis;
    }
    m_input = m_output = nullptr;
    m_binCount = 0;
    c->setTitle(title);
    c->setTitleFont([&] {
        QFont f = c->titleFont();
        f.setPointSizeF(f.pointSizeF() * 0.9);
        return f;
    }());
    m_inputHistogram.reset();
    m_outputHistogram.reset();
    if (!input || (output && input->edges() != output->edges()))
        return;
    m_inputHistogram = input;
    m_outputHistogram = output;
    m_decimals = decimals;
    m_binCount = int(input->binCount());
    m_input = new QBarSet(m_inputName.isEmpty() ? tr("Input") : m_inputName);
    m_input->setColor(QColor(150, 150, 160));
    if (output) {
        m_output = new QBarSet(m_outputName.isEmpty() ? tr("Output") : m_outputName);
        m_output->setColor(QColor(70, 130, 200));
    }
    QStringList labels;
    const QLocale locale;
    double top = 0.0;
    for (std::size_t i = 0; i < input->binCount(); ++i) {
        const double a = 100.0 * input->fraction(i), b = output ? 100.0 * output->fraction(i) : 0.0;
        *m_input << a;
        if (m_output)
            *m_output << b;
        top = std::max({top, a, b});
        labels << locale.toString(input->edges()[i], 'f', decimals);
    }
    auto *series = new QBarSeries;
    series->append(m_input);
    if (m_output)
        series->append(m_output);
    series->setBarWidth(0.9);
    connect(series, &QBarSeries::hovered, this, [this](bool status, int bin, QBarSet *) {
        if (status)
            QToolTip::showText(QCursor::pos(), barToolTip(bin), this);
        else
            QToolTip::hideText();
    });
    connect(m_input, &QBarSet::clicked, this, [this](int bin) { emit barClicked(bin, false); });
    if (m_output)
        connect(m_output, &QBarSet::clicked, this, [this](int bin) { emit barClicked(bin, true); });
    c->addSeries(series);
    auto *x = new QBarCategoryAxis;
    x->append(labels);
    x->setLabelsAngle(-90);
    // Qt Charts elides rotated labels of many narrow bins (18 and more) to "…" even when they fit.
    x->setTruncateLabels(false);
    QFont small = x->labelsFont();
    small.setPointSizeF(small.pointSizeF() * 0.8);
    x->setLabelsFont(small);
    auto *y = new QValueAxis;
    y->setRange(0.0, top > 0.0 ? top * 1.05 : 1.0);
    y->setLabelFormat(QStringLiteral("%.0f"));
    y->setLabelsFont(small);
    c->addAxis(x, Qt::AlignBottom);
    c->addAxis(y, Qt::AlignLeft);
    series->attachAxis(x);
    series->attachAxis(y);
}

void HistogramChart::setSeriesNames(const QString &input, const QString &output)
{
    m_inputName = input;
    m_outputName = output;
}

QString HistogramChart::barToolTip(int bin) const
{
    if (!m_inputHistogram || bin < 0 || bin >= m_binCount)
        return {};
    const QLocale locale;
    const auto &edges = m_inputHistogram->edges();
    const std::size_t b = std::size_t(bin);
    const auto line = [&](const QString &name, const Histogram &h) {
        return tr("%1: %Ln triangle(s), %2 %", nullptr, int(h.counts()[b]))
            .arg(name, locale.toString(100.0 * h.fraction(b), 'f', 2));
    };
    QString tip = tr("[%1, %2)")
                      .arg(locale.toString(edges[b], 'f', m_decimals),
                           locale.toString(edges[b + 1], 'f', m_decimals));
    tip += QLatin1Char('\n')
           + line(m_inputName.isEmpty() ? tr("Input") : m_inputName, *m_inputHistogram);
    if (m_outputHistogram)
        tip += QLatin1Char('\n')
               + line(m_outputName.isEmpty() ? tr("Output") : m_outputName, *m_outputHistogram);
    return tip;
}

double HistogramChart::inputPercent(int bin) const
{
    return m_input && bin >= 0 && bin < m_binCount ? m_input->at(bin) : -1.0;
}

double HistogramChart::outputPercent(int bin) const
{
    return m_output && bin >= 0 && bin < m_binCount ? m_output->at(bin) : -1.0;
}

} // namespace stratamesh
