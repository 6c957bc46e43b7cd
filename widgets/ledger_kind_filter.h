// Shows only the ledger records of one kind (or all of them) whose text holds a search string,
// in the ledger order until a column is chosen to sort by (numbers sort as numbers).
#pragma once

#include "remesh/simplification_ledger.h"

#include <QSortFilterProxyModel>

#include <optional>

namespace stratamesh {

class LedgerKindFilter : public QSortFilterProxyModel {
    Q_OBJECT
public:
    explicit LedgerKindFilter(QObject *parent = nullptr);

    // std::nullopt: every record.
    void setKind(std::optional<LedgerKind> kind);
    std::optional<LedgerKind> kind() const { return m_kind; }
    // Case-insensitive, in any column's text; empty: no text condition.
    void setSearchText(const QString &text);
    QString searchText() const { return m_search; }
    // Index in the ledger of the record shown at `row`, -1 when out of range.
    int recordIndex(int row) const;

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;

private:
    std::optional<LedgerKind> m_kind;
    QString m_search;
};

} // namespace stratamesh
