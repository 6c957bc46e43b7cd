#include "ledger_panel.h"

#include "ledger_kind_filter.h"
#include "ledger_table_model.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLineEdit>
#include <QTableView>
#include <QVBoxLayout>

#include <algorithm>

namespace stratamesh {

LedgerPanel::LedgerPanel(QWidget *parent, LedgerTableModel *model)
    : QWidget(parent), m_model(model ? model : new LedgerTableModel(this)),
      m_filter(new LedgerKindFilter(this)), m_kinds(new QComboBox(this)),
      m_filterLabel(new QLabel(this)), m_search(new QLineEdit(this)), m_summary(new QLabel(this)),
      m_table(new QTableView(this))
{
    m_model->setParent(this);
    m_filter->setSourceModel(m_model);
    m_table->setModel(m_filter);
    // The ledger order first; a click on a header sorts, a third click returns to that order.
    m_table->horizontalHeader()->setSortIndicator(-1, Qt::AscendingOrder);
    m_table->horizontalHeader()->setSortIndicatorClearable(true);
    m_table->setSortingEnabled(true);
    m_search->setClearButtonEnabled(true);
    // "All kinds" and the kind names stay whole beside the search field.
    m_kinds->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setAlternatingRowColors(true);
    m_table->setWordWrap(false);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *top = new QHBoxLayout;
    top->addWidget(m_filterLabel);
    top->addWidget(m_kinds);
    top->addWidget(m_search);
    top->addWidget(m_summary, 1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(top);
    layout->addWidget(m_table, 1);

    connect(m_kinds, &QComboBox::currentIndexChanged, this, [this](int i) {
        const QVariant kind = m_kinds->itemData(i);
        m_filter->setKind(kind.isValid() ? std::optional<LedgerKind>(LedgerKind(kind.toInt()))
                                         : std::nullopt);
        onSelectionChanged();
    });
    connect(m_search, &QLineEdit::textChanged, this, [this](const QString &text) {
        m_filter->setSearchText(text);
        onSelectionChanged();
    });
    connect(m_table->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &LedgerPanel::onSelectionChanged);
    retranslate();
}

void LedgerPanel::setLedger(std::shared_ptr<const SimplificationLedger> ledger)
{
    m_model->setLedger(std::move(ledger));
    fillKinds();
    m_summary->setText(m_model->ledger() ? (m_model->ledger()->empty()
                                                ? tr("No simplification")
                                                : LedgerTableModel::summary(*m_model->ledger()))
                                         : QString());
    m_table->resizeColumnsToContents();
    // Long lists of entities stay readable in the tooltip; the columns stay on screen.
    const int widest = m_table->fontMetrics().averageCharWidth() * 40;
    for (int c = LedgerTableModel::InputsColumn; c < LedgerTableModel::ColumnCount; ++c)
        m_table->setColumnWidth(c, std::min(m_table->columnWidth(c), widest));
    onSelectionChanged();
}

void LedgerPanel::setKindFilter(std::optional<LedgerKind> kind)
{
    const int i = kind ? m_kinds->findData(int(*kind)) : 0;
    if (i >= 0)
        m_kinds->setCurrentIndex(i);
    else
        m_filter->setKind(kind); // a kind absent from the ledger: an empty table
}

void LedgerPanel::setSearchText(const QString &text)
{
    m_search->setText(text);
}

void LedgerPanel::selectRow(int row)
{
    if (row < 0 || row >= m_filter->rowCount())
        m_table->clearSelection();
    else
        m_table->selectRow(row);
}

int LedgerPanel::visibleRowCount() const
{
    return m_filter->rowCount();
}

QString LedgerPanel::summaryText() const
{
    return m_summary->text();
}

void LedgerPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void LedgerPanel::retranslate()
{
    m_filterLabel->setText(tr("Kind:"));
    m_search->setPlaceholderText(tr("Search…"));
    m_search->setToolTip(tr("Show only the records whose text holds this (any column)"));
    fillKinds();
    if (m_model->ledger() && !m_model->ledger()->empty())
        m_summary->setText(LedgerTableModel::summary(*m_model->ledger()));
}

// Only the kinds present, each with its count, so the combo itself is a summary.
void LedgerPanel::fillKinds()
{
    const QVariant current = m_kinds->currentData();
    const QSignalBlocker block(m_kinds);
    m_kinds->clear();
    m_kinds->addItem(tr("All kinds"));
    if (m_model->ledger())
        for (LedgerKind kind : LedgerTableModel::allKinds())
            if (const int n = countKind(*m_model->ledger(), kind); n > 0)
                m_kinds->addItem(
                    QStringLiteral("%1 (%2)").arg(LedgerTableModel::kindText(kind)).arg(n),
                    int(kind));
    const int i = current.isValid() ? m_kinds->findData(current) : 0;
    m_kinds->setCurrentIndex(i >= 0 ? i : 0);
    const QVariant kind = m_kinds->currentData();
    m_filter->setKind(kind.isValid() ? std::optional<LedgerKind>(LedgerKind(kind.toInt()))
                                     : std::nullopt);
}

void LedgerPanel::onSelectionChanged()
{
    const QModelIndexList rows = m_table->selectionModel()->selectedRows();
    emit recordSelected(rows.isEmpty() ? -1 : m_filter->recordIndex(rows.first().row()));
}

} // namespace stratamesh
