#include "model_tree_workflow.h"

#include "entity_highlight.h"
#include "model_scene.h"
#include "model_tree_panel.h"
#include "open_workflow.h"
#include "remesh_workflow.h"
#include "triangle_pick.h"
#include "vtk_view_widget.h"
#include "workbench.h"

#include "quality/triangle_quality.h"

#include <QAction>
#include <QDockWidget>
#include <QLocale>
#include <QMainWindow>
#include <QToolTip>
#include <QUndoCommand>
#include <QUndoStack>

#include <vtkRenderer.h>

#include <cmath>

namespace stratamesh {

namespace {

// One check or uncheck in the tree: the surfaces whose visibility it changed, all one way.
class SurfaceVisibilityCommand : public QUndoCommand {
public:
    SurfaceVisibilityCommand(ModelTreeWorkflow &workflow, QList<int> surfaces, bool visible,
                             const QString &text)
        : QUndoCommand(text), m_workflow(workflow), m_surfaces(std::move(surfaces)),
          m_visible(visible)
    {
    }
    void redo() override { m_workflow.applySurfacesVisible(m_surfaces, m_visible); }
    void undo() override { m_workflow.applySurfacesVisible(m_surfaces, !m_visible); }

private:
    ModelTreeWorkflow &m_workflow;
    QList<int> m_surfaces;
    bool m_visible;
};

std::vector<int> toVector(const QList<int> &list)
{
    return std::vector<int>(list.begin(), list.end());
}

} // namespace

ModelTreeWorkflow::ModelTreeWorkflow(Workbench &bench, OpenWorkflow &open, RemeshWorkflow &remesh,
                                     QObject *parent)
    : Workflow(bench, parent), m_panel(new ModelTreePanel(bench.window())),
      m_dock(new QDockWidget(bench.window())),
      m_inputHighlight(std::make_unique<EntityHighlight>(bench.inputView()->renderer())),
      m_outputHighlight(std::make_unique<EntityHighlight>(bench.outputView()->renderer()))
{
    m_dock->setObjectName(QStringLiteral("ModelTreeDock"));
    m_dock->setWidget(m_panel);
    // The open workflow finishes once the window shows the model (after every clear()).
    connect(&open, &Workflow::finished, this, [this](bool ok) {
        if (ok)
            refresh();
    });
    // A new output is drawn with every surface: the tree's choices and selection apply to it.
    connect(&remesh, &Workflow::finished, this, [this] {
        applyOutputVisibility();
        highlightOutput(m_panel->selectedIndex());
        m_bench.render();
    });
    connect(m_panel->treeModel(), &ModelTreeModel::visibilityRequested, this,
            &ModelTreeWorkflow::requestVisibility);
    connect(m_panel, &ModelTreePanel::selected, this, &ModelTreeWorkflow::onSelected);
    QAction *showBox = bench.showBoxAction();
    connect(m_panel, &ModelTreePanel::boxToggled, showBox, &QAction::setChecked);
    connect(showBox, &QAction::toggled, m_panel, &ModelTreePanel::setBoxShown);
    connect(bench.inputView(), &VtkViewWidget::clicked, this,
            [this](double x, double y) { inspect(false, x, y); });
    connect(bench.outputView(), &VtkViewWidget::clicked, this,
            [this](double x, double y) { inspect(true, x, y); });
    connect(bench.inputView(), &VtkViewWidget::hovered, this,
            [this](double x, double y) { hover(false, x, y); });
    connect(bench.outputView(), &VtkViewWidget::hovered, this,
            [this](double x, double y) { hover(true, x, y); });
    for (VtkViewWidget *view : {bench.inputView(), bench.outputView()})
        connect(view, &VtkViewWidget::hoverEnded, this, [] { QToolTip::hideText(); });
}

ModelTreeWorkflow::~ModelTreeWorkflow() = default;

QList<Workflow::Dock> ModelTreeWorkflow::docks() const
{
    return {{m_dock, DockPlace::Left}};
}

void ModelTreeWorkflow::retranslate()
{
    m_dock->setWindowTitle(tr("Model"));
    m_dock->toggleViewAction()->setText(tr("Model &Tree"));
    m_panel->retranslate();
}

void ModelTreeWorkflow::clear()
{
    m_inputHighlight->hide();
    m_outputHighlight->hide();
    m_panel->setModel(nullptr);
}

void ModelTreeWorkflow::refresh()
{
    m_inputHighlight->hide();
    m_outputHighlight->hide();
    m_panel->setModel(m_bench.model());
    m_panel->setBoxShown(m_bench.showBoxAction()->isChecked());
    if (m_bench.model())
        m_dock->show();
    m_bench.render();
}

void ModelTreeWorkflow::requestVisibility(const QList<int> &surfaces, bool visible)
{
    const auto &model = m_bench.model();
    if (!model || surfaces.isEmpty())
        return;
    const QString what =
        surfaces.size() == 1
            ? QString::fromStdString(model->surfaces[std::size_t(surfaces[0])].name)
            : tr("%n surface(s)", nullptr, int(surfaces.size()));
    const QString text = visible ? tr("Show %1").arg(what) : tr("Hide %1").arg(what);
    m_bench.undoStack()->push(new SurfaceVisibilityCommand(*this, surfaces, visible, text));
}

void ModelTreeWorkflow::applySurfacesVisible(const QList<int> &surfaces, bool visible)
{
    m_panel->treeModel()->setSurfacesVisible(surfaces, visible);
    for (int s : surfaces)
        m_bench.inputScene()->setSurfaceVisible(s, visible);
    applyOutputVisibility();
    m_bench.render();
}

int ModelTreeWorkflow::outputSurface(int inputSurface) const
{
    const auto &input = m_bench.model();
    const auto &output = m_bench.outputScene()->model();
    if (!input || !output || inputSurface < 0
        || std::size_t(inputSurface) >= input->surfaces.size())
        return -1;
    const std::string &name = input->surfaces[std::size_t(inputSurface)].name;
    for (std::size_t s = 0; s < output->surfaces.size(); ++s)
        if (output->surfaces[s].name == name)
            return int(s);
    return -1;
}

// The remesher keeps the input's surface names, so the output follows the tree by name.
void ModelTreeWorkflow::applyOutputVisibility()
{
    const auto &input = m_bench.model();
    if (!input || !m_bench.outputScene()->model())
        return;
    for (std::size_t s = 0; s < input->surfaces.size(); ++s)
        m_bench.outputScene()->setSurfaceVisible(outputSurface(int(s)),
                                                 m_panel->treeModel()->surfaceVisible(int(s)));
}

void ModelTreeWorkflow::onSelected(const QModelIndex &index)
{
    const ModelTreeModel *tree = m_panel->treeModel();
    const auto &model = m_bench.model();
    m_inputHighlight->hide();
    if (model && index.isValid()) {
        switch (tree->kind(index)) {
        case ModelTreeModel::Kind::Line:
            m_inputHighlight->showLine(*model, tree->entity(index));
            break;
        case ModelTreeModel::Kind::Corner:
            m_inputHighlight->showCorner(*model, tree->entity(index), 0.01 * m_bench.diagonal());
            break;
        default:
            m_inputHighlight->showSurfaces(*m_bench.inputScene(),
                                           toVector(tree->surfacesOf(index)));
            break;
        }
        m_bench.setStatus(tree->describe(index));
    }
    highlightOutput(index);
    m_bench.render();
}

// Surfaces by name; a corner is a place, the same in both views. The output's lines are its own.
void ModelTreeWorkflow::highlightOutput(const QModelIndex &index)
{
    m_outputHighlight->hide();
    const ModelTreeModel *tree = m_panel->treeModel();
    const auto &model = m_bench.model();
    if (!model || !index.isValid() || !m_bench.outputScene()->model())
        return;
    switch (tree->kind(index)) {
    case ModelTreeModel::Kind::Line:
        return;
    case ModelTreeModel::Kind::Corner:
        m_outputHighlight->showCorner(*model, tree->entity(index), 0.01 * m_bench.diagonal());
        return;
    default:
        break;
    }
    std::vector<int> surfaces;
    for (int s : tree->surfacesOf(index))
        if (const int o = outputSurface(s); o >= 0)
            surfaces.push_back(o);
    m_outputHighlight->showSurfaces(*m_bench.outputScene(), surfaces);
}

std::optional<ModelTreeWorkflow::Description> ModelTreeWorkflow::describe(bool output, double x,
                                                                          double y) const
{
    const ModelScene *scene = output ? m_bench.outputScene() : m_bench.inputScene();
    VtkViewWidget *view = output ? m_bench.outputView() : m_bench.inputView();
    const auto pick = pickTriangle(*scene, view->renderer(), x, y);
    if (!pick)
        return std::nullopt;
    const Surface &surface = scene->model()->surfaces[std::size_t(pick->surface)];
    const Triangle &t = surface.triangles[std::size_t(pick->triangle)];
    const TriangleShape shape =
        triangleShape(surface.vertices[std::size_t(t[0])], surface.vertices[std::size_t(t[1])],
                      surface.vertices[std::size_t(t[2])]);
    Description d;
    // The tree lists the input: an output surface is found there by its name.
    d.inputSurface = pick->surface;
    if (output) {
        d.inputSurface = -1;
        const auto &input = m_bench.model();
        for (std::size_t s = 0; input && s < input->surfaces.size(); ++s)
            if (input->surfaces[s].name == surface.name)
                d.inputSurface = int(s);
    }
    const QLocale locale;
    d.text = (output ? tr("Output surface %1, triangle %2: min angle %3°, Q = %4")
                     : tr("Surface %1, triangle %2: min angle %3°, Q = %4"))
                 .arg(QString::fromStdString(surface.name), QString::number(pick->triangle),
                      locale.toString(shape.minAngleDeg, 'f', 1),
                      locale.toString(shape.quality, 'f', 3));
    return d;
}

bool ModelTreeWorkflow::inspect(bool output, double x, double y)
{
    const auto d = describe(output, x, y);
    if (!d)
        return false;
    if (d->inputSurface >= 0)
        m_panel->selectEntity(ModelTreeModel::Kind::Surface, d->inputSurface);
    m_bench.setStatus(d->text);
    return true;
}

QString ModelTreeWorkflow::hover(bool output, double x, double y)
{
    VtkViewWidget *view = output ? m_bench.outputView() : m_bench.inputView();
    const auto d = describe(output, x, y);
    if (!d) {
        QToolTip::hideText();
        return {};
    }
    // Back from VTK display pixels (origin bottom left) to the widget's own coordinates.
    const qreal ratio = view->devicePixelRatioF();
    const QPoint local(int(std::lround(x / ratio)),
                       int(std::lround((view->height() * ratio - y - 1.0) / ratio)));
    QToolTip::showText(view->mapToGlobal(local), d->text, view);
    return d->text;
}

} // namespace stratamesh
