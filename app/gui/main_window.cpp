#include "main_window.h"

#include "about_dialog.h"
#include "app_settings.h"
#include "complexity_workflow.h"
#include "disabled_reason.h"
#include "exaggeration_workflow.h"
#include "export_workflow.h"
#include "hybrid_workflow.h"
#include "message_panel.h"
#include "model_scene.h"
#include "model_tree_workflow.h"
#include "open_workflow.h"
#include "progress_strip.h"
#include "project_file.h"
#include "project_workflow.h"
#include "recent_files.h"
#include "remesh_workflow.h"
#include "script_runner.h"
#include "steps_workflow.h"
#include "study_workflow.h"
#include "tetmesh_workflow.h"
#include "view_pair.h"
#include "view_workflow.h"
#include "workbench.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMimeData>
#include <QScrollArea>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoStack>

#include <utility>

namespace stratamesh {

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent), m_views(new ViewPair(this)), m_messages(new MessagePanel(this)),
      m_messageDock(new QDockWidget(this)), m_strip(new ProgressStrip(this)),
      m_countsLabel(new QLabel(this))
{
    setObjectName(QStringLiteral("MainWindow"));
    setCentralWidget(m_views);
    m_messageDock->setObjectName(QStringLiteral("MessageDock"));
    m_messageDock->setWidget(m_messages);
    addDockWidget(Qt::BottomDockWidgetArea, m_messageDock);
    resizeDocks({m_messageDock}, {120}, Qt::Vertical);
    statusBar()->addWidget(m_strip->stageLabel(), 1);
    statusBar()->addPermanentWidget(m_strip);
    statusBar()->addPermanentWidget(m_countsLabel);
    setAcceptDrops(true);

    m_bench = std::make_unique<Workbench>(this, m_views, m_messages, m_messageDock, m_strip);
    m_open = add(new OpenWorkflow(*m_bench, this));
    m_study = add(new StudyWorkflow(*m_bench, this));
    m_remesh = add(new RemeshWorkflow(*m_bench, this));
    m_complexity = add(new ComplexityWorkflow(*m_bench, this));
    m_tetmesh = add(new TetmeshWorkflow(*m_bench, *m_remesh, this));
    m_hybrid = add(new HybridWorkflow(*m_bench, *m_remesh, *m_tetmesh, this));
    auto *exporter = add(new ExportWorkflow(*m_bench, *m_remesh, *m_tetmesh, *m_hybrid, this));
    m_project = add(new ProjectWorkflow(*m_bench, *m_open, *m_remesh, this));
    m_view = add(new ViewWorkflow(*m_bench, *m_remesh, *m_tetmesh, *m_hybrid, this));
    m_exaggeration = add(new ExaggerationWorkflow(*m_bench, this));
    m_tree = add(new ModelTreeWorkflow(*m_bench, *m_open, *m_remesh, this));
    m_steps = add(new StepsWorkflow(*m_bench, *m_open, *m_complexity, *m_remesh, *m_tetmesh,
                                    *m_hybrid, *exporter, this));
    connect(m_open, &OpenWorkflow::opened, this, &MainWindow::showModel);
    m_recent = new RecentFiles(this);
    connect(m_recent, &RecentFiles::openRequested, this, &MainWindow::openFile);
    // A project opens its input model first: the project then comes above it.
    connect(m_open, &OpenWorkflow::opened, m_recent,
            [this](const LoadedModel &loaded) { m_recent->add(loaded.path); });
    connect(m_project, &ProjectWorkflow::pathChanged, this, &MainWindow::updateTitle);
    connect(m_project, &ProjectWorkflow::projectOpened, m_recent, [this](bool ok) {
        if (ok)
            m_recent->add(m_project->projectPath());
    });
    // The input view halves beside the output: the heat map's colour bar would be cut there,
    // and the cells were measured on the input only. The Complexity dock shows them again.
    connect(m_remesh, &RemeshWorkflow::outputReplaced, m_complexity,
            [this] { m_complexity->setHeatMapVisible(false); });

    createActions();
    createMenus();
    placeDocks();
    retranslate();
    resize(1280, 800);
    m_recent->refresh();
    restoreLayout();
}

// Running jobs stop, and the workflows' drawings and then the scenes leave the renderers, before
// the views go.
MainWindow::~MainWindow()
{
    while (!m_workflows.isEmpty())
        delete m_workflows.takeLast();
    m_bench.reset();
}

template <class W>
W *MainWindow::add(W *workflow)
{
    m_workflows.append(workflow);
    m_bench->addWorkflow(workflow);
    if (WorkflowJob *job = workflow->job())
        m_bench->addJob(job);
    connect(workflow, &Workflow::busyChanged, this, &MainWindow::updateBusy);
    return workflow;
}

VtkViewWidget *MainWindow::view() const
{
    return m_bench->inputView();
}

VtkViewWidget *MainWindow::outputView() const
{
    return m_bench->outputView();
}

ModelScene *MainWindow::scene() const
{
    return m_bench->inputScene();
}

ModelScene *MainWindow::outputScene() const
{
    return m_bench->outputScene();
}

FeatureLegend *MainWindow::legend() const
{
    return m_bench->legend();
}

void MainWindow::createActions()
{
    m_quit = new QAction(this);
    m_quit->setShortcut(QKeySequence::Quit);
    m_quit->setMenuRole(QAction::QuitRole);
    connect(m_quit, &QAction::triggered, this, &QWidget::close);

    m_showBox = m_bench->showBoxAction();
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
    m_linkCameras = new QAction(this);
    m_linkCameras->setCheckable(true);
    m_linkCameras->setChecked(true);
    connect(m_linkCameras, &QAction::toggled, this,
            [this](bool linked) { m_views->setCamerasLinked(linked); });

    m_about = new QAction(this);
    m_about->setMenuRole(QAction::AboutRole);
    connect(m_about, &QAction::triggered, this,
            [this] { showAboutDialog(this, offeredActions()); });
    m_undo = m_bench->undoStack()->createUndoAction(this);
    m_undo->setShortcut(QKeySequence::Undo);
    m_redo = m_bench->undoStack()->createRedoAction(this);
    m_redo->setShortcut(QKeySequence::Redo);
    setDisabledReason(m_undo, [] { return tr("nothing to undo"); });
    setDisabledReason(m_redo, [] { return tr("nothing to redo"); });

    m_aboutQt = new QAction(this);
    m_aboutQt->setMenuRole(QAction::AboutQtRole);
    connect(m_aboutQt, &QAction::triggered, qApp, &QApplication::aboutQt);
}

void MainWindow::createMenus()
{
    const auto fill = [this](QMenu *menu, Workflow::Menu which) {
        for (const Workflow *workflow : std::as_const(m_workflows))
            menu->addActions(workflow->menuActions(which));
    };
    m_fileMenu = menuBar()->addMenu(QString());
    fill(m_fileMenu, Workflow::Menu::File);
    // Open Recent below the Open actions.
    const QList<QAction *> fileActions = m_fileMenu->actions();
    const qsizetype sample = fileActions.indexOf(m_open->openSampleAction());
    m_fileMenu->insertMenu(sample + 1 < fileActions.size() ? fileActions[sample + 1] : nullptr,
                           m_recent->menu());
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_quit);

    m_editMenu = menuBar()->addMenu(QString());
    m_editMenu->addAction(m_undo);
    m_editMenu->addAction(m_redo);
    fill(m_editMenu, Workflow::Menu::Edit);

    m_viewMenu = menuBar()->addMenu(QString());
    fill(m_viewMenu, Workflow::Menu::View);
    m_viewMenu->addAction(m_showBox);
    m_viewMenu->addAction(m_showEdges);
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_resetCamera);
    m_viewMenu->addAction(m_linkCameras);
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_messageDock->toggleViewAction());

    m_meshMenu = menuBar()->addMenu(QString());
    fill(m_meshMenu, Workflow::Menu::Mesh);
    m_analyseMenu = menuBar()->addMenu(QString());
    fill(m_analyseMenu, Workflow::Menu::Analyse);

    m_helpMenu = menuBar()->addMenu(QString());
    m_helpMenu->addAction(m_about);
    m_helpMenu->addAction(m_aboutQt);
    // A disabled entry's tooltip says why (disabled_reason.h).
    for (QMenu *menu : {m_fileMenu, m_editMenu, m_viewMenu, m_meshMenu, m_analyseMenu})
        menu->setToolTipsVisible(true);

    m_toolBar = addToolBar(QString());
    m_toolBar->setObjectName(QStringLiteral("MainToolBar"));
    m_toolBar->setMovable(false);
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    for (const Workflow *workflow : std::as_const(m_workflows))
        m_toolBar->addActions(workflow->toolBarActions());
    m_toolBar->addSeparator();
    m_toolBar->addAction(m_showBox);
    m_toolBar->addAction(m_showEdges);
    m_toolBar->addAction(m_resetCamera);
}

namespace {

// A dock's panel scrolls rather than forcing its minimum height on the window: stacked docks
// (Input vs Output above Complexity) would otherwise make the window taller than the screen.
void makeScrollable(QDockWidget *dock)
{
    auto *scroll = new QScrollArea(dock);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidgetResizable(true);
    scroll->setWidget(dock->widget());
    dock->setWidget(scroll);
}

} // namespace

// The reviews of a result share the right-hand tabs; lists of records go below, beside Messages.
void MainWindow::placeDocks()
{
    QDockWidget *review = nullptr;
    QDockWidget *left = nullptr;
    for (const Workflow *workflow : std::as_const(m_workflows)) {
        for (const Workflow::Dock &dock : workflow->docks()) {
            switch (dock.place) {
            case Workflow::DockPlace::WithMessages:
                addDockWidget(Qt::BottomDockWidgetArea, dock.dock);
                tabifyDockWidget(m_messageDock, dock.dock);
                break;
            case Workflow::DockPlace::Review:
                addDockWidget(Qt::RightDockWidgetArea, dock.dock);
                if (review)
                    tabifyDockWidget(review, dock.dock);
                else
                    review = dock.dock;
                break;
            case Workflow::DockPlace::Side:
                addDockWidget(Qt::RightDockWidgetArea, dock.dock);
                break;
            case Workflow::DockPlace::Left:
                addDockWidget(Qt::LeftDockWidgetArea, dock.dock);
                // The model's tree stays in front; the other left docks are its tabs.
                if (left) {
                    tabifyDockWidget(left, dock.dock);
                    left->raise();
                } else {
                    left = dock.dock;
                }
                break;
            }
            // A tree scrolls by itself and needs the dock's whole height.
            if (dock.place != Workflow::DockPlace::WithMessages
                && dock.place != Workflow::DockPlace::Left)
                makeScrollable(dock.dock);
            // The model's tree is there from the start: the views keep their size when it fills.
            if (dock.place != Workflow::DockPlace::Left)
                dock.dock->hide();
            m_viewMenu->addAction(dock.dock->toggleViewAction());
        }
    }
}

void MainWindow::retranslate()
{
    m_fileMenu->setTitle(tr("&File"));
    m_editMenu->setTitle(tr("&Edit"));
    m_viewMenu->setTitle(tr("&View"));
    m_meshMenu->setTitle(tr("&Mesh"));
    m_analyseMenu->setTitle(tr("&Analyse"));
    m_helpMenu->setTitle(tr("&Help"));
    m_quit->setText(tr("&Quit"));
    m_showBox->setText(tr("Show &Box"));
    m_showBox->setStatusTip(tr("Show the surfaces of the model's bounding box"));
    m_showEdges->setText(tr("Show Triangle &Edges"));
    m_showEdges->setStatusTip(tr("Draw the edges of every surface triangle"));
    m_resetCamera->setText(tr("&Reset Camera"));
    m_resetCamera->setStatusTip(tr("Look at the whole model from the south-west"));
    m_linkCameras->setText(tr("&Link Cameras"));
    m_linkCameras->setStatusTip(
        tr("Move the input and output views together; unchecked, each view has its own camera"));
    m_about->setText(tr("&About StrataMesh"));
    m_aboutQt->setText(tr("About &Qt"));
    m_recent->retranslate();
    for (Workflow *workflow : std::as_const(m_workflows))
        workflow->retranslate();
    m_toolBar->setWindowTitle(tr("Main Toolbar"));
    m_messageDock->setWindowTitle(tr("Messages"));
    m_messageDock->toggleViewAction()->setText(tr("&Messages"));
    updateTitle();
    updateCounts();
}

void MainWindow::updateTitle()
{
    const QString &name = m_bench->displayName();
    const QString project = QFileInfo(m_project->projectPath()).fileName();
    // [*]: the unsaved-project marker (ProjectWorkflow sets windowModified).
    if (name.isEmpty())
        setWindowTitle(tr("StrataMesh[*]"));
    else if (project.isEmpty())
        setWindowTitle(tr("%1[*] — StrataMesh").arg(name));
    else
        setWindowTitle(tr("%1 (%2)[*] — StrataMesh").arg(project, name));
}

void MainWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QMainWindow::changeEvent(event);
}

void MainWindow::openFile(const QString &path)
{
    if (isProjectFile(path))
        m_project->openProject(path);
    else
        m_open->openFile(path);
}

// Unsaved results (a project's runs and reviews, a remeshed model) are offered for saving.
void MainWindow::closeEvent(QCloseEvent *event)
{
    if (m_bench->mayDiscardWork()) {
        saveLayout();
        event->accept();
    } else
        event->ignore();
}

void MainWindow::openSample()
{
    m_open->openSample();
}

QString MainWindow::sampleProjectPath()
{
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation);
    return QDir(folder).filePath(QStringLiteral("sample/sample.smproj"));
}

void MainWindow::openSampleProject()
{
    const QString path = sampleProjectPath();
    if (QFileInfo::exists(path) && m_project->openProject(path))
        return;
    // First time (or the saved one could not be read: its error is in Messages): made again.
    ScriptStep remesh;
    remesh.kind = ScriptStep::Kind::Remesh;
    remesh.count = 300;
    ScriptStep save;
    save.kind = ScriptStep::Kind::SaveProject;
    save.value = path;
    QDir().mkpath(QFileInfo(path).absolutePath());
    auto *runner = new ScriptRunner(*this, {remesh, save}, this);
    connect(runner, &ScriptRunner::finished, runner, &QObject::deleteLater);
    connect(
        m_open, &OpenWorkflow::finished, runner,
        [runner](bool ok) {
            if (ok)
                runner->start();
            else
                runner->deleteLater();
        },
        Qt::SingleShotConnection);
    openSample();
}

void MainWindow::setBoxVisible(bool visible)
{
    if (m_showBox->isChecked() != visible)
        m_showBox->setChecked(visible); // comes back here through toggled()
    scene()->setBoxVisible(visible);
    outputScene()->setBoxVisible(visible);
    m_bench->updateLegend();
    m_bench->render();
}

void MainWindow::setEdgesVisible(bool visible)
{
    if (m_showEdges->isChecked() != visible)
        m_showEdges->setChecked(visible);
    scene()->setEdgesVisible(visible);
    outputScene()->setEdgesVisible(visible);
    m_bench->render();
}

void MainWindow::resetCamera()
{
    m_bench->resetCamera();
}

void MainWindow::dragEnterEvent(QDragEnterEvent *event)
{
    if (event->mimeData()->hasUrls() && event->mimeData()->urls().size() == 1
        && event->mimeData()->urls().first().isLocalFile())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent *event)
{
    openFile(event->mimeData()->urls().first().toLocalFile());
    event->acceptProposedAction();
}

// What every step showed of the previous model goes before the new one is shown.
void MainWindow::showModel(const LoadedModel &loaded)
{
    for (Workflow *workflow : std::as_const(m_workflows))
        workflow->clear();
    m_bench->setModel(loaded);
    retranslate();
}

// One long run at a time: while any workflow runs, no other starts, nor does a dropped file open.
void MainWindow::updateBusy()
{
    Workflow *running = nullptr;
    for (Workflow *workflow : std::as_const(m_workflows))
        if (workflow->isBusy())
            running = workflow;
    for (Workflow *workflow : std::as_const(m_workflows))
        workflow->enableActions(running != nullptr);
    if (running)
        m_strip->follow(running->job(), running->cancelAction());
    else
        m_strip->release();
    setAcceptDrops(!running);
    m_recent->setEnabled(!running);
}

void MainWindow::saveLayout() const
{
    const std::unique_ptr<QSettings> settings = openSettings();
    settings->setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings->setValue(QStringLiteral("window/state"), saveState(kStateVersion));
}

// The docks come back where the user left them, but hidden until a workflow has something to show
// in them (as at any start): a Review dock open on nothing would only take room.
bool MainWindow::restoreLayout()
{
    const std::unique_ptr<QSettings> settings = openSettings();
    const QByteArray geometry = settings->value(QStringLiteral("window/geometry")).toByteArray();
    const QByteArray state = settings->value(QStringLiteral("window/state")).toByteArray();
    if (!geometry.isEmpty())
        restoreGeometry(geometry);
    if (state.isEmpty() || !restoreState(state, kStateVersion))
        return false;
    for (const Workflow *workflow : std::as_const(m_workflows))
        for (const Workflow::Dock &dock : workflow->docks())
            if (dock.place != Workflow::DockPlace::Left)
                dock.dock->hide();
    return true;
}

QStringList MainWindow::offeredActions() const
{
    QList<const QAction *> cancels;
    for (const Workflow *workflow : std::as_const(m_workflows))
        cancels.append(workflow->cancelAction());
    QStringList offered;
    for (const QMenu *menu : {m_meshMenu, m_analyseMenu})
        for (const QAction *action : menu->actions())
            if (!action->isSeparator() && !cancels.contains(action))
                offered.append(action->text());
    return offered;
}

QString MainWindow::statusCounts() const
{
    return m_countsLabel->text();
}

void MainWindow::updateCounts()
{
    const auto &model = scene()->model();
    if (!model) {
        m_countsLabel->clear();
        return;
    }
    // Table 3.1 of the thesis counts entities without the box; the tooltip gives both.
    const auto describe = [](const EntityCounts &c) {
        const QString sep = QStringLiteral("  ·  ");
        return tr("%n region(s)", nullptr, c.regions) + sep
               + tr("%n surface(s)", nullptr, c.surfaces) + sep + tr("%n line(s)", nullptr, c.lines)
               + sep + tr("%n corner(s)", nullptr, c.corners);
    };
    const QString triangles =
        tr("%1 triangles").arg(QLocale().toString(qulonglong(model->triangleCount())));
    const ModelCounts &counts = m_bench->counts();
    m_countsLabel->setText(
        tr("%1 (box excluded)  ·  %2").arg(describe(counts.withoutBox), triangles));
    m_countsLabel->setToolTip(tr("With the box: %1").arg(describe(counts.all)));
}

} // namespace stratamesh
