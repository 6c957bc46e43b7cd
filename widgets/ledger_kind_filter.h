// Shows only the ledger records of one kind (or all of them), keeping the ledger order.
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
    // Index in the ledger of the record shown at `row`, -1 when out of range.
    int recordIndex(int row) const;

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;

private:
    std::optional<LedgerKind> m_kind;
};

} // namespace stratamesh
