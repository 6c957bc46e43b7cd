#include "workbench.h"

#include "feature_legend.h"
#include "message_panel.h"
#include "model_scene.h"
#include "position_marker.h"
#include "progress_strip.h"
#include "view_pair.h"
#include "vtk_view_widget.h"
#include "workflow.h"
#include "workflow_job.h"

#include <QAction>
#include <QCoreApplication>
#include <QDockWidget>
#include <QMainWindow>
#include <QUndoStack>

#include <vtkRenderer.h>

#include <algorithm>

namespace stratamesh {

Workbench::Workbench(QMainWindow *window, ViewPair *views, MessagePanel *messages,
                     QDockWidget *messageDock, ProgressStrip *strip)
    : m_window(window), m_views(views), m_messages(messages), m_messageDock(messageDock),
      m_strip(strip), m_undo(new QUndoStack(window)), m_showBox(new QAction(window)),
      m_legend(new FeatureLegend(views->inputView())),
      m_inputScene(std::make_unique<ModelScene>(views->inputView()->renderer())),
      m_outputScene(std::make_unique<ModelScene>(views->outputView()->renderer())),
      m_inputMarker(std::make_unique<PositionMarker>(views->inputView()->renderer())),
      m_outputMarker(std::make_unique<PositionMarker>(views->outputView()->renderer()))
{
    // A message that knows where it happened (a validity problem) shows the place.
    QObject::connect(messages, &MessagePanel::messageActivated, window,
                     [this](const Message &message) {
                         if (message.position)
                             showPosition(*message.position);
                     });
    m_ask = [window](const QString &text) {
        return QMessageBox::question(
            window, QCoreApplication::translate("stratamesh::Workbench", "Unsaved Result"), text,
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    };
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
    return m_model;
}

void Workbench::setModel(const LoadedModel &loaded)
{
    m_displayName = loaded.displayName;
    m_modelPath = loaded.path;
    m_counts = loaded.counts;
    // Undoing a choice made on another model would act on what is no longer shown.
    m_undo->clear();
    m_inputMarker->hide();
    m_outputMarker->hide();
    m_model = loaded.model;
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

double Workbench::diagonal() const
{
    return m_inputScene->diagonal();
}

void Workbench::showPosition(const Vec3 &position, double radius)
{
    const double diagonal = this->diagonal();
    // Found at the whole-model zoom, yet small beside the model (a record's area or length is
    // no radius: an unresolved intersection once drew a sphere larger than the model).
    const double r = std::clamp(radius, 0.01 * diagonal, 0.03 * diagonal);
    m_inputMarker->show(position, r);
    m_outputMarker->show(position, r);
    // Close in on the spot in both views, a fifth of the model around it: through the one camera
    // they share, or through each one's own when View > Link Cameras is off.
    const double centre[3] = {position.x(), position.y(), position.z()};
    inputView()->flyTo(centre, 0.4 * diagonal);
    if (m_views->camerasLinked())
        outputView()->renderer()->ResetCameraClippingRange();
    else
        outputView()->flyTo(centre, 0.4 * diagonal);
    render();
}

void Workbench::hidePosition()
{
    m_inputMarker->hide();
    m_outputMarker->hide();
    render();
}

void Workbench::setVerticalExaggeration(double factor)
{
    if (!(factor > 0.0))
        return;
    m_inputMarker->setVerticalExaggeration(factor);
    m_outputMarker->setVerticalExaggeration(factor);
    m_views->setVerticalExaggeration(factor);
}

double Workbench::verticalExaggeration() const
{
    return m_views->verticalExaggeration();
}

void Workbench::resetCamera()
{
    double bounds[6];
    if (m_inputScene->bounds(bounds))
        inputView()->resetCamera(bounds);
    else
        inputView()->resetCamera();
    // The output view shares the camera (its clipping range follows its own actors), or has its
    // own, framed on the same box.
    if (m_views->camerasLinked())
        outputView()->renderer()->ResetCameraClippingRange();
    else if (m_inputScene->bounds(bounds))
        outputView()->resetCamera(bounds);
    else
        outputView()->resetCamera();
    outputView()->render();
}

void Workbench::render()
{
    inputView()->render();
    outputView()->render();
}

void Workbench::updateLegend()
{
    // A colouring by a measure has its scalar bar instead.
    const bool entities = m_inputScene->isVisible() && !m_inputScene->hasScalarColouring();
    m_legend->setEntries(entities ? m_inputScene->legend() : std::vector<LegendEntry>{},
                         m_inputScene->boxVisible());
}

void Workbench::addWorkflow(Workflow *workflow)
{
    m_workflows.append(workflow);
}

// One question for all that is unsaved (a remeshed model, the project holding it and its
// reviews). Saving goes from the last workflow to the first: a later one builds on the earlier
// (a saved project holds the remeshed model, which then needs no file of its own).
bool Workbench::mayDiscardWork()
{
    QStringList unsaved;
    for (const Workflow *workflow : std::as_const(m_workflows))
        if (const QString text = workflow->unsavedWork(); !text.isEmpty())
            unsaved.append(text);
    if (unsaved.isEmpty())
        return true;
    const QString question =
        (unsaved.size() == 1 ? QCoreApplication::translate("stratamesh::Workbench",
                                                           "%1 Save it before it is replaced?")
                             : QCoreApplication::translate(
                                 "stratamesh::Workbench", "%1 Save them before they are replaced?"))
            .arg(unsaved.join(QLatin1Char(' ')));
    switch (m_ask(question)) {
    case QMessageBox::Save:
        for (auto it = m_workflows.crbegin(); it != m_workflows.crend(); ++it)
            if (!(*it)->unsavedWork().isEmpty() && !(*it)->saveUnsavedWork())
                return false;
        return true;
    case QMessageBox::Discard:
        return true;
    default:
        return false;
    }
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
