// What the main window's workflows share: the input and output views with their scenes, the
// message dock, the status line, the open model, and whether any of them is running. A workflow
// reaches the window only through it, so one workflow is written without reading the others.
#pragma once

#include "loaded_model.h"

#include <QList>
#include <QMessageBox>
#include <QString>

#include <functional>
#include <memory>

class QAction;
class QDockWidget;
class QMainWindow;
class QUndoStack;

namespace stratamesh {

class FeatureLegend;
class MessagePanel;
class ModelScene;
class PositionMarker;
class ProgressStrip;
class ViewPair;
class VtkViewWidget;
class Workflow;
class WorkflowJob;

class Workbench {
public:
    Workbench(QMainWindow *window, ViewPair *views, MessagePanel *messages,
              QDockWidget *messageDock, ProgressStrip *strip);
    // The scenes' actors leave the renderers here: before the views go.
    ~Workbench();

    // Parent of the workflows' docks and dialogs.
    QMainWindow *window() const { return m_window; }
    ViewPair *views() const { return m_views; }
    VtkViewWidget *inputView() const;
    VtkViewWidget *outputView() const;
    ModelScene *inputScene() const { return m_inputScene.get(); }
    ModelScene *outputScene() const { return m_outputScene.get(); }
    FeatureLegend *legend() const { return m_legend; }
    MessagePanel *messages() const { return m_messages; }
    ProgressStrip *strip() const { return m_strip; }
    // Edit > Undo/Redo: what the user chose to look at and decided (run shown, visibility,
    // colouring, review decisions), never the engine's results. Cleared with a new model.
    QUndoStack *undoStack() const { return m_undo; }
    // View > Show Box (checkable): the window's menu and tool bar and the Model dock share it.
    QAction *showBoxAction() const { return m_showBox; }

    // The open model (nullptr before the first); its file is never overwritten by a save. The input
    // scene shows it, but while two runs are compared (ProjectWorkflow) it shows the first run.
    const std::shared_ptr<const Model> &model() const;
    const QString &displayName() const { return m_displayName; }
    const QString &modelPath() const { return m_modelPath; }
    const ModelCounts &counts() const { return m_counts; }
    void setModel(const LoadedModel &loaded);

    void addMessage(const Message &message);
    // Shows the message dock, in front of its tabs when `raise`: something there needs reading.
    void showMessages(bool raise = true);
    void setStatus(const QString &text);

    // Marks a place (a ledger record, a validity problem) in both views and flies the shared
    // camera to it. The marker is a small fraction of the model's diagonal whatever the record's
    // own size, so it never hides the model; `radius` > 0 asks for a larger one within that bound.
    void showPosition(const Vec3 &position, double radius = 0.0);
    void hidePosition();
    PositionMarker *inputMarker() const { return m_inputMarker.get(); }
    PositionMarker *outputMarker() const { return m_outputMarker.get(); }
    double diagonal() const;

    // View > Vertical Exaggeration: z stretched in both views (1 = true scale), the marker and
    // every scene with them; positions and bounds given to the views stay model coordinates.
    void setVerticalExaggeration(double factor);
    double verticalExaggeration() const;

    // Frames the input model; the output view shares the camera.
    void resetCamera();
    void render();
    // While tets are drawn in place of the surfaces, the surface legend would describe nothing
    // shown.
    void updateLegend();

    // Before the work shown is replaced (another model or project opened, the window closed): one
    // question lists every workflow's unsaved result, Save saves them all; false when the user
    // keeps them (Cancel, or a save that failed).
    bool mayDiscardWork();
    // Asks Save, Discard or Cancel; tests answer in place of the user.
    using Ask = std::function<QMessageBox::StandardButton(const QString &text)>;
    void setAsk(Ask ask) { m_ask = std::move(ask); }
    void addWorkflow(Workflow *workflow);

    // One long run at a time: every workflow's job is registered, and none starts while any runs.
    void addJob(WorkflowJob *job);
    bool isBusy() const;

private:
    QMainWindow *m_window;
    ViewPair *m_views;
    MessagePanel *m_messages;
    QDockWidget *m_messageDock;
    ProgressStrip *m_strip;
    QUndoStack *m_undo;
    QAction *m_showBox;
    FeatureLegend *m_legend;
    std::shared_ptr<const Model> m_model;
    std::unique_ptr<ModelScene> m_inputScene;
    std::unique_ptr<ModelScene> m_outputScene;
    std::unique_ptr<PositionMarker> m_inputMarker;
    std::unique_ptr<PositionMarker> m_outputMarker;
    QString m_displayName;
    QString m_modelPath;
    ModelCounts m_counts;
    QList<WorkflowJob *> m_jobs;
    QList<Workflow *> m_workflows;
    Ask m_ask;
};

} // namespace stratamesh
