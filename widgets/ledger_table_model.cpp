#include "ledger_table_model.h"

#include "core_text.h"

#include <QLocale>

namespace stratamesh {

LedgerTableModel::LedgerTableModel(QObject *parent) : QAbstractTableModel(parent) {}

void LedgerTableModel::setLedger(std::shared_ptr<const SimplificationLedger> ledger)
{
    beginResetModel();
    m_ledger = std::move(ledger);
    endResetModel();
}

const LedgerRecord *LedgerTableModel::record(int row) const
{
    if (!m_ledger || row < 0 || row >= int(m_ledger->size()))
        return nullptr;
    return &(*m_ledger)[std::size_t(row)];
}

int LedgerTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() || !m_ledger ? 0 : int(m_ledger->size());
}

int LedgerTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant LedgerTableModel::data(const QModelIndex &index, int role) const
{
    const LedgerRecord *r = record(index.row());
    if (!r)
        return {};
    if (role == KindRole)
        return int(r->kind);
    if (role == RecordIndexRole)
        return index.row();
    if (role == SortRole) {
        // "12.5 (distance)" sorts as text after "100 (distance)"; the size itself does not.
        if (index.column() == SizeColumn)
            return r->size;
        return data(index, Qt::DisplayRole);
    }
    if (role == Qt::TextAlignmentRole && index.column() == SizeColumn)
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::ToolTipRole) {
        if (index.column() == InputsColumn)
            return entitiesText(r->inputs);
        if (index.column() == OutputsColumn)
            return entitiesText(r->outputs);
        return coreText(r->noteText, r->note);
    }
    if (role != Qt::DisplayRole)
        return {};
    switch (index.column()) {
    case KindColumn:
        return kindText(r->kind);
    case InputsColumn:
        return entitiesText(r->inputs);
    case OutputsColumn:
        return entitiesText(r->outputs);
    case SizeColumn:
        return sizeText(*r);
    case PositionColumn:
        return positionText(r->position);
    case NoteColumn:
        return coreText(r->noteText, r->note);
    default:
        return {};
    }
}

QVariant LedgerTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case KindColumn:
        return tr("Kind");
    case InputsColumn:
        return tr("Input entities");
    case OutputsColumn:
        return tr("Output");
    case SizeColumn:
        return tr("Size");
    case PositionColumn:
        return tr("Position");
    case NoteColumn:
        return tr("Note");
    default:
        return {};
    }
}

std::vector<LedgerKind> LedgerTableModel::allKinds()
{
    std::vector<LedgerKind> kinds;
    for (int k = 0; k <= int(kLastLedgerKind); ++k)
        kinds.push_back(LedgerKind(k));
    return kinds;
}

QString LedgerTableModel::kindText(LedgerKind kind)
{
    switch (kind) {
    case LedgerKind::CornerMerge:
        return tr("Corner merge");
    case LedgerKind::MultiPointMerge:
        return tr("Multi-point merge");
    case LedgerKind::CloseFeatureMerge:
        return tr("Close feature merge");
    case LedgerKind::DegenerateContactTriangle:
        return tr("Degenerate contact triangle");
    case LedgerKind::DegenerateBorderTriangle:
        return tr("Degenerate border triangle");
    case LedgerKind::Valence3Removed:
        return tr("Valence-3 vertex removed");
    case LedgerKind::SurfaceLost:
        return tr("Surface lost");
    case LedgerKind::LineLost:
        return tr("Line lost");
    case LedgerKind::CornerLost:
        return tr("Corner lost");
    case LedgerKind::SurfaceCreated:
        return tr("Surface created");
    case LedgerKind::LineCreated:
        return tr("Line created");
    case LedgerKind::CornerCreated:
        return tr("Corner created");
    case LedgerKind::IntersectionUnresolved:
        return tr("Unresolved intersection");
    case LedgerKind::SurfacePartLost:
        return tr("Surface part lost");
    case LedgerKind::SurfacePartCreated:
        return tr("Surface part created");
    }
    return QString::fromStdString(ledgerKindName(kind));
}

QString LedgerTableModel::summary(const SimplificationLedger &ledger)
{
    QStringList parts;
    for (LedgerKind kind : allKinds())
        if (const int n = countKind(ledger, kind); n > 0)
            parts << tr("%1: %2").arg(kindText(kind), QLocale().toString(n));
    return parts.join(QStringLiteral("  ·  "));
}

QString LedgerTableModel::entitiesText(const std::vector<EntityRef> &refs)
{
    QStringList names;
    for (const EntityRef &ref : refs) {
        if (!ref.name.empty())
            names << QString::fromStdString(ref.name);
        else if (ref.kind == EntityKind::Vertex)
            names << tr("vertex %1").arg(ref.id);
        else
            names << QStringLiteral("%1 %2")
                         .arg(QString::fromStdString(entityKindName(ref.kind)))
                         .arg(ref.id);
    }
    return names.join(QStringLiteral(", "));
}

QString LedgerTableModel::sizeText(const LedgerRecord &record)
{
    const QString value = QLocale().toString(record.size, 'g', 4);
    if (record.sizeMeaning == "distance")
        return tr("%1 (distance)").arg(value);
    if (record.sizeMeaning == "area")
        return tr("%1 (area)").arg(value);
    if (record.sizeMeaning == "length")
        return tr("%1 (length)").arg(value);
    if (record.sizeMeaning.empty())
        return value;
    return QStringLiteral("%1 (%2)").arg(value, QString::fromStdString(record.sizeMeaning));
}

QString LedgerTableModel::positionText(const Vec3 &p)
{
    const QLocale locale;
    // Semicolons: with a decimal comma, "140,0, 3 302,3" would read as four numbers.
    return QStringLiteral("(%1; %2; %3)")
        .arg(locale.toString(p.x(), 'f', 1), locale.toString(p.y(), 'f', 1),
             locale.toString(p.z(), 'f', 1));
}

} // namespace stratamesh
