// The TetGen comparison part of the main window (thesis §5.2): Mesh > Tetrahedralise…, the
// Tetrahedra dock, and the tets drawn in place of the surfaces in the input and remesh views.
#include "main_window.h"

#include "message_panel.h"
#include "model_scene.h"
#include "open_model_controller.h"
#include "tet_mesh_pair.h"
#include "tetmesh_controller.h"
#include "tetmesh_dialog.h"
#include "tetmesh_panel.h"
#include "vtk_view_widget.h"

#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QLayout>
#include <QLocale>
#include <QMenu>
#include <QProgressBar>
#include <QStyle>
#include <QToolButton>

#include <cmath>

namespace stratamesh {

void MainWindow::createTetmeshUi()
{
    m_tetmesh = new QAction(this);
    m_tetmesh->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_T));
    m_tetmesh->setEnabled(false);
    connect(m_tetmesh, &QAction::triggered, this, &MainWindow::tetrahedralise);
    m_cancelTetmesh = new QAction(this);
    m_cancelTetmesh->setIcon(style()->standardIcon(QStyle::SP_DialogCancelButton));
    m_cancelTetmesh->setEnabled(false);
    connect(m_cancelTetmesh, &QAction::triggered, this, &MainWindow::cancelTetmesh);
    m_meshMenu->addSeparator();
    m_meshMenu->addAction(m_tetmesh);
    m_meshMenu->addAction(m_cancelTetmesh);

    m_tetScenes = std::make_unique<TetMeshPair>(m_view->renderer(), m_outputView->renderer());
    m_tetmeshPanel = new TetmeshPanel(this);
    m_tetmeshDock = new QDockWidget(this);
    m_tetmeshDock->setObjectName(QStringLiteral("TetrahedraDock"));
    m_tetmeshDock->setWidget(m_tetmeshPanel);
    addDockWidget(Qt::RightDockWidgetArea, m_tetmeshDock);
    // Tabbed with Input vs Output: the histograms need the dock's whole height.
    tabifyDockWidget(m_comparisonDock, m_tetmeshDock);
    m_tetmeshDock->hide();
    m_viewMenu->addAction(m_tetmeshDock->toggleViewAction());
    connect(m_tetmeshPanel, &TetmeshPanel::colouringChanged, this, &MainWindow::applyTetView);
    connect(m_tetmeshPanel, &TetmeshPanel::clipChanged, this, &MainWindow::applyTetView);

    connect(m_tetmeshController, &TetmeshController::started, this, &MainWindow::onTetmeshStarted);
    connect(m_tetmeshController, &TetmeshController::progressChanged, this,
            &MainWindow::onProgress);
    connect(m_tetmeshController, &TetmeshController::succeeded, this, &MainWindow::onTetmeshed);
    connect(m_tetmeshController, &TetmeshController::failed, this, &MainWindow::onTetmeshFailed);
    connect(m_tetmeshController, &TetmeshController::cancelled, this,
            &MainWindow::onTetmeshCancelled);
    connect(m_tetmeshController, &TetmeshController::finished, this, &MainWindow::tetmeshFinished);
}

void MainWindow::retranslateTetmesh()
{
    m_tetmesh->setText(tr("&Tetrahedralise…"));
    m_tetmesh->setStatusTip(tr("Mesh the regions of the input and of the remesh with TetGen and "
                               "compare the tetrahedra"));
    m_cancelTetmesh->setText(tr("Cancel &Tetrahedralisation"));
    m_cancelTetmesh->setStatusTip(tr("Stop TetGen; nothing is kept of this run"));
    m_tetmeshDock->setWindowTitle(tr("Tetrahedra"));
    m_tetmeshDock->toggleViewAction()->setText(tr("&Tetrahedra"));
    m_tetScenes->setTitles(tr("Region").toUtf8().constData(),
                           tr("Min dihedral\nangle (°)").toUtf8().constData());
}

void MainWindow::clearTetmeshOutcome()
{
    m_tetmeshOutcome.reset();
    m_tetScenes->clear();
    m_tetmeshPanel->setSides(nullptr, nullptr);
    m_tetmeshDock->hide();
    m_scene->setVisible(true);
    m_outputScene->setVisible(true);
    updateLegend();
    m_view->render();
    m_outputView->render();
}

void MainWindow::tetrahedralise()
{
    if (!m_scene->model() || isWorking())
        return;
    TetmeshDialog dialog(m_outcome.has_value(), m_scene->diagonal(), this);
    if (m_lastTetmeshParams)
        dialog.setParams(*m_lastTetmeshParams);
    if (dialog.exec() != QDialog::Accepted)
        return;
    startTetmesh(dialog.params(), dialog.bothModels());
}

bool MainWindow::startTetmesh(const TetgenParams &params, bool withRemesh)
{
    if (isWorking() || !m_scene->model())
        return false;
    m_lastTetmeshParams = params;
    std::shared_ptr<const Model> remesh = withRemesh && m_outcome ? m_outcome->output : nullptr;
    return m_tetmeshController->start(m_scene->model(), std::move(remesh), params);
}

void MainWindow::cancelTetmesh()
{
    if (!m_tetmeshController->isBusy())
        return;
    m_tetmeshController->cancel();
    m_cancelTetmesh->setEnabled(false);
    m_stageLabel->setText(tr("Cancelling…"));
}

void MainWindow::onTetmeshStarted()
{
    clearTetmeshOutcome();
    setBusy(true);
    m_cancelTetmesh->setEnabled(true);
    m_cancelButton->setDefaultAction(m_cancelTetmesh);
    m_cancelButton->show();
    m_stageLabel->setText(tr("Tetrahedralising %1…").arg(m_displayName));
    m_progress->setValue(0);
    m_progress->show();
}

void MainWindow::endTetmeshRun()
{
    m_cancelTetmesh->setEnabled(false);
    m_cancelButton->hide();
    m_progress->hide();
    setBusy(false);
}

void MainWindow::onTetmeshed(const TetmeshOutcome &outcome)
{
    m_tetmeshOutcome = outcome;
    endTetmeshRun();
    // A side TetGen failed on keeps its surfaces on screen; its failure is in the table.
    const auto inputMesh = TetmeshOutcome::meshOf(outcome.inputSide);
    const auto outputMesh = TetmeshOutcome::meshOf(outcome.outputSide);
    m_tetScenes->setMeshes(inputMesh, outputMesh);
    m_scene->setVisible(!inputMesh);
    m_outputScene->setVisible(!outputMesh);
    updateLegend();
    applyTetView();
    // Shown first: the charts lay their axis labels out for the size they are given.
    m_tetmeshDock->show();
    m_tetmeshDock->raise();
    m_tetmeshPanel->setSides(outcome.inputSide.get(), outcome.outputSide.get());
    resizeDocks({m_tetmeshDock}, {m_tetmeshPanel->sizeHint().width()}, Qt::Horizontal);
    // The views were resized by the dock: frame the model for their final sizes.
    layout()->activate();
    resetCamera();

    const QLocale locale;
    const auto describe = [&](const TetmeshSide &side, bool input) {
        if (side.result.outcome != TetgenOutcome::Ok)
            return TetmeshPanel::failureText(side.result.outcome,
                                             QString::fromStdString(side.result.message),
                                             side.result.seconds, input);
        return (input ? tr("Input: %1 tets, %2 slivers, min dihedral %3° in %4 s")
                      : tr("Remesh: %1 tets, %2 slivers, min dihedral %3° in %4 s"))
            .arg(locale.toString(qulonglong(side.quality.tets)),
                 locale.toString(qulonglong(side.quality.slivers)),
                 locale.toString(side.quality.minDihedralDeg, 'f', 2),
                 locale.toString(side.result.seconds, 'f', 2));
    };
    bool allOk = true;
    for (const auto *side : {outcome.inputSide.get(), outcome.outputSide.get()}) {
        if (!side)
            continue;
        Message m;
        const bool ok = side->result.outcome == TetgenOutcome::Ok;
        allOk = allOk && ok;
        m.severity = ok ? Message::Severity::Info : Message::Severity::Warning;
        m.text = describe(*side, side == outcome.inputSide.get());
        m_messages->addMessage(m);
    }
    m_stageLabel->setText(allOk ? tr("Tetrahedralised — see Tetrahedra")
                                : tr("TetGen failed on a model — see Tetrahedra"));
}

void MainWindow::onTetmeshFailed(const Message &error)
{
    endTetmeshRun();
    Message shown = error;
    shown.text = tr("Tetrahedralisation failed: %1").arg(error.text);
    m_messages->addMessage(shown);
    m_messageDock->show();
    m_messageDock->raise();
    m_stageLabel->setText(tr("Tetrahedralisation failed — see Messages"));
}

void MainWindow::onTetmeshCancelled()
{
    endTetmeshRun();
    m_stageLabel->setText(tr("Tetrahedralisation cancelled"));
}

void MainWindow::applyTetView()
{
    m_tetScenes->setColouring(m_tetmeshPanel->colouring());
    m_tetScenes->setClip(m_tetmeshPanel->clipEnabled(), m_tetmeshPanel->clipAxis(),
                         m_tetmeshPanel->clipFraction());
    m_view->render();
    m_outputView->render();
}

} // namespace stratamesh
