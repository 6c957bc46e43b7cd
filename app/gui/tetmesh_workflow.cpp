#include "tetmesh_workflow.h"

#include "comparison_table.h"
#include "disabled_reason.h"
#include "model_scene.h"
#include "remesh_workflow.h"
#include "tet_mesh_pair.h"
#include "tetmesh_controller.h"
#include "tetmesh_dialog.h"
#include "tetmesh_panel.h"
#include "vtk_view_widget.h"
#include "workbench.h"

#include <QAction>
#include <QDockWidget>
#include <QLayout>
#include <QLocale>
#include <QMainWindow>
#include <QStyle>

namespace stratamesh {

TetmeshWorkflow::TetmeshWorkflow(Workbench &bench, const RemeshWorkflow &remesh, QObject *parent)
    : Workflow(bench, parent), m_remesh(remesh), m_controller(new TetmeshController(this)),
      m_scenes(std::make_unique<TetMeshPair>(bench.inputView()->renderer(),
                                             bench.outputView()->renderer())),
      m_panel(new TetmeshPanel(bench.window())), m_dock(new QDockWidget(bench.window())),
      m_separator(separator()), m_tetmesh(new QAction(this)), m_cancel(new QAction(this))
{
    m_tetmesh->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_T));
    m_tetmesh->setEnabled(false);
    connect(m_tetmesh, &QAction::triggered, this, &TetmeshWorkflow::tetrahedralise);
    m_cancel->setIcon(bench.window()->style()->standardIcon(QStyle::SP_DialogCancelButton));
    m_cancel->setEnabled(false);
    connect(m_cancel, &QAction::triggered, this, &TetmeshWorkflow::cancel);
    setDisabledReason(m_tetmesh, [this] {
        return !m_bench.model() ? tr("no model open") : tr("another step is running");
    });
    setDisabledReason(m_cancel, [] { return tr("TetGen is not running"); });

    m_dock->setObjectName(QStringLiteral("TetrahedraDock"));
    m_dock->setWidget(m_panel);
    connect(m_panel, &TetmeshPanel::colouringChanged, this, &TetmeshWorkflow::applyTetView);
    connect(m_panel, &TetmeshPanel::clipChanged, this, &TetmeshWorkflow::applyTetView);
    connect(&remesh, &RemeshWorkflow::outputReplaced, this, &TetmeshWorkflow::clear);

    connect(m_controller, &TetmeshController::started, this, &TetmeshWorkflow::onStarted);
    connect(m_controller, &TetmeshController::succeeded, this, &TetmeshWorkflow::onTetmeshed);
    connect(m_controller, &TetmeshController::failed, this, &TetmeshWorkflow::onFailed);
    connect(m_controller, &TetmeshController::cancelled, this, &TetmeshWorkflow::onCancelled);
    relay(m_controller);
}

TetmeshWorkflow::~TetmeshWorkflow()
{
    m_controller->disconnect(this);
    delete m_controller;
}

QList<QAction *> TetmeshWorkflow::menuActions(Menu menu) const
{
    if (menu == Menu::Mesh)
        return {m_separator, m_tetmesh, m_cancel};
    return {};
}

// Tabbed with Quality, which shows the tets' histograms: stacked, neither would have the height
// its table and charts need on a laptop screen.
QList<Workflow::Dock> TetmeshWorkflow::docks() const
{
    return {{m_dock, DockPlace::Review}};
}

WorkflowJob *TetmeshWorkflow::job() const
{
    return m_controller;
}

void TetmeshWorkflow::retranslate()
{
    m_tetmesh->setText(tr("&Tetrahedralise…"));
    m_tetmesh->setStatusTip(tr("Mesh the regions of the input and of the remesh with TetGen and "
                               "compare the tetrahedra"));
    m_cancel->setText(tr("Cancel &Tetrahedralisation"));
    m_cancel->setStatusTip(tr("Stop TetGen; nothing is kept of this run"));
    m_dock->setWindowTitle(tr("Tetrahedra"));
    m_dock->toggleViewAction()->setText(tr("&Tetrahedra"));
    m_scenes->setTitles(tr("Region").toUtf8().constData(),
                        tr("Min dihedral\nangle (°)").toUtf8().constData());
}

void TetmeshWorkflow::clear()
{
    m_outcome.reset();
    m_scenes->clear();
    m_panel->setSides(nullptr, nullptr);
    m_remesh.comparisonTable()->setTetQuality(nullptr, nullptr);
    m_dock->hide();
    m_bench.inputScene()->setVisible(true);
    m_bench.outputScene()->setVisible(true);
    m_bench.updateLegend();
    m_bench.render();
}

void TetmeshWorkflow::enableActions(bool busy)
{
    m_tetmesh->setEnabled(!busy && m_bench.model());
}

void TetmeshWorkflow::tetrahedralise()
{
    if (!m_bench.model() || m_bench.isBusy())
        return;
    TetmeshDialog dialog(m_remesh.outcome().has_value(), m_bench.inputScene()->diagonal(),
                         m_bench.window());
    if (m_lastParams)
        dialog.setParams(*m_lastParams);
    if (dialog.exec() != QDialog::Accepted)
        return;
    start(dialog.params(), dialog.bothModels());
}

bool TetmeshWorkflow::start(const TetgenParams &params, bool withRemesh)
{
    if (m_bench.isBusy() || !m_bench.model())
        return false;
    m_lastParams = params;
    const auto &remesh = m_remesh.outcome();
    std::shared_ptr<const Model> output = withRemesh && remesh ? remesh->output : nullptr;
    return m_controller->start(m_bench.model(), std::move(output), params);
}

void TetmeshWorkflow::onStarted()
{
    clear();
    m_cancel->setEnabled(true);
    m_bench.setStatus(tr("Tetrahedralising %1…").arg(m_bench.displayName()));
}

void TetmeshWorkflow::onTetmeshed(const TetmeshOutcome &outcome)
{
    m_outcome = outcome;
    m_cancel->setEnabled(false);
    // A side TetGen failed on keeps its surfaces on screen; its failure is in the table.
    const auto inputMesh = TetmeshOutcome::meshOf(outcome.inputSide);
    const auto outputMesh = TetmeshOutcome::meshOf(outcome.outputSide);
    m_scenes->setMeshes(inputMesh, outputMesh);
    m_bench.inputScene()->setVisible(!inputMesh);
    m_bench.outputScene()->setVisible(!outputMesh);
    m_bench.updateLegend();
    applyTetView();
    m_dock->show();
    m_panel->setSides(outcome.inputSide.get(), outcome.outputSide.get());
    // The distributions go to the Quality tab, overlaid as the triangles' are (a failed side has
    // empty histograms in the same bins). Shown first: the charts lay their axis labels out for
    // the size they are given.
    m_remesh.comparisonDock()->show();
    m_remesh.comparisonDock()->raise();
    m_remesh.comparisonTable()->setTetQuality(
        outcome.inputSide ? &outcome.inputSide->quality : nullptr,
        outcome.outputSide ? &outcome.outputSide->quality : nullptr);
    m_remesh.comparisonTable()->showTetQuality();
    m_bench.window()->resizeDocks({m_dock}, {m_panel->sizeHint().width()}, Qt::Horizontal);
    // The views were resized by the dock: frame the model for their final sizes.
    m_bench.window()->layout()->activate();
    m_bench.resetCamera();

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
        m_bench.addMessage(m);
    }
    m_bench.setStatus(allOk ? tr("Tetrahedralised — see Tetrahedra and Quality")
                            : tr("TetGen failed on a model — see Tetrahedra"));
}

void TetmeshWorkflow::onFailed(const Message &error)
{
    reportFailure(error, tr("Tetrahedralisation failed: %1").arg(error.text),
                  tr("Tetrahedralisation failed — see Messages"));
}

void TetmeshWorkflow::onCancelled()
{
    reportCancel(tr("Tetrahedralisation cancelled: the previous meshes, if any, are kept"),
                 tr("Tetrahedralisation cancelled"));
}

void TetmeshWorkflow::applyTetView()
{
    m_scenes->setColouring(m_panel->colouring());
    m_scenes->setClip(m_panel->clipEnabled(), m_panel->clipAxis(), m_panel->clipFraction());
    m_bench.render();
}

} // namespace stratamesh
