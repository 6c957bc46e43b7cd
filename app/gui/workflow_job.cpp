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

std::shared_ptr<Progress> WorkflowJob::begin(const QString &title)
{
    if (m_pending)
        return nullptr;
    m_pending = true;
    m_percent = 0;
    const int run = ++m_run;
    // Called under the root's lock, in whichever thread ticked: only changes are posted.
    auto last = std::make_shared<std::pair<int, QString>>(-1, QString());
    m_progress = std::make_shared<Progress>(
        [this, run, title, last](double fraction, const std::string &stage) {
            const int percent = int(100.0 * fraction);
            const QString text = stage.empty() ? title
                                 : title.isEmpty()
                                     ? QString::fromStdString(stage)
                                     : title + QStringLiteral(": ") + QString::fromStdString(stage);
            if (percent == last->first && text == last->second)
                return;
            *last = {percent, text};
            QMetaObject::invokeMethod(
                this,
                [this, run, percent, text] {
                    if (run != m_run || !m_pending)
                        return;
                    m_percent = std::max(m_percent, percent);
                    emit progressChanged(m_percent, text);
                },
                Qt::QueuedConnection);
        });
    emit started();
    if (!title.isEmpty())
        emit progressChanged(0, title);
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
