#include "review_panel.h"

#include "ledger_kind_filter.h"
#include "ledger_panel.h"
#include "review_table_model.h"

#include <QAction>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QKeyEvent>
#include <QLabel>
#include <QLocale>
#include <QStyle>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

namespace stratamesh {

ReviewPanel::ReviewPanel(QWidget *parent)
    : QWidget(parent), m_model(new ReviewTableModel(this)),
      m_ledger(new LedgerPanel(this, m_model)), m_progress(new QLabel(this)),
      m_buttons(new QHBoxLayout), m_accept(new QAction(this)), m_flag(new QAction(this)),
      m_note(new QAction(this)), m_previous(new QAction(this)), m_next(new QAction(this))
{
    QTableView *table = tableView();
    // The decision and the record number lead; the review note ends the row, where it can grow.
    QHeaderView *header = table->horizontalHeader();
    header->moveSection(header->visualIndex(ReviewTableModel::RecordColumn), 0);
    header->moveSection(header->visualIndex(ReviewTableModel::DecisionColumn), 1);
    table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    table->installEventFilter(this);

    const QStyle *style = this->style();
    m_accept->setIcon(style->standardIcon(QStyle::SP_DialogApplyButton));
    m_flag->setIcon(style->standardIcon(QStyle::SP_MessageBoxWarning));
    m_note->setIcon(style->standardIcon(QStyle::SP_FileDialogDetailedView));
    m_previous->setIcon(style->standardIcon(QStyle::SP_ArrowUp));
    m_next->setIcon(style->standardIcon(QStyle::SP_ArrowDown));
    connect(m_accept, &QAction::triggered, this, &ReviewPanel::acceptCurrent);
    connect(m_flag, &QAction::triggered, this, &ReviewPanel::flagCurrent);
    connect(m_note, &QAction::triggered, this, &ReviewPanel::editNote);
    connect(m_previous, &QAction::triggered, this, &ReviewPanel::selectPrevious);
    connect(m_next, &QAction::triggered, this, &ReviewPanel::selectNext);
    for (QAction *action : {m_accept, m_flag, m_note, m_previous, m_next}) {
        auto *button = new QToolButton(this);
        button->setDefaultAction(action);
        button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
        button->setAutoRaise(true);
        m_buttons->addWidget(button);
    }
    m_buttons->addStretch(1);
    m_buttons->addWidget(m_progress);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    m_buttons->setContentsMargins(4, 4, 4, 0);
    layout->addLayout(m_buttons);
    layout->addWidget(m_ledger, 1);

    connect(m_ledger, &LedgerPanel::recordSelected, this, [this](int record) {
        updateState();
        emit recordSelected(record);
    });
    connect(m_model, &ReviewTableModel::noteEdited, this, [this](int record, const QString &note) {
        ReviewDecision decision = m_model->decisions().decision(record);
        decision.note = note;
        emit decisionRequested(record, decision);
    });
    retranslate();
    updateState();
}

QTableView *ReviewPanel::tableView() const
{
    return m_ledger->tableView();
}

void ReviewPanel::setLedger(std::shared_ptr<const SimplificationLedger> ledger)
{
    m_ledger->setLedger(std::move(ledger));
    updateState();
}

void ReviewPanel::setDecisions(const ReviewDecisions &decisions)
{
    m_model->setDecisions(decisions);
    updateState();
}

void ReviewPanel::addAction(QAction *action)
{
    auto *button = new QToolButton(this);
    button->setDefaultAction(action);
    button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    button->setAutoRaise(true);
    // Before the stretch and the count.
    m_buttons->insertWidget(m_buttons->count() - 2, button);
}

int ReviewPanel::currentRecord() const
{
    const QModelIndexList rows = tableView()->selectionModel()->selectedRows();
    return rows.isEmpty() ? -1 : m_ledger->filter()->recordIndex(rows.first().row());
}

QString ReviewPanel::progressText() const
{
    return m_progress->text();
}

void ReviewPanel::acceptCurrent()
{
    toggleVerdict(ReviewVerdict::Accepted);
}

void ReviewPanel::flagCurrent()
{
    toggleVerdict(ReviewVerdict::Flagged);
}

void ReviewPanel::toggleVerdict(ReviewVerdict verdict)
{
    const int record = currentRecord();
    if (record < 0)
        return;
    ReviewDecision decision = m_model->decisions().decision(record);
    decision.verdict = decision.verdict == verdict ? ReviewVerdict::Open : verdict;
    emit decisionRequested(record, decision);
}

void ReviewPanel::editNote()
{
    const QModelIndexList rows = tableView()->selectionModel()->selectedRows();
    if (rows.isEmpty())
        return;
    const QModelIndex note =
        m_ledger->filter()->index(rows.first().row(), ReviewTableModel::ReviewNoteColumn);
    tableView()->scrollTo(note);
    tableView()->setCurrentIndex(note);
    tableView()->edit(note);
}

void ReviewPanel::selectNext()
{
    step(1);
}

void ReviewPanel::selectPrevious()
{
    step(-1);
}

void ReviewPanel::step(int delta)
{
    const int rows = m_ledger->visibleRowCount();
    if (rows == 0)
        return;
    const QModelIndexList selected = tableView()->selectionModel()->selectedRows();
    const int row = selected.isEmpty() ? (delta > 0 ? 0 : rows - 1)
                                       : std::clamp(selected.first().row() + delta, 0, rows - 1);
    m_ledger->selectRow(row);
    tableView()->scrollTo(m_ledger->filter()->index(row, 0));
}

bool ReviewPanel::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == tableView() && event->type() == QEvent::KeyPress) {
        const auto *key = static_cast<QKeyEvent *>(event);
        if ((key->modifiers() & ~Qt::KeypadModifier) == Qt::NoModifier) {
            switch (key->key()) {
            case Qt::Key_A:
                acceptCurrent();
                return true;
            case Qt::Key_F:
                flagCurrent();
                return true;
            case Qt::Key_N:
                editNote();
                return true;
            case Qt::Key_J:
                selectNext();
                return true;
            case Qt::Key_K:
                selectPrevious();
                return true;
            default:
                break;
            }
        }
    }
    return QWidget::eventFilter(watched, event);
}

void ReviewPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        updateState();
    }
    QWidget::changeEvent(event);
}

void ReviewPanel::retranslate()
{
    m_accept->setText(tr("&Accept"));
    m_accept->setToolTip(tr("Accept the selected simplification (A; again to reopen it)"));
    m_flag->setText(tr("&Flag"));
    m_flag->setToolTip(tr("Flag the selected simplification for a closer look (F; again to "
                          "reopen it)"));
    m_note->setText(tr("&Note"));
    m_note->setToolTip(tr("Write a note on the selected simplification (N; Enter keeps it)"));
    m_previous->setText(tr("&Previous"));
    m_previous->setToolTip(tr("Go to the previous record and show it in both views (K or Up)"));
    m_next->setText(tr("Ne&xt"));
    m_next->setToolTip(tr("Go to the next record and show it in both views (J or Down)"));
}

void ReviewPanel::updateState()
{
    const int records = m_model->rowCount();
    const QLocale locale;
    m_progress->setText(records == 0
                            ? QString()
                            : tr("%1 of %2 reviewed")
                                  .arg(locale.toString(m_model->decisions().reviewedCount()),
                                       locale.toString(records)));
    const bool selected = currentRecord() >= 0;
    for (QAction *action : {m_accept, m_flag, m_note})
        action->setEnabled(selected);
    for (QAction *action : {m_previous, m_next})
        action->setEnabled(m_ledger->visibleRowCount() > 0);
}

} // namespace stratamesh
