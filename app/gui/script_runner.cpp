#include "script_runner.h"

#include "complexity_workflow.h"
#include "hybrid_workflow.h"
#include "ledger_panel.h"
#include "main_window.h"
#include "message_panel.h"
#include "project_workflow.h"
#include "remesh_workflow.h"
#include "tetmesh_workflow.h"
#include "view_workflow.h"

#include <QAction>
#include <QTimer>

namespace stratamesh {

namespace {

Colouring colouringNamed(const QString &name)
{
    if (name == QLatin1String("min-angle"))
        return Colouring::MinAngle;
    if (name == QLatin1String("quality"))
        return Colouring::Quality;
    if (name == QLatin1String("distance"))
        return Colouring::Distance;
    return Colouring::Entity;
}

} // namespace

ScriptRunner::ScriptRunner(MainWindow &window, std::vector<ScriptStep> steps, QObject *parent)
    : QObject(parent), m_window(window), m_steps(std::move(steps))
{
}

void ScriptRunner::start()
{
    m_next = 0;
    m_failure.clear();
    runStep();
}

void ScriptRunner::runStep()
{
    if (m_next >= int(m_steps.size())) {
        emit finished(true);
        return;
    }
    const ScriptStep &step = m_steps[m_next];
    m_messagesBefore = m_window.messagePanel()->count();
    // A run ends in its workflow's finished(); the next step starts from the event loop, not
    // inside the signal of the one that ended.
    auto awaitRun = [&](Workflow *workflow, auto begin) {
        const QMetaObject::Connection connection = connect(
            workflow, &Workflow::finished, this,
            [this](bool ok) { QTimer::singleShot(0, this, [this, ok] { onStepEnded(ok); }); },
            Qt::SingleShotConnection);
        if (!begin()) {
            disconnect(connection);
            fail(tr("it could not start (no model shown, or another run is going on)"));
        }
    };
    switch (step.kind) {
    case ScriptStep::Kind::Complexity: {
        ComplexityParams params;
        params.cells = {step.count > 0 ? step.count : 1000};
        awaitRun(m_window.complexityWorkflow(),
                 [&] { return m_window.complexityWorkflow()->start(params); });
        return;
    }
    case ScriptStep::Kind::Remesh: {
        RemeshParams params;
        if (step.count > 0)
            params.sites = step.count;
        awaitRun(m_window.remeshWorkflow(),
                 [&] { return m_window.remeshWorkflow()->start(params); });
        return;
    }
    case ScriptStep::Kind::Tetmesh:
        awaitRun(m_window.tetmeshWorkflow(),
                 [&] { return m_window.tetmeshWorkflow()->start(TetgenParams(), true); });
        return;
    case ScriptStep::Kind::Hybrid: {
        HybridParams params;
        if (step.count > 0)
            params.sites = step.count;
        awaitRun(m_window.hybridWorkflow(),
                 [&] { return m_window.hybridWorkflow()->start(params); });
        return;
    }
    case ScriptStep::Kind::ColourBy: {
        ViewWorkflow *view = m_window.viewWorkflow();
        const Colouring colouring = colouringNamed(step.value);
        if (!view->colourAction(colouring)->isEnabled()) {
            fail(tr("this colouring is not available now (the distance needs a remesh before)"));
            return;
        }
        view->chooseColouring(colouring); // undoable, as from View > Colour By
        QTimer::singleShot(0, this, [this] { onStepEnded(true); });
        return;
    }
    case ScriptStep::Kind::SaveProject: {
        const bool saved = m_window.projectWorkflow()->saveProject(step.value);
        QTimer::singleShot(0, this, [this, saved] { onStepEnded(saved); });
        return;
    }
    }
}

void ScriptRunner::onStepEnded(bool ok)
{
    if (!ok) {
        const QString error = lastError();
        fail(error.isEmpty() ? tr("it was cancelled or failed") : error);
        return;
    }
    if (m_steps[m_next].kind == ScriptStep::Kind::Remesh) {
        // As --remesh-sites always did: the first simplification marked, the whole model in view.
        m_window.remeshWorkflow()->ledgerPanel()->selectRow(0);
        m_window.resetCamera();
    }
    emit stepFinished(m_next);
    ++m_next;
    runStep();
}

void ScriptRunner::fail(const QString &cause)
{
    m_failure =
        tr("step %1 (%2) failed: %3").arg(m_next + 1).arg(describeStep(m_steps[m_next]), cause);
    emit finished(false);
}

// The newest error the step put in the Messages dock: what the failed run reported.
QString ScriptRunner::lastError() const
{
    const MessagePanel *messages = m_window.messagePanel();
    for (int row = messages->count() - 1; row >= m_messagesBefore; --row) {
        const Message message = messages->message(row);
        if (message.severity == Message::Severity::Error)
            return message.file.isEmpty()
                       ? message.text
                       : QStringLiteral("%1: %2").arg(message.file, message.text);
    }
    return {};
}

} // namespace stratamesh
