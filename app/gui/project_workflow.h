// File > Open Project…, Save Project, Save Project As…, and the Runs dock: every remesh run of the
// session is kept with its review; choosing a run shows it in the output view (an undoable
// command), and Compare… shows two runs side by side, the first in the input view; a project file
// (.smproj, app/project) keeps the runs, their results and reviews, and the run shown. Reopening
// reads the results back from the run folders: no remeshing.
#pragma once

#include "remesh_outcome.h"
#include "review_decisions.h"
#include "workflow.h"

#include <QJsonObject>

#include <functional>
#include <memory>
#include <vector>

namespace stratamesh {

class OpenWorkflow;
class RemeshWorkflow;
class RunsPanel;

class ProjectWorkflow : public Workflow {
    Q_OBJECT
public:
    ProjectWorkflow(Workbench &bench, OpenWorkflow &open, RemeshWorkflow &remesh,
                    QObject *parent = nullptr);
    ~ProjectWorkflow() override;

    struct Run {
        RemeshOutcome outcome;
        ReviewDecisions decisions;
        QJsonObject report; // as read from its folder; built at the first save for a new run
        QString savedIn;    // the project whose run folder holds it (not written again there)
        int id = 0;         // 1, 2, … as listed; kept from the project file it was read from
        QString folder;     // "run-001" in the project's runs folder
    };
    const std::vector<Run> &runs() const { return m_runs; }
    int shownRun() const { return m_shown; }
    // The run in the input view while two runs are compared; -1 when it shows the input model.
    int comparedRun() const { return m_compared; }
    // Empty until the runs were saved as or opened from a project.
    const QString &projectPath() const { return m_path; }
    bool isModified() const { return m_modified; }
    RunsPanel *runsPanel() const { return m_panel; }
    QDockWidget *runsDock() const { return m_dock; }
    QAction *openAction() const { return m_open; }
    QAction *saveAction() const { return m_save; }
    QAction *saveAsAction() const { return m_saveAs; }

    // Where the missing input model is now (empty: not found); a file dialog by default, tests
    // answer in its place.
    using Locate = std::function<QString(const QString &missing)>;
    void setLocate(Locate locate) { m_locate = std::move(locate); }

    QList<QAction *> menuActions(Menu menu) const override;
    QList<Dock> docks() const override;
    void retranslate() override;
    void clear() override;
    void enableActions(bool busy) override;
    QString unsavedWork() const override;
    bool saveUnsavedWork() override;

public slots:
    // Reads the project and its run folders, then opens its input model; projectOpened() follows
    // once it is shown. False (with a message) when it cannot start: the file or a run folder
    // cannot be read, the input was not located, or the user kept the work shown.
    bool openProject(const QString &path);
    void chooseProject();
    // Save Project: to the project's file, or asks where.
    bool save();
    bool saveAs();
    // Writes the project and its run folders at `path`; errors go to messages.
    bool saveProject(const QString &path);
    // Shows run `index` through an undoable command on the Workbench's undo stack.
    void chooseRun(int index);
    // Shows run `index` in the output view with its review (the command's redo and undo).
    void showRun(int index);
    // Run `first` in the input view and `second` in the output view, through an undoable command;
    // false when they are the same run or not both there.
    bool compareRuns(int first, int second);
    // The input model back in the input view (undoable), the run shown kept in the output.
    void chooseInput();
    // `input` -1: the input model; the commands' redo and undo.
    void showRuns(int input, int output);

signals:
    void projectOpened(bool ok);
    // The project's file changed: opened, saved elsewhere, or none once another model is open.
    void pathChanged(const QString &path);

private:
    struct Pending;
    void onRunAdded(const RemeshOutcome &outcome);
    void onDecisionsChanged();
    void onOpenFinished(bool ok);
    void install(Pending &pending);
    void setModified(bool modified);
    void updatePanel();
    void setInputRun(int index);
    void updateViewTitles();
    void updateComparison();
    void fail(const Message &message, const QString &status);

    OpenWorkflow &m_openWorkflow;
    RemeshWorkflow &m_remesh;
    std::vector<Run> m_runs;
    int m_shown = -1;
    int m_compared = -1;
    QString m_path;
    bool m_modified = false;
    bool m_applying = false; // showing a run: its decisions are not a change
    std::unique_ptr<Pending> m_pending;
    Locate m_locate;
    RunsPanel *m_panel;
    QDockWidget *m_dock;
    QAction *m_open;
    QAction *m_save;
    QAction *m_saveAs;
};

} // namespace stratamesh
