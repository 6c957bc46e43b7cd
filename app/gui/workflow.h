// One step of the work on a model (open, remesh, complexity, tetmesh, …): its actions, its docks,
// its run on a WorkflowJob and what the run leaves to review. MainWindow places the actions in its
// menus and tool bar and the docks around the views, points the shared progress strip at the job
// running, and tells every workflow when a model is opened or the language changes.
#pragma once

#include <QList>
#include <QObject>

class QAction;
class QDockWidget;

namespace stratamesh {

struct Message;
class Workbench;
class WorkflowJob;

class Workflow : public QObject {
    Q_OBJECT
public:
    enum class Menu { File, Edit, View, Mesh, Analyse };
    // Below the views tabbed with Messages; on the right tabbed with the other reviews of a
    // result; on the right on its own; on the left (the model's tree).
    enum class DockPlace { WithMessages, Review, Side, Left };
    struct Dock {
        QDockWidget *dock;
        DockPlace place;
    };

    explicit Workflow(Workbench &bench, QObject *parent = nullptr);
    ~Workflow() override;

    // In menu order; a separator is an action with isSeparator().
    virtual QList<QAction *> menuActions(Menu menu) const;
    virtual QList<QAction *> toolBarActions() const;
    // Placed hidden (but on the left): a workflow shows its docks once it has something in them.
    virtual QList<Dock> docks() const;
    // nullptr for a step without a background run.
    virtual WorkflowJob *job() const;
    // The strip's Cancel button while job() runs (nullptr: the run cannot be cancelled).
    virtual QAction *cancelAction() const;
    virtual void retranslate() = 0;
    // Another model was opened: what this step showed of the previous one goes.
    virtual void clear();
    // `busy`: some workflow runs, so none may start.
    virtual void enableActions(bool busy);

    bool isBusy() const;

    // A result made here that no file holds yet, as one sentence ("The remeshed model has not
    // been saved."); empty when there is none.
    virtual QString unsavedWork() const;
    // Saves it, asking where; false when it was not saved (the user cancelled, or an error).
    virtual bool saveUnsavedWork();

public slots:
    // Asks the run to stop; finished(false) follows once the worker has returned.
    void cancel();

signals:
    // A run started or ended (before finished()): the window re-enables the actions.
    void busyChanged();
    // A run has ended and its outcome (result, cancel or error) was shown.
    void finished(bool ok);

protected:
    // Relays job's start and end to busyChanged() and finished(); called once the workflow's own
    // handlers are connected, so finished() comes after the outcome is shown.
    void relay(WorkflowJob *job);
    // A run ended without a result: Cancel is disabled, the error (its place kept) goes to Messages
    // as `text` and the status line says `status`.
    void reportFailure(const Message &error, const QString &text, const QString &status);
    // A cancelled run is logged too, so the Messages tell the whole session.
    void reportCancel(const QString &text, const QString &status);
    // A separator for menuActions().
    QAction *separator();

    Workbench &m_bench;
};

} // namespace stratamesh
