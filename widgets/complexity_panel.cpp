#include "complexity_panel.h"

#include <QCheckBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace stratamesh {

namespace {

QTableWidget *makeTable(int rows, int columns, QWidget *parent)
{
    auto *table = new QTableWidget(rows, columns, parent);
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setSelectionMode(QAbstractItemView::NoSelection);
    table->setAlternatingRowColors(true);
    table->verticalHeader()->setDefaultSectionSize(table->fontMetrics().height() + 6);
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table->horizontalHeader()->setMinimumSectionSize(56);
    table->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    table->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) {
            auto *item = new QTableWidgetItem;
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            table->setItem(r, c, item);
        }
    return table;
}

// All rows shown, no more room taken.
void fitHeight(QTableWidget *table)
{
    const int header =
        table->horizontalHeader()->isHidden() ? 0 : table->horizontalHeader()->sizeHint().height();
    table->setFixedHeight(header + table->verticalHeader()->length() + 2 * table->frameWidth() + 2);
}

} // namespace

ComplexityPanel::ComplexityPanel(QWidget *parent)
    : QWidget(parent), m_globalCaption(new QLabel(this)),
      m_global(makeTable(GlobalRowCount, GlobalColumnCount, this)),
      m_localCaption(new QLabel(this)), m_local(makeTable(LocalRowCount, 1, this)),
      m_showHeatMap(new QCheckBox(this)), m_thresholdLabel(new QLabel(this)),
      m_threshold(new QSpinBox(this)), m_shown(new QLabel(this))
{
    m_globalCaption->setWordWrap(true);
    m_localCaption->setWordWrap(true);
    m_local->horizontalHeader()->hide();
    m_showHeatMap->setObjectName(QStringLiteral("ShowHeatMap"));
    m_showHeatMap->setChecked(true);
    m_threshold->setObjectName(QStringLiteral("HeatMapThreshold"));
    m_threshold->setRange(0, 1000000);
    m_threshold->setValue(kDefaultThreshold);
    m_thresholdLabel->setBuddy(m_threshold);
    m_shown->setWordWrap(true);

    auto *thresholdRow = new QHBoxLayout;
    thresholdRow->addWidget(m_thresholdLabel);
    thresholdRow->addWidget(m_threshold);
    thresholdRow->addStretch(1);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_globalCaption);
    layout->addWidget(m_global);
    layout->addSpacing(6);
    layout->addWidget(m_localCaption);
    layout->addWidget(m_local);
    layout->addSpacing(6);
    layout->addWidget(m_showHeatMap);
    layout->addLayout(thresholdRow);
    layout->addWidget(m_shown);
    layout->addStretch(1);

    connect(m_threshold, &QSpinBox::valueChanged, this, &ComplexityPanel::thresholdChanged);
    connect(m_showHeatMap, &QCheckBox::toggled, this, [this](bool on) {
        m_threshold->setEnabled(on && m_report);
        emit heatMapVisibleChanged(on);
    });
    retranslate();
}

void ComplexityPanel::setReport(std::optional<ComplexityReport> report,
                                const ComplexityParams &params)
{
    m_report = std::move(report);
    m_params = params;
    fill();
}

QString ComplexityPanel::globalText(GlobalRow row, GlobalColumn column) const
{
    return m_global->item(row, column)->text();
}

QString ComplexityPanel::localText(LocalRow row) const
{
    return m_local->item(row, 0)->text();
}

int ComplexityPanel::threshold() const
{
    return m_threshold->value();
}

void ComplexityPanel::setThreshold(int threshold)
{
    m_threshold->setValue(threshold);
}

bool ComplexityPanel::heatMapVisible() const
{
    return m_showHeatMap->isChecked();
}

void ComplexityPanel::setHeatMapVisible(bool visible)
{
    m_showHeatMap->setChecked(visible);
}

void ComplexityPanel::setShownCells(int shown, int total)
{
    m_shownCells = shown;
    m_totalCells = total;
    m_shown->setText(
        m_report
            ? tr("%1 of %2 cells drawn").arg(QLocale().toString(shown), QLocale().toString(total))
            : QString());
}

QSize ComplexityPanel::sizeHint() const
{
    const int figures = m_global->fontMetrics().horizontalAdvance(QStringLiteral("00000.00")) + 12;
    const int width = m_global->verticalHeader()->sizeHint().width() + GlobalColumnCount * figures
                      + 2 * m_global->frameWidth() + 8;
    return {width, QWidget::sizeHint().height()};
}

void ComplexityPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void ComplexityPanel::retranslate()
{
    m_global->setHorizontalHeaderLabels(
        {tr("Regions"), tr("Surfaces"), tr("Lines"), tr("Corners"), tr("Total")});
    m_global->setVerticalHeaderLabels({tr("Count"), tr("Geometric"), tr("Size var. coeff.")});
    m_global->verticalHeaderItem(CountsRow)->setToolTip(
        tr("Number of elements, box excluded (thesis Table 3.1)"));
    m_global->verticalHeaderItem(GeometricRow)
        ->setToolTip(tr("Sum of C_t + C_f + C_e + C_a over the elements (thesis Table 3.2)"));
    m_global->verticalHeaderItem(VariationRow)
        ->setToolTip(
            tr("Standard deviation / mean of the volumes, areas and lengths (thesis Table 3.3)"));
    m_local->setVerticalHeaderLabels({tr("Cells"), tr("Q10"), tr("Q50 (median)"), tr("Q90"),
                                      tr("Max"), tr("Mean"), tr("Var. coeff.")});
    m_showHeatMap->setText(tr("Show the &heat map of elements per cell"));
    m_thresholdLabel->setText(tr("Draw cells with at &least"));
    m_threshold->setSuffix(tr(" elements"));
    m_threshold->setToolTip(
        tr("Cells meeting fewer model elements are not drawn, so the model stays visible."));
    fill();
}

void ComplexityPanel::fill()
{
    const QLocale locale;
    fitHeight(m_global);
    fitHeight(m_local);
    m_threshold->setEnabled(m_report && m_showHeatMap->isChecked());
    m_showHeatMap->setEnabled(m_report.has_value());
    if (!m_report) {
        for (int r = 0; r < GlobalRowCount; ++r)
            for (int c = 0; c < GlobalColumnCount; ++c)
                m_global->item(r, c)->setText(QString());
        for (int r = 0; r < LocalRowCount; ++r)
            m_local->item(r, 0)->setText(QString());
        m_globalCaption->setText(tr("Global measures (thesis Tables 3.1–3.3): none yet."));
        m_localCaption->setText(tr("Elements per cell (thesis Table 3.4): none yet."));
        m_shown->clear();
        return;
    }
    const ComplexityReport &r = *m_report;
    const auto set = [this](int row, int column, const QString &text) {
        m_global->item(row, column)->setText(text);
    };
    const auto f2 = [&](double v) { return locale.toString(v, 'f', 2); };
    const QString none = QStringLiteral("—");
    const EntityCounts &c = r.counts;
    set(CountsRow, RegionsColumn, locale.toString(c.regions));
    set(CountsRow, SurfacesColumn, locale.toString(c.surfaces));
    set(CountsRow, LinesColumn, locale.toString(c.lines));
    set(CountsRow, CornersColumn, locale.toString(c.corners));
    set(CountsRow, TotalColumn, locale.toString(c.regions + c.surfaces + c.lines + c.corners));
    set(GeometricRow, RegionsColumn, f2(r.geometric.regionsTotal));
    set(GeometricRow, SurfacesColumn, f2(r.geometric.surfacesTotal));
    set(GeometricRow, LinesColumn, f2(r.geometric.linesTotal));
    set(GeometricRow, CornersColumn, none);
    set(GeometricRow, TotalColumn, f2(r.geometric.total()));
    set(VariationRow, RegionsColumn, f2(r.variation.regions));
    set(VariationRow, SurfacesColumn, f2(r.variation.surfaces));
    set(VariationRow, LinesColumn, f2(r.variation.lines));
    set(VariationRow, CornersColumn, none);
    set(VariationRow, TotalColumn, f2(r.variation.total));
    m_globalCaption->setText(
        tr("Global measures, box excluded (thesis Tables 3.1–3.3); geometric with h = %1 m, "
           "α = %2°.")
            .arg(locale.toString(m_params.geometric.h, 'g', 6),
                 locale.toString(m_params.geometric.alphaDegrees, 'g', 4)));
    if (r.local.empty()) {
        for (int row = 0; row < LocalRowCount; ++row)
            m_local->item(row, 0)->setText(QString());
        m_localCaption->setText(tr("Elements per cell (thesis Table 3.4): none."));
        return;
    }
    const LocalComplexity &l = r.local.front();
    const CountStatistics &s = l.statistics;
    const auto setLocal = [this](int row, const QString &text) {
        m_local->item(row, 0)->setText(text);
    };
    setLocal(CellsRow, locale.toString(int(l.counts.size())));
    setLocal(Q10Row, locale.toString(s.q10));
    setLocal(Q50Row, locale.toString(s.q50));
    setLocal(Q90Row, locale.toString(s.q90));
    setLocal(MaxRow, locale.toString(s.max));
    setLocal(MeanRow, locale.toString(s.mean, 'f', 3));
    setLocal(VarCoeffRow, locale.toString(s.varCoeff, 'f', 3));
    m_localCaption->setText(
        tr("Elements per cell (thesis Table 3.4), seed %1, %n Lloyd iteration(s); "
           "%2 cell(s) outside the model left out of the statistics.",
           nullptr, l.cvt.iterations)
            .arg(QString::number(m_params.seed), locale.toString(l.outsideCells)));
    setShownCells(m_shownCells, m_totalCells);
}

} // namespace stratamesh
