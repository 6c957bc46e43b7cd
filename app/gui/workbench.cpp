#include "workbench.h"

#include "feature_legend.h"
#include "message_panel.h"
#include "model_scene.h"
#include "progress_strip.h"
#include "view_pair.h"
#include "vtk_view_widget.h"
#include "workflow_job.h"

#include <QDockWidget>

#include <vtkRenderer.h>

namespace stratamesh {

Workbench::Workbench(QMainWindow *window, ViewPair *views, MessagePanel *messages,
                     QDockWidget *messageDock, ProgressStrip *strip)
    : m_window(window), m_views(views), m_messages(messages), m_messageDock(messageDock),
      m_strip(strip), m_legend(new FeatureLegend(views->inputView())),
      m_inputScene(std::make_unique<ModelScene>(views->inputView()->renderer())),
      m_outputScene(std::make_unique<ModelScene>(views->outputView()->renderer()))
{
}

Workbench::~Workbench() = default;

VtkViewWidget *Workbench::inputView() const
{
    return m_views->inputView();
}

VtkViewWidget *Workbench::outputView() const
{
    return m_views->outputView();
}

const std::shared_ptr<const Model> &Workbench::model() const
{
    return m_inputScene->model();
}

void Workbench::setModel(const LoadedModel &loaded)
{
    m_displayName = loaded.displayName;
    m_modelPath = loaded.path;
    m_counts = loaded.counts;
    m_inputScene->setModel(loaded.model);
    updateLegend();
    resetCamera();
}

void Workbench::addMessage(const Message &message)
{
    m_messages->addMessage(message);
}

void Workbench::showMessages(bool raise)
{
    m_messageDock->show();
    if (raise)
        m_messageDock->raise();
}

void Workbench::setStatus(const QString &text)
{
    m_strip->setText(text);
}

void Workbench::resetCamera()
{
    double bounds[6];
    if (m_inputScene->bounds(bounds))
        inputView()->resetCamera(bounds);
    else
        inputView()->resetCamera();
    // The output view shares the camera; its clipping range follows its own actors.
    outputView()->renderer()->ResetCameraClippingRange();
    outputView()->render();
}

void Workbench::render()
{
    inputView()->render();
    outputView()->render();
}

void Workbench::updateLegend()
{
    m_legend->setEntries(m_inputScene->isVisible() ? m_inputScene->legend()
                                                   : std::vector<LegendEntry>{},
                         m_inputScene->boxVisible());
}

void Workbench::addJob(WorkflowJob *job)
{
    m_jobs.append(job);
}

bool Workbench::isBusy() const
{
    for (const WorkflowJob *job : m_jobs)
        if (job->isBusy())
            return true;
    return false;
}

} // namespace stratamesh
