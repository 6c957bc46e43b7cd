#include "tetmesh_panel.h"

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

QString secondsText(double seconds)
{
    return QLocale().toString(seconds, 'f', seconds < 10.0 ? 2 : 0);
}

} // namespace

TetmeshPanel::TetmeshPanel(QWidget *parent)
    : QWidget(parent), m_colourLabel(new QLabel(this)), m_colouring(new QComboBox(this)),
      m_clip(new ClipControls(QStringLiteral("Tet"), this)),
      m_table(new QTableWidget(RowCount, ColumnCount, this)), m_notes(new QLabel(this))
{
    m_colouring->setObjectName(QStringLiteral("TetColouring"));
    m_colouring->addItems({QString(), QString()});
    m_colourLabel->setBuddy(m_colouring);
    setUpStatisticsTable(m_table, 70);
    m_notes->setObjectName(QStringLiteral("TetmeshNotes"));
    m_notes->setWordWrap(true);
    m_notes->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *controls = new QGridLayout;
    controls->addWidget(m_colourLabel, 0, 0);
    controls->addWidget(m_colouring, 0, 1, 1, 2);
    controls->addWidget(m_clip, 1, 0, 1, 3);
    controls->setColumnStretch(2, 1);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(controls);
    layout->addWidget(m_table);
    layout->addWidget(m_notes);
    layout->addStretch(1);

    connect(m_colouring, &QComboBox::currentIndexChanged, this,
            [this] { emit colouringChanged(colouring()); });
    connect(m_clip, &ClipControls::clipChanged, this, &TetmeshPanel::clipChanged);
    retranslate();
}

void TetmeshPanel::setSides(const TetmeshSide *input, const TetmeshSide *output)
{
    const auto summary = [](const TetmeshSide *side) -> std::optional<Side> {
        if (!side)
            return std::nullopt;
        return Side{side->result.outcome, QString::fromStdString(side->result.message),
                    side->result.seconds, side->quality};
    };
    m_input = summary(input);
    m_output = input ? summary(output) : std::nullopt;
    fill();
}

QString TetmeshPanel::cellText(Row row, Column column) const
{
    return m_table->item(row, column)->text();
}

QString TetmeshPanel::notesText() const
{
    return m_notes->text();
}

TetColouring TetmeshPanel::colouring() const
{
    return m_colouring->currentIndex() == 1 ? TetColouring::MinDihedral : TetColouring::Region;
}

void TetmeshPanel::setColouring(TetColouring colouring)
{
    m_colouring->setCurrentIndex(colouring == TetColouring::MinDihedral ? 1 : 0);
}

bool TetmeshPanel::clipEnabled() const
{
    return m_clip->isClipping();
}

ClipAxis TetmeshPanel::clipAxis() const
{
    return m_clip->axis();
}

double TetmeshPanel::clipFraction() const
{
    return m_clip->fraction();
}

void TetmeshPanel::setClip(bool enabled, ClipAxis axis, double fraction)
{
    m_clip->setClip(enabled, axis, fraction);
}

QString TetmeshPanel::outcomeText(TetgenOutcome outcome)
{
    switch (outcome) {
    case TetgenOutcome::Ok:
        return tr("ok");
    case TetgenOutcome::Aborted:
        return tr("aborted");
    case TetgenOutcome::TimedOut:
        return tr("timed out");
    case TetgenOutcome::OutOfMemory:
        return tr("out of memory");
    case TetgenOutcome::Killed:
        return tr("killed");
    case TetgenOutcome::InvalidInput:
        return tr("invalid input");
    }
    return tr("aborted");
}

QString TetmeshPanel::failureText(TetgenOutcome outcome, const QString &message, double seconds,
                                  bool input)
{
    // TetGen never ran on an invalid model: no time to report.
    if (outcome == TetgenOutcome::InvalidInput)
        return input ? tr("TetGen was not run on the input: %1").arg(message)
                     : tr("TetGen was not run on the remesh: %1").arg(message);
    const QString time = secondsText(seconds);
    return input ? tr("TetGen failed on the input after %1 s: %2").arg(time, message)
                 : tr("TetGen failed on the remesh after %1 s: %2").arg(time, message);
}

QSize TetmeshPanel::sizeHint() const
{
    const int figures =
        m_table->fontMetrics().horizontalAdvance(QStringLiteral("000 000 000")) + 12;
    const int width = m_table->verticalHeader()->sizeHint().width() + ColumnCount * figures
                      + 2 * m_table->frameWidth() + 2 * layout()->contentsMargins().left();
    return {width, QWidget::sizeHint().height()};
}

void TetmeshPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void TetmeshPanel::retranslate()
{
    m_colourLabel->setText(tr("C&olour tets by:"));
    m_colouring->setItemText(0, tr("Region"));
    m_colouring->setItemText(1, tr("Min dihedral angle"));
    m_table->setHorizontalHeaderLabels({tr("Input"), tr("Remesh")});
    m_table->setVerticalHeaderLabels({tr("Outcome"), tr("Tetrahedra"), tr("Points"),
                                      tr("Slivers (min dihedral < 5°)"), tr("Min dihedral (°)"),
                                      tr("TetGen time (s)")});
    fill();
}

void TetmeshPanel::fill()
{
    const QLocale locale;
    m_table->setFixedHeight(m_table->horizontalHeader()->sizeHint().height()
                            + m_table->verticalHeader()->length() + 2 * m_table->frameWidth() + 2);
    const std::optional<Side> *sides[ColumnCount] = {&m_input, &m_output};
    QStringList notes;
    for (int c = 0; c < ColumnCount; ++c) {
        const std::optional<Side> &side = *sides[c];
        const auto set = [&](Row row, const QString &text) {
            m_table->item(row, c)->setText(text);
        };
        if (!side) {
            for (int r = 0; r < RowCount; ++r)
                set(Row(r), QString());
            continue;
        }
        const bool ok = side->outcome == TetgenOutcome::Ok;
        const QString none = QStringLiteral("—");
        const VolumeQualityStatistics &q = side->quality;
        set(OutcomeRow, outcomeText(side->outcome));
        m_table->item(OutcomeRow, c)->setToolTip(side->message);
        set(TetsRow, ok ? locale.toString(qulonglong(q.tets)) : none);
        set(PointsRow, ok ? locale.toString(qulonglong(q.points)) : none);
        set(SliversRow, ok ? locale.toString(qulonglong(q.slivers)) : none);
        set(MinDihedralRow, ok ? locale.toString(q.minDihedralDeg, 'f', 2) : none);
        set(TimeRow,
            side->outcome == TetgenOutcome::InvalidInput ? none : secondsText(side->seconds));
        if (!ok)
            notes << failureText(side->outcome, side->message, side->seconds, c == InputColumn);
    }
    m_notes->setText(notes.join(QLatin1Char('\n')));
    m_notes->setVisible(!notes.isEmpty());
}

} // namespace stratamesh
