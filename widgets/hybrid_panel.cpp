#include "hybrid_panel.h"

#include "clip_controls.h"

#include <QComboBox>
#include <QEvent>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace stratamesh {

namespace {

constexpr int kTypeCount = 3;

// Combo box order: the type first, as it is what a hybrid mesh is about.
constexpr TetColouring kColourings[] = {TetColouring::Type, TetColouring::MinDihedral,
                                        TetColouring::Region};

} // namespace

HybridPanel::HybridPanel(QWidget *parent)
    : QWidget(parent), m_colourLabel(new QLabel(this)), m_colouring(new QComboBox(this)),
      m_clip(new ClipControls(QStringLiteral("Hybrid"), this)),
      m_table(new QTableWidget(RowCount, kTypeCount, this)), m_summary(new QLabel(this))
{
    m_colouring->setObjectName(QStringLiteral("HybridColouring"));
    m_colouring->addItems({QString(), QString(), QString()});
    m_colourLabel->setBuddy(m_colouring);
    setUpStatisticsTable(m_table, 60);
    m_table->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_summary->setObjectName(QStringLiteral("HybridSummary"));
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *controls = new QGridLayout;
    controls->addWidget(m_colourLabel, 0, 0);
    controls->addWidget(m_colouring, 0, 1, 1, 2);
    controls->addWidget(m_clip, 1, 0, 1, 3);
    controls->setColumnStretch(2, 1);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(controls);
    layout->addWidget(m_table);
    layout->addWidget(m_summary);
    layout->addStretch(1);

    connect(m_colouring, &QComboBox::currentIndexChanged, this,
            [this] { emit colouringChanged(colouring()); });
    connect(m_clip, &ClipControls::clipChanged, this, &HybridPanel::clipChanged);
    retranslate();
}

void HybridPanel::setStatistics(const HybridStatistics *statistics)
{
    m_statistics = statistics ? std::optional<HybridStatistics>(*statistics) : std::nullopt;
    fill();
}

QString HybridPanel::cellText(Row row, CellType type) const
{
    return m_table->item(row, int(type))->text();
}

QString HybridPanel::summaryText() const
{
    return m_summary->text();
}

TetColouring HybridPanel::colouring() const
{
    return kColourings[std::clamp(m_colouring->currentIndex(), 0, 2)];
}

void HybridPanel::setColouring(TetColouring colouring)
{
    for (int i = 0; i < 3; ++i)
        if (kColourings[i] == colouring)
            m_colouring->setCurrentIndex(i);
}

bool HybridPanel::clipEnabled() const
{
    return m_clip->isClipping();
}

ClipAxis HybridPanel::clipAxis() const
{
    return m_clip->axis();
}

double HybridPanel::clipFraction() const
{
    return m_clip->fraction();
}

void HybridPanel::setClip(bool enabled, ClipAxis axis, double fraction)
{
    m_clip->setClip(enabled, axis, fraction);
}

QSize HybridPanel::sizeHint() const
{
    const int figures = m_table->fontMetrics().horizontalAdvance(QStringLiteral("Tetrahedra")) + 24;
    const int width = m_table->verticalHeader()->sizeHint().width() + kTypeCount * figures
                      + 2 * m_table->frameWidth() + 2 * layout()->contentsMargins().left();
    return {std::max(width, QWidget::sizeHint().width()), QWidget::sizeHint().height()};
}

void HybridPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void HybridPanel::retranslate()
{
    m_colourLabel->setText(tr("C&olour cells by:"));
    m_colouring->setItemText(0, tr("Cell type"));
    m_colouring->setItemText(1, tr("Min dihedral angle"));
    m_colouring->setItemText(2, tr("Region"));
    m_table->setHorizontalHeaderLabels({tr("Tetrahedra"), tr("Pyramids"), tr("Prisms")});
    m_table->setVerticalHeaderLabels({tr("Cells"), tr("Min dihedral (°)"),
                                      tr("Mean min dihedral (°)"), tr("Max dihedral (°)"),
                                      tr("Slivers")});
    m_table->verticalHeaderItem(MeanMinDihedralRow)
        ->setToolTip(tr("Mean over the cells of each cell's smallest dihedral angle"));
    m_table->verticalHeaderItem(SliversRow)
        ->setToolTip(tr("Tetrahedra with a dihedral angle below 5° or above 175°"));
    fill();
}

void HybridPanel::fill()
{
    const QLocale locale;
    m_table->setFixedHeight(m_table->horizontalHeader()->sizeHint().height()
                            + m_table->verticalHeader()->length() + 2 * m_table->frameWidth() + 2);
    const QString none = QStringLiteral("—");
    for (int t = 0; t < kTypeCount; ++t) {
        const auto set = [&](Row row, const QString &text) {
            m_table->item(row, t)->setText(text);
        };
        if (!m_statistics) {
            for (int r = 0; r < RowCount; ++r)
                set(Row(r), QString());
            continue;
        }
        const TypeQuality &q = m_statistics->byType[std::size_t(t)];
        const bool any = q.cells > 0;
        set(CellsRow, locale.toString(qulonglong(q.cells)));
        set(MinDihedralRow, any ? locale.toString(q.minDihedral, 'f', 2) : none);
        set(MeanMinDihedralRow, any ? locale.toString(q.meanMinDihedral, 'f', 2) : none);
        set(MaxDihedralRow, any ? locale.toString(q.maxDihedral, 'f', 2) : none);
        set(SliversRow,
            CellType(t) == CellType::Tet ? locale.toString(qulonglong(q.slivers)) : none);
    }
    if (!m_statistics) {
        m_summary->clear();
        return;
    }
    const HybridStatistics &s = *m_statistics;
    QStringList lines;
    lines << (s.valid ? tr("Valid mixed mesh") : tr("Not valid: %1").arg(s.message));
    lines << tr("Invalid cells found: %1  ·  repaired: %2")
                 .arg(locale.toString(qulonglong(s.invalidFound)),
                      locale.toString(qulonglong(s.repaired)));
    if (s.fellBackToTetgen)
        lines << tr("No hybrid cell could be kept: this is TetGen's mesh of the remesh");
    else
        lines << tr("Cells between two surfaces: %1  ·  at Voronoi vertices: %2  ·  transition "
                    "pyramids: %3  ·  TetGen's tets: %4")
                     .arg(locale.toString(qulonglong(s.segmentDual)),
                          locale.toString(qulonglong(s.vertexDual)),
                          locale.toString(qulonglong(s.transitionPyramids)),
                          locale.toString(qulonglong(s.fillTets)));
    lines << tr("Time: %1 s").arg(locale.toString(s.seconds, 'f', s.seconds < 10.0 ? 2 : 1));
    m_summary->setText(lines.join(QLatin1Char('\n')));
}

} // namespace stratamesh
