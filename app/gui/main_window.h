// The main window only assembles: the 3D view with its legend, the message dock, menus,
// and the status bar. Loading is the OpenModelController's job.
#pragma once

#include "loaded_model.h"

#include <QMainWindow>

#include <memory>

class QAction;
class QDockWidget;
class QLabel;
class QProgressBar;
class QToolBar;

namespace stratamesh {

class FeatureLegend;
class MessagePanel;
class ModelScene;
class OpenModelController;
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

public slots:
    void openFile(const QString &path);
    void openSample();
    void chooseFile();
    void setBoxVisible(bool visible);
    void setEdgesVisible(bool visible);
    void resetCamera();
    void showAbout();

signals:
    // After a load attempt has been shown (model displayed, or error listed).
    void loadFinished(bool ok);

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

    VtkViewWidget *m_view = nullptr;
    std::unique_ptr<ModelScene> m_scene;
    FeatureLegend *m_legend = nullptr;
    MessagePanel *m_messages = nullptr;
    QDockWidget *m_messageDock = nullptr;
    OpenModelController *m_controller = nullptr;
    QString m_displayName;
    ModelCounts m_counts;

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
