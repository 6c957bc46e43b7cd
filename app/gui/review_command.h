// One review decision (accept, flag, reopen, note) on the undo stack: undo restores the record's
// previous verdict and note. A command made on an earlier remesh's ledger does nothing and drops
// out of the stack: its record numbers name other records now.
#pragma once

#include "review_decisions.h"

#include "remesh/simplification_ledger.h"

#include <QCoreApplication>
#include <QUndoCommand>

#include <memory>

namespace stratamesh {

class RemeshWorkflow;

class ReviewCommand : public QUndoCommand {
    Q_DECLARE_TR_FUNCTIONS(ReviewCommand)

public:
    ReviewCommand(RemeshWorkflow &workflow, int record, const ReviewDecision &before,
                  const ReviewDecision &after);

    void redo() override;
    void undo() override;

    // "Accept record 3", "Note on record 3"… (the Edit menu shows "Undo Accept record 3").
    static QString describe(int record, const ReviewDecision &before, const ReviewDecision &after);

private:
    void apply(const ReviewDecision &decision);

    RemeshWorkflow &m_workflow;
    std::weak_ptr<const SimplificationLedger> m_ledger;
    int m_record;
    ReviewDecision m_before;
    ReviewDecision m_after;
};

} // namespace stratamesh
