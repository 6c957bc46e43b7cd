#include "ledger_kind_filter.h"

#include "ledger_table_model.h"

namespace stratamesh {

LedgerKindFilter::LedgerKindFilter(QObject *parent) : QSortFilterProxyModel(parent)
{
    setSortRole(LedgerTableModel::SortRole);
    setSortCaseSensitivity(Qt::CaseInsensitive);
}

void LedgerKindFilter::setKind(std::optional<LedgerKind> kind)
{
    if (kind == m_kind)
        return;
    // Qt 6.4 has no begin/endFilterChange: invalidateFilter() re-runs filterAcceptsRow.
    m_kind = kind;
    invalidateFilter();
}

void LedgerKindFilter::setSearchText(const QString &text)
{
    const QString trimmed = text.trimmed();
    if (trimmed == m_search)
        return;
    m_search = trimmed;
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
    const QAbstractItemModel *source = sourceModel();
    if (m_kind
        && source->index(sourceRow, 0, sourceParent).data(LedgerTableModel::KindRole).toInt()
               != int(*m_kind))
        return false;
    if (m_search.isEmpty())
        return true;
    // Every column the source has, so a derived model's columns (a review note) are searched too.
    for (int c = 0; c < source->columnCount(sourceParent); ++c)
        if (source->index(sourceRow, c, sourceParent)
                .data()
                .toString()
                .contains(m_search, Qt::CaseInsensitive))
            return true;
    return false;
}

} // namespace stratamesh
