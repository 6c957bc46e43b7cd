#include "workflow.h"

#include "message.h"
#include "workbench.h"
#include "workflow_job.h"

#include <QAction>

namespace stratamesh {

Workflow::Workflow(Workbench &bench, QObject *parent) : QObject(parent), m_bench(bench) {}

Workflow::~Workflow() = default;

QList<QAction *> Workflow::menuActions(Menu) const
{
    return {};
}

QList<QAction *> Workflow::toolBarActions() const
{
    return {};
}

QList<Workflow::Dock> Workflow::docks() const
{
    return {};
}

WorkflowJob *Workflow::job() const
{
    return nullptr;
}

QAction *Workflow::cancelAction() const
{
    return nullptr;
}

void Workflow::clear() {}

void Workflow::enableActions(bool) {}

QString Workflow::unsavedWork() const
{
    return {};
}

bool Workflow::saveUnsavedWork()
{
    return true;
}

bool Workflow::isBusy() const
{
    return job() && job()->isBusy();
}

void Workflow::cancel()
{
    if (!isBusy())
        return;
    job()->cancel();
    if (QAction *action = cancelAction())
        action->setEnabled(false);
    m_bench.setStatus(tr("Cancelling…"));
}

void Workflow::relay(WorkflowJob *job)
{
    connect(job, &WorkflowJob::started, this, &Workflow::busyChanged);
    connect(job, &WorkflowJob::finished, this, [this](bool ok) {
        emit busyChanged();
        emit finished(ok);
    });
}

void Workflow::reportFailure(const Message &error, const QString &text, const QString &status)
{
    if (QAction *action = cancelAction())
        action->setEnabled(false);
    Message shown = error;
    shown.text = text;
    m_bench.addMessage(shown);
    m_bench.showMessages();
    m_bench.setStatus(status);
}

void Workflow::reportCancel(const QString &text, const QString &status)
{
    if (QAction *action = cancelAction())
        action->setEnabled(false);
    Message cancelled;
    cancelled.text = text;
    m_bench.addMessage(cancelled);
    m_bench.setStatus(status);
}

QAction *Workflow::separator()
{
    auto *action = new QAction(this);
    action->setSeparator(true);
    return action;
}

} // namespace stratamesh
