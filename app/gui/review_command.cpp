#include "review_command.h"

#include "remesh_workflow.h"

namespace stratamesh {

ReviewCommand::ReviewCommand(RemeshWorkflow &workflow, int record, const ReviewDecision &before,
                             const ReviewDecision &after)
    : QUndoCommand(describe(record, before, after)), m_workflow(workflow),
      m_ledger(workflow.outcome() ? workflow.outcome()->ledger : nullptr), m_record(record),
      m_before(before), m_after(after)
{
}

void ReviewCommand::redo()
{
    apply(m_after);
}

void ReviewCommand::undo()
{
    apply(m_before);
}

void ReviewCommand::apply(const ReviewDecision &decision)
{
    const std::shared_ptr<const SimplificationLedger> ledger = m_ledger.lock();
    if (!ledger || !m_workflow.outcome() || m_workflow.outcome()->ledger != ledger) {
        setObsolete(true);
        return;
    }
    ReviewDecisions decisions = m_workflow.decisions();
    decisions.setDecision(m_record, decision);
    m_workflow.setDecisions(decisions);
}

QString ReviewCommand::describe(int record, const ReviewDecision &before,
                                const ReviewDecision &after)
{
    // The record's index, as the table's # column and the exported CSV show it.
    const int shown = record;
    if (before.verdict == after.verdict)
        return tr("Note on record %1").arg(shown);
    switch (after.verdict) {
    case ReviewVerdict::Accepted:
        return tr("Accept record %1").arg(shown);
    case ReviewVerdict::Flagged:
        return tr("Flag record %1").arg(shown);
    case ReviewVerdict::Open:
        break;
    }
    return tr("Reopen record %1").arg(shown);
}

} // namespace stratamesh
