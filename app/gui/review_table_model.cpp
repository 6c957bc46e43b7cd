#include "review_table_model.h"

#include <QBrush>
#include <QColor>

namespace stratamesh {

ReviewTableModel::ReviewTableModel(QObject *parent) : LedgerTableModel(parent) {}

void ReviewTableModel::setDecisions(const ReviewDecisions &decisions)
{
    if (decisions == m_decisions)
        return;
    m_decisions = decisions;
    if (rowCount() > 0)
        emit dataChanged(index(0, DecisionColumn), index(rowCount() - 1, ReviewNoteColumn));
}

QString ReviewTableModel::verdictText(ReviewVerdict verdict)
{
    switch (verdict) {
    case ReviewVerdict::Accepted:
        return tr("Accepted");
    case ReviewVerdict::Flagged:
        return tr("Flagged");
    case ReviewVerdict::Open:
        break;
    }
    return tr("Open");
}

int ReviewTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ReviewColumnCount;
}

QVariant ReviewTableModel::data(const QModelIndex &index, int role) const
{
    if (index.column() < ColumnCount || !record(index.row()))
        return LedgerTableModel::data(index, role);
    if (index.column() == RecordColumn) {
        if (role == Qt::DisplayRole || role == SortRole)
            return index.row();
        if (role == Qt::TextAlignmentRole)
            return int(Qt::AlignRight | Qt::AlignVCenter);
        return LedgerTableModel::data(index, role);
    }
    const ReviewDecision decision = m_decisions.decision(index.row());
    if (index.column() == DecisionColumn) {
        switch (role) {
        case Qt::DisplayRole:
            return verdictText(decision.verdict);
        case SortRole:
            return int(decision.verdict);
        case Qt::ForegroundRole:
            // Flagged records are the ones to come back to: they stand out.
            if (decision.verdict == ReviewVerdict::Flagged)
                return QBrush(QColor(0xc0, 0x39, 0x2b));
            if (decision.verdict == ReviewVerdict::Accepted)
                return QBrush(QColor(0x1e, 0x84, 0x49));
            return {};
        default:
            return LedgerTableModel::data(index, role);
        }
    }
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole:
    case Qt::ToolTipRole:
    case SortRole:
        return decision.note;
    default:
        return LedgerTableModel::data(index, role);
    }
}

QVariant ReviewTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole || section < ColumnCount)
        return LedgerTableModel::headerData(section, orientation, role);
    switch (section) {
    case DecisionColumn:
        return tr("Decision");
    case ReviewNoteColumn:
        return tr("Review note");
    case RecordColumn:
        return tr("#");
    default:
        return {};
    }
}

Qt::ItemFlags ReviewTableModel::flags(const QModelIndex &index) const
{
    Qt::ItemFlags flags = LedgerTableModel::flags(index);
    if (index.column() == ReviewNoteColumn)
        flags |= Qt::ItemIsEditable;
    return flags;
}

bool ReviewTableModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (role != Qt::EditRole || index.column() != ReviewNoteColumn || !record(index.row()))
        return false;
    const QString note = value.toString().trimmed();
    if (note != m_decisions.decision(index.row()).note)
        emit noteEdited(index.row(), note);
    return true;
}

} // namespace stratamesh
