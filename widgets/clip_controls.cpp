#include "clip_controls.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QSlider>
#include <QTableWidget>

#include <algorithm>
#include <cmath>

namespace stratamesh {

namespace {
constexpr int kSliderSteps = 100;
} // namespace

ClipControls::ClipControls(const QString &name, QWidget *parent)
    : QWidget(parent), m_clip(new QCheckBox(this)), m_axis(new QComboBox(this)),
      m_position(new QSlider(Qt::Horizontal, this))
{
    m_clip->setObjectName(name + QStringLiteral("Clip"));
    m_axis->setObjectName(name + QStringLiteral("ClipAxis"));
    m_axis->addItems({QString(), QString(), QString()});
    m_axis->setCurrentIndex(int(ClipAxis::Y));
    m_position->setObjectName(name + QStringLiteral("ClipPosition"));
    m_position->setRange(0, kSliderSteps);
    m_position->setValue(kSliderSteps / 2);
    m_axis->setEnabled(false);
    m_position->setEnabled(false);

    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_clip);
    layout->addWidget(m_axis);
    layout->addWidget(m_position, 1);

    connect(m_clip, &QCheckBox::toggled, this, [this](bool on) {
        m_axis->setEnabled(on);
        m_position->setEnabled(on);
        emitClip();
    });
    connect(m_axis, &QComboBox::currentIndexChanged, this, &ClipControls::emitClip);
    connect(m_position, &QSlider::valueChanged, this, &ClipControls::emitClip);
    retranslate();
}

bool ClipControls::isClipping() const
{
    return m_clip->isChecked();
}

ClipAxis ClipControls::axis() const
{
    return ClipAxis(m_axis->currentIndex());
}

double ClipControls::fraction() const
{
    return double(m_position->value()) / kSliderSteps;
}

void ClipControls::setClip(bool enabled, ClipAxis axis, double fraction)
{
    // One signal for the three settings, not one per widget.
    {
        const QSignalBlocker a(m_clip), b(m_axis), c(m_position);
        m_clip->setChecked(enabled);
        m_axis->setCurrentIndex(int(axis));
        m_position->setValue(int(std::lround(std::clamp(fraction, 0.0, 1.0) * kSliderSteps)));
        m_axis->setEnabled(enabled);
        m_position->setEnabled(enabled);
    }
    emitClip();
}

void ClipControls::emitClip()
{
    emit clipChanged(isClipping(), axis(), fraction());
}

void ClipControls::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void ClipControls::retranslate()
{
    m_clip->setText(tr("C&lip plane"));
    m_clip->setToolTip(tr("Show only the cells on one side of a plane, to see inside the mesh"));
    m_axis->setItemText(int(ClipAxis::X), tr("North–south section (x)"));
    m_axis->setItemText(int(ClipAxis::Y), tr("East–west section (y)"));
    m_axis->setItemText(int(ClipAxis::Z), tr("Horizontal section (z)"));
    m_position->setToolTip(tr("Position of the plane across the mesh"));
}

void setUpStatisticsTable(QTableWidget *table, int minimumSection)
{
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setSelectionMode(QAbstractItemView::NoSelection);
    table->setAlternatingRowColors(true);
    table->verticalHeader()->setDefaultSectionSize(table->fontMetrics().height() + 6);
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table->horizontalHeader()->setMinimumSectionSize(minimumSection);
    table->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    for (int r = 0; r < table->rowCount(); ++r)
        for (int c = 0; c < table->columnCount(); ++c) {
            auto *item = new QTableWidgetItem;
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            table->setItem(r, c, item);
        }
}

} // namespace stratamesh
