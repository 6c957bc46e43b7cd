#include "ledger_kind_filter.h"

#include "ledger_table_model.h"

namespace stratamesh {

LedgerKindFilter::LedgerKindFilter(QObject *parent) : QSortFilterProxyModel(parent) {}

void LedgerKindFilter::setKind(std::optional<LedgerKind> kind)
{
    if (kind == m_kind)
        return;
    // Qt 6.4 has no begin/endFilterChange: invalidateFilter() re-runs filterAcceptsRow.
    m_kind = kind;
    invalidateFilter();
}

int LedgerKindFilter::recordIndex(int row) const
{
    if (row < 0 || row >= rowCount())
        return -1;
    return index(row, 0).data(LedgerTableModel::RecordIndexRole).toInt();
}

bool LedgerKindFilter::filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const
{
    if (!m_kind)
        return true;
    const QModelIndex i = sourceModel()->index(sourceRow, 0, sourceParent);
    return i.data(LedgerTableModel::KindRole).toInt() == int(*m_kind);
}

} // namespace stratamesh
