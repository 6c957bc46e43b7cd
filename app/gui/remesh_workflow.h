// Mesh > Remesh…: the dialog, the run (RemeshController), and the result beside the input in the
// output view with its Review tab (the ledger, a decision and a note per record, undoable) and its
// Quality tab (input vs output); File > Save Remeshed Model As… and File > Export Review as CSV….
#pragma once

#include "remesh_outcome.h"
#include "review_decisions.h"
#include "workflow.h"

#include <memory>
#include <optional>

namespace stratamesh {

class ComparisonTable;
class LedgerPanel;
class PositionMarker;
class ReviewPanel;
class RemeshController;

class RemeshWorkflow : public Workflow {
    Q_OBJECT
public:
    explicit RemeshWorkflow(Workbench &bench, QObject *parent = nullptr);
    // A running remeshing is cancelled and its outcome dropped.
    ~RemeshWorkflow() override;

    RemeshController *controller() const { return m_controller; }
    // The last remeshing shown, if any (cleared when another model is opened).
    const std::optional<RemeshOutcome> &outcome() const { return m_outcome; }
    ReviewPanel *reviewPanel() const { return m_review; }
    // The review panel's ledger table (kind filter, search, sorting).
    LedgerPanel *ledgerPanel() const;
    ComparisonTable *comparisonTable() const { return m_comparison; }
    // The Quality tab: Table 4.2 and the histograms (the tets' too, once TetGen ran).
    QDockWidget *comparisonDock() const { return m_comparisonDock; }
    // The record's mark in the output view (Workbench marks the input view too).
    PositionMarker *marker() const;
    // The review of the shown outcome's ledger (empty for a new remesh).
    const ReviewDecisions &decisions() const { return m_decisions; }
    // Replaces every decision at once (a project being loaded, an undo); not undoable itself.
    void setDecisions(const ReviewDecisions &decisions);
    // Shows a run made earlier (a project's, or another of this session's) in place of the shown
    // one, with its review: no engine run, no message.
    void show(const RemeshOutcome &outcome, const ReviewDecisions &decisions);
    // "Input: <model>" and "Output: <sites>, <triangles>" over the views.
    void updateViewTitles();
    QAction *remeshAction() const { return m_remesh; }
    QAction *saveAction() const { return m_save; }
    QAction *exportReviewAction() const { return m_exportReview; }

    QList<QAction *> menuActions(Menu menu) const override;
    QList<QAction *> toolBarActions() const override;
    QList<Dock> docks() const override;
    WorkflowJob *job() const override;
    QAction *cancelAction() const override { return m_cancel; }
    void retranslate() override;
    void clear() override;
    void enableActions(bool busy) override;
    QString unsavedWork() const override;
    bool saveUnsavedWork() override;
    // The shown outcome was written whole by another step (a saved project, or File > Export… to a
    // format that keeps all of a model): opening another model or closing no longer asks to save
    // it.
    void markSaved() { m_saved = m_outcome.has_value(); }

public slots:
    // Opens the parameter dialog, then remeshes the shown model.
    void remesh();
    // Remeshes the shown model with these parameters (no dialog); false when it cannot start.
    bool start(const RemeshParams &params);
    // False when nothing was saved.
    bool chooseFile();
    // Writes the remeshed model (exportModel: format from the extension); errors go to messages.
    bool save(const QString &path);
    // Marks a ledger record in both views and flies the camera to it (-1: no mark).
    void showLedgerRecord(int recordIndex);
    // The geologist's decision on one record, as a command on the undo stack (nothing when it
    // changes nothing or the record is not in the shown ledger).
    void review(int record, const ReviewDecision &decision);
    // False when nothing was written.
    bool chooseReviewFile();
    // The review as CSV (review_csv.h); errors go to messages.
    bool exportReview(const QString &path);

signals:
    // A new remesh replaces the last, before it is shown: what was made of the last one goes.
    void outputReplaced();
    void decisionsChanged();
    // A remesh finished and was shown (after outputReplaced()): the run list keeps it.
    void runAdded(const stratamesh::RemeshOutcome &outcome);

private:
    void onStarted();
    void onRemeshed(const RemeshOutcome &outcome);
    void onFailed(const Message &error);
    void onCancelled();

    RemeshController *m_controller;
    std::optional<RemeshOutcome> m_outcome;
    RemeshParams m_lastParams;
    ReviewDecisions m_decisions;
    bool m_saved = false; // the shown outcome has been written to a file
    ReviewPanel *m_review;
    QDockWidget *m_ledgerDock;
    ComparisonTable *m_comparison;
    QDockWidget *m_comparisonDock;
    QAction *m_remesh;
    QAction *m_cancel;
    QAction *m_save;
    QAction *m_exportReview;
};

} // namespace stratamesh
