#include "main_window.h"

#include "about_dialog.h"
#include "feature_legend.h"
#include "message_panel.h"
#include "model_scene.h"
#include "open_model_controller.h"
#include "vtk_view_widget.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMimeData>
#include <QProgressBar>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>

namespace stratamesh {

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent), m_view(new VtkViewWidget(this)), m_controller(new OpenModelController(this))
{
    setObjectName(QStringLiteral("MainWindow"));
    setCentralWidget(m_view);
    m_scene = std::make_unique<ModelScene>(m_view->renderer());
    m_legend = new FeatureLegend(m_view);
    setAcceptDrops(true);

    createActions();
    createMenus();
    createDocks();
    createStatusBar();
    retranslate();

    connect(m_controller, &OpenModelController::started, this, &MainWindow::onLoadStarted);
    connect(m_controller, &OpenModelController::progressChanged, this, &MainWindow::onProgress);
    connect(m_controller, &OpenModelController::loaded, this, &MainWindow::onLoaded);
    connect(m_controller, &OpenModelController::failed, this, &MainWindow::onFailed);
    connect(m_controller, &OpenModelController::finished, this, &MainWindow::loadFinished);
    resize(1280, 800);
}

// The scene's actors must leave the renderer before the view goes.
MainWindow::~MainWindow() { m_scene.reset(); }

void MainWindow::createActions()
{
    m_open = new QAction(this);
    m_open->setShortcut(QKeySequence::Open);
    m_open->setIcon(QIcon::fromTheme(QStringLiteral("document-open"), style()->standardIcon(QStyle::SP_DialogOpenButton)));
    connect(m_open, &QAction::triggered, this, &MainWindow::chooseFile);

    m_openSample = new QAction(this);
    connect(m_openSample, &QAction::triggered, this, &MainWindow::openSample);

    m_quit = new QAction(this);
    m_quit->setShortcut(QKeySequence::Quit);
    m_quit->setMenuRole(QAction::QuitRole);
    connect(m_quit, &QAction::triggered, this, &QWidget::close);

    m_showBox = new QAction(this);
    m_showBox->setCheckable(true);
    m_showBox->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
    connect(m_showBox, &QAction::toggled, this, &MainWindow::setBoxVisible);

    m_showEdges = new QAction(this);
    m_showEdges->setCheckable(true);
    m_showEdges->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    connect(m_showEdges, &QAction::toggled, this, &MainWindow::setEdgesVisible);

    m_resetCamera = new QAction(this);
    m_resetCamera->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_0));
    connect(m_resetCamera, &QAction::triggered, this, &MainWindow::resetCamera);

    m_about = new QAction(this);
    m_about->setMenuRole(QAction::AboutRole);
    connect(m_about, &QAction::triggered, this, &MainWindow::showAbout);
    m_aboutQt = new QAction(this);
    m_aboutQt->setMenuRole(QAction::AboutQtRole);
    connect(m_aboutQt, &QAction::triggered, qApp, &QApplication::aboutQt);
}

void MainWindow::createMenus()
{
    m_fileMenu = menuBar()->addMenu(QString());
    m_fileMenu->addAction(m_open);
    m_fileMenu->addAction(m_openSample);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_quit);

    m_viewMenu = menuBar()->addMenu(QString());
    m_viewMenu->addAction(m_showBox);
    m_viewMenu->addAction(m_showEdges);
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_resetCamera);

    m_helpMenu = menuBar()->addMenu(QString());
    m_helpMenu->addAction(m_about);
    m_helpMenu->addAction(m_aboutQt);

    m_toolBar = addToolBar(QString());
    m_toolBar->setObjectName(QStringLiteral("MainToolBar"));
    m_toolBar->setMovable(false);
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_toolBar->addAction(m_open);
    m_toolBar->addSeparator();
    m_toolBar->addAction(m_showBox);
    m_toolBar->addAction(m_showEdges);
    m_toolBar->addAction(m_resetCamera);
}

void MainWindow::createDocks()
{
    m_messages = new MessagePanel(this);
    m_messageDock = new QDockWidget(this);
    m_messageDock->setObjectName(QStringLiteral("MessageDock"));
    m_messageDock->setWidget(m_messages);
    addDockWidget(Qt::BottomDockWidgetArea, m_messageDock);
    resizeDocks({m_messageDock}, {120}, Qt::Vertical);
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_messageDock->toggleViewAction());
}

void MainWindow::createStatusBar()
{
    m_stageLabel = new QLabel(this);
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 100);
    m_progress->setMaximumWidth(180);
    m_progress->setTextVisible(false);
    m_progress->hide();
    m_countsLabel = new QLabel(this);
    statusBar()->addWidget(m_stageLabel, 1);
    statusBar()->addPermanentWidget(m_progress);
    statusBar()->addPermanentWidget(m_countsLabel);
}

void MainWindow::retranslate()
{
    m_fileMenu->setTitle(tr("&File"));
    m_viewMenu->setTitle(tr("&View"));
    m_helpMenu->setTitle(tr("&Help"));
    m_open->setText(tr("&Open Model…"));
    m_open->setStatusTip(tr("Open a structural model file"));
    m_openSample->setText(tr("Open &Sample Model"));
    m_openSample->setStatusTip(tr("Show the synthetic model bundled with StrataMesh"));
    m_quit->setText(tr("&Quit"));
    m_showBox->setText(tr("Show &Box"));
    m_showBox->setStatusTip(tr("Show the surfaces of the model's bounding box"));
    m_showEdges->setText(tr("Show Triangle &Edges"));
    m_showEdges->setStatusTip(tr("Draw the edges of every surface triangle"));
    m_resetCamera->setText(tr("&Reset Camera"));
    m_resetCamera->setStatusTip(tr("Look at the whole model from the south-west"));
    m_about->setText(tr("&About StrataMesh"));
    m_aboutQt->setText(tr("About &Qt"));
    m_toolBar->setWindowTitle(tr("Main Toolbar"));
    m_messageDock->setWindowTitle(tr("Messages"));
    m_messageDock->toggleViewAction()->setText(tr("&Messages"));
    setWindowTitle(m_displayName.isEmpty() ? tr("StrataMesh")
                                           : tr("%1 — StrataMesh").arg(m_displayName));
    updateCounts();
}

void MainWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QMainWindow::changeEvent(event);
}

void MainWindow::openFile(const QString &path) { m_controller->openFile(path); }

void MainWindow::openSample() { m_controller->openSample(); }

void MainWindow::chooseFile()
{
    QSettings settings;
    const QString dir = settings.value(QStringLiteral("lastDirectory")).toString();
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open Model"), dir, OpenModelController::fileFilter());
    if (path.isEmpty())
        return;
    settings.setValue(QStringLiteral("lastDirectory"), QFileInfo(path).absolutePath());
    openFile(path);
}

void MainWindow::setBoxVisible(bool visible)
{
    if (m_showBox->isChecked() != visible)
        m_showBox->setChecked(visible); // comes back here through toggled()
    m_scene->setBoxVisible(visible);
    updateLegend();
    m_view->render();
}

void MainWindow::setEdgesVisible(bool visible)
{
    if (m_showEdges->isChecked() != visible)
        m_showEdges->setChecked(visible);
    m_scene->setEdgesVisible(visible);
    m_view->render();
}

void MainWindow::resetCamera()
{
    double bounds[6];
    if (m_scene->bounds(bounds))
        m_view->resetCamera(bounds);
    else
        m_view->resetCamera();
}

void MainWindow::showAbout() { showAboutDialog(this); }

void MainWindow::dragEnterEvent(QDragEnterEvent *event)
{
    if (event->mimeData()->hasUrls() && event->mimeData()->urls().size() == 1 &&
        event->mimeData()->urls().first().isLocalFile())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent *event)
{
    openFile(event->mimeData()->urls().first().toLocalFile());
    event->acceptProposedAction();
}

void MainWindow::onLoadStarted(const QString &displayName)
{
    m_open->setEnabled(false);
    m_openSample->setEnabled(false);
    m_stageLabel->setText(tr("Opening %1…").arg(displayName));
    m_progress->setValue(0);
    m_progress->show();
}

void MainWindow::onProgress(int percent, const QString &stage)
{
    m_progress->setValue(percent);
    if (!stage.isEmpty())
        m_stageLabel->setText(stage + QStringLiteral("…"));
}

void MainWindow::onLoaded(const LoadedModel &loaded)
{
    m_open->setEnabled(true);
    m_openSample->setEnabled(true);
    m_progress->hide();
    m_messages->clear();
    m_displayName = loaded.displayName;
    m_counts = loaded.counts;
    m_scene->setModel(loaded.model);
    updateLegend();
    resetCamera();

    Message opened;
    opened.text = tr("%1 opened in %2 s").arg(loaded.displayName, QLocale().toString(loaded.milliseconds / 1000.0, 'f', 2));
    opened.file = loaded.path;
    m_messages->addMessage(opened);
    for (const Message &m : loaded.messages)
        m_messages->addMessage(m);
    if (loaded.messages.empty()) {
        Message valid;
        valid.text = tr("No validity problem found");
        valid.file = loaded.path;
        m_messages->addMessage(valid);
    } else {
        m_messageDock->show();
    }
    m_stageLabel->setText(loaded.messages.empty()
                              ? tr("Ready")
                              : tr("%n validity problem(s) — see Messages", nullptr, int(loaded.messages.size())));
    retranslate();
}

void MainWindow::onFailed(const Message &error)
{
    m_open->setEnabled(true);
    m_openSample->setEnabled(true);
    m_progress->hide();
    m_messages->clear();
    m_messages->addMessage(error);
    m_messageDock->show();
    m_messageDock->raise();
    const QString where = formatLocation(error);
    m_stageLabel->setText(where.isEmpty() ? tr("Could not open the model") : tr("Could not open %1").arg(where));
}

QString MainWindow::statusCounts() const { return m_countsLabel ? m_countsLabel->text() : QString(); }

void MainWindow::updateCounts()
{
    const auto &model = m_scene->model();
    if (!model) {
        m_countsLabel->clear();
        return;
    }
    // Table 3.1 of the thesis counts entities without the box; the tooltip gives both.
    const auto describe = [](const EntityCounts &c) {
        const QString sep = QStringLiteral("  ·  ");
        return tr("%n region(s)", nullptr, c.regions) + sep + tr("%n surface(s)", nullptr, c.surfaces) + sep +
               tr("%n line(s)", nullptr, c.lines) + sep + tr("%n corner(s)", nullptr, c.corners);
    };
    const QString triangles = tr("%1 triangles").arg(QLocale().toString(qulonglong(model->triangleCount())));
    m_countsLabel->setText(tr("%1 (box excluded)  ·  %2").arg(describe(m_counts.withoutBox), triangles));
    m_countsLabel->setToolTip(tr("With the box: %1").arg(describe(m_counts.all)));
}

void MainWindow::updateLegend() { m_legend->setEntries(m_scene->legend(), m_scene->boxVisible()); }

} // namespace stratamesh
