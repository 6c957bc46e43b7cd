// The Review tab: the remesh's ledger (LedgerPanel: kind filter, search, sorting) with each
// record's decision and note, driven from the keyboard — A accepts, F flags (again: reopens),
// N edits the note in place, J/K or Down/Up go to the next/previous record — and a count of the
// records reviewed. The panel only asks for decisions (decisionRequested); the workflow puts them
// on the undo stack and hands the new set back with setDecisions.
#pragma once

#include "review_decisions.h"

#include "remesh/simplification_ledger.h"

#include <QWidget>

#include <memory>

class QAction;
class QHBoxLayout;
class QLabel;
class QTableView;

namespace stratamesh {

class LedgerPanel;
class ReviewTableModel;

class ReviewPanel : public QWidget {
    Q_OBJECT
public:
    explicit ReviewPanel(QWidget *parent = nullptr);

    // nullptr clears the table.
    void setLedger(std::shared_ptr<const SimplificationLedger> ledger);
    void setDecisions(const ReviewDecisions &decisions);
    // A button for `action` (Export Review…) at the end of the panel's row of buttons.
    void addAction(QAction *action);

    // Index in the ledger of the selected record, -1 when none is.
    int currentRecord() const;
    // "37 of 174 reviewed".
    QString progressText() const;

    LedgerPanel *ledgerPanel() const { return m_ledger; }
    ReviewTableModel *reviewModel() const { return m_model; }
    QTableView *tableView() const;
    QAction *acceptAction() const { return m_accept; }
    QAction *flagAction() const { return m_flag; }
    QAction *noteAction() const { return m_note; }
    QAction *nextAction() const { return m_next; }
    QAction *previousAction() const { return m_previous; }

public slots:
    void acceptCurrent();
    void flagCurrent();
    // Opens the note editor on the selected record.
    void editNote();
    void selectNext();
    void selectPrevious();

signals:
    // The geologist's choice for one record; nothing changes until setDecisions.
    void decisionRequested(int record, const ReviewDecision &decision);
    // Index in the ledger of the selected record, -1 when nothing is selected.
    void recordSelected(int record);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void updateState();
    // Sets `verdict` on the selected record, or reopens it when it has that verdict already.
    void toggleVerdict(ReviewVerdict verdict);
    void step(int delta);

    ReviewTableModel *m_model;
    LedgerPanel *m_ledger;
    QLabel *m_progress;
    QHBoxLayout *m_buttons;
    QAction *m_accept;
    QAction *m_flag;
    QAction *m_note;
    QAction *m_previous;
    QAction *m_next;
};

} // namespace stratamesh
