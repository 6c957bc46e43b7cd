#include "main_window.h"

#include "about_dialog.h"
#include "cell_heat_map.h"
#include "comparison_table.h"
#include "complexity_controller.h"
#include "error_message.h"
#include "feature_legend.h"
#include "ledger_panel.h"
#include "message_panel.h"
#include "model_scene.h"
#include "open_model_controller.h"
#include "position_marker.h"
#include "remesh_controller.h"
#include "remesh_dialog.h"
#include "tet_mesh_pair.h"
#include "tetmesh_controller.h"
#include "validity_messages.h"
#include "vtk_view_widget.h"

#include "common/error.h"
#include "io/formats.h"
#include "io/mesh_writer.h"
#include "io/output_plan.h"

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
#include <QSplitter>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>

#include <vtkRenderer.h>

namespace stratamesh {

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent), m_view(new VtkViewWidget(this)),
      m_controller(new OpenModelController(this)), m_outputView(new VtkViewWidget(this)),
      m_remeshController(new RemeshController(this)),
      m_complexityController(new ComplexityController(this)),
      m_tetmeshController(new TetmeshController(this))
{
    setObjectName(QStringLiteral("MainWindow"));
    createViews();
    m_scene = std::make_unique<ModelScene>(m_view->renderer());
    m_outputScene = std::make_unique<ModelScene>(m_outputView->renderer());
    m_marker = std::make_unique<PositionMarker>(m_outputView->renderer());
    m_heatMap = std::make_unique<CellHeatMap>(m_view->renderer());
    m_legend = new FeatureLegend(m_view);
    setAcceptDrops(true);

    createActions();
    createMenus();
    createDocks();
    createStatusBar();
    createComplexityUi();
    createTetmeshUi();
    retranslate();

    connect(m_controller, &OpenModelController::opening, this, &MainWindow::onLoadStarted);
    connect(m_controller, &OpenModelController::progressChanged, this, &MainWindow::onProgress);
    connect(m_controller, &OpenModelController::loaded, this, &MainWindow::onLoaded);
    connect(m_controller, &OpenModelController::failed, this, &MainWindow::onFailed);
    connect(m_controller, &OpenModelController::finished, this, &MainWindow::loadFinished);
    connect(m_remeshController, &RemeshController::started, this, &MainWindow::onRemeshStarted);
    connect(m_remeshController, &RemeshController::progressChanged, this, &MainWindow::onProgress);
    connect(m_remeshController, &RemeshController::succeeded, this, &MainWindow::onRemeshed);
    connect(m_remeshController, &RemeshController::failed, this, &MainWindow::onRemeshFailed);
    connect(m_remeshController, &RemeshController::cancelled, this, &MainWindow::onRemeshCancelled);
    connect(m_remeshController, &RemeshController::finished, this, &MainWindow::remeshFinished);
    resize(1280, 800);
}

// The scene's actors must leave the renderer before the view goes.
MainWindow::~MainWindow()
{
    m_remeshController->disconnect(this); // a running remeshing is cancelled, its outcome dropped
    delete m_remeshController;
    m_complexityController->disconnect(this);
    delete m_complexityController;
    m_tetmeshController->disconnect(this); // kills a running TetGen helper
    delete m_tetmeshController;
    m_tetScenes.reset();
    m_heatMap.reset();
    m_marker.reset();
    m_outputScene.reset();
    m_scene.reset();
}

// Input and output side by side, looking through one shared camera: moving either view moves
// both, so the same place is compared.
void MainWindow::createViews()
{
    const auto pane = [this](QLabel *title, VtkViewWidget *view) {
        auto *widget = new QWidget(this);
        auto *layout = new QVBoxLayout(widget);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->setSpacing(2);
        title->setAlignment(Qt::AlignCenter);
        layout->addWidget(title);
        layout->addWidget(view, 1);
        return widget;
    };
    m_inputTitle = new QLabel(this);
    m_outputTitle = new QLabel(this);
    m_inputTitle->setObjectName(QStringLiteral("InputViewTitle"));
    m_outputTitle->setObjectName(QStringLiteral("OutputViewTitle"));
    m_splitter = new QSplitter(Qt::Horizontal, this);
    m_splitter->addWidget(pane(m_inputTitle, m_view));
    m_outputPane = pane(m_outputTitle, m_outputView);
    m_splitter->addWidget(m_outputPane);
    m_splitter->setChildrenCollapsible(false);
    m_outputPane->hide();
    m_inputTitle->hide();
    setCentralWidget(m_splitter);

    m_outputView->renderer()->SetActiveCamera(m_view->renderer()->GetActiveCamera());
    connect(m_view, &VtkViewWidget::cameraMovedByUser, m_outputView, &VtkViewWidget::render);
    connect(m_outputView, &VtkViewWidget::cameraMovedByUser, m_view, &VtkViewWidget::render);
}

void MainWindow::createActions()
{
    m_open = new QAction(this);
    m_open->setShortcut(QKeySequence::Open);
    m_open->setIcon(QIcon::fromTheme(QStringLiteral("document-open"),
                                     style()->standardIcon(QStyle::SP_DialogOpenButton)));
    connect(m_open, &QAction::triggered, this, &MainWindow::chooseFile);

    m_openSample = new QAction(this);
    connect(m_openSample, &QAction::triggered, this, &MainWindow::openSample);
    m_openStudy = new QAction(this);
    connect(m_openStudy, &QAction::triggered, this, &MainWindow::chooseStudy);

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
    m_remesh = new QAction(this);
    m_remesh->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    m_remesh->setIcon(QIcon::fromTheme(QStringLiteral("system-run"),
                                       style()->standardIcon(QStyle::SP_BrowserReload)));
    m_remesh->setEnabled(false);
    connect(m_remesh, &QAction::triggered, this, &MainWindow::remesh);
    m_cancelRemesh = new QAction(this);
    m_cancelRemesh->setIcon(style()->standardIcon(QStyle::SP_DialogCancelButton));
    m_cancelRemesh->setEnabled(false);
    connect(m_cancelRemesh, &QAction::triggered, this, &MainWindow::cancelRemesh);
    m_saveRemeshed = new QAction(this);
    m_saveRemeshed->setShortcut(QKeySequence::SaveAs);
    m_saveRemeshed->setIcon(QIcon::fromTheme(QStringLiteral("document-save-as"),
                                             style()->standardIcon(QStyle::SP_DialogSaveButton)));
    m_saveRemeshed->setEnabled(false);
    connect(m_saveRemeshed, &QAction::triggered, this, &MainWindow::chooseRemeshedFile);

    m_aboutQt = new QAction(this);
    m_aboutQt->setMenuRole(QAction::AboutQtRole);
    connect(m_aboutQt, &QAction::triggered, qApp, &QApplication::aboutQt);
}

void MainWindow::createMenus()
{
    m_fileMenu = menuBar()->addMenu(QString());
    m_fileMenu->addAction(m_open);
    m_fileMenu->addAction(m_openSample);
    m_fileMenu->addAction(m_openStudy);
    m_fileMenu->addAction(m_saveRemeshed);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_quit);

    m_viewMenu = menuBar()->addMenu(QString());
    m_viewMenu->addAction(m_showBox);
    m_viewMenu->addAction(m_showEdges);
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_resetCamera);

    m_meshMenu = menuBar()->addMenu(QString());
    m_meshMenu->addAction(m_remesh);
    m_meshMenu->addAction(m_cancelRemesh);

    m_analyseMenu = menuBar()->addMenu(QString());

    m_helpMenu = menuBar()->addMenu(QString());
    m_helpMenu->addAction(m_about);
    m_helpMenu->addAction(m_aboutQt);

    m_toolBar = addToolBar(QString());
    m_toolBar->setObjectName(QStringLiteral("MainToolBar"));
    m_toolBar->setMovable(false);
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_toolBar->addAction(m_open);
    m_toolBar->addAction(m_remesh);
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

    // Remeshing docks, shown once there is a remeshing to review.
    m_ledger = new LedgerPanel(this);
    m_ledgerDock = new QDockWidget(this);
    m_ledgerDock->setObjectName(QStringLiteral("SimplificationsDock"));
    m_ledgerDock->setWidget(m_ledger);
    addDockWidget(Qt::BottomDockWidgetArea, m_ledgerDock);
    tabifyDockWidget(m_messageDock, m_ledgerDock);
    m_ledgerDock->hide();
    m_comparison = new ComparisonTable(this);
    m_comparisonDock = new QDockWidget(this);
    m_comparisonDock->setObjectName(QStringLiteral("ComparisonDock"));
    m_comparisonDock->setWidget(m_comparison);
    addDockWidget(Qt::RightDockWidgetArea, m_comparisonDock);
    m_comparisonDock->hide();
    m_viewMenu->addAction(m_ledgerDock->toggleViewAction());
    m_viewMenu->addAction(m_comparisonDock->toggleViewAction());
    connect(m_ledger, &LedgerPanel::recordSelected, this, &MainWindow::showLedgerRecord);
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
    m_cancelButton = new QToolButton(this);
    m_cancelButton->setDefaultAction(m_cancelRemesh);
    m_cancelButton->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_cancelButton->setAutoRaise(true);
    m_cancelButton->hide();
    statusBar()->addPermanentWidget(m_progress);
    statusBar()->addPermanentWidget(m_cancelButton);
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
    m_openStudy->setText(tr("Open S&tudy…"));
    m_openStudy->setStatusTip(
        tr("Show the table of a study run by stratamesh-cli study (.smstudy or study.json)"));
    m_quit->setText(tr("&Quit"));
    m_showBox->setText(tr("Show &Box"));
    m_showBox->setStatusTip(tr("Show the surfaces of the model's bounding box"));
    m_showEdges->setText(tr("Show Triangle &Edges"));
    m_showEdges->setStatusTip(tr("Draw the edges of every surface triangle"));
    m_resetCamera->setText(tr("&Reset Camera"));
    m_resetCamera->setStatusTip(tr("Look at the whole model from the south-west"));
    m_about->setText(tr("&About StrataMesh"));
    m_aboutQt->setText(tr("About &Qt"));
    m_meshMenu->setTitle(tr("&Mesh"));
    m_remesh->setText(tr("&Remesh…"));
    m_remesh->setStatusTip(
        tr("Remesh all the surfaces at a chosen resolution, keeping the model conformal"));
    m_cancelRemesh->setText(tr("&Cancel Remeshing"));
    m_cancelRemesh->setStatusTip(tr("Stop the remeshing; the input model is left as it is"));
    m_saveRemeshed->setText(tr("Save Remeshed Model &As…"));
    m_saveRemeshed->setStatusTip(
        tr("Write the remeshed model as a Gocad, RINGMesh, Gmsh or VTK file"));
    m_ledgerDock->setWindowTitle(tr("Simplifications"));
    m_ledgerDock->toggleViewAction()->setText(tr("&Simplifications"));
    m_comparisonDock->setWindowTitle(tr("Input vs Output"));
    m_comparisonDock->toggleViewAction()->setText(tr("&Input vs Output"));
    updateViewTitles();
    retranslateComplexity();
    retranslateTetmesh();
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

void MainWindow::openFile(const QString &path)
{
    m_controller->openFile(path);
}

void MainWindow::openSample()
{
    m_controller->openSample();
}

void MainWindow::chooseFile()
{
    QSettings settings;
    const QString dir = settings.value(QStringLiteral("lastDirectory")).toString();
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Model"), dir,
                                                      OpenModelController::fileFilter());
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
    m_outputScene->setBoxVisible(visible);
    updateLegend();
    m_view->render();
    m_outputView->render();
}

void MainWindow::setEdgesVisible(bool visible)
{
    if (m_showEdges->isChecked() != visible)
        m_showEdges->setChecked(visible);
    m_scene->setEdgesVisible(visible);
    m_outputScene->setEdgesVisible(visible);
    m_view->render();
    m_outputView->render();
}

void MainWindow::resetCamera()
{
    double bounds[6];
    if (m_scene->bounds(bounds))
        m_view->resetCamera(bounds);
    else
        m_view->resetCamera();
    // The output view shares the camera; its clipping range follows its own actors.
    m_outputView->renderer()->ResetCameraClippingRange();
    m_outputView->render();
}

void MainWindow::showAbout()
{
    showAboutDialog(this);
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

void MainWindow::onLoadStarted(const QString &displayName)
{
    setBusy(true);
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
    setBusy(false);
    m_progress->hide();
    m_messages->clear();
    m_displayName = loaded.displayName;
    m_modelPath = loaded.path;
    m_counts = loaded.counts;
    clearTetmeshOutcome();
    clearRemeshOutcome();
    clearComplexityOutcome();
    m_scene->setModel(loaded.model);
    m_remesh->setEnabled(true);
    m_complexity->setEnabled(true);
    m_tetmesh->setEnabled(true);
    updateLegend();
    resetCamera();

    Message opened;
    opened.text =
        tr("%1 opened in %2 s")
            .arg(loaded.displayName, QLocale().toString(loaded.milliseconds / 1000.0, 'f', 2));
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
    m_stageLabel->setText(loaded.messages.empty() ? tr("Ready")
                                                  : tr("%n validity problem(s) — see Messages",
                                                       nullptr, int(loaded.messages.size())));
    retranslate();
}

void MainWindow::onFailed(const Message &error)
{
    setBusy(false);
    m_progress->hide();
    m_messages->clear();
    m_messages->addMessage(error);
    m_messageDock->show();
    m_messageDock->raise();
    const QString where = formatLocation(error);
    m_stageLabel->setText(where.isEmpty() ? tr("Could not open the model")
                                          : tr("Could not open %1").arg(where));
}

QString MainWindow::statusCounts() const
{
    return m_countsLabel ? m_countsLabel->text() : QString();
}

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
        return tr("%n region(s)", nullptr, c.regions) + sep
               + tr("%n surface(s)", nullptr, c.surfaces) + sep + tr("%n line(s)", nullptr, c.lines)
               + sep + tr("%n corner(s)", nullptr, c.corners);
    };
    const QString triangles =
        tr("%1 triangles").arg(QLocale().toString(qulonglong(model->triangleCount())));
    m_countsLabel->setText(
        tr("%1 (box excluded)  ·  %2").arg(describe(m_counts.withoutBox), triangles));
    m_countsLabel->setToolTip(tr("With the box: %1").arg(describe(m_counts.all)));
}

// While tets are drawn in place of the surfaces, the surface legend would describe nothing shown.
void MainWindow::updateLegend()
{
    m_legend->setEntries(m_scene->isVisible() ? m_scene->legend() : std::vector<LegendEntry>{},
                         m_scene->boxVisible());
}

} // namespace stratamesh

namespace stratamesh {

// One long job at a time: no opening while remeshing, no remeshing while opening.
void MainWindow::setBusy(bool busy)
{
    m_open->setEnabled(!busy);
    m_openSample->setEnabled(!busy);
    m_remesh->setEnabled(!busy && m_scene->model());
    m_complexity->setEnabled(!busy && m_scene->model());
    m_tetmesh->setEnabled(!busy && m_scene->model());
    m_exportCells->setEnabled(!busy && m_complexityOutcome.has_value());
    m_saveRemeshed->setEnabled(!busy && m_outcome.has_value());
    setAcceptDrops(!busy);
}

void MainWindow::clearRemeshOutcome()
{
    m_outcome.reset();
    m_marker->hide();
    m_outputScene->setModel(nullptr);
    m_ledger->setLedger(nullptr);
    m_comparison->setComparison(std::nullopt);
    m_outputPane->hide();
    m_inputTitle->hide();
    m_ledgerDock->hide();
    m_comparisonDock->hide();
    m_saveRemeshed->setEnabled(false);
    updateViewTitles();
}

void MainWindow::remesh()
{
    const auto &model = m_scene->model();
    if (!model || isWorking())
        return;
    RemeshDialog dialog(m_scene->diagonal(), this);
    if (m_lastParams.sites > 0 || m_lastParams.edgeLength > 0.0)
        dialog.setParams(m_lastParams);
    if (dialog.exec() != QDialog::Accepted)
        return;
    startRemesh(dialog.params());
}

bool MainWindow::startRemesh(const RemeshParams &params)
{
    if (isWorking())
        return false;
    m_lastParams = params;
    return m_remeshController->start(m_scene->model(), params);
}

void MainWindow::cancelRemesh()
{
    if (!m_remeshController->isBusy())
        return;
    m_remeshController->cancel();
    m_cancelRemesh->setEnabled(false);
    m_stageLabel->setText(tr("Cancelling…"));
}

void MainWindow::onRemeshStarted()
{
    setBusy(true);
    m_cancelRemesh->setEnabled(true);
    m_cancelButton->setDefaultAction(m_cancelRemesh);
    m_cancelButton->show();
    m_stageLabel->setText(tr("Remeshing %1…").arg(m_displayName));
    m_progress->setValue(0);
    m_progress->show();
}

void MainWindow::onRemeshed(const RemeshOutcome &outcome)
{
    clearTetmeshOutcome(); // its remesh side was another model
    m_outcome = outcome;
    m_cancelRemesh->setEnabled(false);
    m_cancelButton->hide();
    m_progress->hide();
    setBusy(false);
    m_marker->hide();
    m_outputScene->setBoxVisible(m_scene->boxVisible());
    m_outputScene->setEdgesVisible(m_scene->edgesVisible());
    m_outputScene->setModel(outcome.output);
    m_outputPane->show();
    m_inputTitle->show();
    m_ledgerDock->show();
    m_ledgerDock->raise();
    m_comparisonDock->show();
    m_ledger->setLedger(outcome.ledger);
    m_comparison->setComparison(outcome.comparison);
    resizeDocks({m_comparisonDock}, {m_comparison->sizeHint().width()}, Qt::Horizontal);
    resizeDocks({m_ledgerDock}, {220}, Qt::Vertical);
    // Lay the new panes out now: the camera is framed for the views' final sizes.
    layout()->activate();
    const int half = m_splitter->width() / 2;
    m_splitter->setSizes({half, m_splitter->width() - half});
    updateViewTitles();
    resetCamera();

    Message done;
    done.text = tr("Remeshed with %1 sites in %2 s: %3 triangles, %n simplification(s) recorded",
                   nullptr, int(outcome.ledger->size()))
                    .arg(QLocale().toString(outcome.siteCount),
                         QLocale().toString(outcome.milliseconds / 1000.0, 'f', 2),
                         QLocale().toString(qulonglong(outcome.output->triangleCount())));
    m_messages->addMessage(done);
    if (!outcome.validity.valid) {
        // Never announced as a plain success: a volume mesher would fail on it.
        Message invalid;
        invalid.severity = Message::Severity::Warning;
        invalid.text = tr(
            "The remeshed model is NOT valid: %n problem(s) left after local refinement; saving it "
            "is at your own risk",
            nullptr, int(outcome.validity.problems.size()));
        m_messages->addMessage(invalid);
        for (const Message &m : validityMessages(outcome.validity, QString()))
            m_messages->addMessage(m);
        m_messageDock->show();
        m_messageDock->raise();
        m_stageLabel->setText(tr("Remeshed, NOT valid: %n problem(s) — see Messages", nullptr,
                                 int(outcome.validity.problems.size())));
        return;
    }
    m_stageLabel->setText(tr("Remeshed: %n simplification(s) — see Simplifications", nullptr,
                             int(outcome.ledger->size())));
}

void MainWindow::onRemeshFailed(const Message &error)
{
    m_cancelRemesh->setEnabled(false);
    m_cancelButton->hide();
    m_progress->hide();
    setBusy(false);
    Message shown = error;
    shown.text = tr("Remeshing failed: %1").arg(error.text);
    m_messages->addMessage(shown);
    m_messageDock->show();
    m_messageDock->raise();
    m_stageLabel->setText(tr("Remeshing failed — see Messages"));
}

void MainWindow::onRemeshCancelled()
{
    m_cancelRemesh->setEnabled(false);
    m_cancelButton->hide();
    m_progress->hide();
    setBusy(false);
    m_stageLabel->setText(tr("Remeshing cancelled"));
}

void MainWindow::updateViewTitles()
{
    if (!m_inputTitle)
        return;
    m_inputTitle->setText(tr("Input: %1").arg(m_displayName));
    if (!m_outcome) {
        m_outputTitle->clear();
        return;
    }
    const QLocale locale;
    m_outputTitle->setText(
        tr("Output: %1 sites, %2 triangles")
            .arg(locale.toString(m_outcome->siteCount),
                 locale.toString(qulonglong(m_outcome->output->triangleCount()))));
}

void MainWindow::showLedgerRecord(int recordIndex)
{
    const LedgerRecord *record =
        m_outcome && recordIndex >= 0 && recordIndex < int(m_outcome->ledger->size())
            ? &(*m_outcome->ledger)[std::size_t(recordIndex)]
            : nullptr;
    if (!record) {
        m_marker->hide();
        m_outputView->render();
        return;
    }
    // Big enough to be found at the whole-model zoom, never hiding the change itself entirely.
    m_marker->show(record->position,
                   std::max(0.015 * m_outputScene->diagonal(), 0.5 * record->size));
    // The views share one camera: centred on the record in both.
    const double centre[3] = {record->position.x(), record->position.y(), record->position.z()};
    m_view->centreOn(centre);
    m_outputView->renderer()->ResetCameraClippingRange();
    m_view->render();
    m_outputView->render();
}

void MainWindow::chooseRemeshedFile()
{
    if (!m_outcome)
        return;
    QSettings settings;
    const QString dir = settings.value(QStringLiteral("lastDirectory")).toString();
    QString selected;
    QString path = QFileDialog::getSaveFileName(
        this, tr("Save Remeshed Model"), dir,
        QString::fromStdString(fileDialogFilter(FormatUse::WriteModel, {}, {})), &selected);
    if (path.isEmpty())
        return;
    path = QString::fromStdString(
        withFormatExtension(path.toStdString(), FormatUse::WriteModel, selected.toStdString()));
    settings.setValue(QStringLiteral("lastDirectory"), QFileInfo(path).absolutePath());
    saveRemeshedModel(path);
}

bool MainWindow::saveRemeshedModel(const QString &path)
{
    if (!m_outcome)
        return false;
    Message message;
    message.file = path;
    try {
        // As the command line does (io/output_plan.h): never over the open model, checked before
        // writing, through a temporary file (which keeps the extension) and a rename.
        OutputPlan plan({m_modelPath.toStdString()});
        plan.add(path.toStdString(), "remeshed model");
        plan.write(path.toStdString(), [&](const std::string &temporary) {
            exportModel(*m_outcome->output, temporary);
        });
        plan.commit();
        message.text = tr("Remeshed model saved");
        m_messages->addMessage(message);
        m_stageLabel->setText(tr("Saved %1").arg(QFileInfo(path).fileName()));
        return true;
    } catch (const std::exception &e) {
        message = errorMessage(e, path);
    }
    m_messages->addMessage(message);
    m_messageDock->show();
    m_messageDock->raise();
    m_stageLabel->setText(tr("Could not save the remeshed model"));
    return false;
}

} // namespace stratamesh
