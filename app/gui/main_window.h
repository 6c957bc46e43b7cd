// The main window only assembles: the 3D view with its legend, the message dock, menus,
// and the status bar. Loading is the OpenModelController's job.
#pragma once

#include "complexity_outcome.h"
#include "loaded_model.h"
#include "remesh_outcome.h"
#include "tetmesh_outcome.h"

#include <QMainWindow>

#include <memory>
#include <optional>

class QAction;
class QDockWidget;
class QLabel;
class QProgressBar;
class QSplitter;
class QToolBar;
class QToolButton;

namespace stratamesh {

class CellHeatMap;
class ComparisonTable;
class ComplexityController;
class ComplexityPanel;
class FeatureLegend;
class LedgerPanel;
class MessagePanel;
class ModelScene;
class OpenModelController;
class PositionMarker;
class RemeshController;
class TetMeshPair;
class TetmeshController;
class TetmeshPanel;
class VtkViewWidget;

class StudyWindow;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    VtkViewWidget *view() const { return m_view; }
    ModelScene *scene() const { return m_scene.get(); }
    MessagePanel *messagePanel() const { return m_messages; }
    FeatureLegend *legend() const { return m_legend; }
    OpenModelController *controller() const { return m_controller; }
    QAction *showBoxAction() const { return m_showBox; }
    QAction *showEdgesAction() const { return m_showEdges; }
    QString statusCounts() const;

    // Remeshing: the output beside the input (same camera), its ledger and comparison docks.
    VtkViewWidget *outputView() const { return m_outputView; }
    ModelScene *outputScene() const { return m_outputScene.get(); }
    PositionMarker *marker() const { return m_marker.get(); }
    RemeshController *remeshController() const { return m_remeshController; }
    LedgerPanel *ledgerPanel() const { return m_ledger; }
    ComparisonTable *comparisonTable() const { return m_comparison; }
    QAction *remeshAction() const { return m_remesh; }
    QAction *cancelRemeshAction() const { return m_cancelRemesh; }
    QAction *saveRemeshedAction() const { return m_saveRemeshed; }
    // The last remeshing shown, if any (cleared when another model is opened).
    const std::optional<RemeshOutcome> &remeshOutcome() const { return m_outcome; }

    // Complexity analysis (thesis ch. 3): the Complexity dock and the cells heat map in the view.
    ComplexityController *complexityController() const { return m_complexityController; }
    ComplexityPanel *complexityPanel() const { return m_complexityPanel; }
    CellHeatMap *heatMap() const { return m_heatMap.get(); }
    QAction *complexityAction() const { return m_complexity; }
    QAction *cancelComplexityAction() const { return m_cancelComplexity; }
    QAction *exportCellsAction() const { return m_exportCells; }
    // The last analysis shown, if any (cleared when another model is opened).
    const std::optional<ComplexityOutcome> &complexityOutcome() const
    {
        return m_complexityOutcome;
    }

    // TetGen comparison meshes (thesis §5.2): tets in both views, the Tetrahedra dock.
    TetmeshController *tetmeshController() const { return m_tetmeshController; }
    TetmeshPanel *tetmeshPanel() const { return m_tetmeshPanel; }
    TetMeshPair *tetScenes() const { return m_tetScenes.get(); }
    QAction *tetmeshAction() const { return m_tetmesh; }
    QAction *cancelTetmeshAction() const { return m_cancelTetmesh; }
    // The last meshes shown, if any (cleared by another model or another remesh).
    const std::optional<TetmeshOutcome> &tetmeshOutcome() const { return m_tetmeshOutcome; }

    // File > Open Study…: the gathered table of a study in its own window.
    StudyWindow *studyWindow() const { return m_studyWindow; }
    QAction *openStudyAction() const { return m_openStudy; }

public slots:
    void openFile(const QString &path);
    void openSample();
    void chooseFile();
    // A .smstudy or a gathered study.json; a message box says what is wrong with it.
    void openStudy(const QString &path);
    void chooseStudy();
    void setBoxVisible(bool visible);
    void setEdgesVisible(bool visible);
    void resetCamera();
    void showAbout();
    // Opens the parameter dialog, then remeshes the shown model.
    void remesh();
    // Remeshes the shown model with these parameters (no dialog); false when it cannot start.
    bool startRemesh(const RemeshParams &params);
    void cancelRemesh();
    void chooseRemeshedFile();
    // Writes the remeshed model (exportModel: format from the extension); errors go to messages.
    bool saveRemeshedModel(const QString &path);
    // Marks a ledger record in the output view and centres the camera on it (-1: no mark).
    void showLedgerRecord(int recordIndex);
    // Opens the parameter dialog, then measures the complexity of the shown model.
    void analyseComplexity();
    // Measures with these parameters (one number of cells, no dialog); false when it cannot start.
    bool startComplexity(const ComplexityParams &params);
    void cancelComplexity();
    void chooseCellsFile();
    // Writes the cells of the last analysis with their counts (.vtu); errors go to the messages.
    bool exportComplexityCells(const QString &path);
    void setHeatMapVisible(bool visible);
    void setHeatMapThreshold(int threshold);
    // Opens the TetGen dialog, then tetrahedralises the input and, by default, the remesh.
    void tetrahedralise();
    // With these switches, the remesh too when `withRemesh` and there is one; false when it
    // cannot start.
    bool startTetmesh(const TetgenParams &params, bool withRemesh);
    void cancelTetmesh();

signals:
    // After a load attempt has been shown (model displayed, or error listed).
    void loadFinished(bool ok);
    // After a remeshing has ended and its outcome (result, cancel or error) was shown.
    void remeshFinished(bool ok);
    // After a complexity analysis has ended and its outcome was shown.
    void complexityFinished(bool ok);
    // After a tetrahedralisation has ended and its outcome was shown.
    void tetmeshFinished(bool ok);

protected:
    void changeEvent(QEvent *event) override;
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    void createActions();
    void createMenus();
    void createDocks();
    void createStatusBar();
    void retranslate();
    void onLoadStarted(const QString &displayName);
    void onProgress(int percent, const QString &stage);
    void onLoaded(const LoadedModel &loaded);
    void onFailed(const Message &error);
    void updateCounts();
    void updateLegend();
    void createViews();
    void setBusy(bool busy);
    void clearRemeshOutcome();
    void onRemeshStarted();
    void onRemeshed(const RemeshOutcome &outcome);
    void onRemeshFailed(const Message &error);
    void onRemeshCancelled();
    void updateViewTitles();
    void createComplexityUi();
    void retranslateComplexity();
    void clearComplexityOutcome();
    void onComplexityStarted();
    void onComplexityDone(const ComplexityOutcome &outcome);
    void onComplexityFailed(const Message &error);
    void onComplexityCancelled();
    void endComplexityRun();
    void updateHeatMapCount();
    bool isWorking() const;
    void createTetmeshUi();
    void retranslateTetmesh();
    void clearTetmeshOutcome();
    void onTetmeshStarted();
    void onTetmeshed(const TetmeshOutcome &outcome);
    void onTetmeshFailed(const Message &error);
    void onTetmeshCancelled();
    void endTetmeshRun();
    void applyTetView();

    VtkViewWidget *m_view = nullptr;
    std::unique_ptr<ModelScene> m_scene;
    FeatureLegend *m_legend = nullptr;
    MessagePanel *m_messages = nullptr;
    QDockWidget *m_messageDock = nullptr;
    OpenModelController *m_controller = nullptr;
    QString m_displayName;
    QString m_modelPath; // the open model's file (empty for the sample): saves never replace it
    ModelCounts m_counts;

    QSplitter *m_splitter = nullptr;
    QLabel *m_inputTitle = nullptr;
    QLabel *m_outputTitle = nullptr;
    QWidget *m_outputPane = nullptr;
    VtkViewWidget *m_outputView = nullptr;
    std::unique_ptr<ModelScene> m_outputScene;
    std::unique_ptr<PositionMarker> m_marker;
    RemeshController *m_remeshController = nullptr;
    std::optional<RemeshOutcome> m_outcome;
    RemeshParams m_lastParams;
    LedgerPanel *m_ledger = nullptr;
    QDockWidget *m_ledgerDock = nullptr;
    ComparisonTable *m_comparison = nullptr;
    QDockWidget *m_comparisonDock = nullptr;
    QAction *m_remesh = nullptr;
    QAction *m_cancelRemesh = nullptr;
    QAction *m_saveRemeshed = nullptr;
    QMenu *m_meshMenu = nullptr;
    QToolButton *m_cancelButton = nullptr;

    ComplexityController *m_complexityController = nullptr;
    std::optional<ComplexityOutcome> m_complexityOutcome;
    ComplexityParams m_lastComplexityParams;
    std::unique_ptr<CellHeatMap> m_heatMap;
    ComplexityPanel *m_complexityPanel = nullptr;
    QDockWidget *m_complexityDock = nullptr;
    QAction *m_complexity = nullptr;
    QAction *m_cancelComplexity = nullptr;
    QAction *m_exportCells = nullptr;
    QMenu *m_analyseMenu = nullptr;

    TetmeshController *m_tetmeshController = nullptr;
    std::optional<TetmeshOutcome> m_tetmeshOutcome;
    std::optional<TetgenParams> m_lastTetmeshParams;
    std::unique_ptr<TetMeshPair> m_tetScenes;
    TetmeshPanel *m_tetmeshPanel = nullptr;
    QDockWidget *m_tetmeshDock = nullptr;
    QAction *m_tetmesh = nullptr;
    QAction *m_cancelTetmesh = nullptr;

    QAction *m_open = nullptr;
    QAction *m_openSample = nullptr;
    QAction *m_openStudy = nullptr;
    StudyWindow *m_studyWindow = nullptr;
    QAction *m_quit = nullptr;
    QAction *m_showBox = nullptr;
    QAction *m_showEdges = nullptr;
    QAction *m_resetCamera = nullptr;
    QAction *m_about = nullptr;
    QAction *m_aboutQt = nullptr;
    QMenu *m_fileMenu = nullptr;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_helpMenu = nullptr;
    QToolBar *m_toolBar = nullptr;

    QLabel *m_countsLabel = nullptr;
    QLabel *m_stageLabel = nullptr;
    QProgressBar *m_progress = nullptr;
};

} // namespace stratamesh
