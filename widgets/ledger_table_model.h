// The simplification ledger of a remeshing as a table a geologist reviews row by row (thesis
// §4.4.2–4.4.5, §4.6.1: "a quality check of the disappearing and appearing elements is
// necessary"): kind, input entities, output entities, size with its meaning, position, note.
// It shows what the core recorded; nothing is computed here.
#pragma once

#include "remesh/simplification_ledger.h"

#include <QAbstractTableModel>

#include <memory>
#include <vector>

namespace stratamesh {

class LedgerTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        KindColumn,
        InputsColumn,
        OutputsColumn,
        SizeColumn,
        PositionColumn,
        NoteColumn,
        ColumnCount
    };
    enum Role {
        KindRole = Qt::UserRole + 1, // int(LedgerKind), for filtering
        RecordIndexRole,             // index of the record in the ledger
        SortRole,                    // what a column sorts by: numbers as numbers
    };

    explicit LedgerTableModel(QObject *parent = nullptr);

    // nullptr clears. The model keeps the ledger alive.
    void setLedger(std::shared_ptr<const SimplificationLedger> ledger);
    const std::shared_ptr<const SimplificationLedger> &ledger() const { return m_ledger; }
    const LedgerRecord *record(int row) const;

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    // Every kind, in the order of LedgerKind.
    static std::vector<LedgerKind> allKinds();
    static QString kindText(LedgerKind kind);
    // "Corner merge" → "Corner merges: 3"; "" for an empty ledger.
    static QString summary(const SimplificationLedger &ledger);
    static QString entitiesText(const std::vector<EntityRef> &refs);
    static QString sizeText(const LedgerRecord &record);
    static QString positionText(const Vec3 &position);

private:
    std::shared_ptr<const SimplificationLedger> m_ledger;
};

} // namespace stratamesh
