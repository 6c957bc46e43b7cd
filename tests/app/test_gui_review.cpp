// The Review tab of the main window, end to end on the bundled sample remeshed at 300 sites: one
// table row per ledger record; keys decide (A accepts, F flags, N writes a note, J/K move and the
// views follow); "3 of N reviewed"; Edit > Undo and Redo restore decisions; the CSV export reads
// back with its quoting; sorting and searching keep decisions on their records; decisions set
// from outside (a project being loaded) show; a new remesh starts a new review.
#include "ledger_kind_filter.h"
#include "ledger_panel.h"
#include "main_window.h"
#include "open_workflow.h"
#include "position_marker.h"
#include "remesh_workflow.h"
#include "review_panel.h"
#include "review_table_model.h"
#include "translations.h"
#include "vtk_view_widget.h"
#include "window_screenshot.h"
#include "workbench.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QHeaderView>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTableView>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace stratamesh;

namespace {

constexpr int kTimeoutMs = 120000;
const QString kShots = QStringLiteral(STRATAMESH_SCREENSHOT_DIR);
// A comma and quotes: the CSV must quote the field and double the quotes.
const QString kNote = QStringLiteral("Fault \"F2\" moved 12 m, check the throw");

// RFC 4180 rows (quoted fields may hold commas, doubled quotes and line breaks).
QList<QStringList> parseCsv(const QString &text)
{
    QList<QStringList> rows;
    QStringList row;
    QString field;
    bool quoted = false;
    for (int i = 0; i < text.size(); ++i) {
        const QChar c = text[i];
        if (quoted) {
            if (c == QLatin1Char('"') && i + 1 < text.size() && text[i + 1] == QLatin1Char('"')) {
                field += c;
                ++i;
            } else if (c == QLatin1Char('"')) {
                quoted = false;
            } else {
                field += c;
            }
        } else if (c == QLatin1Char('"')) {
            quoted = true;
        } else if (c == QLatin1Char(',')) {
            row << field;
            field.clear();
        } else if (c == QLatin1Char('\r')) {
            continue;
        } else if (c == QLatin1Char('\n')) {
            row << field;
            rows << row;
            row.clear();
            field.clear();
        } else {
            field += c;
        }
    }
    if (!field.isEmpty() || !row.isEmpty())
        rows << (row << field);
    return rows;
}

} // namespace

class TestGuiReview : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QLocale::setDefault(QLocale::c());
        QDir().mkpath(kShots);
        m_window = std::make_unique<MainWindow>();
        m_window->resize(1400, 900);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        // Keys go to the focus widget, and only an active window has one.
        m_window->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
        m_window->workbench()->setAsk([](const QString &) { return QMessageBox::Discard; });
        QSignalSpy loaded(m_window->openWorkflow(), &OpenWorkflow::finished);
        m_window->openSample();
        QVERIFY(loaded.wait(kTimeoutMs));
        QVERIFY(loaded.first().first().toBool());
        QVERIFY(remesh());
        m_workflow = m_window->remeshWorkflow();
        m_panel = m_workflow->reviewPanel();
        m_table = m_panel->tableView();
        m_undo = m_window->workbench()->undoStack();
        m_records = int(m_workflow->outcome()->ledger->size());
        qInfo("%d ledger records", m_records);
        QVERIFY2(m_records >= 5, "the review needs a few records to decide on");
    }

    void cleanupTestCase() { m_window.reset(); }

    void tableHoldsTheLedger()
    {
        auto *dock = qobject_cast<QDockWidget *>(m_panel->parentWidget());
        QVERIFY(dock);
        QCOMPARE(dock->windowTitle(), QStringLiteral("Review"));
        QVERIFY(dock->isVisible());
        QCOMPARE(m_panel->reviewModel()->rowCount(), m_records);
        QCOMPARE(m_table->model()->rowCount(), m_records);
        QCOMPARE(m_table->model()->columnCount(), int(ReviewTableModel::ReviewColumnCount));
        QCOMPARE(m_panel->progressText(), QStringLiteral("0 of %1 reviewed").arg(m_records));
        QVERIFY(m_workflow->decisions().isEmpty());
        QVERIFY(m_workflow->exportReviewAction()->isEnabled());
        QMenu *fileMenu = nullptr;
        for (QAction *a : m_window->menuBar()->actions())
            if (a->menu() && a->menu()->actions().contains(m_workflow->exportReviewAction()))
                fileMenu = a->menu();
        QVERIFY2(fileMenu, "Export Review as CSV is in a menu");
        QCOMPARE(fileMenu->title(), QStringLiteral("&File"));
        QVERIFY(m_panel->acceptAction()->toolTip().contains(QStringLiteral("(A")));
        QVERIFY(m_panel->flagAction()->toolTip().contains(QStringLiteral("(F")));
        QVERIFY(m_panel->noteAction()->toolTip().contains(QStringLiteral("(N")));
        QVERIFY(m_panel->nextAction()->toolTip().contains(QStringLiteral("J or Down")));
        QVERIFY(m_panel->previousAction()->toolTip().contains(QStringLiteral("K or Up")));
        // Nothing selected: nothing to decide on.
        QCOMPARE(m_panel->currentRecord(), -1);
        QVERIFY(!m_panel->acceptAction()->isEnabled());
    }

    void keysDecideAndTheViewsFollow()
    {
        m_table->setFocus();
        const int undoBefore = m_undo->count();
        QTest::keyClick(m_table, Qt::Key_J); // nothing selected: the first record
        QCOMPARE(m_panel->currentRecord(), 0);
        QVERIFY(m_workflow->marker()->isVisible());
        QVERIFY(m_window->workbench()->inputMarker()->isVisible());
        QVERIFY(
            (m_workflow->marker()->position() - (*m_workflow->outcome()->ledger)[0].position).norm()
            < 1e-9);
        QTest::keyClick(m_table, Qt::Key_A);
        QTest::keyClick(m_table, Qt::Key_Down);
        QCOMPARE(m_panel->currentRecord(), 1);
        QVERIFY(
            (m_workflow->marker()->position() - (*m_workflow->outcome()->ledger)[1].position).norm()
            < 1e-9);
        QTest::keyClick(m_table, Qt::Key_A);
        QTest::keyClick(m_table, Qt::Key_J);
        QCOMPARE(m_panel->currentRecord(), 2);
        QTest::keyClick(m_table, Qt::Key_N);
        QLineEdit *editor = nullptr;
        for (QLineEdit *e : m_table->viewport()->findChildren<QLineEdit *>())
            if (e->isVisible())
                editor = e;
        QVERIFY2(editor, "N opens the note editor");
        QCOMPARE(QApplication::focusWidget(), editor);
        QTest::keyClicks(editor, kNote);
        QTest::keyClick(editor, Qt::Key_Return);
        // The delegate commits on the next turn of the event loop.
        QTRY_COMPARE(m_workflow->decisions().decision(2).note, kNote);
        QCOMPARE(m_workflow->decisions().decision(2).verdict, ReviewVerdict::Open);
        QCOMPARE(QApplication::focusWidget(), m_table); // back to the table for the next key
        QTest::keyClick(m_table, Qt::Key_F);

        const ReviewDecisions &d = m_workflow->decisions();
        QCOMPARE(d.decision(0).verdict, ReviewVerdict::Accepted);
        QCOMPARE(d.decision(1).verdict, ReviewVerdict::Accepted);
        QCOMPARE(d.decision(2).verdict, ReviewVerdict::Flagged);
        QCOMPARE(d.decision(2).note, kNote);
        QCOMPARE(d.decision(3).verdict, ReviewVerdict::Open);
        QCOMPARE(d.reviewedCount(), 3);
        QCOMPARE(m_panel->progressText(), QStringLiteral("3 of %1 reviewed").arg(m_records));
        QCOMPARE(cell(2, ReviewTableModel::DecisionColumn), QStringLiteral("Flagged"));
        QCOMPARE(cell(2, ReviewTableModel::ReviewNoteColumn), kNote);
        QCOMPARE(cell(0, ReviewTableModel::DecisionColumn), QStringLiteral("Accepted"));
        QCOMPARE(cell(3, ReviewTableModel::DecisionColumn), QStringLiteral("Open"));
        QCOMPARE(m_undo->count(), undoBefore + 4); // accept, accept, note, flag

        // K goes back; letters never start the table's type-ahead search.
        QTest::keyClick(m_table, Qt::Key_K);
        QCOMPARE(m_panel->currentRecord(), 1);
        QTest::keyClick(m_table, Qt::Key_J);
        QCOMPARE(m_panel->currentRecord(), 2);
    }

    void undoAndRedoRestoreDecisions()
    {
        QCOMPARE(m_undo->undoText(), QStringLiteral("Flag record 2"));
        m_undo->undo();
        QCOMPARE(m_workflow->decisions().decision(2).verdict, ReviewVerdict::Open);
        QCOMPARE(m_workflow->decisions().decision(2).note, kNote); // the note was its own step
        QCOMPARE(m_workflow->decisions().reviewedCount(), 2);
        QCOMPARE(m_panel->progressText(), QStringLiteral("2 of %1 reviewed").arg(m_records));
        QCOMPARE(cell(2, ReviewTableModel::DecisionColumn), QStringLiteral("Open"));
        m_undo->undo();
        QCOMPARE(m_workflow->decisions().decision(2).note, QString());
        QCOMPARE(cell(2, ReviewTableModel::ReviewNoteColumn), QString());
        m_undo->redo();
        m_undo->redo();
        QCOMPARE(m_workflow->decisions().decision(2).verdict, ReviewVerdict::Flagged);
        QCOMPARE(m_workflow->decisions().decision(2).note, kNote);
        QCOMPARE(m_panel->progressText(), QStringLiteral("3 of %1 reviewed").arg(m_records));
        QVERIFY(!m_undo->canRedo());
        // The Edit menu's action is the stack's.
        QAction *undo = nullptr;
        for (QAction *a : m_window->findChildren<QAction *>())
            if (a->shortcut() == QKeySequence(QKeySequence::Undo))
                undo = a;
        QVERIFY(undo);
        undo->trigger();
        QCOMPARE(m_workflow->decisions().reviewedCount(), 2);
        m_undo->redo();
        QCOMPARE(m_workflow->decisions().reviewedCount(), 3);
    }

    void screenshot()
    {
        QTest::qWait(300);
        QVERIFY(saveWindowScreenshot(m_window.get(), kShots + "/review_tab.png"));
    }

    void exportedCsvReadsBack()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("review.csv"));
        QVERIFY(m_workflow->exportReview(path));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
                 QStringList{QStringLiteral("review.csv")}); // no temporary left
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(file.readAll());
        QVERIFY(text.contains(QStringLiteral("\"Fault \"\"F2\"\" moved 12 m, check the throw\"")));
        const QList<QStringList> rows = parseCsv(text);
        QCOMPARE(rows.size(), m_records + 1);
        const QStringList header = rows.first();
        QCOMPARE(header, QStringLiteral("record,kind,inputs,outputs,x,y,z,size,size_meaning,"
                                        "verdict,note")
                             .split(QLatin1Char(',')));
        const auto &ledger = *m_workflow->outcome()->ledger;
        for (int r = 0; r < m_records; ++r) {
            const QStringList &row = rows[r + 1];
            QCOMPARE(row.size(), header.size());
            QCOMPARE(row[0].toInt(), r);
            QCOMPARE(row[1], QString::fromStdString(ledgerKindName(ledger[std::size_t(r)].kind)));
            QCOMPARE(row[4].toDouble(), ledger[std::size_t(r)].position.x());
            QCOMPARE(row[7].toDouble(), ledger[std::size_t(r)].size);
            const QString verdict = r < 2    ? QStringLiteral("accepted")
                                    : r == 2 ? QStringLiteral("flagged")
                                             : QStringLiteral("open");
            QCOMPARE(row[9], verdict);
            QCOMPARE(row[10], r == 2 ? kNote : QString());
        }
        // A folder that does not exist: an error naming the file, no crash, no file.
        const QString bad = dir.filePath(QStringLiteral("missing/review.csv"));
        QVERIFY(!m_workflow->exportReview(bad));
        QVERIFY(!QFile::exists(bad));
    }

    void sortingKeepsDecisionsOnTheirRecords()
    {
        // Flagged records first: record 2 tops the table.
        m_table->sortByColumn(ReviewTableModel::DecisionColumn, Qt::DescendingOrder);
        QCOMPARE(viewCell(0, ReviewTableModel::RecordColumn).toInt(), 2);
        QCOMPARE(viewCell(0, ReviewTableModel::DecisionColumn), QStringLiteral("Flagged"));
        QCOMPARE(viewCell(0, ReviewTableModel::ReviewNoteColumn), kNote);
        QCOMPARE(viewCell(1, ReviewTableModel::DecisionColumn), QStringLiteral("Accepted"));
        // A decision on view row 0 goes to record 2, not to the ledger's first record.
        m_workflow->ledgerPanel()->selectRow(0);
        QCOMPARE(m_panel->currentRecord(), 2);
        m_table->setFocus();
        QTest::keyClick(m_table, Qt::Key_A);
        QCOMPARE(m_workflow->decisions().decision(2).verdict, ReviewVerdict::Accepted);
        QCOMPARE(m_workflow->decisions().decision(2).note, kNote);
        QCOMPARE(m_workflow->decisions().decision(0).verdict, ReviewVerdict::Accepted);
        QCOMPARE(m_panel->currentRecord(), 2); // the selection follows its record when it moves
        m_undo->undo();
        QCOMPARE(m_workflow->decisions().decision(2).verdict, ReviewVerdict::Flagged);

        // Sizes sort as numbers, and every row still shows its own record's decision.
        m_table->sortByColumn(LedgerTableModel::SizeColumn, Qt::AscendingOrder);
        const auto &ledger = *m_workflow->outcome()->ledger;
        double last = -1e300;
        for (int row = 0; row < m_records; ++row) {
            const int record = viewCell(row, ReviewTableModel::RecordColumn).toInt();
            const double size = ledger[std::size_t(record)].size;
            QVERIFY(size >= last);
            last = size;
            QCOMPARE(
                viewCell(row, ReviewTableModel::DecisionColumn),
                ReviewTableModel::verdictText(m_workflow->decisions().decision(record).verdict));
        }
        // Back to the ledger order.
        m_table->sortByColumn(-1, Qt::AscendingOrder);
        QCOMPARE(viewCell(0, ReviewTableModel::RecordColumn).toInt(), 0);
        QCOMPARE(viewCell(m_records - 1, ReviewTableModel::RecordColumn).toInt(), m_records - 1);
    }

    void searchFindsNotesAndKinds()
    {
        LedgerPanel *ledger = m_workflow->ledgerPanel();
        ledger->setSearchText(QStringLiteral("THROW"));
        QCOMPARE(ledger->visibleRowCount(), 1);
        QCOMPARE(viewCell(0, ReviewTableModel::RecordColumn).toInt(), 2);
        const QString kind = cell(0, LedgerTableModel::KindColumn);
        ledger->setSearchText(kind);
        int ofKind = 0;
        for (int r = 0; r < m_records; ++r)
            ofKind += cell(r, LedgerTableModel::KindColumn) == kind;
        QVERIFY(ledger->visibleRowCount() >= ofKind);
        ledger->setSearchText(QStringLiteral("no record says this"));
        QCOMPARE(ledger->visibleRowCount(), 0);
        QVERIFY(!m_panel->acceptAction()->isEnabled());
        ledger->setSearchText(QString());
        QCOMPARE(ledger->visibleRowCount(), m_records);
    }

    void frenchTexts()
    {
        installTranslations(QStringLiteral("fr"));
        auto *dock = qobject_cast<QDockWidget *>(m_panel->parentWidget());
        // The language change reaches the window through the event loop.
        QTRY_COMPARE(dock->windowTitle(), QStringLiteral("Contrôle"));
        QCOMPARE(m_panel->progressText(), QStringLiteral("3 sur %1 examinés").arg(m_records));
        QCOMPARE(cell(2, ReviewTableModel::DecisionColumn), QStringLiteral("Signalée"));
        QCOMPARE(
            m_panel->reviewModel()->headerData(ReviewTableModel::DecisionColumn, Qt::Horizontal),
            QStringLiteral("Décision"));
        QVERIFY(m_panel->acceptAction()->toolTip().contains(QStringLiteral("(A ;")));
        dock->raise(); // the failed export above raised Messages
        QTest::qWait(200);
        QVERIFY(saveWindowScreenshot(m_window.get(), kShots + "/review_tab_fr.png"));
        installTranslations(QStringLiteral("en"));
        QLocale::setDefault(QLocale::c());
        QTRY_COMPARE(dock->windowTitle(), QStringLiteral("Review"));
        QCOMPARE(m_panel->progressText(), QStringLiteral("3 of %1 reviewed").arg(m_records));
    }

    // A project file being loaded sets the decisions at once: the table and the count follow.
    void decisionsSetFromOutsideShow()
    {
        ReviewDecisions loaded;
        loaded.setDecision(4, {ReviewVerdict::Flagged, QStringLiteral("from the project")});
        m_workflow->setDecisions(loaded);
        QCOMPARE(cell(4, ReviewTableModel::DecisionColumn), QStringLiteral("Flagged"));
        QCOMPARE(cell(4, ReviewTableModel::ReviewNoteColumn), QStringLiteral("from the project"));
        QCOMPARE(cell(0, ReviewTableModel::DecisionColumn), QStringLiteral("Open"));
        QCOMPARE(m_panel->progressText(), QStringLiteral("1 of %1 reviewed").arg(m_records));
    }

    // The records of the next remesh are other records: its review starts empty, and undoing a
    // decision made on the last one changes nothing.
    void newRemeshStartsANewReview()
    {
        m_workflow->ledgerPanel()->selectRow(0);
        m_panel->acceptCurrent();
        QCOMPARE(m_workflow->decisions().reviewedCount(), 2);
        // Accepting an accepted record reopens it.
        m_panel->acceptCurrent();
        QCOMPARE(m_workflow->decisions().decision(0).verdict, ReviewVerdict::Open);
        QCOMPARE(m_undo->undoText(), QStringLiteral("Reopen record 0"));
        m_panel->acceptCurrent();
        QCOMPARE(m_workflow->decisions().reviewedCount(), 2);
        QVERIFY(remesh(400));
        QVERIFY(m_workflow->decisions().isEmpty());
        QCOMPARE(m_panel->reviewModel()->rowCount(), int(m_workflow->outcome()->ledger->size()));
        QCOMPARE(m_panel->progressText(),
                 QStringLiteral("0 of %1 reviewed").arg(m_workflow->outcome()->ledger->size()));
        while (m_undo->canUndo())
            m_undo->undo();
        QVERIFY(m_workflow->decisions().isEmpty());
    }

private:
    bool remesh(int sites = 300)
    {
        RemeshParams params;
        params.sites = sites;
        params.iterations = 20;
        QSignalSpy finished(m_window->remeshWorkflow(), &RemeshWorkflow::finished);
        return m_window->remeshWorkflow()->start(params) && finished.wait(kTimeoutMs)
               && finished.first().first().toBool();
    }

    // The text of a record's cell, whatever the view's order.
    QString cell(int record, int column) const
    {
        return m_panel->reviewModel()->index(record, column).data().toString();
    }

    QString viewCell(int row, int column) const
    {
        return m_table->model()->index(row, column).data().toString();
    }

    std::unique_ptr<MainWindow> m_window;
    RemeshWorkflow *m_workflow = nullptr;
    ReviewPanel *m_panel = nullptr;
    QTableView *m_table = nullptr;
    QUndoStack *m_undo = nullptr;
    int m_records = 0;
};

int main(int argc, char **argv)
{
    QSurfaceFormat::setDefaultFormat(VtkViewWidget::defaultFormat());
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("StrataMeshTest"));
    installTranslations(QStringLiteral("en"));
    TestGuiReview test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_gui_review.moc"
