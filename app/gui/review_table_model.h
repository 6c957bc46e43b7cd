// The ledger table with the review beside each record: the decision (Open, Accepted, Flagged)
// and the geologist's note, which is edited in place. Edits are requests: the model shows the
// decisions it is given and never changes them itself, so every change goes through the undo
// stack.
#pragma once

#include "ledger_table_model.h"
#include "review_decisions.h"

namespace stratamesh {

class ReviewTableModel : public LedgerTableModel {
    Q_OBJECT
public:
    enum ReviewColumn {
        DecisionColumn = ColumnCount,
        ReviewNoteColumn,
        RecordColumn, // the index in the ledger, as in the exported CSV and the project file
        ReviewColumnCount
    };

    explicit ReviewTableModel(QObject *parent = nullptr);

    void setDecisions(const ReviewDecisions &decisions);
    const ReviewDecisions &decisions() const { return m_decisions; }

    static QString verdictText(ReviewVerdict verdict);

    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    // The note column only: emits noteEdited and returns true; the shown note changes when the
    // decisions are set again.
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;

signals:
    void noteEdited(int record, const QString &note);

private:
    ReviewDecisions m_decisions;
};

} // namespace stratamesh
