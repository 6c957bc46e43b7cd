#include "steps_workflow.h"

#include "complexity_workflow.h"
#include "export_workflow.h"
#include "hybrid_workflow.h"
#include "loaded_model.h"
#include "open_workflow.h"
#include "remesh_workflow.h"
#include "step_list.h"
#include "tetmesh_workflow.h"
#include "workbench.h"

#include <QAction>
#include <QDockWidget>
#include <QLocale>
#include <QMainWindow>
#include <QScrollArea>

#include <algorithm>

namespace stratamesh {

StepsWorkflow::StepsWorkflow(Workbench &bench, OpenWorkflow &open, ComplexityWorkflow &complexity,
                             RemeshWorkflow &remesh, TetmeshWorkflow &tetmesh,
                             HybridWorkflow &hybrid, ExportWorkflow &exporter, QObject *parent)
    : Workflow(bench, parent), m_open(open), m_complexity(complexity), m_remesh(remesh),
      m_tetmesh(tetmesh), m_hybrid(hybrid), m_steps(new StepList),
      m_dock(new QDockWidget(bench.window())), m_showProblems(new QAction(this))
{
    m_showProblems->setEnabled(false);
    connect(m_showProblems, &QAction::triggered, this, [this] { m_bench.showMessages(); });
    m_steps->addStep({m_showProblems});
    m_steps->addStep({complexity.analyseAction()});
    m_steps->addStep({remesh.remeshAction()});
    m_steps->addStep({tetmesh.tetmeshAction(), hybrid.hybridAction()});
    m_steps->addStep({exporter.exportAction()});
    m_dock->setObjectName(QStringLiteral("StepsDock"));
    // The steps keep their height and scroll in a short dock, rather than squeezing their texts.
    auto *scroll = new QScrollArea(m_dock);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(m_steps);
    m_dock->setWidget(scroll);

    connect(&open, &OpenWorkflow::opened, this, &StepsWorkflow::onOpened);
    for (Workflow *w : std::initializer_list<Workflow *>{&complexity, &remesh, &tetmesh, &hybrid})
        connect(w, &Workflow::finished, this, &StepsWorkflow::refresh);
    // A run chosen in the Runs dock, or read from a project, is shown without a run finishing.
    connect(&remesh, &RemeshWorkflow::outputReplaced, this, &StepsWorkflow::refresh,
            Qt::QueuedConnection);
    retranslate();
}

QList<Workflow::Dock> StepsWorkflow::docks() const
{
    return {{m_dock, DockPlace::Left}};
}

void StepsWorkflow::onOpened(const LoadedModel &loaded)
{
    m_problems =
        int(std::count_if(loaded.messages.begin(), loaded.messages.end(), [](const Message &m) {
            return m.severity == Message::Severity::Warning
                   || m.severity == Message::Severity::Error;
        }));
    m_showProblems->setEnabled(true);
    refresh();
}

void StepsWorkflow::clear()
{
    refresh();
}

void StepsWorkflow::enableActions(bool busy)
{
    m_showProblems->setEnabled(!busy && m_problems >= 0);
}

void StepsWorkflow::retranslate()
{
    m_dock->setWindowTitle(tr("Steps"));
    m_dock->toggleViewAction()->setText(tr("S&teps"));
    m_showProblems->setText(tr("Show Problems"));
    m_showProblems->setToolTip(tr("Show the Messages, where each validity problem of the model is "
                                  "listed; a click on one flies the views to it"));
    m_steps->setTitle(Check, tr("Check"));
    m_steps->setTitle(Complexity, tr("Complexity"));
    m_steps->setTitle(Remesh, tr("Remesh"));
    m_steps->setTitle(Volume, tr("Volume"));
    m_steps->setTitle(Export, tr("Export"));
    refresh();
}

void StepsWorkflow::refresh()
{
    const QLocale locale;
    if (m_problems < 0)
        m_steps->setStatus(Check, tr("Open a model (File > Open Model…)."), false);
    else if (m_problems == 0)
        m_steps->setStatus(Check, tr("%1: no validity problem found.").arg(m_bench.displayName()),
                           true);
    else
        m_steps->setStatus(Check,
                           tr("%1: %n validity problem(s) — see Messages.", nullptr, m_problems)
                               .arg(m_bench.displayName()),
                           true);

    if (const auto &c = m_complexity.outcome())
        m_steps->setStatus(Complexity,
                           tr("Measured with %1 Voronoi cells.")
                               .arg(locale.toString(qlonglong(c->params.cells.front()))),
                           true);
    else
        m_steps->setStatus(Complexity, tr("Elements per Voronoi cell as a heat map (ch. 3)."),
                           false);

    if (const auto &r = m_remesh.outcome())
        m_steps->setStatus(Remesh,
                           tr("%1 sites: %2 vertices, %3 triangles, %4.")
                               .arg(locale.toString(r->siteCount))
                               .arg(locale.toString(qlonglong(r->comparison.output.mesh.vertices)))
                               .arg(locale.toString(qlonglong(r->comparison.output.mesh.triangles)))
                               .arg(r->validity.valid ? tr("valid") : tr("not valid")),
                           true);
    else
        m_steps->setStatus(Remesh, tr("All surfaces at once at a chosen resolution (ch. 4)."),
                           false);

    QStringList volume;
    if (m_tetmesh.outcome())
        volume << tr("TetGen meshes made.");
    if (const auto &h = m_hybrid.outcome())
        volume << tr("Hybrid mesh of %1 cells.")
                      .arg(locale.toString(qlonglong(h->result->mesh.cells.size())));
    m_steps->setStatus(Volume,
                       volume.isEmpty()
                           ? tr("TetGen meshes of input and remesh, or a hybrid mesh (ch. 5).")
                           : volume.join(QLatin1Char(' ')),
                       !volume.isEmpty());
    m_steps->setStatus(Export, tr("The input, the remesh or a volume mesh in another format."),
                       false);
}

} // namespace stratamesh
