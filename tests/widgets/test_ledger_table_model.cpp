// The Simplifications table shows every ledger record with its kind, the names of the entities it
// touched, its size with the meaning of that size, and its position; the kind filter keeps
// exactly the records of one kind; selecting a row names the record in the ledger.
#include "ledger_kind_filter.h"
#include "ledger_panel.h"
#include "ledger_table_model.h"

#include <QComboBox>
#include <QSignalSpy>
#include <QTableView>
#include <QtTest>

using namespace stratamesh;

namespace {

LedgerRecord record(LedgerKind kind, std::vector<EntityRef> inputs, std::vector<EntityRef> outputs,
                    double size, const char *meaning, Vec3 position)
{
    LedgerRecord r;
    r.kind = kind;
    r.inputs = std::move(inputs);
    r.outputs = std::move(outputs);
    r.size = size;
    r.sizeMeaning = meaning;
    r.position = position;
    r.note = "note of " + ledgerKindName(kind);
    return r;
}

EntityRef ref(EntityKind kind, int id, const char *name)
{
    return EntityRef{kind, id, name};
}

// 5 records of 3 kinds, the kinds interleaved so that filtering has to skip rows.
std::shared_ptr<const SimplificationLedger> makeLedger()
{
    auto ledger = std::make_shared<SimplificationLedger>();
    ledger->push_back(
        record(LedgerKind::CornerMerge,
               {ref(EntityKind::Corner, 3, "corner_3"), ref(EntityKind::Corner, 8, "corner_8")},
               {ref(EntityKind::Vertex, 41, "")}, 12.5, "distance", Vec3(1.0, 2.0, 3.0)));
    ledger->push_back(record(LedgerKind::LineLost, {ref(EntityKind::Line, 7, "line_7")}, {}, 80.0,
                             "length", Vec3(10.0, 20.0, -30.0)));
    ledger->push_back(record(LedgerKind::CornerMerge,
                             {ref(EntityKind::Surface, 0, "H1"), ref(EntityKind::Surface, 2, "F1")},
                             {}, 4.0, "distance", Vec3(5.0, 5.0, 5.0)));
    ledger->push_back(
        record(LedgerKind::DegenerateContactTriangle, {ref(EntityKind::Surface, 1, "H2")},
               {ref(EntityKind::Surface, 1, "H2")}, 0.25, "area", Vec3(-1.0, 0.0, 0.5)));
    ledger->push_back(record(LedgerKind::LineLost, {ref(EntityKind::Line, 9, "")}, {}, 3.0,
                             "length", Vec3(0.0, 0.0, 0.0)));
    return ledger;
}

QString cell(const QAbstractItemModel &model, int row, int column)
{
    return model.index(row, column).data().toString();
}

} // namespace

class TestLedgerTableModel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QLocale::setDefault(QLocale::c()); }

    void oneRowPerRecordWithNamesSizeAndPosition()
    {
        LedgerTableModel model;
        QCOMPARE(model.rowCount(), 0);
        const auto ledger = makeLedger();
        model.setLedger(ledger);
        QCOMPARE(model.rowCount(), int(ledger->size()));
        QCOMPARE(model.columnCount(), int(LedgerTableModel::ColumnCount));
        QCOMPARE(cell(model, 0, LedgerTableModel::KindColumn), QStringLiteral("Corner merge"));
        QCOMPARE(cell(model, 0, LedgerTableModel::InputsColumn),
                 QStringLiteral("corner_3, corner_8"));
        QCOMPARE(cell(model, 0, LedgerTableModel::OutputsColumn), QStringLiteral("vertex 41"));
        QCOMPARE(cell(model, 0, LedgerTableModel::SizeColumn), QStringLiteral("12.5 (distance)"));
        QCOMPARE(cell(model, 0, LedgerTableModel::PositionColumn),
                 QStringLiteral("(1.0; 2.0; 3.0)"));
        QCOMPARE(cell(model, 0, LedgerTableModel::NoteColumn),
                 QStringLiteral("note of corner_merge"));
        QCOMPARE(cell(model, 1, LedgerTableModel::SizeColumn), QStringLiteral("80 (length)"));
        QCOMPARE(cell(model, 1, LedgerTableModel::PositionColumn),
                 QStringLiteral("(10.0; 20.0; -30.0)"));
        QCOMPARE(cell(model, 3, LedgerTableModel::SizeColumn), QStringLiteral("0.25 (area)"));
        QCOMPARE(cell(model, 3, LedgerTableModel::KindColumn),
                 QStringLiteral("Degenerate contact triangle"));
        // A line without a name is still named.
        QCOMPARE(cell(model, 4, LedgerTableModel::InputsColumn), QStringLiteral("line 9"));
        for (int row = 0; row < model.rowCount(); ++row) {
            QCOMPARE(model.index(row, 0).data(LedgerTableModel::KindRole).toInt(),
                     int((*ledger)[row].kind));
            QCOMPARE(model.index(row, 0).data(LedgerTableModel::RecordIndexRole).toInt(), row);
            QCOMPARE(model.record(row), &(*ledger)[row]);
        }
        QVERIFY(!model.record(5));
        QVERIFY(!cell(model, 5, 0).size());
        model.setLedger(nullptr);
        QCOMPARE(model.rowCount(), 0);
    }

    void everyKindHasItsOwnText()
    {
        QSet<QString> texts;
        for (LedgerKind kind : LedgerTableModel::allKinds())
            texts.insert(LedgerTableModel::kindText(kind));
        QCOMPARE(int(LedgerTableModel::allKinds().size()), int(kLastLedgerKind) + 1);
        QCOMPARE(texts.size(), int(LedgerTableModel::allKinds().size()));
    }

    void summaryCountsEachKind()
    {
        const auto ledger = makeLedger();
        QCOMPARE(
            LedgerTableModel::summary(*ledger),
            QStringLiteral("Corner merge: 2  ·  Degenerate contact triangle: 1  ·  Line lost: 2"));
        QCOMPARE(LedgerTableModel::summary({}), QString());
    }

    void filterKeepsExactlyOneKind()
    {
        LedgerTableModel model;
        const auto ledger = makeLedger();
        model.setLedger(ledger);
        LedgerKindFilter filter;
        filter.setSourceModel(&model);
        QCOMPARE(filter.rowCount(), 5);
        for (LedgerKind kind : LedgerTableModel::allKinds()) {
            filter.setKind(kind);
            QCOMPARE(filter.rowCount(), countKind(*ledger, kind));
            for (int row = 0; row < filter.rowCount(); ++row)
                QCOMPARE((*ledger)[std::size_t(filter.recordIndex(row))].kind, kind);
        }
        filter.setKind(LedgerKind::LineLost);
        QCOMPARE(filter.recordIndex(0), 1);
        QCOMPARE(filter.recordIndex(1), 4);
        QCOMPARE(filter.recordIndex(2), -1);
        filter.setKind(std::nullopt);
        QCOMPARE(filter.rowCount(), 5);
    }

    void panelFiltersSummarisesAndReportsTheSelection()
    {
        LedgerPanel panel;
        const auto ledger = makeLedger();
        panel.setLedger(ledger);
        QCOMPARE(panel.visibleRowCount(), 5);
        QCOMPARE(panel.summaryText(), LedgerTableModel::summary(*ledger));
        // "All kinds" and the 3 kinds present, with their counts.
        QCOMPARE(panel.kindCombo()->count(), 4);
        QCOMPARE(panel.kindCombo()->itemText(1), QStringLiteral("Corner merge (2)"));

        QSignalSpy selected(&panel, &LedgerPanel::recordSelected);
        panel.kindCombo()->setCurrentIndex(panel.kindCombo()->findData(int(LedgerKind::LineLost)));
        QCOMPARE(panel.visibleRowCount(), 2);
        panel.selectRow(1);
        QVERIFY(!selected.isEmpty());
        QCOMPARE(selected.last().first().toInt(), 4); // the second line lost is record 4
        panel.selectRow(-1);
        QCOMPARE(selected.last().first().toInt(), -1);

        panel.setKindFilter(LedgerKind::DegenerateContactTriangle);
        QCOMPARE(panel.visibleRowCount(), 1);
        QCOMPARE(
            panel.tableView()->model()->index(0, LedgerTableModel::KindColumn).data().toString(),
            QStringLiteral("Degenerate contact triangle"));
        panel.setKindFilter(LedgerKind::SurfaceLost); // absent: nothing to show
        QCOMPARE(panel.visibleRowCount(), 0);
        panel.setKindFilter(std::nullopt);
        QCOMPARE(panel.visibleRowCount(), 5);

        panel.setLedger(std::make_shared<const SimplificationLedger>());
        QCOMPARE(panel.visibleRowCount(), 0);
        QCOMPARE(panel.summaryText(), QStringLiteral("No simplification"));
        QCOMPARE(panel.kindCombo()->count(), 1);
    }
};

QTEST_MAIN(TestLedgerTableModel)
#include "test_ledger_table_model.moc"
