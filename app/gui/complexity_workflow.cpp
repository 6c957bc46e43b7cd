#include "complexity_workflow.h"

#include "cell_heat_map.h"
#include "complexity_controller.h"
#include "complexity_dialog.h"
#include "complexity_panel.h"
#include "disabled_reason.h"
#include "error_message.h"
#include "vtk_view_widget.h"
#include "workbench.h"

#include "io/cells_vtu_writer.h"
#include "io/output_plan.h"

#include <QAction>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>
#include <QMainWindow>
#include <QSettings>
#include <QStyle>

namespace stratamesh {

ComplexityWorkflow::ComplexityWorkflow(Workbench &bench, QObject *parent)
    : Workflow(bench, parent), m_controller(new ComplexityController(this)),
      m_heatMap(std::make_unique<CellHeatMap>(bench.inputView()->renderer())),
      m_panel(new ComplexityPanel(bench.window())), m_dock(new QDockWidget(bench.window())),
      m_analyse(new QAction(this)), m_cancel(new QAction(this)), m_export(new QAction(this)),
      m_separator(separator())
{
    m_analyse->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_K));
    m_analyse->setEnabled(false);
    connect(m_analyse, &QAction::triggered, this, &ComplexityWorkflow::analyse);
    m_cancel->setIcon(bench.window()->style()->standardIcon(QStyle::SP_DialogCancelButton));
    m_cancel->setEnabled(false);
    connect(m_cancel, &QAction::triggered, this, &ComplexityWorkflow::cancel);
    m_export->setEnabled(false);
    connect(m_export, &QAction::triggered, this, &ComplexityWorkflow::chooseCellsFile);
    setDisabledReason(m_analyse, [this] {
        return !m_bench.model() ? tr("no model open") : tr("another step is running");
    });
    setDisabledReason(m_cancel, [] { return tr("no complexity analysis is running"); });
    setDisabledReason(m_export, [this] {
        return !m_outcome ? tr("no complexity analysis yet") : tr("another step is running");
    });

    m_dock->setObjectName(QStringLiteral("ComplexityDock"));
    m_dock->setWidget(m_panel);
    m_heatMap->setThreshold(m_panel->threshold());
    connect(m_panel, &ComplexityPanel::thresholdChanged, this,
            &ComplexityWorkflow::setHeatMapThreshold);
    connect(m_panel, &ComplexityPanel::heatMapVisibleChanged, this,
            &ComplexityWorkflow::setHeatMapVisible);

    connect(m_controller, &ComplexityController::started, this, &ComplexityWorkflow::onStarted);
    connect(m_controller, &ComplexityController::succeeded, this, &ComplexityWorkflow::onMeasured);
    connect(m_controller, &ComplexityController::failed, this, &ComplexityWorkflow::onFailed);
    connect(m_controller, &ComplexityController::cancelled, this, &ComplexityWorkflow::onCancelled);
    relay(m_controller);
}

// The heat map leaves the renderer only once no run can deliver cells to it.
ComplexityWorkflow::~ComplexityWorkflow()
{
    m_controller->disconnect(this);
    delete m_controller;
}

QList<QAction *> ComplexityWorkflow::menuActions(Menu menu) const
{
    if (menu == Menu::Analyse)
        return {m_analyse, m_cancel, m_separator, m_export};
    return {};
}

QList<Workflow::Dock> ComplexityWorkflow::docks() const
{
    return {{m_dock, DockPlace::Side}};
}

WorkflowJob *ComplexityWorkflow::job() const
{
    return m_controller;
}

void ComplexityWorkflow::retranslate()
{
    m_analyse->setText(tr("&Complexity…"));
    m_analyse->setStatusTip(
        tr("Measure the complexity of the model and show the elements per cell as a heat map"));
    m_cancel->setText(tr("C&ancel Complexity Analysis"));
    m_cancel->setStatusTip(tr("Stop the complexity analysis"));
    m_export->setText(tr("&Export Complexity Cells…"));
    m_export->setStatusTip(
        tr("Write the cells with their element counts as a VTK unstructured grid (.vtu)"));
    m_dock->setWindowTitle(tr("Complexity"));
    m_dock->toggleViewAction()->setText(tr("&Complexity"));
    m_heatMap->setTitle(tr("Elements\nper cell").toUtf8().constData());
}

void ComplexityWorkflow::clear()
{
    m_outcome.reset();
    m_heatMap->clear();
    m_panel->setReport(std::nullopt);
    m_dock->hide();
    m_export->setEnabled(false);
}

void ComplexityWorkflow::enableActions(bool busy)
{
    m_analyse->setEnabled(!busy && m_bench.model());
    m_export->setEnabled(!busy && m_outcome.has_value());
}

void ComplexityWorkflow::analyse()
{
    if (!m_bench.model() || m_bench.isBusy())
        return;
    ComplexityDialog dialog(m_bench.window());
    if (!m_lastParams.cells.empty())
        dialog.setParams(m_lastParams);
    if (dialog.exec() != QDialog::Accepted)
        return;
    start(dialog.params());
}

bool ComplexityWorkflow::start(const ComplexityParams &params)
{
    if (m_bench.isBusy())
        return false;
    m_lastParams = params;
    return m_controller->start(m_bench.model(), params);
}

void ComplexityWorkflow::onStarted()
{
    // The previous heat map goes: it would not match the figures being computed.
    clear();
    m_bench.inputView()->render();
    m_cancel->setEnabled(true);
    m_bench.setStatus(tr("Measuring the complexity of %1…").arg(m_bench.displayName()));
}

void ComplexityWorkflow::onMeasured(const ComplexityOutcome &outcome)
{
    m_outcome = outcome;
    m_cancel->setEnabled(false);
    const LocalComplexity &local = outcome.local();
    std::vector<int> counts;
    counts.reserve(local.counts.size());
    for (const CellElementCounts &c : local.counts)
        counts.push_back(c.total());
    m_heatMap->setThreshold(m_panel->threshold());
    m_heatMap->setVisible(m_panel->heatMapVisible());
    m_heatMap->setCells(outcome.cells, std::move(counts));
    m_panel->setReport(*outcome.report, outcome.params);
    updateHeatMapCount();
    m_dock->show();
    m_dock->raise();
    m_bench.window()->resizeDocks({m_dock}, {m_panel->sizeHint().width()}, Qt::Horizontal);
    m_bench.inputView()->render();

    const QLocale locale;
    Message done;
    done.text =
        tr("Complexity measured with %1 cells in %2 s: %3 elements per cell at most, %4 on average")
            .arg(locale.toString(int(local.counts.size())),
                 locale.toString(outcome.milliseconds / 1000.0, 'f', 2),
                 locale.toString(local.statistics.max),
                 locale.toString(local.statistics.mean, 'f', 2));
    m_bench.addMessage(done);
    m_bench.setStatus(tr("Complexity measured — see Complexity"));
}

void ComplexityWorkflow::onFailed(const Message &error)
{
    reportFailure(error, tr("Complexity analysis failed: %1").arg(error.text),
                  tr("Complexity analysis failed — see Messages"));
}

void ComplexityWorkflow::onCancelled()
{
    reportCancel(tr("Complexity analysis cancelled: no result, the model is unchanged"),
                 tr("Complexity analysis cancelled"));
}

void ComplexityWorkflow::setHeatMapVisible(bool visible)
{
    if (m_panel->heatMapVisible() != visible)
        m_panel->setHeatMapVisible(visible); // comes back here through the signal
    m_heatMap->setVisible(visible);
    m_bench.inputView()->render();
}

void ComplexityWorkflow::setHeatMapThreshold(int threshold)
{
    if (m_panel->threshold() != threshold)
        m_panel->setThreshold(threshold);
    m_heatMap->setThreshold(threshold);
    updateHeatMapCount();
    m_bench.inputView()->render();
}

void ComplexityWorkflow::updateHeatMapCount()
{
    const int total = m_outcome ? int(m_outcome->local().counts.size()) : 0;
    m_panel->setShownCells(m_heatMap->shownCellCount(), total);
}

void ComplexityWorkflow::chooseCellsFile()
{
    if (!m_outcome)
        return;
    QSettings settings;
    const QString dir = settings.value(QStringLiteral("lastDirectory")).toString();
    QString path = QFileDialog::getSaveFileName(m_bench.window(), tr("Export Complexity Cells"),
                                                dir, tr("VTK unstructured grid (*.vtu)"));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().toLower() != QLatin1String("vtu"))
        path += QStringLiteral(".vtu");
    settings.setValue(QStringLiteral("lastDirectory"), QFileInfo(path).absolutePath());
    exportCells(path);
}

bool ComplexityWorkflow::exportCells(const QString &path)
{
    if (!m_outcome)
        return false;
    Message message;
    message.file = path;
    try {
        // As the command line does (io/output_plan.h): never over the open model, checked before
        // writing, through a temporary file and a rename.
        OutputPlan plan({m_bench.modelPath().toStdString()});
        plan.add(path.toStdString(), "complexity cells file");
        plan.write(path.toStdString(), [&](const std::string &temporary) {
            writeLocalComplexityVtu(temporary, m_outcome->local());
        });
        plan.commit();
        message.text = tr("Complexity cells exported");
        m_bench.addMessage(message);
        m_bench.setStatus(tr("Saved %1").arg(QFileInfo(path).fileName()));
        return true;
    } catch (const std::exception &e) {
        message = errorMessage(e, path);
    }
    m_bench.addMessage(message);
    m_bench.showMessages();
    m_bench.setStatus(tr("Could not export the complexity cells"));
    return false;
}

} // namespace stratamesh
