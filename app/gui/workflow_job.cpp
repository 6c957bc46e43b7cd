#include "workflow_job.h"

#include "common/progress.h"

#include <QEventLoop>

#include <algorithm>

namespace stratamesh {

WorkflowJob::WorkflowJob(QObject *parent) : QObject(parent)
{
    qRegisterMetaType<stratamesh::Message>();
}

WorkflowJob::~WorkflowJob() = default;

void WorkflowJob::relayProgress(QFutureWatcherBase &watcher)
{
    // The watcher's value and text signals arrive separately, and the value read with a text may
    // be ahead of a value signal still queued: the worker only moves forward, so the bar does too.
    connect(&watcher, &QFutureWatcherBase::progressValueChanged, this, [this, &watcher](int value) {
        m_percent = std::max(m_percent, value);
        emit progressChanged(m_percent, watcher.progressText());
    });
    connect(&watcher, &QFutureWatcherBase::progressTextChanged, this,
            [this, &watcher](const QString &text) {
                m_percent = std::max(m_percent, watcher.progressValue());
                emit progressChanged(m_percent, text);
            });
}

std::shared_ptr<Progress> WorkflowJob::begin()
{
    if (m_pending)
        return nullptr;
    m_pending = true;
    m_percent = 0;
    m_progress = std::make_shared<Progress>();
    emit started();
    return m_progress;
}

void WorkflowJob::end(RunStatus status, const Message &error,
                      const std::function<void()> &emitSucceeded)
{
    m_pending = false;
    m_progress.reset();
    switch (status) {
    case RunStatus::Done:
        emitSucceeded();
        break;
    case RunStatus::Cancelled:
        emit cancelled();
        break;
    case RunStatus::Failed:
        emit failed(error);
        break;
    }
    emit finished(status == RunStatus::Done);
}

void WorkflowJob::stop(QFutureWatcherBase &watcher)
{
    watcher.disconnect(this);
    if (m_progress)
        m_progress->cancel();
    watcher.cancel();
    watcher.waitForFinished();
}

void WorkflowJob::cancel()
{
    if (m_pending && m_progress)
        m_progress->cancel();
}

void WorkflowJob::waitForFinished()
{
    if (!m_pending)
        return;
    QEventLoop loop;
    connect(this, &WorkflowJob::finished, &loop, &QEventLoop::quit);
    loop.exec();
}

} // namespace stratamesh
