#include "comparison_table.h"

#include "histogram_chart.h"

#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

namespace stratamesh {

ComparisonTable::ComparisonTable(QWidget *parent)
    : QWidget(parent), m_table(new QTableWidget(RowCount, ColumnCount, this)),
      m_caption(new QLabel(this)), m_charts(new QTabWidget(this)),
      m_minAngle(new HistogramChart(this)), m_quality(new HistogramChart(this)),
      m_minDihedral(new HistogramChart(this)), m_radiusRatio(new HistogramChart(this))
{
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->setAlternatingRowColors(true);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->horizontalHeader()->setMinimumSectionSize(70);
    m_caption->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_table);
    layout->addWidget(m_caption);
    m_charts->addTab(m_minAngle, QString());
    m_charts->addTab(m_quality, QString());
    // Tabs only while there are tets (setTetQuality).
    m_minDihedral->hide();
    m_radiusRatio->hide();
    layout->addWidget(m_charts, 1);
    for (int r = 0; r < RowCount; ++r)
        for (int c = 0; c < ColumnCount; ++c) {
            auto *item = new QTableWidgetItem;
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(r, c, item);
        }
    retranslate();
}

void ComparisonTable::setComparison(std::optional<ModelComparison> comparison)
{
    m_comparison = std::move(comparison);
    fill();
}

QSize ComparisonTable::sizeHint() const
{
    const int figures =
        m_table->fontMetrics().horizontalAdvance(QStringLiteral("000 000 000")) + 12;
    const int width = m_table->verticalHeader()->sizeHint().width() + ColumnCount * figures
                      + 2 * m_table->frameWidth() + 2 * layout()->contentsMargins().left();
    return {width, QWidget::sizeHint().height()};
}

QString ComparisonTable::cellText(Row row, Column column) const
{
    return m_table->item(row, column)->text();
}

QString ComparisonTable::columnName(Column column) const
{
    return m_table->horizontalHeaderItem(column)->text();
}

void ComparisonTable::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void ComparisonTable::retranslate()
{
    m_table->setHorizontalHeaderLabels({m_firstName.isEmpty() ? tr("Input") : m_firstName,
                                        m_secondName.isEmpty() ? tr("Output") : m_secondName});
    m_table->setVerticalHeaderLabels(
        {tr("Vertices"), tr("Triangles"), tr("Surfaces"), tr("Lines"), tr("Corners"),
         tr("Min angle (°)"), tr("Angle < 30° (% triangles)"), tr("Mean quality Q"),
         tr("Hausdorff (% bbox diagonal)"), tr("Sampling time (s)"), tr("Mesh building time (s)")});
    // Short tab names, so that the four fit a narrow dock; what the bars count is in the tooltip.
    const auto name = [this](QWidget *chart, const QString &tab, const QString &tip) {
        const int index = m_charts->indexOf(chart);
        if (index < 0)
            return;
        m_charts->setTabText(index, tab);
        m_charts->setTabToolTip(index, tip);
    };
    name(m_minAngle, tr("Min angle"), tr("Smallest angle of each triangle, in % of the triangles"));
    name(m_quality, tr("Q"),
         tr("Quality Q of each triangle (1: equilateral), in % of the triangles"));
    name(m_minDihedral, tr("Min dihedral"),
         tr("Smallest dihedral angle of each tetrahedron, in % of the tets"));
    name(m_radiusRatio, tr("Radius ratio"),
         tr("Radius ratio 3r/R of each tetrahedron (1: regular, 0: flat), in % of the tets"));
    // TetGen meshed the input and the remesh, whichever runs the views compare.
    m_minDihedral->setSeriesNames(tr("Input"), tr("Remesh"));
    m_radiusRatio->setSeriesNames(tr("Input"), tr("Remesh"));
    m_caption->setText(tr("As thesis Table 4.2: entities counted without the box; Q is 1 for an "
                          "equilateral triangle."));
    fill();
}

void ComparisonTable::setTetQuality(const VolumeQualityStatistics *input,
                                    const VolumeQualityStatistics *remesh)
{
    m_tetInput = input ? std::optional(*input) : std::nullopt;
    m_tetRemesh = input && remesh ? std::optional(*remesh) : std::nullopt;
    for (HistogramChart *chart : {m_minDihedral, m_radiusRatio}) {
        const int tab = m_charts->indexOf(chart);
        if (input && tab < 0)
            m_charts->addTab(chart, QString());
        else if (!input && tab >= 0)
            m_charts->removeTab(tab);
        chart->setVisible(input != nullptr);
    }
    retranslate();
}

void ComparisonTable::showTetQuality()
{
    if (hasTetQuality())
        m_charts->setCurrentWidget(m_minDihedral);
}

void ComparisonTable::setColumnNames(const QString &first, const QString &second)
{
    m_firstName = first;
    m_secondName = second;
    m_minAngle->setSeriesNames(first, second);
    m_quality->setSeriesNames(first, second);
    retranslate();
}

void ComparisonTable::fill()
{
    const QLocale locale;
    const auto set = [this](int row, int column, const QString &text) {
        m_table->item(row, column)->setText(text);
    };
    // The table shows all its rows and takes no more room: the charts get the rest.
    m_table->setFixedHeight(m_table->horizontalHeader()->sizeHint().height()
                            + m_table->verticalHeader()->length() + 2 * m_table->frameWidth() + 2);
    if (m_comparison) {
        m_minAngle->setHistograms(QString(), m_comparison->inputMinAngle,
                                  m_comparison->outputMinAngle, 0);
        m_quality->setHistograms(QString(), m_comparison->inputQuality, m_comparison->outputQuality,
                                 2);
    } else {
        m_minAngle->setHistograms(QString(), std::nullopt, std::nullopt, 0);
        m_quality->setHistograms(QString(), std::nullopt, std::nullopt, 0);
    }
    // Shown once filled: the axes lay their labels out when the chart appears.
    if (m_tetInput) {
        std::optional<Histogram> remeshMin, remeshRatio;
        if (m_tetRemesh) {
            remeshMin = m_tetRemesh->minDihedral;
            remeshRatio = m_tetRemesh->inverseRadiusRatio;
        }
        m_minDihedral->setHistograms(QString(), m_tetInput->minDihedral, remeshMin, 0);
        m_radiusRatio->setHistograms(QString(), m_tetInput->inverseRadiusRatio, remeshRatio, 2);
    } // else setTetQuality took their tabs away
    m_charts->setVisible(m_comparison.has_value() || hasTetQuality());
    m_table->setVisible(m_comparison.has_value());
    m_caption->setVisible(m_comparison.has_value());
    if (!m_comparison) {
        for (int r = 0; r < RowCount; ++r)
            for (int c = 0; c < ColumnCount; ++c)
                set(r, c, QString());
        return;
    }
    const ComparisonRow *rows[ColumnCount] = {&m_comparison->input, &m_comparison->output};
    for (int c = 0; c < ColumnCount; ++c) {
        const ComparisonRow &row = *rows[c];
        set(VerticesRow, c, locale.toString(qulonglong(row.mesh.vertices)));
        set(TrianglesRow, c, locale.toString(qulonglong(row.mesh.triangles)));
        set(SurfacesRow, c, locale.toString(row.counts.surfaces));
        set(LinesRow, c, locale.toString(row.counts.lines));
        set(CornersRow, c, locale.toString(row.counts.corners));
        set(MinAngleRow, c, locale.toString(row.mesh.minAngleDeg, 'f', 2));
        set(Below30Row, c, locale.toString(row.mesh.pctTrianglesAngleBelow30, 'f', 1));
        set(MeanQualityRow, c, locale.toString(row.mesh.meanQuality, 'f', 3));
        set(HausdorffRow, c,
            row.hausdorffPctBbox < 0.0 ? QStringLiteral("—")
                                       : locale.toString(row.hausdorffPctBbox, 'f', 3));
        const bool input = row.hausdorffPctBbox < 0.0; // the input model: it was not remeshed
        set(SamplingTimeRow, c,
            input ? QStringLiteral("—") : locale.toString(row.samplingSeconds, 'f', 2));
        set(MeshTimeRow, c, input ? QStringLiteral("—") : locale.toString(row.meshSeconds, 'f', 2));
    }
}

} // namespace stratamesh
