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
      m_minAngle(new HistogramChart(this)), m_quality(new HistogramChart(this))
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
    m_charts->setTabText(0, tr("Min angle (% of triangles)"));
    m_charts->setTabText(1, tr("Quality Q (% of triangles)"));
    m_caption->setText(tr("As thesis Table 4.2: entities counted without the box; Q is 1 for an "
                          "equilateral triangle."));
    fill();
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
    m_charts->setVisible(m_comparison.has_value());
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
