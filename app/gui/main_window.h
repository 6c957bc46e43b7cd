// The main window only assembles: the input and output views, the menus and the tool bar from the
// workflows' actions, their docks around the views, the message dock, and the status bar with the
// one progress strip. What each step does (open, study, remesh, complexity, tetmesh, hybrid) is its
// Workflow's; what they share is the Workbench.
#pragma once

#include <QList>
#include <QMainWindow>

#include <memory>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QToolBar;

namespace stratamesh {

class ComplexityWorkflow;
class HybridWorkflow;
class FeatureLegend;
class MessagePanel;
class ModelScene;
class ModelTreeWorkflow;
class OpenWorkflow;
class ProgressStrip;
class ProjectWorkflow;
class RecentFiles;
class RemeshWorkflow;
class StepsWorkflow;
class StudyWorkflow;
class TetmeshWorkflow;
class ViewWorkflow;
class ExaggerationWorkflow;
class ViewPair;
class VtkViewWidget;
class Workbench;
class Workflow;
struct LoadedModel;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    VtkViewWidget *view() const;
    VtkViewWidget *outputView() const;
    ModelScene *scene() const;
    ModelScene *outputScene() const;
    FeatureLegend *legend() const;
    MessagePanel *messagePanel() const { return m_messages; }
    ProgressStrip *progressStrip() const { return m_strip; }
    QAction *showBoxAction() const { return m_showBox; }
    QAction *showEdgesAction() const { return m_showEdges; }
    QAction *linkCamerasAction() const { return m_linkCameras; }
    QString statusCounts() const;
    Workbench *workbench() const { return m_bench.get(); }
    // What Help > About lists: the Mesh and Analyse actions, but the Cancels.
    QStringList offeredActions() const;

    OpenWorkflow *openWorkflow() const { return m_open; }
    StudyWorkflow *studyWorkflow() const { return m_study; }
    RemeshWorkflow *remeshWorkflow() const { return m_remesh; }
    ComplexityWorkflow *complexityWorkflow() const { return m_complexity; }
    TetmeshWorkflow *tetmeshWorkflow() const { return m_tetmesh; }
    HybridWorkflow *hybridWorkflow() const { return m_hybrid; }
    ProjectWorkflow *projectWorkflow() const { return m_project; }
    ViewWorkflow *viewWorkflow() const { return m_view; }
    ExaggerationWorkflow *exaggerationWorkflow() const { return m_exaggeration; }
    ModelTreeWorkflow *modelTreeWorkflow() const { return m_tree; }
    StepsWorkflow *stepsWorkflow() const { return m_steps; }
    RecentFiles *recentFiles() const { return m_recent; }

    // Bumped when the docks change so that an older saved layout is not applied.
    static constexpr int kStateVersion = 1;
    // The window's size and docks as the settings keep them (app_settings.h); the constructor
    // restores them, closing the window saves them.
    void saveLayout() const;
    bool restoreLayout();

public slots:
    // A model, or a project (.smproj).
    void openFile(const QString &path);
    void openSample();
    // What the window opens on without a file: the bundled sample as a project (sample.smproj in
    // the user's data folder). The first time, the sample model is remeshed once at 300 sites and
    // saved there, so that Runs, Review and Input vs Output have a result to show; afterwards the
    // project is read back without remeshing, with what the user saved in it.
    void openSampleProject();
    static QString sampleProjectPath();
    void setBoxVisible(bool visible);
    void setEdgesVisible(bool visible);
    void resetCamera();

protected:
    void changeEvent(QEvent *event) override;
    void closeEvent(QCloseEvent *event) override;
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    template <class W>
    W *add(W *workflow);
    void createActions();
    void createMenus();
    // "PROJECT.smproj (model)" while a project is open, else the model's name.
    void updateTitle();
    void placeDocks();
    void retranslate();
    void showModel(const LoadedModel &loaded);
    void updateBusy();
    void updateCounts();

    ViewPair *m_views;
    MessagePanel *m_messages;
    QDockWidget *m_messageDock;
    ProgressStrip *m_strip;
    QLabel *m_countsLabel;
    std::unique_ptr<Workbench> m_bench;
    QList<Workflow *> m_workflows; // in menu order
    OpenWorkflow *m_open = nullptr;
    StudyWorkflow *m_study = nullptr;
    RemeshWorkflow *m_remesh = nullptr;
    ComplexityWorkflow *m_complexity = nullptr;
    TetmeshWorkflow *m_tetmesh = nullptr;
    HybridWorkflow *m_hybrid = nullptr;
    ProjectWorkflow *m_project = nullptr;
    ViewWorkflow *m_view = nullptr;
    ExaggerationWorkflow *m_exaggeration = nullptr;
    ModelTreeWorkflow *m_tree = nullptr;
    StepsWorkflow *m_steps = nullptr;
    RecentFiles *m_recent = nullptr;

    QAction *m_quit = nullptr;
    QAction *m_showBox = nullptr;
    QAction *m_showEdges = nullptr;
    QAction *m_resetCamera = nullptr;
    QAction *m_linkCameras = nullptr;
    QAction *m_about = nullptr;
    QAction *m_aboutQt = nullptr;
    QAction *m_undo = nullptr;
    QAction *m_redo = nullptr;
    QMenu *m_fileMenu = nullptr;
    QMenu *m_editMenu = nullptr;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_meshMenu = nullptr;
    QMenu *m_analyseMenu = nullptr;
    QMenu *m_helpMenu = nullptr;
    QToolBar *m_toolBar = nullptr;
};

} // namespace stratamesh
