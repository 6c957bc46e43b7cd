// The complexity analysis part of the main window (thesis ch. 3): the Analyse menu, the
// Complexity dock and the heat map of elements per cell in the 3D view (Fig 3.7).
#include "error_message.h"
#include "main_window.h"

#include "cell_heat_map.h"
#include "complexity_controller.h"
#include "complexity_dialog.h"
#include "complexity_panel.h"
#include "message_panel.h"
#include "model_scene.h"
#include "open_model_controller.h"
#include "remesh_controller.h"
#include "tetmesh_controller.h"
#include "vtk_view_widget.h"

#include "common/error.h"
#include "io/cells_vtu_writer.h"
#include "io/output_plan.h"

#include <QAction>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QProgressBar>
#include <QSettings>
#include <QStyle>
#include <QToolButton>

namespace stratamesh {

void MainWindow::createComplexityUi()
{
    m_complexity = new QAction(this);
    m_complexity->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_K));
    m_complexity->setEnabled(false);
    connect(m_complexity, &QAction::triggered, this, &MainWindow::analyseComplexity);
    m_cancelComplexity = new QAction(this);
    m_cancelComplexity->setIcon(style()->standardIcon(QStyle::SP_DialogCancelButton));
    m_cancelComplexity->setEnabled(false);
    connect(m_cancelComplexity, &QAction::triggered, this, &MainWindow::cancelComplexity);
    m_exportCells = new QAction(this);
    m_exportCells->setEnabled(false);
    connect(m_exportCells, &QAction::triggered, this, &MainWindow::chooseCellsFile);
    m_analyseMenu->addAction(m_complexity);
    m_analyseMenu->addAction(m_cancelComplexity);
    m_analyseMenu->addSeparator();
    m_analyseMenu->addAction(m_exportCells);

    m_complexityPanel = new ComplexityPanel(this);
    m_complexityDock = new QDockWidget(this);
    m_complexityDock->setObjectName(QStringLiteral("ComplexityDock"));
    m_complexityDock->setWidget(m_complexityPanel);
    addDockWidget(Qt::RightDockWidgetArea, m_complexityDock);
    m_complexityDock->hide();
    m_viewMenu->addAction(m_complexityDock->toggleViewAction());
    m_heatMap->setThreshold(m_complexityPanel->threshold());
    connect(m_complexityPanel, &ComplexityPanel::thresholdChanged, this,
            &MainWindow::setHeatMapThreshold);
    connect(m_complexityPanel, &ComplexityPanel::heatMapVisibleChanged, this,
            &MainWindow::setHeatMapVisible);

    connect(m_complexityController, &ComplexityController::started, this,
            &MainWindow::onComplexityStarted);
    connect(m_complexityController, &ComplexityController::progressChanged, this,
            &MainWindow::onProgress);
    connect(m_complexityController, &ComplexityController::succeeded, this,
            &MainWindow::onComplexityDone);
    connect(m_complexityController, &ComplexityController::failed, this,
            &MainWindow::onComplexityFailed);
    connect(m_complexityController, &ComplexityController::cancelled, this,
            &MainWindow::onComplexityCancelled);
    connect(m_complexityController, &ComplexityController::finished, this,
            &MainWindow::complexityFinished);
}

void MainWindow::retranslateComplexity()
{
    m_analyseMenu->setTitle(tr("&Analyse"));
    m_complexity->setText(tr("&Complexity…"));
    m_complexity->setStatusTip(
        tr("Measure the complexity of the model and show the elements per cell as a heat map"));
    m_cancelComplexity->setText(tr("C&ancel Complexity Analysis"));
    m_cancelComplexity->setStatusTip(tr("Stop the complexity analysis"));
    m_exportCells->setText(tr("&Export Complexity Cells…"));
    m_exportCells->setStatusTip(
        tr("Write the cells with their element counts as a VTK unstructured grid (.vtu)"));
    m_complexityDock->setWindowTitle(tr("Complexity"));
    m_complexityDock->toggleViewAction()->setText(tr("&Complexity"));
    m_heatMap->setTitle(tr("Elements\nper cell").toUtf8().constData());
}

bool MainWindow::isWorking() const
{
    return m_controller->isBusy() || m_remeshController->isBusy()
           || m_complexityController->isBusy() || m_tetmeshController->isBusy();
}

void MainWindow::clearComplexityOutcome()
{
    m_complexityOutcome.reset();
    m_heatMap->clear();
    m_complexityPanel->setReport(std::nullopt);
    m_complexityDock->hide();
    m_exportCells->setEnabled(false);
}

void MainWindow::analyseComplexity()
{
    if (!m_scene->model() || isWorking())
        return;
    ComplexityDialog dialog(this);
    if (!m_lastComplexityParams.cells.empty())
        dialog.setParams(m_lastComplexityParams);
    if (dialog.exec() != QDialog::Accepted)
        return;
    startComplexity(dialog.params());
}

bool MainWindow::startComplexity(const ComplexityParams &params)
{
    if (isWorking())
        return false;
    m_lastComplexityParams = params;
    return m_complexityController->start(m_scene->model(), params);
}

void MainWindow::cancelComplexity()
{
    if (!m_complexityController->isBusy())
        return;
    m_complexityController->cancel();
    m_cancelComplexity->setEnabled(false);
    m_stageLabel->setText(tr("Cancelling…"));
}

void MainWindow::onComplexityStarted()
{
    // The previous heat map goes: it would not match the figures being computed.
    clearComplexityOutcome();
    m_view->render();
    setBusy(true);
    m_cancelComplexity->setEnabled(true);
    m_cancelButton->setDefaultAction(m_cancelComplexity);
    m_cancelButton->show();
    m_stageLabel->setText(tr("Measuring the complexity of %1…").arg(m_displayName));
    m_progress->setValue(0);
    m_progress->show();
}

void MainWindow::endComplexityRun()
{
    m_cancelComplexity->setEnabled(false);
    m_cancelButton->hide();
    m_progress->hide();
    setBusy(false);
}

void MainWindow::onComplexityDone(const ComplexityOutcome &outcome)
{
    m_complexityOutcome = outcome;
    endComplexityRun();
    const LocalComplexity &local = outcome.local();
    std::vector<int> counts;
    counts.reserve(local.counts.size());
    for (const CellElementCounts &c : local.counts)
        counts.push_back(c.total());
    m_heatMap->setThreshold(m_complexityPanel->threshold());
    m_heatMap->setVisible(m_complexityPanel->heatMapVisible());
    m_heatMap->setCells(outcome.cells, std::move(counts));
    m_complexityPanel->setReport(*outcome.report, outcome.params);
    updateHeatMapCount();
    m_complexityDock->show();
    m_complexityDock->raise();
    resizeDocks({m_complexityDock}, {m_complexityPanel->sizeHint().width()}, Qt::Horizontal);
    m_view->render();

    const QLocale locale;
    Message done;
    done.text =
        tr("Complexity measured with %1 cells in %2 s: %3 elements per cell at most, %4 on average")
            .arg(locale.toString(int(local.counts.size())),
                 locale.toString(outcome.milliseconds / 1000.0, 'f', 2),
                 locale.toString(local.statistics.max),
                 locale.toString(local.statistics.mean, 'f', 2));
    m_messages->addMessage(done);
    m_stageLabel->setText(tr("Complexity measured — see Complexity"));
}

void MainWindow::onComplexityFailed(const Message &error)
{
    endComplexityRun();
    Message shown = error;
    shown.text = tr("Complexity analysis failed: %1").arg(error.text);
    m_messages->addMessage(shown);
    m_messageDock->show();
    m_messageDock->raise();
    m_stageLabel->setText(tr("Complexity analysis failed — see Messages"));
}

void MainWindow::onComplexityCancelled()
{
    endComplexityRun();
    m_stageLabel->setText(tr("Complexity analysis cancelled"));
}

void MainWindow::setHeatMapVisible(bool visible)
{
    if (m_complexityPanel->heatMapVisible() != visible)
        m_complexityPanel->setHeatMapVisible(visible); // comes back here through the signal
    m_heatMap->setVisible(visible);
    m_view->render();
}

void MainWindow::setHeatMapThreshold(int threshold)
{
    if (m_complexityPanel->threshold() != threshold)
        m_complexityPanel->setThreshold(threshold);
    m_heatMap->setThreshold(threshold);
    updateHeatMapCount();
    m_view->render();
}

void MainWindow::updateHeatMapCount()
{
    const int total = m_complexityOutcome ? int(m_complexityOutcome->local().counts.size()) : 0;
    m_complexityPanel->setShownCells(m_heatMap->shownCellCount(), total);
}

void MainWindow::chooseCellsFile()
{
    if (!m_complexityOutcome)
        return;
    QSettings settings;
    const QString dir = settings.value(QStringLiteral("lastDirectory")).toString();
    QString path = QFileDialog::getSaveFileName(this, tr("Export Complexity Cells"), dir,
                                                tr("VTK unstructured grid (*.vtu)"));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().toLower() != QLatin1String("vtu"))
        path += QStringLiteral(".vtu");
    settings.setValue(QStringLiteral("lastDirectory"), QFileInfo(path).absolutePath());
    exportComplexityCells(path);
}

bool MainWindow::exportComplexityCells(const QString &path)
{
    if (!m_complexityOutcome)
        return false;
    Message message;
    message.file = path;
    try {
        // As the command line does (io/output_plan.h): never over the open model, checked before
        // writing, through a temporary file and a rename.
        OutputPlan plan({m_modelPath.toStdString()});
        plan.add(path.toStdString(), "complexity cells file");
        plan.write(path.toStdString(), [&](const std::string &temporary) {
            writeLocalComplexityVtu(temporary, m_complexityOutcome->local());
        });
        plan.commit();
        message.text = tr("Complexity cells exported");
        m_messages->addMessage(message);
        m_stageLabel->setText(tr("Saved %1").arg(QFileInfo(path).fileName()));
        return true;
    } catch (const std::exception &e) {
        message = errorMessage(e, path);
    }
    m_messages->addMessage(message);
    m_messageDock->show();
    m_messageDock->raise();
    m_stageLabel->setText(tr("Could not export the complexity cells"));
    return false;
}

} // namespace stratamesh
