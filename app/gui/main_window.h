// The main window only assembles: the 3D view with its legend, the message dock, menus,
// and the status bar. Loading is the OpenModelController's job.
#pragma once

#include "loaded_model.h"
#include "remesh_outcome.h"

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

class ComparisonTable;
class FeatureLegend;
class LedgerPanel;
class MessagePanel;
class ModelScene;
class OpenModelController;
class PositionMarker;
class RemeshController;
class VtkViewWidget;

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

public slots:
    void openFile(const QString &path);
    void openSample();
    void chooseFile();
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
    // Writes the remeshed model (.ml: Gocad Model3d, else TSurf); errors go to the messages.
    bool saveRemeshedModel(const QString &path);
    // Marks a ledger record in the output view and centres the camera on it (-1: no mark).
    void showLedgerRecord(int recordIndex);

signals:
    // After a load attempt has been shown (model displayed, or error listed).
    void loadFinished(bool ok);
    // After a remeshing has ended and its outcome (result, cancel or error) was shown.
    void remeshFinished(bool ok);

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

    VtkViewWidget *m_view = nullptr;
    std::unique_ptr<ModelScene> m_scene;
    FeatureLegend *m_legend = nullptr;
    MessagePanel *m_messages = nullptr;
    QDockWidget *m_messageDock = nullptr;
    OpenModelController *m_controller = nullptr;
    QString m_displayName;
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

    QAction *m_open = nullptr;
    QAction *m_openSample = nullptr;
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
