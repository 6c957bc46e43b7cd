#include "hybrid_workflow.h"

#include "disabled_reason.h"
#include "error_message.h"
#include "hybrid_controller.h"
#include "hybrid_dialog.h"
#include "hybrid_panel.h"
#include "model_scene.h"
#include "remesh_workflow.h"
#include "tet_mesh_pair.h"
#include "tetmesh_controller.h"
#include "tetmesh_workflow.h"
#include "view_pair.h"
#include "vtk_view_widget.h"
#include "workbench.h"

#include "common/error.h"
#include "io/mesh_writer.h"
#include "io/output_plan.h"

#include <QAction>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLayout>
#include <QLocale>
#include <QMainWindow>
#include <QSettings>
#include <QStyle>

namespace stratamesh {

namespace {

bool isMeshFile(const QString &path)
{
    const QString ext = QFileInfo(path).suffix().toLower();
    return ext == QLatin1String("vtu") || ext == QLatin1String("msh");
}

} // namespace

HybridWorkflow::HybridWorkflow(Workbench &bench, const RemeshWorkflow &remesh,
                               TetmeshWorkflow &tetmesh, QObject *parent)
    : Workflow(bench, parent), m_remesh(remesh), m_tetmesh(tetmesh),
      m_controller(new HybridController(this)),
      m_scenes(std::make_unique<TetMeshPair>(bench.inputView()->renderer(),
                                             bench.outputView()->renderer())),
      m_panel(new HybridPanel(bench.window())), m_dock(new QDockWidget(bench.window())),
      m_separator(separator()), m_hybrid(new QAction(this)), m_cancel(new QAction(this)),
      m_save(new QAction(this))
{
    const QStyle *style = bench.window()->style();
    m_hybrid->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_H));
    m_hybrid->setEnabled(false);
    connect(m_hybrid, &QAction::triggered, this, &HybridWorkflow::buildMesh);
    m_cancel->setIcon(style->standardIcon(QStyle::SP_DialogCancelButton));
    m_cancel->setEnabled(false);
    connect(m_cancel, &QAction::triggered, this, &HybridWorkflow::cancel);
    m_save->setIcon(style->standardIcon(QStyle::SP_DialogSaveButton));
    m_save->setEnabled(false);
    connect(m_save, &QAction::triggered, this, &HybridWorkflow::chooseFile);
    setDisabledReason(m_hybrid, [this] {
        return !m_bench.model() ? tr("no model open") : tr("another step is running");
    });
    setDisabledReason(m_cancel, [] { return tr("no hybrid mesh is being built"); });
    setDisabledReason(m_save, [this] {
        return !m_outcome ? tr("no hybrid mesh yet") : tr("another step is running");
    });
    m_scenes->setColouring(m_panel->colouring());

    m_dock->setObjectName(QStringLiteral("HybridMeshDock"));
    m_dock->setWidget(m_panel);
    connect(m_panel, &HybridPanel::colouringChanged, this, &HybridWorkflow::applyView);
    connect(m_panel, &HybridPanel::clipChanged, this, &HybridWorkflow::applyView);
    // Both take the output view: the hybrid mesh steps aside, kept for saving.
    connect(&remesh, &RemeshWorkflow::outputReplaced, this, &HybridWorkflow::hideMesh);
    connect(tetmesh.controller(), &TetmeshController::started, this, &HybridWorkflow::hideMesh);

    connect(m_controller, &HybridController::started, this, &HybridWorkflow::onStarted);
    connect(m_controller, &HybridController::succeeded, this, &HybridWorkflow::onBuilt);
    connect(m_controller, &HybridController::failed, this, &HybridWorkflow::onFailed);
    connect(m_controller, &HybridController::cancelled, this, &HybridWorkflow::onCancelled);
    relay(m_controller);
}

HybridWorkflow::~HybridWorkflow()
{
    m_controller->disconnect(this);
    delete m_controller;
}

QList<QAction *> HybridWorkflow::menuActions(Menu menu) const
{
    switch (menu) {
    case Menu::File:
        return {m_save};
    case Menu::Mesh:
        return {m_separator, m_hybrid, m_cancel};
    case Menu::Edit:
    case Menu::View:
    case Menu::Analyse:
        break;
    }
    return {};
}

QList<Workflow::Dock> HybridWorkflow::docks() const
{
    return {{m_dock, DockPlace::Review}};
}

WorkflowJob *HybridWorkflow::job() const
{
    return m_controller;
}

void HybridWorkflow::retranslate()
{
    m_hybrid->setText(tr("&Hybrid Mesh…"));
    m_hybrid->setStatusTip(
        tr("Mesh the regions with prisms in the thin layers, tetrahedra elsewhere and pyramids "
           "between them"));
    m_cancel->setText(tr("Cancel &Hybrid Mesh"));
    m_cancel->setStatusTip(tr("Stop the hybrid mesher; the previous hybrid mesh is kept"));
    m_save->setText(tr("Save &Hybrid Mesh As…"));
    m_save->setStatusTip(tr("Write the hybrid mesh as a VTK (.vtu) or Gmsh (.msh) file"));
    m_dock->setWindowTitle(tr("Hybrid Mesh"));
    m_dock->toggleViewAction()->setText(tr("&Hybrid Mesh"));
    m_scenes->setTitles(tr("Region").toUtf8().constData(),
                        tr("Min dihedral\nangle (°)").toUtf8().constData());
    const std::array<std::string, 3> names{tr("tetrahedron").toStdString(),
                                           tr("pyramid").toStdString(), tr("prism").toStdString()};
    m_scenes->output().setTypeTitles(tr("Cell type").toUtf8().constData(), names);
    updateTitles();
}

void HybridWorkflow::clear()
{
    m_outcome.reset();
    hideMesh();
    m_panel->setStatistics(nullptr);
    m_dock->hide();
    m_save->setEnabled(false);
}

void HybridWorkflow::enableActions(bool busy)
{
    m_hybrid->setEnabled(!busy && m_bench.model());
    m_save->setEnabled(!busy && m_outcome.has_value());
}

void HybridWorkflow::buildMesh()
{
    if (!m_bench.model() || m_bench.isBusy())
        return;
    HybridDialog dialog(m_bench.inputScene()->diagonal(), m_bench.window());
    if (m_lastParams)
        dialog.setParams(*m_lastParams);
    if (dialog.exec() != QDialog::Accepted)
        return;
    start(dialog.params());
}

bool HybridWorkflow::start(const HybridParams &params)
{
    if (m_bench.isBusy() || !m_bench.model())
        return false;
    m_lastParams = params;
    return m_controller->start(m_bench.model(), params);
}

// The previous mesh stays on screen until this one is made: a cancel leaves it.
void HybridWorkflow::onStarted()
{
    m_cancel->setEnabled(true);
    m_bench.setStatus(tr("Building the hybrid mesh of %1…").arg(m_bench.displayName()));
}

void HybridWorkflow::onBuilt(const HybridOutcome &outcome)
{
    m_outcome = outcome;
    m_cancel->setEnabled(false);
    showMesh();
    m_dock->show();
    m_dock->raise();
    m_panel->setStatistics(&outcome.statistics);
    m_bench.window()->resizeDocks({m_dock}, {m_panel->sizeHint().width()}, Qt::Horizontal);
    m_bench.window()->layout()->activate();
    m_bench.resetCamera();

    const QLocale locale;
    const auto count = [&](CellType type) {
        return locale.toString(qulonglong(outcome.statistics.byType[std::size_t(type)].cells));
    };
    Message m;
    m.severity = outcome.statistics.valid ? Message::Severity::Info : Message::Severity::Warning;
    m.text =
        tr("Hybrid mesh: %1 tetrahedra, %2 pyramids, %3 prisms, %4 in %5 s")
            .arg(count(CellType::Tet), count(CellType::Pyramid), count(CellType::Prism),
                 outcome.statistics.valid ? tr("valid")
                                          : tr("not valid (%1)").arg(outcome.statistics.message),
                 locale.toString(outcome.statistics.seconds, 'f', 2));
    m_bench.addMessage(m);
    if (!outcome.statistics.valid)
        m_bench.showMessages();
    m_bench.setStatus(outcome.statistics.valid ? tr("Hybrid mesh built — see Hybrid Mesh")
                                               : tr("The hybrid mesh is not valid — see Messages"));
}

void HybridWorkflow::onFailed(const Message &error)
{
    reportFailure(error, tr("Hybrid meshing failed: %1").arg(error.text),
                  tr("Hybrid meshing failed — see Messages"));
}

void HybridWorkflow::onCancelled()
{
    reportCancel(m_outcome ? tr("Hybrid meshing cancelled; the previous mesh is kept")
                           : tr("Hybrid meshing cancelled: no mesh"),
                 tr("Hybrid meshing cancelled"));
}

// One drawing in the output view at a time: the TetGen meshes give way.
void HybridWorkflow::showMesh()
{
    if (!m_outcome)
        return;
    m_tetmesh.clear();
    m_scenes->setMeshes(nullptr, m_outcome->mesh());
    m_bench.outputScene()->setVisible(false);
    m_bench.views()->setOutputShown(true);
    m_bench.updateLegend();
    updateTitles();
    applyView();
}

void HybridWorkflow::hideMesh()
{
    if (!m_scenes->hasMesh())
        return;
    m_scenes->clear();
    m_bench.outputScene()->setVisible(true);
    m_bench.views()->setOutputShown(m_remesh.outcome().has_value());
    m_bench.updateLegend();
    m_bench.render();
}

void HybridWorkflow::applyView()
{
    m_scenes->setColouring(m_panel->colouring());
    m_scenes->setClip(m_panel->clipEnabled(), m_panel->clipAxis(), m_panel->clipFraction());
    m_bench.render();
}

void HybridWorkflow::updateTitles()
{
    if (!m_outcome || !m_scenes->hasMesh())
        return;
    const QLocale locale;
    m_bench.views()->setTitles(
        tr("Input: %1").arg(m_bench.displayName()),
        tr("Hybrid mesh: %1 cells, %2 sites")
            .arg(locale.toString(qulonglong(m_outcome->result->mesh.cells.size())),
                 locale.toString(m_outcome->params.sites)));
}

void HybridWorkflow::chooseFile()
{
    if (!m_outcome)
        return;
    QSettings settings;
    const QString dir = settings.value(QStringLiteral("lastDirectory")).toString();
    const QString vtu = tr("VTK unstructured grid (*.vtu)");
    const QString msh = tr("Gmsh mesh (*.msh)");
    QString selected;
    QString path = QFileDialog::getSaveFileName(m_bench.window(), tr("Save Hybrid Mesh"), dir,
                                                vtu + QStringLiteral(";;") + msh, &selected);
    if (path.isEmpty())
        return;
    if (!isMeshFile(path))
        path += selected == msh ? QStringLiteral(".msh") : QStringLiteral(".vtu");
    settings.setValue(QStringLiteral("lastDirectory"), QFileInfo(path).absolutePath());
    save(path);
}

bool HybridWorkflow::save(const QString &path)
{
    if (!m_outcome)
        return false;
    Message message;
    message.file = path;
    try {
        // The formats that keep pyramids and prisms, as the command line allows.
        if (!isMeshFile(path))
            throw FileError(path.toStdString(), 0,
                            tr("a hybrid mesh is saved as a .vtu or .msh file").toStdString());
        // As the command line does (io/output_plan.h): never over the open model, checked before
        // writing, through a temporary file (which keeps the extension) and a rename.
        OutputPlan plan({m_bench.modelPath().toStdString()});
        plan.add(path.toStdString(), "hybrid mesh");
        plan.write(path.toStdString(), [&](const std::string &temporary) {
            exportVolumeMesh(m_outcome->result->mesh, temporary);
        });
        plan.commit();
        message.text = tr("Hybrid mesh saved");
        m_bench.addMessage(message);
        m_bench.setStatus(tr("Saved %1").arg(QFileInfo(path).fileName()));
        return true;
    } catch (const std::exception &e) {
        message = errorMessage(e, path);
    }
    m_bench.addMessage(message);
    m_bench.showMessages();
    m_bench.setStatus(tr("Could not save the hybrid mesh"));
    return false;
}

} // namespace stratamesh
